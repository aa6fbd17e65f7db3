// fftess prove end to end on rings_small (small regions, so the proofs take a fraction of a second): the three
// verdicts and their exit statuses, the counterexample camera re-run through check, bad boxes; and --gpu-float
// conformant on check and sweep: its negative control (docs/examples/gpu_float_control.toml) is watertight for a
// plain sweep and flagged with --gpu-float conformant, the default rings_small is not flagged.
#include "run.h"
#include "usage_error.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

using clitest::run;
using nlohmann::json;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");
const std::string kControl = clitest::source("docs/examples/gpu_float_control.toml");

bool has(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

// The line of `text` that starts with `prefix` ("" if none).
std::string lineStarting(const std::string& text, const std::string& prefix) {
  size_t at = 0;
  while (at < text.size()) {
    const size_t end = text.find('\n', at);
    const std::string line = text.substr(at, end == std::string::npos ? std::string::npos : end - at);
    if (line.rfind(prefix, 0) == 0) return line;
    if (end == std::string::npos) break;
    at = end + 1;
  }
  return "";
}

} // namespace

TEST_CASE("prove: a point region at rings_small's camera is PROVED with exit 0, its region and stats stated",
          "[cli][prove]") {
  const auto r = run({"prove", kRings, "--eye-box", "10,25,-70,10,25,-70", "--target-box", "0,0,0,0,0,0", "-j", "2"});
  INFO(r.out << r.err);
  CHECK(r.status == 0);
  CHECK(has(r.out, "  region         eye (10, 25, -70) target (0, 0, 0)\n"));
  CHECK(!has(r.out, "the default region"));
  const std::string stats = lineStarting(r.out, "  stats          regions 1 (1 proved, 0 undecided), depth 0, pairs by trace ");
  CHECK(!stats.empty());
  CHECK(has(stats, " / by value "));
  CHECK(has(stats, " / off screen "));
  CHECK(lineStarting(r.out, "PROVED: ") != "");
  CHECK(!has(r.out, "COUNTEREXAMPLE"));
}

TEST_CASE("prove: without the clamp the counterexample camera's printed values make check confirm the same finding",
          "[cli][prove]") {
  // A box whose corners are not simple decimals: the sampled camera (the box's centre or its simplest floats) is
  // printed with %.9g, which check's --eye / --target read back to the same floats.
  const std::string path = clitest::tmpDir() + "/prove_counterexample.json";
  const auto r = run({"prove", kRings, "--set", "lod.adjacency_clamp=none", "--eye-box", "9.3,24.1,-70.7,10.9,25.3,-69.1",
                      "--target-box", "-0.3,0,0.2,0.1,0,0.7", "-j", "2", "--show", "1", "--json", path});
  INFO(r.out << r.err);
  REQUIRE(r.status == 1);
  const std::string line = lineStarting(r.out, "COUNTEREXAMPLE: eye (");
  REQUIRE(!line.empty());
  float e[3], t[3];
  REQUIRE(std::sscanf(line.c_str(), "COUNTEREXAMPLE: eye (%f, %f, %f) target (%f, %f, %f)", &e[0], &e[1], &e[2], &t[0],
                      &t[1], &t[2]) == 6);
  // The printed values are the camera's floats exactly (the JSON report's numbers are those floats in double).
  const json report = json::parse(clitest::readFile(path));
  REQUIRE(report.at("verdict") == "COUNTEREXAMPLE");
  for (int k = 0; k < 3; ++k) {
    CHECK(report.at("counterexample").at("eye").at(k).get<double>() == static_cast<double>(e[k]));
    CHECK(report.at("counterexample").at("target").at(k).get<double>() == static_cast<double>(t[k]));
  }
  const std::string finding = lineStarting(r.out, "crack      ");
  REQUIRE(!finding.empty());
  const std::string eye = line.substr(line.find("eye (") + 5, line.find(") target") - line.find("eye (") - 5);
  const std::string target = line.substr(line.find("target (") + 8, line.size() - line.find("target (") - 9);
  auto commas = [](std::string s) {
    std::string out;
    for (char c : s)
      if (c != ' ') out += c;
    return out;
  };
  CHECK(has(r.out, "  confirm with   fftess check " + kRings + " --set lod.adjacency_clamp=none --eye " + commas(eye) +
                       " --target " + commas(target) + "\n"));
  const auto c = run({"check", kRings, "--set", "lod.adjacency_clamp=none", "--eye", commas(eye), "--target",
                      commas(target), "--show", "1000"});
  INFO(c.out);
  CHECK(c.status == 1);
  // The very finding prove printed (sides, gap, where; then its cause), as check lists it under its cause.
  size_t cut = finding.find("; ");
  while (cut != std::string::npos && finding.compare(cut + 2, 22, "farthest vertex of all") == 0)
    cut = finding.find("; ", cut + 2);
  REQUIRE(cut != std::string::npos);
  CHECK(has(c.out, "\n      " + finding.substr(11, cut - 11) + "\n"));
}

TEST_CASE("prove: a region left open at --max-regions 1 is UNDECIDED with exit 1, its regions and why listed",
          "[cli][prove]") {
  const auto r = run({"prove", kRings, "--eye-box", "9,24,-71,11,26,-69", "--target-box", "0,0,0,0,0,0",
                      "--max-regions", "1", "-j", "2"});
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  const std::string head = lineStarting(r.out, "UNDECIDED: ");
  CHECK(has(head, " regions left open (never PROVED while any remain)"));
  CHECK(has(r.out, "  eye (10, 24, -71)..(11, 26, -69) target (0, 0, 0) (depth 1): "));
  CHECK(!has(r.out, "PROVED:"));
  // The JSON report says the same.
  const std::string path = clitest::tmpDir() + "/prove_undecided.json";
  const auto j = run({"prove", kRings, "--eye-box", "9,24,-71,11,26,-69", "--target-box", "0,0,0,0,0,0",
                      "--max-regions", "1", "-j", "2", "--json", path, "-q"});
  CHECK(j.status == 1);
  CHECK(j.out.empty());
  const json report = json::parse(clitest::readFile(path));
  CHECK(report.at("kind") == "prove");
  CHECK(report.at("verdict") == "UNDECIDED");
  CHECK(report.at("undecided").size() >= 1);
  CHECK(report.at("stats").at("regions_undecided").get<int64_t>() >= 1);
  CHECK(report.at("counterexample").is_null());
}

TEST_CASE("prove: a bad --eye-box or --target-box is a usage error naming the option and the bad number's position",
          "[cli][prove]") {
  clitest::checkUsageError({"prove", kRings, "--eye-box", "1,2,x,4,5,6"}, "--eye-box '1,2,x,4,5,6': number 3 ('x')");
  clitest::checkUsageError({"prove", kRings, "--eye-box", "1,2,3,4,5"}, "--eye-box '1,2,3,4,5': 5 numbers, expected 6");
  clitest::checkUsageError({"prove", kRings, "--target-box", "1,2,3,4,5,6,7"}, "--target-box '1,2,3,4,5,6,7': more than 6");
  clitest::checkUsageError({"prove", kRings, "--target-box", "0,0,0,0,nan,0"}, "--target-box '0,0,0,0,nan,0': number 5");
  clitest::checkUsageError({"prove", kRings, "--eye-box", "1,2,3,0,5,6"}, "--eye-box '1,2,3,0,5,6': number 4 (X1 = 0) is below number 1");
  clitest::checkUsageError({"prove", kRings, "--max-depth", "-1"}, "--max-depth -1");
}

TEST_CASE("gpu float: the negative control is watertight for a plain sweep and flagged by --gpu-float conformant",
          "[cli][gpu_float]") {
  const auto plain = run({"sweep", kControl, "--random", "40", "-j", "2"});
  INFO(plain.out << plain.err);
  CHECK(plain.status == 0);
  CHECK(has(plain.out, "verdict: WATERTIGHT from all 40 cameras"));
  const auto gpu = run({"sweep", kControl, "--random", "40", "-j", "2", "--gpu-float", "conformant"});
  INFO(gpu.out << gpu.err);
  CHECK(gpu.status == 1);
  CHECK(has(gpu.out, "verdict: MAY CRACK ON SOME GPUS: "));
  CHECK(has(gpu.out, "    may crack on some GPUs: the two sides compute the factor through different operations "));
  // The operation named: the add a compiler may fuse with a product, on each side.
  CHECK(has(gpu.out, "the first operation that differs: side a add~fma("));
  CHECK(has(gpu.out, "      fix: declare the edge factor's computation precise"));
  // check: the same, with the JSON report's entries.
  const std::string path = clitest::tmpDir() + "/gpu_float_check.json";
  const auto c = run({"check", kControl, "--gpu-float", "conformant", "--json", path, "-q"});
  CHECK(c.status == 1);
  const json j = json::parse(clitest::readFile(path));
  CHECK(j.at("gpu_float_mode") == "conformant");
  CHECK(j.at("verdict") == "gpu_float");
  const int64_t n = j.at("stats").at("gpu_float_findings").get<int64_t>();
  CHECK(n > 0);
  REQUIRE(j.at("gpu_float").is_array());
  CHECK(j.at("gpu_float").size() == static_cast<size_t>(n));
  const json& g = j.at("gpu_float").at(0);
  CHECK(has(g.at("cause").get<std::string>(), "may crack on some GPUs"));
  for (const char* side : {"a", "b"}) {
    CHECK(g.at(side).at("patch").at("index").is_number_integer());
    CHECK(g.at(side).at("operation").get<std::string>().rfind("add~fma(", 0) == 0);
    CHECK(std::stof(g.at(side).at("conformant_lo").get<std::string>()) <
          std::stof(g.at(side).at("conformant_hi").get<std::string>()));
  }
  CHECK(g.at("a").at("factor") == g.at("b").at("factor")); // a match with lod/'s C++ build
}

TEST_CASE("gpu float: the default rings_small and the control with half_sum have no GPU float finding",
          "[cli][gpu_float]") {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"check", kRings, "--gpu-float", "conformant"},
        std::vector<std::string>{"check", kControl, "--gpu-float", "conformant", "--set", "lod.sphere_centre=half_sum"}}) {
    const auto r = run(args);
    INFO(args[1] << "\n" << r.out << r.err);
    CHECK(r.status == 0);
    const std::string line = lineStarting(r.out, "  gpu float      ");
    CHECK(has(line, " matching pairs evaluated under a conformant GPU compiler's choices (--gpu-float conformant), 0 "
                    "may crack on some GPUs"));
    CHECK(!has(line, "  gpu float      0 matching"));
    CHECK(has(r.out, "verdict: watertight\n"));
  }
}

TEST_CASE("gpu float: scenes the model does not cover and unknown values are usage errors", "[cli][gpu_float]") {
  clitest::checkUsageError({"check", clitest::source("docs/examples/geomorph.toml"), "--gpu-float", "conformant"},
                           "--gpu-float conformant: lod.scheme = \"geomorph\"");
  clitest::checkUsageError({"sweep", clitest::source("docs/examples/gpu_sphere_hlsl.toml"), "--gpu-float", "conformant"},
                           "--gpu-float conformant: lod.shader");
  clitest::checkUsageError({"check", kRings, "--gpu-float", "fast"}, "--gpu-float 'fast': expected off|conformant");
}

TEST_CASE("prove: rings_small's default region is PROVED with the pow2 clamp and stated as the default", "[cli][prove][slow]") {
  // The first "Done when": `fftess prove docs/examples/rings_small.toml` says PROVED (exit 0); the region is
  // the scene camera's eye and target +-2^-12 of the terrain's side (256: +-0.0625), and the output says it is the
  // default one.
  const auto d = run({"prove", kRings, "-j", "2"});
  INFO(d.out << d.err);
  CHECK(d.status == 0);
  CHECK(has(lineStarting(d.out, "  region         eye ("),
            "eye (9.9375, 24.9375, -70.0625)..(10.0625, 25.0625, -69.9375) target (-0.0625, -0.0625, -0.0625)..(0.0625, "
            "0.0625, 0.0625) (the default region: the scene camera's eye and target, each +-2^-12 of the terrain's side)"));
  CHECK(has(d.out, "\nPROVED: "));
}
