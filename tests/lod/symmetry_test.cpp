// Every scheme: two patches that share an edge compute bitwise the same factor for it, over a camera sweep, on
// displaced terrain, whichever way round each patch lists the edge's corners.
#include <catch2/catch.hpp>

#include <functional>

#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {

using SchemeFn = std::function<PatchLod(const Patch&, const Camera&)>;

// The patch mirrored in u: corners (0,0)<->(1,0), (0,1)<->(1,1). Its Ueq0 is the original's Ueq1 and its Veq0
// lists the original's Veq0 corners in the opposite order.
Patch mirrorU(const Patch& p) {
  Patch m = p;
  m.corners[0] = p.corners[1];
  m.corners[1] = p.corners[0];
  m.corners[2] = p.corners[3];
  m.corners[3] = p.corners[2];
  return m;
}

// The shared-edge comparison over the camera sweep: per camera where no patch is culled, four comparisons
// (a.Ueq1 == right.Ueq0, a.Veq1 == up.Veq0, and the mirrored patch's two edges). Counts what agreed.
struct Agreement {
  int compared = 0;   // cameras compared
  int mismatches = 0; // comparisons that disagreed
  int camerasWithMismatch = 0;
};

Agreement sharedEdges(const char* name, const SchemeFn& fn, bool expectAgreement) {
  Agreement out;
  for (int i = 0; i < 150; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    const Patch a = lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true);
    const Patch right = lodtest::terrainPatch(4.0f, -4.0f, 8.0f, true);
    const Patch up = lodtest::terrainPatch(-4.0f, 4.0f, 8.0f, true);
    const PatchLod ra = fn(a, cam), rr = fn(right, cam), ru = fn(up, cam), rm = fn(mirrorU(a), cam);
    INFO(name << " camera " << i << " Ueq1 " << hex(ra.factors[2]) << " right Ueq0 " << hex(rr.factors[0]));
    if (ra.why.culled || rr.why.culled || ru.why.culled) {
      continue; // culling is per patch; the sweep keeps most patches in view
    }
    const bool same[4] = {bitsOf(ra.factors[2]) == bitsOf(rr.factors[0]),  // a.Ueq1 == right.Ueq0
                          bitsOf(ra.factors[3]) == bitsOf(ru.factors[1]),  // a.Veq1 == up.Veq0
                          bitsOf(ra.factors[0]) == bitsOf(rm.factors[2]),  // reversed corner order
                          bitsOf(ra.factors[1]) == bitsOf(rm.factors[1])};
    int wrong = 0;
    for (bool ok : same) {
      if (expectAgreement) CHECK(ok);
      wrong += ok ? 0 : 1;
    }
    out.mismatches += wrong;
    out.camerasWithMismatch += wrong > 0 ? 1 : 0;
    ++out.compared;
  }
  return out;
}

void checkShared(const char* name, const SchemeFn& fn) {
  const Agreement r = sharedEdges(name, fn, true);
  CHECK(r.compared > 100);
  CHECK(r.mismatches == 0);
}

} // namespace

TEST_CASE("symmetry: shared edges get bitwise the same factor in every scheme", "[lod][symmetry]") {
  checkShared("screenSphere", [](const Patch& p, const Camera& c) { return screenSphere(p, c); });
  checkShared("nvidiaTile", [](const Patch& p, const Camera& c) { return nvidiaTile(p, TileNeighbours{}, c); });
  checkShared("distancePow2", [](const Patch& p, const Camera& c) { return distancePow2(p, c); });
  checkShared("bonaventura", [](const Patch& p, const Camera& c) {
    BonaventuraParams q;
    q.rank = 1.0f;
    q.minDistance = 5.0f;
    q.maxDistance = 80.0f;
    return bonaventura(p, c, q);
  });
  checkShared("clipDiameter", [](const Patch& p, const Camera& c) { return clipDiameter(p, c); });
  // --gpu-float's negative control: the two sides add the same two rounded products in opposite orders (the same
  // bits in the C++ build; tests/lod/screen_sphere_test.cpp shows that a fused product would not be).
  ScreenSphereParams around;
  around.sphereCentre = SphereCentre::AroundQuadScaled;
  checkShared("screenSphere around_quad_scaled", [around](const Patch& p, const Camera& c) { return screenSphere(p, c, around); });
  NvidiaTileParams aroundTile;
  aroundTile.sphere = around;
  checkShared("nvidiaTile around_quad_scaled",
              [aroundTile](const Patch& p, const Camera& c) { return nvidiaTile(p, TileNeighbours{}, c, aroundTile); });
  checkShared("geomorph", [](const Patch& p, const Camera& c) {
    // Levels from the patch and its neighbours across each edge (shifted by the patch's own edge vectors, so the
    // mirrored patch finds its neighbours too); the shared edge takes the min of the two levels.
    const float du = p.corners[1].x - p.corners[0].x;
    const float dv = p.corners[2].z - p.corners[0].z;
    Patch l = p, r = p, d = p, u = p;
    for (int k = 0; k < 4; ++k) {
      l.corners[k].x -= du;
      r.corners[k].x += du;
      d.corners[k].z -= dv;
      u.corners[k].z += dv;
    }
    const float n[4] = {geomorphLevel(l, c), geomorphLevel(d, c), geomorphLevel(r, c), geomorphLevel(u, c)};
    return geomorph(geomorphLevel(p, c), n);
  });
}

TEST_CASE("symmetry: a deliberately broken LOD (factor from the patch centre) is caught", "[lod][symmetry]") {
  // The same check as above, run on lod::patchCenter (lod/shaders/screen_sphere.glsl patchCenterLod: every edge's
  // sphere at the patch centre): shared edges disagree, so the check above has teeth.
  // No clamp, so that a factor that differs is not hidden behind minFactor / maxFactor.
  ScreenSphereParams q;
  q.minFactor = 0.0f;
  q.maxFactor = 1e30f;
  const Agreement r =
      sharedEdges("patchCenter", [q](const Patch& p, const Camera& c) { return patchCenter(p, c, q); }, false);
  CHECK(r.compared > 100);
  CHECK(r.camerasWithMismatch > r.compared * 9 / 10);
  // The working scheme it breaks passes on the very same patches and cameras.
  CHECK(sharedEdges("screenSphere", [q](const Patch& p, const Camera& c) { return screenSphere(p, c, q); }, true)
            .mismatches == 0);
}
