// Subcommand registration: each subcommand's arguments, and its add* function, which adds the subcommand to the app
// and returns it (defined with the subcommand, the only files that include CLI11); run* executes it after a successful
// parse and returns the exit status (errors: throws UsageError -> 2, anything else -> 3). No heavy header: main.cpp
// and every command include this.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace CLI {
class App;
}

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

// ---- check, sweep, merge (cli/check.cpp, cli/sweep.cpp, cli/merge.cpp): the crack checker people run (verify/ does the
// checking; these turn its reports into text, JSON, SVG and an exit status). The scene options both share:
// cli/scene_options.h.
struct SceneArgs {
  std::string scene;
  std::vector<std::string> overrides; // --set KEY=VALUE
  std::string eye, target;            // --eye X,Y,Z / --target X,Y,Z: shorthands for --set camera.eye=[X,Y,Z]
  std::string kernel = "epick";
  std::string flushDenormals = "auto"; // --flush-denormals[=on|off|auto]: bare = on
  std::string json, svg;
  bool quiet = false;
  bool failOnTJunctions = false;
  bool gpuHardware = false; // --gpu-hardware: the GPU LOD path on a GPU's EGL device instead of llvmpipe
  bool offscreen = false;   // --offscreen: findings outside the view frustum count too (vf::CheckOptions::countOffScreen)
  std::string cameras;      // --cameras FILE: cameras from a CSV / JSON file (cli/camera_file.h)
  std::string gltf;         // --gltf FILE: the checked camera in 3D (check: its camera; sweep: the worst camera's)
  std::string view;         // check --view FILE.svg: what the camera sees (cli/report_view.h); "" for sweep
  std::string gpuFloat = "off"; // --gpu-float off|conformant (vf::CheckOptions::gpuFloat)
  std::string sarif, junit; // --sarif FILE / --junit FILE: the findings for CI (cli/ci_scene.h, docs/ci.md)
};

struct CheckArgs : SceneArgs {
  int pathCamera = -1; // --path-camera N: the scene path's camera N instead of [camera]
  bool pathCameraGiven = false; // --path-camera was given (any value, negative ones refused)
  int show = 3;        // example edges printed per cause (the widest gaps)
  bool mesh = false;   // also run the whole-mesh check and compare
  int cameraIndex = -1; // --camera-index N: camera N of --cameras FILE
  bool cameraIndexGiven = false;
};

struct SweepArgs : SceneArgs {
  int orbit = -1, flyover = -1, random = -1; // -1: not given; given counts must be >= 1
  bool orbitGiven = false, flyoverGiven = false, randomGiven = false; // the option was given (-1 included: refused)
  std::string seed = "1";                     // --seed: a decimal 0 .. 2^64-1, checked by runSweep
  int threads = 0;
  std::string label;   // --label TEXT: name printed in the summary (default: the scene name)
  std::string shard;   // --shard K/N: only the cameras i with i % N == K - 1 (global indices kept)
  // The sweep shortcuts (docs/verify.md, "Sweep shortcuts"), on unless turned off: --no-visible-first (also off with
  // --offscreen: vf::CheckOptions::visibleFirst), --no-result-cache (vf::SweepOptions::resultCache).
  bool noVisibleFirst = false;
  bool noResultCache = false;
  int show = 20;       // --show N: causes printed in the cause table (all are in --json)
};

struct MergeArgs {
  std::vector<std::string> inputs; // shards' JSON reports
  std::string json;                // --json FILE: the merged report ("-": stdout)
  bool quiet = false;
  bool failOnTJunctions = false;
};

CLI::App* addCheck(CLI::App& app, CheckArgs& a);
CLI::App* addSweep(CLI::App& app, SweepArgs& a);
int runCheck(const CheckArgs& a);
int runSweep(const SweepArgs& a);
CLI::App* addMerge(CLI::App& app, MergeArgs& a);
int runMerge(const MergeArgs& a);

// ---- layout (cli/layout.cpp): a scene's patches written as a layout.kind = "patches" file.
struct LayoutArgs {
  SceneArgs scene;  // SCENE, --set, --eye, --target, -q (the other scene options are not registered)
  std::string obj;  // --obj FILE
  std::string csv;  // --csv FILE
};
CLI::App* addLayout(CLI::App& app, LayoutArgs& a);
int runLayout(const LayoutArgs& a);

// ---- prove (cli/prove.cpp): a scene proven watertight for every camera of a region (verify/prove.h). Exit 0 PROVED,
// 1 COUNTEREXAMPLE or UNDECIDED, 2 bad usage or scene, 3 internal.
struct ProveArgs {
  SceneArgs scene;           // SCENE, --set, --json, -q (the other scene options are not registered)
  std::string eyeBox;        // --eye-box X0,Y0,Z0,X1,Y1,Z1 ("": the default region's)
  std::string targetBox;     // --target-box X0,Y0,Z0,X1,Y1,Z1
  int maxDepth = 24;         // vf::ProveOptions::maxDepth
  int64_t maxRegions = 200000;
  int threads = 0;           // 0: all cores
  int show = 20;             // counterexample finding lines and undecided regions printed
};
CLI::App* addProve(CLI::App& app, ProveArgs& a);
int runProve(const ProveArgs& a);

// ---- compare, driver-check (cli/compare.cpp, cli/driver_check.cpp; their report: cli/compare_report.h). Exit 0
// same, 1 differs, 2 bad input, 3 internal.
struct CompareArgs {
  std::string patches;
  std::string capture;
  std::string format = "auto";
  bool strictOrder = false;
  bool json = false;
  bool flushDenormals = false;
  int show = 20;
  int details = 4;
  std::string svg; // --svg FILE: the first differing patches drawn, reference over capture
  std::string sarif, junit; // --sarif FILE / --junit FILE: every differing patch for CI (cli/ci_compare.h)
  std::string* jsonOut = nullptr; // with json: the report goes here instead of stdout (cli/report_api.h)
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
  std::string api = "gl";  // --api gl|vulkan
  std::string portBug;     // --port-bug NAME: run the driver as a port with that bug would (the bug must be named)
  std::string writeBatch;  // --write-batch FILE: the patches checked, as a batch file
  std::string svg;         // --svg FILE, as compare's
  uint64_t permuteCapture = 0; // --permute-capture SEED (test): the driver's records permuted before they are grouped
  std::string sarif, junit;    // --sarif FILE / --junit FILE, as compare's
};
// fftess driver-check (cli/driver_check.cpp): the local GL driver's tessellator through the comparison of compare.
CLI::App* addDriverCheck(CLI::App& app, DriverCheckArgs& a);
int runDriverCheck(const DriverCheckArgs& a);

// fftess gen (cli/gen.cpp): seeded random patches (driver-check's generator, gl/random_patches.h) as a batch file.
struct GenArgs {
  long random = 1000;
  uint64_t seed = 1;
  bool sweep = false;   // the systematic sweep first
  std::string output;   // -o FILE (default stdout)
};
CLI::App* addGen(CLI::App& app, GenArgs& a);
int runGen(const GenArgs& a);


} // namespace fftess::cli
