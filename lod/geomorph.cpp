// fftess lod, scheme 6: geomorphing tween factors. The arithmetic is lod/shaders/geomorph.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

float geomorphLevel(const Patch& patch, const Camera& camera, const GeomorphParams& params) {
  const glm::vec3* c = patch.corners;
  return glsl::geomorphLevelAt(glsl::patchCentre(c[0], c[1], c[2], c[3]), detail::toGlsl(camera), detail::toGlsl(params));
}

PatchLod geomorph(float level, const float neighbourLevel[4]) {
  glsl::LodResult r =
      glsl::geomorphLod(level, neighbourLevel[0], neighbourLevel[1], neighbourLevel[2], neighbourLevel[3]);
  return detail::fromGlsl(r, Scheme::Geomorph);
}

GeomorphEdge geomorphEdgeHeights(float level, float neighbourLevel, const float fineHeights[65],
                                 const GeomorphParams& params) {
  float fine[65];
  for (int i = 0; i < 65; ++i) {
    fine[i] = fineHeights[i];
  }
  glsl::GeomorphBorder b = glsl::geomorphBorderHeights(level, neighbourLevel, fine, detail::toGlsl(params));
  GeomorphEdge e;
  e.segments = b.segments;
  for (int i = 0; i < 65; ++i) {
    e.heights[i] = b.heights[i];
  }
  return e;
}

float geomorphWeight(float level, float neighbourLevel, const GeomorphParams& params) {
  return glsl::geomorphWeight(level, neighbourLevel, detail::toGlsl(params));
}

float geomorphHeight(float height, float previousHeight, float nextHeight, float weight) {
  return glsl::geomorphHeight(height, previousHeight, nextHeight, weight);
}

} // namespace fftess::lod
