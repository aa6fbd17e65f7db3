// Scheme 5: clip-space sphere diameter.
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

TEST_CASE("clipDiameter: hand-computed factors with the exact camera", "[lod][clip_diameter]") {
  // Every edge: diameter 2, clip.w = 8, P[1][1] = 1: metric 2 * 1 / 8 = 0.25; * 16 edges per screen height = 4.
  const Camera cam = lodtest::exactCamera();
  PatchLod r = clipDiameter(lodtest::facingPatch(0.0f, 0.0f, -8.0f), cam);
  for (int i = 0; i < 6; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(4.0f));
  }
  CHECK(bitsOf(r.why.factor[0].metric) == bitsOf(0.25f));
  CHECK(r.why.scheme == Scheme::ClipDiameter);
  // 1024 edges per screen height: 256 -> clamped to 64; 2: 0.5 -> clamped to 1.
  ClipDiameterParams p;
  p.edgesPerScreenHeight = 1024.0f;
  r = clipDiameter(lodtest::facingPatch(0.0f, 0.0f, -8.0f), cam, p);
  CHECK(bitsOf(r.factors[0]) == bitsOf(64.0f));
  CHECK(bitsOf(r.why.factor[0].unclamped) == bitsOf(256.0f));
  CHECK(r.why.factor[0].fixes == FixClampedMax);
  p.edgesPerScreenHeight = 2.0f;
  r = clipDiameter(lodtest::facingPatch(0.0f, 0.0f, -8.0f), cam, p);
  CHECK(bitsOf(r.factors[0]) == bitsOf(1.0f));
  CHECK(r.why.factor[0].fixes == FixClampedMin);
}

TEST_CASE("clipDiameter: behind the eye gets minFactor, no culling unless asked", "[lod][clip_diameter][culling]") {
  const Camera cam = lodtest::exactCamera();
  PatchLod r = clipDiameter(lodtest::facingPatch(0.0f, 0.0f, 8.0f), cam); // clip.w = -8
  CHECK_FALSE(r.why.culled);
  for (int i = 0; i < 4; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(1.0f));
    CHECK(bitsOf(r.why.factor[i].unclamped) == bitsOf(-4.0f));
  }
  // On the eye plane (w = 0): minFactor, not NaN or Inf.
  Patch onPlane = lodtest::facingPatch(0.0f, 0.0f, 0.0f);
  r = clipDiameter(onPlane, cam);
  for (float f : r.factors) {
    CHECK(bitsOf(f) == bitsOf(1.0f));
  }
  ClipDiameterParams p;
  p.frustumCull = true;
  r = clipDiameter(lodtest::facingPatch(0.0f, 0.0f, 8.0f), cam, p);
  CHECK(r.why.culled);
  for (float f : r.factors) {
    CHECK(bitsOf(f) == bitsOf(0.0f));
  }
}

TEST_CASE("clipDiameter: glm::perspective camera within 4 ulp of a double evaluation", "[lod][clip_diameter]") {
  int compared = 0; // edges compared: the skip below must not empty the test
  for (int i = 0; i < 100; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    const Patch patch = lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true);
    ClipDiameterParams p;
    p.maxFactor = 1e30f;
    p.minFactor = -1e30f;
    const PatchLod r = clipDiameter(patch, cam, p);
    const int ends[4][2] = {{0, 2}, {0, 1}, {1, 3}, {2, 3}};
    for (int e = 0; e < 4; ++e) {
      const glm::dvec3 a(patch.corners[ends[e][0]]), b(patch.corners[ends[e][1]]);
      const glm::dvec4 clip = glm::dmat4(cam.projection) * (glm::dmat4(cam.view) * glm::dvec4((a + b) * 0.5, 1.0));
      if (clip.w <= 0.5) {
        continue;
      }
      const double want = glm::length(a - b) * static_cast<double>(cam.projection[1][1]) / clip.w * 16.0;
      INFO("camera " << i << " edge " << e << " got " << hex(r.factors[e]) << " want " << want);
      CHECK(lodtest::ulpFrom(r.factors[e], want) <= 4.0);
      ++compared;
    }
  }
  CHECK(compared > 200);
}
