// Invariants that hold for any input (the Vulkan CTS tessellation invariance rules, plus the output contract),
// checked on seeded random patches drawn with many special values.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "invariants.h"

using namespace fftess;
using namespace fftess::testing;

TEST_CASE("invariants on random patches with special values", "[tessellator][invariants][slow]") {
  FactorDraw draw(20261121u);
  Tessellator t, tw;
  int tessellated = 0, culled = 0;
  for (int n = 0; n < 20000; ++n) {
    const Patch p = draw.patch();
    Options o;
    o.flushDenormals = n % 5 == 0;
    INFO("patch " << n << ": " << describe(p) << (o.flushDenormals ? " (flush denormals)" : ""));
    t.tessellate(p, o);
    if (checkInvariants(p, o, t, tw))
      ++tessellated;
    else
      ++culled;
  }
  CHECK(tessellated > 10000);
  CHECK(culled > 1000);
}

TEST_CASE("edge query: symmetric, increasing, the trace gives the same points", "[tessellator][invariants][edge]") {
  for (Partitioning part :
       {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd, Partitioning::FractionalEven}) {
    for (float f : specialFactors()) {
      for (bool hlsl : {false, true}) {
        Stage st;
        st.hlsl = hlsl;
        const EdgePoints e = edgePoints(f, part, st);
        INFO(toString(part) << " factor " << hex(f) << (hlsl ? " hlsl" : " hw"));
        REQUIRE(e.culled == !(f > 0.0f));
        if (e.culled) continue;
        REQUIRE(e.count >= 2);
        REQUIRE(e.count <= kMaxEdgePoints);
        REQUIRE(e.fixed[0] == 0u);
        REQUIRE(e.fixed[e.count - 1] == 0x10000u);
        for (int k = 0; k < e.count; ++k) {
          // Symmetry: t -> 1 - t maps the point set onto itself, in exact 16.16.
          REQUIRE(e.fixed[k] + e.fixed[e.count - 1 - k] == 0x10000u);
          if (k > 0) REQUIRE(e.fixed[k] >= e.fixed[k - 1]); // duplicates are allowed (reference behaviour)
          REQUIRE(bitsOf(e.param[k]) == bitsOf(float(e.fixed[k]) / 65536.0f));
        }
        // The trace reproduces the same points.
        const EdgeTrace tr = traceEdge(f, part, st);
        REQUIRE(tr.count == e.count);
        for (int k = 0; k < e.count; ++k) REQUIRE(tr.points[k].fixed == e.fixed[k]);
      }
    }
  }
}

// The claim the random invariants rest on, tested head-on: the Ueq0 edge of a full tessellation is the edge query's,
// whatever the other five factors are (small, large, fractional, culling-free extremes).
TEST_CASE("an outer edge depends only on its own factor, not on its neighbours or the inside",
          "[tessellator][invariants][edge]") {
  const float others[] = {1.0f, 2.0f, 3.5f, 7.25f, 33.3f, 64.0f, floatOf(0x00000001), floatOf(0x7f800000)};
  Tessellator t, tw;
  int compared = 0;
  for (Partitioning part :
       {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd, Partitioning::FractionalEven})
    for (Domain d : {Domain::Quad, Domain::Tri})
      for (float f : specialFactors()) {
        if (!(f > 0.0f)) continue; // a culled patch has no edge
        for (float other : others) {
          Patch p;
          p.domain = d;
          p.partitioning = part;
          for (float& x : p.factors) x = other;
          p.factors[Ueq0] = f;
          INFO(describe(p));
          REQUIRE(t.tessellate(p) > 0);
          checkOuterRing(p, t, Options{});
          ++compared;
        }
      }
  CHECK(compared > 1000);
}
