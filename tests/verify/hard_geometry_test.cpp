// Hard geometry stays stable: a 128 km x 128 km world, the camera a centimetre above a patch corner, the camera
// exactly on an edge, patches behind the camera, far patches at the minimum factor. Watertight layouts must stay
// watertight, and nothing may turn into NaN.
#include "verify_test_util.h"

#include "tessellator/edge_analysis.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

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
    CHECK(r.stats.edgesChecked > 0);
    CHECK(r.stats.cracks == 0);
    CHECK(r.stats.tJunctions == 0);
    CHECK(r.stats.holes == 0);
    CHECK(verdictOf(r.stats) == Verdict::Watertight);
    CHECK(std::isfinite(r.stats.worstGapWorld));
  }
}

} // namespace

TEST_CASE("hard geometry: a 128 km world, the camera 1 cm above a corner", "[verify][hard]") {
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

// The eye on the flat terrain (grid.toml: 24 x 24 patches of 4 units, corners at multiples of 4), looking along +z
// with screen_sphere and no frustum culling. Every edge whose midpoint lies in the eye's image plane (view z = 0)
// projects with w = 0: its factor is NaN, the tessellator discards both patches that share it, and those in view
// are holes. The expected holes are computed here from the layout: the patches with such an edge that have a point
// in front of the eye inside the frustum.
namespace {

Scene flatGrid() {
  return loadExample("grid.toml", {"displacement.kind=none", "lod.scheme=screen_sphere",
                                   "tessellation.partitioning=fractional_even", "lod.frustum_cull=false"});
}

void requireHolesAtTheEyePlane(const glm::vec3& eye, const char* what, int expectedMin) {
  const Scene s = flatGrid();
  const Terrain terrain = prepared(s);
  Camera cam = s.camera;
  cam.eye = eye;
  cam.target = eye + glm::vec3(0.0f, 0.0f, 100.0f);
  for (Kernel k : {Kernel::Epick, Kernel::Epeck}) {
    CheckOptions o;
    o.kernel = k;
    const Report r = checkScene(terrain, cam, o);
    INFO(what << " " << toString(k));
    REQUIRE(r.error.empty());
    CHECK(r.stats.holes >= expectedMin);
    CHECK(r.stats.holes == r.stats.holesDiscarded);
    CHECK(verdictOf(r.stats) == Verdict::Holes);
    REQUIRE(r.holes.size() == static_cast<size_t>(r.stats.holes));
    for (const Hole& h : r.holes) {
      const PatchGeometry& g = terrain.patches()[static_cast<size_t>(h.patch.index)];
      INFO("patch " << h.patch.index << " edge " << h.edge);
      CHECK(h.kind == HoleKind::Discarded);
      CHECK(h.visibility == Visibility::Visible);
      CHECK(std::isnan(h.hullFactor));
      CHECK(h.midpointW == 0.0f);
      // The discarding edge's midpoint lies in the eye's image plane z = eye.z.
      REQUIRE(h.edge >= 0);
      static constexpr int kEnds[4][2] = {{0, 2}, {0, 1}, {1, 3}, {2, 3}};
      const float mz = (g.corners[kEnds[h.edge][0]].z + g.corners[kEnds[h.edge][1]].z) * 0.5f;
      CHECK(mz == eye.z);
      // The point that proved it visible is in front of the eye.
      CHECK(h.visiblePoint.z > eye.z);
    }
  }
}

} // namespace

TEST_CASE("hard geometry: an eye exactly on an edge reports holes", "[verify][hard]") {
  // (0, 0, 2): the midpoint of the shared edge x = 0, z in [0, 4].
  requireHolesAtTheEyePlane({0.0f, 0.0f, 2.0f}, "eye on an edge", 2);
}

TEST_CASE("hard geometry: an eye exactly on a corner reports holes", "[verify][hard]") {
  // (0, 0, 0): four patches' corner; the edges along x at z = 0 have their midpoints in the image plane.
  requireHolesAtTheEyePlane({0.0f, 0.0f, 0.0f}, "eye on a corner", 2);
}

TEST_CASE("hard geometry: an eye exactly on an interior vertex", "[verify][hard]") {
  // (1, 0, 2): an interior vertex of patch [0,4]x[0,4] (u = 1/4, v = 1/2 at factor 4); the plane z = 2 holds the
  // midpoints of the edges x = 0 and x = 4: holes. (1, 0, 1) holds none: the control, watertight.
  requireHolesAtTheEyePlane({1.0f, 0.0f, 2.0f}, "eye on an interior vertex", 1);
  const Scene s = flatGrid();
  Camera cam = s.camera;
  cam.eye = {1.0f, 0.0f, 1.0f};
  cam.target = cam.eye + glm::vec3(0.0f, 0.0f, 100.0f);
  requireWatertight(s, cam, "eye on an interior vertex off the midpoint rows");
}

TEST_CASE("hard geometry: holes with frustum culling on", "[verify][hard]") {
  // The same eye with screen_sphere's own frustum test: it keeps the patches beside the eye, so the NaN still
  // reaches the tessellator.
  Scene s = flatGrid();
  s.lod.screenSphere.sphere.frustumCull = true;
  Camera cam = s.camera;
  cam.eye = {0.0f, 0.0f, 2.0f};
  cam.target = {0.0f, 0.0f, 100.0f};
  const Report r = checkScene(prepared(s), cam);
  CHECK(r.stats.holesDiscarded >= 2);
  CHECK(verdictOf(r.stats) == Verdict::Holes);
}

TEST_CASE("hard geometry: a world far from the origin", "[verify][hard]") {
  SECTION("centre at 1e5: watertight with pow2") {
    const Scene s = loadExample("rings_small.toml", {"layout.center=[1e5,1e5]"});
    const Terrain t = prepared(s);
    const SweepResult r = sweep(t, randomCameras(t, 40, 5));
    CHECK(r.camerasDone == 40);
    CHECK(verdictOf(r) == Verdict::Watertight);
  }
  SECTION("centre at 1e7, 2-unit patches: rejected, the patch size vanishes at those coordinates") {
    SceneResult sr = loadScene(examplePath("rings_small.toml"), {"layout.center=[1e7,1e7]"});
    REQUIRE(sr.ok);
    const TerrainResult tr = prepareTerrain(sr.scene);
    CHECK(!tr.ok);
    CHECK(tr.error.find("layout.base_patch_size") != std::string::npos);
  }
  SECTION("centre at 1e7, 16-unit patches: the LOD's float frustum test culls patches in view") {
    // At 1e7 a float's ulp is 1 unit: the float plane equations (proj * view, in lod/) misplace the frustum by
    // units, and patches in front of the camera are culled. A GPU running the same float test shows those holes.
    const Scene s = loadExample("rings_small.toml", {"layout.center=[1e7,1e7]", "layout.base_patch_size=16"});
    const Terrain t = prepared(s);
    CheckOptions o;
    o.maxFindings = 100000;
    SweepOptions so;
    so.keepReports = true;
    const SweepResult r = sweep(t, randomCameras(t, 20, 1), o, so);
    CHECK(r.total.holesCulledVisible > 0);
    CHECK(r.total.cracks == 0);
    CHECK(verdictOf(r) == Verdict::Holes);
    for (const Report& rep : r.reports)
      for (const Hole& h : rep.holes) {
        CHECK(h.kind == HoleKind::CulledWhileVisible);
        CHECK(h.visibility == Visibility::Visible);
      }
    // 1e6 is still fine.
    const Scene near = loadExample("rings_small.toml", {"layout.center=[1e6,1e6]", "layout.base_patch_size=16"});
    const Terrain tn = prepared(near);
    CHECK(verdictOf(sweep(tn, randomCameras(tn, 20, 1))) == Verdict::Watertight);
  }
}

TEST_CASE("hard geometry: a camera below the displaced surface", "[verify][hard]") {
  // Looking up at the terrain from below: the LOD, the tessellator and the check see the same surface.
  const Scene s = loadExample("rings_small.toml");
  Camera cam = s.camera;
  cam.eye = {3.0f, -20.0f, -5.0f};
  cam.target = {10.0f, 5.0f, 30.0f};
  requireWatertight(s, cam, "below the surface");
}

TEST_CASE("hard geometry: grazing angles", "[verify][hard]") {
  const Scene s = loadExample("rings_small.toml");
  const Terrain t = prepared(s);
  // The eye a hair above the highest texel, looking horizontally across the whole terrain in several directions.
  const float top = s.displacement.heightScale + 0.001f;
  for (int k = 0; k < 8; ++k) {
    const float a = static_cast<float>(k) * 0.785398f;
    Camera cam = s.camera;
    // Off the grid lines: an eye on a line x = const looking along x has edge midpoints in its image plane (w = 0,
    // holes: the tests above).
    cam.eye = {-61.3f * std::cos(a) + 0.37f, top, -61.3f * std::sin(a) + 0.21f};
    cam.target = {60.0f * std::cos(a) + 0.11f, top, 60.0f * std::sin(a) + 0.05f};
    requireWatertight(s, cam, "grazing");
  }
}

TEST_CASE("hard geometry: patches behind the camera", "[verify][hard]") {
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

TEST_CASE("hard geometry: far patches at the minimum factor", "[verify][hard]") {
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

TEST_CASE("hard geometry: raw heightmaps at full scale", "[verify][hard]") {
  // 16-bit RAW heightmaps of 0 and of 65535 everywhere (and an 8-bit 255): the heights are exactly 0 and exactly
  // height_scale, the terrain is a plane, and the NVIDIA setup is watertight.
  const std::string dir = std::string(FFTESS_TEST_TMP_DIR) + "/raw_full_scale";
  std::filesystem::create_directories(dir);
  const int n = 129;
  struct Case {
    const char* name;
    int bits;
    unsigned value;
    float height;
  };
  for (const Case& c : {Case{"zero16", 16, 0u, 0.0f}, Case{"max16", 16, 65535u, 8.0f}, Case{"max8", 8, 255u, 8.0f}}) {
    const std::string file = dir + "/" + c.name + ".raw";
    {
      std::ofstream out(file, std::ios::binary);
      for (int i = 0; i < n * n; ++i) {
        out.put(static_cast<char>(c.value & 0xFF));
        if (c.bits == 16) out.put(static_cast<char>(c.value >> 8));
      }
    }
    const Scene s = loadExample("rings_small.toml",
                                {"displacement.kind=raw", std::string("displacement.file=\"") + file + "\"",
                                 "displacement.width=129", "displacement.height=129",
                                 "displacement.bits=" + std::to_string(c.bits), "displacement.height_scale=8"});
    const Terrain t = prepared(s);
    INFO(c.name);
    CHECK(domainPosition(t, 7, 0.3f, 0.6f).y == c.height);
    const SweepResult r = sweep(t, randomCameras(t, 25, 3));
    CHECK(r.camerasDone == 25);
    CHECK(verdictOf(r) == Verdict::Watertight);
  }
}

TEST_CASE("hard geometry: non-finite inputs never reach the LOD silently", "[verify][hard]") {
  // Every float a scene gives the LOD, the layout or the camera: NaN, +Inf and -Inf are refused at load with the
  // key named. What is left for NaN is arithmetic (w = 0, tested above), and that is reported as a hole.
  const char* keys[] = {"layout.patch_size", "layout.base_patch_size", "layout.cell_size", "displacement.height_scale",
                        "displacement.frequency", "displacement.lacunarity", "displacement.gain", "lod.factor",
                        "lod.target_pixels", "lod.min_factor", "lod.max_factor", "lod.min_distance",
                        "lod.max_distance", "lod.min_tess", "lod.max_tess", "lod.rank",
                        "lod.edges_per_screen_height", "camera.fov_y", "camera.near", "camera.far"};
  for (const char* key : keys)
    for (const char* value : {"nan", "inf", "-inf"}) {
      const SceneResult r = loadScene(examplePath("terrain.toml"), {std::string(key) + "=" + value});
      INFO(key << " = " << value << ": " << r.error);
      CHECK(!r.ok);
      CHECK(r.error.find(key) != std::string::npos);
    }
  for (const char* key : {"layout.center", "camera.eye", "camera.target", "camera.up"})
    for (const char* value : {"[nan, 0]", "[0, inf, 0]", "[-inf, 0, 0]"}) {
      const SceneResult r = loadScene(examplePath("terrain.toml"), {std::string(key) + "=" + value});
      INFO(key << " = " << value << ": " << r.error);
      CHECK(!r.ok);
      CHECK(r.error.find(key) != std::string::npos);
    }
}

TEST_CASE("hard geometry: factors one ulp around powers of two, through each clamp", "[verify][hard]") {
  // lod.scheme = constant on tile rings: every edge's factor is f, the neighbour rule makes the jump's sides
  // big = clamp(f) and small = big / 2. For f one ulp below, at and one ulp above 2, 4, .., 64 and each clamp, the
  // hull factors at every jump are what the clamp's recipe says (computed here, not by lod/), and a jump cracks
  // exactly when the 16.16 model (compareHalfEdges) says the sides miss: never with pow2.
  auto recipe = [](const std::string& clamp, float f) {
    if (clamp == "pow2") {
      float p = 4.0f;
      while (p < 64.0f && p < f) p *= 2.0f;
      return p;
    }
    if (clamp == "integer") {
      float e = std::ceil(f * 0.5f) * 2.0f;
      return e < 4.0f ? 4.0f : e > 64.0f ? 64.0f : e;
    }
    return f;
  };
  for (const char* clamp : {"none", "integer", "pow2"})
    for (float p : {2.0f, 4.0f, 8.0f, 16.0f, 32.0f, 64.0f})
      for (float f : {std::nextafter(p, 0.0f), p, std::nextafter(p, 100.0f)}) {
        char value[64];
        std::snprintf(value, sizeof value, "lod.factor=%.9g", static_cast<double>(f));
        const Scene s = loadExample("rings_small.toml", {"lod.scheme=constant", value,
                                                         std::string("lod.adjacency_clamp=") + clamp});
        REQUIRE(s.lod.factor == f);
        CheckOptions o;
        o.keepMatches = true;
        o.maxFindings = 1u << 20;
        const Report r = checkScene(prepared(s), s.camera, o);
        INFO(clamp << " f = " << value);
        REQUIRE(r.error.empty());
        CHECK(r.stats.holes == 0);
        const float big = recipe(clamp, f), small = big * 0.5f;
        const fftess::HalfEdgeComparison c = fftess::compareHalfEdges(big, small, s.partitioning, s.stage);
        int jumps = 0;
        for (const Finding& x : r.findings) {
          if (x.a.patch.level == x.b.patch.level) {
            CHECK(x.classification == Classification::Match); // same-size neighbours: both f
            continue;
          }
          ++jumps;
          CHECK(x.a.hullFactor == big);
          CHECK(x.b.hullFactor == small);
          CHECK(std::isfinite(x.a.hullFactor));
          // The 16.16 model for this half of the big edge.
          const bool second = x.a.paramLo == 0.5f;
          bool miss = false;
          for (const fftess::HalfEdgeRow& row : c.rows) {
            if (row.match) continue;
            const int64_t t = row.big >= 0 ? c.bigPoints[static_cast<size_t>(row.big)].t
                                           : c.smallPoints[static_cast<size_t>(row.small)].t;
            miss = miss || (second ? t >= 65536 : t <= 65536);
          }
          CHECK((x.classification != Classification::Match) == miss);
        }
        CHECK(jumps > 0);
        if (std::string(clamp) == "pow2") CHECK(verdictOf(r.stats) == Verdict::Watertight);
      }
}
