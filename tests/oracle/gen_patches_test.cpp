// `fftess gen` writes the oracle's own patches: its output, after the header line, is oracle::generatePatches (the
// generator of driver-check and of this folder's vs-emulator test, gl/random_patches.h) written with the oracle's own
// batch formatter (oracle::batchLine, gl/batch.cpp, independent of fftess's tessellator/batch.h).
//
//   test_oracle_gen_patches FFTESS        (no GL context needed; exit 0 same, 1 differs)
#include "random_patches.h"

#include <cstdio>
#include <string>
#include <vector>

using namespace fftess::oracle;

namespace {

// The lines of `FFTESS gen ARGS` (without their '\n').
std::vector<std::string> genLines(const std::string& fftess, const std::string& args) {
  std::vector<std::string> lines;
  FILE* p = popen(("'" + fftess + "' gen " + args).c_str(), "r");
  if (!p) return lines;
  std::string line;
  for (int c; (c = std::fgetc(p)) != EOF;) {
    if (c != '\n') {
      line += static_cast<char>(c);
      continue;
    }
    lines.push_back(line);
    line.clear();
  }
  if (pclose(p) != 0 || !line.empty()) lines.clear(); // a failed run, or no '\n' at the end: nothing to accept
  return lines;
}

bool check(const std::string& fftess, long total, uint64_t seed, bool sweep) {
  const std::string args =
      "--random " + std::to_string(total) + " --seed " + std::to_string(seed) + (sweep ? " --sweep" : "");
  const std::vector<std::string> lines = genLines(fftess, args);
  const std::vector<Patch> patches = generatePatches(total, seed, sweep);
  if (lines.size() != patches.size() + 1 || lines[0] != "# fftess gen " + args) {
    std::printf("gen %s: %zu lines (expected the header and %zu patches)\n", args.c_str(), lines.size(),
                patches.size());
    return false;
  }
  for (size_t i = 0; i < patches.size(); ++i)
    if (lines[i + 1] != batchLine(patches[i])) {
      std::printf("gen %s: line %zu is '%s', the oracle's patch %zu is '%s'\n", args.c_str(), i + 2,
                  lines[i + 1].c_str(), i, batchLine(patches[i]).c_str());
      return false;
    }
  std::printf("gen %s: %zu patches, each the oracle's\n", args.c_str(), patches.size());
  return true;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: test_oracle_gen_patches FFTESS\n");
    return 2;
  }
  const bool ok = check(argv[1], 3000, 20261122, true) && check(argv[1], 2000, 7, false) && check(argv[1], 0, 1, false);
  return ok ? 0 : 1;
}
