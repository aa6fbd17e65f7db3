// Hard geometry stays stable: a 128 km x 128 km world, the camera a centimetre above a patch corner, the camera
// exactly on an edge, patches behind the camera, far patches at the minimum factor. Watertight layouts must stay
// watertight, and nothing may turn into NaN.
#include "verify_test_util.h"

#include <cmath>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// 128 km: a uniform grid of 128 x 128 patches of 1 km, and NVIDIA tile rings (5 rings of 8x8 tiles of 8x8
// patches of 125 m: ring 4's outer edge is 8 * 8 * 125 * 16 = 128 km).
Scene world(bool rings, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> ov;
  if (rings) {
    ov = {"layout.rings=5", "layout.tiles_per_ring_edge=8", "layout.base_patch_size=125",
          "displacement.height_scale=900", "displacement.resolution=257"};
  } else {
    ov = {"layout.kind=grid", "layout.patches_x=128", "layout.patches_z=128", "layout.patch_size=1000",
          "layout.corners=reconstructed", "lod.scheme=screen_sphere", "displacement.height_scale=900",
          "tessellation.partitioning=fractional_even"};
  }
  ov.insert(ov.end(), extra.begin(), extra.end());
  return loadExample(rings ? "terrain.toml" : "grid.toml", ov);
}

void requireWatertight(const Scene& s, const Camera& cam, const char* what) {
  for (Kernel k : {Kernel::Epick, Kernel::Epeck}) {
    CheckOptions o;
    o.kernel = k;
    Report r = checkScene(prepared(s), cam, o);
    INFO(what << " " << toString(k) << ": " << r.error);
    REQUIRE(r.error.empty());
    CHECK(r.stats.edgesChecked + r.stats.skippedCulled > 0);
    CHECK(r.stats.cracks == 0);
    CHECK(r.stats.tJunctions == 0);
    CHECK(std::isfinite(r.stats.worstGapWorld));
  }
}

} // namespace

TEST_CASE("hard_geometry_128km_world_camera_1cm_above_a_corner", "[verify][hard]") {
  for (bool rings : {false, true}) {
    Scene s = world(rings);
    const Terrain terrain = prepared(s);
    const Extent e = terrain.extent();
    CHECK(e.maxX - e.minX == 128000.0f);
    // Patch 0's corner (0, 0), one centimetre above the terrain there.
    const glm::vec3 corner = domainPosition(terrain, rings ? 0 : 64 * 128 + 64, 0.0f, 0.0f);
    Camera cam = s.camera;
    cam.eye = glm::vec3{corner.x, corner.y + 0.01f, corner.z};
    cam.target = glm::vec3{corner.x + 100.0f, corner.y - 5.0f, corner.z + 70.0f};
    cam.nearZ = 0.001f;
    cam.farZ = 300000.0f;
    requireWatertight(s, cam, rings ? "rings, 1 cm above a corner" : "grid, 1 cm above a corner");
  }
}

TEST_CASE("hard_geometry_camera_exactly_on_an_edge", "[verify][hard]") {
  for (bool rings : {false, true}) {
    // Flat terrain: the eye lies on the edge's line itself (y = 0), looking along it.
    Scene s = world(rings, {"displacement.kind=none"});
    const Terrain terrain = prepared(s);
    const glm::vec3 a = domainPosition(terrain, rings ? 5 : 64 * 128 + 64, 0.0f, 0.0f);
    const glm::vec3 b = domainPosition(terrain, rings ? 5 : 64 * 128 + 64, 0.0f, 1.0f);
    Camera cam = s.camera;
    cam.eye = glm::vec3{a.x, 0.0f, 0.5f * (a.z + b.z)};
    cam.target = glm::vec3{a.x, 0.0f, b.z + 1000.0f};
    cam.nearZ = 0.01f;
    cam.farZ = 300000.0f;
    requireWatertight(s, cam, rings ? "rings, eye on an edge" : "grid, eye on an edge");
  }
}

TEST_CASE("hard_geometry_patches_behind_the_camera", "[verify][hard]") {
  for (bool rings : {false, true}) {
    Scene s = world(rings, {"lod.frustum_cull=false"});
    Camera cam = s.camera;
    cam.eye = glm::vec3{0.0f, 50.0f, 0.0f};
    cam.target = glm::vec3{0.0f, 40.0f, 1000.0f}; // half the world is behind
    cam.farZ = 300000.0f;
    requireWatertight(s, cam, rings ? "rings, no culling, half behind" : "grid, no culling, half behind");
    Scene culled = world(rings);
    Report r = checkScene(prepared(culled), cam);
    CHECK(r.stats.culledPatches > 0);
    CHECK(r.stats.skippedCulled > 0);
    CHECK(r.stats.cracks == 0);
  }
}

TEST_CASE("hard_geometry_far_patches_at_the_minimum_factor", "[verify][hard]") {
  Scene s = world(false, {"lod.frustum_cull=false", "lod.target_pixels=20"});
  Camera cam = s.camera;
  cam.eye = glm::vec3{-63500.0f, 30.0f, -63500.0f}; // one corner of the world
  cam.target = glm::vec3{0.0f, 0.0f, 0.0f};
  cam.farZ = 300000.0f;
  CheckOptions o;
  o.keepMatches = true;
  o.maxFindings = 1000000;
  Report r = checkScene(prepared(s), cam, o);
  REQUIRE(r.error.empty());
  CHECK(r.stats.cracks == 0);
  int far = 0;
  for (const Finding& f : r.findings) {
    const double dx = f.edgeStart.x - cam.eye.x, dz = f.edgeStart.z - cam.eye.z;
    if (std::sqrt(dx * dx + dz * dz) < 100000.0) continue;
    ++far;
    // The LOD's minimum (1) reaches the tessellator, which raises it to fractional_even's minimum of 2.
    CHECK(f.a.hullFactor == 1.0f);
    CHECK(f.a.processedFactor == 2.0f);
    CHECK(f.classification == Classification::Match);
  }
  CHECK(far > 100);
}
