// Isoline domain: numLines lines at v = density placements 0 .. numLines-1 (never v = 1), each with the detail
// placement along u. Point output lists every point; any other output joins consecutive points of each line.
#include "generate.h"

namespace fftess::legacy {

void generateIsoline(const ProcessedIsoline& l, bool points, MeshWriter& out) {
  if (l.culled) return;
  const int perLine = l.detail.numPoints;
  for (int line = 0; line < l.numLines; ++line) {
    const fx::Fixed v = placePoint(l.density, line);
    for (int p = 0; p < perLine; ++p) out.point(placePoint(l.detail, p), v);
  }
  for (int line = 0; line < l.numLines; ++line) {
    const int base = line * perLine;
    if (points) {
      for (int p = 0; p < perLine; ++p) out.indices[out.numIndices++] = base + p;
    } else {
      for (int p = 1; p < perLine; ++p) {
        out.indices[out.numIndices++] = base + p - 1;
        out.indices[out.numIndices++] = base + p;
      }
    }
  }
}

} // namespace fftess
