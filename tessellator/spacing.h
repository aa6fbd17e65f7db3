// Placement of points along one tessellated axis (an outer edge, or an inside axis) in 16.16 fixed point.
// Internal header of fftess_tessellator.
//
// D3D11.3 spec 11.7.13 (in our words): the points along an edge are placed symmetrically about its midpoint, and
// fractional factors grow new points from the middle. The reference realises this with two placements of half
// the edge (on floor and ceil of half the factor) blended by the fraction of half the factor, a fixed split order
// (which point of the floor placement lags behind), mirroring for the second half and an exact 0.5 at the middle.
#pragma once

#include "fixed.h"

namespace fftess {

struct EdgePointTrace;

// Everything about one factor that point placement needs; computed once per factor.
struct AxisSpacing {
  bool odd;              // parity the axis is placed with
  fx::Fixed invFloorSegments; // reciprocal of the segment count at floor(half factor)
  fx::Fixed invCeilSegments;  // reciprocal of the segment count at ceil(half factor)
  fx::Fixed halfFraction;     // fraction of half the factor (blend weight of the ceil placement)
  int numHalfPoints;          // points on half the axis (even parity: the midpoint is not counted)
  int splitPoint;             // half-axis indices above this lag one point behind on the floor placement
  int numPoints;              // points on the whole axis, both ends included
  // Kept for traces:
  fx::Fixed halfFactor, floorHalf, ceilHalf;
  int floorSegments, ceilSegments;
};

// fixedFactor: the processed factor in 16.16 (1..64). odd: the parity to place with. (Inline: six per patch.)
namespace detail {
// Clears the highest set bit among bits 30..0.
inline int withoutHighestBit(int v) {
  const unsigned low = unsigned(v) & 0x7fffffffu;
  return low ? int(unsigned(v) & ~(1u << (31 - __builtin_clz(low)))) : 0;
}

// Number of points on an axis of this factor and parity, both ends included.
inline int pointsForFactor(fx::Fixed f, bool odd) {
  const fx::Fixed half = (f + 1) / 2; // rounded half factor
  if (odd) return int((fx::fixedCeil(fx::kHalf + half) * 2) >> fx::kFractionBits);
  return int((fx::fixedCeil(half) * 2) >> fx::kFractionBits) + 1;
}

} // namespace detail

inline AxisSpacing makeAxisSpacing(fx::Fixed f, bool odd) {
  AxisSpacing s;
  s.odd = odd;
  s.numPoints = detail::pointsForFactor(f, odd);
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
    s.splitPoint = (s.floorHalf == fx::kOne) ? 0 : (detail::withoutHighestBit(floorInt - 1) << 1) + 1;
  else
    s.splitPoint = (detail::withoutHighestBit(floorInt) << 1) + 1;
  s.floorSegments = int((s.floorHalf * 2) >> fx::kFractionBits) - (odd ? 1 : 0);
  s.ceilSegments = int((s.ceilHalf * 2) >> fx::kFractionBits) - (odd ? 1 : 0);
  s.invFloorSegments = fx::kReciprocals.entry[s.floorSegments];
  s.invCeilSegments = fx::kReciprocals.entry[s.ceilSegments];
  return s;
}


// The 16.16 location of point 'index' (0 .. numPoints-1) along the axis. trace may be null.
fx::Fixed placePoint(const AxisSpacing& s, int index, EdgePointTrace* trace = nullptr);

// Every point of one axis at once, in 16.16 and as the output floats: the 1D tables the domain kernels read their
// points from (a quad's interior point is (u table[i], v table[j])). Entry k equals placePoint(s, k) for
// k < s.numPoints (which may exceed the factor's own count: inside axes are raised to the minimum ring size).
constexpr int kMaxAxisPoints = 72; // >= 65, a multiple of 8
struct AxisTable {
  int count = 0;
  fx::Fixed fixed[kMaxAxisPoints];
  float param[kMaxAxisPoints];
};
void fillAxisTable(const AxisSpacing& s, AxisTable& t);

} // namespace fftess
