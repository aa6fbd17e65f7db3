// The example quoted in docs/lod.md: factors for one terrain patch under two schemes. Built and run as a test so
// the documentation cannot go stale.
#include <catch2/catch.hpp>

#include "lod/lod.h"

// [example]
#include <glm/glm.hpp>

#include "lod/lod.h"

namespace {
fftess::lod::PatchLod exampleFactors() {
  using namespace fftess::lod;
  // Eye 10 above the terrain, looking along -z; 1920 x 1200 viewport, 60 degree vertical field of view.
  const Camera cam = makeCamera(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(0.0f, 0.0f, -50.0f),
                                glm::vec3(0.0f, 1.0f, 0.0f), glm::radians(60.0f), 0.1f, 1000.0f,
                                glm::vec2(1920.0f, 1200.0f));
  // An 8 x 8 patch 20..28 in front of the eye; corners[u + 2v], u along +x, v along +z.
  Patch patch;
  patch.corners[0] = glm::vec3(-4.0f, 0.0f, -28.0f);
  patch.corners[1] = glm::vec3(4.0f, 0.0f, -28.0f);
  patch.corners[2] = glm::vec3(-4.0f, 0.0f, -20.0f);
  patch.corners[3] = glm::vec3(4.0f, 0.0f, -20.0f);

  ScreenSphereParams sphere; // the NVIDIA sample: 3-pixel triangles
  const PatchLod a = screenSphere(patch, cam, sphere);
  // a.factors = Ueq0 Veq0 Ueq1 Veq1 insideU insideV; a.why.factor[i] says what each came from.
  (void)a;

  TileNeighbours n;          // this patch meets a patch twice its size across Ueq0 (-x)
  n.size[0] = 2.0f;
  NvidiaTileParams tile;     // power-of-two clamp, edge-vector rebuild (the sample's)
  return nvidiaTile(patch, n, cam, tile);
}
} // namespace
// [example]

TEST_CASE("docs/lod.md example runs and gives the documented kinds of factors", "[lod][docs]") {
  const fftess::lod::PatchLod r = exampleFactors();
  CHECK_FALSE(r.why.culled);
  // Ueq0 faces a larger neighbour: half of a power of two in [4, 64].
  const float f = r.factors[0];
  CHECK((f == 2.0f || f == 4.0f || f == 8.0f || f == 16.0f || f == 32.0f));
  CHECK((r.why.factor[0].fixes & fftess::lod::FixLargerNeighbour) != 0);
  CHECK((r.why.factor[0].fixes & fftess::lod::FixPow2Clamp) != 0);
  for (int i = 1; i < 6; ++i) {
    CHECK(r.factors[i] >= 1.0f);
    CHECK(r.factors[i] <= 64.0f);
  }
}
