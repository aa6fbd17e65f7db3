// The SARIF 2.1.0 and JUnit checks of ci_check.h.
#include "ci_check.h"

#include <cctype>
#include <set>

namespace clitest {

namespace {

using nlohmann::json;

struct Checker {
  std::vector<std::string> problems;
  void need(bool ok, const std::string& where, const std::string& what) {
    if (!ok) problems.push_back(where + ": " + what);
  }
  bool isString(const json& j, const char* key) { return j.contains(key) && j[key].is_string(); }

  // RFC 3986 URI reference: unreserved, reserved and '%' HEXDIG HEXDIG only.
  static bool uriReference(const std::string& s) {
    static const std::string allowed = "-._~:/?#[]@!$&'()*+,;=";
    for (size_t i = 0; i < s.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if (c == '%') {
        if (i + 2 >= s.size() + 0 || !std::isxdigit(static_cast<unsigned char>(s[i + 1])) ||
            !std::isxdigit(static_cast<unsigned char>(s[i + 2])))
          return false;
        i += 2;
        continue;
      }
      if (!(std::isalnum(c) && c < 128) && allowed.find(static_cast<char>(c)) == std::string::npos) return false;
    }
    return true;
  }
  static bool absoluteUri(const std::string& s) {
    const size_t colon = s.find(':');
    if (colon == std::string::npos || colon == 0 || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
    for (size_t i = 0; i < colon; ++i)
      if (!std::isalnum(static_cast<unsigned char>(s[i])) && s[i] != '+' && s[i] != '-' && s[i] != '.') return false;
    return true;
  }

  void message(const json& m, const std::string& where) {
    need(m.is_object() && (isString(m, "text") || isString(m, "id")), where, "message needs text or id (§3.11.2)");
  }

  void artifactLocation(const json& a, const std::string& where) {
    need(a.is_object(), where, "artifactLocation must be an object");
    if (!a.is_object() || !a.contains("uri")) return;
    need(a["uri"].is_string(), where, "uri must be a string");
    if (!a["uri"].is_string()) return;
    const std::string uri = a["uri"];
    need(uriReference(uri), where, "uri is not a URI reference (RFC 3986): " + uri);
    if (a.contains("uriBaseId")) need(!absoluteUri(uri), where, "uri with a uriBaseId must be relative (§3.4.4)");
  }

  void location(const json& l, const std::string& where) {
    need(l.is_object(), where, "location must be an object");
    if (!l.is_object()) return;
    if (l.contains("physicalLocation")) {
      const json& p = l["physicalLocation"];
      need(p.contains("artifactLocation") || p.contains("address"), where,
           "physicalLocation needs artifactLocation or address (§3.29.2)");
      if (p.contains("artifactLocation")) artifactLocation(p["artifactLocation"], where + ".artifactLocation");
      if (p.contains("region")) {
        const json& r = p["region"];
        if (r.contains("startLine")) need(r["startLine"].is_number_integer() && r["startLine"] >= 1, where, "startLine >= 1 (§3.30.5)");
        if (r.contains("endLine") && r.contains("startLine"))
          need(r["endLine"] >= r["startLine"], where, "endLine >= startLine (§3.30.6)");
        if (r.contains("startColumn")) need(r["startColumn"] >= 1, where, "startColumn >= 1");
      }
    }
    static const std::set<std::string> kinds{"function", "member", "module", "namespace", "parameter", "resource",
                                             "returnType", "type", "variable", "object", "array", "property", "value",
                                             "element", "text", "attribute", "comment", "declaration", "dtd",
                                             "processingInstruction"};
    if (l.contains("logicalLocations"))
      for (const json& ll : l["logicalLocations"])
        if (ll.contains("kind")) need(ll["kind"].is_string() && kinds.count(ll["kind"]), where, "logicalLocation.kind");
  }

  void result(const json& r, const json& rules, const std::string& where) {
    need(r.contains("message"), where, "result.message is required (§3.27.11)");
    if (r.contains("message")) message(r["message"], where);
    static const std::set<std::string> levels{"none", "note", "warning", "error"};
    static const std::set<std::string> kinds{"notApplicable", "pass", "fail", "review", "open", "informational"};
    const std::string kind = r.value("kind", "fail");
    need(kinds.count(kind) > 0, where, "result.kind");
    if (r.contains("level")) {
      need(levels.count(r["level"].get<std::string>()) > 0, where, "result.level");
      if (kind != "fail") need(r["level"] == "none", where, "level must be none when kind is not fail (§3.27.10)");
    }
    if (r.contains("ruleIndex")) {
      const long i = r["ruleIndex"].get<long>();
      need(i >= -1, where, "ruleIndex >= -1");
      need(i < long(rules.size()), where, "ruleIndex < rules size (§3.27.6)");
      if (i >= 0 && i < long(rules.size()) && r.contains("ruleId"))
        need(rules[size_t(i)].value("id", "") == r["ruleId"], where, "rules[ruleIndex].id == ruleId (§3.27.6)");
    }
    if (r.contains("locations"))
      for (size_t k = 0; k < r["locations"].size(); ++k)
        location(r["locations"][k], where + ".locations[" + std::to_string(k) + "]");
  }

  void run(const json& run, const std::string& where) {
    need(run.contains("tool") && run["tool"].contains("driver"), where, "run.tool.driver is required (§3.14.6, §3.18.2)");
    if (!run.contains("tool") || !run["tool"].contains("driver")) return;
    const json& driver = run["tool"]["driver"];
    need(isString(driver, "name") && !driver["name"].get<std::string>().empty(), where, "tool.driver.name (§3.19.8)");
    const json rules = driver.value("rules", json::array());
    std::set<std::string> ids;
    for (const json& rule : rules) {
      need(isString(rule, "id"), where, "reportingDescriptor.id is required (§3.49.3)");
      if (isString(rule, "id")) need(ids.insert(rule["id"].get<std::string>()).second, where, "rule ids unique");
    }
    const json results = run.value("results", json::array());
    for (size_t i = 0; i < results.size(); ++i) result(results[i], rules, where + ".results[" + std::to_string(i) + "]");
    for (const json& inv : run.value("invocations", json::array())) {
      need(inv.contains("executionSuccessful") && inv["executionSuccessful"].is_boolean(), where,
           "invocation.executionSuccessful is required (§3.20.14)");
      for (const json& n : inv.value("toolExecutionNotifications", json::array()))
        message(n.value("message", json()), where + ".notification");
    }
    if (run.contains("originalUriBaseIds"))
      for (const auto& [id, base] : run["originalUriBaseIds"].items()) {
        const std::string uri = base.value("uri", "");
        need(absoluteUri(uri) && !uri.empty() && uri.back() == '/', where,
             "originalUriBaseIds." + id + ".uri must be absolute and end in '/' (§3.14.14)");
      }
  }
};

long attribute(const std::string& tag, const char* name) {
  const std::string key = std::string(" ") + name + "=\"";
  const size_t at = tag.find(key);
  if (at == std::string::npos) return -1;
  return std::stol(tag.substr(at + key.size()));
}

long countTags(const std::string& xml, const std::string& open, size_t from, size_t to) {
  long n = 0;
  for (size_t at = xml.find(open, from); at != std::string::npos && at < to; at = xml.find(open, at + 1)) {
    const char next = xml[at + open.size()];
    n += next == ' ' || next == '>' || next == '/';
  }
  return n;
}

} // namespace

std::vector<std::string> sarifProblems(const json& log) {
  Checker c;
  c.need(log.is_object(), "sarifLog", "must be an object");
  if (!log.is_object()) return c.problems;
  c.need(log.value("version", "") == "2.1.0", "sarifLog", "version must be \"2.1.0\" (§3.13.2)");
  c.need(log.contains("runs") && log["runs"].is_array(), "sarifLog", "runs is required (§3.13.4)");
  if (log.contains("$schema")) c.need(log["$schema"].is_string() && Checker::absoluteUri(log["$schema"]), "sarifLog", "$schema a URI");
  if (log.contains("runs") && log["runs"].is_array())
    for (size_t i = 0; i < log["runs"].size(); ++i) c.run(log["runs"][i], "runs[" + std::to_string(i) + "]");
  return c.problems;
}

JunitCounts junitCounts(const std::string& xml) {
  JunitCounts n;
  const size_t suite = xml.find("<testsuite ");
  if (suite == std::string::npos) return n;
  const std::string tag = xml.substr(suite, xml.find('>', suite) - suite);
  n.tests = attribute(tag, "tests"), n.failures = attribute(tag, "failures");
  n.errors = attribute(tag, "errors"), n.skipped = attribute(tag, "skipped");
  const size_t end = xml.find("</testsuite>", suite);
  n.testcases = countTags(xml, "<testcase", suite, end);
  n.failureElements = countTags(xml, "<failure", suite, end);
  n.errorElements = countTags(xml, "<error", suite, end);
  n.skippedElements = countTags(xml, "<skipped", suite, end);
  return n;
}

} // namespace clitest
