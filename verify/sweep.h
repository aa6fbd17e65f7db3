// fftess verify, stage 8: the sweep. Many cameras (camera.h) checked against one prepared terrain on worker
// threads, each camera by checkScene (check.h); per camera a summary (CameraResult), over all a total (SweepResult).
// The verdict of the total is report.h's.
#pragma once

#include "verify/check.h"
#include "verify/scene.h"
#include "verify/terrain.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace fftess::verify {

// One camera of a sweep, summarised (SweepResult::cameras, SweepOptions::onCamera).
struct CameraResult {
  size_t cameraIndex = 0;
  bool done = false;             // false: skipped because of cancel, or invalid (error set)
  std::string error;             // the camera could not be checked (Report::error); done is false
  Stats stats;
  bool hasFinding = false;
  // The finding with the largest gap (first crack or T-junction if no gap) among the findings that count: the
  // on-screen ones by their onScreenGapWorld, or with CheckOptions::countOffScreen all of them by gapWorld.
  Finding worst;
  bool hasHole = false;
  Hole firstHole;                // the first hole in layout order
  bool hasUndecided = false;
  Hole firstUndecided;           // the first undecided patch (Report::undecided) in layout order
  bool hasGpuFloat = false;
  GpuFloatFinding firstGpuFloat; // CheckOptions::gpuFloat: the first GPU float finding (Report::gpuFloat)
};

// How a sweep runs (threads, progress, cancel, what it keeps). Each field's default is its initialiser.
struct SweepOptions {
  int threads = 0;               // 0: std::thread::hardware_concurrency(); never more than the cameras
  // Called after each camera from a worker thread (serialised by the driver): cameras done, cameras total.
  std::function<void(size_t done, size_t total)> progress;
  const std::atomic<bool>* cancel = nullptr; // set to true to stop; cameras not started are skipped
  bool keepReports = false;      // keep every camera's full report (else only its stats and first finding)
  // Called once per camera checked, with the camera's index into `cameras` and its full report (findings as
  // CheckOptions::maxFindings keeps them; Report::error set if the camera was invalid), before `progress` for that
  // camera. Thread-safety: called from worker threads, but never concurrently: sweep serialises it (with
  // `progress`) under one lock, so the callback needs no locking of its own. Order: the order cameras finish,
  // which with threads > 1 is not camera order; order-sensitive callers key their results by cameraIndex.
  // Cameras skipped because of cancel are not reported. The report is only valid during the call. Must not throw
  // (an exception on a worker thread ends the process).
  std::function<void(size_t cameraIndex, const Report& report)> onReport;
  // Called right after onReport for the same camera, under the same lock, with the camera's summary (what
  // SweepResult::cameras keeps). Same rules as onReport.
  std::function<void(const CameraResult& camera)> onCamera;
  // Keep one CameraResult per camera in SweepResult::cameras (default). false: SweepResult::cameras stays empty and
  // the sweep's memory does not grow with the camera count (the aggregates are kept; onCamera sees each camera).
  bool keepCameras = true;
  // The sweep-wide result cache (docs/verify.md, "Sweep shortcuts"; result_cache.h): what one camera proved about a
  // shared edge (a match for two factor bits; the edge's seam proof) is reused by every later camera, on every
  // thread. Off by itself (SweepResult::resultCacheOff says why) when the scene calls for a camera-dependent effect
  // (cameraDependentEffects), with CheckOptions::keepMatches (a cached match has no finding to keep), and for the
  // pairs of the fault-injection hook's patch (they always see the perturbed computation).
  bool resultCache = true;
  size_t resultCacheSlots = size_t(1) << 18; // its bound: 16 bytes per slot (4 MiB), allocated once per sweep
};

// The effects of a scene that make a shared edge's check depend on the camera beyond its two factors, each as the
// scene key that asks for it and why ("lod.scheme = \"geomorph\": vertices morph by the camera's distance"); empty:
// none. Each effect the scene format offers declares here whether it is camera-dependent.
std::vector<std::string> cameraDependentEffects(const Scene& scene);

// The result of a sweep: the totals over the cameras checked, and what SweepOptions asked to keep.
struct SweepResult {
  std::vector<CameraResult> cameras; // one per input camera, in input order (empty unless SweepOptions::keepCameras)
  std::vector<Report> reports;       // keepReports: one per camera (empty reports for skipped cameras)
  Stats total;                       // summed over cameras done; worst gaps are maxima
  WorkStats work;                    // summed over cameras done (the terrain's own work is terrain.stats())
  size_t camerasDone = 0;            // cameras checked
  size_t camerasInvalid = 0;         // cameras that could not be checked (CameraResult::error)
  size_t camerasNothingChecked = 0;  // cameras done that classified no shared edge (everything culled, say)
  size_t camerasUndecided = 0;       // cameras done with Stats::undecided > 0 (not clean)
  size_t camerasGpuFloat = 0;        // cameras done with Stats::gpuFloatFindings > 0 (CheckOptions::gpuFloat)
  bool cancelled = false;
  // What the shortcuts did (docs/verify.md, "Sweep shortcuts"): visibleFirst when every camera ran visible first;
  // the result cache's state (resultCacheOff: empty when it was on, else why not) and, when on, its size.
  bool visibleFirst = false;
  bool resultCache = false;
  std::string resultCacheOff;
  // resultCacheOff as a key ("" when on): "option" (SweepOptions::resultCache false), "camera_dependent_effect",
  // "keep_matches" (CheckOptions::keepMatches).
  std::string resultCacheOffKey;
  size_t resultCacheBytes = 0;
  size_t resultCacheItems = 0;
  int64_t resultCacheDropped = 0;
};

// Checks every camera against the one prepared terrain (shared read-only by the threads). A worker thread the system
// will not start stops the others and throws std::runtime_error ("could not start thread K of N: ...", base/threads.h).
SweepResult sweep(const Terrain& terrain, const std::vector<Camera>& cameras, const CheckOptions& options = {},
                  const SweepOptions& sweepOptions = {});
// The same over `count` cameras made when needed: cameraAt(i) (i < count; called from the worker threads, possibly at
// once) is camera i. Memory does not grow with count unless SweepOptions::keepCameras / keepReports ask for it.
SweepResult sweep(const Terrain& terrain, size_t count, const std::function<Camera(size_t)>& cameraAt,
                  const CheckOptions& options = {}, const SweepOptions& sweepOptions = {});

} // namespace fftess::verify
