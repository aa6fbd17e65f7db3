// splitmix64: the seeded generator of every test's random data. The same seed gives the same values on every
// platform, compiler and standard library (std::mt19937 is portable, but std::uniform_*_distribution is not).
// Header-only, standard library only; include as "tests/common/splitmix.h" (the repository root is on every test's
// include path).
#pragma once

#include <cstdint>

namespace fftess {
namespace testing {

struct SplitMix64 {
  uint64_t state = 0; // the seed; any value

  // The next 64 random bits (Steele, Lea, Flood: "Fast splittable pseudorandom number generators", 2014).
  uint64_t next() {
    uint64_t z = (state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // 0 .. n-1 (n > 0; the modulo bias is irrelevant for test data).
  uint32_t below(uint64_t n) { return static_cast<uint32_t>(next() % n); }
  // [0, 1) as a float with 24 random bits (every value exact).
  float unit() { return static_cast<float>(next() >> 40) * (1.0f / 16777216.0f); }
  // [0, 1) as a double with 53 random bits.
  double unitDouble() { return static_cast<double>(next() >> 11) * (1.0 / 9007199254740992.0); }
  // lo + (hi - lo) * unit(), in float (lo <= hi; may round up to hi).
  float uniform(float lo, float hi) { return lo + (hi - lo) * unit(); }
};

} // namespace testing
} // namespace fftess
