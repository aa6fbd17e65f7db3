// The seeded random patches of `fftess gen` and `driver-check --random` (gl/random_patches.h: the generator and
// special values of the GPU oracle tests) as fftess patches and as a batch file, so that a random run can be kept
// and re-run anywhere (docs/compare.md, "Keepable inputs").
//
// A generated batch is one comment line naming the command that regenerates it ("# fftess gen --random N --seed S"),
// then one formatBatchLine per patch (tessellator/batch.h: hex factors): patch i is on line i + 2 (genLineOf).
// Header-only generator: works without the GL module (fftess_gl is not linked for this).
#pragma once

#include "common.h"

#include "tessellator/tessellator.h"

#include "gl/gl_capture.h" // oracle::Patch (types only)

#include <cstdint>
#include <functional>
#include <string>

namespace fftess::cli {

struct GenSpec {
  long random = 1000;  // random patches after the sweep
  uint64_t seed = 1;
  bool sweep = false;  // oracle::sweepPatches() first (6,348 patches)
};

// The oracle's patch as an fftess patch (hw stage, the factors' bits kept).
Patch fromOracle(const oracle::Patch& g);
oracle::Patch toOracle(const Patch& p); // a hw-stage patch (the stage is not carried)

// "fftess gen --random N --seed S" (+ " --sweep"): the command that writes these patches.
std::string genCommand(const GenSpec& spec);
// The first line of a generated batch: "# " + genCommand + "\n".
std::string genHeader(const GenSpec& spec);
// The line of a generated batch that holds patch 'index' (0-based): index + 2 (1-based lines, after the header).
int genLineOf(int64_t index);

// Calls emit(index, patch) for every patch of spec in order: the sweep (when set), then spec.random patches from
// oracle::Rng{spec.seed} (exactly oracle::generatePatches, without holding them all).
void forEachGenPatch(const GenSpec& spec, const std::function<void(int64_t, const Patch&)>& emit);

// A batch file written as it is produced, in bounded memory (AtomicFile: the path is checked on construction, before
// any work; the file appears whole at commit() or not at all). "-" is stdout.
class BatchFileWriter {
public:
  explicit BatchFileWriter(const std::string& path) : file_(path) {}
  void text(const std::string& s); // verbatim (a header: "# ...\n")
  void add(const Patch& p);        // formatBatchLine(p) + "\n"
  void commit();

private:
  AtomicFile file_;
  std::string pending_;
};

} // namespace fftess::cli
