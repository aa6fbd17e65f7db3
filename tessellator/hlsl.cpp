// The HLSL compiler's tess-factor preconditioning (ProcessQuadTessFactors*, ProcessTriTessFactors*,
// ProcessIsolineTessFactors), as Microsoft's reference (CHLSLTessellator) defines it. Float operations are single
// precision, in the order written here (sums left to right, then one division).
#include "factors.h"

#include <cmath>

namespace fftess {
namespace {

using fx::d3dMax;
using fx::d3dMin;

constexpr float kThree = 3.0f;

// Clean-up of an edge factor: NaN and anything below 1 (including -0 and denormals) become 1; +Inf stays.
float cleanup(float x) { return (fx::isNan(x) || x < 1.0f) ? 1.0f : x; }

// Inside scale: NaN and negatives become 0, above 1 becomes 1; -0 and denormals pass through.
float cleanupScale(float x) {
  if (fx::isNan(x) || x < 0.0f) return 0.0f;
  return x > 1.0f ? 1.0f : x;
}

struct HlslMode {
  Partitioning partitioning;
  bool pow2() const { return partitioning == Partitioning::Pow2; }
  bool integer() const { return partitioning == Partitioning::Integer; }
  bool odd() const { return partitioning == Partitioning::FractionalOdd; }

  // HLSL ranges: pow2 [1,64], integer [1,64], fractional_odd [1,63], fractional_even [2,64].
  float clamp(float x) const {
    float lo = fx::kMinOddFactor, hi = fx::kMaxEvenFactor;
    if (partitioning == Partitioning::FractionalOdd) hi = fx::kMaxOddFactor;
    if (partitioning == Partitioning::FractionalEven) lo = fx::kMinEvenFactor;
    return d3dMin(hi, d3dMax(x, lo));
  }
  // pow2: next power of two by clearing the mantissa and bumping the exponent (x >= 1 assumed);
  // integer: ceil; fractional: unchanged.
  float roundUp(float x) const {
    if (pow2()) {
      const uint32_t b = fx::bitsOf(x);
      if (b & fx::kMantissaMask) return fx::floatOf((b & fx::kExponentMask) + fx::kExponentLsb);
      return x;
    }
    if (integer()) return std::ceil(x);
    return x;
  }
  // Parity of an inside factor after rounding: integer-like factors by value (1 counts as even),
  // fractional ones by the partitioning.
  bool insideOdd(float x) const {
    if (pow2() || integer()) return !((int(x) & 1) == 0 || x == 1.0f);
    return odd();
  }
};

} // namespace

float hlslOuterEdge(float factor, Partitioning p) {
  const HlslMode m{p};
  return m.clamp(m.roundUp(cleanup(factor)));
}

static void quadHlsl(const HlslMode& m, const Stage& stage, const float in[6], HlslFactors& out) {
  if (!(in[Ueq0] > 0) || !(in[Veq0] > 0) || !(in[Ueq1] > 0) || !(in[Veq1] > 0)) {
    for (int i = 0; i < 4; ++i) out.unrounded[i] = in[i];
    return; // rounded stays all zero: the hardware stage culls
  }
  const float u0 = cleanup(in[Ueq0]), v0 = cleanup(in[Veq0]), u1 = cleanup(in[Ueq1]), v1 = cleanup(in[Veq1]);
  out.unrounded[Ueq0] = u0;
  out.unrounded[Veq0] = v0;
  out.unrounded[Ueq1] = u1;
  out.unrounded[Veq1] = v1;
  const float edge[4] = {u0, v0, u1, v1};
  for (int i = 0; i < 4; ++i) out.rounded[i] = m.clamp(m.roundUp(edge[i]));

  float inside[2] = {0, 0};
  bool odd[2] = {false, false};
  if (stage.axes == ReductionAxes::OneAxis) {
    // One inside factor from all four edges.
    switch (stage.reduction) {
    case Reduction::Min: inside[0] = d3dMin(d3dMin(v0, v1), d3dMin(u0, u1)); break;
    case Reduction::Max: inside[0] = d3dMax(d3dMax(v0, v1), d3dMax(u0, u1)); break;
    case Reduction::Average: inside[0] = (v0 + v1 + u0 + u1) / 4.0f; break;
    }
    inside[0] = inside[0] * cleanupScale(in[InsideU]);
    inside[0] = m.clamp(inside[0]);
    out.unrounded[InsideU] = out.unrounded[InsideV] = inside[0];
    inside[0] = m.roundUp(inside[0]);
    odd[0] = m.insideOdd(inside[0]);
    // "Picture frame" rule: an odd inside factor below 3 comes in by max or average, ignoring the scale.
    if (odd[0] && inside[0] < kThree) {
      if (stage.reduction == Reduction::Max)
        inside[0] = d3dMin(kThree, d3dMax(d3dMax(v0, v1), d3dMax(u0, u1)));
      else
        inside[0] = d3dMin(kThree, (v0 + v1 + u0 + u1) / 4.0f);
      inside[0] = m.clamp(inside[0]);
      out.unrounded[InsideU] = out.unrounded[InsideV] = inside[0];
      if (m.integer()) inside[0] = m.roundUp(inside[0]);
    }
    inside[1] = inside[0];
  } else {
    // insideU from the two edges along U (Veq0, Veq1), insideV from Ueq0, Ueq1.
    switch (stage.reduction) {
    case Reduction::Min:
      inside[0] = d3dMin(v0, v1);
      inside[1] = d3dMin(u0, u1);
      break;
    case Reduction::Max:
      inside[0] = d3dMax(v0, v1);
      inside[1] = d3dMax(u0, u1);
      break;
    case Reduction::Average:
      inside[0] = (v0 + v1) / 2.0f;
      inside[1] = (u0 + u1) / 2.0f;
      break;
    }
    inside[0] = inside[0] * cleanupScale(in[InsideU]);
    inside[1] = inside[1] * cleanupScale(in[InsideV]);
    for (int a = 0; a < 2; ++a) {
      inside[a] = m.clamp(inside[a]);
      out.unrounded[InsideU + a] = inside[a];
      inside[a] = m.roundUp(inside[a]);
      odd[a] = m.insideOdd(inside[a]);
    }
    const float pairA[2] = {v0, u0}, pairB[2] = {v1, u1};
    for (int a = 0; a < 2; ++a) {
      if (odd[a] && inside[a] < kThree) {
        if (stage.reduction == Reduction::Max)
          inside[a] = d3dMin(kThree, d3dMax(pairA[a], pairB[a]));
        else
          inside[a] = d3dMin(kThree, (pairA[a] + pairB[a]) / 2.0f);
        inside[a] = m.clamp(inside[a]);
        out.unrounded[InsideU + a] = inside[a];
        if (m.integer()) {
          inside[a] = m.roundUp(inside[a]);
          odd[a] = (int(inside[a]) & 1) != 0;
        }
      }
    }
    // The first ring interpolates in as much on all sides as the side with the smaller factor: an odd axis below 3
    // that is smaller than the other axis takes the other's value (at most 3). Axis U first, then V (sees new U).
    for (int a = 0; a < 2; ++a) {
      const int b = 1 - a;
      if (odd[a] && inside[a] < kThree && inside[a] < inside[b]) {
        inside[a] = d3dMin(inside[b], kThree);
        out.unrounded[InsideU + a] = inside[a];
      }
    }
  }
  out.rounded[InsideU] = inside[0];
  out.rounded[InsideV] = inside[1];
}

static void triHlsl(const HlslMode& m, const Stage& stage, const float in[6], HlslFactors& out) {
  if (!(in[TriUeq0] > 0) || !(in[TriVeq0] > 0) || !(in[TriWeq0] > 0)) {
    for (int i = 0; i < 3; ++i) out.unrounded[i] = in[i];
    return;
  }
  const float u = cleanup(in[TriUeq0]), v = cleanup(in[TriVeq0]), w = cleanup(in[TriWeq0]);
  out.unrounded[TriUeq0] = u;
  out.unrounded[TriVeq0] = v;
  out.unrounded[TriWeq0] = w;
  const float edge[3] = {u, v, w};
  for (int i = 0; i < 3; ++i) out.rounded[i] = m.clamp(m.roundUp(edge[i]));

  float inside = 0;
  switch (stage.reduction) {
  case Reduction::Min: inside = d3dMin(d3dMin(u, v), w); break;
  case Reduction::Max: inside = d3dMax(d3dMax(u, v), w); break;
  case Reduction::Average: inside = (u + v + w) / 3.0f; break;
  }
  inside = inside * d3dMin(1.0f, cleanupScale(in[TriInside]));
  inside = m.clamp(inside);
  out.unrounded[TriInside] = inside;
  inside = m.roundUp(inside);
  const bool odd = m.insideOdd(inside);
  if (odd && inside < kThree) {
    if (stage.reduction == Reduction::Max)
      inside = d3dMin(kThree, d3dMax(u, d3dMax(v, w)));
    else
      inside = d3dMin(kThree, (u + v + w) / 3.0f);
    inside = m.clamp(inside);
    out.unrounded[TriInside] = inside;
    if (m.integer()) inside = m.roundUp(inside);
  }
  out.rounded[TriInside] = inside;
}

static void isolineHlsl(const HlslMode& m, const float in[6], HlslFactors& out) {
  float density = in[IsolineDensity], detail = in[IsolineDetail];
  if (!(density > 0) || !(detail > 0)) {
    out.unrounded[IsolineDensity] = density;
    out.unrounded[IsolineDetail] = detail;
    return;
  }
  density = cleanup(density);
  detail = m.clamp(cleanup(detail));
  out.unrounded[IsolineDetail] = detail;
  detail = m.roundUp(detail);
  // Line density is always integer.
  const HlslMode integer{Partitioning::Integer};
  density = integer.clamp(density);
  out.unrounded[IsolineDensity] = density;
  out.rounded[IsolineDensity] = integer.roundUp(density);
  out.rounded[IsolineDetail] = detail;
}

HlslFactors processHlslFactors(Domain domain, Partitioning partitioning, const Stage& stage, const float factors[6],
                               const Options& options) {
  float in[6];
  for (int i = 0; i < 6; ++i) in[i] = applyOptions(factors[i], options);
  HlslFactors out;
  const HlslMode m{partitioning};
  switch (domain) {
  case Domain::Quad: quadHlsl(m, stage, in, out); break;
  case Domain::Tri: triHlsl(m, stage, in, out); break;
  case Domain::Isoline: isolineHlsl(m, in, out); break;
  }
  return out;
}

} // namespace fftess
