// Scheme 1: screen-space sphere.
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

TEST_CASE("screenSphere: hand-computed factors with the exact camera", "[lod][screen_sphere]") {
  // Each edge of the 2 x 2 patch at z = -8 is a sphere of diameter 2 centred 8 in front of the eye: its far
  // side projects 2/8 = 0.25 NDC units away, i.e. 0.25 * 1920/2 = 240 pixels.
  const Camera cam = lodtest::exactCamera();
  const Patch patch = lodtest::facingPatch(0.0f, 0.0f, -8.0f);
  ScreenSphereParams p;
  p.tessellatedTriWidth = 6.0f;
  const PatchLod r = screenSphere(patch, cam, p);
  for (int i = 0; i < 6; ++i) {
    INFO("factor " << i << " = " << hex(r.factors[i]));
    CHECK(bitsOf(r.factors[i]) == bitsOf(40.0f));
  }
  for (int i = 0; i < 4; ++i) {
    CHECK(bitsOf(r.why.factor[i].metric) == bitsOf(240.0f));
    CHECK(r.why.factor[i].fixes == FixNone);
  }
  CHECK_FALSE(r.why.culled);
  CHECK(r.why.scheme == Scheme::ScreenSphere);
}

TEST_CASE("screenSphere: clamps to [minFactor, maxFactor] and records it", "[lod][screen_sphere]") {
  const Camera cam = lodtest::exactCamera();
  const Patch patch = lodtest::facingPatch(0.0f, 0.0f, -8.0f);
  ScreenSphereParams p; // 3 px: 240 / 3 = 80 > 64
  PatchLod r = screenSphere(patch, cam, p);
  for (int i = 0; i < 4; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(64.0f));
    CHECK(bitsOf(r.why.factor[i].unclamped) == bitsOf(80.0f));
    CHECK(r.why.factor[i].fixes == FixClampedMax);
  }
  p.tessellatedTriWidth = 480.0f; // 0.5 -> 1
  r = screenSphere(patch, cam, p);
  for (int i = 0; i < 4; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(1.0f));
    CHECK(bitsOf(r.why.factor[i].unclamped) == bitsOf(0.5f));
    CHECK(r.why.factor[i].fixes == FixClampedMin);
  }
  // Range over a camera sweep: every factor in [min, max].
  for (int i = 0; i < 200; ++i) {
    const Camera c = lodtest::sweepCamera(i);
    ScreenSphereParams q;
    q.minFactor = 2.0f;
    q.maxFactor = 33.0f;
    q.frustumCull = false;
    const PatchLod s = screenSphere(lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true), c, q);
    for (int k = 0; k < 6; ++k) {
      CHECK(s.factors[k] >= 2.0f);
      CHECK(s.factors[k] <= 33.0f);
    }
  }
}

TEST_CASE("screenSphere: inside rules", "[lod][screen_sphere]") {
  // A patch whose edges project differently: the right edge is nearer (tilted patch).
  const Camera cam = lodtest::exactCamera();
  Patch patch = lodtest::facingPatch(0.0f, 0.0f, -8.0f);
  patch.corners[1].z = -4.0f;
  patch.corners[3].z = -4.0f;
  ScreenSphereParams p;
  p.tessellatedTriWidth = 12.0f;
  p.inside = InsideRule::Average;
  const PatchLod avg = screenSphere(patch, cam, p);
  CHECK(bitsOf(avg.factors[4]) == bitsOf((avg.factors[1] + avg.factors[3]) * 0.5f));
  CHECK(bitsOf(avg.factors[5]) == bitsOf((avg.factors[0] + avg.factors[2]) * 0.5f));
  p.inside = InsideRule::Min;
  const PatchLod mn = screenSphere(patch, cam, p);
  CHECK(bitsOf(mn.factors[5]) == bitsOf(std::min(mn.factors[0], mn.factors[2])));
  p.inside = InsideRule::Max;
  const PatchLod mx = screenSphere(patch, cam, p);
  CHECK(bitsOf(mx.factors[5]) == bitsOf(std::max(mx.factors[0], mx.factors[2])));
  CHECK(mn.factors[5] < mx.factors[5]); // the edges differ, so the rules do
  // Ueq1 (x = +1 at z = -4): sphere diameter 2 at distance 4 -> 2/4 * 960 = 480 px -> 40.
  CHECK(bitsOf(mx.factors[2]) == bitsOf(40.0f));
}

TEST_CASE("screenSphere: frustum culling writes -1", "[lod][screen_sphere][culling]") {
  const Camera cam = lodtest::exactCamera();
  // Behind the eye, beyond the far plane (17), and far to the side: culled.
  for (const Patch& patch : {lodtest::facingPatch(0.0f, 0.0f, 8.0f), lodtest::facingPatch(0.0f, 0.0f, -30.0f),
                             lodtest::facingPatch(40.0f, 0.0f, -8.0f), lodtest::facingPatch(0.0f, -40.0f, -8.0f)}) {
    const PatchLod r = screenSphere(patch, cam);
    CHECK(r.why.culled);
    for (int i = 0; i < 6; ++i) {
      CHECK(bitsOf(r.factors[i]) == bitsOf(-1.0f));
      CHECK((r.why.factor[i].fixes & FixCulled) != 0);
    }
  }
  // Straddling the left plane x = -w (at z = -8: x = -8): kept.
  const PatchLod edge = screenSphere(lodtest::facingPatch(-8.5f, 0.0f, -8.0f), cam);
  CHECK_FALSE(edge.why.culled);
  // Height bounds: corners below the frustum (y < -8 at z = -8), bounds reaching into it: kept.
  Patch low = lodtest::facingPatch(0.0f, -20.0f, -8.0f);
  CHECK(screenSphere(low, cam).why.culled);
  low.useHeightBounds = true;
  low.minHeight = -25.0f;
  low.maxHeight = 0.0f;
  CHECK_FALSE(screenSphere(low, cam).why.culled);
  // Culling off: factors computed.
  ScreenSphereParams p;
  p.frustumCull = false;
  CHECK(screenSphere(lodtest::facingPatch(0.0f, 0.0f, -30.0f), cam, p).factors[0] > 0.0f);
}

TEST_CASE("screenSphere: glm::lookAt / glm::perspective camera within 8 ulp of a double evaluation",
          "[lod][screen_sphere]") {
  int compared = 0; // edges compared: the skip below must not empty the test
  for (int i = 0; i < 100; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    const Patch patch = lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true);
    ScreenSphereParams p;
    p.frustumCull = false;
    p.maxFactor = 1e30f;
    p.minFactor = 0.0f;
    const PatchLod r = screenSphere(patch, cam, p);
    const glm::dmat4 v(cam.view), pr(cam.projection);
    const int ends[4][2] = {{0, 2}, {0, 1}, {1, 3}, {2, 3}};
    for (int e = 0; e < 4; ++e) {
      const glm::dvec3 a(patch.corners[ends[e][0]]), b(patch.corners[ends[e][1]]);
      const glm::dvec3 c = (a + b) * 0.5;
      const double d = glm::length(a - b);
      glm::dvec4 v0 = v * glm::dvec4(c, 1.0);
      glm::dvec4 v1 = v0;
      v1.x += d;
      const glm::dvec4 c0 = pr * v0, c1 = pr * v1;
      if (c0.w <= 0.1 || c1.w <= 0.1) {
        continue; // behind or at the eye: the projection is meaningless there
      }
      const double px = (c1.x / c1.w - c0.x / c0.w) * 960.0;
      const double py = (c1.y / c1.w - c0.y / c0.w) * 600.0;
      const double want = std::sqrt(px * px + py * py) / 3.0;
      INFO("camera " << i << " edge " << e << " got " << hex(r.factors[e]) << " want " << want);
      CHECK(lodtest::ulpFrom(r.factors[e], want) <= 8.0);
      ++compared;
    }
  }
  CHECK(compared > 200);
}

TEST_CASE("screenSphere: sphere_centre around_quad_scaled moves the sphere and is sensitive to a fused product",
          "[lod][screen_sphere]") {
  // The negative control of --gpu-float (lod.sphere_centre = "around_quad_scaled"): the centre (from * 3 + to * 3) /
  // 6 is not the midpoint's bits, so the factors differ from the default's on some cameras (the field is used); and
  // on these displaced corners a compiler that fuses one product into the add, fma(from, 3, to * 3), gets different
  // bits from the two sides (which pass the ends in opposite orders), so the control has something to find.
  const Patch a = lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true);
  ScreenSphereParams around;
  around.sphereCentre = SphereCentre::AroundQuadScaled;
  around.minFactor = 0.0f;
  around.maxFactor = 1e30f;
  ScreenSphereParams half = around;
  half.sphereCentre = SphereCentre::HalfSum;
  int differ = 0;
  for (int i = 0; i < 50; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    const PatchLod ra = screenSphere(a, cam, around), rh = screenSphere(a, cam, half);
    for (int k = 0; k < 4; ++k) differ += bitsOf(ra.factors[k]) != bitsOf(rh.factors[k]) ? 1 : 0;
  }
  CHECK(differ > 0);
  // Veq0 passes c0 -> c1; the patch across it (its Veq1) passes the same two points c1 -> c0.
  const float p = a.corners[0].y, q = a.corners[1].y;
  const float sideA = std::fma(p, 3.0f, q * 3.0f), sideB = std::fma(q, 3.0f, p * 3.0f);
  INFO("heights " << hex(p) << ", " << hex(q) << ": fused " << hex(sideA) << " / " << hex(sideB));
  CHECK(bitsOf(p * 3.0f + q * 3.0f) == bitsOf(q * 3.0f + p * 3.0f));
  CHECK(bitsOf(sideA) != bitsOf(sideB));
}
