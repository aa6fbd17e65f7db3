// Scheme 2: non-uniform patches in tile rings (rebuilt neighbour edge, half factor, integer / pow2 clamps).
#include <catch2/catch.hpp>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {

NvidiaTileParams tileParams(float triWidth, AdjacencyClamp clamp, Reconstruction rebuild) {
  NvidiaTileParams p;
  p.sphere.tessellatedTriWidth = triWidth;
  p.clamp = clamp;
  p.reconstruction = rebuild;
  return p;
}

} // namespace

TEST_CASE("nvidiaTile: smaller side rebuilds the larger edge and halves its factor (hand-computed)",
          "[lod][nvidia_tile]") {
  // The patch's Ueq0 runs from (-1,-1,-8) to (-1,1,-8). Rebuilt (even: beyond the end corner) it runs to the far
  // corner (-1,3,-8); odd: from (-1,-3,-8). (The patch faces the camera, so y is not a height here: FarCorner.) Either way a sphere of diameter 4 at distance 8: 4/8 * 960 = 480 px.
  // 480 / 14 = 34.2857132 (float), so: none -> 17.1428566, integer -> 36 / 2 = 18, pow2 -> 64 / 2 = 32.
  const Camera cam = lodtest::exactCamera();
  const Patch patch = lodtest::facingPatch(0.0f, 0.0f, -8.0f);
  const float f = 480.0f / 14.0f;
  struct Case {
    AdjacencyClamp clamp;
    float want;
    uint32_t fix;
  } cases[] = {{AdjacencyClamp::None, f * 0.5f, 0u},
               {AdjacencyClamp::Integer, 18.0f, FixIntegerClamp},
               {AdjacencyClamp::Pow2, 32.0f, FixPow2Clamp}};
  for (const Case& c : cases) {
    for (bool odd : {false, true}) {
      TileNeighbours n;
      n.size[0] = 2.0f;
      n.oddV = odd;
      n.farCorner[0] = glm::vec3(-1.0f, odd ? -3.0f : 3.0f, -8.0f);
      const PatchLod r = nvidiaTile(patch, n, cam, tileParams(14.0f, c.clamp, Reconstruction::FarCorner));
      INFO("clamp " << static_cast<int>(c.clamp) << " odd " << odd << " got " << hex(r.factors[0]));
      CHECK(bitsOf(r.factors[0]) == bitsOf(c.want));
      CHECK(bitsOf(r.why.factor[0].metric) == bitsOf(480.0f));
      CHECK(r.why.factor[0].fixes == (FixLargerNeighbour | c.fix));
      // The other edges see same-size neighbours: 240 px / 14.
      CHECK(bitsOf(r.factors[1]) == bitsOf(240.0f / 14.0f));
      CHECK(r.why.factor[1].fixes == FixNone);
      // Inside factors come from the patch's own edges, not the halved one.
      CHECK(bitsOf(r.factors[5]) == bitsOf(240.0f / 14.0f));
    }
  }
  CHECK(bitsOf(f * 0.5f) == bitsOf(17.1428566f));
}

TEST_CASE("nvidiaTile: larger side rounds its own factor", "[lod][nvidia_tile]") {
  const Camera cam = lodtest::exactCamera();
  const Patch patch = lodtest::facingPatch(0.0f, 0.0f, -8.0f); // 240 px per edge
  TileNeighbours n;
  n.size[2] = 0.5f;
  // 240 / 14 = 17.142857: integer -> 18, pow2 -> 32, none -> as is.
  CHECK(bitsOf(nvidiaTile(patch, n, cam, tileParams(14.0f, AdjacencyClamp::Integer, Reconstruction::EdgeVector))
                 .factors[2]) == bitsOf(18.0f));
  CHECK(bitsOf(nvidiaTile(patch, n, cam, tileParams(14.0f, AdjacencyClamp::Pow2, Reconstruction::EdgeVector))
                 .factors[2]) == bitsOf(32.0f));
  CHECK(bitsOf(nvidiaTile(patch, n, cam, tileParams(14.0f, AdjacencyClamp::None, Reconstruction::EdgeVector))
                 .factors[2]) == bitsOf(240.0f / 14.0f));
  // 240 / 120 = 2 -> pow2 lower bound 4; integer lower bound 4 too (the sample's recipe: larger side >= 4).
  CHECK(bitsOf(nvidiaTile(patch, n, cam, tileParams(120.0f, AdjacencyClamp::Pow2, Reconstruction::EdgeVector))
                 .factors[2]) == bitsOf(4.0f));
  CHECK(bitsOf(nvidiaTile(patch, n, cam, tileParams(120.0f, AdjacencyClamp::Integer, Reconstruction::EdgeVector))
                 .factors[2]) == bitsOf(4.0f));
  const PatchLod r = nvidiaTile(patch, n, cam, tileParams(14.0f, AdjacencyClamp::Pow2, Reconstruction::EdgeVector));
  CHECK(r.why.factor[2].fixes == (FixSmallerNeighbour | FixPow2Clamp));
}

TEST_CASE("nvidiaTile: clamp ranges over a camera sweep", "[lod][nvidia_tile]") {
  // Pow2: larger side in {4, 8, 16, 32, 64}, smaller side in {2, .., 32}; integer: larger side even, smaller
  // side its half; both sides of a jump agree (smaller == larger / 2) when the far corner is given.
  const Patch big = lodtest::terrainPatch(0.0f, 0.0f, 16.0f, true);
  Patch small0 = lodtest::terrainPatch(-8.0f, 0.0f, 8.0f, true); // its Ueq1 is the first half of big's Ueq0
  Patch small1 = lodtest::terrainPatch(-8.0f, 8.0f, 8.0f, true); // the second half
  TileNeighbours nb;
  nb.size[0] = 0.5f;
  TileNeighbours n0, n1;
  n0.size[2] = 2.0f;
  n0.oddV = false;
  n0.farCorner[2] = big.corners[2];
  n1.size[2] = 2.0f;
  n1.oddV = true;
  n1.farCorner[2] = big.corners[0];
  int checked = 0;
  for (AdjacencyClamp clamp : {AdjacencyClamp::None, AdjacencyClamp::Integer, AdjacencyClamp::Pow2}) {
    for (int i = 0; i < 300; ++i) {
      const Camera cam = lodtest::sweepCamera(i);
      NvidiaTileParams p = tileParams(3.0f, clamp, Reconstruction::FarCorner);
      p.sphere.frustumCull = false;
      const float L = nvidiaTile(big, nb, cam, p).factors[0];
      const float s0 = nvidiaTile(small0, n0, cam, p).factors[2];
      const float s1 = nvidiaTile(small1, n1, cam, p).factors[2];
      INFO("camera " << i << " clamp " << static_cast<int>(clamp) << " L " << hex(L) << " s0 " << hex(s0));
      CHECK(bitsOf(s0) == bitsOf(s1));
      CHECK(bitsOf(s0) == bitsOf(L * 0.5f));
      if (clamp == AdjacencyClamp::Pow2) {
        CHECK((L == 4.0f || L == 8.0f || L == 16.0f || L == 32.0f || L == 64.0f));
        CHECK(s0 >= 2.0f);
        CHECK(s0 <= 32.0f);
      }
      if (clamp == AdjacencyClamp::Integer) {
        CHECK(std::fmod(L, 2.0f) == 0.0f);
        CHECK(L >= 4.0f);
        CHECK(L <= 64.0f);
        CHECK(std::floor(s0) == s0);
      }
      ++checked;
    }
  }
  CHECK(checked == 900);
}

TEST_CASE("nvidiaTile: EdgeVector rebuild agrees on flat exact terrain, can miss on displaced terrain",
          "[lod][nvidia_tile]") {
  // Flat, integer coordinates: p1 + (p1 - p0) is exact, so the rebuilt edge is the larger patch's edge.
  const Patch big = lodtest::terrainPatch(0.0f, 0.0f, 16.0f, false);
  const Patch small0 = lodtest::terrainPatch(-8.0f, 0.0f, 8.0f, false);
  TileNeighbours nb;
  nb.size[0] = 0.5f;
  TileNeighbours n0;
  n0.size[2] = 2.0f;
  int mismatchesDisplaced = 0;
  const Patch bigD = lodtest::terrainPatch(3.0f, 0.0f, 16.0f, true); // x = 3: heights vary along the edge
  const Patch small0D = lodtest::terrainPatch(-5.0f, 0.0f, 8.0f, true);
  for (int i = 0; i < 100; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    NvidiaTileParams p = tileParams(60.0f, AdjacencyClamp::None, Reconstruction::EdgeVector);
    p.sphere.frustumCull = false;
    CHECK(bitsOf(nvidiaTile(small0, n0, cam, p).factors[2]) == bitsOf(nvidiaTile(big, nb, cam, p).factors[0] * 0.5f));
    CHECK(nvidiaTile(bigD, nb, cam, p).why.factor[0].fixes == FixSmallerNeighbour); // unclamped: 60 px triangles
    if (bitsOf(nvidiaTile(small0D, n0, cam, p).factors[2]) != bitsOf(nvidiaTile(bigD, nb, cam, p).factors[0] * 0.5f)) {
      ++mismatchesDisplaced;
    }
  }
  // Displaced: the rebuilt far end has the wrong height, so the two sides compute different spheres.
  CHECK(mismatchesDisplaced > 0);
}

TEST_CASE("nvidiaTile: culling writes -1", "[lod][nvidia_tile][culling]") {
  const Camera cam = lodtest::exactCamera();
  TileNeighbours n;
  n.size[0] = 2.0f;
  const PatchLod r = nvidiaTile(lodtest::facingPatch(0.0f, 0.0f, 8.0f), n, cam);
  CHECK(r.why.culled);
  for (float f : r.factors) {
    CHECK(bitsOf(f) == bitsOf(-1.0f));
  }
}

TEST_CASE("assignNeighbourSizes and patchNeighbours", "[lod][nvidia_tile]") {
  // A ring 4 tiles wide with a 2-tile hole (tiles 1..2), not the outermost.
  TileSides t = assignNeighbourSizes(0, 0, 2, 4, false);
  CHECK((t.size[0] == 2.0f && t.size[1] == 2.0f && t.size[2] == 1.0f && t.size[3] == 1.0f));
  t = assignNeighbourSizes(0, 1, 2, 4, false); // left of the hole
  CHECK((t.size[0] == 2.0f && t.size[1] == 1.0f && t.size[2] == 0.5f && t.size[3] == 1.0f));
  t = assignNeighbourSizes(3, 2, 2, 4, false); // right of the hole
  CHECK((t.size[0] == 0.5f && t.size[1] == 1.0f && t.size[2] == 2.0f && t.size[3] == 1.0f));
  t = assignNeighbourSizes(1, 0, 2, 4, false); // below the hole
  CHECK((t.size[0] == 1.0f && t.size[1] == 2.0f && t.size[2] == 1.0f && t.size[3] == 0.5f));
  t = assignNeighbourSizes(2, 3, 2, 4, true); // above the hole, outermost ring
  CHECK((t.size[0] == 1.0f && t.size[1] == 0.5f && t.size[2] == 1.0f && t.size[3] == 1.0f));
  t = assignNeighbourSizes(1, 1, 0, 4, false); // innermost ring (no hole), interior tile
  CHECK((t.size[0] == 1.0f && t.size[1] == 1.0f && t.size[2] == 1.0f && t.size[3] == 1.0f));

  TileSides side;
  side.size[0] = 2.0f;
  side.size[3] = 0.5f;
  TileNeighbours n = patchNeighbours(side, 0, 7, 8);
  CHECK((n.size[0] == 2.0f && n.size[1] == 1.0f && n.size[2] == 1.0f && n.size[3] == 0.5f));
  CHECK_FALSE(n.oddU);
  CHECK(n.oddV);
  n = patchNeighbours(side, 3, 4, 8);
  CHECK((n.size[0] == 1.0f && n.size[3] == 1.0f));
  CHECK(n.oddU);
  CHECK_FALSE(n.oddV);
}

// ---------------------------------------------------------------------------------------------------------------
// The neighbour rule for every scheme (lod.h section 7) and the integer clamp's recipe.

namespace {

enum class Base { Sphere, Distance, Bonaventura, Clip };
const char* baseName(Base b) {
  switch (b) {
  case Base::Sphere: return "screen_sphere";
  case Base::Distance: return "distance_pow2";
  case Base::Bonaventura: return "bonaventura";
  case Base::Clip: return "clip_diameter";
  }
  return "?";
}

PatchLod tileLod(Base b, const Patch& p, const TileNeighbours& n, const Camera& cam, TileAdjacency adj) {
  switch (b) {
  case Base::Sphere: {
    NvidiaTileParams t = tileParams(60.0f, adj.clamp, adj.reconstruction); // 60 px: mostly below the 64 clamp
    t.sphere.frustumCull = false;
    return nvidiaTile(p, n, cam, t);
  }
  case Base::Distance: {
    DistancePow2Params d;
    d.frustumCull = false;
    return distancePow2Tile(p, n, cam, d, adj);
  }
  case Base::Bonaventura: {
    BonaventuraParams d;
    d.frustumCull = false;
    return bonaventuraTile(p, n, cam, d, adj);
  }
  case Base::Clip: return clipDiameterTile(p, n, cam, ClipDiameterParams{}, adj);
  }
  return {};
}

PatchLod ownLod(Base b, const Patch& p, const Camera& cam) {
  switch (b) {
  case Base::Sphere: {
    ScreenSphereParams s;
    s.tessellatedTriWidth = 60.0f;
    s.frustumCull = false;
    return screenSphere(p, cam, s);
  }
  case Base::Distance: {
    DistancePow2Params d;
    d.frustumCull = false;
    return distancePow2(p, cam, d);
  }
  case Base::Bonaventura: {
    BonaventuraParams d;
    d.frustumCull = false;
    return bonaventura(p, cam, d);
  }
  case Base::Clip: return clipDiameter(p, cam, ClipDiameterParams{});
  }
  return {};
}

float largerOf(float f, AdjacencyClamp c) {
  if (c == AdjacencyClamp::Pow2) return f <= 4.0f ? 4.0f : f <= 8.0f ? 8.0f : f <= 16.0f ? 16.0f : f <= 32.0f ? 32.0f : 64.0f;
  if (c == AdjacencyClamp::Integer) return std::fmin(std::fmax(std::ceil(f * 0.5f) * 2.0f, 4.0f), 64.0f);
  return f;
}

} // namespace

TEST_CASE("tile rule, every scheme: the smaller side takes the scheme's factor of the rebuilt edge, halved",
          "[lod][nvidia_tile][tile_rule]") {
  // big (16 x 16 at x = 3) and its two half-size neighbours across its Ueq0 (x = 3; heights vary along it):
  // small0 covers z 0..8 (even), small1 z 8..16 (odd). Displaced corners (terrainHeight). With Resampled the small
  // sides are handed the height at rebuiltCorner's x/z, computed by lod::rebuiltCorner as verify's layout does;
  // FarCorner the big patch's corner.
  const Patch big = lodtest::terrainPatch(3.0f, 0.0f, 16.0f, true);
  const Patch small0 = lodtest::terrainPatch(-5.0f, 0.0f, 8.0f, true);
  const Patch small1 = lodtest::terrainPatch(-5.0f, 8.0f, 8.0f, true);
  TileNeighbours nb;
  nb.size[0] = 0.5f;
  auto smallSide = [](const Patch& p, bool odd, const glm::vec3& far) {
    TileNeighbours n;
    n.size[2] = 2.0f; // Ueq1 = corners 1-3
    n.oddV = odd;
    n.farCorner[2] = far;
    const glm::vec3 c = rebuiltCorner(p.corners[1], p.corners[3], odd);
    n.rebuiltHeight[2] = lodtest::terrainHeight(c.x, c.z);
    return n;
  };
  const TileNeighbours n0 = smallSide(small0, false, big.corners[2]);
  const TileNeighbours n1 = smallSide(small1, true, big.corners[0]);
  // The rebuilt corner's x/z are the far corner's here (exact coordinates).
  CHECK(rebuiltCorner(small0.corners[1], small0.corners[3], false).z == big.corners[2].z);
  CHECK(rebuiltCorner(small1.corners[1], small1.corners[3], true).z == big.corners[0].z);
  CHECK(bitsOf(rebuiltCorner(small0.corners[1], small0.corners[3], false).y) == bitsOf(small0.corners[3].y));

  for (Base b : {Base::Sphere, Base::Distance, Base::Bonaventura, Base::Clip}) {
    for (AdjacencyClamp clamp : {AdjacencyClamp::None, AdjacencyClamp::Integer, AdjacencyClamp::Pow2}) {
      const uint32_t clampBit = clamp == AdjacencyClamp::Pow2      ? FixPow2Clamp
                                : clamp == AdjacencyClamp::Integer ? FixIntegerClamp
                                                                   : FixNone;
      int edgeVectorMisses = 0;
      for (Reconstruction rec : {Reconstruction::Resampled, Reconstruction::FarCorner, Reconstruction::EdgeVector}) {
        for (int i = 0; i < 120; ++i) {
          const Camera cam = lodtest::sweepCamera(i);
          const TileAdjacency adj{clamp, rec};
          const PatchLod own = ownLod(b, big, cam);
          const PatchLod L = tileLod(b, big, nb, cam, adj);
          const PatchLod s0 = tileLod(b, small0, n0, cam, adj);
          const PatchLod s1 = tileLod(b, small1, n1, cam, adj);
          INFO(baseName(b) << " clamp " << int(clamp) << " rec " << int(rec) << " camera " << i << " L "
                           << hex(L.factors[0]) << " s0 " << hex(s0.factors[2]) << " s1 " << hex(s1.factors[2]));
          // Larger side: larger(own factor), fixes recorded.
          CHECK(bitsOf(L.factors[0]) == bitsOf(largerOf(own.factors[0], clamp)));
          CHECK(L.why.factor[0].fixes == (own.why.factor[0].fixes | FixSmallerNeighbour | clampBit));
          // Everything else is the scheme's own (edges without a jump, inside factors).
          for (int k = 1; k < 6; ++k) CHECK(bitsOf(L.factors[k]) == bitsOf(own.factors[k]));
          CHECK(bitsOf(s0.factors[5]) == bitsOf(ownLod(b, small0, cam).factors[5]));
          CHECK((s0.why.factor[2].fixes & (FixLargerNeighbour | clampBit)) == (FixLargerNeighbour | clampBit));
          const bool agree = bitsOf(s0.factors[2]) == bitsOf(L.factors[0] * 0.5f) &&
                             bitsOf(s1.factors[2]) == bitsOf(L.factors[0] * 0.5f);
          if (rec == Reconstruction::EdgeVector) {
            edgeVectorMisses += agree ? 0 : 1;
          } else {
            CHECK(agree);
          }
        }
      }
      // The literal edge vector keeps the moved-from corner's height: on displaced corners it misses somewhere
      // (except where the scheme's factor does not depend on the height there).
      INFO(baseName(b) << " clamp " << int(clamp) << " edge_vector misses " << edgeVectorMisses);
      if (b != Base::Bonaventura && clamp == AdjacencyClamp::None) CHECK(edgeVectorMisses > 0);
    }
  }
}

TEST_CASE("tile rule: the integer clamp is the sample's recipe, NaN stays visible", "[lod][nvidia_tile][tile_rule]") {
  TileNeighbours n;
  n.size[0] = 2.0f; // Ueq0: smaller side
  n.size[2] = 0.5f; // Ueq1: larger side
  struct Case {
    float factor, larger;
  } cases[] = {{1.0f, 4.0f},   {2.0f, 4.0f},   {3.0f, 4.0f},   {4.0f, 4.0f},   {4.5f, 6.0f},  {6.0f, 6.0f},
               {11.0f, 12.0f}, {12.0f, 12.0f}, {63.5f, 64.0f}, {64.0f, 64.0f}, {100.0f, 64.0f}};
  for (const Case& c : cases) {
    const PatchLod r = constantTile(c.factor, n, {AdjacencyClamp::Integer, Reconstruction::EdgeVector});
    INFO("factor " << c.factor << " larger " << hex(r.factors[2]) << " smaller " << hex(r.factors[0]));
    CHECK(bitsOf(r.factors[2]) == bitsOf(c.larger));
    CHECK(bitsOf(r.factors[0]) == bitsOf(c.larger * 0.5f));
    CHECK(r.factors[0] >= 2.0f);
    CHECK(r.factors[0] <= 32.0f);
    CHECK(r.why.factor[0].fixes == (FixLargerNeighbour | FixIntegerClamp));
    CHECK(r.why.factor[2].fixes == (FixSmallerNeighbour | FixIntegerClamp));
    CHECK(bitsOf(r.factors[1]) == bitsOf(c.factor)); // no jump: the constant itself
    CHECK(r.why.scheme == Scheme::Constant);
  }
  // NaN: none and integer keep NaN on both sides of the jump (the tessellator then culls the patch); pow2 maps it
  // to 4 and 2 by its comparisons (the existing rule, unchanged).
  const float nan = std::nanf("");
  for (AdjacencyClamp c : {AdjacencyClamp::None, AdjacencyClamp::Integer}) {
    const PatchLod r = constantTile(nan, n, {c, Reconstruction::EdgeVector});
    CHECK(std::isnan(r.factors[0]));
    CHECK(std::isnan(r.factors[2]));
  }
  const PatchLod p = constantTile(nan, n, {AdjacencyClamp::Pow2, Reconstruction::EdgeVector});
  CHECK(bitsOf(p.factors[2]) == bitsOf(4.0f));
  CHECK(bitsOf(p.factors[0]) == bitsOf(2.0f));
  CHECK(std::isnan(p.factors[1]));
  // The same through a camera scheme: a NaN corner gives NaN factors; integer keeps them NaN at the jump.
  Patch bad = lodtest::terrainPatch(0.0f, 0.0f, 8.0f, false);
  bad.corners[0].y = nan;
  DistancePow2Params d;
  d.frustumCull = false;
  const PatchLod r = distancePow2Tile(bad, n, lodtest::sweepCamera(3), d, {AdjacencyClamp::Integer, Reconstruction::EdgeVector});
  CHECK(std::isnan(r.factors[0]));
}
