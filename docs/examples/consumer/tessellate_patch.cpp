// Tessellates one patch with the installed emulator (fftess::tessellator) and prints it in the golden hex format,
// exactly as `fftess tessellate --format hex -e LINE` does (the ctest "install:consumer" compares the two).
#include <cstdio>
#include <string>

#include <fftess/tessellator/batch.h>
#include <fftess/tessellator/tessellator.h>

int main(int argc, char** argv) {
  const std::string line = argc > 1 ? argv[1] : "quad fractional_odd triangle_cw hw 3.5 2 5 4 3 3";
  fftess::Patch patch;
  fftess::BatchError err;
  if (!fftess::parseBatchLine(line, patch, err)) {
    std::fprintf(stderr, "%s\n", err.message.c_str());
    return 2;
  }
  fftess::Tessellator tess;
  const int points = tess.tessellate(patch);
  // The closed-form sizes (independent of the tessellation code) must match what was generated.
  const fftess::OutputCounts expected = fftess::outputCounts(patch);
  if (points != expected.points || int(tess.indices().size()) != expected.indices) {
    std::fprintf(stderr, "%d points, %d indices; outputCounts says %d, %d\n", points, int(tess.indices().size()),
                 expected.points, expected.indices);
    return 1;
  }
  std::string out;
  fftess::appendHexBlock(out, 0, patch, tess);
  std::fputs(out.c_str(), stdout);
  return 0;
}
