// fftess prove's cost (verify/prove.h, docs/verify.md "Proofs"): rings_small (power-of-two clamp) proven over a small
// box of cameras around its scene camera (eye +-0.01, target +-0.01 in x and z: decided at the root), on 1 and 2 threads. The label says
// the verdict and what the proof counted (regions, depth, pair decisions, LOD paths).
#include "verify/prove.h"
#include "verify/verify.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

namespace vf = fftess::verify;

const vf::Terrain& ringsSmall() {
  static vf::Terrain t;
  if (t.empty()) {
    const std::string path = std::string(FFTESS_SOURCE_ROOT) + "/docs/examples/rings_small.toml";
    vf::SceneResult s = vf::loadScene(path);
    vf::TerrainResult r = s ? vf::prepareTerrain(s.scene) : vf::TerrainResult{};
    if (!r) {
      std::fprintf(stderr, "cannot prepare %s: %s%s\n", path.c_str(), s.error.c_str(), r.error.c_str());
      std::exit(2);
    }
    t = r.terrain;
  }
  return t;
}

void BM_Prove(benchmark::State& state) {
  const vf::Terrain& t = ringsSmall();
  vf::ProveOptions o;
  o.regionGiven = true;
  o.region.eyeLo = glm::vec3(9.99f, 24.99f, -70.01f);
  o.region.eyeHi = glm::vec3(10.01f, 25.01f, -69.99f);
  o.region.targetLo = glm::vec3(-0.01f, 0.0f, -0.01f);
  o.region.targetHi = glm::vec3(0.01f, 0.0f, 0.01f);
  o.threads = static_cast<int>(state.range(0));
  vf::ProveReport r;
  for (auto _ : state) {
    r = vf::proveScene(t, o);
    benchmark::DoNotOptimize(r.stats.regions);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations()) * r.stats.regions);
  char label[200];
  std::snprintf(label, sizeof label, "%s; regions %lld (proved %lld), depth %d, trace %lld, value %lld, paths %lld",
                vf::toString(r.verdict), static_cast<long long>(r.stats.regions),
                static_cast<long long>(r.stats.regionsProved), r.stats.maxDepthReached,
                static_cast<long long>(r.stats.pairsByTrace), static_cast<long long>(r.stats.pairsByValue),
                static_cast<long long>(r.stats.lodPaths));
  state.SetLabel(label);
}
// arg: threads
BENCHMARK(BM_Prove)->Arg(1)->Arg(2)->ArgName("threads")->Unit(benchmark::kMillisecond)->Iterations(1);

} // namespace
