// fftess compare, triangle level: a port's own triangulation listed in the text and the JSON (hand-checked factor-1
// quad), rotated in strict order, and --svg: the picture of the first differing patches, all or nothing.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <regex>

using clitest::run;
using nlohmann::json;

namespace {

// quad integer factor 1: the reference's points (0,0) (1,0) (1,1) (0,1), triangles 0 1 3 and 1 2 3. The port numbers
// them (1,1) (0,1) (0,0) (1,0) and splits along (0,0)-(1,1): triangles 2 3 0 and 2 0 1.
const char* const kPortBlock = "patch 0 points 4 indices 6\n"
                               "3f800000 3f800000\n00000000 3f800000\n00000000 00000000\n3f800000 00000000\n"
                               "2 3 0\n2 0 1\n";

std::string writeTmp(const std::string& name, const std::string& text) {
  const std::string path = clitest::tmpDir() + "/" + name;
  clitest::writeFile(path, text);
  return path;
}

json vertex(double u, double v) {
  auto bits = [](double x) { return std::string(x == 0 ? "0x00000000" : "0x3f800000"); };
  return json{{"u", u}, {"v", v}, {"u_bits", bits(u)}, {"v_bits", bits(v)}, {"u_16_16", u * 65536}, {"v_16_16", v * 65536}};
}

size_t count(const std::string& s, const std::string& what) {
  size_t n = 0;
  for (size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

} // namespace

TEST_CASE("compare: a port with its own triangulation lists the missing and extra triangles in the text and the JSON",
          "[cli]") {
  const std::string batch = writeTmp("q1.batch", "quad integer triangle_cw hw 1 1 1 1 1 1\n");
  const std::string cap = writeTmp("q1.out", kPortBlock);
  const auto r = run({"compare", batch, cap});
  CHECK(r.status == 1);
  CHECK(r.out.find("patch 0 (" + batch + ":1): triangulation_differs: 2 reference primitives, 2 in the capture\n"
                   "  batch line: quad integer triangle_cw hw 0x3f800000 0x3f800000 0x3f800000 0x3f800000 0x3f800000 "
                   "0x3f800000\n"
                   "  2 triangles only in the reference:\n"
                   "    primitive 0, reference indices 0 1 3: (0, 0) (1, 0) (0, 1); 16.16: (0, 0) (65536, 0) (0, 65536)\n"
                   "    primitive 1, reference indices 1 2 3: (1, 0) (1, 1) (0, 1); 16.16: (65536, 0) (65536, 65536) "
                   "(0, 65536)\n"
                   "  2 triangles only in the capture:\n"
                   "    primitive 0, indices 2 3 0, reference indices 0 1 2: (0, 0) (1, 0) (1, 1); 16.16: (0, 0) "
                   "(65536, 0) (65536, 65536)\n"
                   "    primitive 1, indices 2 0 1, reference indices 0 2 3: (0, 0) (1, 1) (0, 1); 16.16: (0, 0) "
                   "(65536, 65536) (0, 65536)\n") != std::string::npos);
  const auto j = run({"compare", "--json", batch, cap});
  REQUIRE(j.status == 1);
  const json doc = json::parse(j.out);
  CHECK(doc["by_kind"]["triangulation_differs"] == 1);
  const json& t = doc["listed"][0]["triangles"];
  const json expected = {
      {"only_in_reference_count", 2},
      {"only_in_capture_count", 2},
      {"only_in_reference",
       {{{"primitive", 0}, {"vertices", {vertex(0, 0), vertex(1, 0), vertex(0, 1)}}, {"indices", {0, 1, 3}},
         {"reference_indices", {0, 1, 3}}},
        {{"primitive", 1}, {"vertices", {vertex(1, 0), vertex(1, 1), vertex(0, 1)}}, {"indices", {1, 2, 3}},
         {"reference_indices", {1, 2, 3}}}}},
      {"only_in_capture",
       {{{"primitive", 0}, {"vertices", {vertex(0, 0), vertex(1, 0), vertex(1, 1)}}, {"indices", {2, 3, 0}},
         {"reference_indices", {0, 1, 2}}},
        {{"primitive", 1}, {"vertices", {vertex(0, 0), vertex(1, 1), vertex(0, 1)}}, {"indices", {2, 0, 1}},
         {"reference_indices", {0, 2, 3}}}}}};
  CHECK(t == expected);
  CHECK(doc["listed"][0]["points"] == json::array()); // the points agree
}

TEST_CASE("compare: the triangulation example of docs/compare.md lists 16 triangles only in each side", "[cli]") {
  const auto r = run({"compare", clitest::source("docs/examples/compare_triangulation.batch"),
                      clitest::source("docs/examples/compare_triangulation.csv")});
  CHECK(r.status == 1);
  CHECK(r.out.find("triangulation_differs: 32 reference primitives, 32 in the capture\n"
                   "  batch line: quad integer triangle_cw hw 0x40800000 0x40800000 0x40800000 0x40800000 0x40800000 "
                   "0x40800000\n"
                   "  16 triangles only in the reference (the first 8):\n"
                   "    primitive 0, reference indices 0 1 16: (0, 1) (0, 0.75) (0.25, 0.75); 16.16: (0, 65536) "
                   "(0, 49152) (16384, 49152)\n") != std::string::npos);
  CHECK(r.out.find("  16 triangles only in the capture (the first 8):\n"
                   "    primitive 4, reference indices 2 17 16: (0, 0.5) (0.25, 0.5) (0.25, 0.75); 16.16: (0, 32768) "
                   "(16384, 32768) (16384, 49152)\n") != std::string::npos);
  CHECK(r.out.find("summary: 1 patches, 0 same, 1 differ (triangulation_differs 1)") != std::string::npos);
}

TEST_CASE("compare: triangles starting at another vertex are rotated in strict order, same by default", "[cli]") {
  const std::string batch = writeTmp("q1r.batch", "quad integer triangle_cw hw 1 1 1 1 1 1\n");
  const std::string cap = writeTmp("q1r.out", "patch 0 points 4 indices 6\n00000000 00000000\n3f800000 00000000\n"
                                              "3f800000 3f800000\n00000000 3f800000\n1 3 0\n1 2 3\n");
  CHECK(run({"compare", batch, cap}).status == 0);
  const auto r = run({"compare", "--strict-order", batch, cap});
  CHECK(r.status == 1);
  CHECK(r.out.find("rotated: 2 reference primitives, 2 in the capture; 1 start at another vertex\n") !=
        std::string::npos);
  const json doc = json::parse(run({"compare", "--strict-order", "--json", batch, cap}).out);
  CHECK(doc["listed"][0]["kind"] == "rotated");
  CHECK(doc["listed"][0]["rotated_primitives"] == 1);
}

TEST_CASE("compare --svg draws the first six differing patches, reference and capture over each other, with a legend",
          "[cli]") {
  // Eight patches: patch 0 the port above, patches 1..7 lost by the capture (culled_in_capture), patch 8 the same.
  std::string lines;
  for (int i = 0; i < 9; ++i) lines += "quad integer triangle_cw hw 1 1 1 1 1 1\n";
  const std::string batch = writeTmp("svg.batch", lines);
  const std::string cap = writeTmp("svg.out", std::string(kPortBlock) +
                                                  "patch 8 points 4 indices 6\n00000000 00000000\n3f800000 00000000\n"
                                                  "3f800000 3f800000\n00000000 3f800000\n0 1 3\n1 2 3\n");
  const std::string svg = clitest::tmpDir() + "/compare.svg";
  const auto r = run({"compare", batch, cap, "--svg", svg});
  CHECK(r.status == 1);
  CHECK(r.err.empty());
  const std::string text = clitest::readFile(svg);
  std::string why;
  REQUIRE(clitest::wellFormedXml(text, why));
  CHECK(text.find("9 patches, 1 same, 8 differ; the first 6 differing drawn") != std::string::npos);
  CHECK(text.find(">patch 0 (line 1):") != std::string::npos); // the kind on the next line: the panel is narrow
  CHECK(text.find(">triangulation_differs<") != std::string::npos);
  CHECK(text.find("patch 5 (line 6): culled_in_capture") != std::string::npos);
  CHECK(text.find("patch 6 (") == std::string::npos);
  CHECK(text.find("2 only in the reference, 2 only in the capture") != std::string::npos);
  // Panel 0: the reference's two triangles and the capture's two, each side's pair highlighted; panels 1..5: the
  // reference's pair, highlighted.
  CHECK(count(text, "<path class=\"r\" ") == 6 + 1); // + the legend's swatch
  CHECK(count(text, "<path class=\"c\" ") == 1 + 1);
  CHECK(count(text, "<path class=\"or\" ") == 6 + 1);
  CHECK(count(text, "<path class=\"oc\" ") == 1 + 1);
  const std::regex panel0("<path class=\"oc\" d=\"M([0-9.]+) ([0-9.]+)L([0-9.]+) ([0-9.]+)L([0-9.]+) ([0-9.]+)Z");
  std::smatch m;
  REQUIRE(std::regex_search(text, m, panel0)); // the capture's first triangle (0,0) (1,0) (1,1): v up on the page
  CHECK(std::stod(m[3]) > std::stod(m[1]));
  CHECK(m[4] == m[2]);
  CHECK(m[5] == m[3]);
  CHECK(std::stod(m[6]) < std::stod(m[4]));
  for (const char* legend : {"the reference's primitives", "the capture's primitives", "only in the reference",
                             "only in the capture", "point only in the reference", "point only in the capture"})
    CHECK(text.find(legend) != std::string::npos);
}

TEST_CASE("compare --svg: a bad path or an input as the picture exits 2 before any report, bad input leaves no file",
          "[cli]") {
  const std::string batch = writeTmp("bad_svg.batch", "quad integer triangle_cw hw 1 1 1 1 1 1\n");
  const std::string cap = writeTmp("bad_svg.out", kPortBlock);
  auto r = run({"compare", batch, cap, "--svg", clitest::tmpDir() + "/no-such-dir/x.svg"});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err.find("--svg") != std::string::npos);
  r = run({"compare", batch, cap, "--svg", cap});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(clitest::readFile(cap) == kPortBlock);
  // A malformed capture found after the first patch: exit 2, no report, no picture, no temporary file.
  const std::string bad = writeTmp("bad_svg2.out", std::string(kPortBlock) + "patch 1 points 1 indices 0\nzz\n");
  const std::string two = writeTmp("bad_svg2.batch", "quad integer triangle_cw hw 1 1 1 1 1 1\n"
                                                     "quad integer triangle_cw hw 1 1 1 1 1 1\n");
  const std::string svg = clitest::tmpDir() + "/never.svg";
  r = run({"compare", two, bad, "--svg", svg});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK_FALSE(clitest::fileExists(svg));
  for (const std::string& f : clitest::listDir(clitest::tmpDir())) CHECK(f.find("never.svg.tmp") == std::string::npos);
}
