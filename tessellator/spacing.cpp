#include "spacing.h"

#include "tessellator.h"

namespace fftess {
namespace {

// Clears the highest set bit (values 0..64 here).
int withoutHighestBit(int v) {
  for (int bit = 1 << 30; bit; bit >>= 1)
    if (v & bit) return v & ~bit;
  return 0;
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

// Same arithmetic as placePoint, for all points in one branch-free pass (the compiler vectorises it): first the
// half axis, then the mirrored half as 1 - location, the exact middle 0.5 where the index lands on it.
void fillAxisTable(const AxisSpacing& s, AxisTable& t) {
  const int n = s.numPoints, half = s.numHalfPoints, odd = s.odd ? 1 : 0;
  t.count = n;
  const uint32_t wFloor = fx::kOne - s.halfFraction, wCeil = s.halfFraction;
  for (int k = 0; k < n; ++k) {
    const bool mirrored = k >= half;
    const int p = mirrored ? 2 * half - k - odd : k;
    const uint32_t onCeil = uint32_t(p);
    const uint32_t onFloor = p > s.splitPoint ? onCeil - 1 : onCeil;
    const uint32_t blend = onFloor * s.invFloorSegments * wFloor + onCeil * s.invCeilSegments * wCeil;
    const fx::Fixed onHalf = (blend + fx::kHalf) >> fx::kFractionBits;
    const fx::Fixed x = mirrored ? fx::kOne - onHalf : onHalf;
    t.fixed[k] = p == half ? fx::kHalf : x;
  }
  for (int k = 0; k < n; ++k) t.param[k] = fx::fixedToFloat(t.fixed[k]);
}

} // namespace fftess
