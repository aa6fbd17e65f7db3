// fftess prove (verify/prove.h) on its degenerate regions: never PROVED for a region that holds cameras the check
// refuses (eye == target, a view direction parallel to up) or from which nothing is on screen; and the soundness
// sampler: cameras of every PROVED region (uniform, corners, face centres) checked one by one with checkScene.
// Fixtures are named after their case (the audit of issue [8/8]).
#include "verify_test_util.h"

#include "verify/prove.h"
#include "verify/report.h"

#include <cstdint>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

CameraRegion box(glm::vec3 eyeLo, glm::vec3 eyeHi, glm::vec3 targetLo, glm::vec3 targetHi) {
  CameraRegion r;
  r.eyeLo = eyeLo;
  r.eyeHi = eyeHi;
  r.targetLo = targetLo;
  r.targetHi = targetHi;
  return r;
}

ProveOptions withRegion(const CameraRegion& r, int64_t maxRegions) {
  ProveOptions o;
  o.region = r;
  o.regionGiven = true;
  o.threads = 2;
  o.maxRegions = maxRegions;
  return o;
}

// splitmix64's next value in [0, 1).
double unit(uint64_t& state) {
  uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1p-53;
}

float lerpIn(float lo, float hi, double u) {
  const float v = static_cast<float>(static_cast<double>(lo) + u * (static_cast<double>(hi) - lo));
  return std::min(std::max(v, lo), hi);
}

// The cameras of a region the soundness sampler checks: its 64 corners, its 12 face centres (one coordinate at a
// bound, the others at the centre) and `uniform` uniform cameras (seeded).
std::vector<Camera> samples(const Camera& scene, const CameraRegion& r, int uniform, uint64_t seed) {
  const float lo[6] = {r.eyeLo.x, r.eyeLo.y, r.eyeLo.z, r.targetLo.x, r.targetLo.y, r.targetLo.z};
  const float hi[6] = {r.eyeHi.x, r.eyeHi.y, r.eyeHi.z, r.targetHi.x, r.targetHi.y, r.targetHi.z};
  std::vector<Camera> out;
  auto add = [&](const double u[6]) {
    Camera c = scene;
    for (int d = 0; d < 6; ++d) (d < 3 ? c.eye : c.target)[d % 3] = lerpIn(lo[d], hi[d], u[d]);
    out.push_back(c);
  };
  double u[6];
  for (int k = 0; k < 64; ++k) {
    for (int d = 0; d < 6; ++d) u[d] = (k >> d) & 1;
    add(u);
  }
  for (int f = 0; f < 12; ++f) {
    for (int d = 0; d < 6; ++d) u[d] = 0.5;
    u[f / 2] = f % 2;
    add(u);
  }
  for (int i = 0; i < uniform; ++i) {
    for (int d = 0; d < 6; ++d) u[d] = unit(seed);
    add(u);
  }
  return out;
}

// Every sampled camera of a PROVED region: a valid camera whose check has no on-screen crack or T-junction and no
// hole. Returns the number of cameras that broke the proof (INFO names the first).
int brokenCameras(const Terrain& t, const CameraRegion& r, int uniform, uint64_t seed) {
  int broken = 0;
  for (const Camera& c : samples(t.scene().camera, r, uniform, seed)) {
    const Report rep = checkScene(t, c);
    bool bad = !rep.error.empty() || rep.stats.holes > 0;
    for (const Finding& f : rep.findings) bad = bad || (f.classification != Classification::Match && f.onScreen);
    if (bad && broken++ == 0)
      UNSCOPED_INFO("camera eye (" << c.eye.x << ", " << c.eye.y << ", " << c.eye.z << ") target (" << c.target.x
                                   << ", " << c.target.y << ", " << c.target.z << "): " << rep.error << " holes "
                                   << rep.stats.holes << " cracks " << rep.stats.cracksOnScreen());
  }
  return broken;
}

// The audit's false PROVED: rings_small with the clip-diameter scheme and the integer clamp, the eye 80 above the
// target and free in x and z, so that the region holds the camera looking straight down.
Terrain straightDownScene() {
  return prepared(loadExample("rings_small.toml", {"lod.scheme=clip_diameter", "lod.adjacency_clamp=integer",
                                                   "lod.edges_per_screen_height=128"}));
}

} // namespace

TEST_CASE("prove: regionInvalidCameras names eye == target and view directions parallel to up", "[verify][prove]") {
  const glm::vec3 up(0, 1, 0);
  const glm::vec3 o(0.0f);
  struct Case {
    const char* name;
    CameraRegion r;
    const char* want; // a word of the reason, or "" for a valid region
  } cases[] = {
      {"point camera", box({10, 25, -70}, {10, 25, -70}, o, o), ""},
      {"eye box equals target box", box({-1, 30, -1}, {1, 30, 1}, {-1, 30, -1}, {1, 30, 1}), "eye == target"},
      {"boxes touch at one corner", box({0, 0, 0}, {1, 1, 1}, {1, 1, 1}, {2, 2, 2}), "eye == target"},
      {"straight down", box({-1, 80, -1}, {1, 80, 1}, o, o), "parallel"},
      {"straight up", box({-1, -80, -1}, {1, -80, 1}, o, o), "parallel"},
      {"straight down, eye off the axis by 2^-20", box({0x1p-20f, 80, 0x1p-20f}, {1, 80, 1}, o, o), ""},
      {"straight down, eye off the axis by 2^-40 (within the margin)", box({0x1p-40f, 80, 0}, {1, 80, 1}, o, o),
       "parallel"},
      {"horizontal view", box({-1, 0, -80}, {1, 0, -79}, o, o), ""},
      {"a view direction that overflows float", box({-3e38f, 0, 0}, {-3e38f, 0, 0}, {3e38f, 0, 0}, {3e38f, 0, 0}),
       "overflow"},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const std::string why = regionInvalidCameras(c.r, up);
    if (std::string(c.want).empty()) CHECK(why.empty());
    else CHECK(why.find(c.want) != std::string::npos);
  }
}

TEST_CASE("prove never proves a region holding the straight-down camera (the audit's false PROVED)",
          "[verify][prove][slow]") {
  const Terrain t = straightDownScene();
  const ProveReport r = proveScene(t, withRegion(box({-1, 80, -1}, {1, 80, 1}, {0, 0, 0}, {0, 0, 0}), 400));
  REQUIRE(r.error.empty());
  CHECK(r.verdict != ProveVerdict::Proved);
  // Its valid cameras crack: the proof finds one (the check confirms it).
  REQUIRE(r.verdict == ProveVerdict::Counterexample);
  const Report again = checkScene(t, r.counterexample);
  CHECK(again.error.empty());
  CHECK(again.stats.cracksOnScreen() > 0);
}

TEST_CASE("prove never proves a region whose eye box equals its target box", "[verify][prove]") {
  const Terrain t = prepared(loadExample("rings_small.toml"));
  const ProveReport r = proveScene(t, withRegion(box({-1, 30, -1}, {1, 30, 1}, {-1, 30, -1}, {1, 30, 1}), 300));
  REQUIRE(r.error.empty());
  CHECK(r.verdict != ProveVerdict::Proved);
  CHECK(r.stats.volumeProved < 1);
}

TEST_CASE("prove lists the regions holding invalid cameras and decides the rest", "[verify][prove]") {
  // A constant factor, no displacement: every valid camera is watertight, so what is left is the invalid set.
  const Terrain t = prepared(loadExample("prove_w0.toml", {"lod.scheme=constant", "lod.factor=4"}));
  ProveOptions o = withRegion(box({15, 20, 15}, {17, 20, 17}, {16, 0, 16}, {16, 0, 16}), 2000);
  o.maxDepth = 6;
  const ProveReport r = proveScene(t, o);
  REQUIRE(r.error.empty());
  INFO((r.undecided.empty() ? std::string() : r.undecided.front().why));
  CHECK(r.verdict == ProveVerdict::InvalidCameras);
  CHECK(r.stats.regionsInvalid >= 1);
  REQUIRE_FALSE(r.invalid.empty());
  CHECK(r.invalid.front().why.find("parallel") != std::string::npos);
  // The straight-down camera (16, 20, 16) lies in every listed region.
  for (const UndecidedRegion& u : r.invalid) {
    CHECK(u.region.eyeLo.x <= 16.0f);
    CHECK(u.region.eyeHi.x >= 16.0f);
    CHECK(u.region.eyeLo.z <= 16.0f);
    CHECK(u.region.eyeHi.z >= 16.0f);
  }
  CHECK(r.stats.volumeInvalid > 0);
  CHECK(r.stats.volumeInvalid <= 4.0 / 64.0); // depth 6 in two coordinates: the 4 cells around the axis at most
  CHECK(r.stats.volumeProved + r.stats.volumeInvalid + r.stats.volumeNothingOnScreen == Approx(1.0));
}

TEST_CASE("prove says nothing on screen, not PROVED, for a region looking away from the terrain", "[verify][prove]") {
  const Terrain t = prepared(loadExample("prove_w0.toml"));
  const CameraRegion g = box({15, 10, -10}, {17, 10, -10}, {16, 10, -30}, {16, 10, -30});
  const ProveReport r = proveScene(t, withRegion(g, 100));
  REQUIRE(r.error.empty());
  CHECK(r.verdict == ProveVerdict::NothingOnScreen);
  CHECK(r.stats.volumeNothingOnScreen == Approx(1.0));
  // The check says the same of its cameras.
  Camera c = t.scene().camera;
  c.eye = glm::vec3(16, 10, -10);
  c.target = glm::vec3(16, 10, -30);
  CHECK(verdictOf(checkScene(t, c).stats) == Verdict::NothingChecked);
}

TEST_CASE("prove's PROVED regions hold under sampling (fast subset)", "[verify][prove][soundness]") {
  SECTION("rings_small, pow2 clamp, eye and target +-0.01") {
    const Terrain t = prepared(loadExample("rings_small.toml"));
    const CameraRegion g = box({9.99f, 24.99f, -70.01f}, {10.01f, 25.01f, -69.99f}, {-0.01f, 0, -0.01f},
                               {0.01f, 0, 0.01f});
    const ProveReport r = proveScene(t, withRegion(g, 64));
    REQUIRE(r.verdict == ProveVerdict::Proved);
    CHECK(brokenCameras(t, g, 24, 1) == 0);
  }
}

TEST_CASE("prove's PROVED regions hold under sampling (wide: 10^4 cameras a region)", "[verify][prove][soundness][slow]") {
  const Terrain t = prepared(loadExample("rings_small.toml"));
  const CameraRegion g = box({9.99f, 24.99f, -70.01f}, {10.01f, 25.01f, -69.99f}, {-0.01f, 0, -0.01f},
                             {0.01f, 0, 0.01f});
  const ProveReport r = proveScene(t, withRegion(g, 64));
  REQUIRE(r.verdict == ProveVerdict::Proved);
  CHECK(brokenCameras(t, g, 10000, 3) == 0);
  ProveOptions o;
  o.threads = 2;
  const ProveReport d = proveScene(t, o);
  REQUIRE(d.verdict == ProveVerdict::Proved);
  CHECK(brokenCameras(t, d.region, 10000, 4) == 0);
}
