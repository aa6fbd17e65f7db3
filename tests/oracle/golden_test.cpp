// Validates the GL oracle harness against the reference outputs in shared/golden (the hw-stage files): every patch
// without a denormal factor must agree exactly (points, primitives as coordinates, indices). Patches with a denormal
// factor are counted apart: llvmpipe flushes denormal factors to zero, so a denormal outer factor culls the patch
// there, while the reference tessellates it; anything else is a failure. Needs no emulator.
// Only the full .out files are used: the stored hashes in the .hashes files do not follow the recipe in
// golden/README.md (a culled patch's block hashes to none of them), so they cannot check anything yet.
// Columns: compared/agree = patches without denormal factors and how many agree; primitive = of those agreeing,
// patches where GL drew primitives (triangles, isoline lines); dup-prim = of those, patches with duplicate points
// (where the index comparison says more than the coordinate one); denormal/agree/GL-culled = patches with a
// denormal factor, how many agree anyway, how many llvmpipe culled instead.
//
//   test_oracle_golden [GOLDEN_DIR]      (default ../shared/golden)
#include "oracle_test_util.h"

#include <chrono>
#include <cstdio>
#include <fstream>
#include <iterator>

using namespace fftess::oracle;

int main(int argc, char** argv) {
  const char* name = "oracle_golden";
  const std::string dir = argc > 1 ? argv[1] : "../shared/golden";
  auto oracle = createOracleOrExit(name);
  int failures = 0;
  std::printf("%-8s %8s %9s %9s %10s %9s %9s %9s %9s %10s %7s\n", "file", "patches", "compared", "agree", "primitive",
              "dup-prim", "denormal", "agree", "GL-culled", "points", "seconds");
  for (const char* domain : {"quad", "tri", "isoline"}) {
    const std::string base = dir + "/" + domain + "-hw";
    std::ifstream in(base + ".in");
    if (!in) unavailable(name, "golden data missing: cannot read " + base + ".in");
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<BatchLine> lines;
    std::string error;
    if (!parseBatch(text, lines, error)) {
      std::fprintf(stderr, "%s.in: %s\n", base.c_str(), error.c_str());
      return 1;
    }
    std::vector<Expected> expected;
    if (!readOutFile(base + ".out", expected, error)) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
    if (expected.size() != lines.size()) {
      std::fprintf(stderr, "%s: %zu patches in .in, %zu in .out\n", base.c_str(), lines.size(), expected.size());
      return 1;
    }
    std::vector<Patch> patches;
    for (const BatchLine& b : lines) patches.push_back(b.patch);
    std::vector<Result> results;
    const auto t0 = std::chrono::steady_clock::now();
    if (!oracle->run(patches, results, error)) {
      std::fprintf(stderr, "%s: oracle failed: %s\n", base.c_str(), error.c_str());
      return 1;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    int compared = 0, agree = 0, withPrimitives = 0, duplicates = 0, denormal = 0, denormalAgree = 0, denormalCulled = 0;
    long long points = 0;
    for (size_t i = 0; i < patches.size(); ++i) {
      const Verdict v = compare(patches[i], results[i], expected[i]);
      points += results[i].pointCount();
      if (hasDenormalFactor(patches[i])) {
        ++denormal;
        if (v.all()) {
          ++denormalAgree;
        } else if (results[i].pointCount() == 0 && hasDenormalOuterFactor(patches[i])) {
          ++denormalCulled;
        } else {
          ++failures;
          std::fprintf(stderr, "%s.in line %d (patch %zu, denormal factor, neither equal nor culled by GL): %s\n  %s\n",
                       base.c_str(), lines[i].lineNumber, i, batchLine(patches[i]).c_str(), v.firstDifference.c_str());
        }
        continue;
      }
      ++compared;
      if (v.all()) {
        ++agree;
        if (hasGlPrimitives(patches[i]) && results[i].pointCount() > 0) {
          ++withPrimitives;
          duplicates += hasDuplicatePoints(results[i]);
        }
      } else {
        ++failures;
        std::fprintf(stderr, "%s.in line %d (patch %zu) differs: %s\n  %s\n", base.c_str(), lines[i].lineNumber, i,
                     batchLine(patches[i]).c_str(), v.firstDifference.c_str());
      }
    }
    std::printf("%-8s %8zu %9d %9d %10d %9d %9d %9d %9d %10lld %7.2f\n", domain, patches.size(), compared, agree,
                withPrimitives, duplicates, denormal, denormalAgree, denormalCulled, points, seconds);
  }
  if (failures) {
    std::printf("oracle_golden: %d patch(es) differ from the reference\n", failures);
    return 1;
  }
  std::printf("oracle_golden: every comparable patch agrees bit for bit (points, primitives, indices)\n");
  return 0;
}
