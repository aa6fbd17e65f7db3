// The report of fftess compare and driver-check (cli/compare.cpp, cli/driver_check.cpp; docs/compare.md).
#pragma once

#include "commands.h"

#include "compare/compare.h"

#include <nlohmann/json.hpp>

#include <string>

namespace fftess::cli {

// The report of compare and driver-check: per-patch lines for the first 'show' differing patches, the summary, the
// verdict; text or JSON (docs/compare.md). finish() writes it to stdout.
class CompareReporter {
public:
  CompareReporter(bool json, int show, bool strictOrder, std::string batch);
  void add(int64_t index, int line, const PatchComparison& c);
  void finish(const std::string& format, const std::string& header);
  const CompareSummary& summary() const { return sum_; }
  // A top-level key of the JSON report (after "source"), e.g. driver-check's "port_bug".
  void addJsonField(const std::string& key, nlohmann::ordered_json value) { extra_[key] = std::move(value); }

private:
  bool json_, strict_;
  int show_, shown_ = 0;
  std::string batch_, text_;
  nlohmann::ordered_json listed_;
  nlohmann::ordered_json extra_ = nlohmann::ordered_json::object();
  CompareSummary sum_;
};

} // namespace fftess::cli
