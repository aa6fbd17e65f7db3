// Domain-shader emulation: world position of a domain point as the scene's domain shader computes it, in float, in
// the order each formula states (no contraction into FMA unless the formula names fma).
#include "verify/terrain.h"
#include "verify/internal.h"

#include <cmath>

namespace fftess::verify::detail {

namespace {

float lerpWith(LerpFormula f, float a, float b, float t) {
  switch (f) {
  case LerpFormula::Nvidia:
  case LerpFormula::Lerp: return a + t * (b - a);
  case LerpFormula::LerpFma: return std::fma(t, b - a, a);
  case LerpFormula::Blend: return a * (1.0f - t) + b * t;
  case LerpFormula::BlendFma: return std::fma(b, t, a * (1.0f - t));
  }
  return a + t * (b - a);
}

// Bilinear interpolation of four scalars c[u + 2v] in the scene's stated order.
float bilerp(const DomainShader& ds, float c0, float c1, float c2, float c3, float u, float v) {
  if (ds.order == LerpOrder::UFirst) {
    const float bottom = lerpWith(ds.formula, c0, c1, u);
    const float top = lerpWith(ds.formula, c2, c3, u);
    return lerpWith(ds.formula, bottom, top, v);
  }
  const float left = lerpWith(ds.formula, c0, c2, v);
  const float right = lerpWith(ds.formula, c1, c3, v);
  return lerpWith(ds.formula, left, right, u);
}

} // namespace

// tx = (x - minX) * (1 / sizeX), tz likewise, each rounded to float; height = heightScale * sample.
float heightAt(const TerrainData& t, float x, float z, WorkStats& work) {
  ++work.heightSamples;
  const float tx = (x - t.extent.minX) * t.invSizeX;
  const float tz = (z - t.extent.minZ) * t.invSizeZ;
  const Displacement& d = t.scene.displacement;
  return d.heightScale * sampleBilinear(d, tx, tz);
}

namespace {

// The interpolated world x/z of (u, v) (y = 0: the corners are flat, the sample's hull shader drops y).
glm::vec3 flatPosition(const TerrainData& t, const TerrainPatch& p, float u, float v) {
  const DomainShader& ds = t.scene.domain;
  const glm::vec3* c = p.corners;
  glm::vec3 w;
  w.x = bilerp(ds, c[0].x, c[1].x, c[2].x, c[3].x, u, v);
  w.z = bilerp(ds, c[0].z, c[1].z, c[2].z, c[3].z, u, v);
  w.y = 0.0f;
  return w;
}

// The mip level at (u, v): per_patch the patch's level; per_vertex the corner levels interpolated u first with
// blend, a*(1 - u) + b*u, then the same across v (exact at u, v in {0, 1}, so the two patches of an edge
// interpolate the same two corner levels with the same weight: the same level at the same point).
float mipLevelAt(const Displacement& d, const PatchDomain& cam, float u, float v) {
  if (d.mip == MipMode::PerPatch) return cam.mipLevel[0];
  const float* l = cam.mipLevel;
  const float bottom = l[0] * (1.0f - u) + l[1] * u;
  const float top = l[2] * (1.0f - u) + l[3] * u;
  return bottom * (1.0f - v) + top * v;
}

// The true displaced height at (u, v) whose flat position is w: the texture coordinate per domain.height_uv,
// sampled (bilinear, or trilinear at the camera's mip level), then 0 + height_scale * h.
float trueHeight(const TerrainData& t, const TerrainPatch& p, const glm::vec3& w, float u, float v,
                 const PatchDomain* cam, WorkStats& work) {
  const Scene& s = t.scene;
  float tx, tz;
  if (s.domain.heightUv == HeightUv::World) {
    tx = (w.x - t.extent.minX) * t.invSizeX;
    tz = (w.z - t.extent.minZ) * t.invSizeZ;
  } else {
    tx = bilerp(s.domain, p.tex[0][0], p.tex[1][0], p.tex[2][0], p.tex[3][0], u, v);
    tz = bilerp(s.domain, p.tex[0][1], p.tex[1][1], p.tex[2][1], p.tex[3][1], u, v);
  }
  ++work.heightSamples;
  const Displacement& d = s.displacement;
  const float h = cam && d.mip != MipMode::None ? sampleTrilinear(d, tx, tz, mipLevelAt(d, *cam, u, v))
                                                : sampleBilinear(d, tx, tz);
  return 0.0f + d.heightScale * h;
}

float heightAtDomain(const TerrainData& t, const TerrainPatch& p, float u, float v, const PatchDomain* cam,
                     WorkStats& work) {
  return trueHeight(t, p, flatPosition(t, p, u, v), u, v, cam, work);
}

// x * n is an odd integer (n a power of two <= 64, x a multiple of 1/n from integer partitioning: exact).
bool oddIndex(float x, float n, float& k) {
  k = x * n;
  if (!(k == std::floor(k))) return false;
  return std::fmod(k, 2.0f) == 1.0f;
}

// Geomorphing (lod.scheme = "geomorph"): the vertices the finest level inserts, i.e. those at an odd index k of
// the n segments, morph between the midpoint of their two neighbours at (k - 1) / n and (k + 1) / n and their true
// height (lod::geomorphHeight, weight lod::geomorphWeight). An edge point (u or v in {0, 1}) uses its edge's
// segments and border weight (Ueq0/Ueq1 along v, Veq0/Veq1 along u; corners are never inserted); an interior point
// the inside segments and the patch's own weight, its neighbours along u when its u index is odd and its v index
// even, along v in the opposite case, and across the diagonal (u -+ 1/n, v -+ 1/n) when both are odd.
float geomorphY(const TerrainData& t, const TerrainPatch& p, float u, float v, float y, const PatchDomain& cam,
                WorkStats& work) {
  int e = -1;
  if (u == 0.0f) e = Ueq0;
  else if (u == 1.0f) e = Ueq1;
  else if (v == 0.0f) e = Veq0;
  else if (v == 1.0f) e = Veq1;
  float du = 0, dv = 0, w = 0;
  if (e >= 0) {
    const float n = cam.morphSegments[e];
    const bool alongU = e == Veq0 || e == Veq1;
    float k;
    if (!oddIndex(alongU ? u : v, n, k)) return y;
    (alongU ? du : dv) = 1.0f / n;
    w = cam.morphWeight[e];
  } else {
    const float n = cam.morphSegments[4];
    float ku, kv;
    const bool oddU = oddIndex(u, n, ku), oddV = oddIndex(v, n, kv);
    if (!(ku == std::floor(ku)) || !(kv == std::floor(kv)) || (!oddU && !oddV)) return y;
    if (oddU) du = 1.0f / n;
    if (oddV) dv = 1.0f / n;
    w = cam.morphWeight[4];
  }
  const float hPrev = heightAtDomain(t, p, u - du, v - dv, &cam, work);
  const float hNext = heightAtDomain(t, p, u + du, v + dv, &cam, work);
  return lod::geomorphHeight(y, hPrev, hNext, w);
}

} // namespace

glm::vec3 flatDomain(const TerrainData& t, const TerrainPatch& p, float u, float v) { return flatPosition(t, p, u, v); }

glm::vec3 evalDomain(const TerrainData& t, const TerrainPatch& p, float u, float v, const PatchDomain* camera,
                     WorkStats& work) {
  const Scene& s = t.scene;
  glm::vec3 w = flatPosition(t, p, u, v);
  ++work.domainEvaluations;
  if (s.displacement.kind != DisplacementKind::None) {
    w.y = trueHeight(t, p, w, u, v, camera, work);
    if (camera && s.lod.scheme == LodScheme::Geomorph) w.y = geomorphY(t, p, u, v, w.y, *camera, work);
  }
  return w;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

glm::vec3 domainPosition(const Terrain& terrain, int patchIndex, float u, float v) {
  if (terrain.empty() || patchIndex < 0 || patchIndex >= terrain.patchCount()) return {};
  const detail::TerrainData& t = terrain.data();
  WorkStats work;
  return detail::evalDomain(t, t.patches[static_cast<size_t>(patchIndex)], u, v, nullptr, work);
}

} // namespace fftess::verify
