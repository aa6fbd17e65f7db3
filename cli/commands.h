// Subcommand registration. Each add* function adds its subcommand to the app and returns it; run* executes it after
// a successful parse and returns the exit status (errors: throws UsageError -> 2, anything else -> 3).
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace fftess::cli {

struct TessellateArgs {
  std::string input = "-";
  std::vector<std::string> patches; // -e LINE
  std::string format = "table";
  std::string output = "-";
  bool flushDenormals = false;
  bool keepGoing = false;
  int threads = 1; // --threads N (0: one per hardware thread)
};
CLI::App* addTessellate(CLI::App& app, TessellateArgs& a);
int runTessellate(const TessellateArgs& a);

struct ExplainArgs {
  std::string partitioning = "integer";
  std::string stage = "hw";
  std::vector<std::string> factors; // BIG SMALL
  bool whyPow2 = false;
  bool json = false;
  int maxBig = 64;
};
CLI::App* addExplain(CLI::App& app, ExplainArgs& a);
int runExplain(const ExplainArgs& a);

struct BenchArgs {
  std::vector<std::string> passThrough;
  std::string scene;                  // --scene FILE
  std::vector<std::string> overrides; // --set KEY=VALUE
  int cameras = 16;
  std::string seed = "1";
  int meshCameras = 1;
  int repeats = 3;
  std::string group;
  std::string markdown, json, svg;
  bool quiet = false;
};
CLI::App* addBench(CLI::App& app, BenchArgs& a);
int runBench(const BenchArgs& a, const char* argv0);

} // namespace fftess::cli
