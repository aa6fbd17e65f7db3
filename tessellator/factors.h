// Tessellation factor processing: the hardware stage's clamps, rounding and parity, per domain.
// Internal header of fftess_tessellator. (The HLSL stage is public: processHlslFactors in tessellator.h.)
#pragma once

#include "spacing.h"
#include "tessellator.h"

namespace fftess {

struct FactorRange {
  float lower, upper;
};
// D3D11.3 spec 11.7.10 / 11.7.11.2: integer and pow2 [1,64], fractional_even [2,64], fractional_odd [1,63].
FactorRange hardwareRange(Partitioning p);
inline bool isIntegerLike(Partitioning p) { return p == Partitioning::Integer || p == Partitioning::Pow2; }

// One outer edge through the hardware stage: cull test, clamp, ceil (integer/pow2), parity, 16.16.
struct ProcessedEdge {
  bool culled = false;
  float clamped = 0, rounded = 0;
  bool odd = false;
  fx::Fixed fixed = 0;
};
ProcessedEdge processOuterEdge(float factor, Partitioning p);

struct ProcessedQuad {
  bool culled = false;
  bool minimum = false; // all factors 1 (integer/pow2/fractional_odd): 4 points, 2 triangles
  AxisSpacing outer[4];
  AxisSpacing inside[2]; // numPoints already raised to the minimum ring size
};
ProcessedQuad processQuadFactors(const float f[6], Partitioning p);

struct ProcessedTri {
  bool culled = false;
  bool minimum = false;
  AxisSpacing outer[3];
  AxisSpacing inside;
};
ProcessedTri processTriFactors(const float f[4], Partitioning p);

struct ProcessedIsoline {
  bool culled = false;
  AxisSpacing density; // placed as integer partitioning, always
  AxisSpacing detail;
  int numLines = 0;    // the line at v == 1 is not drawn
};
ProcessedIsoline processIsolineFactors(float density, float detail, Partitioning p);

// HLSL stage, per outer edge: clean up to [1, +Inf] (NaN -> 1), pow2/integer round-up, clamp to the HLSL range.
float hlslOuterEdge(float factor, Partitioning p);

// Applies Options: flushes denormal inputs to zero when asked.
inline float applyOptions(float f, const Options& o) { return o.flushDenormals ? fx::flushDenormal(f) : f; }

// One outer edge through both stages, as the edge query and the trace see it: options, then the HLSL stage's
// per-edge preconditioning if asked, then the hardware stage. hlslFactor (may be null) receives the factor the
// hardware stage gets.
inline ProcessedEdge processEdgeThroughStages(float factor, Partitioning p, const Stage& stage, const Options& options,
                                              float* hlslFactor) {
  float f = applyOptions(factor, options);
  if (stage.hlsl && f > 0.0f) f = hlslOuterEdge(f, p);
  if (hlslFactor) *hlslFactor = f;
  return processOuterEdge(f, p);
}

} // namespace fftess
