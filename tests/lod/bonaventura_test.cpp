// Scheme 4: rounded-exponent power of two with camera-angle correction (Bonaventura).
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {
// Eye `height` above the origin looking straight down.
Camera fromAbove(float height) {
  return makeCamera(glm::vec3(0.0f, height, 0.0f), glm::vec3(0.0f, height - 1.0f, 0.0f), glm::vec3(0.0f, 0.0f, -1.0f), 1.2f, 0.5f,
                    5000.0f, glm::vec2(1920.0f, 1200.0f));
}
// A flat square patch centred at (cx, y, cz) of half size h.
Patch square(float cx, float y, float cz, float h) {
  Patch p;
  p.corners[0] = glm::vec3(cx - h, y, cz - h);
  p.corners[1] = glm::vec3(cx + h, y, cz - h);
  p.corners[2] = glm::vec3(cx - h, y, cz + h);
  p.corners[3] = glm::vec3(cx + h, y, cz + h);
  return p;
}
} // namespace

TEST_CASE("bonaventura: hand-computed factors", "[lod][bonaventura]") {
  // Centre straight below at d = 260: e0 = 3; looking along up: acos(1) = 0, correction (pi/2 / (pi/2)) * 0.5 + 1
  // - 0.25 = 1.25; exponent 3.75 -> rounded 4 -> 16.
  const Camera cam = fromAbove(260.0f);
  PatchLod r = bonaventura(square(0.0f, 0.0f, 0.0f, 1.0f), cam);
  CHECK(bitsOf(r.why.factor[4].metric) == bitsOf(260.0f));
  CHECK(bitsOf(r.why.factor[4].exponent) == bitsOf(3.75f));
  CHECK(bitsOf(r.factors[4]) == bitsOf(16.0f));
  CHECK(bitsOf(r.factors[5]) == bitsOf(16.0f));
  CHECK(r.why.factor[4].fixes == (FixRoundedExponent | FixAngleCorrection));
  // Without the correction: exponent 3 -> 8.
  BonaventuraParams p;
  p.angleCorrection = false;
  r = bonaventura(square(0.0f, 0.0f, 0.0f, 1.0f), cam, p);
  CHECK(bitsOf(r.factors[4]) == bitsOf(8.0f));
  CHECK(r.why.factor[4].fixes == FixRoundedExponent);
  // Grazing: a point level with the eye at d = 260: acos(0) = pi/2, correction 0 * 0.5 + 0.75; exponent 2.25 -> 4.
  const Camera level = makeCamera(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 1.2f,
                                  0.5f, 5000.0f, glm::vec2(1920.0f, 1200.0f));
  BonaventuraParams q;
  q.frustumCull = false;
  r = bonaventura(square(0.0f, 0.0f, -260.0f, 1.0f), level, q);
  CHECK(bitsOf(std::acos(0.0f)) == bitsOf(1.57079632679489662f));
  CHECK(bitsOf(r.why.factor[4].exponent) == bitsOf(2.25f));
  CHECK(bitsOf(r.factors[4]) == bitsOf(4.0f));
  // Rounding: exponent exactly x.5 rounds up (floor(e + 0.5)); rank 0 = no correction effect.
  q.rank = 0.0f;
  q.minDistance = 0.0f;
  q.maxDistance = 400.0f;
  q.maxExponent = 5.0f;
  q.minExponent = 1.0f; // d = 260 along -z: s = 0.65 -> 5 + 0.65 * -4 = 2.4 -> 2 -> 4
  r = bonaventura(square(0.0f, 0.0f, -260.0f, 1.0f), level, q);
  INFO("exponent " << hex(r.why.factor[4].exponent));
  CHECK(bitsOf(r.factors[4]) == bitsOf(4.0f));
  r = bonaventura(square(0.0f, 0.0f, -250.0f, 1.0f), level, q); // s = 0.625, exponent 2.5 -> 3 -> 8
  CHECK(bitsOf(r.why.factor[4].exponent) == bitsOf(2.5f));
  CHECK(bitsOf(r.factors[4]) == bitsOf(8.0f));
}

TEST_CASE("bonaventura: factors are powers of two in [minFactor, maxFactor]", "[lod][bonaventura]") {
  for (int i = 0; i < 200; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    BonaventuraParams p;
    p.frustumCull = false;
    p.rank = 1.0f;
    p.minDistance = 5.0f;
    p.maxDistance = 80.0f;
    p.maxFactor = 32.0f;
    const PatchLod r = bonaventura(lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true), cam, p);
    for (float f : r.factors) {
      CHECK(f >= 1.0f);
      CHECK(f <= 32.0f);
      int e = 0;
      CHECK(std::frexp(f, &e) == 0.5f); // a power of two
    }
  }
}

TEST_CASE("bonaventura: four patches sharing a corner agree on its level, the literal fourth corner does not",
          "[lod][bonaventura]") {
  // Patches around the grid point (0, 0): it is corner 3 of the patch at (-8,-8), 2 of (0,-8), 1 of (-8,0), 0 of
  // (0,0).
  const Patch a = lodtest::terrainPatch(-8.0f, -8.0f, 8.0f, true);
  const Patch b = lodtest::terrainPatch(0.0f, -8.0f, 8.0f, true);
  const Patch c = lodtest::terrainPatch(-8.0f, 0.0f, 8.0f, true);
  const Patch d = lodtest::terrainPatch(0.0f, 0.0f, 8.0f, true);
  int literalDiffers = 0;
  for (int i = 0; i < 100; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    BonaventuraParams p;
    p.frustumCull = false;
    const float la = bonaventura(a, cam, p).why.cornerLevel[3];
    CHECK(bitsOf(la) == bitsOf(bonaventura(b, cam, p).why.cornerLevel[2]));
    CHECK(bitsOf(la) == bitsOf(bonaventura(c, cam, p).why.cornerLevel[1]));
    CHECK(bitsOf(la) == bitsOf(bonaventura(d, cam, p).why.cornerLevel[0]));
    p.literalFourthCornerAngle = true;
    if (bitsOf(bonaventura(a, cam, p).why.cornerLevel[3]) != bitsOf(bonaventura(d, cam, p).why.cornerLevel[0])) {
      ++literalDiffers;
    }
    // The literal switch touches only corner 3.
    CHECK(bitsOf(bonaventura(d, cam, p).why.cornerLevel[0]) == bitsOf(la));
  }
  CHECK(literalDiffers > 90);
}

TEST_CASE("bonaventura: culling", "[lod][bonaventura][culling]") {
  const Camera cam = fromAbove(260.0f);
  const PatchLod r = bonaventura(square(0.0f, 400.0f, 0.0f, 1.0f), cam); // above (behind) the eye
  CHECK(r.why.culled);
  for (float f : r.factors) {
    CHECK(bitsOf(f) == bitsOf(0.0f));
  }
  CHECK_FALSE(bonaventura(square(0.0f, 0.0f, 0.0f, 1.0f), cam).why.culled);
}

TEST_CASE("bonaventura: eye exactly on the evaluated point stays finite", "[lod][bonaventura]") {
  const Camera cam = fromAbove(0.0f); // the eye at the patch centre
  BonaventuraParams p;
  p.frustumCull = false;
  const PatchLod r = bonaventura(square(0.0f, 0.0f, 0.0f, 1.0f), cam, p);
  for (float f : r.factors) {
    CHECK(std::isfinite(f));
  }
  CHECK(bitsOf(r.factors[4]) == bitsOf(64.0f)); // d = 0: exponent 6 * 1.25 = 7.5 -> 8 -> clamped to 64
  CHECK((r.why.factor[4].fixes & FixClampedMax) != 0);
}
