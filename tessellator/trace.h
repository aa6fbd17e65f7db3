// fftess trace: every fixed-point step that places the points of one outer edge (for `fftess explain`, the edge
// analysis in edge_analysis.h and anyone who wants to see the 16.16 arithmetic of D3D11.3 spec 11.7.6).
//
// A trace is a fixed-size value (no allocation). Its points are bitwise the points of edgePoints() for the same
// arguments, and so the points the full tessellation gives that edge.
#pragma once

#include <cstdint>

#include "tessellator/tessellator.h"

namespace fftess {

// One point of a traced edge: how the reference arrives at its 16.16 parameter.
struct EdgePointTrace {
  int index = 0;                 // point index along the edge (0 .. count-1), in increasing parameter order
  bool mirrored = false;         // second half: placed as 1 - (mirror point's location)
  bool midpoint = false;         // the special-cased exact 0.5
  int halfIndex = 0;             // index on the half edge after mirroring
  int indexOnFloor = 0;          // index on the floor(half factor) placement
  int indexOnCeil = 0;           // index on the ceil(half factor) placement
  uint32_t locationOnFloor = 0;  // indexOnFloor * reciprocal(floor segments), 16.16
  uint32_t locationOnCeil = 0;   // indexOnCeil * reciprocal(ceil segments), 16.16
  uint32_t lerp = 0;             // floor*(1-fraction) + ceil*fraction in 32-bit unsigned arithmetic (x.32), before rounding
  uint32_t halfLocation = 0;     // (lerp + 0x8000) >> 16: location on the half edge, 16.16
  uint32_t fixed = 0;            // final 16.16 parameter
  float param = 0;               // final float parameter
};

// One outer edge, from the factor as given to the last point.
struct EdgeTrace {
  float input = 0;                 // factor as given
  bool culled = false;
  bool flushedDenormal = false;    // options.flushDenormals changed the input
  float hlslFactor = 0;            // after the HLSL stage (equals input for hw)
  float clamped = 0;               // after the hardware clamp to the partitioning's range
  float rounded = 0;               // after ceil (integer/pow2), = clamped otherwise
  bool oddParity = false;
  uint32_t fixedFactor = 0;        // rounded in 16.16 (round to nearest even on the 16th fraction bit)
  uint32_t halfFactor = 0;         // (fixedFactor + 1) / 2, + 0.5 for odd parity or a factor of 1
  uint32_t floorHalf = 0;          // floor(halfFactor), 16.16
  uint32_t ceilHalf = 0;           // ceil(halfFactor), 16.16
  uint32_t halfFraction = 0;       // halfFactor - floorHalf, 16.16
  int numHalfPoints = 0;           // points on a half edge (ceilHalf as an integer)
  int splitPoint = 0;              // first half-edge index past which the floor placement lags one point behind
  int floorSegments = 0;           // segments of the floor placement (reciprocal table index)
  int ceilSegments = 0;
  uint32_t reciprocalFloor = 0;    // table entry round(65536 / floorSegments)
  uint32_t reciprocalCeil = 0;
  int count = 0;                   // points on the edge, both ends included (0 when culled)
  EdgePointTrace points[kMaxEdgePoints];
};

// Traces one outer edge: the factor through the stages (options, HLSL preconditioning, clamp, rounding, parity,
// 16.16), the half-edge spacing (floor/ceil placements, reciprocal table entries, fraction) and, for each point,
// the placement, lerp, rounding and mirroring that give its parameter. A culled edge (factor not > 0) returns
// culled = true and no points.
// factor: any float (NaN, +-Inf, denormals, negatives: all defined, as in edgePoints).
// partitioning: any.
// stage: hw or an hlsl stage (reduction and axes do not matter for an outer edge).
// options: as for Tessellator::tessellate (flushDenormals is reported in flushedDenormal).
EdgeTrace traceEdge(float factor, Partitioning partitioning, const Stage& stage = {}, const Options& options = {});

} // namespace fftess
