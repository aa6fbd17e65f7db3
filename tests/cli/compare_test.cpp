// fftess compare, end to end: the docs examples, exit statuses 0/1/2, bad input naming FILE:LINE with no output.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

using clitest::run;
using nlohmann::json;

TEST_CASE("compare: the ten-line CSV example of docs/compare.md is the reference's output", "[cli]") {
  const auto r = run({"compare", clitest::source("docs/examples/compare_points.batch"),
                      clitest::source("docs/examples/compare_points.csv")});
  CHECK(r.status == 0);
  CHECK(r.err.empty());
  CHECK(r.out.find("1 patches, 1 same, 0 differ") != std::string::npos);
}

TEST_CASE("compare: the float-division port of the README is named (text and JSON), exit 1", "[cli]") {
  const std::string batch = clitest::source("docs/examples/compare_port.batch");
  const std::string bug = clitest::source("docs/examples/compare_port_bug.csv");
  const auto r = run({"compare", batch, bug});
  CHECK(r.status == 1);
  CHECK(r.out.find("verdict: differs; every difference is reproduced by float_division") != std::string::npos);
  CHECK(r.out.find("reciprocal rounding") != std::string::npos);
  const auto j = run({"compare", "--json", batch, bug});
  REQUIRE(j.status == 1);
  const json doc = json::parse(j.out);
  CHECK(doc["patches"] == 3);
  CHECK(doc["differing"] == 2);
  CHECK(doc["by_kind"]["points_differ"] == 2);
  CHECK(doc["explained_by"] == json::array({"float_division"}));
  CHECK(doc["listed"][0]["points"][0]["step"] == "reciprocal rounding");
}

TEST_CASE("compare: a hex capture from tessellate is the same, also in strict order, a lost patch differs", "[cli]") {
  const std::string batch = clitest::source("docs/examples/compare_port.batch");
  const auto hex = run({"tessellate", "--format", "hex", batch});
  REQUIRE(hex.status == 0);
  const std::string path = clitest::tmpDir() + "/port.out";
  clitest::writeFile(path, hex.out);
  CHECK(run({"compare", batch, path}).status == 0);
  CHECK(run({"compare", "--strict-order", batch, path}).status == 0);
  const std::string lost = clitest::tmpDir() + "/lost.out";
  clitest::writeFile(lost, hex.out.substr(0, hex.out.find("patch 1 ")) + hex.out.substr(hex.out.find("patch 2 ")));
  const auto r = run({"compare", batch, lost});
  CHECK(r.status == 1);
  CHECK(r.out.find("culled_in_capture") != std::string::npos);
}

TEST_CASE("compare: bad input exits 2 naming FILE:LINE, and prints no report", "[cli]") {
  const std::string batch = clitest::source("docs/examples/compare_points.batch");
  const std::string bad = clitest::tmpDir() + "/bad.csv";
  clitest::writeFile(bad, "patch,primitive,vertex,u,v\n0,0,0,0,1\n0,1,0,0.5,nope\n");
  auto r = run({"compare", batch, bad});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "fftess: error: " + bad + ":3: field 5 (v) 'nope': not a number\n");
  clitest::writeFile(bad, "0,0,0,0,1\n5,0,0,0,0\n");
  r = run({"compare", batch, bad});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find(bad + ":2: patch 5 is not in") != std::string::npos);
  r = run({"compare", batch, clitest::tmpDir() + "/does-not-exist.csv"});
  CHECK(r.status == 2);
  const std::string badBatch = clitest::tmpDir() + "/bad.batch";
  clitest::writeFile(badBatch, "# x\nquad integer point hw 2 2 2 2 2\n");
  r = run({"compare", badBatch, bad});
  CHECK(r.status == 2);
  CHECK(r.err.find(badBatch + ":2: ") != std::string::npos);
  // A triangle capture for a point patch: primitive size mismatch, named with the capture line.
  clitest::writeFile(bad, "0,0,0,0,0\n0,0,1,1,0\n0,0,2,1,1\n");
  r = run({"compare", batch, bad});
  CHECK(r.status == 2);
  CHECK(r.err.find(bad + ":1: patch 0: the capture has 3 vertices per primitive") != std::string::npos);
}

TEST_CASE("compare: every golden .out file is the reference's output for its .in, in strict order", "[cli]") {
  for (const char* set : {"quad-hw", "tri-hw", "isoline-hw", "quad-hlsl", "tri-hlsl", "isoline-hlsl"}) {
    INFO(set);
    const auto r = run({"compare", "--strict-order", clitest::golden(std::string(set) + ".in"),
                        clitest::golden(std::string(set) + ".out")});
    CHECK(r.status == 0);
    CHECK(r.out.find("verdict: same") != std::string::npos);
  }
}

TEST_CASE("compare: the JSON names its schema, kind, fftess version and batch, and each listed patch's batch line",
          "[cli]") {
  const std::string batch = clitest::source("docs/examples/compare_port.batch");
  const auto j = run({"compare", "--json", batch, clitest::source("docs/examples/compare_port_bug.csv")});
  REQUIRE(j.status == 1);
  const json doc = json::parse(j.out);
  CHECK(doc["version"] == 2);
  CHECK(doc["kind"] == "compare");
  CHECK(run({"--version"}).out == "fftess " + doc["fftess_version"].get<std::string>() + "\n");
  CHECK(doc["batch"] == batch);
  CHECK_FALSE(doc.contains("generated_by"));
  REQUIRE(doc["listed"].size() == 2);
  // Lines 3 and 4 of the file, "quad integer point hw 3 3 3 3 3 3" and "... triangle_cw hw 5 7 5 7 6 5", hex factors.
  CHECK(doc["listed"][0]["line"] == 3);
  CHECK(doc["listed"][0]["batch_line"] ==
        "quad integer point hw 0x40400000 0x40400000 0x40400000 0x40400000 0x40400000 0x40400000");
  CHECK(doc["listed"][1]["line"] == 4);
  CHECK(doc["listed"][1]["batch_line"] ==
        "quad integer triangle_cw hw 0x40a00000 0x40e00000 0x40a00000 0x40e00000 0x40c00000 0x40a00000");
  const auto text = run({"compare", batch, clitest::source("docs/examples/compare_port_bug.csv")});
  CHECK(text.out.find("patch 1 (" + batch + ":4): points_differ: 62 reference primitives, 62 in the capture; 40 "
                      "reference points missing, 40 points the reference lacks\n  batch line: quad integer "
                      "triangle_cw hw 0x40a00000 0x40e00000 0x40a00000 0x40e00000 0x40c00000 0x40a00000\n") !=
        std::string::npos);
}
