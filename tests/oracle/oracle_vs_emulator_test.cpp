// The independent oracle: a sweep of uniform factors 0..66 in steps of 1/8 for every domain and partitioning, then
// seeded random hardware-stage patches (every domain, partitioning and topology; factors
// rich in special values) tessellated by Mesa's llvmpipe (Microsoft's reference inside) and by fftess, compared
// bit for bit: point arrays, primitives as coordinates, index arrays (docs/oracle.md). fftess runs with
// flushDenormals = true, which is what llvmpipe does to denormal factors.
//
//   fftess_oracle_vs_emulator_test [PATCHES [SEED]]
//   environment: FFTESS_ORACLE_PATCHES, FFTESS_ORACLE_SEED override the defaults (30000 patches, seed 20261122).
//
// A failure lists each differing patch as a batch line, to reproduce with
//   echo 'LINE' | fftess_gl_oracle      and      echo 'LINE' | fftess tessellate --batch - --format hex
#include "test_support.h"

#include "tessellator/tessellator.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>

using namespace fftess::oracle;

namespace {

// splitmix64: the same sequence on every platform and standard library (std distributions are not).
struct Rng {
  uint64_t s;
  uint64_t next() {
    uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }
  float unit() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); } // [0,1), 24 bits
};

uint32_t bitsOf(float f) {
  uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
}
float floatOf(uint32_t b) {
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// Special factor values, as bits.
const uint32_t kSpecials[] = {
    0x7fc00000u, // +NaN (quiet)
    0xffc00000u, // -NaN
    0x7f800001u, // signalling NaN
    0x7f800000u, // +Inf
    0xff800000u, // -Inf
    0x00000000u, // +0
    0x80000000u, // -0
    0x00000001u, // smallest denormal
    0x007fffffu, // largest denormal
    0x80000001u, // negative denormal
    0x00800000u, // smallest normal
    0xbf800000u, // -1
    0xc2800000u, // -64
    0x3f800001u, // 1 + 2^-23
    0x42800001u, // 64 + 1 ulp
    0x427ffffeu, // 63.99998
    0x42820000u, // 65
    0x7149f2cau, // 1e30
    0x7f7fffffu, // FLT_MAX
    0x3f000000u, // 0.5
    0x3e800000u, // 0.25
};

// One factor: mostly plausible values, with integers and one 16.16 step (or one ulp) around them, and specials.
uint32_t randomFactor(Rng& r, bool outer) {
  const uint32_t pick = r.below(100);
  if (pick < 40) return bitsOf(r.unit() * 66.0f);                        // anything in [0, 66)
  if (pick < 55) return bitsOf(0.5f + r.unit() * 7.5f);                  // small: [0.5, 8)
  if (pick < 85) {                                                        // integer k, and around it
    const float k = static_cast<float>(1 + r.below(66));
    switch (r.below(8)) {
    case 0: return bitsOf(k);
    case 1: return bitsOf(k + 1.0f / 65536.0f);                           // one 16.16 step above
    case 2: return bitsOf(k - 1.0f / 65536.0f);                           // one 16.16 step below
    case 3: return bitsOf(k + 1.0f / 32768.0f);                           // two steps above (duplicate points)
    case 4: return bitsOf(k) + 1;                                         // one ulp above
    case 5: return bitsOf(k) - 1;                                         // one ulp below
    case 6: return bitsOf(k + 0.5f);
    default: return bitsOf(k + 1.0f / 131072.0f);                         // half a step (rounds to even)
    }
  }
  // Specials: fewer for outer factors, which cull the patch for half of them.
  if (outer && r.below(2)) return bitsOf(1.0f + r.unit() * 63.0f);
  return kSpecials[r.below(sizeof kSpecials / sizeof kSpecials[0])];
}

Patch randomPatch(Rng& r) {
  Patch p;
  const uint32_t d = r.below(10);
  p.domain = d < 5 ? Domain::Quad : d < 8 ? Domain::Tri : Domain::Isoline;
  p.partitioning = static_cast<Partitioning>(r.below(4));
  const uint32_t t = r.below(10);
  if (p.domain == Domain::Isoline) {
    p.topology = t < 7 ? Topology::Line : Topology::Point;
  } else {
    p.topology = t < 4 ? Topology::TriangleCw : t < 7 ? Topology::TriangleCcw : t < 9 ? Topology::Point : Topology::Line;
  }
  const int outer = p.domain == Domain::Quad ? 4 : p.domain == Domain::Tri ? 3 : 2;
  const int used = p.domain == Domain::Quad ? 6 : p.domain == Domain::Tri ? 4 : 2;
  for (int i = 0; i < 6; ++i) p.factorBits[i] = i < used ? randomFactor(r, i < outer) : 0u;
  // Uniform patches (all factors equal) are common in engines: one in eight.
  if (r.below(8) == 0)
    for (int i = 1; i < used; ++i) p.factorBits[i] = p.factorBits[0];
  return p;
}

fftess::Patch toEmulator(const Patch& p) {
  fftess::Patch e;
  e.domain = p.domain == Domain::Quad ? fftess::Domain::Quad
             : p.domain == Domain::Tri ? fftess::Domain::Tri
                                       : fftess::Domain::Isoline;
  switch (p.partitioning) {
  case Partitioning::Integer: e.partitioning = fftess::Partitioning::Integer; break;
  case Partitioning::Pow2: e.partitioning = fftess::Partitioning::Pow2; break;
  case Partitioning::FractionalOdd: e.partitioning = fftess::Partitioning::FractionalOdd; break;
  case Partitioning::FractionalEven: e.partitioning = fftess::Partitioning::FractionalEven; break;
  }
  switch (p.topology) {
  case Topology::Point: e.primitive = fftess::OutputPrimitive::Point; break;
  case Topology::Line: e.primitive = fftess::OutputPrimitive::Line; break;
  case Topology::TriangleCw: e.primitive = fftess::OutputPrimitive::TriangleCw; break;
  case Topology::TriangleCcw: e.primitive = fftess::OutputPrimitive::TriangleCcw; break;
  }
  e.stage = fftess::Stage{}; // hw
  for (int i = 0; i < 6; ++i) e.factors[i] = floatOf(p.factorBits[i]);
  return e;
}

long envOr(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 0) : fallback;
}

} // namespace

int main(int argc, char** argv) {
  const char* name = "oracle_vs_emulator";
  const long total = argc > 1 ? std::strtol(argv[1], nullptr, 0) : envOr("FFTESS_ORACLE_PATCHES", 30000);
  const uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0)
                                 : static_cast<uint64_t>(envOr("FFTESS_ORACLE_SEED", 20261122));
  auto oracle = createOracleOrExit(name);
  std::printf("%s: %ld patches, seed %llu\n", name, total, static_cast<unsigned long long>(seed));

  Rng rng{seed};
  fftess::Tessellator tess;
  fftess::Options options;
  options.flushDenormals = true; // llvmpipe flushes denormal factors to zero
  constexpr long kChunk = 500;   // patches per oracle run (bounds the memory of captured results)
  double glSeconds = 0, emuSeconds = 0;
  long compared = 0, agree = 0, culled = 0, withPrimitives = 0, duplicates = 0, denormal = 0, printed = 0;
  long long points = 0, primitives = 0;
  std::map<std::string, std::pair<long, long>> perMode; // "domain partitioning" -> (patches, failures)
  std::vector<Patch> patches;
  std::vector<Result> results;
  // First a systematic sweep: every domain and partitioning with all factors equal to k/8, k = 0..528 (0..66),
  // topologies taken in turn; then the random patches.
  std::vector<Patch> sweep;
  for (int d = 0; d < 3; ++d)
    for (int part = 0; part < 4; ++part)
      for (int k = 0; k <= 528; ++k) {
        Patch p;
        p.domain = static_cast<Domain>(d);
        p.partitioning = static_cast<Partitioning>(part);
        p.topology = p.domain == Domain::Isoline ? (k % 2 ? Topology::Line : Topology::Point)
                                                 : static_cast<Topology>((k + part) % 4);
        for (uint32_t& f : p.factorBits) f = bitsOf(static_cast<float>(k) / 8.0f);
        sweep.push_back(p);
      }
  const long sweepCount = static_cast<long>(sweep.size());
  for (long done = 0; done < sweepCount + total; done += kChunk) {
    patches.clear();
    for (long i = done; i < sweepCount + total && i < done + kChunk; ++i)
      patches.push_back(i < sweepCount ? sweep[static_cast<size_t>(i)] : randomPatch(rng));
    std::string error;
    const auto t0 = std::chrono::steady_clock::now();
    if (!oracle->run(patches, results, error)) {
      std::fprintf(stderr, "%s: the GL oracle failed: %s\n", name, error.c_str());
      return 1;
    }
    const auto t1 = std::chrono::steady_clock::now();
    glSeconds += std::chrono::duration<double>(t1 - t0).count();
    for (size_t i = 0; i < patches.size(); ++i) {
      const auto e0 = std::chrono::steady_clock::now();
      tess.tessellate(toEmulator(patches[i]), options);
      Expected want;
      want.points.reserve(tess.points().size() * 2);
      for (const fftess::DomainPoint& pt : tess.points()) {
        want.points.push_back(bitsOf(pt.u));
        want.points.push_back(bitsOf(pt.v));
      }
      want.indices = tess.indices();
      emuSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
      const Verdict v = compare(patches[i], results[i], want);
      ++compared;
      points += results[i].pointCount();
      primitives += static_cast<long long>(results[i].primitives.size() / 2 / static_cast<size_t>(results[i].verticesPerPrimitive));
      culled += results[i].pointCount() == 0;
      if (hasGlPrimitives(patches[i]) && results[i].pointCount() > 0) {
        ++withPrimitives;
        duplicates += hasDuplicatePoints(results[i]);
      }
      denormal += hasDenormalFactor(patches[i]);
      auto& mode = perMode[std::string(toString(patches[i].domain)) + " " + toString(patches[i].partitioning)];
      ++mode.first;
      if (v.all()) {
        ++agree;
        continue;
      }
      ++mode.second;
      if (printed++ < 20)
        std::printf("DIFFERS (%s %ld): %s\n  %s\n", done + static_cast<long>(i) < sweepCount ? "sweep" : "random",
                    done + static_cast<long>(i) - (done + static_cast<long>(i) < sweepCount ? 0 : sweepCount),
                    batchLine(patches[i]).c_str(),
                    v.firstDifference.c_str());
    }
  }
  std::printf("%-24s %8s %8s\n", "mode", "patches", "differ");
  for (const auto& kv : perMode) std::printf("%-24s %8ld %8ld\n", kv.first.c_str(), kv.second.first, kv.second.second);
  std::printf("%s: %ld patches compared (%ld sweep + %ld random; %ld culled, %ld with GL primitives of which %ld with duplicate points, %ld "
              "with a denormal factor), %lld points, %lld primitives; %ld agree bit for bit, %ld differ. "
              "llvmpipe %.2f s, fftess %.3f s\n",
              name, compared, sweepCount, total, culled, withPrimitives, duplicates, denormal, points, primitives, agree, compared - agree,
              glSeconds, emuSeconds);
  return agree == compared ? 0 : 1;
}
