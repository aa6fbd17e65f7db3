// Is a patch that is not drawn on screen? The hole check's visibility decision (visibility.h, Hole; docs/verify.md,
// "Holes"): the patch's (u, v) domain is split recursively; a sub-rectangle whose conservative box of the displaced
// surface lies outside one frustum plane is invisible, a domain point strictly inside the frustum proves the patch
// visible, anything else is split again down to a stated minimum size. All in double from lod's float matrices, so
// the decision does not inherit the float rounding of the LOD's own cull.
#include "verify/visibility.h"
#include "verify/internal.h"

#include <algorithm>
#include <cmath>

namespace fftess::verify::detail {

FrustumTest::FrustumTest(const lod::Camera& camera) {
  // clip = projection * view; m_[row][col]. glm is column-major: matrix[col][row].
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      double sum = 0;
      for (int k = 0; k < 4; ++k)
        sum += static_cast<double>(camera.projection[k][r]) * static_cast<double>(camera.view[c][k]);
      m_[r][c] = sum;
    }
  static constexpr int kRow[6] = {0, 0, 1, 1, 2, 2};
  static constexpr double kSign[6] = {1, -1, 1, -1, 1, -1};
  for (int p = 0; p < 6; ++p)
    for (int c = 0; c < 4; ++c) {
      plane_[p][c] = m_[3][c] + kSign[p] * m_[kRow[p]][c];
      planeScale_[p][c] = std::fabs(m_[3][c]) + std::fabs(m_[kRow[p]][c]);
    }
}

// The six planes (plane_, from the constructor), each tested at the box corner furthest along its normal.
bool FrustumTest::boxOutside(const glm::dvec3& lo, const glm::dvec3& hi) const {
  for (int p = 0; p < 6; ++p) {
    const double* n = plane_[p];
    // The box corner furthest along the plane's normal.
    const double x = n[0] >= 0 ? hi.x : lo.x, y = n[1] >= 0 ? hi.y : lo.y, z = n[2] >= 0 ? hi.z : lo.z;
    if (n[0] * x + n[1] * y + n[2] * z + n[3] < 0) return true;
  }
  return false;
}

bool FrustumTest::boxInside(const glm::dvec3& lo, const glm::dvec3& hi) const {
  for (int p = 0; p < 6; ++p) {
    const double* n = plane_[p];
    // The box corner furthest against the plane's normal.
    const double x = n[0] >= 0 ? lo.x : hi.x, y = n[1] >= 0 ? lo.y : hi.y, z = n[2] >= 0 ? lo.z : hi.z;
    if (!(n[0] * x + n[1] * y + n[2] * z + n[3] > 0)) return false;
  }
  return true;
}

// The same planes; a box counts as outside a plane only by a margin: at the corner tested, the plane's value
// (w +- x, w +- y, w +- z of the clip matrix's rows) must be below -2^-16 * sum over c of (|m[3][c]| + |m[k][c]|) *
// M_c, M_c = max(|lo_c|, |hi_c|) (M_3 = 1): a bound on the magnitudes a GPU's float clip coordinates w and x (y, z)
// of any point of the box are rounded relative to (view, then projection: a few roundings of 2^-24 each). The margin
// is 2^8 times that, so nothing a GPU may draw is called off screen. Monotone: a box inside a box proven off screen
// is proven off screen (its value is no larger, its margin no larger). The clip matrix itself is the double product
// of lod's float matrices (as boxOutside).
bool FrustumTest::boxOffScreen(const glm::dvec3& lo, const glm::dvec3& hi) const {
  for (int p = 0; p < 6; ++p) {
    const double* n = plane_[p];
    const double x = n[0] >= 0 ? hi.x : lo.x, y = n[1] >= 0 ? hi.y : lo.y, z = n[2] >= 0 ? hi.z : lo.z;
    const double value = n[0] * x + n[1] * y + n[2] * z + n[3];
    const double at[4] = {std::fmax(std::fabs(lo.x), std::fabs(hi.x)), std::fmax(std::fabs(lo.y), std::fabs(hi.y)),
                          std::fmax(std::fabs(lo.z), std::fabs(hi.z)), 1};
    double scale = 0;
    for (int c = 0; c < 4; ++c) scale += planeScale_[p][c] * at[c];
    if (value < -0x1p-16 * scale) return true;
  }
  return false;
}

bool FrustumTest::clipSegment(const glm::dvec3& p, const glm::dvec3& q, double& t0, double& t1) const {
  for (int k = 0; k < 6; ++k) {
    const double* n = plane_[k];
    const double dp = n[0] * p.x + n[1] * p.y + n[2] * p.z + n[3];
    const double dq = n[0] * q.x + n[1] * q.y + n[2] * q.z + n[3];
    if (dp < 0 && dq < 0) return false;
    if (dp < 0) t0 = std::max(t0, dp / (dp - dq)); // enters the plane's inside at this t
    if (dq < 0) t1 = std::min(t1, dp / (dp - dq)); // leaves it
    if (t0 > t1) return false;
  }
  return true;
}

bool FrustumTest::inside(const glm::vec3& p) const {
  double c[4];
  for (int r = 0; r < 4; ++r) c[r] = m_[r][0] * p.x + m_[r][1] * p.y + m_[r][2] * p.z + m_[r][3];
  const double w = c[3];
  return w > 0 && std::fabs(c[0]) < w && std::fabs(c[1]) < w && c[2] > -w && c[2] < w;
}

namespace {

// A sub-rectangle of the domain: [u0, u0 + side] x [v0, v0 + side], side = 2^-depth (dyadic: exact in float).
struct SubRect {
  float u0 = 0, v0 = 0;
  int depth = 0;
  float side() const { return std::ldexp(1.0f, -depth); }
};

// The exact bilinear interpolation (double) of four values c[u + 2v] at (u, v).
double bilinearExact(double c0, double c1, double c2, double c3, double u, double v) {
  return (c0 * (1 - u) + c1 * u) * (1 - v) + (c2 * (1 - u) + c3 * u) * v;
}

// Range of the exact bilinear interpolation of c[u + 2v] over [u0, u1] x [v0, v1] (extremes at its corners),
// widened by pad.
void bilinearRange(const double c[4], double u0, double u1, double v0, double v1, double pad, double& lo,
                   double& hi) {
  lo = INFINITY, hi = -INFINITY;
  for (int k = 0; k < 4; ++k) {
    const double x = bilinearExact(c[0], c[1], c[2], c[3], (k & 1) ? u1 : u0, (k & 2) ? v1 : v0);
    lo = std::fmin(lo, x);
    hi = std::fmax(hi, x);
  }
  lo -= pad, hi += pad;
}

// How far the domain shader's float bilinear interpolation (domain.formula, two stages, either order) of four float
// values c can be from their exact bilinear interpolation, with a factor 2 of margin. u = 2^-24, mag = max |c|,
// span = max c - min c. lerp forms (a + t*(b - a), fma(t, b - a, a)): per stage 2u*|b - a| + u*|result|, so
// 4u*span + 2u*mag over the two stages; blend forms (a*(1 - t) + b*t, fma(b, t, a*(1 - t))): 1 - t, both products
// and the sum round with errors of the operands' size, 4u*mag per stage, 8u*mag in all.
double lerpPad(LerpFormula f, const double c[4]) {
  double lo = c[0], hi = c[0], mag = 0;
  for (int k = 0; k < 4; ++k) lo = std::fmin(lo, c[k]), hi = std::fmax(hi, c[k]), mag = std::fmax(mag, std::fabs(c[k]));
  const double u = 0x1p-24;
  const bool blend = f == LerpFormula::Blend || f == LerpFormula::BlendFma;
  return 2 * (blend ? 8 * u * mag : 4 * u * (hi - lo) + 2 * u * mag) + 1e-300;
}

// Per patch, fixed over the decision: what the sub-rectangle boxes need.
struct BoxMaker {
  const TerrainData& t;
  const TerrainPatch& p;
  const PatchDomain* cam;
  double cx[4], cz[4], tu[4], tv[4]; // corner x, z and texture coordinates
  double padX = 0, padZ = 0, padU = 0, padV = 0; // lerpPad of each
  int levelLo = 0, levelHi = 0;     // the mip levels the domain shader can sample on this patch
  double morphReach = 0;            // geomorph: how far (domain units) an inserted vertex reads its neighbours

  BoxMaker(const TerrainData& td, const TerrainPatch& tp, const PatchDomain* c) : t(td), p(tp), cam(c) {
    for (int k = 0; k < 4; ++k) cx[k] = p.corners[k].x, cz[k] = p.corners[k].z, tu[k] = p.tex[k][0], tv[k] = p.tex[k][1];
    const LerpFormula f = t.scene.domain.formula;
    padX = lerpPad(f, cx), padZ = lerpPad(f, cz), padU = lerpPad(f, tu), padV = lerpPad(f, tv);
    const Displacement& d = t.scene.displacement;
    const int top = d.mips ? static_cast<int>(d.mips->size()) : 0;
    if (cam && d.mip != MipMode::None) {
      // sampleTrilinear: l clamped to [0, top] (NaN: 0), levels floor(l) and floor(l) + 1. per_vertex interpolates the
      // corner levels with weights in [0, 1]: the level stays within the corners' range.
      double lo = INFINITY, hi = -INFINITY;
      const int n = d.mip == MipMode::PerPatch ? 1 : 4;
      bool nan = false;
      for (int k = 0; k < n; ++k) {
        const double l = cam->mipLevel[k];
        nan = nan || std::isnan(l);
        lo = std::fmin(lo, l), hi = std::fmax(hi, l);
      }
      // The interpolation rounds (a level of exactly 1 can come out as 0.99999994): widened by 2^-10 each way.
      lo = std::clamp(lo - 0x1p-10, 0.0, static_cast<double>(top));
      hi = std::clamp(hi + 0x1p-10, 0.0, static_cast<double>(top));
      levelLo = nan ? 0 : static_cast<int>(std::floor(lo));
      levelHi = std::min(top, static_cast<int>(std::floor(hi)) + 1);
    }
    if (cam && t.scene.lod.scheme == LodScheme::Geomorph) {
      // An inserted vertex morphs towards its neighbours at +-1/n (n: the segments of its edge or of the interior).
      float n = INFINITY;
      for (float s : cam->morphSegments) n = std::fmin(n, s);
      morphReach = n >= 1.0f && std::isfinite(n) ? 1.0 / n : 1.0;
    }
  }

  // The conservative box of the displaced surface over r.
  void box(const SubRect& r, glm::dvec3& lo, glm::dvec3& hi) const {
    const double u0 = r.u0, v0 = r.v0, u1 = u0 + r.side(), v1 = v0 + r.side();
    bilinearRange(cx, u0, u1, v0, v1, padX, lo.x, hi.x);
    bilinearRange(cz, u0, u1, v0, v1, padZ, lo.z, hi.z);
    lo.y = hi.y = 0;
    if (t.scene.displacement.kind == DisplacementKind::None) return; // y = 0 exactly
    heightRange(std::fmax(0.0, u0 - morphReach), std::fmin(1.0, u1 + morphReach), std::fmax(0.0, v0 - morphReach),
                std::fmin(1.0, v1 + morphReach), lo.y, hi.y);
  }

  // The heights the domain shader can return at domain points of [u0, u1] x [v0, v1]: the texels its bilinear
  // samples can read on the levels it samples (any filtered, mip-blended or geomorphed height lies between them,
  // up to the filters' rounding), times height_scale, padded by 2^-16 of the largest magnitude (the rounding is a
  // few ulp).
  void heightRange(double u0, double u1, double v0, double v1, double& ylo, double& yhi) const {
    const Displacement& d = t.scene.displacement;
    double txLo, txHi, tzLo, tzHi;
    if (t.scene.domain.heightUv == HeightUv::World) {
      // tx = (x - minX) * invSizeX in float: within 2^-23 (relative) of the exact value at the float x, and x lies
      // in the padded range.
      double xlo, xhi, zlo, zhi;
      bilinearRange(cx, u0, u1, v0, v1, padX, xlo, xhi);
      bilinearRange(cz, u0, u1, v0, v1, padZ, zlo, zhi);
      const double ix = t.invSizeX, iz = t.invSizeZ;
      txLo = (xlo - t.extent.minX) * ix, txHi = (xhi - t.extent.minX) * ix;
      tzLo = (zlo - t.extent.minZ) * iz, tzHi = (zhi - t.extent.minZ) * iz;
      txLo -= std::fabs(txLo) * 0x1p-22, txHi += std::fabs(txHi) * 0x1p-22;
      tzLo -= std::fabs(tzLo) * 0x1p-22, tzHi += std::fabs(tzHi) * 0x1p-22;
    } else {
      bilinearRange(tu, u0, u1, v0, v1, padU, txLo, txHi);
      bilinearRange(tv, u0, u1, v0, v1, padV, tzLo, tzHi);
    }
    double lo = INFINITY, hi = -INFINITY;
    for (int l = levelLo; l <= levelHi; ++l) {
      const std::vector<float>& tex = l == 0 ? *d.texels : (*d.mips)[static_cast<size_t>(l - 1)].texels;
      const int w = l == 0 ? d.texWidth : (*d.mips)[static_cast<size_t>(l - 1)].width;
      const int h = l == 0 ? d.texHeight : (*d.mips)[static_cast<size_t>(l - 1)].height;
      const Span sx = span(txLo, txHi, w, d.subtexelBits), sz = span(tzLo, tzHi, h, d.subtexelBits);
      auto at = [&](int x, int z) {
        return static_cast<double>(tex[static_cast<size_t>(z) * static_cast<size_t>(w) + static_cast<size_t>(x)]);
      };
      // Per texel cell [c, c + 1) the sample blends the same four (clamped) texels with weights in a range ([f0, 1]
      // in the first cell, [0, f1] in the last, [0, 1] between): a bilinear function of the weights, whose extremes
      // lie at the corners of that range.
      for (int64_t cellZ = sz.c0; cellZ <= sz.c1; ++cellZ)
        for (int64_t cellX = sx.c0; cellX <= sx.c1; ++cellX) {
          const int x0 = clampIndex(cellX, w), x1 = clampIndex(cellX + 1, w);
          const int z0 = clampIndex(cellZ, h), z1 = clampIndex(cellZ + 1, h);
          const double a = at(x0, z0), b = at(x1, z0), c = at(x0, z1), e = at(x1, z1);
          const double fx[2] = {cellX == sx.c0 ? sx.f0 : 0.0, cellX == sx.c1 ? sx.f1 : 1.0};
          const double fz[2] = {cellZ == sz.c0 ? sz.f0 : 0.0, cellZ == sz.c1 ? sz.f1 : 1.0};
          for (int k = 0; k < 4; ++k) {
            const double x = fx[k & 1], z = fz[k >> 1];
            const double v = (a + x * (b - a)) * (1 - z) + (c + x * (e - c)) * z;
            lo = std::fmin(lo, v);
            hi = std::fmax(hi, v);
          }
        }
    }
    if (!(lo <= hi)) lo = -INFINITY, hi = INFINITY; // no texel with a value (NaN texels): no bound
    const double hs = d.heightScale;
    const double a = hs * lo, b = hs * hi;
    ylo = std::fmin(a, b), yhi = std::fmax(a, b);
    const double pad = std::fmax(std::fabs(hs), std::fmax(std::fabs(ylo), std::fabs(yhi))) * 0x1p-16;
    ylo -= pad, yhi += pad;
  }

  // What a bilinear sample at a texture coordinate in [a, b] reads on an axis of n texels: s = t * n - 0.5 (float:
  // within (|s| + 1) * 2^-22 of the exact value), in cell c = floor(s) the texels c and c + 1 clamped to [0, n - 1],
  // weight f = s - c quantised to subtexelBits (round to nearest: monotone in s). The cells c0 .. c1 (cells beyond the
  // texture read the same clamped texels as the first one beyond it), the first's weights from f0, the last's to f1.
  struct Span {
    int64_t c0 = -1, c1 = 0;
    double f0 = 0, f1 = 1;
  };
  static Span span(double a, double b, int n, int subtexelBits) {
    double s0 = a * n - 0.5, s1 = b * n - 0.5;
    s0 -= (std::fabs(s0) + 1) * 0x1p-20;
    s1 += (std::fabs(s1) + 1) * 0x1p-20;
    Span out;
    out.c1 = n - 1;
    if (!(s0 <= s1)) return out; // NaN: every cell, full weights
    const double c0 = std::floor(s0), c1 = std::floor(s1);
    const double q = std::ldexp(1.0, subtexelBits);
    auto quantise = [&](double f) { return subtexelBits > 0 ? std::nearbyint(f * q) / q : f; };
    if (c0 >= -1) out.c0 = static_cast<int64_t>(std::fmin(c0, n - 1)), out.f0 = c0 <= n - 1 ? quantise(s0 - c0) : 0;
    if (c1 <= n - 1) out.c1 = static_cast<int64_t>(std::fmax(c1, -1)), out.f1 = c1 >= -1 ? quantise(s1 - c1) : 1;
    return out;
  }
  static int clampIndex(int64_t v, int n) { return v <= 0 ? 0 : v >= n - 1 ? n - 1 : static_cast<int>(v); }
};

} // namespace

void surfaceBox(const TerrainData& t, const TerrainPatch& p, const PatchDomain* domain, float u0, float v0, int depth,
                glm::dvec3& lo, glm::dvec3& hi) {
  BoxMaker(t, p, domain).box(SubRect{u0, v0, depth}, lo, hi);
}

// Breadth first, so that a patch with a large visible part is proven visible at a coarse level, and the work bound
// cuts the finest level rather than one corner of the patch.
VisibilityDecision patchVisibility(const TerrainData& t, const TerrainPatch& p, const PatchDomain* domain,
                                   const FrustumTest& frustum, const VisibilityLimits& limits, WorkStats& work) {
  VisibilityDecision out;
  {
    // The whole patch's box from the prepared bounds (every level the scene samples): most patches stop here.
    glm::dvec3 lo, hi;
    patchBox(p, lo, hi);
    if (frustum.boxOutside(lo, hi)) return out; // Invisible
  }
  const BoxMaker boxes(t, p, domain);
  const int maxDepth = std::clamp(limits.maxDepth, 0, 20);
  auto seen = [&](float u, float v) {
    const glm::vec3 w = evalDomain(t, p, u, v, domain, work);
    ++work.visibilityEvaluations;
    if (!frustum.inside(w)) return false;
    out.visibility = Visibility::Visible;
    out.point = w;
    out.at = {u, v};
    return true;
  };
  auto cornersSeen = [&](const SubRect& r) {
    const float s = r.side();
    return seen(r.u0, r.v0) || seen(r.u0 + s, r.v0) || seen(r.u0, r.v0 + s) || seen(r.u0 + s, r.v0 + s);
  };
  std::vector<SubRect> level{SubRect{}}, next;
  bool undecided = false;
  while (!level.empty()) {
    next.clear();
    for (const SubRect& r : level) {
      if (out.subRectangles >= limits.maxSubRectangles) {
        out.visibility = Visibility::Undecided;
        out.workBound = true;
        if (!undecided) out.at = {r.u0, r.v0}, out.side = r.side();
        return out;
      }
      ++out.subRectangles;
      glm::dvec3 lo, hi;
      boxes.box(r, lo, hi);
      if (frustum.boxOutside(lo, hi)) continue;
      const float half = 0.5f * r.side();
      if (seen(r.u0 + half, r.v0 + half)) return out;
      if ((r.depth == 0 || r.depth == maxDepth) && cornersSeen(r)) return out;
      if (r.depth == maxDepth) {
        if (!undecided) out.at = {r.u0, r.v0}, out.side = r.side();
        undecided = true;
        continue;
      }
      for (int k = 0; k < 4; ++k)
        next.push_back({r.u0 + ((k & 1) ? half : 0.0f), r.v0 + ((k & 2) ? half : 0.0f), r.depth + 1});
    }
    level.swap(next);
  }
  out.visibility = undecided ? Visibility::Undecided : Visibility::Invisible;
  return out;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

const char* toString(HoleKind k) { return k == HoleKind::Discarded ? "discarded" : "culled_while_visible"; }

const char* toString(Visibility v) {
  switch (v) {
  case Visibility::Invisible: return "invisible";
  case Visibility::Visible: return "visible";
  case Visibility::Undecided: return "undecided";
  }
  return "?";
}

} // namespace fftess::verify
