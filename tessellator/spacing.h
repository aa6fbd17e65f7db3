// Placement of points along one tessellated axis (an outer edge, or an inside axis) in 16.16 fixed point.
// Internal header of fftess_tessellator.
//
// D3D11.3 spec 11.7.6: "the tessellated points along an edge are placed symmetrically about the midpoint" and
// fractional factors "grow new points from the middle". The reference realises this with two placements of half
// the edge (on floor and ceil of half the factor) blended by the fraction of half the factor, a fixed split order
// (which point of the floor placement lags behind), mirroring for the second half and an exact 0.5 at the middle.
#pragma once

#include "fixed.h"

namespace fftess {

struct EdgePointTrace;

// Everything about one factor that point placement needs; computed once per factor.
struct AxisSpacing {
  bool odd = false;              // parity the axis is placed with
  fx::Fixed invFloorSegments = 0; // reciprocal of the segment count at floor(half factor)
  fx::Fixed invCeilSegments = 0;  // reciprocal of the segment count at ceil(half factor)
  fx::Fixed halfFraction = 0;     // fraction of half the factor (blend weight of the ceil placement)
  int numHalfPoints = 0;          // points on half the axis (even parity: the midpoint is not counted)
  int splitPoint = 0;             // half-axis indices above this lag one point behind on the floor placement
  int numPoints = 0;              // points on the whole axis, both ends included
  // Kept for traces:
  fx::Fixed halfFactor = 0, floorHalf = 0, ceilHalf = 0;
  int floorSegments = 0, ceilSegments = 0;
};

// fixedFactor: the processed factor in 16.16 (1..64). odd: the parity to place with.
AxisSpacing makeAxisSpacing(fx::Fixed fixedFactor, bool odd);

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
