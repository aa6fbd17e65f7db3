// The schemes over Bounds (lod/lod_bound.h) against the float build (lod.h): a point camera gives the float build's
// factors bit for bit; a camera region holds, in one of its runs, every factor of every sampled camera inside it;
// the camera region's view holds every makeCamera view inside it; the trace proves shared edges equal.
#include <catch2/catch.hpp>

#include <functional>
#include <random>
#include <vector>

#include "lod/lod_bound.h"
#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {

const glm::vec3 kUp(0.0f, 1.0f, 0.0f);
const glm::vec2 kViewport(1920.0f, 1200.0f);

float uniform(std::mt19937& rng, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(rng); }

glm::vec3 uniformIn(std::mt19937& rng, glm::vec3 lo, glm::vec3 hi) {
  return glm::vec3(uniform(rng, lo.x, hi.x), uniform(rng, lo.y, hi.y), uniform(rng, lo.z, hi.z));
}

// One scheme, both builds, with the same patch, neighbours and parameters.
struct SchemeCase {
  const char* name;
  std::function<PatchLod(const Patch&, const Camera&)> plain;
  std::function<BoundPatchLod(const Patch&, const BoundCamera&)> bounded;
};

std::vector<SchemeCase> schemeCases(const TileNeighbours& n, const TileAdjacency& adj) {
  NvidiaTileParams tile;
  tile.clamp = adj.clamp;
  tile.reconstruction = adj.reconstruction;
  DistancePow2Params dp;
  dp.minDistance = 5.0f;
  dp.maxDistance = 80.0f;
  BonaventuraParams bp;
  bp.minDistance = 5.0f;
  bp.maxDistance = 80.0f;
  ClipDiameterParams cp;
  cp.frustumCull = true;
  const ScreenSphereParams sp;
  return {
      {"screen_sphere", [=](const Patch& p, const Camera& c) { return screenSphere(p, c, sp); },
       [=](const Patch& p, const BoundCamera& c) { return screenSphereBound(p, c, sp); }},
      {"patch_center", [=](const Patch& p, const Camera& c) { return patchCenter(p, c, sp); },
       [=](const Patch& p, const BoundCamera& c) { return patchCenterBound(p, c, sp); }},
      {"nvidia_tile", [=](const Patch& p, const Camera& c) { return nvidiaTile(p, n, c, tile); },
       [=](const Patch& p, const BoundCamera& c) { return nvidiaTileBound(p, n, c, tile); }},
      {"distance_pow2", [=](const Patch& p, const Camera& c) { return distancePow2(p, c, dp); },
       [=](const Patch& p, const BoundCamera& c) { return distancePow2Bound(p, c, dp); }},
      {"distance_pow2_tile", [=](const Patch& p, const Camera& c) { return distancePow2Tile(p, n, c, dp, adj); },
       [=](const Patch& p, const BoundCamera& c) { return distancePow2TileBound(p, n, c, dp, adj); }},
      {"bonaventura", [=](const Patch& p, const Camera& c) { return bonaventura(p, c, bp); },
       [=](const Patch& p, const BoundCamera& c) { return bonaventuraBound(p, c, bp); }},
      {"bonaventura_tile", [=](const Patch& p, const Camera& c) { return bonaventuraTile(p, n, c, bp, adj); },
       [=](const Patch& p, const BoundCamera& c) { return bonaventuraTileBound(p, n, c, bp, adj); }},
      {"clip_diameter", [=](const Patch& p, const Camera& c) { return clipDiameter(p, c, cp); },
       [=](const Patch& p, const BoundCamera& c) { return clipDiameterBound(p, c, cp); }},
      {"clip_diameter_tile", [=](const Patch& p, const Camera& c) { return clipDiameterTile(p, n, c, cp, adj); },
       [=](const Patch& p, const BoundCamera& c) { return clipDiameterTileBound(p, n, c, cp, adj); }},
      {"constant_tile", [=](const Patch&, const Camera&) { return constantTile(5.5f, n, adj); },
       [=](const Patch&, const BoundCamera&) { return constantTileBound(5.5f, n, adj); }},
  };
}

// Random neighbours and adjacency settings for the tile variants.
void randomTile(std::mt19937& rng, TileNeighbours& n, TileAdjacency& adj) {
  const float sizes[3] = {0.5f, 1.0f, 2.0f};
  for (int e = 0; e < 4; ++e) {
    n.size[e] = sizes[rng() % 3];
    n.farCorner[e] = uniformIn(rng, glm::vec3(-20.0f, -2.0f, -20.0f), glm::vec3(20.0f, 2.0f, 20.0f));
    n.rebuiltHeight[e] = uniform(rng, -2.0f, 2.0f);
  }
  n.oddU = (rng() & 1) != 0;
  n.oddV = (rng() & 1) != 0;
  adj.clamp = static_cast<AdjacencyClamp>(rng() % 3);
  adj.reconstruction = static_cast<Reconstruction>(rng() % 3);
}

Patch randomPatch(std::mt19937& rng) {
  const float size = std::ldexp(1.0f, static_cast<int>(rng() % 4) - 1);
  Patch p = lodtest::terrainPatch(std::floor(uniform(rng, -20.0f, 20.0f)), std::floor(uniform(rng, -20.0f, 20.0f)),
                                  size, (rng() & 1) != 0);
  p.useHeightBounds = (rng() & 1) != 0;
  p.minHeight = -3.5f;
  p.maxHeight = 3.5f;
  return p;
}

bool sameBits(float a, float b) { return bitsOf(a) == bitsOf(b) || (std::isnan(a) && std::isnan(b)); }

// Every factor of `want` in the run's sets, and the same culled value.
bool runHolds(const BoundPatchLod& run, const PatchLod& want) {
  if (run.culled != want.why.culled) return false;
  for (int i = 0; i < 6; ++i) {
    if (!run.factors[i].contains(want.factors[i])) return false;
  }
  return true;
}

} // namespace

TEST_CASE("Bound schemes: a point camera gives the float build's factors bit for bit (Cpp) and within the sets "
          "(Conformant)",
          "[lod][bound]") {
  std::mt19937 rng(7);
  for (int iter = 0; iter < 60; ++iter) {
    const Patch patch = randomPatch(rng);
    TileNeighbours n;
    TileAdjacency adj;
    randomTile(rng, n, adj);
    const Camera cam = (iter & 1) ? lodtest::sweepCamera(iter)
                                  : makeCameraD3d(glm::vec3(30.0f, 12.0f, -25.0f), glm::vec3(0.0f), kUp, 1.0f, 0.1f,
                                                  2000.0f, kViewport);
    for (const SchemeCase& sc : schemeCases(n, adj)) {
      const PatchLod want = sc.plain(patch, cam);
      for (FloatModel model : {FloatModel::Cpp, FloatModel::Conformant}) {
        BoundContext ctx(model);
        std::vector<BoundPatchLod> runs;
        const bool complete = ctx.forEachPath([&] { runs.push_back(sc.bounded(patch, boundCamera(cam))); });
        INFO(sc.name << " iteration " << iter << (model == FloatModel::Cpp ? " cpp" : " conformant") << " runs "
                     << runs.size());
        REQUIRE(complete);
        if (model == FloatModel::Cpp) {
          REQUIRE(runs.size() == 1);
          REQUIRE(runs[0].culled == want.why.culled);
          for (int i = 0; i < 6; ++i) {
            const Bound& f = runs[0].factors[i];
            INFO("factor " << i << " float " << hex(want.factors[i]) << " bound [" << hex(f.lo) << ", " << hex(f.hi)
                           << "] nan " << f.nan);
            REQUIRE((f.point() || (std::isnan(want.factors[i]) && f.nan && !f.hasValues())));
            REQUIRE((sameBits(f.lo, want.factors[i]) || !f.hasValues()));
          }
        } else {
          bool held = false;
          for (const BoundPatchLod& r : runs) held = held || runHolds(r, want);
          REQUIRE(held);
        }
      }
    }
  }
}

TEST_CASE("Bound schemes: every camera sampled in a small region is held by one run of the region's evaluation",
          "[lod][bound]") {
  std::mt19937 rng(11);
  int undecidedRuns = 0;
  for (int iter = 0; iter < 24; ++iter) {
    const Patch patch = randomPatch(rng);
    TileNeighbours n;
    TileAdjacency adj;
    randomTile(rng, n, adj);
    const bool d3d = (iter % 3) == 0;
    const glm::vec3 eyeLo = uniformIn(rng, glm::vec3(-30.0f, 3.0f, -30.0f), glm::vec3(30.0f, 15.0f, 30.0f));
    const glm::vec3 targetLo = uniformIn(rng, glm::vec3(-5.0f, -1.0f, -5.0f), glm::vec3(5.0f, 1.0f, 5.0f));
    const float w = (iter & 1) ? 0.01f : 0.0005f;
    const glm::vec3 eyeHi = eyeLo + glm::vec3(w, w * 0.5f, w);
    const glm::vec3 targetHi = targetLo + glm::vec3(w * 0.5f, 0.0f, w);
    for (const SchemeCase& sc : schemeCases(n, adj)) {
      std::vector<BoundPatchLod> runs;
      BoundContext ctx(FloatModel::Cpp, 4096);
      const bool complete = ctx.forEachPath([&] {
        const BoundCamera bc =
            boundCameraRegion(eyeLo, eyeHi, targetLo, targetHi, kUp, 1.0f, 0.1f, 2000.0f, kViewport, d3d);
        runs.push_back(sc.bounded(patch, bc));
        undecidedRuns += ctx.choicesInRun() > 0 ? 1 : 0;
      });
      INFO(sc.name << " iteration " << iter << " runs " << runs.size());
      REQUIRE(complete);
      for (int s = 0; s < 12; ++s) {
        const glm::vec3 eye = s == 0 ? eyeLo : s == 1 ? eyeHi : uniformIn(rng, eyeLo, eyeHi);
        const glm::vec3 target = s == 0 ? targetLo : s == 1 ? targetHi : uniformIn(rng, targetLo, targetHi);
        const Camera cam = d3d ? makeCameraD3d(eye, target, kUp, 1.0f, 0.1f, 2000.0f, kViewport)
                               : makeCamera(eye, target, kUp, 1.0f, 0.1f, 2000.0f, kViewport);
        const PatchLod want = sc.plain(patch, cam);
        bool held = false;
        for (const BoundPatchLod& r : runs) held = held || runHolds(r, want);
        INFO(sc.name << " iteration " << iter << " sample " << s << " runs " << runs.size() << " culled "
                     << want.why.culled << " factors " << hex(want.factors[0]) << " " << hex(want.factors[1]) << " "
                     << hex(want.factors[2]) << " " << hex(want.factors[3]));
        REQUIRE(held);
      }
    }
  }
  // The regions are wide enough that some comparisons are undecided (the runs branch).
  REQUIRE(undecidedRuns > 0);
}

TEST_CASE("Bound schemes: boundCameraRegion's view holds makeCamera's view for every sampled eye and target",
          "[lod][bound]") {
  std::mt19937 rng(5);
  for (int iter = 0; iter < 600; ++iter) {
    const bool d3d = (iter & 1) != 0;
    glm::vec3 eyeLo = uniformIn(rng, glm::vec3(-100.0f, 1.0f, -100.0f), glm::vec3(100.0f, 50.0f, 100.0f));
    glm::vec3 targetLo = uniformIn(rng, glm::vec3(-10.0f, -1.0f, -10.0f), glm::vec3(10.0f, 1.0f, 10.0f));
    if (iter % 5 == 2) { // the eye on a diagonal through the target: dot(s, eye) cancels to ~0, many ulps of rounding
      const float a = uniform(rng, 50.0f, 300.0f);
      eyeLo = glm::vec3(a, uniform(rng, 1.0f, 20.0f), (iter & 2) ? a : -a);
      targetLo = glm::vec3(0.0f);
    }
    // Point regions on some axes (iter % 4 == 0: a point camera, every entry the float's bits).
    const float w = (iter % 4 == 0) ? 0.0f : std::ldexp(1.0f, 2 - static_cast<int>(rng() % 24));
    // Some regions with a tilted up vector of another length (the cross products then round).
    const glm::vec3 up = (iter % 3 == 1) ? uniformIn(rng, glm::vec3(-0.4f, 0.5f, -0.4f), glm::vec3(0.4f, 2.0f, 0.4f))
                                         : kUp;
    const glm::vec3 eyeHi = eyeLo + glm::vec3(w, (iter % 3 == 0) ? 0.0f : w, w);
    const glm::vec3 targetHi = targetLo + glm::vec3((iter % 5 == 0) ? 0.0f : w, w, w);
    BoundContext ctx(FloatModel::Conformant); // the camera is built under Cpp whatever the context's model
    BoundContext::Scope scope(ctx);
    const BoundCamera bc =
        boundCameraRegion(eyeLo, eyeHi, targetLo, targetHi, up, 0.9f, 0.5f, 3000.0f, kViewport, d3d);
    REQUIRE(ctx.undecidedOutsidePath() == 0);
    for (int s = 0; s < 40; ++s) {
      const glm::vec3 eye = s == 0 ? eyeLo : s == 1 ? eyeHi : uniformIn(rng, eyeLo, eyeHi);
      const glm::vec3 target = s == 0 ? targetLo : s == 1 ? targetHi : uniformIn(rng, targetLo, targetHi);
      const Camera cam = d3d ? makeCameraD3d(eye, target, up, 0.9f, 0.5f, 3000.0f, kViewport)
                             : makeCamera(eye, target, up, 0.9f, 0.5f, 3000.0f, kViewport);
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) {
          INFO("iteration " << iter << " entry [" << i << "][" << j << "] float " << hex(cam.view[i][j]) << " bound ["
                            << hex(bc.view[i][j].lo) << ", " << hex(bc.view[i][j].hi) << "]");
          REQUIRE(bc.view[i][j].contains(cam.view[i][j]));
          if (w == 0.0f) REQUIRE((bc.view[i][j].point() && sameBits(bc.view[i][j].lo, cam.view[i][j])));
          REQUIRE((bc.projection[i][j].point() && sameBits(bc.projection[i][j].lo, cam.projection[i][j])));
        }
      }
      for (int k = 0; k < 3; ++k) REQUIRE(bc.eye[k].contains(cam.eye[k]));
    }
  }
}
