// The GPU path's contract without a GPU (verify links no GL): lod.shader / lod.evaluate parsing, a scene asking for
// the GPU path without a provider, and a stand-in FactorProvider (lod/'s C++ functions) whose factors are checked
// and compared with the C++ build: equal factors give the C++ verdict and no difference; one factor moved by an ulp
// is reported as exactly one FactorDiff with both bits; a NaN factor makes a hole. docs/gpu_lod.md.
#include "verify_test_util.h"
#include "verify/internal.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// lod::distancePow2 on the grid (no size jumps), as lod_bridge.cpp would call it; then an optional perturbation.
struct StandIn : FactorProvider {
  int patch = -1;
  int factor = 0;
  bool nan = false;
  int calls = 0;
  bool evaluate(const LodPatches& patches, const fftess::lod::Camera& camera, std::vector<fftess::lod::PatchLod>& out,
                std::string&) override {
    ++calls;
    out.resize(patches.size());
    for (size_t i = 0; i < patches.size(); ++i)
      out[i] = fftess::lod::distancePow2(patches[i].patch, camera, patches.scene().lod.distancePow2);
    if (nan) {
      for (fftess::lod::PatchLod& l : out) l.factors[factor] = std::nanf(""); // every patch
    } else if (patch >= 0) {
      float& f = out[static_cast<size_t>(patch)].factors[factor];
      f = std::nextafter(f, 1e9f);
    }
    return true;
  }
};

} // namespace

TEST_CASE("gpu path: scene keys lod.shader and lod.evaluate", "[gpu_lod]") {
  const std::string dir = std::string(FFTESS_EXAMPLES_DIR);
  SceneResult r = loadScene(dir + "/gpu_distance_glsl.toml");
  REQUIRE(r);
  CHECK(r.scene.lod.shader == dir + "/lod_distance.glsl"); // relative to the scene file
  CHECK(r.scene.lod.evaluate == LodEvaluate::Gpu);
  CHECK(r.scene.lod.scheme == LodScheme::DistancePow2);    // the C++ reference
  CHECK(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.scheme=shader"}).scene.lod.scheme == LodScheme::Shader);
  SceneResult none = loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=''"});
  REQUIRE(none);
  CHECK(none.scene.lod.shader.empty());
  CHECK(none.scene.lod.evaluate == LodEvaluate::Cpu);
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=missing.glsl"}).error,
             Catch::Contains("lod.shader: cannot read"));
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.shader=lod.txt"}).error,
             Catch::Contains("expected a file name ending in .glsl"));
  CHECK_THAT(loadScene(dir + "/gpu_distance_glsl.toml", {"lod.evaluate=cpu"}).error,
             Catch::Contains("runs on the GPU only"));
  CHECK_THAT(loadScene(dir + "/grid.toml", {"lod.scheme=shader"}).error, Catch::Contains("needs lod.shader"));
  CHECK_THAT(loadScene(dir + "/geomorph.toml", {"lod.evaluate=gpu"}).error, Catch::Contains("no GPU path"));
}

TEST_CASE("gpu path: a stand-in provider's factors are checked and compared with the C++ build", "[gpu_lod]") {
  const Scene cpuScene = loadExample("grid.toml", {"lod.scheme=distance_pow2"});
  const Scene gpuScene = loadExample("grid.toml", {"lod.scheme=distance_pow2", "lod.evaluate=gpu"});
  const Terrain cpu = prepared(cpuScene), gpu = prepared(gpuScene);
  const Camera cam = cpuScene.camera;

  // Without a provider the camera is not checked (the cli always attaches one).
  Report missing = checkScene(gpu, cam);
  CHECK_THAT(missing.error, Catch::Contains("needs a GPU factor provider"));

  auto standIn = std::make_shared<StandIn>();
  CheckOptions o;
  o.factors = standIn;
  const Report ref = checkScene(cpu, cam);
  Report same = checkScene(gpu, cam, o);
  REQUIRE(same.error.empty());
  CHECK(standIn->calls == 1);
  CHECK(same.stats.factorsCompared == 6 * ref.stats.patches);
  CHECK(same.stats.factorDiffs == 0);
  CHECK(same.factorDiffs.empty());
  CHECK(same.stats.matches == ref.stats.matches);
  CHECK(verdictOf(same.stats) == verdictOf(ref.stats));

  // One factor one ulp up: exactly one difference, with both values and bits.
  int target = -1;
  for (int i = 0; i < gpu.patchCount() && target < 0; ++i) {
    fftess::lod::PatchLod l = fftess::lod::distancePow2(LodPatches(gpu)[static_cast<size_t>(i)].patch,
                                                        detail::toLodCamera(cam), gpuScene.lod.distancePow2);
    if (!l.why.culled) target = i;
  }
  REQUIRE(target >= 0);
  standIn->patch = target;
  standIn->factor = 2;
  Report moved = checkScene(gpu, cam, o);
  REQUIRE(moved.factorDiffs.size() == 1);
  CHECK(moved.stats.factorDiffs == 1);
  const FactorDiff& d = moved.factorDiffs[0];
  CHECK(d.patch.index == target);
  CHECK(d.factor == 2);
  CHECK(d.gpuBits == d.cpuBits + 1);
  CHECK(d.gpu == std::nextafter(d.cpu, 1e9f));

  // A NaN factor on every patch: the tessellator discards them, holes where they are in view.
  standIn->nan = true;
  Report nan = checkScene(gpu, cam, o);
  CHECK(nan.stats.factorDiffs == ref.stats.patches);
  CHECK(nan.stats.holesDiscarded > 0);
  CHECK(nan.stats.holesDiscarded + ref.stats.culledPatches <= ref.stats.patches);
}
