// --sarif and --junit of compare and driver-check (docs/ci.md): every differing patch as a result (JUnit <failure>)
// at its line in the batch file (compare's PATCHES; driver-check's PATCHES or --write-batch file; none for patches
// read from stdin or generated without --write-batch: then only the patch index, as a logical location), its kind
// of difference as the rule, the port bug that reproduces it (if any) as the fix. JUnit: a case per differing patch
// and a case "patches" saying what was compared. The files are checked when this is built (before the work) and
// written together by commit().
#pragma once

#include "ci_report.h"
#include "common.h"

#include "compare/compare.h"

#include <memory>
#include <string>

namespace fftess::cli {

class CompareCi {
public:
  // command: "compare" or "driver-check"; batchFile: the file the results point at ("": none).
  CompareCi(const std::string& sarif, const std::string& junit, std::string command, std::string batchFile);
  ~CompareCi();
  void add(int64_t index, int line, const Patch& patch, const PatchComparison& c);
  // source: what was compared, in words (the batch, the capture or the driver). Writes the files (no-op without).
  void commit(const CompareSummary& summary, int status, const std::string& source);

private:
  std::unique_ptr<AtomicFile> sarif_, junit_;
  CiReport report_;
  std::string batchFile_;
};

} // namespace fftess::cli
