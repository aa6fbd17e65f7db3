// The seeded random patch generator of the GPU oracle tests: the same seed gives the same patches in
// tests/oracle/vs_emulator_test.cpp (llvmpipe vs fftess) and nvidia/nvidia_compare.cpp (NVIDIA vs fftess), on every platform
// and standard library. Distribution: docs/oracle.md, "What is compared, and why" (against fftess).
//
// The patches of a run with seed S and N random patches: sweepPatches(), then N times randomPatch(rng) from
// Rng{S} (generatePatches does both).
#pragma once

#include "gl_capture.h" // Patch and its enums
#include "base/bits.h"
#include "base/splitmix64.h"

#include <cstdint>
#include <vector>

namespace fftess {
namespace oracle {

// splitmix64 (base/splitmix64.h): the same sequence on every platform and standard library (std distributions
// are not). below(n) and unit() (24-bit float in [0,1)) are the ones this generator has always used.
using Rng = SplitMix64;

// Special factor values, as bits.
constexpr uint32_t kSpecials[] = {
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
inline uint32_t randomFactor(Rng& r, bool outer) {
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

// One random hardware-stage patch: half quads, 30% tris, 20% isolines; every partitioning and topology.
inline Patch randomPatch(Rng& r) {
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

// The systematic sweep: every domain and partitioning with all factors equal to k/8, k = 0..528 (0..66), topologies
// taken in turn (isolines: point and line); 3 * 4 * 529 = 6,348 patches.
inline std::vector<Patch> sweepPatches() {
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
  return sweep;
}

// The sweep (when 'sweep' is set), then 'total' random patches from Rng{seed}.
inline std::vector<Patch> generatePatches(long total, uint64_t seed, bool sweep) {
  std::vector<Patch> out;
  if (sweep) out = sweepPatches();
  Rng rng{seed};
  for (long i = 0; i < total; ++i) out.push_back(randomPatch(rng));
  return out;
}

} // namespace oracle
} // namespace fftess
