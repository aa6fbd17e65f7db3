// "Did you mean": the name a user most likely meant by a misspelt one, for the scene loader's unknown keys and values
// (verify/scene_reader.h) and the command line's options, subcommands and values (cli/). One rule everywhere.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace fftess::verify {

// Edits (insert, delete, replace one byte, or swap two adjacent bytes: the optimal string alignment distance)
// that turn a into b, comparing bytes case-insensitively (ASCII).
size_t editDistance(std::string_view a, std::string_view b);

// The candidate meant by `word`, "" when none is close: the nearest by editDistance if it is at most
// max(1, |word| / 3) edits away and fewer edits than |word| (a one-letter word suggests nothing); else the one
// candidate that starts with `word` (at least 2 bytes), if exactly one does. At the same distance a candidate that
// starts with `word` wins ("of": "off", not "on"), else the earlier one; a candidate equal to `word` is never suggested.
std::string nearestName(std::string_view word, const std::vector<std::string>& candidates);

} // namespace fftess::verify
