// What the subcommands' options share (cli/options.cpp): one seed rule, one --show rule, value choices with "did you
// mean", and CLI11's parse errors said in fftess's words, pointing at the subcommand's own help.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
class Error;
class Validator;
} // namespace CLI

namespace fftess::cli {

// The one seed rule: a decimal whole number from 0 to 2^64-1, all digits (no sign, no 0x, no wrap-around, no
// saturation). UsageError "OPTION 'TEXT': expected a whole number from 0 to 18446744073709551615" otherwise.
uint64_t parseSeed(const std::string& text, const std::string& option = "--seed");
// --seed on sub, one type name (SEED) and one help text everywhere: "<what>: a whole number from 0 to
// 18446744073709551615 (default 1)". The text is checked while the command line is parsed (exit 2 before any work).
CLI::Option* addSeedOption(CLI::App* sub, std::string& seed, const std::string& what);
CLI::Option* addSeedOption(CLI::App* sub, uint64_t& seed, const std::string& what);

// --show N on sub: "<what> (default D)" with type N; a negative N is refused while parsing
// ("--show -1: must be >= 0").
CLI::Option* addShowOption(CLI::App* sub, int& show, const std::string& what);

// -j/--threads N on sub: "<what>, 0 (all cores) to 1024 (default D)" with type N; N below 0 or above fftess::kMaxThreads
// (base/threads.h) is refused while parsing ("--threads 100000: must be 0 (all cores) to 1024"), exit 2.
CLI::Option* addThreadsOption(CLI::App* sub, int& threads, const std::string& what);

// "OPTION 'VALUE': expected a|b|c" and, when one of them is near (verify/did_you_mean.h), " (did you mean 'b'?)".
std::string choiceError(const std::string& option, const std::string& value, const std::vector<std::string>& choices);
// A CLI11 check that the value is one of choices (the message: choiceError's).
CLI::Validator choiceOf(std::vector<std::string> choices);

// " (did you mean 'NAME'?)" for the nearest of candidates, "" when none is near.
std::string didYouMeanText(const std::string& word, const std::vector<std::string>& candidates);

// The subcommands of app, in the order they were added.
std::vector<std::string> subcommandNames(const CLI::App& app);

// A CLI11 parse error in fftess's words, one line without the "fftess: error: " prefix, ending with the help to read:
// "sweep: unknown option '--sho' (did you mean '--show'?; see fftess sweep --help)". sub: the subcommand being
// parsed (null: the top level).
std::string parseErrorText(const CLI::App& app, const CLI::App* sub, const CLI::Error& e);

} // namespace fftess::cli
