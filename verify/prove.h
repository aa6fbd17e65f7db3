// fftess verify: proofs over regions of cameras (fftess prove; docs/verify.md, "Proofs"). A sweep checks sampled
// cameras; proveScene decides a whole region: every camera whose eye lies in a box and whose target lies in another
// (the scene camera's up, fov, near, far, viewport and convention), for the scene's built-in LOD scheme evaluated with
// lod/lod_bound.h under FloatModel::Conformant (every float lod/'s C++ build or a conformant GPU may produce).
//
// Branch and bound: a region is decided when, for every camera in it, every shared edge pair whose patches may be on
// screen matches vertex for vertex and no patch that may be on screen is culled or discarded; otherwise it is split
// in two along its widest coordinate, down to ProveOptions::maxDepth. Each region's cameras are also sampled (its
// centre and the "simplest" floats in it, where degenerate cases such as w = 0 at an edge midpoint live): a sampled
// camera whose checkScene has an on-screen finding is a counterexample. Findings are reports: the cli turns a
// ProveReport into an exit status.
#pragma once

#include "verify/check.h"
#include "verify/scene.h"
#include "verify/terrain.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

namespace fftess::verify {

// A box of cameras: eye in [eyeLo, eyeHi], target in [targetLo, targetHi] (per component lo <= hi; a point when
// lo == hi). The other camera parameters are the scene camera's.
struct CameraRegion {
  glm::vec3 eyeLo{0.0f}, eyeHi{0.0f};
  glm::vec3 targetLo{0.0f}, targetHi{0.0f};
};

// The options of a proof. Each field's default is its initialiser; the defaults are what `fftess prove` runs.
struct ProveOptions {
  // The region; regionGiven false: defaultRegion(terrain).
  CameraRegion region{};
  bool regionGiven = false;
  // A region is split at most this many times on the way from the root (each split halves one coordinate's range).
  int maxDepth = 24;
  // Regions evaluated in all (the root counts) before the proof stops; what is left open is reported undecided.
  int64_t maxRegions = 200000;
  // Runs of one patch pair's joint evaluation (BoundContext::forEachPath's maxPaths) before that pair is undecided.
  int maxPaths = 4096;
  // Cameras sampled per region for counterexamples (the centre first, then the simplest floats of the region).
  int samplesPerRegion = 2;
  // Threads (0: hardware concurrency).
  int threads = 0;
  // The kernel a sampled camera's check classifies with.
  Kernel kernel = Kernel::Epick;
  // Undecided regions kept in ProveReport::undecided (all are counted).
  size_t maxUndecidedListed = 20;
  // Polled between regions: when it becomes true the proof stops; what is open is undecided.
  const std::atomic<bool>* cancel = nullptr;
};

// Precedence: Counterexample, Undecided, InvalidCameras, NothingOnScreen, Proved (the first that holds).
enum class ProveVerdict : uint8_t {
  Proved,          // every camera of the region is valid, sees some shared edge on screen (some sub-regions may see
                   // none: ProveStats::volumeNothingOnScreen), every one matches and no patch is lost on screen
  Counterexample,  // a camera of the region whose check has an on-screen finding (ProveReport::counterexample)
  Undecided,       // regions left open (ProveReport::undecided); never Proved while any remain
  InvalidCameras,  // the valid part decided watertight, but the region holds cameras check refuses (eye == target,
                   // the view direction parallel to up, a direction float's lookAt cannot normalise): the regions
                   // that hold them are split down to ProveOptions::maxDepth and listed (ProveReport::invalid)
  NothingOnScreen, // decided, but no camera of the region sees a shared edge on screen: nothing was checked
};

// One region the proof could not decide, and why (the first reason met, e.g. "patch 12 may be culled while on
// screen", "pair 40 (patch 3 Ueq1 / patch 4 Ueq0): factors 7.9999..8.0001 round to different tessellations",
// "maximum depth").
struct UndecidedRegion {
  CameraRegion region;
  int depth = 0;
  std::string why;
};

// What the proof counted.
struct ProveStats {
  int64_t regions = 0;          // regions evaluated (root included)
  int64_t regionsProved = 0;    // leaves decided watertight
  int64_t regionsUndecided = 0; // leaves left open
  int64_t regionsInvalid = 0;   // leaves that may hold cameras check refuses (never evaluated, never proved)
  int64_t regionsNothingOnScreen = 0; // proved leaves from which no camera sees a shared edge on screen
  // The fractions of the root region's volume (over its coordinates of non-zero width; a point region is 1) that the
  // leaves of each kind cover; they add up to 1 when the proof ran to its end (open regions count as undecided).
  double volumeProved = 0, volumeUndecided = 0, volumeInvalid = 0, volumeNothingOnScreen = 0;
  int maxDepthReached = 0;
  int64_t pairsByTrace = 0;     // pair decisions where both sides compute the same factor (same trace) and the seam
                                // is proven identical (verify/seam_proof.h): equal for every camera of the region
  int64_t pairsByValue = 0;     // pair decisions from the factors' sets: every combination matches
  int64_t pairsOffScreen = 0;   // pair decisions skipped: both patches off screen for every camera of the region
  int64_t patchesOffScreen = 0; // patch decisions: off screen for every camera of the region
  int64_t lodPaths = 0;         // joint evaluations run (BoundContext::forEachPath runs)
  int64_t camerasChecked = 0;   // sampled cameras checked for counterexamples
  double seconds = 0;
};

struct ProveReport {
  std::string error;            // non-empty: nothing was proven (e.g. the scene's LOD is a user shader, geomorph)
  ProveVerdict verdict = ProveVerdict::Undecided;
  CameraRegion region;          // the root region proven
  bool regionDefault = false;   // it is defaultRegion's
  // Counterexample: the camera (eye, target and the scene camera's other parameters) and its check's report.
  Camera counterexample{};
  Report counterexampleReport;
  std::vector<UndecidedRegion> undecided; // the first maxUndecidedListed (stats.regionsUndecided counts all)
  std::vector<UndecidedRegion> invalid;   // the first maxUndecidedListed that hold invalid cameras, why: which kind
  // How the pairs were proven, per pair of the layout (static layouts): "trace" / "value" / "off_screen" counts
  // are in stats; these say which edges were proven which way in the last (finest) region that decided them.
  ProveStats stats;
};

// The default region: the scene camera's eye and target, each moved by up to 2^-12 of the terrain extent's larger side
// in every coordinate (rings_small.toml: +-0.0625 around eye (10, 25, -70) and target (0, 0, 0)), a box of cameras
// the interval evaluation decides in seconds. Whole-terrain regions are given explicitly (--eye-box, --target-box);
// docs/verify.md, "Proofs", says what decides how wide a region can be. Stated in the report
// (ProveReport::regionDefault).
CameraRegion defaultRegion(const Terrain& terrain);

// Proves or refutes the terrain watertight for every camera of the region. terrain: built; static layouts
// (layout.kind other than "quadtree"); the scene's LOD a built-in scheme evaluated on the CPU (not lod.shader, not
// lod.evaluate = "gpu", not geomorph); no camera-dependent domain (displacement.mip = "none"). Otherwise
// ProveReport::error says which. A worker thread the system will not start stops the others and throws
// std::runtime_error ("could not start thread K of N: ...", base/threads.h).
ProveReport proveScene(const Terrain& terrain, const ProveOptions& options = {});

const char* toString(ProveVerdict v); // "PROVED", "COUNTEREXAMPLE", "UNDECIDED", "INVALID_CAMERAS", "NOTHING_ON_SCREEN"

// Whether a region may hold a camera that check refuses (validateCamera): eye == target, a view direction target - eye
// parallel to up, or one within 2^-30 (relatively) of either, where float's lookAt cannot normalise. Decided in double
// over the box of directions [targetLo - eyeHi, targetHi - eyeLo]. Empty: none; else which kind.
std::string regionInvalidCameras(const CameraRegion& region, const glm::vec3& up);

} // namespace fftess::verify
