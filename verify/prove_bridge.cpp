// fftess prove: the scene's LOD over Bounds (patchLodBound, the dispatch of lod_bridge.cpp's patchLod), the region's
// cameras, the exact frustum of a region (RegionFrustum) and the culling argument (docs/verify.md, "Proofs").
#include "verify/prove_internal.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fftess::verify::detail {

lod::BoundPatchLod patchLodBound(const TerrainData& t, const TerrainPatch& p, const lod::BoundCamera& cam) {
  const Lod& L = t.scene.lod;
  const bool tile = t.adjacency;
  const lod::TileAdjacency adj{L.screenSphere.clamp, L.screenSphere.reconstruction};
  switch (L.scheme) {
  case LodScheme::ScreenSphere:
    return tile ? lod::nvidiaTileBound(p.lod, p.tile, cam, L.screenSphere)
                : lod::screenSphereBound(p.lod, cam, L.screenSphere.sphere);
  case LodScheme::PatchCenter: return lod::patchCenterBound(p.lod, cam, L.screenSphere.sphere);
  case LodScheme::DistancePow2:
    return tile ? lod::distancePow2TileBound(p.lod, p.tile, cam, L.distancePow2, adj)
                : lod::distancePow2Bound(p.lod, cam, L.distancePow2);
  case LodScheme::Bonaventura:
    return tile ? lod::bonaventuraTileBound(p.lod, p.tile, cam, L.bonaventura, adj)
                : lod::bonaventuraBound(p.lod, cam, L.bonaventura);
  case LodScheme::ClipDiameter:
    return tile ? lod::clipDiameterTileBound(p.lod, p.tile, cam, L.clipDiameter, adj)
                : lod::clipDiameterBound(p.lod, cam, L.clipDiameter);
  case LodScheme::Constant:
    if (tile) return lod::constantTileBound(L.factor, p.tile, adj);
    {
      lod::BoundPatchLod r;
      for (lod::Bound& x : r.factors) x = lod::Bound(L.factor);
      return r;
    }
  case LodScheme::Geomorph: break; // refused by proveScene and gpuFloatRefusal
  case LodScheme::Shader: break;   // refused by proveScene and gpuFloatRefusal
  }
  lod::BoundPatchLod r;
  for (lod::Bound& x : r.factors) x = lod::Bound::anything();
  return r;
}

RegionCameras regionCameras(const Camera& c, const CameraRegion& r) {
  // As viewCamera / toLodCamera: fov in radians = fovY * float(pi / 180), one float product.
  const float fov = c.fovY * (3.14159265358979323846f / 180.0f);
  const glm::vec2 viewport(static_cast<float>(c.width), static_cast<float>(c.height));
  RegionCameras out;
  out.view = lod::boundCameraRegion(r.eyeLo, r.eyeHi, r.targetLo, r.targetHi, c.up, fov, c.nearZ, c.farZ, viewport,
                                    false);
  out.lod = c.convention == CameraConvention::Gl
                ? out.view
                : lod::boundCameraRegion(r.eyeLo, r.eyeHi, r.targetLo, r.targetHi, c.up, fov, c.nearZ, c.farZ,
                                         viewport, true);
  return out;
}

namespace {

constexpr double kPad = 0x1p-40;
constexpr double kTiny = 1e-300;

Interval widen(double lo, double hi) {
  return {lo - std::fabs(lo) * kPad - kTiny, hi + std::fabs(hi) * kPad + kTiny};
}
Interval add(Interval a, Interval b) { return widen(a.lo + b.lo, a.hi + b.hi); }
Interval scaled(Interval a, double c) {
  const double x = a.lo * c, y = a.hi * c;
  return widen(std::min(x, y), std::max(x, y));
}
double magnitude(Interval a) { return std::max(std::fabs(a.lo), std::fabs(a.hi)); }

Interval ofBound(const lod::Bound& b) {
  if (b.nan) return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  return {static_cast<double>(b.lo), static_cast<double>(b.hi)};
}

constexpr int kRow[6] = {0, 0, 1, 1, 2, 2};
constexpr double kSign[6] = {1, -1, 1, -1, 1, -1};

// The rounding bound of lod/'s float plane test (the matrix product, the plane's sum, the dot product with the box
// corner, a corner chosen by a coefficient's rounded sign) and of a vertex's clip coordinates, relative to scale: 64
// units in the last place (2^-24 each) of the magnitudes, several times the sum of the individual bounds.
constexpr double kRounding = 0x1p-18;

glm::dvec3 cornerOf(const glm::dvec3& lo, const glm::dvec3& hi, int i) {
  return {i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z};
}

} // namespace

void lodBox(const TerrainPatch& p, glm::dvec3& lo, glm::dvec3& hi) {
  lo = hi = glm::dvec3(p.lod.corners[0]);
  for (const glm::vec3& c : p.lod.corners) {
    lo = glm::min(lo, glm::dvec3(c));
    hi = glm::max(hi, glm::dvec3(c));
  }
  if (p.lod.useHeightBounds) {
    lo.y = std::min(lo.y, static_cast<double>(p.lod.minHeight));
    hi.y = std::max(hi.y, static_cast<double>(p.lod.maxHeight));
  }
}

RegionFrustum::RegionFrustum(const lod::BoundCamera& view) {
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < 4; ++l) {
      v_[c][l] = ofBound(view.view[c][l]);
      p_[c][l] = static_cast<double>(view.projection[c][l].lo);
    }
  viewport_[0] = static_cast<double>(view.viewport.x.lo);
  viewport_[1] = static_cast<double>(view.viewport.y.lo);
}

// value = sum over l of a_l * (view * q)_l, a_l = P[l][3] + sign * P[l][row] (exact in double).
Interval RegionFrustum::plane(int k, const glm::dvec3& q) const {
  const double qc[4] = {q.x, q.y, q.z, 1.0};
  Interval sum{0, 0};
  for (int l = 0; l < 4; ++l) {
    const double a = p_[l][3] + kSign[k] * p_[l][kRow[k]];
    if (a == 0) continue;
    Interval vq{0, 0};
    for (int c = 0; c < 4; ++c) vq = add(vq, scaled(v_[c][l], qc[c]));
    sum = add(sum, scaled(vq, a));
  }
  return sum;
}

Interval RegionFrustum::clipW(const glm::dvec3& q) const {
  const double qc[4] = {q.x, q.y, q.z, 1.0};
  Interval sum{0, 0};
  for (int l = 0; l < 4; ++l) {
    if (p_[l][3] == 0) continue;
    Interval vq{0, 0};
    for (int c = 0; c < 4; ++c) vq = add(vq, scaled(v_[c][l], qc[c]));
    sum = add(sum, scaled(vq, p_[l][3]));
  }
  return sum;
}

double RegionFrustum::scale(int k, const glm::dvec3& q) const {
  const double qc[4] = {std::fabs(q.x), std::fabs(q.y), std::fabs(q.z), 1.0};
  double s = 0;
  for (int c = 0; c < 4; ++c)
    for (int l = 0; l < 4; ++l)
      s += (std::fabs(p_[l][3]) + std::fabs(p_[l][kRow[k]])) * magnitude(v_[c][l]) * qc[c];
  return s * (1 + 0x1p-30);
}

bool RegionFrustum::boxOffScreen(const glm::dvec3& lo, const glm::dvec3& hi) const {
  const glm::dvec3 at = glm::max(glm::abs(lo), glm::abs(hi));
  for (int k = 0; k < 6; ++k) {
    const double margin = 0x1p-16 * scale(k, at);
    bool outside = true;
    for (int i = 0; i < 8 && outside; ++i) outside = plane(k, cornerOf(lo, hi, i)).hi + margin < 0;
    if (outside) return true;
  }
  return false;
}

bool RegionFrustum::cullHarmless(const glm::dvec3& lodLo, const glm::dvec3& lodHi, const glm::dvec3& lo,
                                 const glm::dvec3& hi, std::string& why) const {
  const glm::dvec3 at = glm::max(glm::max(glm::abs(lo), glm::abs(hi)), glm::max(glm::abs(lodLo), glm::abs(lodHi)));
  // (a) near and far cannot reject: some lod box corner inside by more than the rounding bound at every camera.
  for (int k = 4; k < 6; ++k) {
    const double e = kRounding * scale(k, at);
    bool inside = false;
    for (int i = 0; i < 8 && !inside; ++i) inside = plane(k, cornerOf(lodLo, lodHi, i)).lo > e;
    if (!inside) {
      why = k == 4 ? "the near plane may cull it" : "the far plane may cull it";
      return false;
    }
  }
  // (b) side planes: rounding + excess of the patch box over the lod box < half of w / W at every corner.
  const glm::dvec3 excess = glm::max(hi - lodHi, glm::dvec3(0)) + glm::max(lodLo - lo, glm::dvec3(0));
  double wMin = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 8; ++i) wMin = std::min(wMin, clipW(cornerOf(lo, hi, i)).lo);
  if (!(wMin > 0)) {
    why = "part of it may be behind the eye";
    return false;
  }
  for (int k = 0; k < 4; ++k) {
    double slope = 0; // >= |plane coefficient c| for every camera, times the excess along c
    for (int c = 0; c < 3; ++c) {
      double n = 0;
      for (int l = 0; l < 4; ++l) n += std::fabs(p_[l][3] + kSign[k] * p_[l][kRow[k]]) * magnitude(v_[c][l]);
      slope += n * excess[c];
    }
    const double bound = kRounding * scale(k, at) + slope * (1 + 0x1p-30);
    const double halfPixel = wMin / viewport_[k < 2 ? 0 : 1];
    if (!(bound < 0.5 * halfPixel)) {
      why = "its distance to the eye is too small for the half-pixel argument (rounding bound " +
            std::to_string(bound) + " >= " + std::to_string(0.5 * halfPixel) + ")";
      return false;
    }
  }
  return true;
}

} // namespace fftess::verify::detail
