// Shared factor sampling for the tessellator tests: a table of special floats plus seeded random draws (splitmix64,
// so the draws are the same with every standard library).
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "base/bits.h"
#include "tessellator/names.h"
#include "tessellator/tessellator.h"
#include "tessellator/trace.h"
#include "base/splitmix64.h"

namespace fftess {
namespace testing {

inline std::string hex(float f) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%08x", bitsOf(f));
  return buf;
}

// Special values: NaN (both signs), +-Inf, +-0, denormals, negatives, 1, one ulp and one 16.16 step around
// integers and even integers, 63.99998, 64, 64.00001, above 64.
inline std::vector<float> specialFactors() {
  std::vector<float> v = {floatOf(0x7fc00000), floatOf(0xffc00000), floatOf(0x7f800001), floatOf(0x7f800000),
                          floatOf(0xff800000), 0.0f, -0.0f, floatOf(0x00000001), floatOf(0x007fffff),
                          floatOf(0x80000001), -1.0f, -64.0f, 0.5f, 1.0f, 63.99998f, 64.0f, 64.00001f, 65.0f,
                          1e30f, floatOf(0x7f7fffff)};
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
  SplitMix64 rng;
  std::vector<float> special = specialFactors();
  explicit FactorDraw(uint64_t seed) : rng{seed} {}

  float factor() {
    const uint32_t kind = rng.below(8);
    if (kind < 2) return special[rng.below(special.size())];
    if (kind == 2) return float(1 + rng.below(64));                                   // integers
    if (kind == 3) return float(1 + rng.below(64)) + float(int(rng.below(5)) - 2) / 65536.0f; // 16.16 steps
    return rng.uniform(0.0f, 70.0f);
  }
  float scale() { return rng.below(4) == 0 ? special[rng.below(special.size())] : rng.unit(); }

  Patch patch() {
    Patch p;
    p.domain = Domain(rng.below(3));
    p.partitioning = Partitioning(rng.below(4));
    p.primitive = OutputPrimitive(rng.below(4));
    // hw in 3 of 9 draws, each of the six hlsl stages in 1 of 9.
    const std::vector<std::string>& stages = stageNames();
    const uint32_t k = rng.below(stages.size() + 2);
    parseStage(stages[k < 3 ? 0 : k - 2].c_str(), p.stage);
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
