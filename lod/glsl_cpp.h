// Internal: the shared lod/shaders/*.glsl compiled as C++ through GLM.
//
// The shim: the .glsl files are included inside an unnamed namespace in fftess::lod (so each .cpp gets its own
// internal copy and nothing clashes at link time), in namespace glsl with `using namespace glm;`, so vec3, mat4,
// min, max, floor, ceil, exp2, sqrt, acos and abs resolve to GLM's (single precision; GLM's scalar functions call
// the float overloads of <cmath>). Nothing else is needed: the files avoid every construct the two languages spell
// differently (array constructors, out/inout, multi-component swizzle writes, unsuffixed float literals).
// Compile with -ffp-contract=off (lod/CMakeLists.txt and the top level do) so no FMA is formed.
#pragma once

#include <glm/glm.hpp>

#include "lod/lod.h"

namespace fftess::lod {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace glsl {
using namespace glm;
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#include "shaders/distance_pow2.glsl"
#include "shaders/bonaventura.glsl"
#include "shaders/clip_diameter.glsl"
#include "shaders/geomorph.glsl"
} // namespace glsl

// The shader's fix bits are the public enum's.
static_assert(glsl::kFixClampedMin == FixClampedMin && glsl::kFixClampedMax == FixClampedMax &&
                  glsl::kFixCulled == FixCulled && glsl::kFixLargerNeighbour == FixLargerNeighbour &&
                  glsl::kFixSmallerNeighbour == FixSmallerNeighbour && glsl::kFixIntegerClamp == FixIntegerClamp &&
                  glsl::kFixPow2Clamp == FixPow2Clamp && glsl::kFixAngleCorrection == FixAngleCorrection &&
                  glsl::kFixRoundedExponent == FixRoundedExponent &&
                  glsl::kFixCoarserNeighbour == FixCoarserNeighbour && glsl::kFixLiteralSource == FixLiteralSource,
              "lod/shaders/common.glsl fix bits must equal fftess::lod::Fix");

namespace detail {

// Public structs -> shader structs, and the shader result -> PatchLod.
glsl::LodCamera toGlsl(const Camera& camera) {
  glsl::LodCamera c;
  c.view = camera.view;
  c.proj = camera.projection;
  c.viewport = camera.viewport;
  c.eye = camera.eye;
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
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

} // namespace detail
#pragma GCC diagnostic pop

} // namespace
} // namespace fftess::lod
