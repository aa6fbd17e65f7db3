// libFuzzer target for the scene loader and the --set override parser: the input is TOML text, then up to four
// overrides, separated by NUL bytes ("TOML\0KEY=VALUE\0KEY=VALUE..."). What must hold for every input: no crash, no
// sanitizer report, no hang; a rejected scene has a one-line error naming a position or a key; an accepted small
// scene is prepared (prepareTerrain) and, when that succeeds, checked from its own camera (CGAL) without crashing.
// Build (clang): cmake -S . -B build-fuzz -G Ninja -DCMAKE_CXX_COMPILER=clang++ -DFFTESS_FUZZ=ON
//   cmake --build build-fuzz --target fuzz_scene && build-fuzz/verify/fuzz_scene -runs=100000 verify/fuzz_corpus
// Without clang, tests/fuzz_replay_main.cpp runs the corpus (and mutations of it) through this same entry
// point as a ctest, under the sanitizer build's ASan+UBSan.
#include "verify/verify.h"

#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#ifndef FFTESS_FUZZ_BASE_DIR
#define FFTESS_FUZZ_BASE_DIR "."
#endif

using namespace fftess::verify;

namespace {

// Scenes large enough to make one input take seconds are valid but not interesting here: skip their build.
bool small(const Scene& s) {
  const Layout& L = s.layout;
  double patches = 0;
  if (L.kind == LayoutKind::TileRings)
    patches = double(L.tilesPerRingEdge) * L.tilesPerRingEdge * L.patchesPerTileEdge * L.patchesPerTileEdge *
              (1 + 0.75 * (L.rings - 1));
  else if (L.kind == LayoutKind::Grid)
    patches = double(L.patchesX) * L.patchesZ;
  else if (L.kind == LayoutKind::Quadtree) // the pyramid's nodes (every one prepared)
    patches = double(L.rootsX) * L.rootsZ * (std::pow(4.0, L.maxDepth + 1) - 1) / 3;
  else
    patches = double(s.displacement.texWidth) * s.displacement.texHeight / (double(L.cellsPerPatch) * L.cellsPerPatch);
  const bool smallTexture = s.displacement.kind == DisplacementKind::None ||
                            double(s.displacement.texWidth) * s.displacement.texHeight <= 300.0 * 300.0;
  return patches <= 2048 && smallTexture;
}

// A generated texture of up to 8192^2 texels is valid but takes seconds: such inputs are skipped before parsing
// (the resolution is read with toml++ from the text and from a displacement.resolution override).
bool generatesHugeTexture(const std::string& text, const std::vector<std::string>& overrides) {
  constexpr int64_t kMax = 300;
  for (const std::string& o : overrides)
    if (o.find("resolution") != std::string::npos) {
      const size_t eq = o.find('=');
      if (eq == std::string::npos) continue;
      try {
        if (toml::parse("v = " + o.substr(eq + 1))["v"].value_or(int64_t(0)) > kMax) return true;
      } catch (const toml::parse_error&) {
      }
    }
  try {
    const toml::table root = toml::parse(text);
    const int64_t v = root["displacement"]["resolution"].value_or(int64_t(0));
    return v > kMax;
  } catch (const toml::parse_error&) {
    return false; // the loader rejects it quickly
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > 1 << 16) return 0;
  const std::string all(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  for (size_t start = 0;;) {
    const size_t nul = all.find('\0', start);
    parts.push_back(all.substr(start, nul == std::string::npos ? std::string::npos : nul - start));
    if (nul == std::string::npos || parts.size() == 5) break;
    start = nul + 1;
  }
  const std::string text = parts[0];
  const std::vector<std::string> overrides(parts.begin() + 1, parts.end());
  if (generatesHugeTexture(text, overrides)) return 0;
  SceneResult r = parseScene(text, "fuzz.toml", overrides, FFTESS_FUZZ_BASE_DIR);
  if (!r) {
    if (r.error.empty() || r.error.find('\n') != std::string::npos) std::abort(); // one line, always
    return 0;
  }
  if (!small(r.scene)) return 0;
  TerrainResult t = prepareTerrain(r.scene);
  if (!t) {
    if (t.error.empty()) std::abort();
    return 0;
  }
  CheckOptions o;
  o.maxFindings = 16;
  (void)checkScene(t.terrain, r.scene.camera, o);
  return 0;
}
