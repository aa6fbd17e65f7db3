// The report of fftess compare and driver-check (cli/compare.cpp, cli/driver_check.cpp; docs/compare.md).
#pragma once

#include "commands.h"

#include "compare/compare.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fftess::cli {

// "version" of the compare and driver-check JSON reports (docs/compare.md); bumped on any change of their schema.
// 1: the first versioned schema: "version", "kind", "fftess_version", "batch" or "generated_by", per listed patch
//    "batch_line".
// 2: the envelope of every report kind (docs/schema): driver-check's kind is "driver_check" (version 1 wrote
//    "driver-check"); the header line moved from "source" to "source_text" (words, not a key).
constexpr int kCompareReportVersion = 2;

// The report of compare and driver-check: per-patch lines for the first 'show' differing patches, the summary, the
// verdict; text or JSON (docs/compare.md). finish() writes it to stdout.
// batch: the batch file's name; kind: the JSON "kind" ("compare", "driver_check").
class CompareReporter {
public:
  CompareReporter(bool asJson, int show, bool strictOrder, std::string batch, const char* kind = "compare");
  // The batch is not a file but the command that writes it (`fftess gen ...`): patches are named "(COMMAND, line N)"
  // and the JSON says "generated_by" instead of "batch".
  void setGenerated() { generated_ = true; }
  // index: 0-based patch number; line: its line in the batch; patch: what was compared (a differing one is printed
  // as its batch line, so it can be re-run alone).
  void add(int64_t index, int line, const Patch& patch, const PatchComparison& c);
  void finish(const std::string& format, const std::string& header);
  const CompareSummary& summary() const { return sum_; }
  // The JSON report into *out instead of stdout (null: stdout).
  void setJsonSink(std::string* out) { sink_ = out; }
  // A top-level key of the JSON report (after "source_text"), e.g. driver-check's "port_bug".
  void addJsonField(const std::string& key, nlohmann::ordered_json value) { extra_[key] = std::move(value); }

private:
  bool json_, strict_, generated_ = false;
  const char* kind_;
  int show_, shown_ = 0;
  std::string batch_, text_;
  nlohmann::ordered_json listed_;
  nlohmann::ordered_json extra_ = nlohmann::ordered_json::object();
  CompareSummary sum_;
  std::string* sink_ = nullptr;
};

} // namespace fftess::cli
