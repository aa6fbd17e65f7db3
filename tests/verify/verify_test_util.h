// Shared helpers of the verifier tests.
#pragma once

#include "verify/verify.h"

#include <catch2/catch.hpp>

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

} // namespace fftess::verify::test
