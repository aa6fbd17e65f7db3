// The trace of Bound (lod/bound.h): where both sides of an edge run the same operations on the same input bits, their
// factors get the same node for every camera of a region (same-size neighbours; a tile-ring jump on flat integer
// corners, whose rebuilt corner folds into the larger patch's own corner), and one run answers the comparisons of
// both sides alike.
#include <catch2/catch.hpp>

#include <set>

#include "lod/lod_bound.h"
#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);
const glm::vec2 kViewport(1920.0f, 1200.0f);

BoundCamera regionCamera(glm::vec3 eyeLo, glm::vec3 eyeHi, glm::vec3 target) {
  return boundCameraRegion(eyeLo, eyeHi, target, target, kUp, 1.0f, 0.1f, 2000.0f, kViewport, false);
}

// The larger patch of a jump (x in [-2, 0], z in [0, 2]) and the two smaller ones along its +x edge, flat, integer
// corners. The larger's Ueq1 (corner 1 -> 3) is the smaller ones' rebuilt Ueq0.
struct Jump {
  Patch large = lodtest::terrainPatch(-2.0f, 0.0f, 2.0f, false);
  Patch small[2] = {lodtest::terrainPatch(0.0f, 0.0f, 1.0f, false), lodtest::terrainPatch(0.0f, 1.0f, 1.0f, false)};
  TileNeighbours largeSides;
  TileNeighbours smallSides[2];
  Jump() {
    largeSides.size[2] = 0.5f;
    for (int i = 0; i < 2; ++i) {
      smallSides[i].size[0] = 2.0f;
      smallSides[i].oddV = i == 1;
    }
  }
};

NvidiaTileParams tileParams(AdjacencyClamp clamp) {
  NvidiaTileParams p;
  p.clamp = clamp;
  p.sphere.maxFactor = 1000.0f; // the power-of-two clamp decides, not the factor clamp
  return p;
}

} // namespace

TEST_CASE("Bound trace: a same-size shared edge gets the same node on both sides for a camera region",
          "[lod][bound]") {
  const Patch a = lodtest::terrainPatch(2.0f, 3.0f, 1.0f, true);
  const Patch b = lodtest::terrainPatch(3.0f, 3.0f, 1.0f, true); // a's Ueq1 (x = 3) is b's Ueq0
  REQUIRE(bitsOf(a.corners[1].y) == bitsOf(b.corners[0].y));
  for (FloatModel model : {FloatModel::Cpp, FloatModel::Conformant}) {
    BoundContext ctx(model);
    int runs = 0;
    bool nonPoint = false;
    const bool complete = ctx.forEachPath([&] {
      ++runs;
      const BoundCamera cam =
          regionCamera(glm::vec3(20.0f, 8.0f, 25.0f), glm::vec3(20.0625f, 8.0625f, 25.0625f), glm::vec3(0.0f));
      const BoundPatchLod sides[3][2] = {
          {screenSphereBound(a, cam, {}), screenSphereBound(b, cam, {})},
          {distancePow2Bound(a, cam, {}), distancePow2Bound(b, cam, {})},
          {clipDiameterBound(a, cam, {}), clipDiameterBound(b, cam, {})},
      };
      for (const auto& s : sides) {
        INFO((model == FloatModel::Cpp ? "cpp" : "conformant") << " run " << runs << ": "
                                                                << ctx.describe(s[0].factors[2].node) << " vs "
                                                                << ctx.describe(s[1].factors[0].node));
        if (s[0].culled || s[1].culled) continue; // a run that culls (the region's planes are not decided)
        REQUIRE(s[0].factors[2].node == s[1].factors[0].node);
        REQUIRE(s[0].factors[1].node != s[1].factors[1].node); // different edges, different nodes
        nonPoint = nonPoint || !s[0].factors[2].point();
        uint32_t other = 0;
        REQUIRE(ctx.firstDifference(s[0].factors[2].node, s[1].factors[0].node, &other) == 0);
      }
    });
    REQUIRE(complete);
    REQUIRE(nonPoint); // the region moves the factor: the equality is the trace's, not the value's
  }
}

TEST_CASE("Bound trace: a tile-ring jump on flat integer corners rebuilds the larger patch's own edge factor",
          "[lod][bound]") {
  const Jump j;
  // Eyes along x: find two neighbouring eyes between which the larger patch's own edge factor crosses 16, so that
  // the power-of-two clamp branches inside the region.
  const glm::vec3 target(0.0f, 0.0f, 1.0f);
  glm::vec3 eyeLo(0.0f);
  glm::vec3 eyeHi(0.0f);
  bool found = false;
  float previous = 0.0f;
  for (int i = 0; i < 2000 && !found; ++i) {
    const glm::vec3 eye(6.0f + 0.05f * static_cast<float>(i), 6.0f, 1.0f);
    const Camera cam = makeCamera(eye, target, kUp, 1.0f, 0.1f, 2000.0f, kViewport);
    const float f = nvidiaTile(j.large, j.largeSides, cam, tileParams(AdjacencyClamp::None)).factors[2];
    if (i > 0 && previous > 16.0f && f <= 16.0f) {
      eyeLo = glm::vec3(eye.x - 0.05f, eye.y, eye.z);
      eyeHi = eye;
      found = true;
    }
    previous = f;
  }
  REQUIRE(found);
  for (FloatModel model : {FloatModel::Cpp, FloatModel::Conformant}) {
    // No clamp: the smaller side's factor is (the larger side's own factor) * 0.5, node for node.
    BoundContext ctx(model);
    bool nonPoint = false;
    const bool completeNone = ctx.forEachPath([&] {
      const BoundCamera cam = regionCamera(eyeLo, eyeHi, target);
      const NvidiaTileParams p = tileParams(AdjacencyClamp::None);
      const Bound own = nvidiaTileBound(j.large, j.largeSides, cam, p).factors[2];
      const Bound half = own * Bound(0.5f);
      for (int i = 0; i < 2; ++i) {
        const Bound rebuilt = nvidiaTileBound(j.small[i], j.smallSides[i], cam, p).factors[0];
        INFO("small patch " << i << ": " << ctx.describe(rebuilt.node, 6) << " vs " << ctx.describe(half.node, 6));
        REQUIRE(rebuilt.node == half.node);
      }
      nonPoint = nonPoint || !own.point();
    });
    REQUIRE(completeNone);
    REQUIRE(nonPoint);
    // Power-of-two clamp: the runs branch on the larger factor; each run gives both sides the same choice.
    std::set<uint32_t> largerValues;
    const bool completePow2 = ctx.forEachPath([&] {
      const BoundCamera cam = regionCamera(eyeLo, eyeHi, target);
      const NvidiaTileParams p = tileParams(AdjacencyClamp::Pow2);
      const Bound large = nvidiaTileBound(j.large, j.largeSides, cam, p).factors[2];
      REQUIRE(large.point());
      largerValues.insert(bitsOf(large.lo));
      for (int i = 0; i < 2; ++i) {
        const Bound small = nvidiaTileBound(j.small[i], j.smallSides[i], cam, p).factors[0];
        INFO("small patch " << i << " " << hex(small.lo) << " larger " << hex(large.lo));
        REQUIRE(small.point());
        REQUIRE(bitsOf(small.lo * 2.0f) == bitsOf(large.lo));
      }
    });
    REQUIRE(completePow2);
    REQUIRE(largerValues.size() == 2); // 16 and 32: the region straddles the clamp's threshold
  }
}

TEST_CASE("Bound trace: describe and firstDifference name the operation where two traces part", "[lod][bound]") {
  BoundContext ctx(FloatModel::Conformant);
  BoundContext::Scope scope(ctx);
  const Bound p = Bound::input(1.0f, 2.0f, 1);
  const Bound q = Bound::input(3.0f, 4.0f, 2);
  const Bound three(3.0f);
  // (p * 3 + q * 3) on one side, (q * 3 + p * 3) on the other: equal on the C++ build, not once a compiler fuses
  // the first product of each.
  const Bound left = p * three + q * three;
  const Bound right = q * three + p * three;
  REQUIRE(left.node != right.node);
  uint32_t other = 0;
  const uint32_t first = ctx.firstDifference(left.node, right.node, &other);
  REQUIRE(first == left.node);
  REQUIRE(other == right.node);
  REQUIRE(ctx.describe(left.node) == "add~fma(mul~gpu(input 1 [1, 2], 3 (0x40400000)), mul~gpu(input 2 [3, 4], 3 "
                                     "(0x40400000)))");
  // Under Cpp the two orders are one node (a + b is b + a bit for bit without contraction).
  BoundContext cpp(FloatModel::Cpp);
  BoundContext::Scope cppScope(cpp);
  const Bound three2(3.0f);
  const Bound p2 = Bound::input(1.0f, 2.0f, 1);
  const Bound q2 = Bound::input(3.0f, 4.0f, 2);
  REQUIRE((p2 * three2 + q2 * three2).node == (q2 * three2 + p2 * three2).node);
  // A deeper difference: the same operation over one differing operand is followed into that operand.
  const Bound x = sqrt(p2 * three2 + q2);
  const Bound y = sqrt(p2 * Bound(5.0f) + q2);
  const uint32_t d = cpp.firstDifference(x.node, y.node, &other);
  // (mul is commutative: its operands are kept in node order)
  REQUIRE(cpp.describe(d, 1) == "mul(3 (0x40400000), input 1 [1, 2])");
  REQUIRE(cpp.describe(other, 1) == "mul(input 1 [1, 2], 5 (0x40a00000))");
}
