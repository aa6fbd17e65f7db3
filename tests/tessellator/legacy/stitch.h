// Connectivity between two rows of points (an outer ring edge and the next ring's edge), in the exact triangle
// order of the D3D11 reference. Internal header of fftess_tessellator.
#pragma once

#include <cstdint>

#include "tessellator/fixed.h"
#include "tessellator/factors.h"

namespace fftess::legacy {

// Caller-owned output arrays plus counters. Triangles are given clockwise; Ccw output swaps the last two indices.
struct MeshWriter {
  DomainPoint* points = nullptr;
  int32_t* indices = nullptr;
  int numPoints = 0;
  int numIndices = 0;
  bool ccw = false;

  void point(fx::Fixed u, fx::Fixed v) { points[numPoints++] = {fx::fixedToFloat(u), fx::fixedToFloat(v)}; }
  void triangle(int a, int b, int c) {
    indices[numIndices++] = a;
    indices[numIndices++] = ccw ? c : b;
    indices[numIndices++] = ccw ? b : c;
  }
};

// Maps a position along a row of points to the point's index in the output array. Rows run forwards or backwards
// through the point array; one position may be redirected (the last position of a ring's last edge wraps to the
// ring's first point; the first position of the centre strip of an odd quad starts on the ring before it).
struct Row {
  int first = 0;
  int step = 1;
  int redirectFrom = -1;
  int redirectTo = 0;
  int at(int k) const { return k == redirectFrom ? redirectTo : first + step * k; }
};

// Stitches the outermost ring (arbitrary factors on both rows) as the reference does: points are added on either
// row in "ruler function" order over each half, then the middle is closed according to the two parities.
// numHalf*: AxisSpacing::numHalfPoints of each row's factor; odd*: their parities.
void stitchTransition(MeshWriter& out, const Row& inside, int insideNumHalf, bool insideOdd, const Row& outside,
                      int outsideNumHalf, bool outsideOdd);

enum class Diagonals { InsideToOutside, InsideToOutsideExceptMiddle, Mirrored };

// Stitches two rows where the outside row has one more segment per end than the inside (trapezoid) or the same
// count (strip). numInsidePoints: points on the inside row.
void stitchRegular(MeshWriter& out, bool trapezoid, Diagonals diagonals, int numInsidePoints, const Row& inside,
                   const Row& outside);

} // namespace fftess
