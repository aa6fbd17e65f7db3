// Tiny patches whose outputs were worked out by hand from the D3D11 rules (expected arrays in full).
#include <catch2/catch.hpp>

#include "factor_samples.h"

using namespace fftess;
using namespace fftess::testing;

namespace {

std::vector<float> flat(const Tessellator& t) {
  std::vector<float> v;
  for (const DomainPoint& p : t.points()) v.push_back(p.u), v.push_back(p.v);
  return v;
}

Patch make(Domain d, Partitioning part, OutputPrimitive prim, std::initializer_list<float> f) {
  Patch p;
  p.domain = d;
  p.partitioning = part;
  p.primitive = prim;
  std::copy(f.begin(), f.end(), p.factors);
  return p;
}

} // namespace

TEST_CASE("quad integer, all factors 2", "[tessellator][hand]") {
  Tessellator t;
  t.tessellate(make(Domain::Quad, Partitioning::Integer, OutputPrimitive::TriangleCw, {2, 2, 2, 2, 2, 2}));
  // Outer ring clockwise from (0,1): Ueq0 down, Veq0 right, Ueq1 up, Veq1 left; then the centre.
  CHECK(flat(t) == std::vector<float>{0, 1, 0, 0.5f, 0, 0, 0.5f, 0, 1, 0, 1, 0.5f, 1, 1, 0.5f, 1, 0.5f, 0.5f});
  // Each outer edge (2 segments) against the degenerate inner ring (the centre point, 1 point):
  // two triangles per edge, fanning around the centre.
  CHECK(t.indices() == std::vector<int32_t>{0, 1, 8, 1, 2, 8, 2, 3, 8, 3, 4, 8, 4, 5, 8, 5, 6, 8, 6, 7, 8, 7, 0, 8});
}

TEST_CASE("quad integer, outer 3 3 1 1, inside 1 1: odd edges, degenerate inside", "[tessellator][hand]") {
  Tessellator t;
  t.tessellate(make(Domain::Quad, Partitioning::Integer, OutputPrimitive::Point, {3, 3, 1, 1, 1, 1}));
  const float a = float(21845) / 65536.0f, b = float(65536 - 21845) / 65536.0f; // r(3) = 21845
  // Inside 1 is placed as even: 3 points per axis, so one interior point at the centre.
  CHECK(flat(t) == std::vector<float>{0, 1, 0, b, 0, a, 0, 0, a, 0, b, 0, 1, 0, 1, 1, 0.5f, 0.5f});
  CHECK(t.indices() == std::vector<int32_t>{0, 1, 2, 3, 4, 5, 6, 7, 8});
}

TEST_CASE("tri integer, all factors 1: the minimum triangle", "[tessellator][hand]") {
  Tessellator t;
  t.tessellate(make(Domain::Tri, Partitioning::Integer, OutputPrimitive::TriangleCw, {1, 1, 1, 1}));
  CHECK(flat(t) == std::vector<float>{0, 1, 0, 0, 1, 0}); // V, W, U
  CHECK(t.indices() == std::vector<int32_t>{0, 1, 2});
  t.tessellate(make(Domain::Tri, Partitioning::Integer, OutputPrimitive::TriangleCcw, {1, 1, 1, 1}));
  CHECK(t.indices() == std::vector<int32_t>{0, 2, 1});
}

TEST_CASE("isoline: density 2, detail 2", "[tessellator][hand]") {
  Tessellator t;
  t.tessellate(make(Domain::Isoline, Partitioning::Integer, OutputPrimitive::Line, {2, 2}));
  // Two lines at v = 0 and v = 0.5 (the line at v = 1 is not drawn), three points each.
  CHECK(flat(t) == std::vector<float>{0, 0, 0.5f, 0, 1, 0, 0, 0.5f, 0.5f, 0.5f, 1, 0.5f});
  CHECK(t.indices() == std::vector<int32_t>{0, 1, 1, 2, 3, 4, 4, 5});
  t.tessellate(make(Domain::Isoline, Partitioning::Integer, OutputPrimitive::Point, {2, 2}));
  CHECK(t.indices() == std::vector<int32_t>{0, 1, 2, 3, 4, 5});
}

TEST_CASE("fractional_even 3: points grow from the middle", "[tessellator][hand]") {
  // Half factor 1.5: floor placement 2 segments (0, 0.5), ceil placement 4 segments (0, 0.25, 0.5), blended with
  // the fraction 0.5: point 1 = 0.5*0.5 + 0.5*0.25 = 0.375; the new points grow out of the middle.
  const EdgePoints e = edgePoints(3.0f, Partitioning::FractionalEven);
  CHECK(std::vector<uint32_t>(e.fixed, e.fixed + e.count) == std::vector<uint32_t>{0, 24576, 32768, 40960, 65536});
}
