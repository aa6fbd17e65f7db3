// Tri domain: outer ring starting at V (the Ueq0 edge), inner rings spiralling in, centre point for even parity;
// connectivity ring by ring, a centre triangle for odd parity. Order exactly as the D3D11 reference.
#include "generate.h"

namespace fftess::legacy {
namespace {

void triPoints(const ProcessedTri& t, MeshWriter& out) {
  // Outer ring: Ueq0 (V -> W, v decreasing), Veq0 (W -> U, u increasing), Weq0 (U -> V, u decreasing, v = 1 - u).
  for (int e = 0; e < 3; ++e) {
    const AxisSpacing& s = t.outer[e];
    const int last = s.numPoints - 1;
    for (int p = 0; p < last; ++p) {
      const fx::Fixed x = placePoint(s, (e & 1) ? p : last - p);
      if (e == 0)
        out.point(0, x);
      else
        out.point(x, e == 2 ? fx::kOne - x : 0);
    }
  }
  // Inner rings. A ring at 1D position 'ring' sits at 2/3 of that location in barycentric terms; the points along
  // each of its edges are pulled in by half of that (rounded up) to stay on the shrunken triangle. All 16.16,
  // unsigned 32-bit.
  const AxisSpacing& s = t.inside;
  const int n = s.numPoints;
  const int rings = n >> 1;
  for (int ring = 1; ring < rings; ++ring) {
    const int end = n - 1 - ring;
    for (int e = 0; e < 3; ++e) {
      fx::Fixed perp = placePoint(s, ring) * fx::kTwoThirds;
      perp = (perp + fx::kHalf) >> fx::kFractionBits;
      const fx::Fixed pull = (perp + 1) / 2;
      for (int p = ring; p < end; ++p) {
        const fx::Fixed x = placePoint(s, (e & 1) ? p : end - (p - ring));
        switch (e) {
        case 0: out.point(perp, x - pull); break;
        case 1: out.point(x - pull, perp); break;
        default: out.point(x - pull, fx::kOne - (x - pull) - perp); break;
        }
      }
    }
  }
  if (!s.odd) out.point(fx::kOneThird, fx::kOneThird);
}

void triTriangles(const ProcessedTri& t, MeshWriter& out, int firstInsidePoint) {
  const int n = t.inside.numPoints;
  const int rings = (n + 1) >> 1; // even parity: the centre point is the last "ring"
  int outsideHalf[3], outsidePoints[3];
  bool outsideOdd[3];
  for (int e = 0; e < 3; ++e) {
    outsideHalf[e] = t.outer[e].numHalfPoints;
    outsideOdd[e] = t.outer[e].odd;
    outsidePoints[e] = t.outer[e].numPoints;
  }
  int insideBase = firstInsidePoint, outsideBase = 0;
  for (int ring = 1; ring < rings; ++ring) {
    const int insidePoints = n - 2 * ring;
    const int ringInsideStart = insideBase, ringOutsideStart = outsideBase;
    for (int e = 0; e < 3; ++e) {
      Row inside{insideBase, 1}, outside{outsideBase, 1};
      if (e == 2) { // the ring's last edge ends on the ring's first point
        inside.redirectFrom = insidePoints - 1;
        inside.redirectTo = ringInsideStart;
        outside.redirectFrom = outsidePoints[e] - 1;
        outside.redirectTo = ringOutsideStart;
      }
      if (ring == 1)
        stitchTransition(out, inside, t.inside.numHalfPoints, t.inside.odd, outside, outsideHalf[e], outsideOdd[e]);
      else
        stitchRegular(out, true, Diagonals::Mirrored, insidePoints, inside, outside);
      outsideBase += outsidePoints[e] - 1;
      insideBase += insidePoints - 1;
      outsidePoints[e] = insidePoints;
    }
    if (ring == 1) {
      for (int e = 0; e < 3; ++e) {
        outsideHalf[e] = t.inside.numHalfPoints;
        outsideOdd[e] = t.inside.odd;
      }
    }
  }
  if (t.inside.odd) out.triangle(outsideBase, outsideBase + 1, outsideBase + 2);
}

} // namespace

void generateTri(const ProcessedTri& t, bool triangles, MeshWriter& out) {
  if (t.culled) return;
  if (t.minimum) {
    out.point(0, fx::kOne); // V
    out.point(0, 0);        // W
    out.point(fx::kOne, 0); // U
    if (triangles) out.triangle(0, 1, 2);
    return;
  }
  triPoints(t, out);
  if (triangles) {
    int outerPoints = 0;
    for (int e = 0; e < 3; ++e) outerPoints += t.outer[e].numPoints - 1;
    triTriangles(t, out, outerPoints);
  }
}

} // namespace fftess
