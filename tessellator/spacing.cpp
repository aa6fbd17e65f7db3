#include "spacing.h"

#include <cstring>

#include "tessellator.h"

namespace fftess {

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
void fillAxisTable(const AxisSpacing& s, AxisTable& t) {
  const int n = s.numPoints, half = s.numHalfPoints, odd = s.odd ? 1 : 0;
  t.count = n;
  const uint32_t wFloor = fx::kOne - s.halfFraction, wCeil = s.halfFraction;
  const uint32_t fFloor = s.invFloorSegments * wFloor, fCeil = s.invCeilSegments * wCeil; // (mod 2^32, as placePoint)
  auto onHalf = [&](int p) {
    const uint32_t onCeil = uint32_t(p);
    const uint32_t onFloor = p > s.splitPoint ? onCeil - 1 : onCeil;
    return (onFloor * fFloor + onCeil * fCeil + fx::kHalf) >> fx::kFractionBits;
  };
  // fx::fixedToFloat as one conversion: integer part + fraction/65536 in one float add is x/65536 rounded to
  // nearest even, and so is float(x) (rounded to nearest even) times the exact power of two 2^-16.
  auto put = [&t](int k, fx::Fixed x) {
    t.fixed[k] = x;
    t.param[k] = float(x) * (1.0f / float(fx::kOne));
  };
  const int firstHalf = half < n ? half : n;
  for (int k = 0; k < firstHalf; ++k) put(k, onHalf(k));
  for (int k = firstHalf; k < n; ++k) {
    const int p = 2 * half - k - odd;
    put(k, fx::kOne - (p >= 0 && p < firstHalf ? t.fixed[p] : onHalf(p)));
  }
  if (!odd && half < n) put(half, fx::kHalf);
}

} // namespace fftess
