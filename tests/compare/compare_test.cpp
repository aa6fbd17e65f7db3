// Corrupted captures, built from the emulator's own output, are each detected and classified; the typical port
// bugs are named. The buggy captures are built here independently of compare's bug models (from the formula the
// buggy port would use), except where noted.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "base/bits.h"
#include "tessellator/batch.h"
#include "compare/compare.h"
#include "compare_test_util.h"

using namespace fftess;

namespace {

using comparetest::patchOf;
using comparetest::run;

bool named(const PatchComparison& c, PortBug b) { return std::find(c.bugs.begin(), c.bugs.end(), b) != c.bugs.end(); }

// Every coordinate of the capture through f (coordinates 0, 1 stay).
template <class F> CapturedPatch mapCoordinates(CapturedPatch c, F f) {
  for (auto& v : c.vertices) {
    v.u = bitsOf(f(floatOf(v.u)));
    v.v = bitsOf(f(floatOf(v.v)));
  }
  return c;
}

const char* const kPatches[] = {
    "quad integer triangle_cw hw 3 3 3 3 3 3",
    "quad fractional_even triangle_ccw hw 2.5 4 5.25 3 3.5 2.75",
    "quad fractional_odd triangle_cw hw 7.1 3 1 9 4.4 2",
    "tri integer triangle_ccw hw 3 4 5 4 0 0",
    "tri fractional_even triangle_cw hw 3.7 2 9.1 5.5 0 0",
    "isoline integer line hw 3 5 0 0 0 0",
    "quad pow2 point hw 5 6 7 8 9 10",
};

} // namespace

TEST_CASE("compare: the emulator's own output is the same, in both modes, as triangles and as point lists",
          "[compare]") {
  for (const char* line : kPatches) {
    const Patch p = patchOf(line);
    for (bool pointList : {false, true}) {
      const CapturedPatch c = referenceCapture(p, 0, {}, pointList);
      INFO(line << (pointList ? " as points" : ""));
      CHECK(run(p, &c).kind == DifferenceKind::Same);
      CHECK(run(p, &c, true).kind == DifferenceKind::Same);
    }
  }
}

TEST_CASE("compare: one coordinate off by one ulp or by one 16.16 step is points_differ, with its nearest point",
          "[compare]") {
  const Patch p = patchOf("quad fractional_even triangle_cw hw 2.5 4 5.25 3 3.5 2.75");
  for (int step : {0, 1}) {
    CapturedPatch c = referenceCapture(p, 0, {});
    // Change one interior vertex coordinate everywhere it occurs (the point moves, its triangles follow).
    CapturedVertex victim{};
    for (auto v : c.vertices)
      if (floatOf(v.u) > 0.0f && floatOf(v.u) < 1.0f && floatOf(v.v) > 0.0f && floatOf(v.v) < 1.0f) victim = v;
    const float u = floatOf(victim.u);
    REQUIRE(u > 0.0f);
    const uint32_t moved = step ? bitsOf(u + 1.0f / 65536.0f) : victim.u + 1;
    for (auto& v : c.vertices)
      if (v == victim) v.u = moved;
    const PatchComparison r = run(p, &c);
    INFO("step " << step);
    REQUIRE(r.kind == DifferenceKind::PointsDiffer);
    CHECK(r.extraPoints == 1);
    CHECK(r.missingPoints == 1);
    REQUIRE(r.points.size() == 1);
    CHECK(r.points[0].nearest == victim);
    CHECK(r.points[0].dv == 0.0);
    if (step)
      CHECK(r.points[0].du == 1.0);
    else
      CHECK((r.points[0].du > 0.0 && r.points[0].du < 0.01));
    CHECK(r.bugs.empty());
  }
}

TEST_CASE("compare: flipped winding is winding_only, all flipped is named winding_swapped", "[compare]") {
  const Patch p = patchOf("tri integer triangle_ccw hw 3 4 5 4 0 0");
  CapturedPatch all = referenceCapture(p, 0, {});
  for (size_t i = 0; i < all.vertices.size(); i += 3) std::swap(all.vertices[i + 1], all.vertices[i + 2]);
  PatchComparison r = run(p, &all);
  CHECK(r.kind == DifferenceKind::WindingOnly);
  CHECK(r.flippedTriangles == r.referencePrimitives);
  CHECK(named(r, PortBug::WindingSwapped));

  CapturedPatch one = referenceCapture(p, 0, {});
  std::swap(one.vertices[1], one.vertices[2]);
  r = run(p, &one);
  CHECK(r.kind == DifferenceKind::WindingOnly);
  CHECK(r.flippedTriangles == 1);
  CHECK_FALSE(named(r, PortBug::WindingSwapped));
}

TEST_CASE("compare: rotated triangles match by default and are rotated with strict order", "[compare]") {
  const Patch p = patchOf("quad integer triangle_cw hw 3 3 3 3 3 3");
  CapturedPatch c = referenceCapture(p, 0, {});
  for (size_t i = 0; i < c.vertices.size(); i += 3)
    std::rotate(c.vertices.begin() + long(i), c.vertices.begin() + long(i) + 1, c.vertices.begin() + long(i) + 3);
  CHECK(run(p, &c).kind == DifferenceKind::Same);
  const PatchComparison strict = run(p, &c, true);
  CHECK(strict.kind == DifferenceKind::Rotated);
  CHECK(strict.rotatedPrimitives == strict.referencePrimitives);
  CHECK(strict.onlyInReferenceCount + strict.onlyInCaptureCount == 0);
  // Reordered primitives (same first vertices): also only strict order sees it.
  CapturedPatch r = referenceCapture(p, 0, {});
  std::swap_ranges(r.vertices.begin(), r.vertices.begin() + 3, r.vertices.begin() + 3);
  CHECK(run(p, &r).kind == DifferenceKind::Same);
  CHECK(run(p, &r, true).kind == DifferenceKind::OrderDiffers);
}

TEST_CASE("compare: a missing patch, a patch culled on either side", "[compare]") {
  const Patch p = patchOf("quad integer triangle_cw hw 3 3 3 3 3 3");
  CHECK(run(p, nullptr).kind == DifferenceKind::CulledInCapture);
  CapturedPatch empty;
  empty.patch = 0;
  CHECK(run(p, &empty).kind == DifferenceKind::CulledInCapture);
  const Patch culled = patchOf("quad integer triangle_cw hw 3 0 3 3 3 3");
  const CapturedPatch c = referenceCapture(p, 0, {});
  CHECK(run(culled, &c).kind == DifferenceKind::CulledInReference);
  CHECK(run(culled, nullptr).kind == DifferenceKind::Same);
}

TEST_CASE("compare: multiplicity and triangulation_differs", "[compare]") {
  const Patch p = patchOf("quad integer point hw 3 3 3 3 3 3");
  CapturedPatch c = referenceCapture(p, 0, {});
  c.vertices.push_back(c.vertices[3]);
  CHECK(run(p, &c).kind == DifferenceKind::Multiplicity);

  // The other diagonal of the first two triangles' quad (if they share an edge): same points, other triangles.
  const Patch t = patchOf("quad integer triangle_cw hw 1 1 1 1 1 1");
  CapturedPatch q = referenceCapture(t, 0, {});
  REQUIRE(q.vertices.size() == 6); // (0,1,3) (1,2,3) as corners 0..3
  const CapturedVertex a = q.vertices[0], b = q.vertices[1], cc = q.vertices[4], d = q.vertices[2];
  q.vertices = {a, b, cc, a, cc, d};
  CHECK(run(t, &q).kind == DifferenceKind::TriangulationDiffers);

}

TEST_CASE("compare: float division instead of the 16.16 reciprocal is named, with its step", "[compare]") {
  for (int n : {3, 5, 7}) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "quad integer triangle_cw hw %d %d %d %d %d %d", n, n, n, n, n, n);
    const Patch p = patchOf(buf);
    // The buggy port: point k of n at float(k) / float(n).
    const CapturedPatch c = mapCoordinates(referenceCapture(p, 0, {}), [n](float x) {
      const float k = std::round(x * float(n));
      return x == 0.0f || x == 1.0f ? x : k / float(n);
    });
    const PatchComparison r = run(p, &c);
    INFO(buf);
    REQUIRE(r.kind == DifferenceKind::PointsDiffer);
    CHECK(named(r, PortBug::FloatDivision));
    CHECK(r.bugs.size() == 1);
    REQUIRE_FALSE(r.points.empty());
    CHECK(r.points[0].step == "reciprocal rounding");
  }
}

TEST_CASE("compare: no mirroring of the second half is named", "[compare]") {
  const Patch p = patchOf("quad integer point hw 3 5 7 6 3 5");
  // The buggy port: point k of n at k * round(65536 / n) also past the middle (not 1 - (n - k) * ...).
  auto place = [](int k, int n) {
    const uint32_t r = (65536u + unsigned(n) / 2) / unsigned(n);
    const uint32_t x = uint32_t(k) * r;
    return float(x >> 16) + float(x & 0xffff) / 65536.0f;
  };
  CapturedPatch c = referenceCapture(p, 0, {});
  const float f[6] = {3, 5, 7, 6, 3, 5};
  for (auto& v : c.vertices) {
    float u = floatOf(v.u), w = floatOf(v.v);
    // Which factor places each coordinate: outer edges on the border, inside factors inside.
    const bool uEdge = u == 0.0f || u == 1.0f, vEdge = w == 0.0f || w == 1.0f;
    if (uEdge && vEdge) continue;
    const int nu = vEdge ? int(f[w == 0.0f ? 1 : 3]) : int(f[4]);
    const int nv = uEdge ? int(f[u == 0.0f ? 0 : 2]) : int(f[5]);
    if (!uEdge && u > 0.5f) u = place(int(std::lround(u * float(nu))), nu);
    if (!vEdge && w > 0.5f) w = place(int(std::lround(w * float(nv))), nv);
    v.u = bitsOf(u);
    v.v = bitsOf(w);
  }
  const PatchComparison r = run(p, &c);
  REQUIRE(r.kind == DifferenceKind::PointsDiffer);
  CHECK(named(r, PortBug::NoMirroring));
  REQUIRE_FALSE(r.points.empty());
  CHECK(r.points[0].step == "mirrored half");
}

TEST_CASE("compare: the middle point computed instead of the exact 0.5 is named", "[compare]") {
  const Patch p = patchOf("quad integer triangle_ccw hw 6 6 6 6 6 6");
  // 3 * round(65536 / 6) = 32769, not 32768.
  const CapturedPatch c =
      mapCoordinates(referenceCapture(p, 0, {}), [](float x) { return x == 0.5f ? 32769.0f / 65536.0f : x; });
  const PatchComparison r = run(p, &c);
  REQUIRE(r.kind == DifferenceKind::PointsDiffer);
  CHECK(named(r, PortBug::NoSpecialMidpoint));
  CHECK(r.points.at(0).step == "special midpoint");
  CHECK(r.points.at(0).du + r.points.at(0).dv == 1.0);
}

TEST_CASE("compare: denormals flushed and pow2 not mapped to integer are named", "[compare]") {
  const Patch d = patchOf("quad integer triangle_cw hw 4 0x00000010 4 4 4 4");
  const PatchComparison r = run(d, nullptr);
  CHECK(r.kind == DifferenceKind::CulledInCapture);
  CHECK(named(r, PortBug::DenormalsFlushed));

  const Patch p = patchOf("quad pow2 triangle_cw hw 3 5 6 3 7 2.5");
  Patch fe = p;
  fe.partitioning = Partitioning::FractionalEven;
  const CapturedPatch c = referenceCapture(fe, 0, {});
  const PatchComparison q = run(p, &c);
  CHECK(q.kind == DifferenceKind::PointsDiffer);
  CHECK(named(q, PortBug::Pow2AsFractionalEven));
  CHECK_FALSE(named(q, PortBug::Pow2AsFractionalOdd));
}

TEST_CASE("compare: fractional factors not snapped to 16.16 and an unrounded lerp are named (bug-model captures)",
          "[compare]") {
  // These two captures come from compare's own bug model applied to the reference (buggyEdgeParam): the test checks
  // that the model changes the output and that the recognition finds it, not the model itself.
  for (PortBug b : {PortBug::FactorsNotSnapped, PortBug::LerpNotRounded}) {
    // The first Ueq0 factor (5.01, 5.02, ...) where the bug moves a point.
    float f = 5.01f; // above 4: segment counts that are not powers of two (else float division gives the same values)
    for (; f < 64.0f; f += 0.01f) {
      const EdgeTrace tr = traceEdge(f, Partitioning::FractionalEven);
      bool moves = false;
      for (int k = 0; k < tr.count; ++k)
        moves = moves || bitsOf(buggyEdgeParam(b, tr, k, tr.clamped)) != bitsOf(tr.points[k].param);
      if (moves) break;
    }
    char line[96];
    std::snprintf(line, sizeof line, "quad fractional_even point hw %.9g 4 4 4 4 4", double(f));
    const Patch p = patchOf(line);
    CapturedPatch c = referenceCapture(p, 0, {}, true);
    // Edge Ueq0 (u == 0): v values through the model.
    const EdgeTrace tr = traceEdge(p.factors[0], p.partitioning);
    bool changed = false;
    for (auto& v : c.vertices) {
      if (v.u != 0 || floatOf(v.v) == 0.0f || floatOf(v.v) == 1.0f) continue;
      for (int k = 0; k < tr.count; ++k)
        if (bitsOf(tr.points[k].param) == v.v) {
          const float m = buggyEdgeParam(b, tr, k, tr.clamped);
          changed = changed || bitsOf(m) != v.v;
          v.v = bitsOf(m);
          break;
        }
    }
    INFO(toString(b));
    REQUIRE(changed);
    const PatchComparison r = run(p, &c);
    CHECK(r.kind == DifferenceKind::PointsDiffer);
    CHECK(named(r, b));
    CHECK(r.points.at(0).step == stepOf(b));
  }
}

TEST_CASE("compare: summary counts and the bug that explains every differing patch", "[compare]") {
  CompareSummary s;
  Tessellator t;
  const Patch p = patchOf("tri integer triangle_ccw hw 3 4 5 4 0 0");
  CapturedPatch all = referenceCapture(p, 0, {});
  for (size_t i = 0; i < all.vertices.size(); i += 3) std::swap(all.vertices[i + 1], all.vertices[i + 2]);
  s.add(comparePatch(p, &all, {}, t), 10);
  const CapturedPatch same = referenceCapture(p, 1, {});
  s.add(comparePatch(p, &same, {}, t), 10);
  CHECK(s.patches == 2);
  CHECK(s.same == 1);
  CHECK(s.differing == 1);
  CHECK(s.byKind[size_t(DifferenceKind::WindingOnly)] == 1);
  REQUIRE(s.explainingAll().size() == 1);
  CHECK(s.explainingAll()[0] == PortBug::WindingSwapped);
}

TEST_CASE("compare: an unsnapped fractional factor just above an even integer adds points, named factors_not_snapped",
          "[compare]") {
  // 2 + 2^-22 rounds to 2.0 in 16.16: the reference places 3 points on Ueq0 (facts.md). A port comparing the float
  // sees a factor above 2 and grows two more points at the ends of the middle (here: duplicates of 0 and 0.5 after
  // rounding), as the reference does for 2 + 2^-16, the next 16.16 value.
  const Patch p = patchOf("quad fractional_even point hw 0x40000002 4 4 4 4 4");
  Patch next = p;
  next.factors[0] = 2.0f + 1.0f / 65536.0f;
  const CapturedPatch c = referenceCapture(next, 0, {}, true);
  const PatchComparison r = run(p, &c);
  CHECK(r.capturePrimitives == r.referencePrimitives + 2);
  CHECK(named(r, PortBug::FactorsNotSnapped));
  CHECK(r.bugs.size() == 1);
}
