// traceEdge: the edge query of tessellator.cpp, recording every step (trace.h).
#include "trace.h"

#include "factors.h"

namespace fftess {

EdgeTrace traceEdge(float factor, Partitioning partitioning, const Stage& stage, const Options& options) {
  EdgeTrace t;
  t.input = factor;
  t.flushedDenormal = fx::bitsOf(applyOptions(factor, options)) != fx::bitsOf(factor);
  const ProcessedEdge e = processEdgeThroughStages(factor, partitioning, stage, options, &t.hlslFactor);
  if (e.culled) {
    t.culled = true;
    return t;
  }
  t.clamped = e.clamped;
  t.rounded = e.rounded;
  t.oddParity = e.odd;
  t.fixedFactor = e.fixed;
  const AxisSpacing s = makeAxisSpacing(e.fixed, e.odd);
  t.halfFactor = s.halfFactor;
  t.floorHalf = s.floorHalf;
  t.ceilHalf = s.ceilHalf;
  t.halfFraction = s.halfFraction;
  t.numHalfPoints = s.numHalfPoints;
  t.splitPoint = s.splitPoint;
  t.floorSegments = s.floorSegments;
  t.ceilSegments = s.ceilSegments;
  t.reciprocalFloor = s.invFloorSegments;
  t.reciprocalCeil = s.invCeilSegments;
  t.count = s.numPoints;
  for (int k = 0; k < s.numPoints; ++k) {
    placePoint(s, k, &t.points[k]);
    t.points[k].param = fx::fixedToFloat(t.points[k].fixed);
  }
  return t;
}

} // namespace fftess
