// fftess edge analysis: an edge of factor B beside two half-length edges of factor S (a 2x patch-size jump), or
// more generally two sides of one shared edge: do their points meet vertex for vertex, and if not, why.
//
// Comparison: both sides are mapped onto the big edge's parameter t: big t = v; first small edge t = v1/2; second
// small edge t = 1/2 + v2/2. All values are 16.16 fixed point, so t is an integer in units of 1/131072 of the big
// edge and the comparison is exact. Each mismatch is attributed to its cause by replaying the point's placement in
// exact rational arithmetic (traceEdge): the reciprocal table entry, the rounding of the lerp back to 16.16, the
// special-cased 0.5 midpoint, mirroring, or segments that do not nest even in exact arithmetic.
//
// Used by `fftess explain`, the power-of-two tests and the crack report's SVG inset. Standard library only.
#pragma once

#include <cstdint>
#include <vector>

#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

namespace fftess {

// An exact rational num/den in lowest terms, den > 0. Values here are 16.16 quantities, so num and den fit easily.
struct Fraction {
  int64_t num = 0;
  int64_t den = 1;
  bool zero() const { return num == 0; }
  double value() const { return double(num) / double(den); }
};
bool operator==(const Fraction& a, const Fraction& b);
inline bool operator!=(const Fraction& a, const Fraction& b) { return !(a == b); }

// Error budget of one traced point against exact arithmetic, in 16.16 units of its own edge, signed as it acts on
// the final value (already negated for mirrored points): fixed = ideal + reciprocalError + lerpError.
struct PointBudget {
  bool midpoint = false;    // the special-cased exact 0.5 (ideal = 32768, no errors)
  bool mirrored = false;    // placed as 65536 - (location of its mirror point)
  Fraction ideal;           // exact-arithmetic position: exact reciprocals 65536/segments, unrounded lerp
  Fraction reciprocalError; // index * (table entry - 65536/segments), blended by the half fraction
  Fraction lerpError;       // rounding of the x.32 lerp back to 16.16
  bool consistent = true;   // ideal + errors reproduces the traced 16.16 value (a self-check of the trace)
};

// The error budget of point `index` of a traced edge.
// trace: from traceEdge, not culled. index: 0 .. trace.count - 1.
PointBudget pointBudget(const EdgeTrace& trace, int index);

// Why two points that should coincide do not (or why a point has no partner).
enum class MismatchCause : uint8_t {
  PointCount,      // one side has a point where the other has none (different point counts)
  Placement,       // exact arithmetic already puts them apart: the two factors' segments do not nest
  SpecialHalf,     // one point is the special-cased exact 0.5, the other is computed
  ReciprocalTable, // a reciprocal table entry round(65536/n) is not exact (mirroring makes it act in opposite ways)
  LerpRounding,    // the fractional lerp was rounded to 16.16
};
// The cause's name in reports: point_count, placement, special_half, reciprocal_table, lerp_rounding.
// c: any value; a value outside the enum gives "?".
const char* toString(MismatchCause c);

// One point of one side, placed on the big edge.
struct HalfEdgePoint {
  int64_t t = 0;      // position along the big edge in 1/131072 of it
  int edge = 0;       // 0 = big edge, 1 = first small edge (t 0 .. 1/2), 2 = second small edge (t 1/2 .. 1)
  int index = 0;      // index along its own edge
  uint32_t fixed = 0; // 16.16 parameter on its own edge
};

// One row of the side-by-side table: a big point and a small point that should coincide (or one of them alone).
struct HalfEdgeRow {
  int big = -1;     // index into HalfEdgeComparison::bigPoints, -1: none
  int small = -1;   // index into HalfEdgeComparison::smallPoints, -1: none
  int64_t gap = 0;  // 1/131072 units: small t - big t when paired, else the distance to the other side's nearest point
  bool match = true;
  // Mismatches only: the causes in the order reports print them, and the two points' budgets (when both exist).
  std::vector<MismatchCause> causes;
  bool attributed = false; // both points exist and their traces reproduce them: budgets and causes below are valid
  PointBudget bigBudget, smallBudget;
};

// The two sides of the comparison, each with its edge query and trace.
struct HalfEdgeSide {
  float factor = 0;
  EdgePoints edge;
  EdgeTrace trace;
};

struct HalfEdgeComparison {
  HalfEdgeSide big, small;
  bool culled = false;  // a factor is not > 0: no edge to compare (match is false, no points)
  bool paired = false;  // same number of points on both sides: rows pair points in order
  std::vector<HalfEdgePoint> bigPoints;   // in increasing t
  std::vector<HalfEdgePoint> smallPoints; // in increasing t: the first small edge, then the second without its t = 1/2
  std::vector<HalfEdgeRow> rows;          // in increasing t
  bool match = false;   // the sides meet vertex for vertex
  int64_t worstGap = 0; // 1/131072 units: Hausdorff distance of the two point sets along the edge
  int64_t worstAt = 0;  // 1/131072 units: t of a point at that distance
  int mismatches = 0;   // rows that do not match
};

// Compares an edge of factor bigFactor with two half-length edges of factor smallFactor, in exact 16.16, and
// attributes every mismatch to its causes.
// bigFactor, smallFactor: any floats (a factor not > 0 gives culled = true).
// partitioning: any. stage: hw or an hlsl stage (the per-edge HLSL preconditioning applies to both factors).
// options: as for Tessellator::tessellate.
HalfEdgeComparison compareHalfEdges(float bigFactor, float smallFactor, Partitioning partitioning,
                                    const Stage& stage = {}, const Options& options = {});

// ---------------------------------------------------------------------------------------------------------------
// Two sides of any shared edge (e.g. a crack report's finding): which points of each side have a partner.

// One side: the factor of its edge and the part [lo, hi] of its own edge parameter that is shared.
struct SharedEdgeSpan {
  float factor = 0;
  float lo = 0; // 0 <= lo < hi <= 1; in a 2x jump the big side shares [0, 0.5] or [0.5, 1]
  float hi = 1;
};

struct SharedEdgeTick {
  double t = 0;         // (param - lo) / (hi - lo): position along the shared part, 0 .. 1
  int index = 0;        // index of the point along its own edge
  bool partner = false; // the other side has a point at the same t
};

struct SharedEdgeTicks {
  bool culled = false;           // a side's factor is not > 0: it has no ticks, the other side's have no partner
  std::vector<SharedEdgeTick> a; // side a's points with lo <= param <= hi, in increasing t
  std::vector<SharedEdgeTick> b;
};

// The points of both sides on the shared part of the edge, each mapped to t in 0..1 along it, and whether the
// other side has a point at the same t (compared exactly as doubles: t is exact when hi - lo is a power of two, as
// in every 2^k size jump). Both sides go through the same partitioning, stage and options.
// a, b: spans with 0 <= lo < hi <= 1 (an empty or reversed span gives no ticks for that side).
SharedEdgeTicks sharedEdgeTicks(const SharedEdgeSpan& a, const SharedEdgeSpan& b, Partitioning partitioning,
                                const Stage& stage = {}, const Options& options = {});

} // namespace fftess
