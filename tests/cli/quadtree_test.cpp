// layout.kind = "quadtree" through the cli: a check from a path camera (not the scene camera) draws and lists that
// camera's own leaves (layoutFor), so the picture's patches are the report's; an unbalanced quadtree's jumps beyond
// 2x are named with their fix.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using json = nlohmann::json;

namespace {

// One root of 64, depth 4; the scene camera far above a corner, the path camera low over the middle: their leaf
// counts differ.
const char* const kScene = R"(
[layout]
kind = "quadtree"
root_size = 64.0
max_depth = 4
lod_distance = 8.0
lod_distance_ratio = 1.0
corners = "shared"
[displacement]
kind = "none"
[lod]
scheme = "screen_sphere"
target_pixels = 6.0
[tessellation]
partitioning = "fractional_even"
[camera]
eye = [-28.0, 4.0, -28.0]
target = [0.0, 0.0, 0.0]
[[camera_path]]
eye = [2.0, 3.0, -10.0]
target = [0.0, 0.0, 0.0]
)";

size_t countOf(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The outlines of the "p" path (one "M" per patch) in an SVG.
size_t svgPatchCount(const std::string& svg) {
  const size_t start = svg.find("<path class=\"p\" d=\"");
  REQUIRE(start != std::string::npos);
  const size_t end = svg.find('"', start + 19);
  return countOf(svg.substr(start, end - start), "M");
}

} // namespace

TEST_CASE("check of a quadtree from a path camera draws and lists that camera's leaves", "[cli][check][quadtree]") {
  const std::string dir = clitest::tmpDir();
  const std::string scene = dir + "/quadtree.toml", js = dir + "/quadtree.json", svg = dir + "/quadtree.svg";
  clitest::writeFile(scene, kScene);
  auto r = clitest::run({"check", scene, "--json", js, "--svg", svg});
  REQUIRE(r.status < 2);
  const int64_t sceneLeaves = json::parse(clitest::readFile(js)).at("stats").at("patches").get<int64_t>();
  CHECK(svgPatchCount(clitest::readFile(svg)) == size_t(sceneLeaves));
  r = clitest::run({"check", scene, "--path-camera", "0", "--json", js, "--svg", svg});
  INFO(r.err);
  REQUIRE(r.status < 2);
  const json report = json::parse(clitest::readFile(js));
  const int64_t pathLeaves = report.at("stats").at("patches").get<int64_t>();
  CHECK(report.at("work").at("layout_selections") == 2); // the prepare's (scene camera), the check's (path camera)
  CHECK(report.at("work").at("layout_nodes").get<int64_t>() > 0);
  CHECK(pathLeaves != sceneLeaves);
  CHECK(svgPatchCount(clitest::readFile(svg)) == size_t(pathLeaves));
}

TEST_CASE("check of an unbalanced quadtree names the jumps beyond 2x and the fix", "[cli][check][quadtree]") {
  const std::string dir = clitest::tmpDir();
  const std::string scene = dir + "/quadtree_unbalanced.toml";
  clitest::writeFile(scene, kScene);
  const auto r = clitest::run({"check", scene, "--path-camera", "0", "--set", "layout.balance=none"});
  INFO(r.out << r.err);
  CHECK(r.status == 0); // flat: the jumps are T-junctions (the big edge is straight)
  CHECK(r.out.find("t_junction") != std::string::npos);
  CHECK(r.out.find("lod/'s neighbour rule handles 2x jumps only") != std::string::npos);
  CHECK(r.out.find("balance the quadtree 2:1 (layout.balance = \"2to1\")") != std::string::npos);
  const auto b = clitest::run({"check", scene, "--path-camera", "0"});
  CHECK(b.out.find("handles 2x jumps only") == std::string::npos);
}
