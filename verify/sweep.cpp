// Sweep driver: cameras on T threads, one terrain shared read-only, one edge cache per thread.
#include "verify/internal.h"

#include <algorithm>
#include <mutex>
#include <thread>

namespace fftess::verify {

SweepResult sweep(const Terrain& terrain, const std::vector<Camera>& cameras, const CheckOptions& options,
                  const SweepOptions& sweepOptions) {
  SweepResult out;
  out.cameras.resize(cameras.size());
  if (sweepOptions.keepReports) out.reports.resize(cameras.size());
  for (size_t i = 0; i < cameras.size(); ++i) out.cameras[i].cameraIndex = i;

  const Scene& scene = terrain.scene();

  int threads = sweepOptions.threads > 0 ? sweepOptions.threads
                                         : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads = static_cast<int>(std::min<size_t>(static_cast<size_t>(threads), std::max<size_t>(cameras.size(), 1)));

  std::vector<WorkStats> work(cameras.size());
  std::atomic<size_t> next{0};
  std::mutex mutex; // serialises the onReport and progress callbacks
  size_t done = 0;
  auto worker = [&]() {
    detail::EdgeCache cache(scene.partitioning, scene.stage, options.tessellator);
    for (;;) {
      if (sweepOptions.cancel && sweepOptions.cancel->load()) return;
      const size_t i = next.fetch_add(1);
      if (i >= cameras.size()) return;
      Report rep = detail::checkTerrain(terrain.data(), cameras[i], options, cache);
      CameraResult& cr = out.cameras[i];
      cr.done = rep.error.empty();
      cr.error = rep.error;
      cr.stats = rep.stats;
      if (!rep.holes.empty()) {
        cr.hasHole = true;
        cr.firstHole = rep.holes.front();
      }
      work[i] = rep.work;
      for (const Finding& f : rep.findings) {
        if (f.classification == Classification::Match) continue;
        if (!cr.hasFinding || f.gapWorld > cr.worst.gapWorld) {
          cr.worst = f;
          cr.hasFinding = true;
        }
      }
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (sweepOptions.onReport) sweepOptions.onReport(i, rep);
        ++done;
        if (sweepOptions.progress) sweepOptions.progress(done, cameras.size());
      }
      if (sweepOptions.keepReports) out.reports[i] = std::move(rep);
    }
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < threads; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();

  for (const CameraResult& cr : out.cameras) {
    if (!cr.error.empty()) ++out.camerasInvalid;
    if (!cr.done) continue;
    ++out.camerasDone;
    if (cr.stats.edgesChecked == 0) ++out.camerasNothingChecked;
    out.work += work[cr.cameraIndex];
    Stats& s = out.total;
    s.patches += cr.stats.patches;
    s.culledPatches += cr.stats.culledPatches;
    s.edgesChecked += cr.stats.edgesChecked;
    s.skippedCulled += cr.stats.skippedCulled;
    s.matches += cr.stats.matches;
    s.tJunctions += cr.stats.tJunctions;
    s.cracks += cr.stats.cracks;
    s.holes += cr.stats.holes;
    s.holesDiscarded += cr.stats.holesDiscarded;
    s.holesCulledVisible += cr.stats.holesCulledVisible;
    s.factorsCompared += cr.stats.factorsCompared;
    s.factorDiffs += cr.stats.factorDiffs;
    s.factorDiffsTessellation += cr.stats.factorDiffsTessellation;
    s.culledUndecided += cr.stats.culledUndecided;
    s.visibilityTests += cr.stats.visibilityTests;
    s.worstGapWorld = std::max(s.worstGapWorld, cr.stats.worstGapWorld);
    s.worstGapPixels = std::max(s.worstGapPixels, cr.stats.worstGapPixels);
  }
  out.cancelled = sweepOptions.cancel && sweepOptions.cancel->load() && out.camerasDone + out.camerasInvalid < cameras.size();
  return out;
}

} // namespace fftess::verify
