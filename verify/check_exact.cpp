// Exact classification of one shared edge with CGAL predicates. The float inputs convert to double exactly, so
// the kernel decides on the very values the domain-shader emulation produced.
//   Epick: exact predicates (equality, collinear, collinear_are_ordered_along_line) -> exact verdicts; the gap is a
//          double computation (only printed).
//   Epeck: exact predicates and exact constructions: the gap is exact until it is converted for printing.
//   Simple_cartesian<float>: the same predicates evaluated in float, to show what a float checker gets wrong.
#include "verify/edges.h"
#include "verify/internal.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace fftess::verify::detail {

namespace {

template <class K>
struct Classifier {
  using P = typename K::Point_3;
  using S = typename K::Segment_3;
  using FT = typename K::FT;

  static P toPoint(const glm::vec3& v) { return P(v.x, v.y, v.z); }

  static bool onPolyline(const P& p, const std::vector<P>& poly) {
    for (const P& q : poly)
      if (p == q) return true;
    for (size_t j = 0; j + 1 < poly.size(); ++j) {
      const P& q = poly[j];
      const P& r = poly[j + 1];
      if (q == r) continue;
      if (CGAL::collinear(q, p, r) && CGAL::collinear_are_ordered_along_line(q, p, r)) return true;
    }
    return false;
  }

  // *nearest: a j such that a nearest point of the polyline lies on its segment [j, j + 1] (0 if it has one point).
  static FT squaredDistance(const P& p, const std::vector<P>& poly, size_t* nearest) {
    FT best = CGAL::squared_distance(p, poly.front());
    *nearest = 0;
    for (size_t j = 0; j + 1 < poly.size(); ++j) {
      if (poly[j] == poly[j + 1]) continue;
      FT d = CGAL::squared_distance(p, S(poly[j], poly[j + 1]));
      if (d < best) best = d, *nearest = j;
    }
    return best;
  }

  static ExactVerdict run(const glm::vec3* a, int na, const glm::vec3* aFull, int naFull, const glm::vec3* b, int nb,
                          const FrustumTest* frustum) {
    std::vector<P> A, AF, B;
    A.reserve(na);
    AF.reserve(naFull);
    B.reserve(nb);
    for (int i = 0; i < na; ++i) A.push_back(toPoint(a[i]));
    for (int i = 0; i < naFull; ++i) AF.push_back(toPoint(aFull[i]));
    for (int i = 0; i < nb; ++i) B.push_back(toPoint(b[i]));

    ExactVerdict v;
    bool match = na == nb;
    for (int i = 0; match && i < na; ++i) match = A[i] == B[i];
    if (match) return v;

    v.classification = Classification::TJunction;
    FT worst(0), worstOn(0);
    bool any = false;
    // A vertex's gap is on screen unless its gap segment, from the vertex to the nearest point of the other side's
    // polyline, is proven off screen (docs/verify.md, "On screen"). The nearest point is computed in double on the
    // float ends of the nearest segment (FrustumTest::boxOffScreen's margin covers its rounding).
    auto gapOnScreen = [&](int side, int i, size_t j) {
      const glm::vec3& p = side == 0 ? a[i] : b[i];
      const glm::vec3* other = side == 0 ? b : aFull;
      const int otherN = side == 0 ? nb : naFull;
      const glm::dvec3 pd(p), s0(other[j]), s1(other[std::min(static_cast<int>(j) + 1, otherN - 1)]);
      const glm::dvec3 d = s1 - s0;
      const double len2 = glm::dot(d, d);
      const double t = len2 > 0 ? std::clamp(glm::dot(pd - s0, d) / len2, 0.0, 1.0) : 0.0;
      const glm::dvec3 q = s0 + t * d;
      return !frustum->boxOffScreen(glm::min(pd, q), glm::max(pd, q));
    };
    auto test = [&](const std::vector<P>& pts, const std::vector<P>& other, int side) {
      for (size_t i = 0; i < pts.size(); ++i) {
        if (onPolyline(pts[i], other)) continue;
        v.classification = Classification::Crack;
        size_t nearest = 0;
        FT d = squaredDistance(pts[i], other, &nearest);
        if (!any || worst < d) {
          worst = d;
          any = true;
          v.gapSide = side;
          v.gapIndex = static_cast<int>(i);
        }
        if (frustum && (!v.onScreenAny || worstOn < d) && gapOnScreen(side, static_cast<int>(i), nearest)) {
          worstOn = d;
          v.onScreenAny = true;
          v.onScreenGapSide = side;
          v.onScreenGapIndex = static_cast<int>(i);
        }
      }
    };
    test(A, B, 0);
    test(B, AF, 1);
    if (any) v.gap = std::sqrt(CGAL::to_double(worst));
    if (v.onScreenAny) v.onScreenGap = std::sqrt(CGAL::to_double(worstOn));
    return v;
  }
};

} // namespace

ExactVerdict classifyExact(Kernel kernel, const glm::vec3* a, int na, const glm::vec3* aFull, int naFull, const glm::vec3* b,
                           int nb, const FrustumTest* frustum) {
  if (na == 0 || nb == 0 || naFull == 0) return {};
  switch (kernel) {
  case Kernel::Epick:
    return Classifier<CGAL::Exact_predicates_inexact_constructions_kernel>::run(a, na, aFull, naFull, b, nb, frustum);
  case Kernel::Epeck:
    return Classifier<CGAL::Exact_predicates_exact_constructions_kernel>::run(a, na, aFull, naFull, b, nb, frustum);
  case Kernel::FloatNaive:
    return Classifier<CGAL::Simple_cartesian<float>>::run(a, na, aFull, naFull, b, nb, frustum);
  }
  return {};
}

} // namespace fftess::verify::detail
