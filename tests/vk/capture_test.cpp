// tests for vk/ (vk_capture.h): the Vulkan capture on lavapipe (Mesa's CPU Vulkan driver, the D3D11 reference
// tessellator inside) against the emulator, the order-free grouping under permuted records, the D3D winding mapping
// (domain origin), the indices found by coordinates, culled patches between drawn ones.
// One ctest test for the executable: exit 77 (skipped) without a Vulkan device, a failure when CI is set.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "vk/vk_capture.h"

#include "compare/compare.h"
#include "gl/random_patches.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

using namespace fftess::oracle;

namespace {

VkOracle* gVk = nullptr;

fftess::Patch toEmulator(const Patch& g) {
  fftess::Patch p;
  p.domain = static_cast<fftess::Domain>(static_cast<uint8_t>(g.domain));
  p.partitioning = static_cast<fftess::Partitioning>(static_cast<uint8_t>(g.partitioning));
  p.primitive = static_cast<fftess::OutputPrimitive>(static_cast<uint8_t>(g.topology));
  std::memcpy(p.factors, g.factorBits, sizeof p.factors);
  return p;
}

// The capture as driver-check gives it to the comparison: the primitives where Vulkan draws them, else the points.
fftess::CapturedPatch toCapture(const Result& r) {
  fftess::CapturedPatch c;
  const bool prims = !r.primitives.empty();
  const std::vector<uint32_t>& words = prims ? r.primitives : r.points;
  for (size_t i = 0; i + 1 < words.size(); i += 2) c.vertices.push_back({words[i], words[i + 1]});
  c.verticesPerPrimitive = c.vertices.empty() ? 0 : prims ? r.verticesPerPrimitive : 1;
  return c;
}

std::vector<Result> capture(const std::vector<Patch>& patches) {
  std::vector<Result> results;
  std::string error;
  const bool ok = gVk->run(patches, results, error);
  INFO(error);
  REQUIRE(ok);
  REQUIRE(results.size() == patches.size());
  return results;
}

// The patches whose capture is not the emulator's (denormals flushed, as lavapipe does), as batch lines.
std::vector<std::string> differing(const std::vector<Patch>& patches, const std::vector<Result>& results) {
  fftess::CompareOptions opt;
  opt.emulator.flushDenormals = true;
  fftess::Tessellator tess;
  std::vector<std::string> out;
  for (size_t i = 0; i < patches.size(); ++i) {
    const fftess::CapturedPatch c = toCapture(results[i]);
    const fftess::PatchComparison d = fftess::comparePatch(toEmulator(patches[i]), &c, opt, tess);
    if (d.kind != fftess::DifferenceKind::Same) out.push_back(batchLine(patches[i]) + ": " + toString(d.kind));
  }
  return out;
}

using Vertex = std::array<uint32_t, 2>;
using Primitive = std::vector<Vertex>;

// The primitives of a word list (n vertices each), sorted: the capture as a multiset.
std::vector<Primitive> multiset(const std::vector<uint32_t>& words, int n) {
  std::vector<Primitive> out;
  for (size_t i = 0; i + 2 * size_t(n) <= words.size(); i += 2 * size_t(n)) {
    Primitive p;
    for (int k = 0; k < n; ++k) p.push_back({words[i + 2 * k], words[i + 2 * k + 1]});
    out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

float asFloat(uint32_t bits) {
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// Twice the signed area of a captured triangle in the (u, v) domain, exact in double for 16.16-sized coordinates.
double cross(const std::vector<uint32_t>& p, size_t t) {
  const double u0 = asFloat(p[t]), v0 = asFloat(p[t + 1]), u1 = asFloat(p[t + 2]), v1 = asFloat(p[t + 3]);
  const double u2 = asFloat(p[t + 4]), v2 = asFloat(p[t + 5]);
  return (u1 - u0) * (v2 - v0) - (u2 - u0) * (v1 - v0);
}

Patch patch(Domain d, Topology t, std::initializer_list<float> factors) {
  Patch p;
  p.domain = d;
  p.topology = t;
  int i = 0;
  for (float f : factors) std::memcpy(&p.factorBits[i++], &f, 4);
  return p;
}

} // namespace

TEST_CASE("The Vulkan capture of seeded random patches is the emulator's output with denormals flushed") {
  if (!gVk->isCpu()) {
    WARN("the Vulkan device is " << gVk->renderer() << ", not lavapipe: the reference claim does not apply");
    return;
  }
  const std::vector<Patch> patches = generatePatches(1500, 20261202, false);
  const std::vector<std::string> bad = differing(patches, capture(patches));
  INFO((bad.empty() ? std::string() : bad.front()));
  CHECK(bad.size() == 0);
  CHECK(gVk->drawCalls() > 1); // more than one draw: the batching and the grouping by patch id were exercised
}

TEST_CASE("Records given to their patches in another order give the same capture as multisets") {
  const std::vector<Patch> patches = generatePatches(400, 3, false);
  const std::vector<Result> driver = capture(patches);
  struct Shuffle { // on for this case only, even when a REQUIRE throws
    Shuffle() { gVk->setRecordShuffle(99); }
    ~Shuffle() { gVk->setRecordShuffle(0); }
  };
  std::vector<Result> shuffled;
  {
    Shuffle on;
    shuffled = capture(patches);
  }
  int reordered = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    INFO(batchLine(patches[i]));
    reordered += shuffled[i].points != driver[i].points || shuffled[i].primitives != driver[i].primitives;
    CHECK(multiset(shuffled[i].points, 1) == multiset(driver[i].points, 1));
    CHECK(shuffled[i].verticesPerPrimitive == driver[i].verticesPerPrimitive);
    CHECK(multiset(shuffled[i].primitives, driver[i].verticesPerPrimitive) ==
          multiset(driver[i].primitives, driver[i].verticesPerPrimitive));
  }
  CHECK(reordered > 100); // the shuffle did reorder: the grouping met another order than the driver's
  if (gVk->isCpu()) CHECK(differing(patches, shuffled).empty());
}

TEST_CASE("The unit quad's triangle_cw triangles are the reference's, each starting at any of its vertices") {
  // Hand-checked with fftess tessellate -e "quad integer triangle_cw hw 1 1 1 1 1 1": points (0,0) (1,0) (1,1)
  // (0,1), triangles (0,1,3) (1,2,3).
  const uint32_t one = 0x3f800000u;
  const std::vector<Result> r = capture({patch(Domain::Quad, Topology::TriangleCw, {1, 1, 1, 1, 1, 1})});
  REQUIRE(r[0].verticesPerPrimitive == 3);
  std::vector<Primitive> got;
  for (Primitive t : multiset(r[0].primitives, 3)) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end()); // the smallest vertex first, order kept
    got.push_back(t);
  }
  std::sort(got.begin(), got.end());
  const std::vector<Primitive> expected = {{{0, 0}, {one, 0}, {0, one}}, {{0, one}, {one, 0}, {one, one}}};
  CHECK(got == expected);
}

TEST_CASE("The triangles of a triangle_cw patch cover the domain clockwise with v down and triangle_ccw ones the "
          "other way") {
  // Each triangle alone may turn either way (fractional partitionings make slivers the reference flips), but the
  // triangles tile the domain: their signed areas sum to the domain's (quad 1, tri 1/2), positive for clockwise
  // with v down, D3D's triangle_cw (the unit quad's (0,0) (1,0) (0,1)).
  const std::vector<Patch> patches = generatePatches(600, 5, false);
  const std::vector<Result> results = capture(patches);
  long cw = 0, ccw = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    const Topology t = patches[i].topology;
    const std::vector<uint32_t>& p = results[i].primitives;
    if ((t != Topology::TriangleCw && t != Topology::TriangleCcw) || p.empty()) continue;
    INFO(batchLine(patches[i]));
    double area = 0.0;
    for (size_t k = 0; k + 6 <= p.size(); k += 6) area += cross(p, k) / 2.0;
    const double domain = patches[i].domain == Domain::Quad ? 1.0 : 0.5;
    CHECK(std::abs(area - (t == Topology::TriangleCw ? domain : -domain)) < 1e-4);
    (t == Topology::TriangleCw ? cw : ccw) += 1;
  }
  CHECK(cw > 50);
  CHECK(ccw > 50);
}

TEST_CASE("Triangle and isoline indices name the point with the vertex's coordinates when the points are distinct") {
  const std::vector<Patch> patches = generatePatches(600, 8, false);
  const std::vector<Result> results = capture(patches);
  long withIndices = 0, duplicated = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    const Result& r = results[i];
    if (r.primitives.empty()) continue;
    INFO(batchLine(patches[i]));
    const std::vector<Primitive> points = multiset(r.points, 1);
    const bool distinct = std::adjacent_find(points.begin(), points.end()) == points.end();
    duplicated += !distinct;
    if (!distinct) {
      CHECK(r.indices.empty());
      continue;
    }
    REQUIRE(r.indices.size() * 2 == r.primitives.size());
    ++withIndices;
    for (size_t k = 0; k < r.indices.size(); ++k) {
      const size_t at = static_cast<size_t>(r.indices[k]);
      REQUIRE(at < static_cast<size_t>(r.pointCount()));
      CHECK(r.points[2 * at] == r.primitives[2 * k]);
      CHECK(r.points[2 * at + 1] == r.primitives[2 * k + 1]);
    }
  }
  CHECK(withIndices > 100);
  CHECK(duplicated > 0); // the generator's "two 16.16 steps above k" factors give duplicate points
}

TEST_CASE("Culled patches between drawn ones give nothing and leave their neighbours' captures whole") {
  const float nan = asFloat(0x7fc00000u);
  const Patch unit = patch(Domain::Quad, Topology::TriangleCw, {1, 1, 1, 1, 1, 1});
  const Patch four = patch(Domain::Quad, Topology::TriangleCcw, {4, 4, 4, 4, 4, 4});
  const std::vector<Patch> patches = {unit,
                                      patch(Domain::Quad, Topology::TriangleCw, {0, 1, 1, 1, 1, 1}),
                                      four,
                                      patch(Domain::Quad, Topology::TriangleCw, {1, 1, nan, 1, 1, 1}),
                                      patch(Domain::Quad, Topology::TriangleCcw, {1, 1, 1, -1, 1, 1}),
                                      unit};
  const std::vector<Result> r = capture(patches);
  for (int i : {1, 3, 4}) {
    CHECK(r[i].points.empty());
    CHECK(r[i].primitives.empty());
  }
  CHECK(r[0].pointCount() == 4);
  CHECK(r[0].primitives.size() == 2 * 3 * 2);
  CHECK(r[5].points == r[0].points);
  CHECK(r[2].pointCount() == 25); // 5 x 5 points
  CHECK(r[2].primitives.size() == 32 * 3 * 2);
}

int main(int argc, char** argv) {
  std::string error;
  std::unique_ptr<VkOracle> vk = VkOracle::create(error);
  if (!vk) {
    if (std::getenv("CI")) {
      std::fprintf(stderr, "test_vk_capture: FAILED: no Vulkan device for the capture: %s (CI is set)\n",
                   error.c_str());
      return 1;
    }
    std::fprintf(stderr, "test_vk_capture: SKIPPED: no Vulkan device for the capture: %s (would fail with CI set)\n",
                 error.c_str());
    return 77;
  }
  std::fprintf(stderr, "test_vk_capture: %s, %s\n", vk->renderer().c_str(), vk->version().c_str());
  gVk = vk.get();
  return Catch::Session().run(argc, argv);
}
