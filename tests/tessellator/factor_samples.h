// Shared factor sampling for the tessellator tests: a table of special floats plus seeded random draws.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "tessellator/names.h"
#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

namespace fftess {
namespace testing {

inline uint32_t bits(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
inline float fromBits(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}
inline std::string hex(float f) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", bits(f));
  return buf;
}

// Special values: NaN (both signs), +-Inf, +-0, denormals, negatives, 1, one ulp and one 16.16 step around
// integers and even integers, 63.99998, 64, 64.00001, above 64.
inline std::vector<float> specialFactors() {
  std::vector<float> v = {fromBits(0x7fc00000), fromBits(0xffc00000), fromBits(0x7f800001), fromBits(0x7f800000),
                          fromBits(0xff800000), 0.0f, -0.0f, fromBits(0x00000001), fromBits(0x007fffff),
                          fromBits(0x80000001), -1.0f, -64.0f, 0.5f, 1.0f, 63.99998f, 64.0f, 64.00001f, 65.0f,
                          1e30f, fromBits(0x7f7fffff)};
  for (int k : {1, 2, 3, 4, 5, 7, 8, 12, 16, 31, 32, 33, 62, 63, 64}) {
    const float f = float(k);
    v.push_back(f);
    v.push_back(f + 1.0f / 65536.0f);
    v.push_back(f - 1.0f / 65536.0f);
    v.push_back(f + 1.0f / 131072.0f);
    v.push_back(std::nextafter(f, 100.0f));
    v.push_back(std::nextafter(f, 0.0f));
  }
  return v;
}

struct FactorDraw {
  std::mt19937 rng;
  std::vector<float> special = specialFactors();
  explicit FactorDraw(uint32_t seed) : rng(seed) {}

  float factor() {
    const uint32_t kind = rng() % 8;
    if (kind < 2) return special[rng() % special.size()];
    if (kind == 2) return float(1 + rng() % 64);                              // integers
    if (kind == 3) return float(1 + rng() % 64) + float(int(rng() % 5) - 2) / 65536.0f; // 16.16 steps
    return std::uniform_real_distribution<float>(0.0f, 70.0f)(rng);
  }
  float scale() { return rng() % 4 == 0 ? special[rng() % special.size()] : std::uniform_real_distribution<float>(0, 1)(rng); }

  Patch patch() {
    Patch p;
    p.domain = Domain(rng() % 3);
    p.partitioning = Partitioning(rng() % 4);
    p.primitive = OutputPrimitive(rng() % 4);
    static const char* stages[] = {"hw", "hw", "hw", "hlsl-avg", "hlsl-min", "hlsl-max", "hlsl-avg-1axis",
                                   "hlsl-min-1axis", "hlsl-max-1axis"};
    parseStage(stages[rng() % 9], p.stage);
    for (int i = 0; i < 6; ++i) p.factors[i] = factor();
    if (p.stage.hlsl) {
      if (p.domain == Domain::Quad) p.factors[4] = scale(), p.factors[5] = scale();
      if (p.domain == Domain::Tri) p.factors[3] = scale();
    }
    return p;
  }
};

inline std::string describe(const Patch& p) {
  std::string s = std::string(toString(p.domain)) + " " + toString(p.partitioning) + " " + toString(p.primitive) +
                  " " + toString(p.stage);
  for (float f : p.factors) s += " " + hex(f);
  return s;
}

} // namespace testing
} // namespace fftess
