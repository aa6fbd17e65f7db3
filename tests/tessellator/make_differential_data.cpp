// Writes tests/tessellator/data/differential.hashes ONCE from the kernels before issue 11 (tests/tessellator/legacy):
// one line per chunk of differential_cases.h, NAME HASH. Also checks the live emulator against the same outputs
// (the differential test as it was), exit 1 on any difference. Deleted together with legacy/ right after its run.
#include <cstdio>
#include <cstring>
#include <vector>

#include "differential_cases.h"
#include "legacy/legacy.h"

using namespace fftess;

int main() {
  std::printf("# FNV-1a 64 over 32-bit words (tests/tessellator/differential_cases.h, OutputHash) of the outputs of the\n"
              "# tessellation kernels before issue 11 (tests/tessellator/legacy/, bit-exact with Microsoft's reference on\n"
              "# all golden data), one line per chunk of differential_cases.h: NAME HASH. Produced once on 2026-12-01 by\n"
              "# tests/tessellator/make_differential_data.cpp (g++ 12.2, Release -O3, -ffp-contract=off) from that code; both\n"
              "# were deleted in the next commit (git log --diff-filter=D -- tests/tessellator/legacy).\n");
  Tessellator t;
  std::vector<DomainPoint> pts;
  std::vector<int32_t> idx;
  long cases = 0, mismatches = 0;
  for (auto group : {testing::specialValueChunks, testing::plainFactorChunks, testing::equalFactorChunks,
                     testing::portableChunks}) {
    for (const testing::DifferentialChunk& chunk : group()) {
      testing::OutputHash legacyHash, liveHash;
      for (const testing::DifferentialCase& c : chunk.cases) {
        const int n = legacy::tessellate(c.patch, c.options, pts, idx);
        legacyHash.patch(n, pts, idx);
        const int m = t.tessellate(c.patch, c.options);
        liveHash.patch(m, t.points(), t.indices());
        const bool same = m == n && t.points().size() == pts.size() && t.indices().size() == idx.size() &&
                          (pts.empty() || std::memcmp(t.points().data(), pts.data(), pts.size() * 8) == 0) &&
                          (idx.empty() || std::memcmp(t.indices().data(), idx.data(), idx.size() * 4) == 0);
        mismatches += !same;
        ++cases;
      }
      std::printf("%s %016llx\n", chunk.name.c_str(), static_cast<unsigned long long>(legacyHash.h));
    }
  }
  std::fprintf(stderr, "make_differential_data: %ld patches, %ld differ from the live emulator\n", cases, mismatches);
  return mismatches == 0 ? 0 : 1;
}
