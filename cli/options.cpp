// What the subcommands' options share (options.h): seeds, --show, choices, and CLI11's parse errors in fftess's words.
#include "options.h"
#include "common.h"

#include "base/threads.h"
#include "verify/did_you_mean.h"

#include <CLI/CLI.hpp>

#include <cctype>
#include <regex>

namespace fftess::cli {

namespace {

// A bad value found while CLI11 parses, already in fftess's words ("--seed 'x': expected ..."): printed as it is.
struct OptionValueError : CLI::ValidationError {
  explicit OptionValueError(const std::string& msg) : CLI::ValidationError(msg, CLI::ExitCodes::ValidationError) {}
};

const char* const kSeedRange = "a whole number from 0 to 18446744073709551615";

} // namespace

uint64_t parseSeed(const std::string& text, const std::string& option) {
  uint64_t v = 0;
  bool ok = !text.empty() && text.size() <= 20;
  for (char c : text) {
    if (!ok) break;
    const unsigned d = static_cast<unsigned>(c - '0');
    ok = c >= '0' && c <= '9' && v <= (UINT64_MAX - d) / 10;
    v = v * 10 + d;
  }
  if (!ok) throw UsageError(option + " " + quoteToken(text) + ": expected " + kSeedRange);
  return v;
}

// The value checked now, in parse order, so a bad seed is exit 2 before any work whatever the subcommand.
static uint64_t seedWhileParsing(const std::string& text) {
  try {
    return parseSeed(text);
  } catch (const UsageError& e) {
    throw OptionValueError(e.what());
  }
}

static std::string seedHelp(const std::string& what) { return what + ": " + kSeedRange + " (default 1)"; }

CLI::Option* addSeedOption(CLI::App* sub, std::string& seed, const std::string& what) {
  return sub->add_option_function<std::string>(
                "--seed", [&seed](const std::string& s) { seedWhileParsing(s), seed = s; }, seedHelp(what))
      ->type_name("SEED");
}

CLI::Option* addSeedOption(CLI::App* sub, uint64_t& seed, const std::string& what) {
  return sub->add_option_function<std::string>(
                "--seed", [&seed](const std::string& s) { seed = seedWhileParsing(s); }, seedHelp(what))
      ->type_name("SEED");
}

CLI::Option* addShowOption(CLI::App* sub, int& show, const std::string& what) {
  const std::string help = what + " (default " + std::to_string(show) + ")";
  return sub->add_option_function<int>(
                "--show",
                [&show](const int& n) {
                  if (n < 0) throw OptionValueError("--show " + std::to_string(n) + ": must be >= 0");
                  show = n;
                },
                help)
      ->type_name("N");
}

CLI::Option* addThreadsOption(CLI::App* sub, int& threads, const std::string& what) {
  const std::string help =
      what + ", 0 (all cores) to " + std::to_string(kMaxThreads) + " (default " + std::to_string(threads) + ")";
  return sub->add_option_function<int>(
                "-j,--threads",
                [&threads](const int& n) {
                  if (n < 0 || n > kMaxThreads)
                    throw OptionValueError("--threads " + std::to_string(n) + ": must be 0 (all cores) to " +
                                           std::to_string(kMaxThreads));
                  threads = n;
                },
                help)
      ->type_name("N");
}

std::string didYouMeanText(const std::string& word, const std::vector<std::string>& candidates) {
  const std::string near = verify::nearestName(word, candidates);
  return near.empty() ? "" : "; did you mean " + quoteToken(near) + "?";
}

static std::string joinChoices(const std::vector<std::string>& choices) {
  std::string s;
  for (const std::string& c : choices) s += (s.empty() ? "" : "|") + c;
  return s;
}

std::string choiceError(const std::string& option, const std::string& value, const std::vector<std::string>& choices) {
  return option + " " + quoteToken(value) + ": expected " + joinChoices(choices) + didYouMeanText(value, choices);
}

CLI::Validator choiceOf(std::vector<std::string> choices) {
  const std::string desc = "{" + joinChoices(choices) + "}";
  // The message is completed with the option's name by parseErrorText ("OPTION: 'VALUE': ..." -> "OPTION 'VALUE': ...").
  return CLI::Validator(
      [choices](std::string& v) -> std::string {
        for (const std::string& c : choices)
          if (v == c) return "";
        return quoteToken(v) + ": expected " + joinChoices(choices) + didYouMeanText(v, choices);
      },
      desc);
}

std::vector<std::string> subcommandNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* s : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(s->get_name());
  return names;
}

// ---- parse errors ------------------------------------------------------------------------------------------------
namespace {

// Every spelling of sub's options: "--show", "-q", "--quiet", ...
std::vector<std::string> optionSpellings(const CLI::App& sub) {
  std::vector<std::string> names;
  for (const CLI::Option* o : sub.get_options()) {
    for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    for (const std::string& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

const CLI::Option* findOption(const CLI::App& sub, const std::string& name) {
  for (const CLI::Option* o : sub.get_options())
    if (o->check_name(name)) return o;
  return nullptr;
}

// What a value of a type name must be, in words.
std::string typeWords(const std::string& type) {
  if (type == "INT" || type == "N") return "a whole number";
  if (type == "UINT") return "a whole number >= 0";
  if (type == "FLOAT") return "a number";
  return "a value of type " + type;
}

// The arguments CLI11 could not place: the first unknown option (an option's value after it is then an extra too),
// else the first unexpected argument.
std::string extrasText(const CLI::App& scope, const std::vector<std::string>& extras) {
  for (const std::string& x : extras) {
    if (x.size() < 2 || x[0] != '-') continue;
    const std::string name = x.substr(0, x.find('='));
    std::string hint = didYouMeanText(name, optionSpellings(scope));
    const CLI::App* top = scope.get_parent();
    std::string others; // the few subcommands that take it (sweep --mesh: "an option of fftess check")
    int takers = 0;
    if (top && hint.empty())
      for (const CLI::App* s : top->get_subcommands([](const CLI::App*) { return true; }))
        if (s != &scope && findOption(*s, name))
          ++takers, others += (others.empty() ? "fftess " : ", fftess ") + s->get_name();
    if (takers > 0 && takers <= 3) hint = " (an option of " + others + ")";
    return "unknown option " + quoteToken(name) + hint;
  }
  if (extras.empty()) return "unexpected arguments";
  return "unexpected argument " + quoteToken(extras.front()) +
         (scope.get_parent() ? "" : didYouMeanText(extras.front(), subcommandNames(scope)));
}

// "NAME: rest" of CLI11's messages, split; false when the message does not start with an option's name.
bool splitName(const CLI::App& scope, const std::string& msg, std::string& name, std::string& rest) {
  const size_t colon = msg.find(": ");
  if (colon == std::string::npos) return false;
  name = msg.substr(0, colon), rest = msg.substr(colon + 2);
  return findOption(scope, name) != nullptr;
}

std::string conversionText(const CLI::App& scope, const std::string& msg) {
  static const std::regex convert("Could not convert: (.*) = (.*)"), allowed("The value (.*) is not an allowed value for (.*)");
  std::smatch m;
  std::string name, value;
  if (std::regex_match(msg, m, convert)) name = m[1], value = m[2];
  else if (std::regex_match(msg, m, allowed)) value = m[1], name = m[2];
  else return msg;
  const CLI::Option* o = findOption(scope, name);
  return name + " " + quoteToken(value) + ": expected " + typeWords(o ? o->get_type_name() : "");
}

std::string validationText(const CLI::App& scope, const std::string& msg) {
  std::string name, rest;
  if (!splitName(scope, msg, name, rest)) return msg;
  static const std::regex range("Value (.*) not in range (.*) to (.*)");
  std::smatch m;
  if (std::regex_match(rest, m, range))
    return name + " " + quoteToken(m[1]) + ": must be from " + m[2].str() + " to " + m[3].str();
  if (!rest.empty() && rest[0] == '\'') return name + " " + rest; // choiceOf: "'VALUE': expected ..."
  return name + ": " + rest;
}

std::string mismatchText(const CLI::App& scope, const std::string& msg) {
  std::string name, rest;
  if (!splitName(scope, msg, name, rest)) return msg;
  const CLI::Option* o = findOption(scope, name);
  return name + ": missing its value (" + o->get_type_name() + ")";
}

} // namespace

std::string parseErrorText(const CLI::App& app, const CLI::App* sub, const CLI::Error& e) {
  const CLI::App& scope = sub ? *sub : app;
  const std::string help = sub ? "fftess " + sub->get_name() + " --help" : "fftess --help";
  const std::string who = sub ? sub->get_name() + ": " : "";
  const std::string msg = e.what();
  std::string text;
  if (dynamic_cast<const OptionValueError*>(&e)) {
    text = msg;
  } else if (dynamic_cast<const CLI::ExtrasError*>(&e)) {
    text = who + extrasText(scope, scope.remaining(false));
  } else if (dynamic_cast<const CLI::RequiredError*>(&e)) {
    if (!sub) text = "missing subcommand (expected " + joinChoices(subcommandNames(app)) + ")";
    else {
      std::string what = msg.substr(0, msg.rfind(" is required"));
      if (!what.empty() && what[0] != '-') // a positional argument: named as the usage lines name it (SCENE, PATCHES)
        for (char& c : what) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
      text = who + "missing " + (what == "SCENE" ? "SCENE (the scene file)" : what);
    }
  } else if (dynamic_cast<const CLI::ConversionError*>(&e)) {
    text = conversionText(scope, msg);
  } else if (dynamic_cast<const CLI::ValidationError*>(&e)) {
    text = validationText(scope, msg);
  } else if (dynamic_cast<const CLI::ArgumentMismatch*>(&e)) {
    text = mismatchText(scope, msg);
  } else {
    text = who + msg;
  }
  return text + " (see " + help + ")";
}

} // namespace fftess::cli
