// lod_bound.h: lod/shaders/*.glsl (not geomorph.glsl) compiled with Bound as float: the shim of lod/glsl_cpp.h with
// float, vec2/3/4 and mat4 mapped to Bound types; a vector times a float literal converts the literal to a constant
// Bound; the vector min/max the shaders use are written per component (GLM's static_assert an IEEE float type).
#include "lod/lod_bound.h"

#include <algorithm>
#include <cmath>

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
// Component by component, in GLM's order, without GLM's temporaries (the operations the shaders use).
inline vec2 operator*(const vec2& v, const Bound& s) { return vec2(v.x * s, v.y * s); }
inline vec3 operator*(const vec3& v, const Bound& s) { return vec3(v.x * s, v.y * s, v.z * s); }
inline vec4 operator*(const vec4& v, const Bound& s) { return vec4(v.x * s, v.y * s, v.z * s, v.w * s); }
inline vec3 operator*(const Bound& s, const vec3& v) { return vec3(s * v.x, s * v.y, s * v.z); }
inline vec3 operator/(const vec3& v, const Bound& s) { return vec3(v.x / s, v.y / s, v.z / s); }
inline vec3 operator+(const vec3& a, const vec3& b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
inline vec3 operator-(const vec3& a, const vec3& b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
inline vec4 operator+(const vec4& a, const vec4& b) { return vec4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w); }
inline vec4 operator-(const vec4& a, const vec4& b) { return vec4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w); }
// A vector times a float literal: the literal as a constant Bound.
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

// A second enclosure of lookAt's entries, intersected with the GLM-order one (which treats s, u, f and the eye as
// independent, so a region's entries come out a few times wider than they vary): the exact lookAt at the centre of
// the region (double), plus a Lipschitz bound of the exact function over the region, plus a bound of the rounding of
// GLM's float sequence (eps = 2^-24, each term four times the derivation's, docs/lod.md "Bounds"):
//   d = target - eye, |d - dc| <= r = re + rt (half diagonals); on |d| >= md = |dc| - r, |f - fc| <= r / md = rhoF;
//   c = f x up: |c - cc| <= |up| rhoF; s = c / |c|: rhoS = |up| rhoF / mc, mc = |cc| - |up| rhoF;
//   u = s x f: rhoU = rhoS + rhoF; dot(s, eye): rhoS |eye|max + re (likewise u, f).
//   Rounding: f 6.5 eps (16 used); c 21 eps |up| (32); s 2 errC / (mc - errC) + 6.5 eps (16); u errS + errF + 5.2
//   eps (16); dot(v, eye) (errV + 3.1 eps) |eye|max (4).
// Applied only when the region is small against the eye-target distance and the up vector's angle (md > dc / 2,
// mc > cc / 2); otherwise the GLM-order enclosure stands alone.
void tightenLookAt(BoundMat4& view, glm::dvec3 eLo, glm::dvec3 eHi, glm::dvec3 tLo, glm::dvec3 tHi, glm::dvec3 up,
                   bool leftHanded) {
  const double eps = 0x1p-24;
  const double safety = 4.0;
  const glm::dvec3 ec = (eLo + eHi) * 0.5;
  const glm::dvec3 tc = (tLo + tHi) * 0.5;
  const double re = glm::length(eHi - eLo) * 0.5;
  const double r = re + glm::length(tHi - tLo) * 0.5;
  const glm::dvec3 dc = tc - ec;
  const double nd = glm::length(dc);
  const double md = nd - r;
  if (!(md > 0.5 * nd)) return;
  const glm::dvec3 fc = dc / nd;
  const double rhoF = r / md;
  const double nu = glm::length(up);
  const glm::dvec3 cc = leftHanded ? glm::cross(up, fc) : glm::cross(fc, up);
  const double nc = glm::length(cc);
  const double mc = nc - nu * rhoF;
  if (!(mc > 0.5 * nc)) return;
  const glm::dvec3 sc = cc / nc;
  const glm::dvec3 uc = leftHanded ? glm::cross(fc, sc) : glm::cross(sc, fc);
  const double rhoS = nu * rhoF / mc;
  const double rhoU = rhoS + rhoF;
  const double eyeMax = glm::length(ec) + re;
  const double errF = safety * 16.0 * eps;
  const double errC = safety * 32.0 * eps * nu;
  if (!(mc - errC > 0.0)) return;
  const double errS = safety * (2.0 * errC / (mc - errC) + 16.0 * eps);
  const double errU = errS + errF + safety * 16.0 * eps;
  const double slack = 1e-12 * (1.0 + eyeMax); // the double evaluation of the centre
  const double fSign = leftHanded ? 1.0 : -1.0;
  struct Entry {
    int col, row;
    double centre, radius;
  } entries[12] = {
      {0, 0, sc.x, rhoS + errS},
      {1, 0, sc.y, rhoS + errS},
      {2, 0, sc.z, rhoS + errS},
      {0, 1, uc.x, rhoU + errU},
      {1, 1, uc.y, rhoU + errU},
      {2, 1, uc.z, rhoU + errU},
      {0, 2, fSign * fc.x, rhoF + errF},
      {1, 2, fSign * fc.y, rhoF + errF},
      {2, 2, fSign * fc.z, rhoF + errF},
      {3, 0, -glm::dot(sc, ec), rhoS * eyeMax + re + (errS + safety * 4.0 * eps) * eyeMax},
      {3, 1, -glm::dot(uc, ec), rhoU * eyeMax + re + (errU + safety * 4.0 * eps) * eyeMax},
      {3, 2, fSign * glm::dot(fc, ec), rhoF * eyeMax + re + (errF + safety * 4.0 * eps) * eyeMax},
  };
  for (const Entry& e : entries) {
    Bound& b = view[e.col][e.row];
    const double radius = e.radius * 1.01 + slack;
    const float lo = std::max(b.lo, static_cast<float>(e.centre - radius)); // float(x) rounds to nearest: step out
    const float hi = std::min(b.hi, static_cast<float>(e.centre + radius));
    const float loOut = std::nextafter(lo, -INFINITY);
    const float hiOut = std::nextafter(hi, INFINITY);
    if (b.hasValues() && std::max(b.lo, loOut) <= std::min(b.hi, hiOut)) {
      b.lo = std::max(b.lo, loOut);
      b.hi = std::min(b.hi, hiOut);
    }
  }
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
  tightenLookAt(c.view, glm::dvec3(eyeLo), glm::dvec3(eyeHi), glm::dvec3(targetLo), glm::dvec3(targetHi),
                glm::dvec3(up), d3d);
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
