// splitmix64 (Steele, Lea, Flood: "Fast splittable pseudorandom number generators", 2014): the one seeded generator of
// fftess. Random cameras, the heightfield's lattice noise, the GPU oracle's random patches, the benchmarks' cases and
// every test's random data come from it, so a seed gives the same values on every platform, compiler and standard
// library (std::mt19937 is portable, std::uniform_*_distribution is not). Header-only, standard library only.
//
// Counter-based: the state after k draws is seed + k * kIncrement (mod 2^64), so draw k of a seed is computed without
// the k - 1 before it (CameraSet computes camera i from (seed, i) this way; docs/verify.md).
#pragma once

#include <cstdint>

namespace fftess {

struct SplitMix64 {
  static constexpr uint64_t kIncrement = 0x9e3779b97f4a7c15ull; // the golden-ratio increment of the state

  uint64_t state = 0; // the seed; any value

  // The finaliser: a well-distributed 64-bit hash of x. next() is mix(state += kIncrement).
  static constexpr uint64_t mix(uint64_t x) {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }
  // The next 64 random bits.
  uint64_t next() { return mix(state += kIncrement); }
  // 0 .. n-1 (n > 0; the modulo bias is irrelevant for test data and camera choice).
  uint32_t below(uint64_t n) { return static_cast<uint32_t>(next() % n); }
  // [0, 1) as a float with 24 random bits (every value exact).
  float unit() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }
  // [0, 1) as a double with 53 random bits.
  double unitDouble() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  // lo + (hi - lo) * unit(), in float (lo <= hi; may round up to hi).
  float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

} // namespace fftess
