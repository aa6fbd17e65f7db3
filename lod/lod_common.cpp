// fftess lod: what every scheme shares on the C++ side (camera, conversions, names).
#include <glm/gtc/matrix_transform.hpp>

#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

namespace {

Camera cameraOf(const glm::mat4& view, const glm::mat4& projection, glm::vec2 viewport, glm::vec3 eye, bool zeroToOne) {
  Camera c;
  c.view = view;
  c.projection = projection;
  c.viewport = viewport;
  c.eye = eye;
  c.depthZeroToOne = zeroToOne;
  return c;
}

} // namespace

Camera makeCamera(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fovyRadians, float zNear, float zFar,
                  glm::vec2 viewport) {
  return cameraOf(glm::lookAt(eye, target, up), glm::perspective(fovyRadians, viewport.x / viewport.y, zNear, zFar),
                  viewport, eye, false);
}

Camera makeCameraD3d(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fovyRadians, float zNear, float zFar,
                     glm::vec2 viewport) {
  return cameraOf(glm::lookAtLH(eye, target, up),
                  glm::perspectiveLH_ZO(fovyRadians, viewport.x / viewport.y, zNear, zFar), viewport, eye, true);
}

FrustumPlanes frustumPlanes(const Camera& camera) {
  const glsl::LodFrustum f = glsl::lodFrustumPlanes(detail::toGlsl(camera));
  FrustumPlanes out;
  for (int k = 0; k < 6; ++k) out.planes[k] = f.p[k];
  return out;
}

const char* schemeName(Scheme scheme) {
  switch (scheme) {
  case Scheme::ScreenSphere:
    return "screen_sphere";
  case Scheme::NvidiaTile:
    return "nvidia_tile";
  case Scheme::DistancePow2:
    return "distance_pow2";
  case Scheme::Bonaventura:
    return "bonaventura";
  case Scheme::ClipDiameter:
    return "clip_diameter";
  case Scheme::Geomorph:
    return "geomorph";
  case Scheme::PatchCenter:
    return "patch_center";
  case Scheme::Constant:
    return "constant";
  }
  return "";
}

const char* fixName(Fix fix) {
  switch (fix) {
  case FixNone:
    return "";
  case FixClampedMin:
    return "clamped_min";
  case FixClampedMax:
    return "clamped_max";
  case FixCulled:
    return "culled";
  case FixLargerNeighbour:
    return "larger_neighbour";
  case FixSmallerNeighbour:
    return "smaller_neighbour";
  case FixIntegerClamp:
    return "integer_clamp";
  case FixPow2Clamp:
    return "pow2_clamp";
  case FixAngleCorrection:
    return "angle_correction";
  case FixRoundedExponent:
    return "rounded_exponent";
  case FixCoarserNeighbour:
    return "coarser_neighbour";
  case FixLiteralSource:
    return "literal_source";
  }
  return "";
}

} // namespace fftess::lod
