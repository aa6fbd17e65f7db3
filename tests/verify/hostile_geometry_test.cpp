// Geometry that does not fit in float is bad input (issue 13, item 1): prepareTerrain names the key, nothing
// non-finite reaches CGAL, and the camera generators stop on a cancel flag.
#include "verify_test_util.h"

#include <atomic>

using namespace fftess::verify;
using namespace fftess::verify::test;

TEST_CASE("hostile geometry: vanishing or overflowing patch sizes are rejected by prepareTerrain",
          "[verify][hostile]") {
  for (float size : {1e-45f, 1e-40f, 1e37f}) {
    Scene s = loadExample("terrain.toml");
    s.layout.basePatchSize = size;
    const TerrainResult r = prepareTerrain(s);
    INFO(size);
    CHECK_FALSE(r.ok);
    CHECK(r.error.rfind("layout.base_patch_size: ", 0) == 0);
  }
  Scene g = loadExample("grid.toml");
  g.layout.patchSize = 3e38f;
  CHECK(prepareTerrain(g).error.rfind("layout.patch_size: ", 0) == 0);
  // The bundled scenes still fit.
  for (const char* name : {"terrain.toml", "grid.toml", "rings_small.toml", "luna.toml", "t_junction.toml"})
    CHECK(prepareTerrain(loadExample(name)).ok);
}

TEST_CASE("hostile geometry: camera generators stop when cancelled", "[verify][hostile]") {
  const TerrainResult r = prepareTerrain(loadExample("rings_small.toml"));
  REQUIRE(r.ok);
  std::atomic<bool> cancel{true};
  CHECK(randomCameras(r.terrain, 1000000, 1, &cancel).size() < 4096);
  CHECK(orbitCameras(r.terrain, 1000000, 0, 0, &cancel).size() < 4096);
  CHECK(flyoverCameras(r.terrain, 1000000, 0, &cancel).size() < 4096);
  cancel = false;
  CHECK(randomCameras(r.terrain, 5000, 1, &cancel).size() == 5000);
}

TEST_CASE("hostile input: loader errors stay on one line whatever bytes the key has", "[verify][hostile]") {
  // Found by the scene fuzzer: an override whose key holds a newline was echoed raw.
  const SceneResult r = parseScene("# nothing\n", "fuzz.toml", {"the edge midpoint,\n# so=1"});
  REQUIRE_FALSE(r.ok);
  CHECK(r.error.find('\n') == std::string::npos);
  CHECK(r.error.find("\\x0a") != std::string::npos);
}
