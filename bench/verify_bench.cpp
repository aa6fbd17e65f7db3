// What accuracy costs in time, verifier side: one camera of the bundled scene with the exact-predicate kernel
// (Epick), the exact-construction kernel (Epeck) and naive float predicates; the edge check vs the whole-mesh check.
#include "verify/internal.h"
#include "verify/verify.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <algorithm>
#include <string>
#include <vector>

namespace {

namespace vf = fftess::verify;

const vf::Scene& scene(const char* clamp) {
  static vf::Scene pow2, none;
  static bool loaded = false;
  if (!loaded) {
    const std::string path = std::string(FFTESS_SOURCE_ROOT) + "/docs/examples/terrain.toml";
    vf::SceneResult a = vf::loadScene(path), b = vf::loadScene(path, {"lod.adjacency_clamp=none"});
    if (!a || !b) {
      std::fprintf(stderr, "cannot load %s: %s%s\n", path.c_str(), a.error.c_str(), b.error.c_str());
      std::exit(2);
    }
    pow2 = a.scene;
    none = b.scene;
    loaded = true;
  }
  return std::string(clamp) == "none" ? none : pow2;
}

void BM_CheckScene(benchmark::State& state) {
  const vf::Scene& s = scene(state.range(1) ? "none" : "pow2");
  const vf::Terrain t = vf::prepareTerrain(s).terrain; // once: only the per-camera work is measured
  vf::CheckOptions o;
  o.kernel = static_cast<vf::Kernel>(state.range(0));
  int64_t edges = 0;
  for (auto _ : state) {
    const vf::Report r = vf::checkScene(t, s.camera, o);
    edges += r.stats.edgesChecked;
    benchmark::DoNotOptimize(r.stats.cracks);
  }
  state.SetItemsProcessed(edges);
  state.SetLabel(std::string(vf::toString(o.kernel)) + (state.range(1) ? ", clamp none" : ", clamp pow2"));
}
// args: kernel (0 epick, 1 epeck, 2 float), clamp (0 pow2, 1 none)
BENCHMARK(BM_CheckScene)->ArgsProduct({{0, 1, 2}, {0, 1}})->ArgNames({"kernel", "noclamp"})->Unit(benchmark::kMillisecond);

void BM_CheckSceneMesh(benchmark::State& state) {
  const vf::Scene& s = scene("pow2");
  const vf::Terrain t = vf::prepareTerrain(s).terrain;
  for (auto _ : state) benchmark::DoNotOptimize(vf::checkSceneMesh(t, s.camera).innerBorderEdges);
}
BENCHMARK(BM_CheckSceneMesh)->Unit(benchmark::kMillisecond);

// The sweep shortcuts (docs/verify.md, "Sweep shortcuts") on the bundled scene, clamp pow2. BM_CheckSceneVisibleFirst:
// one camera (the scene's) checked in full and visible first. BM_SweepShortcuts: a sweep of 32 random cameras on one
// thread without a shortcut, visible first, the result cache, both: the cache lives for one sweep (a camera reuses
// what the cameras before it proved), so the unit is the sweep; items are cameras.
void BM_CheckSceneVisibleFirst(benchmark::State& state) {
  const vf::Scene& s = scene("pow2");
  const vf::Terrain t = vf::prepareTerrain(s).terrain;
  vf::CheckOptions o;
  o.visibleFirst = state.range(0) != 0;
  int64_t offScreen = 0, cameras = 0;
  for (auto _ : state) {
    const vf::Report r = vf::checkScene(t, s.camera, o);
    offScreen += r.stats.patchesOffScreen;
    ++cameras;
    benchmark::DoNotOptimize(r.stats.cracks);
  }
  state.SetItemsProcessed(cameras);
  state.SetLabel(o.visibleFirst ? "visible first, patches off screen " + std::to_string(offScreen / std::max<int64_t>(1, cameras))
                                : std::string("full check"));
}
BENCHMARK(BM_CheckSceneVisibleFirst)->Arg(0)->Arg(1)->ArgName("visible_first")->Unit(benchmark::kMillisecond);

void BM_SweepShortcuts(benchmark::State& state) {
  const vf::Scene& s = scene("pow2");
  const vf::Terrain t = vf::prepareTerrain(s).terrain;
  const std::vector<vf::Camera> cams = vf::randomCameras(t, 32, 1);
  vf::CheckOptions o;
  o.visibleFirst = state.range(0) != 0;
  vf::SweepOptions so;
  so.threads = 1;
  so.keepCameras = false;
  so.resultCache = state.range(1) != 0;
  vf::WorkStats work;
  vf::Stats total;
  for (auto _ : state) {
    const vf::SweepResult r = vf::sweep(t, cams, o, so);
    work = r.work;
    total = r.total;
    benchmark::DoNotOptimize(r.total.cracks);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * cams.size()));
  const double pairs = static_cast<double>(std::max<int64_t>(1, total.edgesChecked));
  char label[160];
  std::snprintf(label, sizeof label, "cameras/s; per camera %lld lod evals, %lld domain evals; hits %.1f %%, seam %.1f %%",
                static_cast<long long>(work.lodEvaluations / 32), static_cast<long long>(work.domainEvaluations / 32),
                100.0 * static_cast<double>(work.cacheHits) / pairs, 100.0 * static_cast<double>(work.seamHits) / pairs);
  state.SetLabel(label);
}
// args: visible first (0, 1), result cache (0, 1)
BENCHMARK(BM_SweepShortcuts)
    ->ArgsProduct({{0, 1}, {0, 1}})
    ->ArgNames({"visible_first", "cache"})
    ->Unit(benchmark::kMillisecond);

// Per-camera cost of a camera-dependent layout beside a static one (docs/verify.md, "Quadtree"): the quadtree's
// selection alone (cameraLayout into a warm per-thread scratch), and selection + check per camera for the CDLOD
// example against the check alone for tile_rings (terrain.toml), both over the same kind of random cameras, each
// camera with a warm EdgeCache as a sweep's thread has.
namespace layouts {

const vf::Terrain& terrain(int which) {
  static vf::Terrain t[2];
  static const char* const files[2] = {"terrain.toml", "quadtree_cdlod.toml"};
  if (t[which].empty()) {
    const std::string path = std::string(FFTESS_SOURCE_ROOT) + "/docs/examples/" + files[which];
    vf::SceneResult s = vf::loadScene(path);
    vf::TerrainResult r = s ? vf::prepareTerrain(s.scene) : vf::TerrainResult{};
    if (!r) {
      std::fprintf(stderr, "cannot prepare %s: %s%s\n", path.c_str(), s.error.c_str(), r.error.c_str());
      std::exit(2);
    }
    t[which] = r.terrain;
  }
  return t[which];
}

void BM_QuadtreeSelect(benchmark::State& state) {
  const vf::Terrain& t = terrain(1);
  const vf::CameraSet cams = vf::CameraSet::random(t, 64, 1);
  vf::detail::TerrainData scratch;
  vf::WorkStats work;
  size_t i = 0, leaves = 0;
  for (auto _ : state) {
    vf::detail::cameraLayout(t.data(), cams.at(i++ % cams.size()), scratch, work);
    leaves += scratch.patches.size();
  }
  state.SetItemsProcessed(static_cast<int64_t>(leaves));
  state.SetLabel("leaves/s; nodes visited per camera " +
                 std::to_string(work.layoutNodes / std::max<int64_t>(1, work.layoutSelections)));
}
BENCHMARK(BM_QuadtreeSelect)->Unit(benchmark::kMicrosecond);

void BM_LayoutCheck(benchmark::State& state) {
  const vf::Terrain& t = terrain(static_cast<int>(state.range(0)));
  const vf::Scene& s = t.scene();
  const vf::CameraSet cams = vf::CameraSet::random(t, 64, 1);
  vf::detail::EdgeCache cache(s.partitioning, s.stage, vf::detail::tessellatorOptions(s, {}));
  size_t i = 0;
  int64_t patches = 0;
  for (auto _ : state) {
    const vf::Report r = vf::detail::checkTerrain(t.data(), cams.at(i++ % cams.size()), {}, cache);
    patches += r.stats.patches;
    benchmark::DoNotOptimize(r.stats.cracks);
  }
  state.SetItemsProcessed(patches);
  state.SetLabel(state.range(0) ? "quadtree_cdlod (selection + check), patches/s" : "tile_rings terrain.toml (check), patches/s");
}
// arg: 0 tile_rings (terrain.toml), 1 quadtree (quadtree_cdlod.toml)
BENCHMARK(BM_LayoutCheck)->Arg(0)->Arg(1)->ArgName("quadtree")->Unit(benchmark::kMillisecond);

// The camera-independent prepare a camera does not repeat: the node pyramid (quadtree) or the static layout.
void BM_PrepareTerrain(benchmark::State& state) {
  const vf::Scene& s = terrain(static_cast<int>(state.range(0))).scene();
  for (auto _ : state) benchmark::DoNotOptimize(vf::prepareTerrain(s).terrain.patchCount());
  state.SetLabel(state.range(0) ? "quadtree_cdlod (node pyramid + the scene camera's selection)" : "tile_rings terrain.toml");
}
BENCHMARK(BM_PrepareTerrain)->Arg(0)->Arg(1)->ArgName("quadtree")->Unit(benchmark::kMillisecond);

} // namespace layouts

} // namespace
