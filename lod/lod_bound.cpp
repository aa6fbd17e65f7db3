// lod_bound.h: lod/shaders/*.glsl (not geomorph.glsl) compiled with Bound as float: the shim of lod/glsl_cpp.h with
// float, vec2/3/4 and mat4 mapped to Bound types; a vector times a float literal converts the literal to a constant
// Bound; the vector min/max the shaders use are written per component (GLM's static_assert an IEEE float type).
#include "lod/lod_bound.h"

#include <glm/glm.hpp>

#include "lod/bound_internal.h"
#include "lod/shader_convert.h"

namespace fftess::lod {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace glslb {
using namespace glm;
using vec2 = BoundVec2;
using vec3 = BoundVec3;
using vec4 = BoundVec4;
using mat4 = BoundMat4;
inline vec2 operator*(const vec2& v, float s) { return v * Bound(s); }
inline vec3 operator*(const vec3& v, float s) { return v * Bound(s); }
inline vec4 operator*(const vec4& v, float s) { return v * Bound(s); }
inline vec3 operator*(float s, const vec3& v) { return Bound(s) * v; }
// GLM's component-wise min / max: min(a, b) = b < a ? b : a per component (lod::min's semantics).
inline vec3 min(const vec3& a, const vec3& b) {
  return vec3(fftess::lod::min(a.x, b.x), fftess::lod::min(a.y, b.y), fftess::lod::min(a.z, b.z));
}
inline vec3 max(const vec3& a, const vec3& b) {
  return vec3(fftess::lod::max(a.x, b.x), fftess::lod::max(a.y, b.y), fftess::lod::max(a.z, b.z));
}
#define float Bound
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#include "shaders/distance_pow2.glsl"
#include "shaders/bonaventura.glsl"
#include "shaders/clip_diameter.glsl"
#undef float
} // namespace glslb
#pragma GCC diagnostic pop

BoundVec3 toB(glm::vec3 v) { return BoundVec3(Bound(v.x), Bound(v.y), Bound(v.z)); }

BoundMat4 toB(const glm::mat4& m) {
  BoundMat4 r;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) r[i][j] = Bound(m[i][j]);
  }
  return r;
}

glslb::LodCamera toB(const BoundCamera& camera) {
  glslb::LodCamera c;
  c.view = camera.view;
  c.proj = camera.projection;
  c.viewport = camera.viewport;
  c.eye = camera.eye;
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
}

// lod.h's *Params -> the Bound *Settings, field by field from lod/lod_fields.h (lod/shader_convert.h; every float a
// constant).
glslb::ScreenSphereSettings toB(const ScreenSphereParams& p) {
  return convert::ShaderValue<glslb::ScreenSphereSettings>::from(p);
}
glslb::TileSettings toB(const NvidiaTileParams& p) { return convert::ShaderValue<glslb::TileSettings>::from(p); }
glslb::AdjacencySettings toB(const TileAdjacency& p) {
  return convert::ShaderValue<glslb::AdjacencySettings>::from(p);
}
glslb::DistancePow2Settings toB(const DistancePow2Params& p) {
  return convert::ShaderValue<glslb::DistancePow2Settings>::from(p);
}
glslb::BonaventuraSettings toB(const BonaventuraParams& p) {
  return convert::ShaderValue<glslb::BonaventuraSettings>::from(p);
}
glslb::ClipDiameterSettings toB(const ClipDiameterParams& p) {
  return convert::ShaderValue<glslb::ClipDiameterSettings>::from(p);
}

glslb::TileNeighbourInfo toB(const TileNeighbours& t) {
  glslb::TileNeighbourInfo n;
  for (int i = 0; i < 4; ++i) {
    n.size[i] = Bound(t.size[i]);
    n.farCorner[i] = toB(t.farCorner[i]);
    n.rebuiltHeight[i] = Bound(t.rebuiltHeight[i]);
  }
  n.oddU = t.oddU;
  n.oddV = t.oddV;
  return n;
}

BoundPatchLod fromB(const glslb::LodResult& r) {
  BoundPatchLod out;
  for (int i = 0; i < 6; ++i) {
    out.factors[i] = r.e[i].factor;
    bound::resolveNode(out.factors[i]);
  }
  out.culled = r.culled;
  return out;
}

// The patch's arguments as the shaders take them (corners and heights as constants).
struct PatchB {
  BoundVec3 c[4];
  Bound minHeight;
  Bound maxHeight;
  explicit PatchB(const Patch& p)
      : c{toB(p.corners[0]), toB(p.corners[1]), toB(p.corners[2]), toB(p.corners[3])}, minHeight(p.minHeight),
        maxHeight(p.maxHeight) {}
};

// GLM's geometric functions in GLM's order (glm/detail/func_geometric.inl, func_exponential.inl): dot = tmp = a * b,
// tmp.x + tmp.y + tmp.z; cross; normalize = v * inversesqrt(dot(v, v)) with inversesqrt(x) = 1 / sqrt(x).
Bound dotGlm(const BoundVec3& a, const BoundVec3& b) {
  const Bound x = a.x * b.x;
  const Bound y = a.y * b.y;
  const Bound z = a.z * b.z;
  return x + y + z;
}

BoundVec3 crossGlm(const BoundVec3& x, const BoundVec3& y) {
  return BoundVec3(x.y * y.z - y.y * x.z, x.z * y.x - y.z * x.x, x.x * y.y - y.x * x.y);
}

BoundVec3 normalizeGlm(const BoundVec3& v) {
  const Bound s = Bound(1.0f) / sqrt(dotGlm(v, v));
  return BoundVec3(v.x * s, v.y * s, v.z * s);
}

// glm::lookAtRH (d3d: lookAtLH), glm/ext/matrix_transform.inl, with Bound.
BoundMat4 lookAtBound(const BoundVec3& eye, const BoundVec3& center, const BoundVec3& up, bool leftHanded) {
  const BoundVec3 f = normalizeGlm(BoundVec3(center.x - eye.x, center.y - eye.y, center.z - eye.z));
  const BoundVec3 s = leftHanded ? normalizeGlm(crossGlm(up, f)) : normalizeGlm(crossGlm(f, up));
  const BoundVec3 u = leftHanded ? crossGlm(f, s) : crossGlm(s, f);
  BoundMat4 r;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) r[i][j] = Bound(i == j ? 1.0f : 0.0f);
  }
  r[0][0] = s.x;
  r[1][0] = s.y;
  r[2][0] = s.z;
  r[0][1] = u.x;
  r[1][1] = u.y;
  r[2][1] = u.z;
  r[0][2] = leftHanded ? f.x : -f.x;
  r[1][2] = leftHanded ? f.y : -f.y;
  r[2][2] = leftHanded ? f.z : -f.z;
  r[3][0] = -dotGlm(s, eye);
  r[3][1] = -dotGlm(u, eye);
  r[3][2] = leftHanded ? -dotGlm(f, eye) : dotGlm(f, eye);
  return r;
}

} // namespace

BoundCamera boundCamera(const Camera& camera) {
  BoundCamera c;
  c.view = toB(camera.view);
  c.projection = toB(camera.projection);
  c.viewport = BoundVec2(Bound(camera.viewport.x), Bound(camera.viewport.y));
  c.eye = toB(camera.eye);
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
}

BoundCamera boundCameraRegion(glm::vec3 eyeLo, glm::vec3 eyeHi, glm::vec3 targetLo, glm::vec3 targetHi, glm::vec3 up,
                              float fovyRadians, float zNear, float zFar, glm::vec2 viewport, bool d3d) {
  const bound::ModelOverride cpu(FloatModel::Cpp); // the camera is built on the CPU
  const BoundVec3 eye(Bound::input(eyeLo.x, eyeHi.x, 1), Bound::input(eyeLo.y, eyeHi.y, 2),
                      Bound::input(eyeLo.z, eyeHi.z, 3));
  const BoundVec3 target(Bound::input(targetLo.x, targetHi.x, 4), Bound::input(targetLo.y, targetHi.y, 5),
                         Bound::input(targetLo.z, targetHi.z, 6));
  // The projection does not depend on the eye or target: the float build's, as constants.
  const Camera reference = d3d ? makeCameraD3d(eyeLo, targetLo, up, fovyRadians, zNear, zFar, viewport)
                               : makeCamera(eyeLo, targetLo, up, fovyRadians, zNear, zFar, viewport);
  BoundCamera c = boundCamera(reference);
  c.view = lookAtBound(eye, target, toB(up), d3d);
  c.eye = eye;
  return c;
}

BoundPatchLod screenSphereBound(const Patch& patch, const BoundCamera& camera, const ScreenSphereParams& params) {
  const PatchB p(patch);
  return fromB(glslb::screenSphereLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                      p.maxHeight, toB(camera), toB(params)));
}

BoundPatchLod patchCenterBound(const Patch& patch, const BoundCamera& camera, const ScreenSphereParams& params) {
  const PatchB p(patch);
  return fromB(glslb::patchCenterLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                     p.maxHeight, toB(camera), toB(params)));
}

BoundPatchLod nvidiaTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                              const NvidiaTileParams& params) {
  const PatchB p(patch);
  return fromB(glslb::nvidiaTileLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                    p.maxHeight, toB(neighbours), toB(camera), toB(params)));
}

BoundPatchLod distancePow2Bound(const Patch& patch, const BoundCamera& camera, const DistancePow2Params& params) {
  const PatchB p(patch);
  return fromB(glslb::distancePow2Lod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                      p.maxHeight, toB(camera), toB(params)));
}

BoundPatchLod distancePow2TileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                    const DistancePow2Params& params, const TileAdjacency& adjacency) {
  const PatchB p(patch);
  return fromB(glslb::distancePow2TileLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                          p.maxHeight, toB(neighbours), toB(camera), toB(params), toB(adjacency)));
}

BoundPatchLod bonaventuraBound(const Patch& patch, const BoundCamera& camera, const BonaventuraParams& params) {
  const PatchB p(patch);
  return fromB(glslb::bonaventuraLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                     p.maxHeight, toB(camera), toB(params)));
}

BoundPatchLod bonaventuraTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                   const BonaventuraParams& params, const TileAdjacency& adjacency) {
  const PatchB p(patch);
  return fromB(glslb::bonaventuraTileLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                         p.maxHeight, toB(neighbours), toB(camera), toB(params), toB(adjacency)));
}

BoundPatchLod clipDiameterBound(const Patch& patch, const BoundCamera& camera, const ClipDiameterParams& params) {
  const PatchB p(patch);
  return fromB(glslb::clipDiameterLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                      p.maxHeight, toB(camera), toB(params)));
}

BoundPatchLod clipDiameterTileBound(const Patch& patch, const TileNeighbours& neighbours, const BoundCamera& camera,
                                    const ClipDiameterParams& params, const TileAdjacency& adjacency) {
  const PatchB p(patch);
  return fromB(glslb::clipDiameterTileLod(p.c[0], p.c[1], p.c[2], p.c[3], patch.useHeightBounds, p.minHeight,
                                          p.maxHeight, toB(neighbours), toB(camera), toB(params), toB(adjacency)));
}

BoundPatchLod constantTileBound(float factor, const TileNeighbours& neighbours, const TileAdjacency& adjacency) {
  return fromB(glslb::constantTileLod(Bound(factor), toB(neighbours), toB(adjacency)));
}

} // namespace fftess::lod
