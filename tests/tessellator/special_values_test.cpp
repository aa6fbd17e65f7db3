// Surprising inputs of the reference, one table row each; values printed as hex bits on failure.
#include <catch2/catch.hpp>

#include <set>
#include <utility>

#include "factor_samples.h"

using namespace fftess;
using namespace fftess::testing;

namespace {

struct EdgeCase {
  uint32_t input;
  Partitioning partitioning;
  bool culled;
  float processed; // factor the fixed-function unit uses
  int points;      // points on the edge
};

Patch uniformQuad(Partitioning part, float f, OutputPrimitive prim = OutputPrimitive::TriangleCw) {
  Patch p;
  p.domain = Domain::Quad;
  p.partitioning = part;
  p.primitive = prim;
  for (float& x : p.factors) x = f;
  return p;
}

int distinctPoints(const Tessellator& t) {
  std::set<std::pair<uint32_t, uint32_t>> s;
  for (const DomainPoint& q : t.points()) s.insert({bitsOf(q.u), bitsOf(q.v)});
  return int(s.size());
}

int zeroAreaTriangles(const Tessellator& t) {
  int n = 0;
  const auto& p = t.points();
  const auto& i = t.indices();
  for (size_t k = 0; k < i.size(); k += 3) {
    const DomainPoint a = p[size_t(i[k])], b = p[size_t(i[k + 1])], c = p[size_t(i[k + 2])];
    const double cross = (double(b.u) - a.u) * (double(c.v) - a.v) - (double(b.v) - a.v) * (double(c.u) - a.u);
    if (cross == 0.0) ++n;
  }
  return n;
}

} // namespace

TEST_CASE("special edge factors: culling, clamping, rounding", "[tessellator][special]") {
  const Partitioning I = Partitioning::Integer, E = Partitioning::FractionalEven, O = Partitioning::FractionalOdd,
                     P = Partitioning::Pow2;
  const EdgeCase table[] = {
      {0x7fc00000, I, true, 0, 0},   // +NaN culls
      {0xffc00000, E, true, 0, 0},   // -NaN culls
      {0x00000000, I, true, 0, 0},   // +0 culls
      {0x80000000, O, true, 0, 0},   // -0 culls
      {0xbf800000, I, true, 0, 0},   // -1 culls
      {0xff800000, E, true, 0, 0},   // -Inf culls
      {0x7f800000, I, false, 64, 65}, // +Inf clamps to 64
      {0x7f800000, O, false, 63, 64}, // ... and to 63 under fractional_odd
      {0x00000001, I, false, 1, 2},  // a positive denormal is not culled: minimum tessellation
      {0x00000001, E, false, 2, 3},
      {0x42820000, I, false, 64, 65}, // 65 -> 64 (clamp before ceil)
      {0x7149f2ca, E, false, 64, 65}, // 1e30 -> 64
      {0x42800000, O, false, 63, 64}, // fractional_odd turns 64 into 63
      {0x42800001, I, false, 64, 65}, // 64.000008 clamps to 64
      {0x3f800001, I, false, 2, 3},  // integer ceil in float: 1 + 2^-23 -> 2 segments
      {0x3f800001, P, false, 2, 3},  // pow2 in the hardware stage is integer
      {0x40000002, E, false, floatOf(0x40000002), 3}, // fractional: 2 + 2^-22 is 2 in 16.16
      {0x40400000, P, false, 3, 4},  // hardware pow2 does not round to a power of two
  };
  for (const EdgeCase& c : table) {
    const EdgePoints e = edgePoints(floatOf(c.input), c.partitioning);
    INFO("input " << hex(floatOf(c.input)) << " " << toString(c.partitioning));
    CHECK(e.culled == c.culled);
    if (c.culled) continue;
    CHECK(hex(e.processedFactor) == hex(c.processed));
    CHECK(e.count == c.points);
  }
  CHECK(edgePoints(floatOf(0x40000002), E).fixedFactor == 0x20000u);
}

TEST_CASE("denormal outer factors: reference keeps the patch, flushDenormals culls it (llvmpipe)",
          "[tessellator][special]") {
  Tessellator t;
  Patch p = uniformQuad(Partitioning::Integer, 4.0f);
  p.factors[Veq0] = floatOf(0x00000001);
  Options flush;
  flush.flushDenormals = true;
  CHECK(t.tessellate(p) > 0);
  CHECK(t.tessellate(p, flush) == 0);
  CHECK(edgePoints(floatOf(0x00000001), Partitioning::Integer, {}, flush).culled);
}

TEST_CASE("all factors 1", "[tessellator][special]") {
  Tessellator t;
  // integer and fractional_odd: the minimum quad, 4 points and 2 triangles
  for (Partitioning part : {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd}) {
    t.tessellate(uniformQuad(part, 1.0f));
    CHECK(t.points().size() == 4);
    CHECK(t.indices() == std::vector<int32_t>{0, 1, 3, 1, 2, 3});
  }
  // fractional_even clamps to 2: 9 points, 8 triangles
  t.tessellate(uniformQuad(Partitioning::FractionalEven, 1.0f));
  CHECK(t.points().size() == 9);
  CHECK(t.indices().size() == 24);
}

TEST_CASE("duplicates and zero-area triangles are real output", "[tessellator][special]") {
  Tessellator t;
  // fractional_even 2 + 2^-16: 25 points, 16 of them duplicates, 24 zero-area triangles
  t.tessellate(uniformQuad(Partitioning::FractionalEven, 2.0f + 1.0f / 65536.0f));
  CHECK(t.points().size() == 25);
  CHECK(25 - distinctPoints(t) == 16);
  CHECK(zeroAreaTriangles(t) == 24);
  // 8 + 2^-16: 121 points, 40 duplicates
  t.tessellate(uniformQuad(Partitioning::FractionalEven, 8.0f + 1.0f / 65536.0f));
  CHECK(t.points().size() == 121);
  CHECK(121 - distinctPoints(t) == 40);
  // fractional_odd inside factor at the picture-frame limit: the frame sits on the corners
  Patch p = uniformQuad(Partitioning::FractionalOdd, 1.0f);
  p.factors[Ueq0] = 1.0f + 1.0f / 32768.0f;
  t.tessellate(p);
  CHECK(distinctPoints(t) < int(t.points().size()));
}

TEST_CASE("HLSL stage: pow2 rounding by exponent bump, rounded and unrounded factors", "[tessellator][special][hlsl]") {
  Stage max;
  REQUIRE(parseStage("hlsl-max", max));
  const float in[6] = {24.0f, 1.0000153f, 28.0f, 0.383f, 1.0f, 1.0f};
  const HlslFactors h = processHlslFactors(Domain::Quad, Partitioning::Pow2, max, in);
  // Ueq0 24 -> 32, Veq0 1.0000153 -> 2, Ueq1 28 -> 32, Veq1 0.383 -> cleaned to 1 (stays 1)
  CHECK(hex(h.rounded[Ueq0]) == hex(32.0f));
  CHECK(hex(h.rounded[Veq0]) == hex(2.0f));
  CHECK(hex(h.rounded[Ueq1]) == hex(32.0f));
  CHECK(hex(h.rounded[Veq1]) == hex(1.0f));
  CHECK(hex(h.unrounded[Veq0]) == hex(1.0000153f));
  CHECK(hex(h.unrounded[Veq1]) == hex(1.0f));
  // insideU = max(Veq0, Veq1) = 1.0000153 -> 2 (the g++ -O2 strict-aliasing miscompile of the reference gives 3)
  CHECK(hex(h.unrounded[InsideU]) == hex(1.0000153f));
  CHECK(hex(h.rounded[InsideU]) == hex(2.0f));
  CHECK(hex(h.rounded[InsideV]) == hex(32.0f));
  Tessellator t;
  Patch p;
  p.domain = Domain::Quad;
  p.partitioning = Partitioning::Pow2;
  p.stage = max;
  std::copy(in, in + 6, p.factors);
  CHECK(t.tessellate(p) == 98);
  // culled patch: rounded all zero, unrounded = the raw edges
  const float culled[6] = {floatOf(0x7fc00000), 3, 3, 3, 0.5f, 0.5f};
  const HlslFactors hc = processHlslFactors(Domain::Quad, Partitioning::Integer, max, culled);
  for (float f : hc.rounded) CHECK(bitsOf(f) == 0u);
  CHECK(bitsOf(hc.unrounded[Ueq0]) == 0x7fc00000u);
}

TEST_CASE("float <-> 16.16 conversion around integers", "[tessellator][special]") {
  // One 16.16 step above 2 is a new factor; half a step (2 + 2^-17) rounds to even (2); 3/4 of a step rounds up.
  CHECK(edgePoints(2.0f + 1.0f / 65536.0f, Partitioning::FractionalEven).fixedFactor == 0x20001u);
  CHECK(edgePoints(2.0f + 1.0f / 131072.0f, Partitioning::FractionalEven).fixedFactor == 0x20000u);
  CHECK(edgePoints(2.0f + 3.0f / 262144.0f, Partitioning::FractionalEven).fixedFactor == 0x20001u);
  CHECK(edgePoints(3.0f + 3.0f / 131072.0f, Partitioning::FractionalEven).fixedFactor == 0x30002u);
  CHECK(edgePoints(std::nextafter(64.0f, 0.0f), Partitioning::FractionalEven).fixedFactor == 0x400000u);
  CHECK(edgePoints(63.99998f, Partitioning::FractionalEven).fixedFactor == 0x3fffffu);
}

TEST_CASE("edgeCulled is edgePoints' culled for every special and random factor", "[tessellator][special]") {
  std::vector<float> factors = specialFactors();
  SplitMix64 rng{22};
  for (int k = 0; k < 4000; ++k) factors.push_back(floatOf(static_cast<uint32_t>(rng.next())));
  Stage hlsl;
  hlsl.hlsl = true;
  Options flush;
  flush.flushDenormals = true;
  int culled = 0;
  for (const Partitioning p : {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalEven,
                               Partitioning::FractionalOdd})
    for (const Stage& s : {Stage{}, hlsl})
      for (const Options& o : {Options{}, flush})
        for (const float f : factors) {
          INFO("factor " << hex(f) << " " << toString(p) << (s.hlsl ? " hlsl" : " hw")
                         << (o.flushDenormals ? " flush" : ""));
          const bool expected = edgePoints(f, p, s, o).culled;
          CHECK(edgeCulled(f, p, s, o) == expected);
          culled += expected ? 1 : 0;
        }
  CHECK(culled > 0); // the table holds factors that cull (NaN, zeros, negatives) and the random half of the bits
}
