// SARIF 2.1.0 of a CiReport (report_sarif.h).
#include "report_sarif.h"

#include <map>
#include <unistd.h>

namespace fftess::cli {

using ojson = nlohmann::ordered_json;

namespace {

constexpr const char* kSchema = "https://docs.oasis-open.org/sarif/sarif/v2.1.0/errata01/os/schemas/sarif-schema-2.1.0.json";

std::string currentDir() {
  std::string buf(4096, '\0');
  if (!::getcwd(buf.data(), buf.size())) return "";
  buf.resize(std::char_traits<char>::length(buf.c_str()));
  return buf;
}

// "a/./b" and "./a" as "a/b", "a" (the spelling the user gave otherwise kept; ".." kept too).
std::string tidy(const std::string& p) {
  std::string out;
  size_t i = 0;
  while (i <= p.size()) {
    const size_t slash = std::min(p.find('/', i), p.size());
    const std::string part = p.substr(i, slash - i);
    if (!(part == "." || (part.empty() && !out.empty()))) out += (out.empty() && i == 0 ? "" : "/") + part;
    i = slash + 1;
  }
  return out;
}

// The artifact location of a file: {"uri": relative, "uriBaseId": "%SRCROOT%"} for a path under the current directory,
// else {"uri": "file:///..."}.
ojson artifactLocation(const std::string& file, const std::string& cwd) {
  const std::string abs = tidy(file.empty() || file.front() != '/' ? cwd + "/" + file : file);
  if (!cwd.empty() && abs.compare(0, cwd.size() + 1, cwd + "/") == 0 && abs.find("/../") == std::string::npos)
    return {{"uri", percentEncodePath(abs.substr(cwd.size() + 1))}, {"uriBaseId", "%SRCROOT%"}};
  return {{"uri", "file://" + percentEncodePath(abs)}};
}

// A rule id from a cause key: its kind, '/', the key's words in lowercase joined by '-' (at most 80 characters);
// distinct keys that spell the same id get "-2", "-3", ...
std::string slugOf(const std::string& kind, const std::string& key) {
  std::string s;
  for (unsigned char c : key) {
    const bool word = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (c >= 'A' && c <= 'Z');
    if (word) s += static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
    else if (!s.empty() && s.back() != '-') s += '-';
  }
  while (!s.empty() && s.back() == '-') s.pop_back();
  if (s.size() > 80) s.resize(80);
  return kind + "/" + (s.empty() ? "cause" : s);
}

ojson logicalJson(const CiLogical& l) {
  return {{"name", l.name}, {"fullyQualifiedName", l.fullyQualifiedName}, {"kind", l.kind}};
}

ojson resultJson(const CiResult& x, const std::string& ruleId, size_t ruleIndex, const std::string& cwd) {
  ojson loc = ojson::object();
  if (!x.file.empty()) {
    ojson phys{{"artifactLocation", artifactLocation(x.file, cwd)}};
    if (x.line >= 1) phys["region"] = {{"startLine", x.line}};
    loc["physicalLocation"] = phys;
  }
  if (!x.logical.empty()) {
    ojson ls = ojson::array();
    for (const CiLogical& l : x.logical) ls.push_back(logicalJson(l));
    loc["logicalLocations"] = ls;
  }
  ojson j{{"ruleId", ruleId}, {"ruleIndex", ruleIndex}, {"kind", "fail"},
          {"level", x.level}, {"message", {{"text", x.where.empty() ? x.message : x.where + ": " + x.message}}}};
  j["locations"] = ojson::array({loc});
  ojson props = x.properties;
  props["fix"] = x.fix;
  props["finding_kind"] = x.kind;
  props["junit"] = x.outcome == CiOutcome::Failure ? "failure" : x.outcome == CiOutcome::Error ? "error" : "not_counted";
  if (!x.lineWhy.empty()) props["line_is"] = x.lineWhy;
  j["properties"] = props;
  return j;
}

} // namespace

std::string percentEncodePath(const std::string& path) {
  static const char* const kHex = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : path) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' ||
                      c == '.' || c == '_' || c == '~' || c == '/';
    if (keep) out += static_cast<char>(c);
    else out += std::string("%") + kHex[c >> 4] + kHex[c & 15];
  }
  return out;
}

std::string sarifText(const CiReport& r, const std::string& cwdIn) {
  const std::string cwd = cwdIn.empty() ? currentDir() : cwdIn;
  ojson rules = ojson::array();
  std::map<std::string, size_t> ruleOf; // cause key -> index in rules
  std::map<std::string, int> idUses;
  std::vector<std::string> ids;
  for (const CiResult& x : r.results) {
    if (ruleOf.count(x.rule)) continue;
    std::string id = slugOf(x.kind, x.rule);
    const int n = ++idUses[id];
    if (n > 1) id += "-" + std::to_string(n);
    ruleOf[x.rule] = rules.size();
    ids.push_back(id);
    rules.push_back({{"id", id},
                     {"shortDescription", {{"text", x.rule}}},
                     {"fullDescription", {{"text", x.rule + ". Fix: " + (x.fix.empty() ? "(no fix known)" : x.fix)}}},
                     {"help", {{"text", x.fix.empty() ? "(no fix known)" : x.fix}}},
                     {"defaultConfiguration", {{"level", x.level}}},
                     {"properties", {{"cause", x.rule}, {"finding_kind", x.kind}}}});
  }
  ojson results = ojson::array();
  for (const CiResult& x : r.results) {
    const size_t i = ruleOf.at(x.rule);
    results.push_back(resultJson(x, ids[i], i, cwd));
  }
  ojson notes = ojson::array();
  for (const auto& [level, text] : r.notes) notes.push_back({{"level", level}, {"message", {{"text", text}}}});
  ojson cmd = ojson::array();
  for (const std::string& s : r.commandLine) cmd.push_back(s);
  ojson invocation{{"executionSuccessful", true}, {"exitCode", r.exitStatus}};
  if (!cmd.empty()) invocation["arguments"] = cmd;
  invocation["toolExecutionNotifications"] = notes;
  ojson run{{"tool", {{"driver", {{"name", "fftess"}, {"version", FFTESS_VERSION}, {"rules", rules}}}}}};
  if (!cwd.empty()) run["originalUriBaseIds"] = {{"%SRCROOT%", {{"uri", "file://" + percentEncodePath(cwd) + "/"}}}};
  run["automationDetails"] = {{"description", {{"text", r.suite}}}};
  run["invocations"] = ojson::array({invocation});
  run["results"] = results;
  ojson props = r.properties;
  props["command"] = r.command;
  run["properties"] = props;
  const ojson log{{"$schema", kSchema}, {"version", "2.1.0"}, {"runs", ojson::array({run})}};
  return log.dump(2, ' ', false, ojson::error_handler_t::replace) + "\n";
}

} // namespace fftess::cli
