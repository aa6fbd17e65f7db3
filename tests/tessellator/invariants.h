// Invariant checks shared by the tessellator tests (random patches, golden hash-file patches).
#pragma once

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "factor_samples.h"

namespace fftess {
namespace testing {


inline bool anyOuterNotPositive(const Patch& p, bool flush) {
  const int outer = p.domain == Domain::Quad ? 4 : p.domain == Domain::Tri ? 3 : 2;
  for (int i = 0; i < outer; ++i) {
    float f = p.factors[i];
    if (flush && std::fpclassify(f) == FP_SUBNORMAL) f = 0.0f;
    if (!(f > 0.0f)) return true;
  }
  return false;
}

// Checks the outer ring of a quad or tri output against the edge query, edge by edge.
inline void checkOuterRing(const Patch& p, const Tessellator& t, const Options& o) {
  const auto& pts = t.points();
  const int edges = p.domain == Domain::Quad ? 4 : 3;
  int start = 0;
  for (int e = 0; e < edges; ++e) {
    const EdgePoints ep = edgePoints(p.factors[e], p.partitioning, p.stage, o);
    INFO("edge " << e << " factor " << hex(p.factors[e]) << " edge points " << ep.count);
    REQUIRE(!ep.culled);
    const int last = ep.count - 1;
    for (int k = 0; k <= last; ++k) {
      int idx = (k == last && e == edges - 1) ? 0 : start + k; // the last edge ends on the first point
      // The minimum quad (all factors 1) lists its corners from (0,0) instead of (0,1): rotate by one.
      if (p.domain == Domain::Quad && pts.size() == 4) idx = (idx + 3) % 4;
      REQUIRE(size_t(idx) < pts.size());
      const DomainPoint q = pts[size_t(idx)];
      float along, across, expectAcross;
      bool forward;
      if (p.domain == Domain::Quad) {
        forward = e == 1 || e == 2;
        along = (e & 1) ? q.u : q.v;
        across = (e & 1) ? q.v : q.u;
        expectAcross = (e == 2 || e == 3) ? 1.0f : 0.0f;
      } else {
        forward = (e & 1) != 0;
        along = e == 0 ? q.v : q.u;
        across = e == 0 ? q.u : e == 1 ? q.v : q.v; // Weq0: v = 1 - u in 16.16
        expectAcross = e == 2 ? 1.0f - along : 0.0f;
      }
      const float expected = ep.param[forward ? k : last - k];
      INFO("point " << idx << " (" << hex(q.u) << ", " << hex(q.v) << ") k " << k);
      REQUIRE(bitsOf(along) == bitsOf(expected));
      REQUIRE(bitsOf(across) == bitsOf(expectAcross));
    }
    start += last;
  }
}



// Checks every output invariant of one tessellated patch; returns false if the patch was (correctly) culled.
// t holds the result of tessellating p with options o; scratch is any other Tessellator.
inline bool checkInvariants(const Patch& p, const Options& o, const Tessellator& t, Tessellator& tw) {
  const auto& pts = t.points();
  const auto& idx = t.indices();
    // Output sizes match the closed-form counts.
    const OutputCounts c = outputCounts(p, o);
    REQUIRE(int(pts.size()) == c.points);
    REQUIRE(int(idx.size()) == c.indices);

    // Culling: any outer factor not > 0 (NaN, +-0, negative, -Inf) culls; with flushDenormals a denormal does too.
    // The HLSL stage culls on the same condition.
    const bool expectCulled = anyOuterNotPositive(p, o.flushDenormals);
    REQUIRE(pts.empty() == expectCulled);
    if (expectCulled) return false;

    // Coordinates in [0,1], exact under 1 - (1 - u), never -0.
    for (const DomainPoint& q : pts) {
      REQUIRE(q.u >= 0.0f);
      REQUIRE(q.u <= 1.0f);
      REQUIRE(q.v >= 0.0f);
      REQUIRE(q.v <= 1.0f);
      REQUIRE(1.0f - (1.0f - q.u) == q.u);
      REQUIRE(1.0f - (1.0f - q.v) == q.v);
      REQUIRE(bitsOf(q.u) != 0x80000000u);
      REQUIRE(bitsOf(q.v) != 0x80000000u);
      if (p.domain == Domain::Tri) REQUIRE(q.u + q.v <= 1.0f);
    }
    // Every index in range.
    for (int32_t i : idx) {
      REQUIRE(i >= 0);
      REQUIRE(size_t(i) < pts.size());
    }
    // Outer edges: equal to the edge query (so they depend only on their own factor and partitioning).
    if (p.domain != Domain::Isoline) checkOuterRing(p, t, o);

    // triangle_ccw is triangle_cw with the 2nd and 3rd index of every triangle swapped, nothing else.
    if (p.domain != Domain::Isoline &&
        (p.primitive == OutputPrimitive::TriangleCw || p.primitive == OutputPrimitive::TriangleCcw)) {
      Patch other = p;
      other.primitive =
          p.primitive == OutputPrimitive::TriangleCw ? OutputPrimitive::TriangleCcw : OutputPrimitive::TriangleCw;
      tw.tessellate(other, o);
      REQUIRE(tw.points().size() == pts.size());
      REQUIRE(std::equal(pts.begin(), pts.end(), tw.points().begin(), [](DomainPoint a, DomainPoint b) {
        return bitsOf(a.u) == bitsOf(b.u) && bitsOf(a.v) == bitsOf(b.v);
      }));
      REQUIRE(tw.indices().size() == idx.size());
      for (size_t k = 0; k < idx.size(); k += 3) {
        REQUIRE(tw.indices()[k] == idx[k]);
        REQUIRE(tw.indices()[k + 1] == idx[k + 2]);
        REQUIRE(tw.indices()[k + 2] == idx[k + 1]);
      }
    }
  return true;
}

} // namespace testing
} // namespace fftess
