// fftess lod: what every scheme shares on the C++ side (camera, conversions, names).
#include <cstring>

#include <glm/gtc/matrix_transform.hpp>

#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

// The shader's fix bits are the public enum's.
static_assert(glsl::kFixClampedMin == FixClampedMin && glsl::kFixClampedMax == FixClampedMax &&
                  glsl::kFixCulled == FixCulled && glsl::kFixLargerNeighbour == FixLargerNeighbour &&
                  glsl::kFixSmallerNeighbour == FixSmallerNeighbour && glsl::kFixIntegerClamp == FixIntegerClamp &&
                  glsl::kFixPow2Clamp == FixPow2Clamp && glsl::kFixAngleCorrection == FixAngleCorrection &&
                  glsl::kFixRoundedExponent == FixRoundedExponent &&
                  glsl::kFixCoarserNeighbour == FixCoarserNeighbour && glsl::kFixLiteralSource == FixLiteralSource,
              "lod/shaders/common.glsl fix bits must equal fftess::lod::Fix");

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

namespace detail {

glsl::LodCamera toGlsl(const Camera& camera) {
  glsl::LodCamera c;
  c.view = camera.view;
  c.proj = camera.projection;
  c.viewport = camera.viewport;
  c.eye = camera.eye;
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
}

PatchLod fromGlsl(const glsl::LodResult& result, Scheme scheme) {
  PatchLod out;
  out.why.scheme = scheme;
  out.why.culled = result.culled;
  for (int i = 0; i < 6; ++i) {
    const glsl::EdgeLod& e = result.e[i];
    out.factors[i] = e.factor;
    out.why.factor[i].metric = e.metric;
    out.why.factor[i].unclamped = e.unclamped;
    out.why.factor[i].exponent = e.exponent;
    out.why.factor[i].fixes = static_cast<uint32_t>(e.fixes);
  }
  for (int i = 0; i < 4; ++i) {
    out.why.cornerLevel[i] = result.cornerLevel[i];
  }
  return out;
}

int insideRuleCode(InsideRule rule) {
  switch (rule) {
  case InsideRule::Min:
    return glsl::kInsideMin;
  case InsideRule::Max:
    return glsl::kInsideMax;
  case InsideRule::Average:
    break;
  }
  return glsl::kInsideAverage;
}

} // namespace detail

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
