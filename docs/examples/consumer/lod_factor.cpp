// The installed LOD functions (fftess::lod): the screen-space sphere scheme (the NVIDIA sample's) for two patches
// side by side, 400 units in front of a fixed camera. Checks the factors' bits against the values the build tree's
// lod/ gives (lod's arithmetic is single precision in a stated order, so they are the same bits everywhere; a
// change is a change of lod/, docs/lod.md) and the scheme's contract that two patches sharing an edge get bitwise
// the same factor for it.
#include <cstdint>
#include <cstdio>
#include <cstring>

#include <glm/glm.hpp>

#include <fftess/lod/lod.h>

static uint32_t bitsOf(float f) { // as fftess::bitsOf (fftess/base/bits.h): through memcpy, never a pointer cast
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

int main() {
  using namespace fftess::lod;
  // Eye 10 above the terrain, looking along -z; 1920 x 1200 viewport, 60 degree vertical field of view.
  const Camera camera = makeCamera(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(0.0f, 0.0f, -50.0f),
                                   glm::vec3(0.0f, 1.0f, 0.0f), glm::radians(60.0f), 0.1f, 1000.0f,
                                   glm::vec2(1920.0f, 1200.0f));
  // Two 8 x 8 patches, x -4..4 and 4..12, z -408..-400; corners[u + 2v], u along +x, v along +z.
  Patch left;
  left.corners[0] = glm::vec3(-4.0f, 0.0f, -408.0f);
  left.corners[1] = glm::vec3(4.0f, 0.0f, -408.0f);
  left.corners[2] = glm::vec3(-4.0f, 0.0f, -400.0f);
  left.corners[3] = glm::vec3(4.0f, 0.0f, -400.0f);
  Patch right = left;
  for (glm::vec3& c : right.corners) c.x += 8.0f;
  const ScreenSphereParams params; // 3-pixel triangles, factors in [1, 64]
  const PatchLod a = screenSphere(left, camera, params);
  const PatchLod b = screenSphere(right, camera, params);
  // Ueq0 Veq0 Ueq1 Veq1 insideU insideV of the left patch, as the build tree's lod/ computes them.
  const uint32_t expected[6] = {0x40dec075, 0x40dc941f, 0x40dec077, 0x40e0f7dd, 0x40dec5fe, 0x40dec076};
  int failures = 0;
  for (int i = 0; i < 6; ++i) {
    const uint32_t bits = bitsOf(a.factors[i]);
    std::printf("factor %d: %.9g (0x%08x)%s\n", i, double(a.factors[i]), unsigned(bits),
                bits == expected[i] ? "" : " expected other bits");
    failures += bits == expected[i] ? 0 : 1;
  }
  // The shared edge: the left patch's Ueq1 (+x) is the right patch's Ueq0 (-x).
  const bool shared = bitsOf(a.factors[2]) == bitsOf(b.factors[0]);
  std::printf("shared edge: %s\n", shared ? "same bits" : "different bits");
  return failures == 0 && shared ? 0 : 1;
}
