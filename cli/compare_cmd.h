// fftess compare (cli/compare.cpp) and driver-check (cli/driver_check.cpp): arguments, registration, the report. Exit 0
// same, 1 differs, 2 bad input, 3 internal.
#pragma once

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "compare/compare.h"

#include <string>

namespace fftess::cli {

struct CompareArgs {
  std::string patches;
  std::string capture;
  std::string format = "auto";
  bool strictOrder = false;
  bool json = false;
  bool flushDenormals = false;
  int show = 20;
  int details = 4;
};
CLI::App* addCompare(CLI::App& app, CompareArgs& a);
int runCompare(const CompareArgs& a);

struct DriverCheckArgs {
  std::string patches; // empty: random
  long random = 1000;
  uint64_t seed = 1;
  bool hardware = false;
  bool strictOrder = false;
  bool flushDenormals = false;
  bool json = false;
  int show = 20;
};
// fftess driver-check (cli/driver_check.cpp): the local GL driver's tessellator through the comparison of compare.
CLI::App* addDriverCheck(CLI::App& app, DriverCheckArgs& a);
int runDriverCheck(const DriverCheckArgs& a);

// The report of compare and driver-check: per-patch lines for the first 'show' differing patches, the summary, the
// verdict; text or JSON (docs/compare.md). finish() writes it to stdout.
class CompareReporter {
public:
  CompareReporter(bool json, int show, bool strictOrder, std::string batch);
  void add(int64_t index, int line, const PatchComparison& c);
  void finish(const std::string& format, const std::string& header);
  const CompareSummary& summary() const { return sum_; }

private:
  bool json_, strict_;
  int show_, shown_ = 0;
  std::string batch_, text_;
  nlohmann::ordered_json listed_;
  CompareSummary sum_;
};

} // namespace fftess::cli
