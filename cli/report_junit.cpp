// JUnit XML of a CiReport (report_junit.h).
#include "report_junit.h"
#include "common.h"

namespace fftess::cli {

namespace {

// Text for an XML attribute or element: printable() (control bytes and bytes that are not UTF-8 as \xHH, never
// cut), then & < > " as entities; newlines kept in element text (keepNewlines), escaped in attributes.
std::string xmlText(const std::string& s, bool keepNewlines) {
  std::string out;
  size_t i = 0;
  while (i <= s.size()) {
    const size_t nl = keepNewlines ? std::min(s.find('\n', i), s.size()) : s.size();
    out += xmlEscape(printable(s.substr(i, nl - i), std::string::npos));
    if (nl < s.size()) out += '\n';
    i = nl + 1;
  }
  return out;
}

std::string attr(const char* name, const std::string& v) { return std::string(" ") + name + "=\"" + xmlText(v, false) + "\""; }

std::string placeText(const CiResult& x) {
  if (x.file.empty()) return "";
  return x.file + (x.line >= 1 ? ":" + std::to_string(x.line) : "") + (x.lineWhy.empty() ? "" : " (" + x.lineWhy + ")");
}

std::string childXml(const CiResult& x) {
  const char* tag = x.outcome == CiOutcome::Failure ? "failure" : "error";
  std::string body = x.message + "\nfix: " + (x.fix.empty() ? "(no fix known)" : x.fix);
  const std::string place = placeText(x);
  if (!place.empty()) body += "\nat " + place;
  return std::string("      <") + tag + attr("message", (x.where.empty() ? "" : x.where + ": ") + x.rule) +
         attr("type", x.kind) + ">" + xmlText(body, true) + "</" + tag + ">\n";
}

} // namespace

CiCounts ciCounts(const CiReport& r) {
  CiCounts c;
  for (const CiCase& k : r.cases) {
    ++c.tests;
    bool counted = false;
    for (size_t i : k.results) {
      const CiOutcome o = r.results[i].outcome;
      c.failures += o == CiOutcome::Failure;
      c.errors += o == CiOutcome::Error;
      counted = counted || o != CiOutcome::NotCounted;
    }
    c.skipped += !counted && !k.skipped.empty();
  }
  return c;
}

std::string junitText(const CiReport& r) {
  const CiCounts n = ciCounts(r);
  auto counts = [&] {
    return attr("tests", std::to_string(n.tests)) + attr("failures", std::to_string(n.failures)) +
           attr("errors", std::to_string(n.errors)) + attr("skipped", std::to_string(n.skipped));
  };
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites" + attr("name", "fftess " + r.command) +
                  counts() + ">\n  <testsuite" + attr("name", r.suite) + counts() + ">\n";
  if (!r.properties.empty()) {
    x += "    <properties>\n";
    for (auto it = r.properties.begin(); it != r.properties.end(); ++it)
      x += "      <property" + attr("name", it.key()) +
           attr("value", it->is_string() ? it->get<std::string>()
                                         : it->dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace)) +
           "/>\n";
    x += "    </properties>\n";
  }
  const std::string classname = "fftess." + r.command;
  for (const CiCase& k : r.cases) {
    x += "    <testcase" + attr("classname", classname) + attr("name", k.name) + ">\n";
    bool counted = false;
    std::string out = k.out;
    for (size_t i : k.results) {
      const CiResult& res = r.results[i];
      if (res.outcome != CiOutcome::NotCounted) {
        x += childXml(res);
        counted = true;
      } else {
        const std::string place = placeText(res);
        out += (out.empty() ? "" : "\n") + std::string("not counted: ") + (res.where.empty() ? "" : res.where + ": ") +
               res.message + "; fix: " + res.fix + (place.empty() ? "" : "; at " + place);
      }
    }
    if (!counted && !k.skipped.empty()) x += "      <skipped" + attr("message", k.skipped) + "/>\n";
    if (!out.empty()) x += "      <system-out>" + xmlText(out, true) + "</system-out>\n";
    x += "    </testcase>\n";
  }
  return x + "  </testsuite>\n</testsuites>\n";
}

} // namespace fftess::cli
