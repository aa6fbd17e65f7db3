// On screen or not, for every finding (docs/verify.md, "On screen"): whether the camera can see a crack or a
// T-junction, and the worst gap of a crack that it sees. Decided in double from lod's float matrices (FrustumTest);
// conservative: a finding is off screen only when it is proven off screen.
#include "verify/edges.h"
#include "verify/internal.h"

#include <algorithm>
#include <cmath>

namespace fftess::verify::detail {

namespace {

// Distance (double) from x to the polyline poly[0..n).
double distanceToPolyline(const glm::dvec3& x, const glm::vec3* poly, int n) {
  double best = glm::length(x - glm::dvec3(poly[0]));
  for (int j = 0; j + 1 < n; ++j) {
    const glm::dvec3 s0(poly[j]), d = glm::dvec3(poly[j + 1]) - s0;
    const double len2 = glm::dot(d, d);
    const double t = len2 > 0 ? std::clamp(glm::dot(x - s0, d) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, glm::length(x - (s0 + t * d)));
  }
  return best;
}

// The view depth -(view * x).z of a point, in double from lod's float view matrix.
double depthOf(const lod::Camera& cam, const glm::dvec3& x) {
  const glm::mat4& v = cam.view;
  return -(double(v[0].z) * x.x + double(v[1].z) * x.y + double(v[2].z) * x.z + double(v[3].z));
}

struct Worst {
  bool any = false;
  double world = 0, pixels = 0;
  glm::vec3 at{};
  int side = 0;
  void offer(double w, const glm::dvec3& x, int s, const lod::Camera& cam, float nearZ) {
    if (any && !(w > world)) return;
    any = true, world = w, side = s, at = glm::vec3(x);
    const double focal = double(cam.projection[1][1]) * 0.5 * double(cam.viewport.y);
    pixels = w * focal / std::max(depthOf(cam, x), double(nearZ));
  }
};

// Where the side's polyline poly[0..n) crosses the frustum's boundary: its width there (distance to the other
// polyline) is a sample of the gap the camera sees at the edge of the view.
void crossings(const FrustumTest& frustum, const glm::vec3* poly, int n, const glm::vec3* other, int otherN, int side,
               const lod::Camera& cam, float nearZ, Worst& w) {
  for (int j = 0; j + 1 < n; ++j) {
    const glm::dvec3 p(poly[j]), q(poly[j + 1]);
    double t0 = 0, t1 = 1;
    if (!frustum.clipSegment(p, q, t0, t1)) continue;
    for (const double t : {t0, t1}) {
      if (t == 0 || t == 1) continue; // a vertex: measured exactly by the classifier
      const glm::dvec3 x = p + t * (q - p);
      w.offer(distanceToPolyline(x, other, otherN), x, side, cam, nearZ);
    }
  }
}

// The gap between the two sides, as a strip of triangles zipped between side a (its shared part with the points on
// either side of it) and side b: from the rung (a[0], b[0]), each triangle advances one side by one point, the one
// whose next point comes first along the edge (flat x/z projected on the edge's direction), to the rung (a[end],
// b[end]). Any such strip spans the gap (whatever the order of the steps), so what the camera can see of the gap is
// seen through one of its triangles. True: every triangle's box is proven off screen.
bool stripOffScreen(const FrustumTest& frustum, const glm::vec3* a, int na, const glm::vec3* b, int nb,
                    const glm::vec3& edgeStart, const glm::vec3& edgeEnd) {
  const double dx = double(edgeEnd.x) - edgeStart.x, dz = double(edgeEnd.z) - edgeStart.z;
  auto along = [&](const glm::vec3& p) { return (double(p.x) - edgeStart.x) * dx + (double(p.z) - edgeStart.z) * dz; };
  auto offScreen = [&](const glm::vec3& p, const glm::vec3& q, const glm::vec3& r) {
    PointBox box;
    box.add(p), box.add(q), box.add(r);
    return frustum.boxOffScreen(box.lo, box.hi);
  };
  int i = 0, j = 0;
  if (na == 1 && nb == 1) return offScreen(a[0], a[0], b[0]);
  while (i + 1 < na || j + 1 < nb) {
    const bool stepA = j + 1 >= nb || (i + 1 < na && along(a[i + 1]) <= along(b[j + 1]));
    if (!(stepA ? offScreen(a[i], b[j], a[i + 1]) : offScreen(a[i], b[j], b[j + 1]))) return false;
    stepA ? ++i : ++j;
  }
  return true;
}

} // namespace

void markOnScreen(const FrustumTest& frustum, const lod::Camera& cam, float nearZ, const ExactVerdict& v,
                  const glm::vec3* fullA, int naFull, int first, int last, const glm::vec3* b, int nb, Finding& f,
                  Stats& stats) {
  // The finding: the strip of triangles between its sides (stripOffScreen).
  const int lo = std::max(first - 1, 0), hi = std::min(last, naFull - 1);
  f.onScreen = !stripOffScreen(frustum, fullA + lo, hi - lo + 1, b, nb, f.edgeStart, f.edgeEnd);
  if (!f.onScreen) {
    ++(f.classification == Classification::Crack ? stats.cracksOffScreen : stats.tJunctionsOffScreen);
    return;
  }
  if (f.classification != Classification::Crack) return;
  // The crack's gap on screen: its off-polyline vertices whose gap segment may be on screen (exact distances from
  // the classifier), and where either side's edge crosses the frustum's boundary (double).
  Worst w;
  if (v.onScreenAny) {
    const glm::vec3& at = v.onScreenGapSide == 0 ? fullA[first + v.onScreenGapIndex] : b[v.onScreenGapIndex];
    w.offer(v.onScreenGap, glm::dvec3(at), v.onScreenGapSide, cam, nearZ);
  }
  crossings(frustum, fullA + first, last - first, b, nb, 0, cam, nearZ, w);
  crossings(frustum, b, nb, fullA, naFull, 1, cam, nearZ, w);
  // Nothing of either edge is in view, yet a triangle of the strip may be (the eye inside the gap, say): the farthest
  // vertex's gap, at no less than the near plane's depth.
  if (!w.any) w.offer(f.gapWorld, glm::dvec3(f.gapVertex), f.gapSide, cam, nearZ);
  f.onScreenGapWorld = w.world;
  f.onScreenGapPixels = w.pixels;
  f.onScreenGapVertex = w.at;
  f.onScreenGapSide = w.side;
  stats.worstGapWorldOnScreen = std::max(stats.worstGapWorldOnScreen, f.onScreenGapWorld);
  stats.worstGapPixelsOnScreen = std::max(stats.worstGapPixelsOnScreen, f.onScreenGapPixels);
}

} // namespace fftess::verify::detail
