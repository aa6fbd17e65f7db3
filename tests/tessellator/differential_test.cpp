// Differential test: the table kernels (issue 11) against the path they replaced (tests/tessellator/legacy), which
// was bit-exact with Microsoft's reference on all golden data. Many seeded random patches of every domain,
// partitioning, topology and stage, with special values (NaN, +-Inf, +-0, denormals, negatives, > 64, one 16.16
// step around integers), through one reused Tessellator (buffers grow and shrink between patches).
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "factor_samples.h"
#include "legacy/legacy.h"
#include "tessellator/simd.h"
#include "tessellator/tessellator.h"

using namespace fftess;

namespace {

std::string describe(const Patch& p, const Options& o) {
  std::string s = std::string(toString(p.domain)) + " " + toString(p.partitioning) + " " + toString(p.primitive) +
                  " " + toString(p.stage);
  for (float f : p.factors) s += " " + testing::hex(f);
  if (o.flushDenormals) s += " (flush denormals)";
  return s;
}

bool sameOutput(const Tessellator& t, int n, const std::vector<DomainPoint>& pts, const std::vector<int32_t>& idx) {
  return n == int(pts.size()) && t.points().size() == pts.size() && t.indices().size() == idx.size() &&
         (pts.empty() || std::memcmp(t.points().data(), pts.data(), pts.size() * sizeof(DomainPoint)) == 0) &&
         (idx.empty() || std::memcmp(t.indices().data(), idx.data(), idx.size() * sizeof(int32_t)) == 0);
}

void runDraws(uint32_t seed, int count, bool uniformFactors) {
  testing::FactorDraw draw(seed);
  testing::FactorDraw uniform(seed ^ 0x9e3779b9u);
  Tessellator t;
  std::vector<DomainPoint> pts;
  std::vector<int32_t> idx;
  int mismatches = 0;
  for (int i = 0; i < count; ++i) {
    Patch p = draw.patch();
    if (uniformFactors) // the common case: plain factors 0..66 in steps of 1/8 and arbitrary fractions
      for (float& f : p.factors)
        f = (uniform.rng.next() & 1) ? float(uniform.rng.next() % 529) / 8.0f : float(uniform.rng.next() % 66000000) / 1e6f;
    Options o;
    o.flushDenormals = (draw.rng.next() & 7) == 0;
    const int n = t.tessellate(p, o);
    legacy::tessellate(p, o, pts, idx);
    if (!sameOutput(t, n, pts, idx) && ++mismatches <= 5) FAIL_CHECK("differs from the old path: " << describe(p, o));
  }
  CHECK(mismatches == 0);
}

} // namespace

TEST_CASE("table kernels equal the old path on random patches with special values", "[tessellator][differential]") {
  for (uint32_t seed : {1u, 2u, 3u, 4u}) runDraws(seed, 50000, false);
}

TEST_CASE("table kernels equal the old path on random plain factors", "[tessellator][differential]") {
  for (uint32_t seed : {11u, 12u, 13u, 14u}) runDraws(seed, 50000, true);
}

TEST_CASE("table kernels equal the old path on every equal-factor quad and tri", "[tessellator][differential]") {
  Tessellator t;
  std::vector<DomainPoint> pts;
  std::vector<int32_t> idx;
  int mismatches = 0;
  for (Domain d : {Domain::Quad, Domain::Tri, Domain::Isoline})
    for (int part = 0; part < 4; ++part)
      for (int prim = 0; prim < 4; ++prim)
        for (int k = 0; k <= 66 * 16; ++k) {
          Patch p;
          p.domain = d;
          p.partitioning = Partitioning(part);
          p.primitive = OutputPrimitive(prim);
          if (d == Domain::Isoline && prim > 1) continue;
          for (float& f : p.factors) f = float(k) / 16.0f;
          const int n = t.tessellate(p);
          legacy::tessellate(p, {}, pts, idx);
          if (!sameOutput(t, n, pts, idx) && ++mismatches <= 5) FAIL_CHECK("differs: " << describe(p, {}));
        }
  CHECK(mismatches == 0);
}

TEST_CASE("portable loops equal the old path too (the AVX2 kernels are chosen at run time)", "[tessellator][differential]") {
  fftess::simd::forcePortable(true);
  runDraws(5u, 50000, false);
  runDraws(15u, 50000, true);
  fftess::simd::forcePortable(false);
}
