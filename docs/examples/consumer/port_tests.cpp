// A port's own test suite against the installed emulator (fftess::compare, which links fftess::tessellator): the
// port's capture of a tiny batch, read back as a capture file, compared patch by patch. Here the "port" is the
// emulator itself, with a known port bug on patch 1 (its outer factors rotated by one edge: Ueq0 gets Veq0's, ...):
// patches 0 and 2 must be the same, and patch 1's difference must be named as that bug and no other.
#include <cstdio>
#include <sstream>
#include <string>

#include <fftess/compare/capture.h>
#include <fftess/compare/compare.h>
#include <fftess/tessellator/batch.h>

int main() {
  const char* batch[] = {"quad integer triangle_cw hw 3 3 3 3 3 3", "quad integer triangle_cw hw 3 5 7 6 4 5",
                         "tri fractional_even triangle_ccw hw 4.25 5 6 4 0 0"};
  fftess::Patch patches[3];
  std::string csv; // what the port wrote: patch,primitive,vertex,u,v
  for (int i = 0; i < 3; ++i) {
    fftess::BatchError err;
    if (!fftess::parseBatchLine(batch[i], patches[i], err)) {
      std::fprintf(stderr, "batch line %d: %s\n", i + 1, err.message.c_str());
      return 2;
    }
    const fftess::PortBug bug = fftess::PortBug::OuterFactorsRotated;
    fftess::appendCsv(csv, i == 1 ? fftess::portBugCapture(bug, 0, patches[i], i, {})
                                  : fftess::referenceCapture(patches[i], i, {}));
  }
  std::istringstream in(csv);
  fftess::CaptureReader reader(in, "port.csv");
  fftess::Tessellator reference;
  fftess::CapturedPatch got;
  int failures = 0, compared = 0;
  for (; compared < 3 && reader.next(got); ++compared) {
    if (got.patch < 0 || got.patch >= 3) return 1; // the capture has a patch the batch has not
    const fftess::PatchComparison c = fftess::comparePatch(patches[got.patch], &got, {}, reference);
    std::printf("patch %d: %s (%d primitives)", int(got.patch), fftess::toString(c.kind), c.capturePrimitives);
    for (fftess::PortBug bug : c.bugs) std::printf(", reproduced by %s", fftess::toString(bug));
    std::printf("\n");
    const bool expected = got.patch == 1 ? c.kind != fftess::DifferenceKind::Same && c.bugs.size() == 1 &&
                                               c.bugs[0] == fftess::PortBug::OuterFactorsRotated
                                         : c.kind == fftess::DifferenceKind::Same && c.bugs.empty();
    failures += expected ? 0 : 1;
  }
  return failures == 0 && compared == 3 ? 0 : 1;
}
