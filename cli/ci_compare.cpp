// --sarif / --junit of compare and driver-check (ci_compare.h).
#include "ci_compare.h"
#include "report_junit.h"
#include "report_sarif.h"

#include "tessellator/batch.h"

namespace fftess::cli {

namespace {

// What removes a difference of this kind when no typical port bug reproduces it.
const char* kindFix(DifferenceKind k) {
  switch (k) {
  case DifferenceKind::CulledInCapture:
    return "the port draws nothing where the reference tessellates: a patch is culled only by a factor <= 0 or NaN "
           "(check the port's factor processing)";
  case DifferenceKind::CulledInReference:
    return "the port draws a patch the reference culls: discard a patch whose outer factor is <= 0 or NaN";
  case DifferenceKind::PointsDiffer:
    return "the port places points differently: compare its 16.16 point placement with the reference's step by step "
           "(fftess tessellate on the patch's batch line; docs/compare.md)";
  case DifferenceKind::Multiplicity:
    return "the port emits points or primitives a different number of times: check its primitive generation";
  case DifferenceKind::WindingOnly: return "the port winds triangles the other way: check its output topology (cw / ccw)";
  case DifferenceKind::PrimitivesDiffer: return "the same points joined into other lines or points: check the port's topology";
  case DifferenceKind::OrderDiffers:
    return "the same primitives in another order (--strict-order): emit them in the reference's order";
  case DifferenceKind::TriangulationDiffers:
    return "the same points joined into other triangles: check the port's ring stitching (docs/compare.md)";
  case DifferenceKind::Rotated:
    return "triangles start at another vertex (--strict-order): start each at the reference's first vertex";
  default: return "";
  }
}

std::unique_ptr<AtomicFile> ciFile(const char* option, const std::string& path) {
  if (path.empty()) return nullptr;
  if (path == "-") throw UsageError(std::string(option) + " -: stdout carries the report; give a file");
  try {
    return std::make_unique<AtomicFile>(path);
  } catch (const UsageError& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
}

} // namespace

CompareCi::CompareCi(const std::string& sarif, const std::string& junit, std::string command, std::string batchFile)
    : sarif_(ciFile("--sarif", sarif)), junit_(ciFile("--junit", junit)), batchFile_(std::move(batchFile)) {
  report_.command = std::move(command);
}

CompareCi::~CompareCi() = default;

void CompareCi::add(int64_t index, int line, const Patch& patch, const PatchComparison& c) {
  if ((!sarif_ && !junit_) || c.kind == DifferenceKind::Same) return;
  CiResult x;
  x.kind = "difference";
  x.rule = toString(c.kind);
  x.level = "error";
  x.where = "patch " + std::to_string(index);
  x.message = std::string(toString(c.kind)) + ": " + std::to_string(c.referencePrimitives) + " reference " +
              (c.verticesPerPrimitive == 1 ? "points" : "primitives") + ", " + std::to_string(c.capturePrimitives) +
              " in the capture; " + std::to_string(c.missingPoints) + " reference points missing, " +
              std::to_string(c.extraPoints) + " points the reference lacks; batch line: " + formatBatchLine(patch);
  x.fix = kindFix(c.kind);
  nlohmann::ordered_json bugs = nlohmann::ordered_json::array();
  for (PortBug b : c.bugs) bugs.push_back(toString(b));
  if (!c.bugs.empty()) {
    x.message += "; reproduced by " + std::string(toString(c.bugs.front())) + ": " + describe(c.bugs.front());
    x.fix = std::string("fix the port's ") + stepOf(c.bugs.front()) + " (" + describe(c.bugs.front()) + ")";
  }
  if (!batchFile_.empty()) {
    x.file = batchFile_;
    x.line = line;
    x.lineWhy = "the patch's batch line";
  }
  x.logical = {{"patch " + std::to_string(index), "patch[" + std::to_string(index) + "]", "object"}};
  x.properties = {{"patch", index}, {"batch_line", formatBatchLine(patch)}, {"line", line}, {"bugs", bugs}};
  report_.cases.push_back(CiCase{"patch " + std::to_string(index) + " (" + (batchFile_.empty() ? "line " : batchFile_ + ":") +
                                     std::to_string(line) + ")",
                                 {report_.results.size()}, "", ""});
  report_.results.push_back(std::move(x));
}

void CompareCi::commit(const CompareSummary& s, int status, const std::string& source) {
  if (!sarif_ && !junit_) return;
  report_.suite = "fftess " + report_.command + " " + source;
  report_.exitStatus = status;
  const std::string what = std::to_string(s.patches) + " patches compared (" + std::to_string(s.pointsCompared) +
                           " reference vertices): " + std::to_string(s.same) + " same, " +
                           std::to_string(s.differing) + " differ";
  // Nothing compared is not a clean comparison: an <error>, never a passing case.
  CiCase all{"patches: " + what, {}, "", what};
  if (s.patches == 0) {
    CiResult x;
    x.kind = "nothing_compared", x.rule = "nothing compared: the batch holds no patch", x.level = "error";
    x.outcome = CiOutcome::Error, x.message = "no patch was compared: not a clean comparison";
    x.fix = "give a batch file with patches (fftess gen writes one)", x.file = batchFile_;
    all.results.push_back(report_.results.size());
    report_.results.push_back(std::move(x));
  }
  report_.cases.push_back(all);
  report_.notes.push_back({"note", source + ": " + what});
  report_.properties = {{"patches", s.patches}, {"same", s.same}, {"differing", s.differing},
                        {"points_compared", s.pointsCompared}, {"source", source}};
  if (sarif_) sarif_->buffer() = sarifText(report_);
  if (junit_) junit_->buffer() = junitText(report_);
  AtomicFile* files[2];
  size_t n = 0;
  if (sarif_) files[n++] = sarif_.get();
  if (junit_) files[n++] = junit_.get();
  commitAll(files, n);
}

} // namespace fftess::cli
