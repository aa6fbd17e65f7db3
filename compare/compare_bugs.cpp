// The typical port bugs of compare.h as changes to one edge's 16.16 placement, and the mapping of a patch's output
// coordinates to the edge (or inside axis) and point that produced them.
#include "compare/compare_internal.h"

#include <cmath>

#include "tessellator/fixed.h"

namespace fftess {
namespace {

float toFloat(uint32_t fixed) { return fx::fixedToFloat(fixed); }

// The reference's blend of the floor and ceil placements for half-edge index h, rounded to 16.16 (no mirroring).
uint32_t placeUnmirrored(const EdgeTrace& t, int h) {
  const uint32_t onCeil = uint32_t(h);
  const uint32_t onFloor = t.halfFraction != 0 && h > t.splitPoint ? onCeil - 1 : onCeil;
  const uint32_t blend =
      onFloor * t.reciprocalFloor * (fx::kOne - t.halfFraction) + onCeil * t.reciprocalCeil * t.halfFraction;
  return (blend + fx::kHalf) >> fx::kFractionBits;
}

const char* const kQuadAxes[6] = {"Ueq0", "Veq0", "Ueq1", "Veq1", "insideU", "insideV"};
const char* const kTriAxes[3] = {"Ueq0", "Veq0", "Weq0"};

// Inside axes and isoline axes as edges: a factor that is not > 0 takes the lower bound (the hardware's clamp), a
// processed integer factor of 1 is placed as even, like 2 (points 0, 0.5, 1).
Axis insideAxis(float f, Partitioning p, const char* name) {
  Axis a;
  a.name = name;
  const float lower = p == Partitioning::FractionalEven ? 2.0f : 1.0f;
  if (!(f > 0.0f)) f = lower;
  a.trace = traceEdge(f, p);
  if ((p == Partitioning::Integer || p == Partitioning::Pow2) && a.trace.fixedFactor == fx::kOne)
    a.trace = traceEdge(2.0f, p);
  a.raw = a.trace.clamped;
  a.valid = !a.trace.culled;
  return a;
}

} // namespace

float buggyEdgeParam(PortBug b, const EdgeTrace& t, int k, float rawFactor) {
  const EdgePointTrace& p = t.points[k];
  switch (b) {
  case PortBug::FloatDivision: {
    if (p.midpoint) return 0.5f;
    const float lf = t.floorSegments ? float(p.indexOnFloor) / float(t.floorSegments) : 0.0f;
    const float lc = float(p.indexOnCeil) / float(t.ceilSegments);
    const float fr = float(t.halfFraction) / 65536.0f;
    const float loc = fr == 0.0f ? lc : lf * (1.0f - fr) + lc * fr;
    return p.mirrored ? 1.0f - loc : loc;
  }
  case PortBug::NoMirroring: return p.mirrored && !p.midpoint ? toFloat(placeUnmirrored(t, p.index)) : p.param;
  case PortBug::NoSpecialMidpoint: return p.midpoint ? toFloat(placeUnmirrored(t, p.halfIndex)) : p.param;
  case PortBug::LerpNotRounded: {
    if (p.midpoint) return 0.5f;
    const double loc = double(p.lerp) / 4294967296.0;
    return float(p.mirrored ? 1.0 - loc : loc);
  }
  case PortBug::FactorsNotSnapped: {
    if (p.midpoint || t.floorSegments == 0) return p.param;
    // Half the factor from the float, not from its 16.16 rounding (same half-point shift as the reference).
    double half = double(rawFactor) * 32768.0;
    if (t.halfFactor != (t.fixedFactor + 1) / 2) half += 32768.0;
    if (std::floor(half / 65536.0) * 65536.0 != double(t.floorHalf))
      return p.param; // another point count: not per point
    const double fr = (half - double(t.floorHalf)) / 65536.0;
    const double blend = double(uint32_t(p.indexOnFloor) * t.reciprocalFloor) * (1.0 - fr) +
                         double(uint32_t(p.indexOnCeil) * t.reciprocalCeil) * fr;
    const uint32_t loc = uint32_t(std::floor(blend + 0.5));
    return toFloat(p.mirrored ? fx::kOne - loc : loc);
  }
  default: return p.param;
  }
}

PatchAxes patchAxes(const Patch& patch, const Options& options) {
  PatchAxes a;
  a.domain = patch.domain;
  float hw[6];
  if (patch.stage.hlsl) {
    const HlslFactors h = processHlslFactors(patch.domain, patch.partitioning, patch.stage, patch.factors, options);
    for (int i = 0; i < 6; ++i) hw[i] = h.rounded[i];
  } else {
    for (int i = 0; i < 6; ++i) hw[i] = options.flushDenormals ? fx::flushDenormal(patch.factors[i]) : patch.factors[i];
  }
  const int outer = patch.domain == Domain::Quad ? 4 : patch.domain == Domain::Tri ? 3 : 0;
  for (int e = 0; e < outer; ++e) {
    Axis& x = a.outer[e];
    x.name = patch.domain == Domain::Quad ? kQuadAxes[e] : kTriAxes[e];
    x.trace = traceEdge(patch.factors[e], patch.partitioning, patch.stage, options);
    x.valid = !x.trace.culled;
    x.raw = x.trace.clamped;
  }
  if (patch.domain == Domain::Quad) {
    a.inside[0] = insideAxis(hw[InsideU], patch.partitioning, "insideU");
    a.inside[1] = insideAxis(hw[InsideV], patch.partitioning, "insideV");
  } else if (patch.domain == Domain::Isoline) {
    a.inside[0] = insideAxis(hw[IsolineDetail], patch.partitioning, "detail");
    a.inside[1] = insideAxis(std::fmin(hw[IsolineDensity], 64.0f), Partitioning::Integer, "density");
  }
  return a;
}

// Which axis gives coordinate c (0 = u, 1 = v) of a reference vertex. Null when the coordinate is a corner's, a
// tri interior's or otherwise not one edge point. 'mirrorV' is set for the tri Weq0 edge (v = 1 - u).
const Axis* axisOf(const PatchAxes& a, CapturedVertex r, int c, bool& mirrorV, bool corners) {
  mirrorV = false;
  const float u = fx::floatOf(r.u), v = fx::floatOf(r.v);
  const bool uEdge = u == 0.0f || u == 1.0f, vEdge = v == 0.0f || v == 1.0f;
  switch (a.domain) {
  case Domain::Quad:
    // Corners: (0,1) is Ueq0's last point, (1,1) Veq1's last point (both placed by mirroring); (0,0), (1,0) are
    // first points (0 under any placement).
    if (uEdge && vEdge) {
      if (corners && v == 1.0f) return c == (u == 0.0f ? 1 : 0) ? &a.outer[u == 0.0f ? 0 : 3] : nullptr;
      return nullptr;
    }
    if (uEdge) return c == 1 ? &a.outer[u == 0.0f ? 0 : 2] : nullptr;
    if (vEdge) return c == 0 ? &a.outer[v == 0.0f ? 1 : 3] : nullptr;
    return &a.inside[c];
  case Domain::Tri:
    // Corners: V (0,1) is Ueq0's last point, U (1,0) Weq0's last point (mirrored); W (0,0) a first point.
    if (uEdge && vEdge) {
      if (!corners) return nullptr;
      if (u == 0.0f && v == 1.0f) return c == 1 ? &a.outer[0] : nullptr;
      if (u == 1.0f && v == 0.0f) {
        mirrorV = true;
        return c == 0 ? &a.outer[2] : nullptr;
      }
      return nullptr;
    }
    if (u == 0.0f) return c == 1 ? &a.outer[0] : nullptr;
    if (v == 0.0f) return c == 0 ? &a.outer[1] : nullptr;
    if (u + v == 1.0f) {
      mirrorV = true;
      return c == 0 ? &a.outer[2] : nullptr;
    }
    return nullptr;
  case Domain::Isoline: return &a.inside[c];
  }
  return nullptr;
}

int pointOnAxis(const Axis& axis, uint32_t bits) {
  if (!axis.valid) return -1;
  for (int k = 0; k < axis.trace.count; ++k)
    if (fx::bitsOf(axis.trace.points[k].param) == bits) return k;
  return -1;
}

CapturedVertex applyBug(const PatchAxes& a, PortBug b, CapturedVertex r, bool corners) {
  CapturedVertex out = r;
  for (int c = 0; c < 2; ++c) {
    bool mirrorV = false;
    const Axis* axis = axisOf(a, r, c, mirrorV, corners);
    if (!axis) continue;
    const int k = pointOnAxis(*axis, c == 0 ? r.u : r.v);
    if (k < 0) continue;
    const float value = buggyEdgeParam(b, axis->trace, k, axis->raw);
    (c == 0 ? out.u : out.v) = fx::bitsOf(value);
    if (mirrorV) out.v = fx::bitsOf(1.0f - value);
  }
  return out;
}

} // namespace fftess
