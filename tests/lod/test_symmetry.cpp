// Every scheme: two patches that share an edge compute bitwise the same factor for it, over a camera sweep, on
// displaced terrain, whichever way round each patch lists the edge's corners.
#include <catch2/catch.hpp>

#include <functional>

#include "lod_test_util.h"

using namespace fftess::lod;
using lodtest::bits;
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

void checkShared(const char* name, const SchemeFn& fn) {
  int compared = 0;
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
    CHECK(bits(ra.factors[2]) == bits(rr.factors[0])); // a.Ueq1 == right.Ueq0
    CHECK(bits(ra.factors[3]) == bits(ru.factors[1])); // a.Veq1 == up.Veq0
    CHECK(bits(ra.factors[0]) == bits(rm.factors[2])); // reversed corner order
    CHECK(bits(ra.factors[1]) == bits(rm.factors[1]));
    ++compared;
  }
  CHECK(compared > 100);
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
  // The same check against a scheme that measures from the patch centre instead of the edge: shared edges
  // disagree, so the comparison above has teeth.
  int disagreements = 0;
  for (int i = 0; i < 50; ++i) {
    const Camera cam = lodtest::sweepCamera(i);
    const Patch a = lodtest::terrainPatch(-4.0f, -4.0f, 8.0f, true);
    const Patch right = lodtest::terrainPatch(4.0f, -4.0f, 8.0f, true);
    DistancePow2Params p;
    p.frustumCull = false;
    p.minDistance = 5.0f;
    p.maxDistance = 80.0f;
    // inside factors are measured from the centre: use them as the "edge" factor.
    if (bits(distancePow2(a, cam, p).factors[4]) != bits(distancePow2(right, cam, p).factors[4])) {
      ++disagreements;
    }
  }
  CHECK(disagreements > 40);
}
