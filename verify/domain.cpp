// Domain-shader emulation: world position of a domain point as the scene's domain shader computes it, in float, in
// the order each formula states (no contraction into FMA unless the formula names fma).
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

glm::vec3 evalDomain(const TerrainData& t, const TerrainPatch& p, float u, float v, WorkStats& work) {
  const Scene& s = t.scene;
  const glm::vec3* c = p.corners;
  glm::vec3 w;
  w.x = bilerp(s.domain, c[0].x, c[1].x, c[2].x, c[3].x, u, v);
  w.z = bilerp(s.domain, c[0].z, c[1].z, c[2].z, c[3].z, u, v);
  w.y = 0.0f; // the corners are flat (the sample's hull shader drops y); the height is added below
  ++work.domainEvaluations;
  if (s.displacement.kind != DisplacementKind::None) {
    float tx, tz;
    if (s.domain.heightUv == HeightUv::World) {
      tx = (w.x - t.extent.minX) * t.invSizeX;
      tz = (w.z - t.extent.minZ) * t.invSizeZ;
    } else {
      tx = bilerp(s.domain, p.tex[0][0], p.tex[1][0], p.tex[2][0], p.tex[3][0], u, v);
      tz = bilerp(s.domain, p.tex[0][1], p.tex[1][1], p.tex[2][1], p.tex[3][1], u, v);
    }
    w.y = w.y + s.displacement.heightScale * sampleBilinear(s.displacement, tx, tz);
    ++work.heightSamples;
  }
  return w;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

glm::vec3 domainPosition(const Terrain& terrain, int patchIndex, float u, float v) {
  if (terrain.empty() || patchIndex < 0 || patchIndex >= terrain.patchCount()) return {};
  const detail::TerrainData& t = terrain.data();
  WorkStats work;
  return detail::evalDomain(t, t.patches[static_cast<size_t>(patchIndex)], u, v, work);
}

} // namespace fftess::verify
