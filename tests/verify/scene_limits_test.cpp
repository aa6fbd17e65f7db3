// Scene loading limits and the scene's content hash: a scene file larger than 16 MiB (/dev/zero) is refused naming
// the file; heightmap_grid is capped at 4 million patches like the other layouts (before the texture is made); a raw
// heightmap larger than 8193 x 8193 texels is refused before it is read; a view direction too short for float is an
// invalid camera naming eye and target (not thousands of holes); an override that makes tables names "--set K=V";
// Scene::contentHash follows the text, the overrides and the files the scene names.
#include "verify_test_util.h"

#include <cstdio>
#include <fstream>
#include <sys/stat.h>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

const char* kFlat = R"(name = "t"
[layout]
kind = "grid"
patches_x = 4
patches_z = 4
patch_size = 2.0
[displacement]
kind = "none"
[lod]
scheme = "constant"
[tessellation]
partitioning = "integer"
[camera]
eye = [0.0, 10.0, -20.0]
target = [0.0, 0.0, 0.0]
)";

std::string tmpFile(const std::string& name, const std::string& bytes) {
  ::mkdir(FFTESS_TEST_TMP_DIR, 0755);
  const std::string path = std::string(FFTESS_TEST_TMP_DIR) + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

} // namespace

TEST_CASE("a scene file is read up to 16 MiB, then refused naming the file", "[verify][scene]") {
  const SceneResult r = loadScene("/dev/zero");
  REQUIRE_FALSE(r.ok);
  CHECK(r.error == "/dev/zero: scene file larger than 16777216 bytes (16 MiB, the limit)");
  // 16 MiB exactly is read (and then parsed: a comment line of that size is a valid scene prefix).
  std::string big = "#" + std::string((size_t(16) << 20) - 2 - std::string(kFlat).size(), 'x') + "\n" + kFlat;
  REQUIRE(big.size() == size_t(16) << 20);
  CHECK(loadScene(tmpFile("exactly16.toml", big)).ok);
  big.insert(0, "\n");
  const std::string over = tmpFile("over16.toml", big);
  CHECK(loadScene(over).error == over + ": scene file larger than 16777216 bytes (16 MiB, the limit)");
}

TEST_CASE("heightmap_grid is capped at 4 million patches, named at layout.cells_per_patch", "[verify][scene]") {
  const std::string text = std::string(kFlat) + "";
  auto load = [&](int resolution, int cpp) {
    return parseScene(text, "hm.toml",
                      {"layout.kind=heightmap_grid", "layout.cells_per_patch=" + std::to_string(cpp),
                       "displacement.kind=fbm", "displacement.resolution=" + std::to_string(resolution)});
  };
  // 2048 x 2048 = 4,194,304 patches: refused (it ran out of memory at 2.6 GB); 2000 x 2000 = 4,000,000 would load.
  const SceneResult big = load(2049, 1);
  CHECK(big.error == "--set layout.cells_per_patch: more than 4 million patches (2048 x 2048 from the 2049 x 2049 "
                     "heightmap at cells_per_patch = 1)");
  CHECK(load(2049, 2).ok); // 1024 x 1024
  // A raw heightmap's size is refused before the file is read (the file does not even exist here).
  const SceneResult raw = parseScene(text, "raw.toml",
                                     {"displacement.kind=raw", "displacement.file=nowhere.raw",
                                      "displacement.width=65536", "displacement.height=2048"});
  CHECK_THAT(raw.error, Catch::StartsWith("--set displacement.width: 65536 x 2048 texels: more than 67125249"));
}

TEST_CASE("a view direction too short for float is an invalid camera naming eye and target", "[verify][scene]") {
  const SceneResult r = parseScene(kFlat, "cam.toml", {"camera.eye=[0.0,10.0,0.0]", "camera.target=[0.0,10.0,1e-30]"});
  REQUIRE_FALSE(r.ok);
  CHECK_THAT(r.error, Catch::StartsWith("--set camera.target: the view direction target - eye = (0, 0, 1e-30) (eye "
                                        "(0, 10, 0), target (0, 10, 1e-30)) is too short for float"));
  // The same camera handed to the checker (a sweep's camera): Report::error, nothing checked, no holes.
  const Scene scene = parseScene(kFlat, "cam.toml").scene;
  const Terrain terrain = prepared(scene);
  Camera c = scene.camera;
  c.eye = {0.0f, 10.0f, 0.0f};
  c.target = {0.0f, 10.0f, 1e-30f};
  Report rep = checkScene(terrain, c);
  CHECK_THAT(rep.error, Catch::Contains("too short for float"));
  CHECK(rep.stats.holes == 0);
  // Just long enough (|d|^2 = 2^-126) is a camera; an up nearly parallel to the view is refused too.
  c.target = {0.0f, 10.0f, 0x1p-63f};
  CHECK(checkScene(terrain, c).error.empty());
  c.target = {0.0f, 0.0f, 0.0f};
  c.up = {0.0f, 1.0f, 1e-30f};
  c.eye = {0.0f, 10.0f, 0.0f};
  CHECK_THAT(checkScene(terrain, c).error, Catch::Contains("camera.up"));
}

TEST_CASE("an override that makes tables is named whole in the error", "[verify][scene]") {
  CHECK(parseScene(kFlat, "s.toml", {"a.b.c.d.e.f=5"}).error == "--set a.b.c.d.e.f=5: a: unknown key");
  CHECK(parseScene(kFlat, "s.toml", {"lod.x.y=1"}).error == "--set lod.x.y=1: lod.x: unknown key");
  CHECK(parseScene(kFlat, "s.toml", {"lod.x=1"}).error == "--set lod.x: unknown key"); // as before
  // A key of the file below a table an override made is still the file's (no override holds it).
  CHECK_THAT(parseScene(std::string(kFlat) + "[extra]\nk = 1\n", "s.toml", {"lod.factor=2"}).error,
             Catch::StartsWith("s.toml:16:1: extra: unknown key"));
}

TEST_CASE("Scene::contentHash follows the scene's text, its overrides and the files it names", "[verify][scene]") {
  auto hashOf = [](const std::string& text, const std::vector<std::string>& ov = {}) {
    const SceneResult r = parseScene(text, "h.toml", ov, FFTESS_TEST_TMP_DIR);
    INFO(r.error);
    REQUIRE(r.ok);
    return r.scene.contentHash;
  };
  const uint64_t base = hashOf(kFlat);
  CHECK(base == hashOf(kFlat));
  CHECK(base != hashOf(std::string(kFlat) + "# a comment\n")); // bytes, not meaning
  CHECK(base != hashOf(kFlat, {"lod.factor=8"}));               // an override, even one that changes nothing
  CHECK(hashOf(kFlat, {"lod.factor=4", "lod.factor=5"}) != hashOf(kFlat, {"lod.factor=45"}));
  // The file and the same text in memory agree.
  const std::string path = tmpFile("hash.toml", kFlat);
  CHECK(loadScene(path).scene.contentHash == base);
  // A raw heightmap's contents (same name, other bytes).
  const std::string rawScene = std::string(kFlat) + "";
  const std::vector<std::string> raw{"displacement.kind=raw", "displacement.file=h.raw", "displacement.width=2",
                                     "displacement.height=2", "displacement.bits=8"};
  tmpFile("h.raw", std::string("\x01\x02\x03\x04", 4));
  const uint64_t h1 = hashOf(kFlat, raw);
  tmpFile("h.raw", std::string("\x01\x02\x03\x05", 4));
  CHECK(hashOf(kFlat, raw) != h1);
  // A lod.shader's contents.
  tmpFile("h.glsl", "LodFactors lodMain(LodPatch q, TileNeighbourInfo n, LodCamera c, LodSettings s) { A }\n");
  const uint64_t s1 = hashOf(kFlat, {"lod.shader=h.glsl"});
  tmpFile("h.glsl", "LodFactors lodMain(LodPatch q, TileNeighbourInfo n, LodCamera c, LodSettings s) { B }\n");
  CHECK(hashOf(kFlat, {"lod.shader=h.glsl"}) != s1);
  // FNV-1a 64 of the stated stream, computed here independently for the plain text.
  uint64_t h = 0xcbf29ce484222325ull;
  auto add = [&](unsigned char b) { h = (h ^ b) * 0x100000001b3ull; };
  const std::string text = kFlat;
  add(0);
  for (int i = 0; i < 8; ++i) add(static_cast<unsigned char>(uint64_t(text.size()) >> (8 * i)));
  for (char c : text) add(static_cast<unsigned char>(c));
  CHECK(base == h);
}
