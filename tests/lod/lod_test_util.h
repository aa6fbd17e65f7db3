// Helpers shared by the lod tests.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>

#include "base/bits.h"
#include "lod/lod.h"

namespace lodtest {

inline std::string hex(float f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9g (0x%08x)", static_cast<double>(f), static_cast<unsigned>(fftess::bitsOf(f)));
  return buf;
}

// Distance in units in the last place between a float and a double reference (the reference rounded first).
inline double ulpFrom(float got, double want) {
  const float w = static_cast<float>(want);
  if (got == w) {
    return 0.0;
  }
  const double ulp = static_cast<double>(std::nextafter(std::fabs(w), INFINITY) - std::fabs(w));
  return std::fabs(static_cast<double>(got) - want) / ulp;
}

// A camera whose arithmetic is exact: view = identity (eye at the origin looking down -z), projection with
// P[0][0] = P[1][1] = 1, w = -z, near 1, far 17 (P[2][2] = -18/16, P[3][2] = -34/16), viewport 1920 x 1200.
inline fftess::lod::Camera exactCamera() {
  fftess::lod::Camera c;
  c.view = glm::mat4(1.0f);
  c.projection = glm::mat4(0.0f);
  c.projection[0][0] = 1.0f;
  c.projection[1][1] = 1.0f;
  c.projection[2][2] = -1.125f;
  c.projection[2][3] = -1.0f;
  c.projection[3][2] = -2.125f;
  c.viewport = glm::vec2(1920.0f, 1200.0f);
  c.eye = glm::vec3(0.0f);
  return c;
}

// A 2 x 2 patch in the plane z = zPlane facing the exact camera, centred at (cx, cy).
inline fftess::lod::Patch facingPatch(float cx, float cy, float zPlane) {
  fftess::lod::Patch p;
  p.corners[0] = glm::vec3(cx - 1.0f, cy - 1.0f, zPlane);
  p.corners[1] = glm::vec3(cx + 1.0f, cy - 1.0f, zPlane);
  p.corners[2] = glm::vec3(cx - 1.0f, cy + 1.0f, zPlane);
  p.corners[3] = glm::vec3(cx + 1.0f, cy + 1.0f, zPlane);
  return p;
}

// A terrain patch on the x-z plane: corner (i, j) of a grid of spacing `size`, heights from a fixed bumpy field.
inline float terrainHeight(float x, float z) {
  return 3.0f * std::sin(0.37f * x) * std::cos(0.23f * z) + 0.01f * x;
}

inline fftess::lod::Patch terrainPatch(float x0, float z0, float size, bool displaced) {
  fftess::lod::Patch p;
  for (int v = 0; v < 2; ++v) {
    for (int u = 0; u < 2; ++u) {
      const float x = x0 + static_cast<float>(u) * size;
      const float z = z0 + static_cast<float>(v) * size;
      p.corners[u + 2 * v] = glm::vec3(x, displaced ? terrainHeight(x, z) : 0.0f, z);
    }
  }
  return p;
}

// A deterministic camera sweep: eye on a spiral above the terrain, looking at a point ahead.
inline fftess::lod::Camera sweepCamera(int i) {
  const float t = static_cast<float>(i) * 0.37f;
  const glm::vec3 eye(40.0f * std::cos(t), 2.0f + static_cast<float>(i % 7) * 3.0f, 40.0f * std::sin(t));
  const glm::vec3 target(8.0f * std::cos(1.3f * t), 0.0f, 8.0f * std::sin(0.7f * t));
  return fftess::lod::makeCamera(eye, target, glm::vec3(0.0f, 1.0f, 0.0f), 1.0f, 0.1f, 2000.0f,
                                 glm::vec2(1920.0f, 1200.0f));
}

} // namespace lodtest
