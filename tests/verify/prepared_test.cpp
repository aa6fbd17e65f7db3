// The prepared terrain: built once, and per camera only camera-dependent work runs (the work counters prove it).
// The LOD's own record reaches each finding.
#include "verify_test_util.h"

#include "verify/testing.h" // Fault, CheckOptions::fault

#include <cstring>
#include <memory>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

TEST_CASE("prepared terrain: one build serves check, mesh check, sweep, cameras, extent and geometry",
          "[verify][prepared][slow]") {
  const Scene s = loadExample("rings_small.toml");
  const int64_t before = terrainBuildCount();
  const TerrainResult r = prepareTerrain(s);
  REQUIRE(r.ok);
  const Terrain& t = r.terrain;
  CHECK(terrainBuildCount() == before + 1);
  CHECK(t.stats().terrainBuilds == 1);

  const std::vector<Camera> cams = orbitCameras(t, 3);
  const std::vector<Camera> more = randomCameras(t, 3, 1);
  const std::vector<Camera> fly = flyoverCameras(t, 3);
  const std::vector<Camera> path = pathCameras(t);
  const Report rep = checkScene(t, s.camera);
  const MeshReport mesh = checkSceneMesh(t, s.camera);
  const SweepResult sw = sweep(t, cams);
  (void)domainPosition(t, 0, 0.5f, 0.5f);
  (void)t.extent();
  (void)t.patches();
  CHECK(terrainBuildCount() == before + 1); // nothing above built a layout again
  CHECK(rep.work.terrainBuilds == 0);
  CHECK(mesh.work.terrainBuilds == 0);
  CHECK(sw.work.terrainBuilds == 0);
  CHECK(t.stats().terrainBuilds == 1);
}

TEST_CASE("prepared terrain: corner heights are sampled once, never per camera", "[verify][prepared][slow]") {
  const Scene s = loadExample("rings_small.toml", {"lod.displaced_corners=true"}); // fbm displacement
  REQUIRE(s.displacement.kind != DisplacementKind::None);
  REQUIRE(s.lod.displacedCorners);
  const Terrain t = prepared(s);
  const WorkStats built = t.stats();
  // The vertex shader's corner heights, plus (lod.reconstruction = "resampled", the default) one height per rebuilt
  // corner: every small-side edge at a ring border, 4 x 32 around ring 0 and 4 x 32 around ring 1.
  CHECK(built.heightSamples == 4 * static_cast<int64_t>(t.patchCount()) + 256);
  const Scene literal = loadExample("rings_small.toml", {"lod.displaced_corners=true", "lod.reconstruction=edge_vector"});
  CHECK(prepared(literal).stats().heightSamples == 4 * static_cast<int64_t>(t.patchCount()));

  const Report a = checkScene(t, s.camera);
  const Report b = checkScene(t, s.camera);
  REQUIRE(a.error.empty());
  // Per camera, every height sample is a domain-shader evaluation of an edge point: no corner height (of the patch
  // or of a larger neighbour's far corner) is sampled again.
  CHECK(a.work.domainEvaluations > 0);
  CHECK(a.work.heightSamples == a.work.domainEvaluations);
  CHECK(a.work.lodEvaluations == t.patchCount());
  CHECK(a.work.edgeQueries > 0);
  // The same camera again: the same camera-dependent work, and the terrain's own work unchanged.
  CHECK(b.work.heightSamples == a.work.heightSamples);
  CHECK(b.work.lodEvaluations == a.work.lodEvaluations);
  CHECK(t.stats().heightSamples == built.heightSamples);

  const MeshReport m = checkSceneMesh(t, s.camera);
  CHECK(m.work.heightSamples == m.work.domainEvaluations);
  CHECK(m.work.cgalCalls == 1);

  // A sweep's work is the sum of its cameras' reports.
  SweepOptions so;
  so.keepReports = true;
  so.threads = 2;
  const std::vector<Camera> cams = orbitCameras(t, 4, 30.0f, 10.0f);
  const SweepResult sw = sweep(t, cams, {}, so);
  WorkStats sum;
  for (const Report& r : sw.reports) sum += r.work;
  CHECK(sw.work.heightSamples == sum.heightSamples);
  CHECK(sw.work.lodEvaluations == 4 * static_cast<int64_t>(t.patchCount()));
  CHECK(sw.work.heightSamples == sw.work.domainEvaluations);
  CHECK(t.stats().heightSamples == built.heightSamples);
}

TEST_CASE("prepared terrain: a flat scene samples no height at all, a constant LOD calls no lod/",
          "[verify][prepared]") {
  const Scene flat = loadExample("rings_small.toml", {"displacement.kind=none"});
  const Terrain t = prepared(flat);
  CHECK(t.stats().heightSamples == 0);
  const Report r = checkScene(t, flat.camera);
  CHECK(r.work.domainEvaluations > 0);
  CHECK(r.work.heightSamples == 0);
  for (const PatchGeometry& g : t.patches())
    for (float h : g.heights) CHECK(h == 0.0f);

  const Scene constant = loadExample("grid.toml", {"lod.scheme=constant"});
  const Report rc = checkScene(prepared(constant), constant.camera);
  CHECK(rc.work.lodEvaluations == 0);
  CHECK(rc.work.edgeQueries == 1); // one factor everywhere: one edge query, cached
}

TEST_CASE("prepared terrain: corner heights are the domain shader's heights at the corners", "[verify][prepared]") {
  // NVIDIA: the height texture coordinate comes from world x/z, so the vertex shader's corner height equals the
  // domain shader's at (u, v) = corner, bit for bit.
  const Scene s = loadExample("rings_small.toml");
  const Terrain t = prepared(s);
  for (int i = 0; i < t.patchCount(); i += 7) {
    const PatchGeometry& g = t.patches()[static_cast<size_t>(i)];
    for (int c = 0; c < 4; ++c) {
      const glm::vec3 p = domainPosition(t, i, static_cast<float>(c & 1), static_cast<float>(c >> 1));
      CHECK(p.y == g.heights[c]);
    }
  }
}

TEST_CASE("findings carry the LOD's own record", "[verify][prepared][causes]") {
  SECTION("integer clamp: both sides of each 2x jump name the clamp and the neighbour rule") {
    const Scene s = loadExample("rings_small.toml", {"lod.adjacency_clamp=integer"});
    const Report r = checkScene(prepared(s), s.camera);
    REQUIRE(r.stats.cracks > 0);
    int jumps = 0;
    for (const Finding& f : r.findings) {
      CHECK(f.a.lod.scheme == LodScheme::ScreenSphere);
      if (f.a.patch.level == f.b.patch.level) continue;
      ++jumps;
      CHECK(f.a.lod.neighbourSize == 0.5f); // a is the bigger side
      CHECK(f.b.lod.neighbourSize == 2.0f);
      CHECK(f.a.lod.clamp == AdjacencyClamp::Integer);
      CHECK((f.a.lod.why.fixes & lod::FixIntegerClamp) != 0);
      CHECK((f.b.lod.why.fixes & lod::FixIntegerClamp) != 0);
      CHECK((f.a.lod.why.fixes & lod::FixSmallerNeighbour) != 0);
      CHECK((f.b.lod.why.fixes & lod::FixLargerNeighbour) != 0);
      CHECK_FALSE(f.a.lod.culled);
      CHECK(f.a.hullFactorBits == bitsOf(f.a.hullFactor));
      CHECK(lodWords(f.b).find("integer_clamp") != std::string::npos);
      CHECK(lodWords(f.b).find("neighbour 2x") != std::string::npos);
    }
    CHECK(jumps > 0);
  }
  SECTION("the broken scheme is named as the source") {
    const Scene s = loadExample("broken_lod.toml");
    const Report r = checkScene(prepared(s), s.camera);
    REQUIRE(r.stats.cracks > 0);
    for (const Finding& f : r.findings) {
      CHECK(f.a.lod.scheme == LodScheme::PatchCenter);
      CHECK(f.a.lod.neighbourSize == 1.0f);
      CHECK(f.a.lod.why.metric > 0.0f); // the projected diameter lod/ measured
    }
  }
  SECTION("constant: no lod/ record") {
    const Scene s = loadExample("grid.toml", {"lod.scheme=constant"});
    CheckOptions o;
    o.keepMatches = true;
    const Report r = checkScene(prepared(s), s.camera, o);
    REQUIRE_FALSE(r.findings.empty());
    CHECK(r.findings[0].a.lod.scheme == LodScheme::Constant);
    CHECK(r.findings[0].a.lod.why.fixes == 0u);
    CHECK(lodWords(r.findings[0].a).empty());
  }
}

TEST_CASE("culled patches run no tessellation and no domain emulation, shared edge points are evaluated once",
          "[verify][prepared]") {
  const Scene s = loadExample("terrain.toml");
  const Terrain t = prepared(s);
  // Looking up into the sky: lod/ culls every patch (its frustum test runs first in the hull shader), and no
  // patch's box touches the frustum, so nothing is tessellated, evaluated or sampled.
  Camera sky = s.camera;
  sky.eye = {0, 50, 0};
  sky.target = {0, 100, 1};
  const Report up = checkScene(t, sky);
  REQUIRE(up.error.empty());
  CHECK(up.stats.culledPatches == up.stats.patches);
  CHECK(up.work.lodEvaluations == up.stats.patches);
  CHECK(up.work.edgeQueries == 0);
  CHECK(up.work.domainEvaluations == up.work.visibilityEvaluations);
  CHECK(up.work.heightSamples == up.work.domainEvaluations);
  CHECK(up.work.fullTessellations == 0);

  // The scene's camera: part of the terrain culled. Every domain evaluation is an edge point of a drawn patch or a
  // point of the hole check's grid: at most two per edge point of the pairs checked, and with the shared points taken
  // from the first side, fewer evaluations than points.
  const Report r = checkScene(t, s.camera);
  REQUIRE(r.stats.culledPatches > 0);
  REQUIRE(r.stats.edgesChecked > 0);
  CHECK(r.work.sharedEdgePoints > 0);
  CHECK(r.work.heightSamples == r.work.domainEvaluations);
  // Without sharing (a fault that changes nothing: a factor's ulp of a culled patch disables it) the same verdicts.
  CheckOptions o;
  Fault fault;
  fault.kind = Fault::Kind::PointUlp;
  fault.patch = 0;
  fault.point = 1000; // out of range: no perturbation, but sharing is off while a fault is set
  o.fault = std::make_shared<const Fault>(fault);
  const Report plain = checkScene(t, s.camera, o);
  CHECK(plain.work.sharedEdgePoints == 0);
  CHECK(plain.stats.matches == r.stats.matches);
  CHECK(plain.stats.cracks == r.stats.cracks);
  CHECK(plain.stats.tJunctions == r.stats.tJunctions);
  CHECK(plain.work.domainEvaluations - plain.work.visibilityEvaluations ==
        r.work.domainEvaluations - r.work.visibilityEvaluations + r.work.sharedEdgePoints);
  CHECK(plain.work.edgeQueries == r.work.edgeQueries);
}
