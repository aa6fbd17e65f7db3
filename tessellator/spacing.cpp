#include "spacing.h"

#include <cstring>

#include "simd.h"
#include "tessellator.h"
#include "trace.h"

namespace fftess {

// D3D11.3 11.7.13: points symmetric about the edge midpoint, (1 - U') == U exactly; 11.7.5: ruler-function split.
fx::Fixed placePoint(const AxisSpacing& s, int index, EdgePointTrace* trace) {
  int p = index;
  bool mirrored = false;
  // Second half: mirror onto the first half and place as 1 - location.
  if (p >= s.numHalfPoints) {
    p = 2 * s.numHalfPoints - p - (s.odd ? 1 : 0);
    mirrored = true;
  }
  if (trace) {
    trace->index = index;
    trace->mirrored = mirrored;
    trace->halfIndex = p;
  }
  // The middle is exactly 0.5: 16-bit reciprocal arithmetic cannot produce it.
  if (p == s.numHalfPoints) {
    if (trace) {
      trace->midpoint = true;
      trace->fixed = fx::kHalf;
    }
    return fx::kHalf;
  }
  const uint32_t onCeil = uint32_t(p);
  const uint32_t onFloor = p > s.splitPoint ? onCeil - 1 : onCeil;
  const fx::Fixed locFloor = onFloor * s.invFloorSegments;
  const fx::Fixed locCeil = onCeil * s.invCeilSegments;
  // Blend of the two placements in x.32, rounded back to 16.16 (unsigned 32-bit throughout).
  const uint32_t blend = locFloor * (fx::kOne - s.halfFraction) + locCeil * s.halfFraction;
  const fx::Fixed onHalf = (blend + fx::kHalf) >> fx::kFractionBits;
  const fx::Fixed result = mirrored ? fx::kOne - onHalf : onHalf;
  if (trace) {
    trace->indexOnFloor = int(onFloor);
    trace->indexOnCeil = int(onCeil);
    trace->locationOnFloor = locFloor;
    trace->locationOnCeil = locCeil;
    trace->lerp = blend;
    trace->halfLocation = onHalf;
    trace->fixed = result;
  }
  return result;
}

// Same arithmetic as placePoint for all points at once. The half axis is placed (blend of the floor and ceil
// placements); the second half is 1 - its mirror point, and the even middle exactly 0.5. Inside axes raised above
// their own point count (mirror index below 0) take placePoint's formula for those points.
// Two versions, chosen once at run time: straight loops, and 8 lanes of AVX2 where the CPU has it.
namespace {

// placePoint's blend for half-axis index p, with the two weights pre-multiplied (mod 2^32, as placePoint).
inline fx::Fixed onHalf(int p, int split, uint32_t fFloor, uint32_t fCeil) {
  const uint32_t onCeil = uint32_t(p);
  const uint32_t onFloor = p > split ? onCeil - 1 : onCeil;
  return (onFloor * fFloor + onCeil * fCeil + fx::kHalf) >> fx::kFractionBits;
}

// fx::fixedToFloat as one conversion: integer part + fraction/65536 in one float add is x/65536 rounded to nearest
// even, and so is float(x) (rounded to nearest even) times the exact power of two 2^-16.
inline float toFloat(fx::Fixed x) { return float(x) * (1.0f / float(fx::kOne)); }

void fillPortable(const AxisSpacing& s, AxisTable& t) {
  const int n = s.numPoints, half = s.numHalfPoints, odd = s.odd ? 1 : 0;
  t.count = n;
  const uint32_t fFloor = s.invFloorSegments * (fx::kOne - s.halfFraction), fCeil = s.invCeilSegments * s.halfFraction;
  auto put = [&t](int k, fx::Fixed x) {
    t.fixed[k] = x;
    t.param[k] = toFloat(x);
  };
  const int firstHalf = half < n ? half : n;
  for (int k = 0; k < firstHalf; ++k) put(k, onHalf(k, s.splitPoint, fFloor, fCeil));
  for (int k = firstHalf; k < n; ++k) {
    const int p = 2 * half - k - odd;
    put(k, fx::kOne - (p >= 0 && p < firstHalf ? t.fixed[p] : onHalf(p, s.splitPoint, fFloor, fCeil)));
  }
  if (!odd && half < n) put(half, fx::kHalf);
}

#if defined(__x86_64__)
// 8 points per step; writes up to the next multiple of 8 (kMaxAxisPoints leaves room).
__attribute__((target("avx2"))) void fillAvx2(const AxisSpacing& s, AxisTable& t) {
  using v8i = int32_t __attribute__((vector_size(32)));
  using v8u = uint32_t __attribute__((vector_size(32)));
  using v8f = float __attribute__((vector_size(32)));
  const int n = s.numPoints, half = s.numHalfPoints, odd = s.odd ? 1 : 0;
  t.count = n;
  const uint32_t fFloor = s.invFloorSegments * (fx::kOne - s.halfFraction), fCeil = s.invCeilSegments * s.halfFraction;
  const v8i lane = {0, 1, 2, 3, 4, 5, 6, 7};
  for (int k0 = 0; k0 < n; k0 += 8) {
    const v8i k = k0 + lane;
    const v8i mirrored = k >= half; // lanes: -1 or 0
    const v8i p = mirrored ? 2 * half - k - odd : k;
    const v8u onCeil = (v8u)p;
    const v8u onFloor = onCeil + (v8u)(p > s.splitPoint); // -1 where the floor placement lags
    const v8u location = (onFloor * fFloor + onCeil * fCeil + fx::kHalf) >> fx::kFractionBits;
    v8u x = mirrored ? fx::kOne - location : location;
    x = p == half ? v8u{} + fx::kHalf : x;
    std::memcpy(t.fixed + k0, &x, sizeof x);
    // toFloat: every value here is below 2^31 or wraps as placePoint's; convert the two 16-bit halves exactly.
    const v8f param = __builtin_convertvector((v8i)(x >> 16), v8f) * 65536.0f + __builtin_convertvector((v8i)(x & 0xffffu), v8f);
    const v8f scaled = param * (1.0f / float(fx::kOne));
    std::memcpy(t.param + k0, &scaled, sizeof scaled);
  }
}

const bool kCpuHasAvx2 = [] {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") != 0;
}();
#else
const bool kCpuHasAvx2 = false;
void fillAvx2(const AxisSpacing& s, AxisTable& t) { fillPortable(s, t); }
#endif
bool gAvx2 = kCpuHasAvx2;

} // namespace

namespace simd {
bool useAvx2() { return gAvx2; }
void forcePortable(bool portable) { gAvx2 = !portable && kCpuHasAvx2; }
} // namespace simd

void fillAxisTable(const AxisSpacing& s, AxisTable& t) {
  if (simd::useAvx2())
    fillAvx2(s, t);
  else
    fillPortable(s, t);
}

} // namespace fftess
