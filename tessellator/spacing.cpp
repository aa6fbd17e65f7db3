#include "spacing.h"

#include <cstring>

#include "tessellator.h"

namespace fftess {
namespace {

// Clears the highest set bit among bits 30..0.
int withoutHighestBit(int v) {
  const unsigned low = unsigned(v) & 0x7fffffffu;
  return low ? int(unsigned(v) & ~(1u << (31 - __builtin_clz(low)))) : 0;
}

// Number of points on an axis of this factor and parity, both ends included.
int pointsForFactor(fx::Fixed f, bool odd) {
  const fx::Fixed half = (f + 1) / 2; // rounded half factor
  if (odd) return int((fx::fixedCeil(fx::kHalf + half) * 2) >> fx::kFractionBits);
  return int((fx::fixedCeil(half) * 2) >> fx::kFractionBits) + 1;
}

} // namespace

AxisSpacing makeAxisSpacing(fx::Fixed f, bool odd) {
  AxisSpacing s;
  s.odd = odd;
  s.numPoints = pointsForFactor(f, odd);
  // Half the factor, rounded; odd parity (and a factor of 1 placed as even) shift it by one half so that the
  // odd count of segments splits around a middle segment.
  fx::Fixed half = (f + 1) / 2;
  if (odd || half == fx::kHalf) half += fx::kHalf;
  s.halfFactor = half;
  s.floorHalf = fx::fixedFloor(half);
  s.ceilHalf = fx::fixedCeil(half);
  s.halfFraction = half - s.floorHalf;
  s.numHalfPoints = int(s.ceilHalf >> fx::kFractionBits);
  // Ruler-function split order: the point that is still "being born" on the floor placement.
  const int floorInt = int(s.floorHalf >> fx::kFractionBits);
  if (s.ceilHalf == s.floorHalf)
    s.splitPoint = s.numHalfPoints + 1; // no fraction: never split
  else if (odd)
    s.splitPoint = (s.floorHalf == fx::kOne) ? 0 : (withoutHighestBit(floorInt - 1) << 1) + 1;
  else
    s.splitPoint = (withoutHighestBit(floorInt) << 1) + 1;
  s.floorSegments = int((s.floorHalf * 2) >> fx::kFractionBits) - (odd ? 1 : 0);
  s.ceilSegments = int((s.ceilHalf * 2) >> fx::kFractionBits) - (odd ? 1 : 0);
  s.invFloorSegments = fx::kReciprocals.entry[s.floorSegments];
  s.invCeilSegments = fx::kReciprocals.entry[s.ceilSegments];
  return s;
}

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

// Same arithmetic as placePoint for all points at once, 4 lanes at a time (GCC vector extensions, SSE2):
// p is the index on the half axis (mirrored for the second half), the location is blended from the floor and ceil
// placements, the second half is 1 - location, and the even middle is exactly 0.5. Writes up to the
// next multiple of 4.
void fillAxisTable(const AxisSpacing& s, AxisTable& t) {
  using v4i = int32_t __attribute__((vector_size(16)));
  using v4u = uint32_t __attribute__((vector_size(16)));
  using v4f = float __attribute__((vector_size(16)));
  const int n = s.numPoints, half = s.numHalfPoints, odd = s.odd ? 1 : 0;
  t.count = n;
  const uint32_t wFloor = fx::kOne - s.halfFraction, wCeil = s.halfFraction;
  const v4i lane = {0, 1, 2, 3};
  for (int k0 = 0; k0 < n; k0 += 4) {
    const v4i k = k0 + lane;
    const v4i mirrored = k >= half;                   // lanes: -1 or 0
    const v4i p = mirrored ? 2 * half - k - odd : k;
    const v4u onCeil = (v4u)p;
    const v4u onFloor = onCeil + (v4u)(p > s.splitPoint); // -1 where the floor placement lags
    const v4u blend = onFloor * s.invFloorSegments * wFloor + onCeil * s.invCeilSegments * wCeil;
    const v4u onHalf = (blend + fx::kHalf) >> fx::kFractionBits;
    v4u x = mirrored ? fx::kOne - onHalf : onHalf;
    x = p == half ? v4u{} + fx::kHalf : x;
    std::memcpy(t.fixed + k0, &x, sizeof x);
    // fx::fixedToFloat: integer part plus fraction * 2^-16 (exact), one float add.
    const v4f param = __builtin_convertvector((v4i)(x >> fx::kFractionBits), v4f) +
                      __builtin_convertvector((v4i)(x & fx::kFractionMask), v4f) * (1.0f / float(fx::kOne));
    std::memcpy(t.param + k0, &param, sizeof param);
  }
}

} // namespace fftess
