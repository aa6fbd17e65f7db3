// What accuracy costs in time, verifier side: one camera of the bundled scene with the exact-predicate kernel
// (Epick), the exact-construction kernel (Epeck) and naive float predicates; the edge check vs the whole-mesh check.
#include "verify/verify.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>

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

} // namespace
