// "Did you mean" (did_you_mean.h): optimal string alignment distance and the nearest candidate.
#include "verify/did_you_mean.h"

#include <algorithm>

namespace fftess::verify {

static char lower(char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; }

size_t editDistance(std::string_view a, std::string_view b) {
  // Three rows of the dynamic programme: d[i][j] = edits turning a[0, i) into b[0, j).
  std::vector<size_t> prev2(b.size() + 1), prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) && lower(a[i - 2]) == lower(b[j - 1]))
        cur[j] = std::min(cur[j], prev2[j - 2] + 1);
    }
    std::swap(prev2, prev);
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string nearestName(std::string_view word, const std::vector<std::string>& candidates) {
  const size_t limit = std::max<size_t>(1, word.size() / 3);
  auto startsWith = [&](const std::string& c) { return c.size() > word.size() && c.compare(0, word.size(), word) == 0; };
  const std::string* best = nullptr;
  size_t bestDistance = 0;
  for (const std::string& c : candidates) {
    if (c == word) continue;
    const size_t d = editDistance(word, c);
    if (d > limit || d >= word.size()) continue;
    // Nearer wins; at the same distance a candidate that starts with the word ("of": "off", not "on"), else the earlier.
    if (!best || d < bestDistance || (d == bestDistance && startsWith(c) && !startsWith(*best))) best = &c, bestDistance = d;
  }
  if (best) return *best;
  const std::string* prefixed = nullptr;
  for (const std::string& c : candidates) {
    if (word.size() < 2 || !startsWith(c)) continue;
    if (prefixed) return ""; // two candidates start with it: no guess
    prefixed = &c;
  }
  return prefixed ? *prefixed : "";
}

} // namespace fftess::verify
