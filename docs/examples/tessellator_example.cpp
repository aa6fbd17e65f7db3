// Example from docs/tessellator.md; built and run by ctest ("tessellator:docs example").
#include <cstdio>

#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

int main() {
  fftess::Tessellator t; // owns reusable buffers: no allocation per patch
  fftess::Patch p;       // domain, partitioning, primitive, stage, factors[6]
  p.domain = fftess::Domain::Quad;
  p.partitioning = fftess::Partitioning::FractionalEven;
  p.primitive = fftess::OutputPrimitive::TriangleCw;
  const float factors[6] = {12.5f, 3, 7, 64, 5, 9}; // Ueq0 Veq0 Ueq1 Veq1 insideU insideV
  for (int i = 0; i < 6; ++i) p.factors[i] = factors[i];
  const int points = t.tessellate(p);
  std::printf("%d points, %zu triangles\n", points, t.indices().size() / 3);

  // One edge only: the points along the Ueq0 edge, in 16.16 and as floats.
  const fftess::EdgePoints e = fftess::edgePoints(12.5f, fftess::Partitioning::FractionalEven);
  std::printf("Ueq0 edge: %d points, second at 0x%05x = %.9g\n", e.count, e.fixed[1], double(e.param[1]));

  // Every fixed-point step of an edge (what `fftess explain` prints).
  const fftess::EdgeTrace tr = fftess::traceEdge(12.0f, fftess::Partitioning::Integer);
  std::printf("factor 12: reciprocal %u, point 1 at %u\n", tr.reciprocalCeil, tr.points[1].fixed);

  // The 12 beside 2x6 fact: 2 * r(12) = 10922 but r(6) = 10923.
  const fftess::EdgeTrace six = fftess::traceEdge(6.0f, fftess::Partitioning::Integer);
  return (2 * tr.reciprocalCeil == 10922 && six.reciprocalCeil == 10923 && points > 0) ? 0 : 1;
}
