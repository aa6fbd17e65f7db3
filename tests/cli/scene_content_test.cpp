// The scene as the reports know it: check and sweep JSON carry scene_hash (FNV-1a 64 of the scene's bytes, its
// overrides and the files it names), and merge refuses shards whose hashes differ; scene-loading limits and the
// camera seen from the command line (exit 2, the input named); --flush-denormals=on|off|auto.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

using clitest::run;
using json = nlohmann::ordered_json;

namespace {

const std::string kGrid = clitest::source("docs/examples/grid.toml");

} // namespace

TEST_CASE("scene content: reports carry scene_hash and merge refuses shards of different contents", "[cli][merge]") {
  const std::string dir = clitest::tmpDir();
  const std::string scene = dir + "/content.toml";
  const std::string text = clitest::readFile(kGrid);
  clitest::writeFile(scene, text);
  const std::string a = dir + "/content_1.json", b = dir + "/content_2.json", c = dir + "/content_check.json";
  REQUIRE(run({"sweep", scene, "--random", "4", "-q", "--shard", "1/2", "--json", a}).status == 0);
  REQUIRE(run({"check", scene, "-q", "--json", c}).status == 0);
  const std::string hash = json::parse(clitest::readFile(a)).at("scene_hash");
  CHECK(hash.size() == std::string("fnv1a64:").size() + 16);
  CHECK(hash.rfind("fnv1a64:", 0) == 0);
  CHECK(json::parse(clitest::readFile(c)).at("scene_hash") == hash);
  // The same path, other contents (one comment line more): the second shard's report differs only there.
  clitest::writeFile(scene, text + "# edited between the shards\n");
  REQUIRE(run({"sweep", scene, "--random", "4", "-q", "--shard", "2/2", "--json", b}).status == 0);
  CHECK(json::parse(clitest::readFile(b)).at("scene_hash") != hash);
  clitest::Result r = run({"merge", a, b, "--json", dir + "/content_merged.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("'" + b + "': scene_hash") != std::string::npos);
  CHECK(r.err.find("differs from '" + a + "'") != std::string::npos);
  CHECK_FALSE(clitest::fileExists(dir + "/content_merged.json"));
  // Back to the first contents: the shards merge.
  clitest::writeFile(scene, text);
  REQUIRE(run({"sweep", scene, "--random", "4", "-q", "--shard", "2/2", "--json", b}).status == 0);
  CHECK(run({"merge", a, b, "-q"}).status == 0);
  // An override changes the hash too.
  REQUIRE(run({"sweep", scene, "--random", "4", "-q", "--shard", "2/2", "--set", "lod.max_tess=5", "--json", b}).status <= 1);
  CHECK(json::parse(clitest::readFile(b)).at("scene_hash") != hash);
}

TEST_CASE("scene limits and cameras from the command line: exit 2 naming the input", "[cli][input]") {
  clitest::Result r = run({"check", "/dev/zero"});
  CHECK(r.status == 2);
  CHECK(r.err == "fftess: error: /dev/zero: scene file larger than 16777216 bytes (16 MiB, the limit)\n");
  // Eye and target within float noise: an invalid camera, not thousands of holes.
  r = run({"check", kGrid, "--eye", "0,10,0", "--target", "0,10,1e-30"});
  CHECK(r.status == 2);
  CHECK(r.err.find("fftess: error: --target 0,10,1e-30: the view direction target - eye = (0, 0, 1e-30)") == 0);
  CHECK(r.out.empty());
  r = run({"sweep", kGrid, "--set", "camera.target=[0.0,10.0,1e-30]", "--set", "camera.eye=[0.0,10.0,0.0]"});
  CHECK(r.status == 2);
  CHECK(r.err.find("fftess: error: --set camera.target: the view direction") == 0);
  // An override that makes tables names the override.
  r = run({"check", kGrid, "--set", "a.b.c.d.e.f=5"});
  CHECK(r.status == 2);
  CHECK(r.err == "fftess: error: --set a.b.c.d.e.f=5: a: unknown key\n");
  // heightmap_grid beyond 4 million patches.
  r = run({"check", kGrid, "--set", "layout.kind=heightmap_grid", "--set", "layout.cells_per_patch=1", "--set",
           "displacement.resolution=2049"});
  CHECK(r.status == 2);
  CHECK(r.err.find("--set layout.cells_per_patch: more than 4 million patches") != std::string::npos);
}

TEST_CASE("denormal rule option: --flush-denormals bare = on, =off, =auto, anything else exit 2", "[cli][input]") {
  for (const char* v : {"--flush-denormals", "--flush-denormals=on", "--flush-denormals=off", "--flush-denormals=auto"})
    CHECK(run({"check", kGrid, "-q", v}).status == 0);
  const clitest::Result r = run({"check", kGrid, "-q", "--flush-denormals=maybe"});
  CHECK(r.status == 2);
  CHECK(r.err == "fftess: error: --flush-denormals='maybe': expected on|off|auto\n");
  // The check report says which rule ran and lists denormal factors (none on lod/'s C++ factors here).
  const std::string out = clitest::tmpDir() + "/denormal_keys.json";
  REQUIRE(run({"check", kGrid, "-q", "--flush-denormals", "--json", out}).status == 0);
  const json j = json::parse(clitest::readFile(out));
  CHECK(j.at("denormals_flushed") == true);
  CHECK(j.at("denormal_factors").empty());
  CHECK(j.at("stats").at("denormal_factors") == 0);
}
