// fftess lod, scheme 1: screen-space sphere. The arithmetic is lod/shaders/screen_sphere.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

namespace detail {
glsl::ScreenSphereSettings toGlsl(const ScreenSphereParams& p) {
  glsl::ScreenSphereSettings s;
  s.triWidth = p.tessellatedTriWidth;
  s.minFactor = p.minFactor;
  s.maxFactor = p.maxFactor;
  s.insideRule = insideRuleCode(p.inside);
  s.frustumCull = p.frustumCull;
  s.culledFactor = p.culledFactor;
  return s;
}
} // namespace detail

PatchLod screenSphere(const Patch& patch, const Camera& camera, const ScreenSphereParams& params) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::screenSphereLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                            patch.maxHeight, detail::toGlsl(camera), detail::toGlsl(params));
  return detail::fromGlsl(r, Scheme::ScreenSphere);
}

} // namespace fftess::lod
