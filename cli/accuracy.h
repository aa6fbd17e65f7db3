// fftess bench's table: what accuracy costs in time (cli/accuracy.cpp; docs/accuracy.md).
#pragma once

#include "verify/verify.h"

#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

struct BenchReportArgs {
  std::string scene;                  // --scene (default docs/examples/terrain.toml of the source tree)
  std::vector<std::string> overrides; // --set
  int cameras = 16;                   // --cameras: random cameras (seed --seed)
  uint64_t seed = 1;
  int meshCameras = 1;                // --mesh-cameras: cameras of the whole-mesh row (seconds each)
  std::string only;                   // --group: only this group's rows
  int repeats = 3;                    // --repeats: each edge-check camera timed as the fastest of this many runs
};

// "version" of bench's JSON report (docs/schema/bench.schema.json); bumped on any change of its schema.
// 2: the envelope ("version", "kind", "fftess_version" first); "verdict" is a key (a verify verdict, "reference",
//    "factors_compared", "no_inner_border", "inner_borders"), its words in "verdict_text"; sweep.result_cache_off a
//    key (as a sweep's result_cache.off_reason), its words in "result_cache_off_text".
constexpr int kBenchReportVersion = 2;

struct BenchRow {
  std::string group, name, what, error, verdict;
  std::string verdictKey; // verdict as a key (JSON "verdict")
  bool reference = false, compared = false;
  size_t cameras = 0;
  double msPerCamera = 0, usPerEdge = 0, relative = 0;
  int64_t findings = 0, gained = 0, lost = 0;
  vf::Stats stats;
  vf::WorkStats work; // summed over the row's cameras
  // The sweep shortcuts group: a whole sweep on one thread; what ran (vf::SweepResult) and the cache's size.
  bool sweep = false;
  bool visibleFirst = false, resultCache = false;
  std::string resultCacheOff;
  std::string resultCacheOffKey; // vf::SweepResult::resultCacheOffKey
  size_t resultCacheItems = 0, resultCacheBytes = 0;
};

struct BenchTable {
  std::string scene;
  int patches = 0;
  std::vector<vf::Camera> cameras;
  size_t meshCameras = 0;
  int repeats = 1;
  std::vector<BenchRow> rows;
};

// The groups of the table's rows, in the table's order ("checker", "domain formula", ..., "sweep shortcuts"): what
// --group takes, and what its help lists.
std::vector<std::string> benchGroups();

// Runs every row (single thread, each timed around checkScene / checkSceneMesh only). UsageError on a bad scene.
BenchTable runBenchTable(const BenchReportArgs& a);
std::string benchText(const BenchTable& t);
std::string benchMarkdown(const BenchTable& t);
std::string benchJson(const BenchTable& t); // the JSON report (docs/accuracy.md), dump(2) and a newline
std::string benchSvg(const BenchTable& t);

} // namespace fftess::cli
