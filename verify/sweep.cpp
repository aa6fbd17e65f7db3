// Sweep driver: cameras on T threads, one terrain shared read-only, one edge cache (and scratch) per thread. Each
// camera is made when a thread takes it (cameraAt), and per camera only aggregates are kept (and, with keepCameras, a
// CameraResult): memory does not grow with the cameras.
#include "verify/report.h"
#include "verify/sweep.h"
#include "verify/internal.h"
#include "base/threads.h"

#include <algorithm>
#include <mutex>
#include <thread>

namespace fftess::verify {

// Every effect of the scene format that puts camera state into the domain shader's points (domainCamera's
// PatchDomain): the others (layouts, LOD schemes, clamps, partitionings, lerp formulas, texel formats, the GPU path)
// change the factors or the points only through values the cache keys by (the two factors' bits) or that are the
// same for every camera.
std::vector<std::string> cameraDependentEffects(const Scene& s) {
  std::vector<std::string> out;
  const bool displaced = s.displacement.kind != DisplacementKind::None;
  if (displaced && s.lod.scheme == LodScheme::Geomorph)
    out.push_back("lod.scheme = \"geomorph\": edge vertices morph by the camera's distance");
  if (displaced && s.displacement.mip != MipMode::None)
    out.push_back(std::string("displacement.mip = \"") + toString(s.displacement.mip) +
                  "\": the height is sampled at the camera's mip level");
  return out;
}

SweepResult sweep(const Terrain& terrain, const std::vector<Camera>& cameras, const CheckOptions& options,
                  const SweepOptions& sweepOptions) {
  return sweep(terrain, cameras.size(), [&cameras](size_t i) { return cameras[i]; }, options, sweepOptions);
}

SweepResult sweep(const Terrain& terrain, size_t count, const std::function<Camera(size_t)>& cameraAt,
                  const CheckOptions& options, const SweepOptions& sweepOptions) {
  SweepResult out;
  if (sweepOptions.keepCameras) {
    out.cameras.resize(count);
    for (size_t i = 0; i < count; ++i) out.cameras[i].cameraIndex = i;
  }
  if (sweepOptions.keepReports) out.reports.resize(count);

  const Scene& scene = terrain.scene();

  int threads = sweepOptions.threads > 0 ? sweepOptions.threads
                                         : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<size_t>(static_cast<size_t>(threads), std::max<size_t>(count, 1)));

  // The sweep-wide memo (result cache and seam proofs), unless the scene or the options rule it out.
  std::unique_ptr<detail::SweepMemo> memo;
  const std::vector<std::string> effects = cameraDependentEffects(scene);
  if (!sweepOptions.resultCache) {
    out.resultCacheOff = "turned off (SweepOptions::resultCache; the cli's --no-result-cache)";
    out.resultCacheOffKey = "option";
  } else if (!effects.empty()) {
    out.resultCacheOff = "camera-dependent effect: " + effects.front();
    out.resultCacheOffKey = "camera_dependent_effect";
  } else if (options.keepMatches) {
    out.resultCacheOff = "matches are kept (CheckOptions::keepMatches): a cached match has no record";
    out.resultCacheOffKey = "keep_matches";
  } else {
    const detail::TerrainData& t = terrain.data();
    memo = std::make_unique<detail::SweepMemo>(sweepOptions.resultCacheSlots, t.tree ? t.tree->allPairs.size() : 0);
  }
  out.resultCache = memo != nullptr;
  bool allVisibleFirst = true;

  std::atomic<size_t> next{0};
  std::atomic<bool> stopped{false}; // a thread could not be started: the sweep ends with an exception
  std::mutex mutex; // serialises the callbacks and the aggregates
  size_t done = 0;
  auto worker = [&]() {
    detail::EdgeCache cache(scene.partitioning, scene.stage, detail::tessellatorOptions(scene, options));
    CameraResult cr; // reused camera to camera
    for (;;) {
      if ((sweepOptions.cancel && sweepOptions.cancel->load()) || stopped.load()) return;
      const size_t i = next.fetch_add(1);
      if (i >= count) return;
      Report rep = detail::checkTerrain(terrain.data(), cameraAt(i), options, cache, memo.get());
      cr.cameraIndex = i;
      cr.done = rep.error.empty();
      cr.error = rep.error;
      cr.stats = rep.stats;
      cr.hasHole = !rep.holes.empty();
      if (cr.hasHole) cr.firstHole = rep.holes.front();
      cr.hasUndecided = !rep.undecided.empty();
      if (cr.hasUndecided) cr.firstUndecided = rep.undecided.front();
      cr.hasGpuFloat = !rep.gpuFloat.empty();
      if (cr.hasGpuFloat) cr.firstGpuFloat = rep.gpuFloat.front();
      cr.hasFinding = false;
      // The worst of the findings that count (CameraResult::worst).
      const bool all = options.countOffScreen;
      for (const Finding& f : rep.findings) {
        if (f.classification == Classification::Match || (!all && !f.onScreen)) continue;
        if (!cr.hasFinding || (all ? f.gapWorld > cr.worst.gapWorld : f.onScreenGapWorld > cr.worst.onScreenGapWorld)) {
          cr.worst = f;
          cr.hasFinding = true;
        }
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (!cr.error.empty()) ++out.camerasInvalid;
        if (cr.done) {
          ++out.camerasDone;
          if (cr.stats.edgesChecked == 0) ++out.camerasNothingChecked;
          if (cr.stats.undecided > 0) ++out.camerasUndecided;
          if (cr.stats.gpuFloatFindings > 0) ++out.camerasGpuFloat;
          out.work += rep.work;
          allVisibleFirst = allVisibleFirst && rep.visibleFirst;
          accumulate(out.total, cr.stats);
        }
        if (sweepOptions.keepCameras) out.cameras[i] = cr;
        if (sweepOptions.onReport) sweepOptions.onReport(i, rep);
        if (sweepOptions.onCamera) sweepOptions.onCamera(cr);
        ++done;
        if (sweepOptions.progress) sweepOptions.progress(done, count);
      }
      if (sweepOptions.keepReports) out.reports[i] = std::move(rep);
    }
  };
  // A thread the system refuses stops the others (stopped) and throws one message (base/threads.h).
  runOnThreads(threads, [&](int) { worker(); }, [&] { stopped.store(true); });

  out.visibleFirst = out.camerasDone > 0 && allVisibleFirst;
  if (memo) {
    out.resultCacheBytes = memo->bytes();
    out.resultCacheItems = memo->results.size();
    out.resultCacheDropped = memo->results.dropped();
  }
  out.cancelled = sweepOptions.cancel && sweepOptions.cancel->load() && out.camerasDone + out.camerasInvalid < count;
  return out;
}

} // namespace fftess::verify
