// fftess lod, scheme 1: screen-space sphere. The arithmetic is lod/shaders/screen_sphere.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod screenSphere(const Patch& patch, const Camera& camera, const ScreenSphereParams& params) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::screenSphereLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                            patch.maxHeight, detail::toGlsl(camera), detail::toGlsl(params));
  return detail::fromGlsl(r, Scheme::ScreenSphere);
}

// The deliberately broken negative control (every edge's sphere at the patch centre): screen_sphere.glsl too.
PatchLod patchCenter(const Patch& patch, const Camera& camera, const ScreenSphereParams& params) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::patchCenterLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                           patch.maxHeight, detail::toGlsl(camera), detail::toGlsl(params));
  return detail::fromGlsl(r, Scheme::PatchCenter);
}

} // namespace fftess::lod
