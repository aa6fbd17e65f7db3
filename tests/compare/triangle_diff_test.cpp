// Triangle-level differences: a port with the reference's points (16.16-exact) and its own triangulation is
// triangulation_differs with the triangles only in one side listed (a hand-checked factor-1 quad, and grid ports
// checked against a multiset difference computed here); segments, winding, multiplicity, culled patches; strict
// order's rotated.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <sstream>

#include "base/bits.h"
#include "compare/compare.h"
#include "compare_test_util.h"
#include "tessellator/batch.h"

using namespace fftess;

namespace {

using comparetest::patchOf;
using comparetest::run;

CapturedPatch readHex(const std::string& text) {
  std::istringstream in(text);
  CaptureReader r(in, "cap.out");
  CapturedPatch c;
  REQUIRE(r.next(c));
  return c;
}

CapturedVertex at(float u, float v) { return CapturedVertex{bitsOf(u), bitsOf(v)}; }

using Tri = std::vector<CapturedVertex>;

// A triangle as the test compares it: rotated so that its smallest vertex (by bits, u then v) comes first.
Tri canonical(Tri t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// The triangles of a, as a multiset, minus those of b (computed here, independently of compare's code).
std::map<Tri, int> onlyIn(const std::vector<CapturedVertex>& a, const std::vector<CapturedVertex>& b) {
  std::map<Tri, int> m;
  for (size_t i = 0; i < a.size(); i += 3) ++m[canonical({a[i], a[i + 1], a[i + 2]})];
  for (size_t i = 0; i < b.size(); i += 3) --m[canonical({b[i], b[i + 1], b[i + 2]})];
  for (auto it = m.begin(); it != m.end();) it = it->second > 0 ? std::next(it) : m.erase(it);
  return m;
}
int total(const std::map<Tri, int>& m) {
  int n = 0;
  for (const auto& e : m) n += e.second;
  return n;
}

// A port that places the reference's points (the distinct u and v values of a uniform integer quad) and splits every
// grid cell along its (u0,v0)-(u1,v1) diagonal, triangles in the reference's winding.
CapturedPatch gridPort(const Patch& p) {
  const CapturedPatch ref = referenceCapture(p, 0, {});
  std::vector<uint32_t> us;
  for (CapturedVertex v : ref.vertices) us.push_back(v.u);
  std::sort(us.begin(), us.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  CapturedPatch c;
  c.verticesPerPrimitive = 3;
  for (size_t i = 0; i + 1 < us.size(); ++i)
    for (size_t j = 0; j + 1 < us.size(); ++j) {
      const CapturedVertex a{us[i], us[j]}, b{us[i + 1], us[j]}, d{us[i + 1], us[j + 1]}, e{us[i], us[j + 1]};
      c.vertices.insert(c.vertices.end(), {a, b, d, a, d, e});
    }
  return c;
}

} // namespace

TEST_CASE("triangle diff: a factor-1 quad split along the other diagonal lists both triangles of each side exactly",
          "[compare][triangles]") {
  // Reference (tessellate --format hex): points (0,0) (1,0) (1,1) (0,1), triangles 0 1 3 and 1 2 3.
  // The port numbers the same points (1,1) (0,1) (0,0) (1,0) and splits along (0,0)-(1,1): 2 3 0 and 2 0 1.
  const Patch p = patchOf("quad integer triangle_cw hw 1 1 1 1 1 1");
  const CapturedPatch c = readHex("patch 0 points 4 indices 6\n"
                                  "3f800000 3f800000\n00000000 3f800000\n00000000 00000000\n3f800000 00000000\n"
                                  "2 3 0\n2 0 1\n");
  REQUIRE(c.indices == std::vector<int32_t>{2, 3, 0, 2, 0, 1});
  const PatchComparison r = run(p, &c);
  CHECK(r.kind == DifferenceKind::TriangulationDiffers);
  CHECK(r.onlyInReferenceCount == 2);
  CHECK(r.onlyInCaptureCount == 2);
  REQUIRE(r.onlyInReference.size() == 2);
  REQUIRE(r.onlyInCapture.size() == 2);
  struct Expected {
    const PrimitiveDifference& got;
    int primitive;
    Tri vertices;
    std::vector<int32_t> indices, referenceIndices;
  };
  for (const Expected& e : {
           Expected{r.onlyInReference[0], 0, {at(0, 0), at(1, 0), at(0, 1)}, {0, 1, 3}, {0, 1, 3}},
           Expected{r.onlyInReference[1], 1, {at(1, 0), at(1, 1), at(0, 1)}, {1, 2, 3}, {1, 2, 3}},
           Expected{r.onlyInCapture[0], 0, {at(0, 0), at(1, 0), at(1, 1)}, {2, 3, 0}, {0, 1, 2}},
           Expected{r.onlyInCapture[1], 1, {at(0, 0), at(1, 1), at(0, 1)}, {2, 0, 1}, {0, 2, 3}},
       }) {
    CHECK(e.got.primitive == e.primitive);
    CHECK(e.got.vertices == e.vertices);
    CHECK(e.got.indices == e.indices);
    CHECK(e.got.referenceIndices == e.referenceIndices);
  }
  // One cell: its other diagonal is also the reference mirrored in v with the winding put back, which is what a port
  // that writes 1 - v and compensates the winding gives; no other bug model moves anything at factor 1.
  CHECK(r.bugs == std::vector<PortBug>{PortBug::DomainVFlipped});
}

TEST_CASE("triangle diff: grid ports with their own diagonals list exactly the multiset difference, in output order",
          "[compare][triangles]") {
  for (int n : {1, 2, 3, 4, 5, 8, 16}) {
    char line[96];
    std::snprintf(line, sizeof line, "quad integer triangle_cw hw %d %d %d %d %d %d", n, n, n, n, n, n);
    INFO(line);
    const Patch p = patchOf(line);
    const CapturedPatch ref = referenceCapture(p, 0, {});
    const CapturedPatch port = gridPort(p);
    REQUIRE(port.primitives() == 2 * n * n);
    const PatchComparison r = run(p, &port, false, 1 << 20);
    CHECK(r.kind == DifferenceKind::TriangulationDiffers);
    const auto expectRef = onlyIn(ref.vertices, port.vertices), expectCap = onlyIn(port.vertices, ref.vertices);
    CHECK(r.onlyInReferenceCount == total(expectRef));
    CHECK(r.onlyInCaptureCount == total(expectCap));
    CHECK(r.referencePrimitives - r.onlyInReferenceCount == r.capturePrimitives - r.onlyInCaptureCount);
    Tessellator t;
    t.tessellate(p, {});
    for (auto [list, side, expect] : {std::tuple(&r.onlyInReference, &ref, &expectRef),
                                      std::tuple(&r.onlyInCapture, &port, &expectCap)}) {
      REQUIRE(int(list->size()) == total(*expect));
      for (size_t k = 0; k < list->size(); ++k) {
        const PrimitiveDifference& d = (*list)[k];
        if (k > 0) CHECK(d.primitive > (*list)[k - 1].primitive);
        const Tri emitted(side->vertices.begin() + 3 * d.primitive, side->vertices.begin() + 3 * d.primitive + 3);
        CHECK(d.vertices == emitted);
        CHECK(expect->count(canonical(emitted)) == 1);
        for (int v = 0; v < 3; ++v) { // every vertex is a reference point: its index in tessellate's numbering
          REQUIRE(d.referenceIndices[size_t(v)] >= 0);
          const DomainPoint& q = t.points()[size_t(d.referenceIndices[size_t(v)])];
          CHECK(at(q.u, q.v) == d.vertices[size_t(v)]);
        }
      }
    }
  }
}

TEST_CASE("triangle diff: the lists stop at maxPrimitiveDetails, the counts do not", "[compare][triangles]") {
  const Patch p = patchOf("quad integer triangle_cw hw 8 8 8 8 8 8");
  const CapturedPatch port = gridPort(p);
  const PatchComparison all = run(p, &port, false, 1 << 20), two = run(p, &port, false, 2);
  REQUIRE(all.onlyInReferenceCount > 2);
  CHECK(two.onlyInReferenceCount == all.onlyInReferenceCount);
  CHECK(two.onlyInCaptureCount == all.onlyInCaptureCount);
  REQUIRE(two.onlyInReference.size() == 2);
  CHECK(two.onlyInReference[1].primitive == all.onlyInReference[1].primitive);
  CHECK(two.onlyInCapture.size() == 2);
  CHECK(run(p, &port, false, 0).onlyInReference.empty());
}

TEST_CASE("triangle diff: segments joined otherwise are primitives_differ with the segments listed",
          "[compare][triangles]") {
  // Reference: points (0,0) (0.5,0) (1,0) (0,0.5) (0.5,0.5) (1,0.5), segments 0 1, 1 2, 3 4, 4 5.
  const Patch p = patchOf("isoline integer line hw 2 2 0 0 0 0");
  CapturedPatch c = referenceCapture(p, 0, {});
  REQUIRE(c.vertices.size() == 8);
  c.vertices[6] = at(0, 0.5f); // the last segment 4 5 becomes 3 5
  c.vertices[7] = at(1, 0.5f);
  const PatchComparison r = run(p, &c);
  CHECK(r.kind == DifferenceKind::PrimitivesDiffer);
  REQUIRE(r.onlyInReference.size() == 1);
  REQUIRE(r.onlyInCapture.size() == 1);
  CHECK(r.onlyInReference[0].primitive == 3);
  CHECK(r.onlyInReference[0].indices == std::vector<int32_t>{4, 5});
  CHECK(r.onlyInCapture[0].primitive == 3);
  CHECK(r.onlyInCapture[0].indices.empty()); // a capture without its own numbering
  CHECK(r.onlyInCapture[0].referenceIndices == std::vector<int32_t>{3, 5});
}

TEST_CASE("triangle diff: winding_only lists the flipped triangles, multiplicity the surplus copy",
          "[compare][triangles]") {
  const Patch p = patchOf("tri integer triangle_ccw hw 3 4 5 4 0 0");
  CapturedPatch one = referenceCapture(p, 0, {});
  std::swap(one.vertices[4], one.vertices[5]); // triangle 1 flipped
  PatchComparison r = run(p, &one);
  CHECK(r.kind == DifferenceKind::WindingOnly);
  REQUIRE(r.onlyInReference.size() == 1);
  REQUIRE(r.onlyInCapture.size() == 1);
  CHECK(r.onlyInReference[0].primitive == 1);
  CHECK(r.onlyInCapture[0].primitive == 1);
  CHECK(r.onlyInCapture[0].vertices == Tri{one.vertices[3], one.vertices[4], one.vertices[5]});

  CapturedPatch twice = referenceCapture(p, 0, {});
  const int n = twice.primitives();
  twice.vertices.insert(twice.vertices.end(), twice.vertices.begin() + 6, twice.vertices.begin() + 9);
  r = run(p, &twice);
  CHECK(r.kind == DifferenceKind::Multiplicity);
  CHECK(r.onlyInReferenceCount == 0);
  REQUIRE(r.onlyInCaptureCount == 1);
  CHECK(r.onlyInCapture[0].primitive == n); // the later copy is the surplus one
  for (int32_t i : r.onlyInCapture[0].referenceIndices) CHECK(i >= 0);
}

TEST_CASE("triangle diff: a moved point lists the triangles around it, a culled patch all of the reference's",
          "[compare][triangles]") {
  const Patch p = patchOf("quad integer triangle_cw hw 4 4 4 4 4 4");
  CapturedPatch c = referenceCapture(p, 0, {});
  const CapturedVertex victim = at(0.5f, 0.5f);
  int around = 0;
  for (size_t i = 0; i < c.vertices.size(); i += 3)
    around += (c.vertices[i] == victim || c.vertices[i + 1] == victim || c.vertices[i + 2] == victim) ? 1 : 0;
  REQUIRE(around > 0);
  for (auto& v : c.vertices)
    if (v == victim) v.u = victim.u + 1;
  PatchComparison r = run(p, &c);
  CHECK(r.kind == DifferenceKind::PointsDiffer);
  CHECK(r.onlyInReferenceCount == around);
  CHECK(r.onlyInCaptureCount == around);
  for (const auto& d : r.onlyInCapture)
    CHECK(std::count(d.referenceIndices.begin(), d.referenceIndices.end(), -1) == 1);

  r = run(p, nullptr);
  CHECK(r.kind == DifferenceKind::CulledInCapture);
  CHECK(r.onlyInReferenceCount == r.referencePrimitives);
  CHECK(r.onlyInReference.size() == 8);
  CHECK(r.onlyInCaptureCount == 0);
}

TEST_CASE("triangle diff: strict order tells rotated primitives from reordered ones", "[compare][triangles]") {
  const Patch p = patchOf("quad fractional_odd triangle_ccw hw 3.5 2 5 4.25 3 2.5");
  CapturedPatch one = referenceCapture(p, 0, {});
  std::rotate(one.vertices.begin() + 6, one.vertices.begin() + 8, one.vertices.begin() + 9); // triangle 2
  PatchComparison r = run(p, &one, true);
  CHECK(r.kind == DifferenceKind::Rotated);
  CHECK(r.rotatedPrimitives == 1);
  CHECK(r.bugs.empty());
  CHECK(run(p, &one).kind == DifferenceKind::Same);

  CapturedPatch both = one; // rotated and reordered: order_differs
  std::swap_ranges(both.vertices.begin(), both.vertices.begin() + 3, both.vertices.begin() + 3);
  r = run(p, &both, true);
  CHECK(r.kind == DifferenceKind::OrderDiffers);
  CHECK(r.rotatedPrimitives == 0);

  const Patch l = patchOf("isoline integer line hw 3 5 0 0 0 0"); // a reversed segment
  CapturedPatch seg = referenceCapture(l, 0, {});
  std::swap(seg.vertices[2], seg.vertices[3]);
  r = run(l, &seg, true);
  CHECK(r.kind == DifferenceKind::Rotated);
  CHECK(r.rotatedPrimitives == 1);
}
