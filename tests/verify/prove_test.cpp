// fftess prove (verify/prove.h): a proof over a region of rings_small with the power-of-two clamp, counterexamples
// that the check confirms (no adjacency clamp; the thin w = 0 set of docs/examples/prove_w0.toml that random
// cameras miss), an undecided proof when the region budget runs out, and the scenes prove refuses.
#include "verify_test_util.h"

#include "verify/prove.h"
#include "verify/report.h"
#include "verify/sweep.h"

#include <cstdint>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// A small box of cameras around rings_small's scene camera (eye (10, 25, -70) +- 0.01, target (0, 0, 0) +- 0.01 in x
// and z): wide enough for every comparison of the clamps and the frustum test to go both ways somewhere (thousands of
// paths), small enough to be decided at the root (docs/verify.md, "Proofs": what makes wider regions slow).
CameraRegion ringsSmallRegion() {
  CameraRegion r;
  r.eyeLo = glm::vec3(9.99f, 24.99f, -70.01f);
  r.eyeHi = glm::vec3(10.01f, 25.01f, -69.99f);
  r.targetLo = glm::vec3(-0.01f, 0.0f, -0.01f);
  r.targetHi = glm::vec3(0.01f, 0.0f, 0.01f);
  return r;
}

// prove_w0.toml's region (its header): the view direction +z exactly, eye z across the patch boundary z = 4.
CameraRegion w0Region() {
  CameraRegion r;
  r.eyeLo = glm::vec3(2.0f, 0.5f, 1.3f);
  r.eyeHi = glm::vec3(2.0f, 0.5f, 6.5f);
  r.targetLo = glm::vec3(2.0f, 0.5f, 20.3f);
  r.targetHi = glm::vec3(2.0f, 0.5f, 30.7f);
  return r;
}

ProveOptions withRegion(const CameraRegion& r) {
  ProveOptions o;
  o.region = r;
  o.regionGiven = true;
  o.threads = 2;
  return o;
}

bool onScreenFindingOrHole(const Report& r) {
  if (r.stats.holes > 0) return true;
  for (const Finding& f : r.findings)
    if (f.classification != Classification::Match && f.onScreen) return true;
  return false;
}

// Uniform floats in [lo, hi] from splitmix64 (the same on every platform).
float uniformIn(uint64_t& state, float lo, float hi) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  const double u = static_cast<double>(z >> 11) * 0x1p-53;
  return static_cast<float>(static_cast<double>(lo) + u * (static_cast<double>(hi) - lo));
}

} // namespace

TEST_CASE("prove proves rings_small with the pow2 clamp on a small region around its camera", "[verify][prove]") {
  const Terrain t = prepared(loadExample("rings_small.toml"));
  ProveOptions o = withRegion(ringsSmallRegion());
  o.maxRegions = 8; // decided at the root: a failing proof stops soon
  const ProveReport r = proveScene(t, o);
  INFO(r.error << (r.undecided.empty() ? std::string() : r.undecided.front().why));
  REQUIRE(r.error.empty());
  CHECK(r.verdict == ProveVerdict::Proved);
  CHECK(r.stats.regionsUndecided == 0);
  CHECK(r.stats.regionsProved >= 1);
  CHECK(r.stats.pairsByTrace > 0);  // same-size neighbours: the same factor's trace on both sides
  CHECK(r.stats.pairsByValue > 0);  // the size jumps: both sides' clamped factors, classified
  CHECK(r.stats.camerasChecked >= 1); // the root's sampled cameras
}

TEST_CASE("prove gives rings_small without an adjacency clamp a counterexample that the check confirms",
          "[verify][prove]") {
  const Terrain t = prepared(loadExample("rings_small.toml", {"lod.adjacency_clamp=none"}));
  ProveOptions o = withRegion(ringsSmallRegion());
  o.maxRegions = 8; // found at the root: a prover that misses it stops soon
  const ProveReport r = proveScene(t, o);
  REQUIRE(r.error.empty());
  REQUIRE(r.verdict == ProveVerdict::Counterexample);
  CHECK(onScreenFindingOrHole(r.counterexampleReport));
  // The camera as printed reproduces the finding in a check of its own.
  const Report again = checkScene(t, r.counterexample);
  CHECK(onScreenFindingOrHole(again));
  CHECK(again.stats.cracks > 0);
  const CameraRegion& g = r.region;
  CHECK(glm::all(glm::greaterThanEqual(r.counterexample.eye, g.eyeLo)));
  CHECK(glm::all(glm::lessThanEqual(r.counterexample.eye, g.eyeHi)));
  CHECK(glm::all(glm::greaterThanEqual(r.counterexample.target, g.targetLo)));
  CHECK(glm::all(glm::lessThanEqual(r.counterexample.target, g.targetHi)));
}

TEST_CASE("prove finds the w = 0 hole of prove_w0 that 1,000 random cameras of its region miss", "[verify][prove]") {
  const Terrain t = prepared(loadExample("prove_w0.toml"));
  const CameraRegion g = w0Region();
  // The sweep: 1,000 uniform random cameras of the region, all watertight.
  std::vector<Camera> cameras;
  uint64_t state = 23;
  for (int i = 0; i < 1000; ++i) {
    Camera c = t.scene().camera;
    c.eye = glm::vec3(g.eyeLo.x, g.eyeLo.y, uniformIn(state, g.eyeLo.z, g.eyeHi.z));
    c.target = glm::vec3(g.targetLo.x, g.targetLo.y, uniformIn(state, g.targetLo.z, g.targetHi.z));
    cameras.push_back(c);
  }
  const SweepResult s = sweep(t, cameras, CheckOptions{}, SweepOptions{});
  CHECK(s.camerasDone == 1000);
  CHECK(verdictOf(s) == Verdict::Watertight);
  // The proof: a counterexample, a hole the check confirms, at an eye in the eye plane of an edge midpoint.
  ProveOptions o = withRegion(g);
  o.maxRegions = 64; // found at the root: a prover that misses it stops soon
  const ProveReport r = proveScene(t, o);
  REQUIRE(r.error.empty());
  REQUIRE(r.verdict == ProveVerdict::Counterexample);
  const Report again = checkScene(t, r.counterexample);
  CHECK(again.stats.holes > 0);
  CHECK(r.counterexample.eye.z == 4.0f);
}

TEST_CASE("prove is undecided, never proved, while regions are left open", "[verify][prove]") {
  const Terrain t = prepared(loadExample("rings_small.toml"));
  ProveOptions o; // eye +-1 around the scene camera: not decided at its root
  o.region.eyeLo = glm::vec3(9.0f, 24.0f, -71.0f);
  o.region.eyeHi = glm::vec3(11.0f, 26.0f, -69.0f);
  o.regionGiven = true;
  o.maxRegions = 1;
  o.threads = 1;
  const ProveReport r = proveScene(t, o);
  REQUIRE(r.error.empty());
  CHECK_FALSE(r.regionDefault);
  CHECK(r.verdict == ProveVerdict::Undecided);
  CHECK(r.stats.regions == 1);
  CHECK(r.stats.regionsUndecided >= 1);
  REQUIRE_FALSE(r.undecided.empty());
  CHECK_FALSE(r.undecided.front().why.empty());
}

TEST_CASE("prove refuses geomorph scenes, quadtree layouts and user shaders", "[verify][prove]") {
  SECTION("geomorph") {
    const ProveReport r = proveScene(prepared(loadExample("geomorph.toml")));
    CHECK(r.error.find("geomorph") != std::string::npos);
  }
  SECTION("quadtree") {
    const ProveReport r = proveScene(prepared(loadExample("quadtree_cdlod.toml")));
    CHECK(r.error.find("quadtree") != std::string::npos);
  }
  SECTION("lod.shader") {
    const ProveReport r = proveScene(prepared(loadExample("gpu_distance_glsl.toml")));
    CHECK(r.error.find("lod.shader") != std::string::npos);
  }
  SECTION("an empty region coordinate") {
    ProveOptions o;
    o.regionGiven = true;
    o.region.eyeLo = glm::vec3(1.0f);
    o.region.eyeHi = glm::vec3(0.0f);
    const ProveReport r = proveScene(prepared(loadExample("rings_small.toml")), o);
    CHECK_FALSE(r.error.empty());
    CHECK(r.verdict == ProveVerdict::Undecided);
  }
}
