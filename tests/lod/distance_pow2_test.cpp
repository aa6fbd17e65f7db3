// Scheme 3: distance-based power of two (Luna / Richards).
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {
// A flat strip in front of an eye at the origin looking down -z: corners at x = +-w, z = -zNear and -zFar.
// Veq0 (corners 0-1) has its midpoint at (0, 0, -zFar), Veq1 (2-3) at (0, 0, -zNear).
Patch strip(float w, float zFar, float zNear) {
  Patch p;
  p.corners[0] = glm::vec3(-w, 0.0f, -zFar);
  p.corners[1] = glm::vec3(w, 0.0f, -zFar);
  p.corners[2] = glm::vec3(-w, 0.0f, -zNear);
  p.corners[3] = glm::vec3(w, 0.0f, -zNear);
  return p;
}
Camera lookingDownZ() {
  return makeCamera(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 1.2f, 0.5f, 5000.0f,
                    glm::vec2(1920.0f, 1200.0f));
}
} // namespace

TEST_CASE("distancePow2: hand-computed factors (Luna's defaults 20..500, exponents 6..0)", "[lod][distance_pow2]") {
  // d = 260: s = 240/480 = 0.5, exponent 6 + 0.5 * (0 - 6) = 3 -> 8. d = 20: 64. d = 500 and beyond: 1.
  const Camera cam = lookingDownZ();
  PatchLod r = distancePow2(strip(100.0f, 260.0f, 20.0f), cam);
  CHECK(bitsOf(r.factors[1]) == bitsOf(8.0f));
  CHECK(bitsOf(r.why.factor[1].metric) == bitsOf(260.0f));
  CHECK(bitsOf(r.why.factor[1].exponent) == bitsOf(3.0f));
  CHECK(bitsOf(r.factors[3]) == bitsOf(64.0f));
  r = distancePow2(strip(100.0f, 1000.0f, 500.0f), cam);
  CHECK(bitsOf(r.factors[1]) == bitsOf(1.0f));
  CHECK(bitsOf(r.factors[3]) == bitsOf(1.0f));
  r = distancePow2(strip(1.0f, 10.0f, 5.0f), cam); // nearer than minDistance: saturates at 64
  for (int i = 0; i < 6; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(64.0f));
  }
  // d = 140: s = 0.25, exponent 4.5, factor 2^4.5 = 22.627417 (exp2 within 1 ulp).
  r = distancePow2(strip(100.0f, 140.0f, 20.0f), cam);
  CHECK(bitsOf(r.why.factor[1].exponent) == bitsOf(4.5f));
  INFO("2^4.5 = " << hex(r.factors[1]));
  CHECK(lodtest::ulpFrom(r.factors[1], std::exp2(4.5)) <= 1.0);
  // Inside: the patch centre. Strip 260..20: centre at z = -140 -> the same 2^4.5.
  r = distancePow2(strip(100.0f, 260.0f, 20.0f), cam);
  CHECK(bitsOf(r.factors[4]) == bitsOf(r.factors[5]));
  CHECK(bitsOf(r.why.factor[4].metric) == bitsOf(140.0f));
  CHECK(bitsOf(r.factors[4]) == bitsOf(std::exp2(4.5f)));
}

TEST_CASE("distancePow2: factors stay in [2^minExp, 2^maxExp] and fall with distance", "[lod][distance_pow2]") {
  const Camera cam = lookingDownZ();
  float previous = 65.0f;
  for (int i = 0; i <= 600; ++i) {
    const float z = static_cast<float>(i);
    const PatchLod r = distancePow2(strip(1.0f, z + 1.0f, z), cam);
    CHECK(r.factors[1] >= 1.0f);
    CHECK(r.factors[1] <= 64.0f);
    CHECK(r.factors[1] <= previous); // monotone in distance
    previous = r.factors[1];
  }
  CHECK(previous == 1.0f);
}

TEST_CASE("distancePow2: AABB culling with height bounds writes 0", "[lod][distance_pow2][culling]") {
  const Camera cam = lookingDownZ();
  // Behind the eye.
  PatchLod r = distancePow2(strip(10.0f, -100.0f, -120.0f), cam);
  CHECK(r.why.culled);
  for (float f : r.factors) {
    CHECK(bitsOf(f) == bitsOf(0.0f));
  }
  // Flat patch far below the view at y = -1000, 100 in front: outside the bottom plane (fovy 1.2 rad).
  Patch low = strip(10.0f, 110.0f, 100.0f);
  for (glm::vec3& c : low.corners) {
    c.y = -1000.0f;
  }
  CHECK(distancePow2(low, cam).why.culled);
  // The same patch whose displacement can reach y = 0 (Luna's BoundsY): visible.
  low.useHeightBounds = true;
  low.minHeight = -1000.0f;
  low.maxHeight = 0.0f;
  CHECK_FALSE(distancePow2(low, cam).why.culled);
  // Straddling: not culled. Culling off: factors computed.
  CHECK_FALSE(distancePow2(strip(10.0f, 100.0f, -100.0f), cam).why.culled);
  DistancePow2Params p;
  p.frustumCull = false;
  CHECK(distancePow2(strip(10.0f, -100.0f, -120.0f), cam, p).factors[0] > 0.0f);
}
