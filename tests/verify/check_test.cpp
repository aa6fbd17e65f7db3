// The exact edge check: uniform patches never crack, a broken LOD is caught, exact vs float predicates, and the
// whole-mesh check agrees with the edge check on every test scene. Both CGAL kernels throughout.
#include "verify_test_util.h"

#include "base/bits.h"
#include "verify/internal.h"

#include <cmath>
#include <cstring>

using namespace fftess::verify;
using namespace fftess::verify::test;
using fftess::Partitioning;
using fftess::bitsOf;

namespace {

const Kernel kKernels[] = {Kernel::Epick, Kernel::Epeck};

} // namespace

TEST_CASE("check: a uniform grid never cracks, in every scheme and partitioning", "[verify][check]") {
  const char* schemes[] = {"constant", "screen_sphere", "distance_pow2", "bonaventura", "clip_diameter"};
  const char* parts[] = {"integer", "pow2", "fractional_odd", "fractional_even"};
  for (const char* scheme : schemes)
    for (const char* part : parts) {
      Scene s = loadExample("grid.toml", {std::string("lod.scheme=") + scheme,
                                          std::string("tessellation.partitioning=") + part, "lod.factor=7.3",
                                          "layout.patches_x=10", "layout.patches_z=10",
                                          "layout.corners=reconstructed"});
      const Terrain t = prepared(s);
      for (Kernel k : kKernels) {
        for (const Camera& cam : orbitCameras(t, 2, 30.0f, 12.0f)) {
          CheckOptions o;
          o.kernel = k;
          Report r = checkScene(t, cam, o);
          INFO(scheme << " " << part << " " << toString(k));
          REQUIRE(r.error.empty());
          CHECK(r.stats.edgesChecked + r.stats.skippedCulled == 2 * 10 * 9);
          CHECK(r.stats.edgesChecked > 0);
          CHECK(r.stats.cracks == 0);
          CHECK(r.stats.tJunctions == 0);
          CHECK(r.findings.empty());
        }
      }
    }
}

TEST_CASE("check: the broken LOD (factor from the patch centre) is caught", "[verify][check]") {
  for (Kernel k : kKernels) {
    CheckOptions o;
    o.kernel = k;
    Scene broken = loadExample("broken_lod.toml");
    Report r = checkScene(prepared(broken), broken.camera, o);
    INFO(toString(k));
    CHECK(r.stats.cracks > 0);
    REQUIRE_FALSE(r.findings.empty());
    const Finding& f = r.findings.front();
    CHECK(f.classification == Classification::Crack);
    // The two sides of a same-size edge disagree on the factor: that is the bug the verifier points at.
    CHECK(f.a.patch.level == f.b.patch.level);
    CHECK(bitsOf(f.a.hullFactor) != bitsOf(f.b.hullFactor));
    CHECK(f.gapWorld > 0);
    CHECK(f.gapPixels > 0);
    CHECK(f.a.firstMismatch >= 1); // the corners always agree
    // The same scene with the edge-midpoint sphere is watertight.
    Scene fixed = loadExample("broken_lod.toml", {"lod.scheme=screen_sphere"});
    Report g = checkScene(prepared(fixed), fixed.camera, o);
    CHECK(g.stats.cracks == 0);
    CHECK(g.stats.tJunctions == 0);
  }
}

// The float checker evaluates CGAL's collinearity determinant in float. Side a is the single segment
// (0,0,0)-(5,1,0); side b has a vertex at (1, 0.2f, 0). Exactly, 0.2f = 0x3E4CCCCD = 0.20000000298023223876953125
// lies 2^-24 * 0.05 above 1/5, so the vertex is off the segment: a crack of width (5 * 0.2f - 1) / sqrt(26)
// ~ 2.92e-9. In float the determinant 5 * 0.2f - 1 * 1 rounds to 0 (5 * 0.2f = 1.0000000149 rounds to 1.0f) and
// the vertex appears to lie on the segment: a T-junction. The exact kernels are right: the two sides do not share
// the point, and displacing them differently can only widen the gap.
TEST_CASE("check: the exact and float checkers disagree on a sub-ulp offset", "[verify][check]") {
  const float fifth = 0.2f;
  REQUIRE(bitsOf(fifth) == 0x3E4CCCCDu);
  const glm::vec3 a[] = {{0, 0, 0}, {5, 1, 0}};
  const glm::vec3 b[] = {{0, 0, 0}, {1, fifth, 0}, {5, 1, 0}};
  const double expected = (5.0 * double(fifth) - 1.0) / std::sqrt(26.0);
  for (Kernel k : kKernels) {
    detail::ExactVerdict v = detail::classifyExact(k, a, 2, a, 2, b, 3);
    INFO(toString(k));
    CHECK(v.classification == Classification::Crack);
    CHECK(v.gapSide == 1);
    CHECK(v.gapIndex == 1);
    CHECK(v.gap == Approx(expected).epsilon(1e-6));
  }
  detail::ExactVerdict naive = detail::classifyExact(Kernel::FloatNaive, a, 2, a, 2, b, 3);
  CHECK(naive.classification == Classification::TJunction);
}

TEST_CASE("check: a T-junction on flat terrain, a crack when displaced", "[verify][check]") {
  // Integer clamp at a 12 | 2x6 jump: flat terrain keeps every vertex on the big edge's line (T-junctions);
  // displacement lifts the off-line vertices (cracks). Same pairs, same first mismatch. The LOD sees flat corners
  // in both runs (lod.displaced_corners = false, frustum culling off), so both choose the same factors and only
  // the domain shader's height differs.
  const std::vector<std::string> common = {"lod.adjacency_clamp=integer", "lod.displaced_corners=false",
                                           "lod.frustum_cull=false"};
  std::vector<std::string> flatSet = common, displacedSet = common;
  flatSet.push_back("displacement.kind=none");
  for (Kernel k : kKernels) {
    INFO(toString(k));
    CheckOptions o;
    o.kernel = k;
    o.maxFindings = 1000000;
    Scene flat = loadExample("terrain.toml", flatSet);
    Scene displaced = loadExample("terrain.toml", displacedSet);
    REQUIRE(displaced.displacement.kind != DisplacementKind::None);
    Report rf = checkScene(prepared(flat), flat.camera, o);
    Report rd = checkScene(prepared(displaced), displaced.camera, o);
    REQUIRE_FALSE(rf.truncated);
    REQUIRE_FALSE(rd.truncated);
    CHECK(rf.stats.tJunctions > 0);
    CHECK(rf.stats.cracks == 0);
    for (const Finding& f : rf.findings) CHECK(f.gapWorld == 0);
    if (k == Kernel::FloatNaive) continue; // float predicates may call a lifted vertex "on the line"
    // Displaced: every flat T-junction is a crack now, at the same pair and the same first mismatch.
    CHECK(rd.stats.tJunctions == 0);
    CHECK(rd.stats.cracks == rf.stats.tJunctions);
    REQUIRE(rd.findings.size() == rf.findings.size());
    for (size_t i = 0; i < rf.findings.size(); ++i) {
      const Finding& f = rf.findings[i];
      const Finding& d = rd.findings[i];
      CHECK(d.classification == Classification::Crack);
      CHECK(d.gapWorld > 0);
      CHECK(d.a.patch.index == f.a.patch.index);
      CHECK(d.a.edge == f.a.edge);
      CHECK(d.b.patch.index == f.b.patch.index);
      CHECK(d.a.firstMismatch == f.a.firstMismatch);
      CHECK(d.b.firstMismatch == f.b.firstMismatch);
    }
  }
}

TEST_CASE("check: the whole-mesh check agrees with the edge check", "[verify][check][mesh][slow]") {
  struct Case {
    const char* file;
    std::vector<std::string> overrides;
  };
  const Case cases[] = {
      {"rings_small.toml", {}},
      {"rings_small.toml", {"lod.adjacency_clamp=none"}},
      {"rings_small.toml", {"lod.adjacency_clamp=integer"}},
      {"rings_small.toml", {"lod.adjacency_clamp=integer", "displacement.kind=none"}},
      {"rings_small.toml", {"lod.displaced_corners=true"}},
      {"grid.toml", {}},
      {"broken_lod.toml", {}},
      {"luna.toml", {}},
  };
  for (const Case& c : cases) {
    Scene s = loadExample(c.file, c.overrides);
    CheckOptions o;
    o.maxFindings = 1000000;
    Report r = checkScene(prepared(s), s.camera, o);
    MeshReport m = checkSceneMesh(prepared(s), s.camera, o);
    std::string label = c.file;
    for (const auto& ov : c.overrides) label += " " + ov;
    INFO(label << ": edge check " << r.stats.cracks << " cracks, " << r.stats.tJunctions << " T-junctions; mesh "
               << m.innerBorderEdges << " inner border edges");
    REQUIRE_FALSE(r.truncated);
    CHECK(m.patchesDrawn == r.stats.patches - r.stats.culledPatches);
    CHECK(m.triangles > 0);
    CHECK((m.innerBorderEdges > 0) == (r.stats.cracks + r.stats.tJunctions > 0));
    CHECK(flaggedPatchEdges(r) == m.flagged);
  }
}

// A big edge beside two half-size neighbours, one of them culled: the edge check classifies the drawn half (a crack
// with the clamp off) and skips the culled one; the whole-mesh check must do the same per half (it used to ignore
// the whole big edge, and `fftess check --mesh` exited 3). Random cameras 6 and 7 of seed 1 on rings_small.toml with
// the clamp off have such cracks.
TEST_CASE("check: the whole-mesh check agrees beside a half-culled edge", "[verify][check][mesh][slow]") {
  const Scene s = loadExample("rings_small.toml", {"lod.adjacency_clamp=none"});
  const Terrain t = prepared(s);
  const detail::TerrainData& d = t.data();
  const std::vector<Camera> cams = randomCameras(t, 8, 1);
  CheckOptions o;
  o.maxFindings = 1000000;
  int halfCulled = 0;
  for (size_t k : {size_t(6), size_t(7)}) {
    const Report r = checkScene(t, cams[k], o);
    REQUIRE(r.error.empty());
    REQUIRE_FALSE(r.truncated);
    std::vector<fftess::lod::PatchLod> lod;
    fftess::verify::WorkStats work;
    detail::computeFactors(d, cams[k], lod, work);
    auto culled = [&](int p) {
      const fftess::lod::PatchLod& l = lod[static_cast<size_t>(p)];
      bool c = l.why.culled;
      for (int e = 0; e < 4; ++e) c = c || !(l.factors[e] > 0);
      return c;
    };
    // Findings on the drawn half of a big edge whose other half's neighbour is culled.
    for (const Finding& f : r.findings) {
      const EdgeSide& big = f.a.patch.level > f.b.patch.level ? f.a : f.b;
      const EdgeSide& small = f.a.patch.level > f.b.patch.level ? f.b : f.a;
      if (f.classification == Classification::Match || big.patch.level == small.patch.level) continue;
      const auto& nb = d.patches[static_cast<size_t>(big.patch.index)].nb[big.edge];
      const int other = nb[0] == small.patch.index ? nb[1] : nb[0];
      if (other >= 0 && culled(other)) ++halfCulled;
    }
    const MeshReport m = checkSceneMesh(t, cams[k], o);
    INFO("camera " << k << ": " << r.stats.cracks << " cracks");
    CHECK(flaggedPatchEdges(r) == m.flagged);
  }
  CHECK(halfCulled > 0); // the case is there
}

TEST_CASE("check: Epick and Epeck agree on every verdict", "[verify][check]") {
  Scene s = loadExample("rings_small.toml", {"lod.adjacency_clamp=none"});
  CheckOptions a, b;
  a.kernel = Kernel::Epick;
  b.kernel = Kernel::Epeck;
  Report ra = checkScene(prepared(s), s.camera, a), rb = checkScene(prepared(s), s.camera, b);
  REQUIRE(ra.findings.size() == rb.findings.size());
  CHECK(ra.stats.cracks > 0);
  CHECK(ra.stats.cracks == rb.stats.cracks);
  CHECK(ra.stats.tJunctions == rb.stats.tJunctions);
  for (size_t i = 0; i < ra.findings.size(); ++i) {
    CHECK(ra.findings[i].classification == rb.findings[i].classification);
    CHECK(ra.findings[i].gapWorld == Approx(rb.findings[i].gapWorld).epsilon(1e-9));
  }
}

// Domain-shader formulas, hand-checked: one patch of size 0.5 centred at 0.02 has corners x = -0.23f (0xBE6B851F)
// and 0.27f (0x3E8A3D71). At u = 1, "lerp" computes -0.23f + 1*(0.27f - -0.23f): the difference 0.5 rounds, and
// the sum lands one ulp below the corner, 0x3E8A3D70; "blend" computes -0.23f*0 + 0.27f*1 = the corner exactly.
// That ulp is why two patches can disagree at a shared corner although they read the same vertex buffer.
TEST_CASE("domain: the formula's order decides the corner bits", "[verify][domain]") {
  const char* base = R"([layout]
kind = "grid"
patches_x = 1
patches_z = 1
patch_size = 0.5
center = [0.02, 0.02]
corners = "shared"
[lod]
scheme = "constant"
[tessellation]
partitioning = "integer"
[camera]
eye = [0.0, 5.0, -5.0]
target = [0.0, 0.0, 0.0]
)";
  SceneResult lerp = parseScene(base, "f.toml", {"domain.formula=lerp"});
  SceneResult blend = parseScene(base, "f.toml", {"domain.formula=blend"});
  REQUIRE(lerp.ok);
  REQUIRE(blend.ok);
  const Extent e = prepared(lerp.scene).extent();
  REQUIRE(bitsOf(e.minX) == 0xBE6B851Fu);
  REQUIRE(bitsOf(e.maxX) == 0x3E8A3D71u);
  CHECK(bitsOf(domainPosition(prepared(lerp.scene), 0, 1.0f, 0.0f).x) == 0x3E8A3D70u);
  CHECK(bitsOf(domainPosition(prepared(blend.scene), 0, 1.0f, 0.0f).x) == 0x3E8A3D71u);
  CHECK(bitsOf(domainPosition(prepared(lerp.scene), 0, 0.0f, 0.0f).x) == 0xBE6B851Fu);
}
