// Scheme 6: geomorphing tween factors.
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;

TEST_CASE("geomorph: level from distance (hand-computed)", "[lod][geomorph]") {
  // Centre at d = 260: s = 0.5, level 5 + 0.5 * (0 - 5) = 2.5.
  const Camera cam = makeCamera(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f), 1.2f,
                                0.5f, 5000.0f, glm::vec2(1920.0f, 1200.0f));
  Patch p;
  p.corners[0] = glm::vec3(-1.0f, 0.0f, -261.0f);
  p.corners[1] = glm::vec3(1.0f, 0.0f, -261.0f);
  p.corners[2] = glm::vec3(-1.0f, 0.0f, -259.0f);
  p.corners[3] = glm::vec3(1.0f, 0.0f, -259.0f);
  CHECK(bitsOf(geomorphLevel(p, cam)) == bitsOf(2.5f));
  for (glm::vec3& c : p.corners) {
    c.z -= 1000.0f;
  }
  CHECK(bitsOf(geomorphLevel(p, cam)) == bitsOf(0.0f));
}

TEST_CASE("geomorph: factors follow the coarser neighbour", "[lod][geomorph]") {
  const float n[4] = {2.5f, 1.25f, 3.0f, 2.75f};
  const PatchLod r = geomorph(2.5f, n);
  // Edges: 2^(floor(min(2.5, n)) + 1): 8, 4, 8, 8; inside 2^(2 + 1) = 8.
  const float want[6] = {8.0f, 4.0f, 8.0f, 8.0f, 8.0f, 8.0f};
  for (int i = 0; i < 6; ++i) {
    CHECK(bitsOf(r.factors[i]) == bitsOf(want[i]));
  }
  CHECK(r.why.factor[1].fixes == FixCoarserNeighbour);
  CHECK(r.why.factor[0].fixes == FixNone);
  CHECK(r.why.factor[2].fixes == FixNone);
  // Level range: factors always in {2, 4, .., 64}.
  const float extremes[] = {-3.0f, 0.0f, 0.999f, 5.0f, 5.999f, 9.0f, 1e30f};
  for (float l : extremes) {
    const float same[4] = {l, l, l, l};
    const PatchLod e = geomorph(l, same);
    for (float f : e.factors) {
      CHECK(f >= 2.0f);
      CHECK(f <= 64.0f);
    }
  }
  const float nanLevels[4] = {NAN, NAN, NAN, NAN};
  CHECK(bitsOf(geomorph(NAN, nanLevels).factors[0]) == bitsOf(2.0f));
}

TEST_CASE("geomorph: border heights, hand-computed, and both sides agree", "[lod][geomorph]") {
  // Fine heights h(i) = i*i at t = i/64. Levels 2.5 and 1.25: border level 1.25 -> 4 segments, tween 0.25.
  // k = 1 (t = 16/64): midpoint of h(0) = 0 and h(32) = 1024 is 512, true 256: 512 + 0.25 * (256 - 512) = 448.
  // k = 3 (t = 48/64): midpoint of 1024 and 4096 = 2560, true 2304: 2560 + 0.25 * -256 = 2496.
  float fine[65];
  for (int i = 0; i < 65; ++i) {
    fine[i] = static_cast<float>(i * i);
  }
  const GeomorphEdge a = geomorphEdgeHeights(2.5f, 1.25f, fine);
  const GeomorphEdge b = geomorphEdgeHeights(1.25f, 2.5f, fine);
  REQUIRE(a.segments == 4);
  const float want[5] = {0.0f, 448.0f, 1024.0f, 2496.0f, 4096.0f};
  for (int k = 0; k <= 4; ++k) {
    CHECK(bitsOf(a.heights[k]) == bitsOf(want[k]));
  }
  CHECK(b.segments == a.segments);
  for (int k = 0; k < 65; ++k) {
    CHECK(bitsOf(a.heights[k]) == bitsOf(b.heights[k]));
  }
  // Finest: level 5.x -> 64 segments, every height its own sample when even.
  const GeomorphEdge f = geomorphEdgeHeights(5.5f, 5.75f, fine);
  CHECK(f.segments == 64);
  CHECK(bitsOf(f.heights[64]) == bitsOf(4096.0f));
}

TEST_CASE("geomorph: the article's literal inserted-vertex weight is not symmetric", "[lod][geomorph]") {
  float fine[65];
  for (int i = 0; i < 65; ++i) {
    fine[i] = static_cast<float>(i * i);
  }
  GeomorphParams p;
  p.literalArticleWeight = true;
  // Same whole level (2), tweens 0.5 and 0.25: weights (1 - 0.25) * 0.5 = 0.375 and (1 - 0.5) * 0.25 = 0.125.
  const GeomorphEdge a = geomorphEdgeHeights(2.5f, 2.25f, fine, p);
  const GeomorphEdge b = geomorphEdgeHeights(2.25f, 2.5f, fine, p);
  REQUIRE(a.segments == 8);
  REQUIRE(b.segments == 8);
  // k = 1 (t = 8/64): midpoint (0 + 256) / 2 = 128, true 64: 128 - 64 * w.
  CHECK(bitsOf(a.heights[1]) == bitsOf(128.0f - 64.0f * 0.375f));
  CHECK(bitsOf(b.heights[1]) == bitsOf(128.0f - 64.0f * 0.125f));
  CHECK(bitsOf(a.heights[1]) != bitsOf(b.heights[1]));
}

TEST_CASE("geomorph: the per-vertex pieces (weight, morphed height), hand-computed", "[lod][geomorph]") {
  // Border weight: the tween of min(L, Ln), the same from both sides.
  CHECK(bitsOf(geomorphWeight(2.25f, 3.5f)) == bitsOf(0.25f));
  CHECK(bitsOf(geomorphWeight(3.5f, 2.25f)) == bitsOf(0.25f));
  CHECK(bitsOf(geomorphWeight(2.75f, 2.75f)) == bitsOf(0.75f));
  // The article's weight (1 - tween(Ln)) * tween(L): (1 - 0.5) * 0.25 = 0.125 one way, (1 - 0.25) * 0.5 = 0.375 the
  // other.
  GeomorphParams lit;
  lit.literalArticleWeight = true;
  CHECK(bitsOf(geomorphWeight(2.25f, 3.5f, lit)) == bitsOf(0.125f));
  CHECK(bitsOf(geomorphWeight(3.5f, 2.25f, lit)) == bitsOf(0.375f));
  // m = (2 + 6) * 0.5 = 4; 4 + 0.25 * (8 - 4) = 5. Tween 0: the midpoint; tween 1: the true height.
  CHECK(bitsOf(geomorphHeight(8.0f, 2.0f, 6.0f, 0.25f)) == bitsOf(5.0f));
  CHECK(bitsOf(geomorphHeight(8.0f, 2.0f, 6.0f, 0.0f)) == bitsOf(4.0f));
  CHECK(bitsOf(geomorphHeight(8.0f, 2.0f, 6.0f, 1.0f)) == bitsOf(8.0f));
}
