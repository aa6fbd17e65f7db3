// The big-vs-half-edge analysis of edge_analysis.h: exact comparison in 1/131072 of the big edge, and the
// attribution of each mismatch by replaying the point's placement in exact rational arithmetic.
#include "edge_analysis.h"

#include <algorithm>
#include <numeric>

namespace fftess {
namespace {

Fraction reduced(int64_t num, int64_t den) {
  if (den < 0) num = -num, den = -den;
  const int64_t g = std::gcd(num, den); // gcd(0, den) = den: zero is 0/1
  return Fraction{num / g, den / g};
}

// Nearest other-side point, in 1/131072 units.
int64_t nearest(const std::vector<HalfEdgePoint>& v, int64_t t) {
  int64_t best = INT64_MAX;
  for (const HalfEdgePoint& p : v) best = std::min(best, p.t > t ? p.t - t : t - p.t);
  return best;
}

// Fills row.causes for a mismatching row (see MismatchCause).
void attribute(const HalfEdgeComparison& c, HalfEdgeRow& r) {
  if (r.big < 0 || r.small < 0) {
    r.causes.push_back(MismatchCause::PointCount);
    return;
  }
  const HalfEdgePoint& big = c.bigPoints[size_t(r.big)];
  const HalfEdgePoint& small = c.smallPoints[size_t(r.small)];
  r.bigBudget = pointBudget(c.big.trace, big.index);
  r.smallBudget = pointBudget(c.small.trace, small.index);
  if (!r.bigBudget.consistent || !r.smallBudget.consistent) return; // no attribution
  r.attributed = true;
  // Both ideals in 1/131072 of the big edge: big 2 * ideal, small ideal (+ 65536 on the second small edge).
  const Fraction& bi = r.bigBudget.ideal;
  const Fraction& si = r.smallBudget.ideal;
  const int64_t offset = small.edge == 2 ? 65536 : 0;
  if (reduced(2 * bi.num, bi.den) != reduced(si.num + offset * si.den, si.den)) {
    r.causes.push_back(MismatchCause::Placement);
    return;
  }
  if (r.bigBudget.midpoint != r.smallBudget.midpoint) r.causes.push_back(MismatchCause::SpecialHalf);
  if (!r.bigBudget.reciprocalError.zero() || !r.smallBudget.reciprocalError.zero())
    r.causes.push_back(MismatchCause::ReciprocalTable);
  if (!r.bigBudget.lerpError.zero() || !r.smallBudget.lerpError.zero())
    r.causes.push_back(MismatchCause::LerpRounding);
}

} // namespace

bool operator==(const Fraction& a, const Fraction& b) {
  const Fraction x = reduced(a.num, a.den), y = reduced(b.num, b.den);
  return x.num == y.num && x.den == y.den;
}

const char* toString(MismatchCause c) {
  static const char* const kNames[] = {"point_count", "placement", "special_half", "reciprocal_table",
                                       "lerp_rounding"};
  const size_t i = size_t(c);
  return i < sizeof kNames / sizeof kNames[0] ? kNames[i] : "?";
}

PointBudget pointBudget(const EdgeTrace& tr, int index) {
  const EdgePointTrace& p = tr.points[index];
  PointBudget b;
  b.midpoint = p.midpoint;
  b.mirrored = p.mirrored;
  if (p.midpoint) {
    b.ideal = Fraction{32768, 1};
    b.consistent = p.fixed == 0x8000u;
    return b;
  }
  // Every quantity over one denominator D = fs * cs * 65536 (fs, cs: segment counts, 1 for an absent placement);
  // numerators stay below 2^46. hf / 65536 is the ceil placement's blend weight.
  const int64_t fs = std::max(tr.floorSegments, 1), cs = std::max(tr.ceilSegments, 1);
  const int64_t hf = tr.halfFraction, D = fs * cs * 65536;
  const int64_t exactFloor = tr.floorSegments > 0 ? int64_t(p.indexOnFloor) * 65536 : 0; // * D / fs / 65536
  const int64_t exactCeil = tr.ceilSegments > 0 ? int64_t(p.indexOnCeil) * 65536 : 0;    // * D / cs / 65536
  const int64_t loc = exactFloor * cs * (65536 - hf) + exactCeil * fs * hf;
  const int64_t recip = (int64_t(p.locationOnFloor) * fs - exactFloor) * cs * (65536 - hf) +
                        (int64_t(p.locationOnCeil) * cs - exactCeil) * fs * hf;
  const int64_t lerp = (int64_t(p.halfLocation) * 65536 - int64_t(p.lerp)) * fs * cs;
  const int64_t sign = p.mirrored ? -1 : 1;
  const int64_t ideal = p.mirrored ? 65536 * D - loc : loc;
  b.ideal = reduced(ideal, D);
  b.reciprocalError = reduced(sign * recip, D);
  b.lerpError = reduced(sign * lerp, D);
  b.consistent = ideal + sign * recip + sign * lerp == int64_t(p.fixed) * D;
  return b;
}

HalfEdgeComparison compareHalfEdges(float bigFactor, float smallFactor, Partitioning part, const Stage& stage,
                                    const Options& options) {
  HalfEdgeComparison c;
  c.big.factor = bigFactor;
  c.small.factor = smallFactor;
  c.big.edge = edgePoints(bigFactor, part, stage, options);
  c.small.edge = edgePoints(smallFactor, part, stage, options);
  c.big.trace = traceEdge(bigFactor, part, stage, options);
  c.small.trace = traceEdge(smallFactor, part, stage, options);
  if (c.big.edge.culled || c.small.edge.culled) {
    c.culled = true;
    return c;
  }
  const EdgePoints& b = c.big.edge;
  const EdgePoints& s = c.small.edge;
  for (int i = 0; i < b.count; ++i) c.bigPoints.push_back({2 * int64_t(b.fixed[i]), 0, i, b.fixed[i]});
  for (int i = 0; i < s.count; ++i) c.smallPoints.push_back({int64_t(s.fixed[i]), 1, i, s.fixed[i]});
  for (int i = 1; i < s.count; ++i) c.smallPoints.push_back({65536 + int64_t(s.fixed[i]), 2, i, s.fixed[i]});

  for (const HalfEdgePoint& p : c.bigPoints) {
    const int64_t d = nearest(c.smallPoints, p.t);
    if (d > c.worstGap) c.worstGap = d, c.worstAt = p.t;
  }
  for (const HalfEdgePoint& p : c.smallPoints) {
    const int64_t d = nearest(c.bigPoints, p.t);
    if (d > c.worstGap) c.worstGap = d, c.worstAt = p.t;
  }
  c.paired = c.bigPoints.size() == c.smallPoints.size();
  c.match = c.worstGap == 0 && c.paired;
  if (c.paired) {
    for (size_t i = 0; i < c.bigPoints.size(); ++i) {
      HalfEdgeRow r;
      r.big = r.small = int(i);
      r.gap = c.smallPoints[i].t - c.bigPoints[i].t;
      r.match = r.gap == 0;
      c.rows.push_back(r);
    }
  } else {
    size_t i = 0, j = 0;
    while (i < c.bigPoints.size() || j < c.smallPoints.size()) {
      HalfEdgeRow r;
      if (j >= c.smallPoints.size() || (i < c.bigPoints.size() && c.bigPoints[i].t < c.smallPoints[j].t)) {
        r.big = int(i);
        r.gap = nearest(c.smallPoints, c.bigPoints[i++].t);
      } else if (i >= c.bigPoints.size() || c.smallPoints[j].t < c.bigPoints[i].t) {
        r.small = int(j);
        r.gap = nearest(c.bigPoints, c.smallPoints[j++].t);
      } else {
        r.big = int(i++);
        r.small = int(j++);
      }
      r.match = r.big >= 0 && r.small >= 0;
      c.rows.push_back(r);
    }
  }
  for (HalfEdgeRow& r : c.rows) {
    if (r.match) continue;
    ++c.mismatches;
    attribute(c, r);
  }
  return c;
}

SharedEdgeTicks sharedEdgeTicks(const SharedEdgeSpan& a, const SharedEdgeSpan& b, Partitioning partitioning,
                                const Stage& stage, const Options& options) {
  SharedEdgeTicks r;
  const EdgePoints ea = edgePoints(a.factor, partitioning, stage, options);
  const EdgePoints eb = edgePoints(b.factor, partitioning, stage, options);
  r.culled = ea.culled || eb.culled; // a culled side has no points: no ticks, and no partners for the other side
  auto ticks = [](const EdgePoints& e, const SharedEdgeSpan& s) {
    std::vector<SharedEdgeTick> out;
    const double lo = s.lo, hi = s.hi;
    for (int i = 0; i < e.count; ++i) {
      const double p = e.param[i];
      if (p < lo || p > hi || hi <= lo) continue;
      out.push_back({(p - lo) / (hi - lo), i, false});
    }
    return out;
  };
  r.a = ticks(ea, a);
  r.b = ticks(eb, b);
  for (SharedEdgeTick& x : r.a)
    for (SharedEdgeTick& y : r.b)
      if (x.t == y.t) x.partner = y.partner = true;
  return r;
}

} // namespace fftess
