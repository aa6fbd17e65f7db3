// lod_double.h: screen_sphere.glsl and nvidia_tile.glsl compiled in double (the shim of glsl_cpp.h with float,
// vec2/3/4 and mat4 mapped to double types; a vector times a float literal converts the literal exactly).
#include "lod/lod_double.h"

#include <glm/glm.hpp>

#include "lod/shader_convert.h"

namespace fftess::lod {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wdouble-promotion"
#pragma GCC diagnostic ignored "-Wfloat-conversion"
namespace glsld {
using namespace glm;
using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat4 = glm::dmat4;
inline vec3 operator*(const vec3& v, float s) { return v * static_cast<double>(s); }
inline vec3 operator*(float s, const vec3& v) { return v * static_cast<double>(s); }
inline vec4 operator*(const vec4& v, float s) { return v * static_cast<double>(s); }
inline vec2 operator*(const vec2& v, float s) { return v * static_cast<double>(s); }
#define float double
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#undef float
} // namespace glsld
#pragma GCC diagnostic pop

glsld::LodCamera toD(const Camera& c) {
  glsld::LodCamera d;
  d.view = glm::dmat4(c.view);
  d.proj = glm::dmat4(c.projection);
  d.viewport = glm::dvec2(c.viewport);
  d.eye = glm::dvec3(c.eye);
  d.depthZeroToOne = c.depthZeroToOne;
  return d;
}

// lod.h's *Params -> the double *Settings, field by field from lod/lod_fields.h (lod/shader_convert.h; floats
// widen exactly).
glsld::ScreenSphereSettings toD(const ScreenSphereParams& p) {
  return convert::ShaderValue<glsld::ScreenSphereSettings>::from(p);
}
glsld::TileSettings toD(const NvidiaTileParams& p) { return convert::ShaderValue<glsld::TileSettings>::from(p); }

PatchLod fromD(const glsld::LodResult& r, Scheme scheme) {
  PatchLod out;
  out.why.scheme = scheme;
  out.why.culled = r.culled;
  for (int i = 0; i < 6; ++i) {
    out.factors[i] = static_cast<float>(r.e[i].factor);
    out.why.factor[i].metric = static_cast<float>(r.e[i].metric);
    out.why.factor[i].unclamped = static_cast<float>(r.e[i].unclamped);
    out.why.factor[i].exponent = static_cast<float>(r.e[i].exponent);
    out.why.factor[i].fixes = static_cast<uint32_t>(r.e[i].fixes);
  }
  return out;
}

} // namespace

PatchLod screenSphereDouble(const Patch& patch, const Camera& camera, const ScreenSphereParams& params) {
  const glm::vec3* c = patch.corners;
  return fromD(glsld::screenSphereLod(glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]), glm::dvec3(c[3]),
                                      patch.useHeightBounds, patch.minHeight, patch.maxHeight, toD(camera),
                                      toD(params)),
               Scheme::ScreenSphere);
}

PatchLod nvidiaTileDouble(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const NvidiaTileParams& params) {
  glsld::TileNeighbourInfo n;
  for (int i = 0; i < 4; ++i) {
    n.size[i] = neighbours.size[i];
    n.farCorner[i] = glm::dvec3(neighbours.farCorner[i]);
    n.rebuiltHeight[i] = neighbours.rebuiltHeight[i];
  }
  n.oddU = neighbours.oddU;
  n.oddV = neighbours.oddV;
  const glm::vec3* c = patch.corners;
  return fromD(glsld::nvidiaTileLod(glm::dvec3(c[0]), glm::dvec3(c[1]), glm::dvec3(c[2]), glm::dvec3(c[3]),
                                    patch.useHeightBounds, patch.minHeight, patch.maxHeight, n, toD(camera),
                                    toD(params)),
               Scheme::NvidiaTile);
}

} // namespace fftess::lod
