// --svg of compare and driver-check (docs/compare.md "The picture"): the first differing patches drawn in their
// domain, the reference's primitives and the capture's over each other, those only in one side highlighted, the
// points only in one side marked, a legend. compareSvg is a pure function; CompareSvg collects the panels while the
// comparison streams and writes the file all or nothing (AtomicFile).
#pragma once

#include "common.h"

#include "compare/compare.h"

#include <memory>
#include <string>
#include <vector>

namespace fftess::cli {

// One differing patch as drawn, in (u, v) domain coordinates.
struct ComparePanel {
  int64_t index = 0;
  int line = 0;      // of the patch in its batch file (0: none, e.g. random patches)
  DifferenceKind kind = DifferenceKind::Same;
  Domain domain = Domain::Quad;
  int arity = 3;                                  // vertices per primitive of the comparison (1: point lists)
  std::vector<CapturedVertex> reference, capture; // primitive after primitive (points when arity is 1)
  std::vector<char> onlyInReference, onlyInCapture; // per primitive: only in that side
  int onlyInReferenceCount = 0, onlyInCaptureCount = 0;
  std::vector<CapturedVertex> missingPoints, extraPoints; // distinct points only in the reference / the capture
};

// The picture: a heading (title and summary line), up to six panels in rows of three, the legend.
std::string compareSvg(const std::vector<ComparePanel>& panels, const std::string& title, const std::string& summary);

class CompareSvg {
public:
  static constexpr size_t kMaxPanels = 6;
  // path "": no picture (add and commit do nothing). Otherwise the path is checked now (UsageError naming --svg).
  CompareSvg(const std::string& path, const CompareOptions& options);
  ~CompareSvg();
  // A compared patch: the first kMaxPanels differing ones are kept, re-compared with every primitive listed.
  void add(int64_t index, int line, const Patch& patch, const CapturedPatch* got, const PatchComparison& c);
  // Draws and writes the file (std::runtime_error naming the path on I/O failure).
  void commit(const std::string& title, const CompareSummary& summary);

private:
  std::unique_ptr<AtomicFile> file_;
  CompareOptions options_;
  std::vector<ComparePanel> panels_;
};

} // namespace fftess::cli
