// Precision constants and the exact float / 16.16 fixed-point conversions of the D3D11 tessellator.
// Internal header of fftess_tessellator: every number that decides a bit of output lives here.
#pragma once

#include <cstdint>
#include <cstring>

#include "base/bits.h"

namespace fftess {
namespace fx {

// ---- Bits <-> float: base/bits.h (through memcpy, never pointer casts). ----
using ::fftess::bitsOf;
using ::fftess::floatOf;

constexpr uint32_t kSignBit = 0x80000000u;
constexpr uint32_t kExponentMask = 0x7f800000u;
constexpr uint32_t kMantissaMask = 0x007fffffu;
constexpr uint32_t kExponentLsb = 0x00800000u; // one step of the exponent field
constexpr uint32_t kMinNormal = 0x00800000u;

inline bool isNan(float f) {
  const uint32_t b = bitsOf(f);
  return (b & kExponentMask) == kExponentMask && (b & kMantissaMask) != 0;
}

// D3D float rules used by the tessellator's clamps: denormals compare as signed zero.
inline float flushDenormal(float f) {
  const uint32_t b = bitsOf(f);
  return (b & ~kSignBit) < kMinNormal ? floatOf(b & kSignBit) : f;
}

// IEEE 754R-style max as the D3D reference evaluates it: the comparison is made on flushed values, the returned value
// is the unflushed operand; a NaN second operand yields the first; for two zeros the sign of the second decides.
// A NaN first operand makes the comparison false and so yields the second operand.
inline float d3dMax(float a, float b) {
  const float fa = flushDenormal(a), fb = flushDenormal(b);
  if (isNan(fb)) return a;
  if (fa == 0.0f && fb == 0.0f) return (bitsOf(fb) & kSignBit) ? a : b;
  return fa >= fb ? a : b;
}
// IEEE 754R-style min, same conventions; for two zeros the sign of the first decides.
inline float d3dMin(float a, float b) {
  const float fa = flushDenormal(a), fb = flushDenormal(b);
  if (isNan(fb)) return a;
  if (fa == 0.0f && fb == 0.0f) return (bitsOf(fa) & kSignBit) ? a : b;
  return fa < fb ? a : b;
}

// ---- Tessellation factor ranges (D3D11.3 spec 11.7.10 / 11.7.11.2). ----
constexpr float kMinOddFactor = 1.0f;
constexpr float kMaxOddFactor = 63.0f;
constexpr float kMinEvenFactor = 2.0f;
constexpr float kMaxEvenFactor = 64.0f;
constexpr float kMinIsolineDensity = 1.0f;
constexpr float kMaxIsolineDensity = 64.0f;
constexpr int kMaxFactor = 64;
// Smallest positive 16.16 fraction. fractional_odd forces the inside factors above 1 by this much ("picture frame")
// as soon as any factor would still be above 1 after the 16.16 conversion, i.e. is above 1 + half of it.
constexpr float kFixedEpsilon = 1.0f / 65536.0f;
constexpr float kOddPictureFrameThreshold = kMinOddFactor + kFixedEpsilon / 2; // 1 + 2^-17
constexpr float kOddPictureFrameMinimum = kMinOddFactor + kFixedEpsilon;       // 1 + 2^-16

// ---- 16.16 fixed point (unsigned, 15 integer bits): the tessellator's domain arithmetic. ----
// All arithmetic on these values is unsigned 32-bit and wraps exactly like the reference's.
using Fixed = uint32_t;
constexpr int kFractionBits = 16;
constexpr Fixed kOne = 1u << kFractionBits;
constexpr Fixed kHalf = 0x8000u;
constexpr Fixed kOneThird = 0x5555u;  // tri centre
constexpr Fixed kTwoThirds = 0xaaaau; // tri interior rings: perpendicular scale
constexpr Fixed kFractionMask = 0x0000ffffu;
constexpr Fixed kIntegerMask = 0x7fff0000u;
constexpr Fixed kFixedMax = 0xffffffffu; // conversion of values >= 2^15

inline Fixed fixedFloor(Fixed x) { return x & kIntegerMask; }
inline Fixed fixedCeil(Fixed x) { return (x & kFractionMask) ? (x & kIntegerMask) + kOne : x; }

// float -> unsigned 15.16, as the reference converts tessellation factors:
// NaN and every negative value (including -0) -> 0; >= 2^15 (and +Inf) -> 0xffffffff; |x| < 2^-17 -> 0;
// otherwise the mantissa is shifted into place with round-to-nearest-even on the last kept bit.
inline Fixed floatToFixed(float f) {
  const uint32_t b = bitsOf(f);
  if (isNan(f) || (b & kSignBit)) return 0;
  if (b >= 0x47000000u) return kFixedMax; // 32768.0f
  const int exponent = int((b & kExponentMask) >> 23) - 127;
  if (exponent < -(kFractionBits + 1)) return 0;
  uint32_t m = (b & kMantissaMask) | 0x00800000u;
  const int drop = 23 - kFractionBits - exponent; // mantissa bits below the 2^-16 place
  if (drop <= 0) return m << -drop;
  const uint32_t keep = 1u << drop, rest = m & (keep - 1), half = keep >> 1;
  if ((m & keep) || rest > half) m += half; // ties go to the even neighbour
  return m >> drop;
}

// 16.16 -> float: integer part plus fraction/65536, both exact in float, then one float add (exact for
// values <= 2^8). Reference behaviour; no -0 can come out.
inline float fixedToFloat(Fixed x) {
  return float(x >> kFractionBits) + float(x & kFractionMask) / float(kOne);
}

// Reciprocal table: entry n is 65536/n rounded to nearest (no ties can occur: 65536/n is x.5 only for n a power of
// two, where it is an integer). Entry 0 is unused and holds 0xffffffff, as the reference's table does.
constexpr Fixed reciprocal(int n) {
  return n == 0 ? kFixedMax : Fixed((65536u + unsigned(n) / 2u) / unsigned(n));
}
static_assert(reciprocal(1) == 0x10000 && reciprocal(3) == 0x5555 && reciprocal(6) == 0x2aab, "table");
static_assert(reciprocal(7) == 9362 && reciprocal(14) == 4681 && reciprocal(63) == 0x410, "table");

struct ReciprocalTable {
  Fixed entry[kMaxFactor + 1];
  constexpr ReciprocalTable() : entry{} {
    for (int n = 0; n <= kMaxFactor; ++n) entry[n] = reciprocal(n);
  }
};
inline constexpr ReciprocalTable kReciprocals{};

} // namespace fx
} // namespace fftess
