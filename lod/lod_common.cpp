// fftess lod: what every scheme shares on the C++ side (camera, conversions, names).
#include <glm/gtc/matrix_transform.hpp>

#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

Camera makeCamera(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fovyRadians, float zNear, float zFar,
                  glm::vec2 viewport) {
  Camera c;
  c.view = glm::lookAt(eye, target, up);
  c.projection = glm::perspective(fovyRadians, viewport.x / viewport.y, zNear, zFar);
  c.viewport = viewport;
  c.eye = eye;
  c.depthZeroToOne = false;
  return c;
}

const char* schemeName(Scheme scheme) {
  switch (scheme) {
  case Scheme::ScreenSphere:
    return "screen-sphere";
  case Scheme::NvidiaTile:
    return "nvidia-tile";
  case Scheme::DistancePow2:
    return "distance-pow2";
  case Scheme::Bonaventura:
    return "bonaventura";
  case Scheme::ClipDiameter:
    return "clip-diameter";
  case Scheme::Geomorph:
    return "geomorph";
  case Scheme::PatchCenter:
    return "patch-center";
  }
  return "";
}

const char* fixName(Fix fix) {
  switch (fix) {
  case FixNone:
    return "";
  case FixClampedMin:
    return "clamped-min";
  case FixClampedMax:
    return "clamped-max";
  case FixCulled:
    return "culled";
  case FixLargerNeighbour:
    return "larger-neighbour";
  case FixSmallerNeighbour:
    return "smaller-neighbour";
  case FixIntegerClamp:
    return "integer-clamp";
  case FixPow2Clamp:
    return "pow2-clamp";
  case FixAngleCorrection:
    return "angle-correction";
  case FixRoundedExponent:
    return "rounded-exponent";
  case FixCoarserNeighbour:
    return "coarser-neighbour";
  case FixLiteralSource:
    return "literal-source";
  }
  return "";
}

} // namespace fftess::lod
