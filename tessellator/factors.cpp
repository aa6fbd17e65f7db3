#include "factors.h"

#include <cmath>

namespace fftess {
namespace {

// The reference decides integer parity from the float's integer part: (int)x & 1.
bool isEvenFactor(float x) { return (int(x) & 1) == 0; }

float clampHardware(float x, FactorRange r) { return fx::d3dMin(r.upper, fx::d3dMax(r.lower, x)); }

// D3D11.3 11.7.12: an edge factor <= 0 or NaN culls the patch.
bool culledBy(float x) { return !(x > 0.0f); } // NaN, +-0, negatives, -Inf; a positive denormal is NOT culled

// Inside axes of integer partitioning: a factor of 1 is placed as even.
bool insideOdd(float x, Partitioning p) {
  if (isIntegerLike(p)) return !(isEvenFactor(x) || x == 1.0f);
  return p == Partitioning::FractionalOdd;
}

AxisSpacing insideSpacing(float x, bool odd) {
  AxisSpacing s = makeAxisSpacing(fx::floatToFixed(x), odd);
  // D3D reference: inside axes have at least one interior ring's worth of points, degenerate when the factor is 1.
  const int minimum = odd ? 4 : 3;
  if (s.numPoints < minimum) s.numPoints = minimum;
  return s;
}

} // namespace

// D3D11.3 11.7.10 / 11.7.11.2: edge factor ranges per partitioning.
FactorRange hardwareRange(Partitioning p) {
  switch (p) {
  case Partitioning::FractionalEven: return {fx::kMinEvenFactor, fx::kMaxEvenFactor};
  case Partitioning::FractionalOdd: return {fx::kMinOddFactor, fx::kMaxOddFactor};
  case Partitioning::Integer:
  case Partitioning::Pow2: break; // D3D11.3 11.7.7.1, 11.7.11.2: hardware treats pow2 as integer
  }
  return {fx::kMinOddFactor, fx::kMaxEvenFactor};
}

// D3D11.3 11.7.11.2: cull, clamp, then (integer, pow2) round up to the next integer; 11.7.14: then 16.16.
ProcessedEdge processOuterEdge(float factor, Partitioning p) {
  ProcessedEdge e;
  if (culledBy(factor)) {
    e.culled = true;
    return e;
  }
  e.clamped = clampHardware(factor, hardwareRange(p));
  e.rounded = isIntegerLike(p) ? std::ceil(e.clamped) : e.clamped;
  e.odd = isIntegerLike(p) ? !isEvenFactor(e.rounded) : p == Partitioning::FractionalOdd;
  e.fixed = fx::floatToFixed(e.rounded);
  return e;
}

// An ordinary factor: a positive normal float below 2^15. Then no NaN, zero, denormal or infinity rule of the
// clamps and of floatToFixed applies, and the D3D min/max are plain comparisons.
inline bool isOrdinary(float x) { return fx::bitsOf(x) - fx::kMinNormal < 0x47000000u - fx::kMinNormal; }

// floatToFixed for a value in [1, 2^15): the mantissa shifted into place, ties to even.
inline fx::Fixed ordinaryToFixed(float x) {
  const uint32_t b = fx::bitsOf(x);
  const int drop = 134 - int(b >> 23); // 23 - 16 - (exponent - 127): mantissa bits below the 2^-16 place
  uint32_t m = (b & fx::kMantissaMask) | 0x00800000u;
  if (drop <= 0) return m << -drop;
  const uint32_t keep = 1u << drop, rest = m & (keep - 1), half = keep >> 1;
  if ((m & keep) || rest > half) m += half;
  return m >> drop;
}

// D3D11.3 spec 11.7.11.2-11.7.11.3 and 11.7.14 for fractional partitionings when all six factors are ordinary:
// the same clamps and 16.16 values as the general path below, without its special-value tests.
ProcessedQuad fractionalQuad(const float f[6], Partitioning p) {
  ProcessedQuad q;
  q.culled = false;
  q.minimum = false;
  const FactorRange range = hardwareRange(p);
  const bool odd = p == Partitioning::FractionalOdd;
  float lower = range.lower;
  fx::Fixed edge[4];
  bool frame = f[InsideU] > fx::kOddPictureFrameThreshold || f[InsideV] > fx::kOddPictureFrameThreshold;
  bool allOne = true;
  for (int i = 0; i < 4; ++i) {
    const float x = f[i];
    const float m = range.lower >= x ? range.lower : x;
    const float c = range.upper < m ? range.upper : m;
    frame = frame || c > fx::kOddPictureFrameThreshold;
    edge[i] = ordinaryToFixed(c);
    allOne = allOne && edge[i] == fx::kOne;
  }
  if (odd && frame) lower = fx::kOddPictureFrameMinimum;
  fx::Fixed inside[2];
  for (int a = 0; a < 2; ++a) {
    const float x = f[InsideU + a];
    const float m = lower >= x ? lower : x;
    inside[a] = ordinaryToFixed(range.upper < m ? range.upper : m);
    allOne = allOne && inside[a] == fx::kOne;
  }
  if (odd && allOne) {
    q.minimum = true;
    return q;
  }
  for (int i = 0; i < 4; ++i) q.outer[i] = makeAxisSpacing(edge[i], odd);
  for (int a = 0; a < 2; ++a) {
    q.inside[a] = makeAxisSpacing(inside[a], odd);
    const int minimum = odd ? 4 : 3;
    if (q.inside[a].numPoints < minimum) q.inside[a].numPoints = minimum;
  }
  return q;
}

ProcessedQuad processQuadFactors(const float f[6], Partitioning p) {
  if (!isIntegerLike(p) && isOrdinary(f[0]) && isOrdinary(f[1]) && isOrdinary(f[2]) && isOrdinary(f[3]) &&
      isOrdinary(f[4]) && isOrdinary(f[5]))
    return fractionalQuad(f, p);
  ProcessedQuad q;
  ProcessedEdge edge[4];
  for (int i = 0; i < 4; ++i) {
    edge[i] = processOuterEdge(f[i], p);
    if (edge[i].culled) q.culled = true;
  }
  if (q.culled) return q;
  FactorRange range = hardwareRange(p);
  // D3D11.3 11.7.11.3 (the inside clamp pseudocode).
  // fractional_odd: if any factor would still exceed 1 in 16.16, force the inside factors above 1 so that there
  // is a picture frame (reference behaviour; the test uses the processed outer and the raw inside factors).
  if (p == Partitioning::FractionalOdd) {
    bool frame = f[InsideU] > fx::kOddPictureFrameThreshold || f[InsideV] > fx::kOddPictureFrameThreshold;
    for (int i = 0; i < 4; ++i) frame = frame || edge[i].rounded > fx::kOddPictureFrameThreshold;
    if (frame) range.lower = fx::kOddPictureFrameMinimum;
  }
  float inside[2];
  for (int a = 0; a < 2; ++a) {
    inside[a] = clampHardware(f[InsideU + a], range); // NaN -> lower bound
    if (isIntegerLike(p)) inside[a] = std::ceil(inside[a]);
  }
  const fx::Fixed insideFixed[2] = {fx::floatToFixed(inside[0]), fx::floatToFixed(inside[1])};
  if (p != Partitioning::FractionalEven) {
    bool allOne = insideFixed[0] == fx::kOne && insideFixed[1] == fx::kOne;
    for (int i = 0; i < 4; ++i) allOne = allOne && edge[i].fixed == fx::kOne;
    if (allOne) {
      q.minimum = true;
      return q;
    }
  }
  for (int i = 0; i < 4; ++i) q.outer[i] = makeAxisSpacing(edge[i].fixed, edge[i].odd);
  for (int a = 0; a < 2; ++a) q.inside[a] = insideSpacing(inside[a], insideOdd(inside[a], p));
  return q;
}

ProcessedTri processTriFactors(const float f[4], Partitioning p) {
  ProcessedTri t;
  ProcessedEdge edge[3];
  for (int i = 0; i < 3; ++i) {
    edge[i] = processOuterEdge(f[i], p);
    if (edge[i].culled) t.culled = true;
  }
  if (t.culled) return t;
  FactorRange range = hardwareRange(p);
  // Same picture-frame rule as the quad, but only the outer factors are looked at (one inside factor).
  if (p == Partitioning::FractionalOdd) {
    bool frame = false;
    for (int i = 0; i < 3; ++i) frame = frame || edge[i].rounded > fx::kOddPictureFrameThreshold;
    if (frame) range.lower = fx::kOddPictureFrameMinimum;
  }
  float inside = clampHardware(f[TriInside], range);
  if (isIntegerLike(p)) inside = std::ceil(inside);
  if (p != Partitioning::FractionalEven) {
    bool allOne = fx::floatToFixed(inside) == fx::kOne;
    for (int i = 0; i < 3; ++i) allOne = allOne && edge[i].fixed == fx::kOne;
    if (allOne) {
      t.minimum = true;
      return t;
    }
  }
  for (int i = 0; i < 3; ++i) t.outer[i] = makeAxisSpacing(edge[i].fixed, edge[i].odd);
  t.inside = insideSpacing(inside, insideOdd(inside, p));
  return t;
}

// D3D11.3 11.7.8 / 11.7.11.2: line detail follows the partitioning; line density is clamped to [1, 64] and
// rounded up to an integer.
ProcessedIsoline processIsolineFactors(float density, float detail, Partitioning p) {
  ProcessedIsoline l;
  if (culledBy(density) || culledBy(detail)) {
    l.culled = true;
    return l;
  }
  density = fx::d3dMin(fx::kMaxIsolineDensity, fx::d3dMax(fx::kMinIsolineDensity, density));
  detail = clampHardware(detail, hardwareRange(p));
  bool detailOdd = p == Partitioning::FractionalOdd;
  if (isIntegerLike(p)) {
    detail = std::ceil(detail);
    detailOdd = !isEvenFactor(detail);
  }
  l.detail = makeAxisSpacing(fx::floatToFixed(detail), detailOdd);
  // Line density is always integer partitioned.
  density = std::ceil(density);
  l.density = makeAxisSpacing(fx::floatToFixed(density), !isEvenFactor(density));
  l.numLines = l.density.numPoints - 1;
  return l;
}

} // namespace fftess
