// Shared helpers of the verifier tests.
#pragma once

#include "base/bits.h"
#include "lod/lod.h"
#include "verify/verify.h"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace fftess::verify::test {

inline std::string examplePath(const std::string& name) { return std::string(FFTESS_EXAMPLES_DIR) + "/" + name; }

inline Scene loadExample(const std::string& name, const std::vector<std::string>& overrides = {}) {
  SceneResult r = loadScene(examplePath(name), overrides);
  INFO(r.error);
  REQUIRE(r.ok);
  return r.scene;
}

// The scene's prepared terrain (REQUIREs that the scene is valid).
inline Terrain prepared(const Scene& scene) {
  TerrainResult r = prepareTerrain(scene);
  INFO(r.error);
  REQUIRE(r.ok);
  return r.terrain;
}

inline const char* kernelName(Kernel k) { return toString(k); }

// lod's camera for a scene camera, built here from lod::makeCamera as the scene format documents it (the harness's
// own, independent of verify's camera code).
inline lod::Camera lodCameraOf(const Camera& c) {
  return lod::makeCamera(c.eye, c.target, c.up, c.fovY * (3.14159265358979323846f / 180.0f), c.nearZ, c.farZ,
                         glm::vec2(static_cast<float>(c.width), static_cast<float>(c.height)));
}

// The harness's own visibility test (independent of verify/visibility.cpp): p projected in double with lod's camera,
// strictly inside the clip volume.
inline bool inView(const lod::Camera& cam, const glm::vec3& p) {
  const glm::dmat4 m = glm::dmat4(cam.projection) * glm::dmat4(cam.view);
  const glm::dvec4 q = m * glm::dvec4(p.x, p.y, p.z, 1.0);
  return q.w > 0 && std::fabs(q.x) < q.w && std::fabs(q.y) < q.w && q.z > -q.w && q.z < q.w;
}

// Some point of an n x n grid of domain points (edges included) of the patch is in view.
inline bool seenOnGrid(const Terrain& t, const Camera& c, int patch, int n = 17) {
  const lod::Camera cam = lodCameraOf(c);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (inView(cam, domainPosition(t, patch, static_cast<float>(i) / static_cast<float>(n - 1),
                                     static_cast<float>(j) / static_cast<float>(n - 1))))
        return true;
  return false;
}

} // namespace fftess::verify::test
