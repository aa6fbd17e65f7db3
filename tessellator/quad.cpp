// Quad domain: outer ring clockwise from (u=0, v=1), inner rings spiralling in, then the middle row of an even
// axis; connectivity ring by ring, then the middle strip of an odd axis. Order exactly as the D3D11 reference.
#include "generate.h"

namespace fftess {
namespace {

constexpr int U = 0, V = 1;

void minimumQuad(bool triangles, MeshWriter& out) {
  out.point(0, 0);
  out.point(fx::kOne, 0);
  out.point(fx::kOne, fx::kOne);
  out.point(0, fx::kOne);
  if (triangles) {
    out.triangle(0, 1, 3);
    out.triangle(1, 2, 3);
  }
}

// D3D11.3 spec 11.7.6-11.7.8: points from 1D tables. Every point of the quad is (u table[i], v table[j]) of one
// outer edge's table or of the two inside axes' tables, so placement runs once per axis, not once per point.
void quadPoints(const ProcessedQuad& q, MeshWriter& out) {
  DomainPoint* dst = out.points + out.numPoints;
  // Outer ring. Edges in order Ueq0, Veq0, Ueq1, Veq1; each without its last point (the next edge's first).
  // Ueq0 runs v from 1 down to 0, Veq0 u up from 0, Ueq1 v up from 0, Veq1 u down from 1.
  AxisTable t;
  for (int e = 0; e < 4; ++e) {
    fillAxisTable(q.outer[e], t);
    const int last = t.count - 1;
    switch (e) {
    case 0: for (int p = 0; p < last; ++p) *dst++ = {0.0f, t.param[last - p]}; break;
    case 1: for (int p = 0; p < last; ++p) *dst++ = {t.param[p], 0.0f}; break;
    case 2: for (int p = 0; p < last; ++p) *dst++ = {1.0f, t.param[p]}; break;
    default: for (int p = 0; p < last; ++p) *dst++ = {t.param[last - p], 1.0f}; break;
    }
  }
  // Inner rings, same edge order, each edge at a fixed position on the perpendicular axis.
  AxisTable tu, tv;
  fillAxisTable(q.inside[U], tu);
  fillAxisTable(q.inside[V], tv);
  const float* U_ = tu.param;
  const float* V_ = tv.param;
  const int nU = q.inside[U].numPoints, nV = q.inside[V].numPoints;
  const int rings = (nU < nV ? nU : nV) >> 1;
  for (int ring = 1; ring < rings; ++ring) {
    const int endU = nU - 1 - ring, endV = nV - 1 - ring;
    for (int p = ring; p < endV; ++p) *dst++ = {U_[ring], V_[endV - (p - ring)]};
    for (int p = ring; p < endU; ++p) *dst++ = {U_[p], V_[ring]};
    for (int p = ring; p < endV; ++p) *dst++ = {U_[endU], V_[p]};
    for (int p = ring; p < endU; ++p) *dst++ = {U_[endU - (p - ring)], V_[endV]};
  }
  // Even parity on the shorter axis leaves a degenerate innermost ring: one row of points through the middle.
  if (nU > nV && !q.inside[V].odd) {
    for (int p = rings; p <= nU - 1 - rings; ++p) *dst++ = {U_[p], 0.5f};
  } else if (nV >= nU && !q.inside[U].odd) {
    for (int p = nV - 1 - rings; p >= rings; --p) *dst++ = {0.5f, V_[p]};
  }
  out.numPoints = int(dst - out.points);
}

void quadTriangles(const ProcessedQuad& q, MeshWriter& out, int firstInsidePoint) {
  const int n[2] = {q.inside[U].numPoints, q.inside[V].numPoints};
  const int rowsToCentre[2] = {(n[U] + 1) >> 1, (n[V] + 1) >> 1};
  const int rings = rowsToCentre[U] < rowsToCentre[V] ? rowsToCentre[U] : rowsToCentre[V];
  // With an even inside axis, the innermost ring of the other axis is a degenerate row of points; the rows along it
  // run backwards through the point array. Indexed by the axis the row runs along.
  const int degenerateRing[2] = {!q.inside[V].odd ? rowsToCentre[V] - 1 : -1,
                                 !q.inside[U].odd ? rowsToCentre[U] - 1 : -1};

  // The current outside row of each edge: factor half-size, parity, point count.
  int outsideHalf[4], outsidePoints[4];
  bool outsideOdd[4];
  for (int e = 0; e < 4; ++e) {
    outsideHalf[e] = q.outer[e].numHalfPoints;
    outsideOdd[e] = q.outer[e].odd;
    outsidePoints[e] = q.outer[e].numPoints;
  }
  int insideBase = firstInsidePoint, outsideBase = 0;
  for (int ring = 1; ring < rings; ++ring) {
    const int insidePoints[2] = {n[U] - 2 * ring, n[V] - 2 * ring};
    const int ringInsideStart = insideBase, ringOutsideStart = outsideBase;
    for (int e = 0; e < 4; ++e) {
      const int along = (e + 1) & 1;
      const bool degenerate = ring == degenerateRing[along];
      Row inside{insideBase, 1}, outside{outsideBase, 1};
      if (e == 3) {
        // The ring's last edge ends on the ring's first point.
        outside.redirectFrom = outsidePoints[e] - 1;
        outside.redirectTo = ringOutsideStart;
        if (degenerate) {
          inside.step = -1;
        } else {
          inside.redirectFrom = insidePoints[along] - 1;
          inside.redirectTo = ringInsideStart;
        }
      } else if (e == 2 && degenerate) {
        inside.step = -1;
      }
      if (ring == 1)
        stitchTransition(out, inside, q.inside[along].numHalfPoints, q.inside[along].odd, outside, outsideHalf[e],
                         outsideOdd[e]);
      else
        stitchRegular(out, true, Diagonals::Mirrored, insidePoints[along], inside, outside);
      outsideBase += outsidePoints[e] - 1;
      insideBase += (e == 2 && degenerate) ? -(insidePoints[along] - 1) : insidePoints[along] - 1;
      outsidePoints[e] = insidePoints[along];
    }
    if (ring == 1) {
      for (int e = 0; e < 4; ++e) {
        outsideHalf[e] = q.inside[e & 1].numHalfPoints;
        outsideOdd[e] = q.inside[e & 1].odd;
      }
    }
  }
  // Odd shorter axis: a strip of quads through the middle, between the two long sides of the last ring.
  if (n[U] > n[V] && q.inside[V].odd) {
    const int quads = (((n[U] >> 1) - (n[V] >> 1)) << 1) + (q.inside[U].odd ? 1 : 2);
    const int far = outsideBase + quads + 2;
    Row inside{far + quads, -1, 0, outsideBase};
    Row outside{outsideBase + 1, 1};
    stitchRegular(out, false, Diagonals::InsideToOutside, quads + 1, inside, outside);
  } else if (n[V] >= n[U] && q.inside[U].odd) {
    const int quads = (((n[V] >> 1) - (n[U] >> 1)) << 1) + (q.inside[V].odd ? 1 : 2);
    const int far = outsideBase + quads + 1;
    Row inside{far + quads, -1};
    Row outside{outsideBase, 1};
    stitchRegular(out, false, q.inside[V].odd ? Diagonals::InsideToOutsideExceptMiddle : Diagonals::InsideToOutside,
                  quads + 1, inside, outside);
  }
}

} // namespace

void generateQuad(const ProcessedQuad& q, bool triangles, MeshWriter& out) {
  if (q.culled) return;
  if (q.minimum) {
    minimumQuad(triangles, out);
    return;
  }
  const int first = out.numPoints;
  quadPoints(q, out);
  if (triangles) {
    int outerPoints = 0;
    for (int e = 0; e < 4; ++e) outerPoints += q.outer[e].numPoints - 1;
    quadTriangles(q, out, first + outerPoints);
  }
}

} // namespace fftess
