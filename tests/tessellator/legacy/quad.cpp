// Quad domain: outer ring clockwise from (u=0, v=1), inner rings spiralling in, then the middle row of an even
// axis; connectivity ring by ring, then the middle strip of an odd axis. Order exactly as the D3D11 reference.
#include "generate.h"

namespace fftess::legacy {
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

void quadPoints(const ProcessedQuad& q, MeshWriter& out) {
  // Outer ring. Edges in order Ueq0, Veq0, Ueq1, Veq1; each without its last point (the next edge's first).
  // Ueq0 runs v from 1 down to 0, Veq0 u up from 0, Ueq1 v up from 0, Veq1 u down from 1.
  for (int e = 0; e < 4; ++e) {
    const AxisSpacing& s = q.outer[e];
    const int last = s.numPoints - 1;
    const bool forward = e == 1 || e == 2;
    for (int p = 0; p < last; ++p) {
      const fx::Fixed t = placePoint(s, forward ? p : last - p);
      if (e & 1)
        out.point(t, e == 3 ? fx::kOne : 0);
      else
        out.point(e == 2 ? fx::kOne : 0, t);
    }
  }
  // Inner rings, same edge order, each edge at a fixed position on the perpendicular axis.
  const int nU = q.inside[U].numPoints, nV = q.inside[V].numPoints;
  const int rings = (nU < nV ? nU : nV) >> 1;
  for (int ring = 1; ring < rings; ++ring) {
    const int end[2] = {nU - 1 - ring, nV - 1 - ring};
    for (int e = 0; e < 4; ++e) {
      const int across = e & 1, along = 1 - across; // axis of the fixed coordinate / of the moving coordinate
      const fx::Fixed fixedCoord = placePoint(q.inside[across], e < 2 ? ring : end[across]);
      const bool forward = e == 1 || e == 2;
      for (int p = ring; p < end[along]; ++p) {
        const fx::Fixed t = placePoint(q.inside[along], forward ? p : end[along] - (p - ring));
        if (along == V)
          out.point(fixedCoord, t);
        else
          out.point(t, fixedCoord);
      }
    }
  }
  // Even parity on the shorter axis leaves a degenerate innermost ring: one row of points through the middle.
  if (nU > nV && !q.inside[V].odd) {
    for (int p = rings; p <= nU - 1 - rings; ++p) out.point(placePoint(q.inside[U], p), fx::kHalf);
  } else if (nV >= nU && !q.inside[U].odd) {
    for (int p = nV - 1 - rings; p >= rings; --p) out.point(fx::kHalf, placePoint(q.inside[V], p));
  }
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
