// --sarif and --junit of check, sweep, compare and driver-check, end to end (docs/ci.md): the SARIF files hold what
// SARIF 2.1.0 requires (clitest::sarifProblems), the JUnit files parse and their counts match their elements and the
// JSON report's findings, every finding is named with its cause, fix, patches and edges, scene file and key line (or
// batch line), and states that are not clean never look clean.
#include "ci_check.h"
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <set>
#include <sys/stat.h>

using clitest::run;
using nlohmann::json;

namespace {

// The 1-based line of the first line of text that contains what (0: none).
int lineOf(const std::string& text, const std::string& what) {
  const size_t at = text.find(what);
  if (at == std::string::npos) return 0;
  int line = 1;
  for (size_t i = 0; i < at; ++i) line += text[i] == '\n';
  return line;
}

// Line n (1-based) of text.
std::string lineText(const std::string& text, int n) {
  size_t at = 0;
  for (int i = 1; i < n && at != std::string::npos; ++i) at = text.find('\n', at) + 1;
  return at == std::string::npos ? "" : text.substr(at, text.find('\n', at) - at);
}

std::string percentDecode(const std::string& s) {
  std::string out;
  for (size_t i = 0; i < s.size(); ++i)
    if (s[i] == '%' && i + 2 < s.size() + 0) out += static_cast<char>(std::stoi(s.substr(i + 1, 2), nullptr, 16)), i += 2;
    else out += s[i];
  return out;
}

bool endsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// A directory whose name has spaces, a non-ASCII byte and a '#' and '%' (all percent-encoded in URIs).
std::string oddDir() {
  const std::string dir = clitest::tmpDir() + "/ci dir #1 %20 \xc3\xa9t\xc3\xa9 " + std::string(60, 'x');
  ::mkdir(dir.c_str(), 0755);
  return dir;
}

json sarifOf(const std::string& path) {
  const json log = json::parse(clitest::readFile(path));
  const std::vector<std::string> problems = clitest::sarifProblems(log);
  for (const std::string& p : problems) UNSCOPED_INFO(p);
  CHECK(problems.empty());
  return log;
}

clitest::JunitCounts junitOf(const std::string& path) {
  const std::string xml = clitest::readFile(path);
  std::string why;
  INFO(why);
  REQUIRE(clitest::wellFormedXml(xml, why));
  const clitest::JunitCounts n = clitest::junitCounts(xml);
  CHECK(n.tests == n.testcases);
  CHECK(n.failures == n.failureElements);
  CHECK(n.errors == n.errorElements);
  CHECK(n.skipped == n.skippedElements);
  return n;
}

// The uri of a result's file, decoded.
std::string fileOf(const json& result) {
  return percentDecode(result["locations"][0]["physicalLocation"]["artifactLocation"]["uri"].get<std::string>());
}

bool hasLogical(const json& result, const std::string& fqnPart) {
  for (const json& l : result["locations"][0].value("logicalLocations", json::array()))
    if (l["fullyQualifiedName"].get<std::string>().find(fqnPart) != std::string::npos) return true;
  return false;
}

} // namespace

TEST_CASE("ci: a cracked sweep's SARIF and JUnit validate and name each cause with its fix, patches, edges, scene file and key line", "[cli]") {
  // terrain.toml with the neighbour rule off in the file itself: the key's line is where the results point.
  const std::string dir = oddDir();
  std::string text = clitest::readFile(clitest::source("docs/examples/terrain.toml"));
  const std::string on = "adjacency_clamp = \"pow2\"";
  REQUIRE(text.find(on) != std::string::npos);
  text.replace(text.find(on), on.size(), "adjacency_clamp = \"none\"");
  const std::string scene = dir + "/cracked scene.toml";
  clitest::writeFile(scene, text);
  const int keyLine = lineOf(text, "adjacency_clamp = \"none\"");
  const std::string js = dir + "/s.json", sarif = dir + "/s.sarif", junit = dir + "/s.xml";
  const auto r = run({"sweep", scene, "--orbit", "3", "--threads", "2", "-q", "--json", js, "--sarif", sarif, "--junit", junit});
  REQUIRE(r.status == 1);
  const json report = json::parse(clitest::readFile(js));
  const json log = sarifOf(sarif);
  const json& run0 = log["runs"][0];
  const json& rules = run0["tool"]["driver"]["rules"];
  const json& results = run0["results"];
  REQUIRE(!results.empty());
  // One rule per cause of the JSON report, its fix as help.
  std::map<std::string, std::string> fixes;
  for (const json& c : report["causes"]) fixes[c["cause"]] = c["fix"];
  REQUIRE(rules.size() == fixes.size());
  for (const json& rule : rules) {
    const std::string cause = rule["properties"]["cause"];
    REQUIRE(fixes.count(cause) == 1);
    CHECK(rule["help"]["text"] == fixes[cause]);
  }
  int64_t failures = 0; // the JSON's counted findings: per cause, the cameras where it appeared
  for (const json& c : report["causes"]) failures += c["cameras"].get<int64_t>();
  CHECK(int64_t(results.size()) == failures);
  for (const json& x : results) {
    CHECK(x["level"] == "error");
    CHECK(endsWith(fileOf(x), "/cracked scene.toml"));
    CHECK(x["locations"][0]["physicalLocation"]["region"]["startLine"] == keyLine);
    CHECK(hasLogical(x, "lod.adjacency_clamp"));
    CHECK(hasLogical(x, "camera["));
    CHECK((hasLogical(x, ".Ueq") || hasLogical(x, ".Veq")));
    CHECK(x["message"]["text"].get<std::string>().find("patch ") != std::string::npos);
    CHECK(!x["properties"]["fix"].get<std::string>().empty());
  }
  const clitest::JunitCounts n = junitOf(junit);
  CHECK(n.failures == failures);
  CHECK(n.errors == 0);
  CHECK(n.tests == report["cameras_done"].get<long>() + 1); // a case per camera, and the verdict
  const std::string xml = clitest::readFile(junit);
  CHECK(xml.find("fix: round the factors at a jump to powers of two") != std::string::npos);
  CHECK(xml.find("cracked scene.toml:" + std::to_string(keyLine) + " (the line of lod.adjacency_clamp)") != std::string::npos);
}

TEST_CASE("ci: a clean check has no SARIF result and no failing test case, and both say what was checked", "[cli]") {
  const std::string dir = clitest::tmpDir();
  const std::string js = dir + "/clean.json", sarif = dir + "/clean.sarif", junit = dir + "/clean.xml";
  const auto r = run({"check", clitest::source("docs/examples/terrain.toml"), "-q", "--json", js, "--sarif", sarif,
                      "--junit", junit});
  REQUIRE(r.status == 0);
  const json report = json::parse(clitest::readFile(js));
  REQUIRE(report["verdict"] == "watertight");
  const json log = sarifOf(sarif);
  const json& run0 = log["runs"][0];
  CHECK(run0["results"].empty());
  CHECK(run0["properties"]["verdict"] == "watertight");
  CHECK(run0["properties"]["stats"]["edges_checked"] == report["stats"]["edges_checked"]);
  CHECK(report["stats"]["edges_checked"].get<long>() > 0);
  const std::string note = run0["invocations"][0]["toolExecutionNotifications"][0]["message"]["text"];
  CHECK(note.find(std::to_string(report["stats"]["edges_checked"].get<long>()) + " shared edges checked") != std::string::npos);
  const clitest::JunitCounts n = junitOf(junit);
  CHECK(n.tests == 1);
  CHECK(n.failures + n.errors + n.skipped == 0);
  CHECK(clitest::readFile(junit).find("name=\"verdict: watertight\"") != std::string::npos);
}

TEST_CASE("ci: a check that classified no shared edge is an error in both files, never a clean run", "[cli]") {
  const std::string dir = clitest::tmpDir();
  const std::string sarif = dir + "/nothing.sarif", junit = dir + "/nothing.xml";
  const auto r = run({"check", clitest::source("docs/examples/terrain.toml"), "-q", "--eye", "0,40,-60", "--target",
                      "0,400,-600", "--sarif", sarif, "--junit", junit});
  REQUIRE(r.status == 1);
  const json log = sarifOf(sarif);
  const json& results = log["runs"][0]["results"];
  REQUIRE(results.size() == 1);
  CHECK(results[0]["level"] == "error");
  CHECK(results[0]["properties"]["finding_kind"] == "nothing_checked");
  const clitest::JunitCounts n = junitOf(junit);
  CHECK(n.errors == 1);
  CHECK(n.failures == 0);
}

TEST_CASE("ci: a sweep camera that classified no edge is skipped with the reason and a warning, a sweep that checked nothing is an error", "[cli]") {
  const std::string dir = clitest::tmpDir();
  const std::string away = dir + "/away.csv", mixed = dir + "/mixed.csv";
  const std::string header = "eye_x,eye_y,eye_z,target_x,target_y,target_z\n", awayRow = "0,40,-60,0,400,-600\n";
  clitest::writeFile(away, header + awayRow);
  clitest::writeFile(mixed, header + awayRow + "0,40,-60,0,0,0\n");
  const std::string scene = clitest::source("docs/examples/terrain.toml");
  const std::string sarif = dir + "/away.sarif", junit = dir + "/away.xml";
  REQUIRE(run({"sweep", scene, "--cameras", mixed, "-q", "--sarif", sarif, "--junit", junit}).status == 0);
  const clitest::JunitCounts m = junitOf(junit);
  CHECK(m.skipped == 1);
  CHECK(clitest::readFile(junit).find("<skipped message=\"nothing checked: ") != std::string::npos);
  const json mlog = sarifOf(sarif);
  const std::string warning = mlog["runs"][0]["invocations"][0]["toolExecutionNotifications"][0]["message"]["text"];
  CHECK(warning.find("1 cameras classified no shared edge") != std::string::npos);
  REQUIRE(run({"sweep", scene, "--cameras", away, "-q", "--sarif", sarif, "--junit", junit}).status == 1);
  const clitest::JunitCounts a = junitOf(junit);
  CHECK(a.errors == 1);
  const json alog = sarifOf(sarif);
  REQUIRE(alog["runs"][0]["results"].size() == 1);
  CHECK(alog["runs"][0]["results"][0]["level"] == "error");
  CHECK(alog["runs"][0]["results"][0]["properties"]["finding_kind"] == "nothing_checked");
}

TEST_CASE("ci: check's findings are one failure each, grouped by cause, at the key's line, and findings that do not count are skipped with the reason", "[cli]") {
  const std::string dir = clitest::tmpDir();
  const std::string scene = clitest::source("docs/examples/broken_lod.toml");
  const std::string js = dir + "/broken.json", sarif = dir + "/broken.sarif", junit = dir + "/broken.xml";
  REQUIRE(run({"check", scene, "-q", "--json", js, "--sarif", sarif, "--junit", junit}).status == 1);
  const json report = json::parse(clitest::readFile(js));
  int64_t counted = 0;
  for (const json& f : report["findings"]) counted += f["classification"] == "crack" && f["on_screen"] == true;
  counted += int64_t(report["holes"].size() + report["gpu_float"].size());
  const clitest::JunitCounts n = junitOf(junit);
  CHECK(n.failures == counted);
  CHECK(n.failures > 0);
  const json log = sarifOf(sarif);
  const int schemeLine = lineOf(clitest::readFile(scene), "scheme = \"patch_center\"");
  for (const json& x : log["runs"][0]["results"])
    CHECK(x["locations"][0]["physicalLocation"]["region"]["startLine"] == schemeLine);
  // T-junctions: exit 0, warnings in SARIF, a skipped case (with the reason) in JUnit, no failure.
  const std::string tj = dir + "/tj.xml", tjs = dir + "/tj.sarif";
  REQUIRE(run({"check", clitest::source("docs/examples/t_junction.toml"), "-q", "--sarif", tjs, "--junit", tj}).status == 0);
  const clitest::JunitCounts t = junitOf(tj);
  CHECK(t.failures == 0);
  CHECK(t.skipped == 1);
  CHECK(clitest::readFile(tj).find("--fail-on-tjunctions counts them") != std::string::npos);
  const json tlog = sarifOf(tjs);
  REQUIRE(!tlog["runs"][0]["results"].empty());
  for (const json& x : tlog["runs"][0]["results"]) CHECK(x["level"] == "warning");
}

TEST_CASE("ci: compare's SARIF and JUnit name each differing patch at its batch line", "[cli]") {
  const std::string dir = oddDir();
  const std::string batchText = clitest::readFile(clitest::source("docs/examples/compare_port.batch"));
  const std::string batch = dir + "/port batch.batch";
  clitest::writeFile(batch, batchText);
  const std::string capture = clitest::source("docs/examples/compare_port_bug.csv");
  const std::string sarif = dir + "/c.sarif", junit = dir + "/c.xml";
  const auto j = run({"compare", "--json", batch, capture, "--sarif", sarif, "--junit", junit});
  REQUIRE(j.status == 1);
  const json report = json::parse(j.out);
  const json log = sarifOf(sarif);
  const json& results = log["runs"][0]["results"];
  REQUIRE(int64_t(results.size()) == report["differing"].get<int64_t>());
  std::map<int64_t, json> listed; // the JSON report's differing patches by index: line and batch line
  for (const json& l : report["listed"]) listed[l["patch"].get<int64_t>()] = l;
  for (const json& x : results) {
    CHECK(endsWith(fileOf(x), "/port batch.batch"));
    const int line = x["locations"][0]["physicalLocation"]["region"]["startLine"];
    const json& l = listed.at(x["properties"]["patch"].get<int64_t>());
    CHECK(l["line"] == line);
    CHECK(l["batch_line"] == x["properties"]["batch_line"]);
    CHECK(lineText(batchText, line).rfind("quad ", 0) == 0); // a patch line of the file, not a comment
    CHECK(hasLogical(x, "patch[" + std::to_string(l["patch"].get<int64_t>()) + "]"));
    CHECK(x["properties"]["fix"].get<std::string>().find("reciprocal rounding") != std::string::npos);
  }
  const clitest::JunitCounts n = junitOf(junit);
  CHECK(n.failures == report["differing"].get<long>());
  CHECK(n.tests == n.failures + 1);
  // The same capture as the reference: no result, a passing case that says what was compared.
  const auto hex = run({"tessellate", "--format", "hex", batch});
  const std::string same = dir + "/same.out";
  clitest::writeFile(same, hex.out);
  REQUIRE(run({"compare", batch, same, "--sarif", sarif, "--junit", junit}).status == 0);
  CHECK(sarifOf(sarif)["runs"][0]["results"].empty());
  const clitest::JunitCounts s = junitOf(junit);
  CHECK(s.tests == 1);
  CHECK(s.failures + s.errors == 0);
  CHECK(clitest::readFile(junit).find("3 patches compared") != std::string::npos);
}

TEST_CASE("ci: --sarif and --junit are refused before any work when they name another output or an input", "[cli]") {
  // Copies of the inputs: a regression must not overwrite the source tree's files.
  const std::string dir = clitest::tmpDir();
  const std::string scene = dir + "/refused scene.toml";
  clitest::writeFile(scene, clitest::readFile(clitest::source("docs/examples/terrain.toml")));
  const std::string a = dir + "/refused.sarif", b = dir + "/refused.json";
  auto r = run({"sweep", scene, "--orbit", "2", "--sarif", a, "--junit", a});
  CHECK(r.status == 2);
  CHECK(r.err.find("--sarif") != std::string::npos);
  CHECK(r.err.find("--junit") != std::string::npos);
  r = run({"check", scene, "--sarif", b, "--json", b});
  CHECK(r.status == 2);
  r = run({"check", scene, "--junit", scene});
  CHECK(r.status == 2);
  CHECK(r.err.find("SCENE") != std::string::npos);
  r = run({"check", scene, "--sarif", "-", "-q"}); // stdout carries the text or JSON report
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  r = run({"check", scene, "--sarif", dir + "/no such dir/x.sarif"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--sarif") != std::string::npos);
  const std::string batch = dir + "/refused.batch";
  clitest::writeFile(batch, clitest::readFile(clitest::source("docs/examples/compare_port.batch")));
  r = run({"compare", batch, clitest::source("docs/examples/compare_port_bug.csv"), "--junit", batch});
  CHECK(r.status == 2);
  CHECK(clitest::readFile(scene) == clitest::readFile(clitest::source("docs/examples/terrain.toml")));
  CHECK(!clitest::fileExists(a));
  CHECK(!clitest::fileExists(b));
}

TEST_CASE("ci: driver-check's SARIF points at the --write-batch lines of --random patches (GL builds only)", "[cli]") {
  const std::string dir = clitest::tmpDir();
  const std::string batch = dir + "/driver.batch", sarif = dir + "/driver.sarif", junit = dir + "/driver.xml";
  const auto r = run({"driver-check", "--random", "20", "--port-bug", "outer_factors_rotated", "--write-batch", batch,
                      "--sarif", sarif, "--junit", junit, "--json"});
  if (r.err.find("built without OpenGL") != std::string::npos || r.status == 3) {
    WARN("driver-check: no GL module or no context here: " + r.err);
    return;
  }
  REQUIRE(r.status == 1);
  const json report = json::parse(r.out);
  const json log = sarifOf(sarif);
  const json& results = log["runs"][0]["results"];
  REQUIRE(int64_t(results.size()) == report["differing"].get<int64_t>());
  std::map<int64_t, int> lines; // the JSON report's differing patches: index -> line in the --write-batch file
  for (const json& l : report["listed"]) lines[l["patch"].get<int64_t>()] = l["line"].get<int>();
  for (const json& x : results) {
    CHECK(endsWith(fileOf(x), "/driver.batch"));
    if (lines.count(x["properties"]["patch"].get<int64_t>()))
      CHECK(lines[x["properties"]["patch"].get<int64_t>()] ==
            x["locations"][0]["physicalLocation"]["region"]["startLine"].get<int>());
  }
  CHECK(junitOf(junit).failures == report["differing"].get<long>());
}
