// fftess lod, scheme 5: clip-space sphere diameter. The arithmetic is lod/shaders/clip_diameter.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod clipDiameter(const Patch& patch, const Camera& camera, const ClipDiameterParams& params) {
  glsl::ClipDiameterSettings s;
  s.edgesPerScreenHeight = params.edgesPerScreenHeight;
  s.minFactor = params.minFactor;
  s.maxFactor = params.maxFactor;
  s.insideRule = detail::insideRuleCode(params.inside);
  s.frustumCull = params.frustumCull;
  s.culledFactor = params.culledFactor;
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::clipDiameterLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                            patch.maxHeight, detail::toGlsl(camera), s);
  return detail::fromGlsl(r, Scheme::ClipDiameter);
}

} // namespace fftess::lod
