// Checks "my port" against the D3D11 reference for one patch, through the installed fftess::compare
// (the comparison component; it links fftess::tessellator).
#include <cstdio>

#include "compare/compare.h"

int main() {
  fftess::Patch patch; // quad, integer, triangle_cw, hardware stage
  for (float& f : patch.factors) f = 3.0f;
  // What the port produced for the patch, primitive after primitive (here: a bit-exact port's output).
  fftess::CapturedPatch mine = fftess::referenceCapture(patch, 0, {});
  fftess::Tessellator reference;
  const fftess::PatchComparison c = fftess::comparePatch(patch, &mine, {}, reference);
  std::printf("%s (%d triangles)\n", fftess::toString(c.kind), c.capturePrimitives);
  for (fftess::PortBug bug : c.bugs) std::printf("reproduced by %s\n", fftess::describe(bug));
  return c.kind == fftess::DifferenceKind::Same ? 0 : 1;
}
