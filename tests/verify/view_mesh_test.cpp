// The terrain as one camera draws it (verify/view_mesh.h): compared with the tessellator's own output
// (fftess::Tessellator, fftess::edgePoints), the domain shader's positions (domainPosition) and the check's report.
#include "verify_test_util.h"

#include "tessellator/tessellator.h"
#include "verify/view_mesh.h"

#include <catch2/catch.hpp>

#include <map>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// rings_small without the clamp: three patch sizes, cracks at the size jumps, fbm displacement, no camera state in
// the domain shader (no geomorph, no mips), so domainPosition gives the drawn positions.
struct Fixture {
  explicit Fixture(const std::string& name = "rings_small.toml",
                   const std::vector<std::string>& overrides = {"lod.adjacency_clamp=none"})
      : scene(loadExample(name, overrides)), terrain(prepared(scene)), view(layoutFor(terrain, scene.camera)) {}
  Scene scene;
  Terrain terrain;
  Terrain view;
};

DomainPoint onEdge(int e, float t) {
  switch (e) {
  case Ueq0: return {0.0f, t};
  case Ueq1: return {1.0f, t};
  case Veq0: return {t, 0.0f};
  default: return {t, 1.0f};
  }
}

} // namespace

TEST_CASE("view mesh: every drawn patch is the tessellator's output for its hull factors at the domain shader's "
          "positions",
          "[verify][view_mesh]") {
  const Fixture f;
  const ViewMesh vm = viewMesh(f.terrain, f.scene.camera);
  REQUIRE(vm.error.empty());
  REQUIRE(vm.drawnAt.size() == static_cast<size_t>(f.view.patchCount()));
  REQUIRE(vm.patches.size() > 100);
  CHECK(vm.points.size() == vm.domain.size());
  Tessellator tess;
  uint32_t nextPoint = 0, nextIndex = 0;
  for (size_t k = 0; k < vm.patches.size(); ++k) {
    const ViewPatch& vp = vm.patches[k];
    INFO("patch " << vp.ref.index);
    CHECK(vm.drawnAt.at(static_cast<size_t>(vp.ref.index)) == static_cast<int>(k));
    CHECK(vp.ref.level == f.view.patches()[static_cast<size_t>(vp.ref.index)].ref.level);
    CHECK(vp.firstPoint == nextPoint); // packed in layout order
    CHECK(vp.firstIndex == nextIndex);
    Patch p;
    p.domain = Domain::Quad;
    p.partitioning = f.scene.partitioning;
    p.primitive = OutputPrimitive::TriangleCw;
    p.stage = f.scene.stage;
    std::copy(vp.factors, vp.factors + 6, p.factors);
    const int count = tess.tessellate(p);
    REQUIRE(vp.pointCount == static_cast<uint32_t>(count));
    REQUIRE(vp.indexCount == tess.indices().size());
    for (int q = 0; q < count; ++q) {
      const DomainPoint& d = tess.points()[static_cast<size_t>(q)];
      const DomainPoint& mine = vm.domain[vp.firstPoint + static_cast<uint32_t>(q)];
      if (!(mine.u == d.u && mine.v == d.v)) FAIL_CHECK("domain point " << q);
      if (!(vm.points[vp.firstPoint + static_cast<uint32_t>(q)] == domainPosition(f.view, vp.ref.index, d.u, d.v)))
        FAIL_CHECK("world point " << q);
    }
    for (size_t q = 0; q < tess.indices().size(); ++q)
      if (vm.indices[vp.firstIndex + q] != vp.firstPoint + static_cast<uint32_t>(tess.indices()[q]))
        FAIL_CHECK("index " << q);
    nextPoint += vp.pointCount, nextIndex += vp.indexCount;
  }
  CHECK(vm.points.size() == nextPoint);
  CHECK(vm.indices.size() == nextIndex);
  CHECK(vm.work.fullTessellations == f.view.patchCount());
}

TEST_CASE("view mesh: it tessellates the check's hull factors and draws exactly the patches the check does not cull",
          "[verify][view_mesh]") {
  const Fixture f;
  CheckOptions opt;
  opt.keepMatches = true; // every shared edge pair, both sides' factors
  opt.maxFindings = static_cast<size_t>(-1);
  const Report r = checkScene(f.terrain, f.scene.camera, opt);
  REQUIRE(r.error.empty());
  REQUIRE(r.stats.cracks > 0);
  const ViewMesh vm = viewMesh(f.terrain, f.scene.camera, opt);
  CHECK(static_cast<int64_t>(vm.patches.size()) == r.stats.patches - r.stats.culledPatches);
  size_t sides = 0;
  for (const Finding& fd : r.findings)
    for (const EdgeSide* s : {&fd.a, &fd.b}) {
      const int at = vm.drawnAt.at(static_cast<size_t>(s->patch.index));
      REQUIRE(at >= 0); // classified pairs are between drawn patches
      CHECK(bitsOf(vm.patches[static_cast<size_t>(at)].factors[s->edge]) == s->hullFactorBits);
      ++sides;
    }
  CHECK(sides > 1000);
}

TEST_CASE("view mesh: a fill is a grid over the patch's domain at the domain shader's positions",
          "[verify][view_mesh]") {
  const Fixture f;
  const ViewMesh drawnOnly = viewMesh(f.terrain, f.scene.camera);
  int culled = -1;
  for (size_t i = 0; i < drawnOnly.drawnAt.size() && culled < 0; ++i)
    if (drawnOnly.drawnAt[i] < 0) culled = static_cast<int>(i);
  REQUIRE(culled >= 0);
  const int n = 4;
  const ViewMesh vm = viewMesh(f.terrain, f.scene.camera, {}, {culled, -1, f.view.patchCount(), 0}, n);
  REQUIRE(vm.fills.size() == 2); // the indices out of range are skipped
  CHECK(vm.patches.size() == drawnOnly.patches.size());
  for (size_t k = 0; k < 2; ++k) {
    const ViewPatch& fp = vm.fills[k];
    const int patch = k == 0 ? culled : 0;
    CHECK(fp.ref.index == patch);
    REQUIRE(fp.pointCount == (n + 1) * (n + 1));
    REQUIRE(fp.indexCount == n * n * 6);
    for (int b = 0; b <= n; ++b)
      for (int a = 0; a <= n; ++a) {
        const uint32_t at = fp.firstPoint + static_cast<uint32_t>(b * (n + 1) + a);
        const float u = static_cast<float>(a) / n, v = static_cast<float>(b) / n;
        CHECK(vm.points[at] == domainPosition(f.view, patch, u, v));
      }
    for (uint32_t q = fp.firstIndex; q < fp.firstIndex + fp.indexCount; ++q) {
      CHECK(vm.indices[q] >= fp.firstPoint);
      CHECK(vm.indices[q] < fp.firstPoint + fp.pointCount);
    }
  }
}

TEST_CASE("edge polyline: a finding side's points are fftess::edgePoints of its factor in its shared part, in order",
          "[verify][view_mesh]") {
  // rings_small: fractional_even factors, every half edge ends on a vertex; t_junction: integer factor 5 beside 3,
  // the big side's halves end between vertices (cover adds one).
  const std::string name = GENERATE(as<std::string>{}, "rings_small.toml", "t_junction.toml");
  const Fixture f(name, name == "rings_small.toml" ? std::vector<std::string>{"lod.adjacency_clamp=none"}
                                                    : std::vector<std::string>{});
  const Report r = checkScene(f.terrain, f.scene.camera);
  const ViewMesh vm = viewMesh(f.terrain, f.scene.camera);
  REQUIRE(r.stats.cracks + r.stats.tJunctions > 0);
  size_t widened = 0;
  for (const Finding& fd : r.findings)
    for (const EdgeSide* s : {&fd.a, &fd.b}) {
      const EdgePoints ep = edgePoints(s->hullFactor, f.scene.partitioning, f.scene.stage);
      std::vector<glm::vec3> expect, covered;
      int before = -1, after = -1;
      for (int k = 0; k < ep.count; ++k) {
        const float t = ep.param[k];
        const DomainPoint d = onEdge(s->edge, t);
        const glm::vec3 w = domainPosition(f.view, s->patch.index, d.u, d.v);
        if (t < s->paramLo) before = k;
        else if (t <= s->paramHi) expect.push_back(w);
        else if (after < 0) after = k;
      }
      const std::vector<glm::vec3> got = edgePolyline(vm, s->patch.index, s->edge, s->paramLo, s->paramHi);
      CHECK(static_cast<int>(expect.size()) == s->pointCount);
      CHECK(got == expect);
      // cover: one point more at each end where the part does not start or end on a vertex.
      const std::vector<glm::vec3> wide = edgePolyline(vm, s->patch.index, s->edge, s->paramLo, s->paramHi, true);
      const bool startsOn = !expect.empty() && ep.param[before + 1] == s->paramLo;
      const bool endsOn = !expect.empty() && ep.param[before + static_cast<int>(expect.size())] == s->paramHi;
      CHECK(wide.size() == expect.size() + (startsOn || before < 0 ? 0 : 1) + (endsOn || after < 0 ? 0 : 1));
      widened += wide.size() - expect.size();
    }
  CHECK((widened > 0) == (name == "t_junction.toml"));
}
