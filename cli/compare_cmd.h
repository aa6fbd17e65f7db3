// fftess compare (cli/compare.cpp): argument struct and registration. Exit 0 same, 1 differs, 2 bad input, 3 internal.
#pragma once

#include <CLI/CLI.hpp>

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

} // namespace fftess::cli
