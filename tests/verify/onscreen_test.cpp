// On screen or not (docs/verify.md, "On screen"): findings outside the view frustum are counted apart and do not
// make the verdict or the worst gap unless CheckOptions::countOffScreen / verdictOf(..., true) asks for them.
#include "verify_test_util.h"

#include "verify/internal.h"

#include <algorithm>
#include <cmath>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {


// Strictly inside the clip volume, in double from lod's float matrices (an independent test of a point).
bool insideView(const lod::Camera& cam, const glm::vec3& p) {
  double view[4], clip[4];
  for (int r = 0; r < 4; ++r)
    view[r] = double(cam.view[0][r]) * p.x + double(cam.view[1][r]) * p.y + double(cam.view[2][r]) * p.z +
              double(cam.view[3][r]);
  for (int r = 0; r < 4; ++r) {
    clip[r] = 0;
    for (int k = 0; k < 4; ++k) clip[r] += double(cam.projection[k][r]) * view[k];
  }
  const double w = clip[3];
  return w > 0 && std::fabs(clip[0]) < w && std::fabs(clip[1]) < w && std::fabs(clip[2]) < w;
}

Camera pathCamera(const Scene& s) {
  REQUIRE(s.cameraPath.size() == 1);
  return s.cameraPath[0];
}

} // namespace

// The measured case of the issue, rebuilt from docs/examples: a heightmap grid, fractional_odd, no frustum cull,
// one path camera among the hills. Most cracks lie outside the view; the farthest vertex of all is one of them.
TEST_CASE("onscreen: the worst gap is the worst the camera sees, off-screen cracks are counted apart",
          "[verify][onscreen]") {
  const Scene s = loadExample("heightmap_offscreen.toml");
  const Terrain terrain = prepared(s);
  const Camera cam = pathCamera(s);
  const lod::Camera lc = lodCameraOf(cam);
  const Report r = checkScene(terrain, cam);
  REQUIRE(r.error.empty());
  REQUIRE_FALSE(r.truncated);
  const Stats& st = r.stats;
  CHECK(st.cracks == 112);
  CHECK(st.cracksOffScreen > 0);
  CHECK(st.cracksOnScreen() > 0);
  int64_t off = 0, partly = 0;
  double worstOnWorld = 0, worstOnPixels = 0, worstOffPixels = 0;
  for (const Finding& f : r.findings) {
    REQUIRE(f.classification == Classification::Crack);
    if (!f.onScreen) {
      ++off;
      // Proven off screen: none of its points that the report names is in view.
      CHECK_FALSE(insideView(lc, f.gapVertex));
      CHECK_FALSE(insideView(lc, f.a.mismatchWorld));
      CHECK_FALSE(insideView(lc, f.b.mismatchWorld));
      CHECK(f.onScreenGapWorld == 0);
      worstOffPixels = std::max(worstOffPixels, f.gapPixels);
      continue;
    }
    CHECK(f.onScreenGapWorld > 0);
    CHECK(std::isfinite(f.onScreenGapPixels));
    // On screen, but its farthest vertex is not in view: its gap on screen is another vertex's (or an edge's where it
    // leaves the view), not the farthest one's.
    if (!insideView(lc, f.gapVertex) && f.onScreenGapWorld < f.gapWorld) ++partly;
    worstOnWorld = std::max(worstOnWorld, f.onScreenGapWorld);
    worstOnPixels = std::max(worstOnPixels, f.onScreenGapPixels);
  }
  CHECK(off == st.cracksOffScreen);
  CHECK(partly > 0);
  CHECK(st.worstGapWorldOnScreen == worstOnWorld);
  CHECK(st.worstGapPixelsOnScreen == worstOnPixels);
  // The headline: the farthest vertex of all (an off-screen crack) is not what the camera sees.
  CHECK(worstOffPixels == st.worstGapPixels);
  CHECK(st.worstGapPixelsOnScreen < st.worstGapPixels / 4);
  CHECK(verdictOf(st) == Verdict::Cracks);
  CHECK(verdictOf(st, true) == Verdict::Cracks);
}

TEST_CASE("onscreen: a camera that sees none of the cracks is watertight, countOffScreen counts them",
          "[verify][onscreen]") {
  const Scene s = loadExample("heightmap_offscreen.toml");
  const Terrain terrain = prepared(s);
  Camera sky = pathCamera(s);
  sky.eye = {-250, 100, -250}; // at a corner of the terrain, looking away from it and up
  sky.target = {-400, 200, -400};
  const Report r = checkScene(terrain, sky);
  REQUIRE(r.error.empty());
  CHECK(r.stats.edgesChecked > 0);
  CHECK(r.stats.cracks > 0);
  CHECK(r.stats.cracksOffScreen == r.stats.cracks);
  CHECK(r.stats.worstGapWorldOnScreen == 0);
  CHECK(r.stats.worstGapPixelsOnScreen == 0);
  CHECK(r.stats.worstGapWorld > 0);
  CHECK(verdictOf(r.stats) == Verdict::Watertight);
  CHECK(verdictOf(r.stats, true) == Verdict::Cracks);

  // A sweep of both cameras: the sky camera has no finding that counts, unless everything counts.
  const std::vector<Camera> cams = {pathCamera(s), sky};
  SweepOptions one;
  one.threads = 1;
  const SweepResult res = sweep(terrain, cams, {}, one);
  REQUIRE(res.cameras.size() == 2);
  CHECK(res.cameras[0].hasFinding);
  CHECK(res.cameras[0].worst.onScreen);
  CHECK_FALSE(res.cameras[1].hasFinding);
  CHECK(res.total.cracksOffScreen == r.stats.cracks + res.cameras[0].stats.cracksOffScreen);
  CHECK(verdictOf(res) == Verdict::Cracks);
  CheckOptions all;
  all.countOffScreen = true;
  const SweepResult strict = sweep(terrain, {sky}, all, one);
  CHECK(strict.cameras[0].hasFinding);
  CHECK(strict.cameras[0].worst.gapWorld == r.stats.worstGapWorld);
  CHECK(verdictOf(strict) == Verdict::Watertight);
  CHECK(verdictOf(strict, true) == Verdict::Cracks);
}

// Hand-made sides along x: a is straight, b leaves it by 0.1, 0.2, 0.1 at x = 1, 2, 3 and by 1.0 at x = 9. The
// camera sees x in about [-0.1, 4.1]: the farthest vertex (9, 1, 0) is off screen, the crack is not, and its gap on
// screen is the 0.2 at x = 2 (where the edges leave the view, the gap is under 0.05).
TEST_CASE("onscreen: a crack whose farthest vertex is off screen reports the gap of its vertices on screen",
          "[verify][onscreen]") {
  const glm::vec3 a[] = {{0, 0, 0}, {10, 0, 0}};
  const glm::vec3 b[] = {{0, 0, 0},   {1, 0.1f, 0}, {2, 0.2f, 0}, {3, 0.1f, 0}, {5, 0, 0},
                         {8, 0, 0},   {9, 1, 0},    {10, 0, 0}};
  Camera c;
  c.eye = {2, 0, -5};
  c.target = {2, 0, 0};
  c.fovY = 30;
  const lod::Camera lc = lodCameraOf(c);
  REQUIRE(insideView(lc, b[2]));
  REQUIRE_FALSE(insideView(lc, b[6]));
  REQUIRE_FALSE(insideView(lc, b[4]));
  const detail::FrustumTest frustum(lc);
  for (Kernel k : {Kernel::Epick, Kernel::Epeck}) {
    INFO(toString(k));
    const detail::ExactVerdict v = detail::classifyExact(k, a, 2, a, 2, b, 8, &frustum);
    REQUIRE(v.classification == Classification::Crack);
    CHECK(v.gapSide == 1);
    CHECK(v.gapIndex == 6);
    CHECK(v.gap == Approx(1.0));
    REQUIRE(v.onScreenAny);
    CHECK(v.onScreenGapSide == 1);
    CHECK(v.onScreenGapIndex == 2);
    CHECK(v.onScreenGap == Approx(0.2).epsilon(1e-6));

    Finding f;
    f.classification = v.classification;
    f.edgeStart = a[0];
    f.edgeEnd = a[1];
    f.gapWorld = v.gap;
    f.gapSide = v.gapSide;
    f.gapVertex = b[v.gapIndex];
    Stats st;
    detail::markOnScreen(frustum, lc, c.nearZ, v, a, 2, 0, 2, b, 8, f, st);
    CHECK(f.onScreen);
    CHECK(f.onScreenGapWorld == Approx(0.2).epsilon(1e-6));
    CHECK(f.onScreenGapVertex == b[2]);
    CHECK(f.onScreenGapSide == 1);
    // In pixels at the vertex's depth 5: 0.2 * projection[1][1] * 1200 / 2 / 5.
    CHECK(f.onScreenGapPixels == Approx(0.2 * double(lc.projection[1][1]) * 600.0 / 5.0).epsilon(1e-5));
    CHECK(st.cracksOffScreen == 0);
    CHECK(st.worstGapPixelsOnScreen == f.onScreenGapPixels);
  }
}

// The same sides seen from behind (the camera turned around): proven off screen, counted apart.
TEST_CASE("onscreen: a crack behind the camera is off screen", "[verify][onscreen]") {
  const glm::vec3 a[] = {{0, 0, 0}, {10, 0, 0}};
  const glm::vec3 b[] = {{0, 0, 0}, {2, 0.2f, 0}, {9, 1, 0}, {10, 0, 0}};
  Camera c;
  c.eye = {2, 0, -5};
  c.target = {2, 0, -10};
  const lod::Camera lc = lodCameraOf(c);
  const detail::FrustumTest frustum(lc);
  const detail::ExactVerdict v = detail::classifyExact(Kernel::Epick, a, 2, a, 2, b, 4, &frustum);
  REQUIRE(v.classification == Classification::Crack);
  CHECK_FALSE(v.onScreenAny);
  Finding f;
  f.classification = v.classification;
  f.edgeStart = a[0];
  f.edgeEnd = a[1];
  f.gapWorld = v.gap;
  Stats st;
  detail::markOnScreen(frustum, lc, c.nearZ, v, a, 2, 0, 2, b, 4, f, st);
  CHECK_FALSE(f.onScreen);
  CHECK(st.cracksOffScreen == 1);
  CHECK(st.worstGapWorldOnScreen == 0);
}

// Golden invariant over many cameras: no point of an off-screen finding's two edges is in view. The edges are rebuilt
// here from the public API (fftess::edgePoints of each side's hull factor, verify::domainPosition of each point) and
// every segment is sampled; the scenes have no camera-dependent domain shader, so the positions are the checker's.
TEST_CASE("onscreen: no point of an off-screen finding's edges is in view, over random cameras", "[verify][onscreen]") {
  struct Case {
    const char* scene;
    std::vector<std::string> overrides;
  };
  const std::vector<Case> cases = {{"heightmap_offscreen.toml", {}},
                                   {"rings_small.toml", {"lod.adjacency_clamp=none"}},
                                   {"terrain.toml", {"lod.adjacency_clamp=none"}}};
  int64_t offSeen = 0, onSeen = 0;
  for (const Case& c : cases) {
    INFO(c.scene);
    const Scene s = loadExample(c.scene, c.overrides);
    const Terrain terrain = prepared(s);
    for (const Camera& cam : randomCameras(terrain, 12, 7)) {
      const lod::Camera lc = lodCameraOf(cam);
      CheckOptions opt;
      opt.maxFindings = static_cast<size_t>(-1);
      const Report r = checkScene(terrain, cam, opt);
      REQUIRE(r.error.empty());
      for (const Finding& f : r.findings) {
        if (f.onScreen) {
          ++onSeen;
          continue;
        }
        ++offSeen;
        for (const EdgeSide* side : {&f.a, &f.b}) {
          const EdgePoints e = edgePoints(side->hullFactor, s.partitioning, s.stage);
          // The shared part of the edge (side a at a 2x jump: half of it) and the point on either side of it.
          int first = 0, last = e.count - 1;
          while (first + 1 < e.count && e.param[first + 1] <= side->paramLo) ++first;
          while (last > 0 && e.param[last - 1] >= side->paramHi) --last;
          std::vector<glm::vec3> pts;
          for (int k = first; k <= last; ++k) {
            const float t = e.param[k];
            const bool alongV = side->edge == 0 || side->edge == 2; // Ueq0, Ueq1: v varies
            const float fixedCoord = side->edge == 0 || side->edge == 1 ? 0.0f : 1.0f;
            pts.push_back(domainPosition(terrain, side->patch.index, alongV ? fixedCoord : t, alongV ? t : fixedCoord));
          }
          for (size_t k = 0; k + 1 < pts.size(); ++k)
            for (int q = 0; q <= 8; ++q) {
              const glm::vec3 p = pts[k] + (pts[k + 1] - pts[k]) * (float(q) / 8.0f);
              if (insideView(lc, p)) {
                INFO("eye " << cam.eye.x << "," << cam.eye.y << "," << cam.eye.z << " target " << cam.target.x << ","
                            << cam.target.y << "," << cam.target.z << " patch " << side->patch.index << " edge "
                            << side->edge << " point " << p.x << "," << p.y << "," << p.z);
                FAIL("a point of an off-screen finding is in view");
              }
            }
        }
      }
    }
  }
  CHECK(offSeen > 100); // the invariant was tested on many findings, both kinds
  CHECK(onSeen > 100);
}
