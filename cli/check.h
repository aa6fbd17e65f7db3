// fftess check / fftess sweep: the crack checker people run (verify/ does the checking; this turns its reports into
// text, JSON, SVG and an exit status).
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fftess::cli {

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
};

struct CheckArgs : SceneArgs {
  int pathCamera = -1; // --path-camera N: the scene path's camera N instead of [camera]
  bool pathCameraGiven = false; // --path-camera was given (any value, negative ones refused)
  int show = 20;       // finding lines printed
  bool mesh = false;   // also run the whole-mesh check and compare
};

struct SweepArgs : SceneArgs {
  int orbit = -1, flyover = -1, random = -1; // -1: not given; given counts must be >= 1
  bool orbitGiven = false, flyoverGiven = false, randomGiven = false; // the option was given (-1 included: refused)
  std::string seed = "1";                     // --seed: a decimal 0 .. 2^64-1, checked by runSweep
  int threads = 0;
  std::string label;   // --label TEXT: name printed in the summary (default: the scene name)
  std::string shard;   // --shard K/N: only the cameras i with i % N == K - 1 (global indices kept)
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

} // namespace fftess::cli
