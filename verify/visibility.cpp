// Is a patch that is not drawn on screen? The hole check's visibility test (verify.h, Hole): a box around the true
// displaced surface against the frustum's planes (proves invisible), then a grid of domain points (proves visible).
// Both in double from lod's float matrices, so the test does not inherit the float rounding of the LOD's own cull.
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
}

// The six planes w + x, w - x, w + y, w - y, w + z (near, GL clip space), w - z (far), as rows of the clip matrix.
bool FrustumTest::boxOutside(const glm::dvec3& lo, const glm::dvec3& hi) const {
  static constexpr int kRow[6] = {0, 0, 1, 1, 2, 2};
  static constexpr double kSign[6] = {1, -1, 1, -1, 1, -1};
  for (int p = 0; p < 6; ++p) {
    double n[4];
    for (int c = 0; c < 4; ++c) n[c] = m_[3][c] + kSign[p] * m_[kRow[p]][c];
    // The box corner furthest along the plane's normal.
    const double x = n[0] >= 0 ? hi.x : lo.x, y = n[1] >= 0 ? hi.y : lo.y, z = n[2] >= 0 ? hi.z : lo.z;
    if (n[0] * x + n[1] * y + n[2] * z + n[3] < 0) return true;
  }
  return false;
}

// The same planes; a box counts as outside a plane only by a margin: at the corner tested, the plane's value
// (w +- x, w +- y, w +- z of the clip matrix's rows) must be below -2^-16 * sum over c of (|m[3][c]| + |m[k][c]|) *
// M_c, M_c = max(|lo_c|, |hi_c|) (M_3 = 1): a bound on the magnitudes a GPU's float clip coordinates w and x (y, z)
// of any point of the box are rounded relative to (view, then projection: a few roundings of 2^-24 each). The margin
// is 2^8 times that, so nothing a GPU may draw is called off screen. Monotone: a box inside a box proven off screen
// is proven off screen (its value is no larger, its margin no larger). The clip matrix itself is the double product
// of lod's float matrices (as boxOutside).
bool FrustumTest::boxOffScreen(const glm::dvec3& lo, const glm::dvec3& hi) const {
  static constexpr int kRow[6] = {0, 0, 1, 1, 2, 2};
  static constexpr double kSign[6] = {1, -1, 1, -1, 1, -1};
  for (int p = 0; p < 6; ++p) {
    double n[4];
    for (int c = 0; c < 4; ++c) n[c] = m_[3][c] + kSign[p] * m_[kRow[p]][c];
    const double x = n[0] >= 0 ? hi.x : lo.x, y = n[1] >= 0 ? hi.y : lo.y, z = n[2] >= 0 ? hi.z : lo.z;
    const double value = n[0] * x + n[1] * y + n[2] * z + n[3];
    const double at[4] = {std::fmax(std::fabs(lo.x), std::fabs(hi.x)), std::fmax(std::fabs(lo.y), std::fabs(hi.y)),
                          std::fmax(std::fabs(lo.z), std::fabs(hi.z)), 1};
    double scale = 0;
    for (int c = 0; c < 4; ++c) scale += (std::fabs(m_[3][c]) + std::fabs(m_[kRow[p]][c])) * at[c];
    if (value < -0x1p-16 * scale) return true;
  }
  return false;
}

bool FrustumTest::clipSegment(const glm::dvec3& p, const glm::dvec3& q, double& t0, double& t1) const {
  static constexpr int kRow[6] = {0, 0, 1, 1, 2, 2};
  static constexpr double kSign[6] = {1, -1, 1, -1, 1, -1};
  for (int k = 0; k < 6; ++k) {
    double n[4];
    for (int c = 0; c < 4; ++c) n[c] = m_[3][c] + kSign[k] * m_[kRow[k]][c];
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

Visibility patchVisibility(const TerrainData& t, const TerrainPatch& p, const PatchDomain* domain,
                           const FrustumTest& frustum, int grid, glm::vec3* point, WorkStats& work) {
  glm::dvec3 lo(p.corners[0]), hi(p.corners[0]);
  for (const glm::vec3& c : p.corners) {
    lo = glm::min(lo, glm::dvec3(c));
    hi = glm::max(hi, glm::dvec3(c));
  }
  // x/z: the domain shader's lerps stay within an ulp or so of the corners; pad by 2^-20 of the magnitude.
  const double padX = std::fmax(std::fabs(lo.x), std::fabs(hi.x)) * 0x1p-20 + 1e-30;
  const double padZ = std::fmax(std::fabs(lo.z), std::fabs(hi.z)) * 0x1p-20 + 1e-30;
  lo.x -= padX, hi.x += padX, lo.z -= padZ, hi.z += padZ;
  lo.y = p.surfaceMinY;
  hi.y = p.surfaceMaxY;
  if (frustum.boxOutside(lo, hi)) return Visibility::Invisible;
  const int n = grid < 2 ? 2 : grid;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float u = static_cast<float>(i) / static_cast<float>(n - 1);
      const float v = static_cast<float>(j) / static_cast<float>(n - 1);
      const glm::vec3 w = evalDomain(t, p, u, v, domain, work);
      ++work.visibilityEvaluations;
      if (frustum.inside(w)) {
        if (point) *point = w;
        return Visibility::Visible;
      }
    }
  return Visibility::Undecided;
}

} // namespace fftess::verify::detail
