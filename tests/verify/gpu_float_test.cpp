// GPU float freedom (CheckOptions::gpuFloat; docs/verify.md, "GPU float freedom") on the verify API: the negative
// control's scene key, the findings' invariants against the plain check, the sweep's totals, the refusals.
#include "verify_test_util.h"

#include "verify/report.h"

using namespace fftess::verify;
using namespace fftess::verify::test;

TEST_CASE("gpu float: lod.sphere_centre reads half_sum and around_quad_scaled and refuses other words",
          "[verify][gpu_float]") {
  CHECK(loadExample("grid.toml").lod.screenSphere.sphere.sphereCentre == fftess::lod::SphereCentre::HalfSum);
  CHECK(loadExample("gpu_float_control.toml").lod.screenSphere.sphere.sphereCentre ==
        fftess::lod::SphereCentre::AroundQuadScaled);
  CHECK(loadExample("gpu_float_control.toml", {"lod.sphere_centre=half_sum"}).lod.screenSphere.sphere.sphereCentre ==
        fftess::lod::SphereCentre::HalfSum);
  const SceneResult bad = loadScene(examplePath("gpu_float_control.toml"), {"lod.sphere_centre=midpoint"});
  INFO(bad.error);
  CHECK_FALSE(bad.ok);
  CHECK(bad.error.find("lod.sphere_centre: unknown value \"midpoint\" (expected \"half_sum\" | \"around_quad_scaled\")") !=
        std::string::npos);
}

TEST_CASE("gpu float: the control's findings are pairs the C++ check matched, their C++ factors inside the ranges",
          "[verify][gpu_float]") {
  const Scene scene = loadExample("gpu_float_control.toml");
  const Terrain t = prepared(scene);
  const Report plain = checkScene(t, scene.camera);
  CheckOptions o;
  o.gpuFloat = GpuFloat::Conformant;
  const Report gpu = checkScene(t, scene.camera, o);
  REQUIRE(gpu.error.empty());
  // The plain check is untouched by the option; every matching pair is evaluated again.
  CHECK(plain.stats.gpuFloatPairs == 0);
  CHECK(plain.gpuFloat.empty());
  CHECK(verdictOf(plain.stats) == Verdict::Watertight);
  CHECK(gpu.stats.matches == plain.stats.matches);
  CHECK(gpu.stats.cracks == 0);
  CHECK(gpu.stats.gpuFloatPairs == gpu.stats.matches);
  CHECK(gpu.stats.gpuFloatFindings > 0);
  CHECK(gpu.gpuFloat.size() == static_cast<size_t>(gpu.stats.gpuFloatFindings));
  CHECK(verdictOf(gpu.stats) == Verdict::GpuFloat);
  for (const GpuFloatFinding& g : gpu.gpuFloat) {
    INFO("patch " << g.a.index << " / " << g.b.index << ": " << g.why);
    CHECK(g.factorA == g.factorB); // a match of equal patches
    CHECK((g.loA <= g.factorA && g.factorA <= g.hiA));
    CHECK((g.loB <= g.factorB && g.factorB <= g.hiB));
    CHECK(g.loA < g.hiA);
    CHECK(g.operationA.rfind("add~fma(", 0) == 0);
    CHECK(!g.operationB.empty());
    CHECK(!g.fix.empty());
  }
}

TEST_CASE("gpu float: a sweep adds up the pairs and findings and counts the cameras that have any",
          "[verify][gpu_float]") {
  const Scene scene = loadExample("gpu_float_control.toml");
  const Terrain t = prepared(scene);
  const std::vector<Camera> cams = randomCameras(t, 12, 5);
  CheckOptions o;
  o.gpuFloat = GpuFloat::Conformant;
  SweepOptions so;
  so.threads = 2;
  so.keepReports = true;
  const SweepResult r = sweep(t, cams, o, so);
  int64_t pairs = 0, findings = 0;
  size_t cameras = 0;
  for (const Report& rep : r.reports) {
    pairs += rep.stats.gpuFloatPairs;
    findings += rep.stats.gpuFloatFindings;
    cameras += rep.stats.gpuFloatFindings > 0 ? 1 : 0;
  }
  CHECK(r.total.gpuFloatPairs == pairs);
  CHECK(r.total.gpuFloatFindings == findings);
  CHECK(r.camerasGpuFloat == cameras);
  CHECK(findings > 0);
  CHECK(verdictOf(r) == Verdict::GpuFloat);
}

TEST_CASE("gpu float: a geomorph scene is refused with a reason, for every camera", "[verify][gpu_float]") {
  const Scene scene = loadExample("geomorph.toml");
  CHECK(gpuFloatRefusal(scene).find("geomorph") != std::string::npos);
  CHECK(gpuFloatRefusal(loadExample("rings_small.toml")).empty());
  CheckOptions o;
  o.gpuFloat = GpuFloat::Conformant;
  const Report r = checkScene(prepared(scene), scene.camera, o);
  CHECK(r.error == gpuFloatRefusal(scene));
}

namespace {

// A stand-in for the GPU path: the C++ build's screen-sphere factors, each edge factor the clamp did not set moved by
// `ulps` float steps up (a driver's division and sqrt within the spec's bounds), or one factor of one patch set to
// `far` (a driver outside any bound).
struct ModelStandIn : FactorProvider {
  int ulps = 0;
  int patch = -1;
  float far = 0.0f;
  bool evaluate(const LodPatches& patches, const fftess::lod::Camera& camera, std::vector<fftess::lod::PatchLod>& out,
                std::string&) override {
    out.resize(patches.size());
    for (size_t i = 0; i < patches.size(); ++i) {
      out[i] = fftess::lod::screenSphere(patches[i].patch, camera, patches.scene().lod.screenSphere.sphere);
      for (int e = 0; e < 4; ++e) {
        float& f = out[i].factors[e];
        if (!(f > 1.0f && f < 64.0f)) continue; // a clamp's or the cull's value is exact on any GPU
        for (int k = 0; k < ulps; ++k) f = std::nextafter(f, 1e30f);
      }
    }
    if (patch >= 0) out[static_cast<size_t>(patch)].factors[0] = far;
    return true;
  }
};

} // namespace

TEST_CASE("gpu float: on the GPU path every factor is checked against the conformant model, and one far off is outside",
          "[verify][gpu_float]") {
  // grid.toml's screen sphere on the GPU path (lod.evaluate = "gpu"): a driver that returns the C++ build's bits, or
  // moves every unclamped edge factor by 2 ulps (inside the spec's division and sqrt bounds), stays inside the model;
  // a factor of 1000 is outside it. The pair analysis runs as on the CPU path.
  const Scene scene = loadExample("grid.toml", {"lod.scheme=screen_sphere", "lod.evaluate=gpu"});
  const Terrain t = prepared(scene);
  auto run = [&](int ulps, int patch, float far) {
    auto p = std::make_shared<ModelStandIn>();
    p->ulps = ulps;
    p->patch = patch;
    p->far = far;
    CheckOptions o;
    o.gpuFloat = GpuFloat::Conformant;
    o.factors = p;
    return checkScene(t, scene.camera, o);
  };
  const Report same = run(0, -1, 0.0f);
  REQUIRE(same.error.empty());
  CHECK(same.stats.gpuModelFactors == 6 * same.stats.patches);
  CHECK(same.stats.gpuModelOutside == 0);
  CHECK(same.stats.gpuFloatPairs > 0);
  const Report moved = run(2, -1, 0.0f);
  CHECK(moved.stats.factorDiffs > 0); // the stand-in did move factors
  CHECK(moved.stats.gpuModelOutside == 0);
  const Report off = run(0, 5, 1000.0f);
  CHECK(off.stats.gpuModelFactors == same.stats.gpuModelFactors);
  CHECK(off.stats.gpuModelOutside == 1);
  // Off: nothing is evaluated.
  auto p = std::make_shared<ModelStandIn>();
  CheckOptions plain;
  plain.factors = p;
  CHECK(checkScene(t, scene.camera, plain).stats.gpuModelFactors == 0);
}
