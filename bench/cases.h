// The two patch sets of issue 11, shared by `fftess bench --micro` and any side-by-side driver:
//   (a) 2,000 quad integer triangle_cw hw patches, all six factors 64.0;
//   (b) 20,000 quad fractional_even triangle_cw hw patches, factors uniform in [1,16] from splitmix64.
// Generator of (b), documented so that anyone can rebuild the set: splitmix64 seeded with kCaseBSeed; for each patch
// the six factors in order Ueq0 Veq0 Ueq1 Veq1 insideU insideV; each factor takes one 64-bit draw x and is
// float(1.0 + 15.0 * (x >> 40) / 2^24) (24 random bits, computed exactly in double, rounded once to float).
#pragma once

#include <cstdint>
#include <vector>

#include "base/splitmix64.h" // the generator of (b)
#include "tessellator/tessellator.h"

namespace fftess::bench {

constexpr int kCaseAPatches = 2000;
constexpr int kCaseBPatches = 20000;
constexpr uint64_t kCaseBSeed = 0x11u; // issue 11

inline std::vector<Patch> caseA() {
  Patch p;
  p.domain = Domain::Quad;
  p.partitioning = Partitioning::Integer;
  p.primitive = OutputPrimitive::TriangleCw;
  for (float& f : p.factors) f = 64.0f;
  return std::vector<Patch>(kCaseAPatches, p);
}

inline std::vector<Patch> caseB() {
  std::vector<Patch> patches(kCaseBPatches);
  SplitMix64 rng{kCaseBSeed};
  for (Patch& p : patches) {
    p.domain = Domain::Quad;
    p.partitioning = Partitioning::FractionalEven;
    p.primitive = OutputPrimitive::TriangleCw;
    for (float& f : p.factors) f = float(1.0 + 15.0 * double(rng.next() >> 40) / 16777216.0);
  }
  return patches;
}

} // namespace fftess::bench
