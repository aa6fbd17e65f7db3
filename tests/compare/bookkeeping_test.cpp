// The bookkeeping port bugs (factors on the wrong edges, coordinates written in the wrong place): a capture built by
// the emulator with each bug and form (portBugCapture) is named by comparePatch, over seeded random patches; a tiny
// hand-checked case per bug pins down what each bug does (the expected points are worked out by hand, not by the
// model).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>
#include <random>
#include <set>
#include <utility>

#include "base/bits.h"
#include "tessellator/batch.h"
#include "compare/compare.h"
#include "tessellator/names.h"

using namespace fftess;

namespace {

constexpr PortBug kBookkeeping[] = {PortBug::OuterFactorsRotated,  PortBug::OuterFactorsMirrored,
                                    PortBug::OuterFactorsVFlipped, PortBug::DomainVFlipped,
                                    PortBug::UvSwapped,            PortBug::InsideFactorsSwapped,
                                    PortBug::TriBarycentricsPermuted, PortBug::IsolineFactorsSwapped};

Patch patchOf(const char* line) {
  Patch p;
  BatchError e;
  REQUIRE(parseBatchLine(line, p, e));
  return p;
}

PatchComparison run(const Patch& p, const CapturedPatch& c) {
  Tessellator t;
  return comparePatch(p, &c, {}, t);
}

// The form under which b is named, or nullptr when it is not.
const std::string* namedForm(const PatchComparison& c, PortBug b) {
  for (size_t i = 0; i < c.bugs.size(); ++i)
    if (c.bugs[i] == b) return &c.bugVariants.at(i);
  return nullptr;
}

// A seeded random patch: every domain, partitioning and topology; factors from small integers, 16.16-exact and
// arbitrary fractions (hardware stage) or an hlsl stage now and then.
Patch randomPatch(std::mt19937& rng) {
  Patch p;
  p.domain = Domain(rng() % 3);
  p.partitioning = Partitioning(rng() % 4);
  const OutputPrimitive prims[] = {OutputPrimitive::Point, OutputPrimitive::Line, OutputPrimitive::TriangleCw,
                                   OutputPrimitive::TriangleCcw};
  p.primitive = p.domain == Domain::Isoline ? (rng() % 2 ? OutputPrimitive::Point : OutputPrimitive::Line)
                                            : prims[rng() % 4];
  std::uniform_real_distribution<float> frac(0.5f, 14.0f);
  for (float& f : p.factors) {
    switch (rng() % 3) {
    case 0: f = float(1 + rng() % 9); break;
    case 1: f = float(rng() % 600) / 64.0f + 1.0f; break;
    default: f = frac(rng);
    }
  }
  if (rng() % 8 == 0) {
    p.stage.hlsl = true;
    p.factors[4] = float(rng() % 5) / 4.0f;
    p.factors[5] = float(rng() % 5) / 4.0f;
  }
  return p;
}

// The patch for a failure message (factors as float bits).
std::string lineOf(const Patch& p) {
  std::string s = std::string(toString(p.domain)) + " " + toString(p.partitioning) + " " + toString(p.primitive) +
                  " " + toString(p.stage);
  char buf[16];
  for (float f : p.factors) {
    std::snprintf(buf, sizeof buf, " 0x%08x", bitsOf(f));
    s += buf;
  }
  return s;
}

std::set<std::pair<float, float>> pointSet(const CapturedPatch& c) {
  std::set<std::pair<float, float>> s;
  for (auto v : c.vertices) s.insert({floatOf(v.u), floatOf(v.v)});
  return s;
}

void flip(CapturedPatch& c) {
  for (size_t i = 0; i + 2 < c.vertices.size(); i += 3) std::swap(c.vertices[i + 1], c.vertices[i + 2]);
}

} // namespace

TEST_CASE("compare: every bookkeeping bug and form is named on seeded random patches of its domains",
          "[compare][bookkeeping]") {
  std::mt19937 rng(20261202);
  int named[int(PortBug::Count)] = {}, differing[int(PortBug::Count)] = {};
  for (int i = 0; i < 400; ++i) {
    const Patch p = randomPatch(rng);
    const bool pointList = rng() % 4 == 0;
    const CapturedPatch ref = referenceCapture(p, 0, {}, pointList);
    const PatchComparison same = run(p, ref);
    REQUIRE(same.kind == DifferenceKind::Same);
    REQUIRE(same.bugs.empty());
    for (PortBug b : kBookkeeping) {
      for (int k = 0; k < portBugVariants(b, p); ++k) {
        const CapturedPatch c = portBugCapture(b, k, p, 0, {}, pointList);
        const PatchComparison r = run(p, c);
        INFO(lineOf(p) << (pointList ? " as points" : "") << ": " << toString(b) << " form " << k);
        if (r.kind == DifferenceKind::Same) continue; // the form changes nothing for these factors
        ++differing[int(b)];
        const std::string* form = namedForm(r, b);
        REQUIRE(form);
        // Named with the first form that reproduces the capture (k, or an earlier one that gives the same output).
        bool formOk = false;
        for (int j = 0; j <= k; ++j) formOk = formOk || *form == portBugVariantName(b, p, j);
        CHECK(formOk);
        if (formOk) ++named[int(b)];
      }
    }
  }
  for (PortBug b : kBookkeeping) {
    INFO(toString(b));
    CHECK(differing[int(b)] >= 30); // the sample exercises every bug
    CHECK(named[int(b)] == differing[int(b)]);
  }
}

TEST_CASE("compare: a coordinate bug is named whether or not the port also flips the winding",
          "[compare][bookkeeping]") {
  std::mt19937 rng(7);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    Patch p = randomPatch(rng);
    if (p.primitive != OutputPrimitive::TriangleCw && p.primitive != OutputPrimitive::TriangleCcw) continue;
    for (PortBug b : {PortBug::DomainVFlipped, PortBug::UvSwapped, PortBug::TriBarycentricsPermuted}) {
      for (int k = 0; k < portBugVariants(b, p); ++k) {
        CapturedPatch c = portBugCapture(b, k, p, 0, {});
        flip(c);
        const PatchComparison r = run(p, c);
        INFO(lineOf(p) << ": " << toString(b) << " form " << k << ", winding flipped");
        if (r.kind == DifferenceKind::Same) continue;
        const std::string* form = namedForm(r, b);
        REQUIRE(form);
        ++checked;
      }
    }
  }
  CHECK(checked > 100);
}

TEST_CASE("compare: the forms of each bug: counts per domain and the names the report prints",
          "[compare][bookkeeping]") {
  const Patch quad = patchOf("quad integer triangle_cw hw 1 2 3 4 5 6");
  const Patch tri = patchOf("tri integer triangle_cw hw 1 2 3 4 0 0");
  const Patch iso = patchOf("isoline integer line hw 3 4 0 0 0 0");
  CHECK(portBugVariants(PortBug::OuterFactorsRotated, quad) == 3);
  CHECK(portBugVariants(PortBug::OuterFactorsRotated, tri) == 2);
  CHECK(portBugVariants(PortBug::OuterFactorsRotated, iso) == 0);
  CHECK(portBugVariants(PortBug::OuterFactorsMirrored, quad) == 3);
  CHECK(portBugVariants(PortBug::OuterFactorsMirrored, tri) == 3);
  CHECK(portBugVariants(PortBug::OuterFactorsVFlipped, tri) == 0);
  CHECK(portBugVariants(PortBug::DomainVFlipped, iso) == 1);
  CHECK(portBugVariants(PortBug::DomainVFlipped, tri) == 0);
  CHECK(portBugVariants(PortBug::UvSwapped, tri) == 1);
  CHECK(portBugVariants(PortBug::InsideFactorsSwapped, tri) == 0);
  CHECK(portBugVariants(PortBug::TriBarycentricsPermuted, tri) == 5);
  CHECK(portBugVariants(PortBug::IsolineFactorsSwapped, iso) == 1);
  CHECK(portBugVariants(PortBug::IsolineFactorsSwapped, quad) == 0);
  CHECK(portBugInput(PortBug::IsolineFactorsSwapped, 0, iso).factors[0] == 4.0f); // density gets detail's 4
  CHECK(portBugInput(PortBug::IsolineFactorsSwapped, 0, iso).factors[1] == 3.0f);
  CHECK(portBugVariants(PortBug::FloatDivision, quad) == 0);
  CHECK(portBugVariantName(PortBug::OuterFactorsRotated, quad, 2) == "by 3: Ueq0 gets Veq1's factor");
  CHECK(portBugVariantName(PortBug::OuterFactorsRotated, tri, 1) == "by 2: Ueq0 gets Weq0's factor");
  CHECK(portBugVariantName(PortBug::TriBarycentricsPermuted, tri, 2) == "(u, v) as (v, w)");
  // Factor bugs move the hardware stage's factors.
  const Patch r = portBugInput(PortBug::OuterFactorsRotated, 0, quad);
  CHECK((r.factors[0] == 2 && r.factors[1] == 3 && r.factors[2] == 4 && r.factors[3] == 1 && r.factors[4] == 5));
  const Patch m = portBugInput(PortBug::OuterFactorsMirrored, 2, quad);
  CHECK((m.factors[0] == 4 && m.factors[1] == 3 && m.factors[2] == 2 && m.factors[3] == 1));
  const Patch s = portBugInput(PortBug::InsideFactorsSwapped, 0, quad);
  CHECK((s.factors[4] == 6 && s.factors[5] == 5 && s.factors[0] == 1));
  const Patch t = portBugInput(PortBug::OuterFactorsMirrored, 1, tri);
  CHECK((t.factors[0] == 1 && t.factors[1] == 3 && t.factors[2] == 2 && t.factors[3] == 4));
  PortBug parsed{};
  CHECK(parsePortBug("tri_barycentrics_permuted", parsed));
  CHECK(parsed == PortBug::TriBarycentricsPermuted);
  CHECK_FALSE(parsePortBug("uv_swap", parsed));
}

namespace {

struct HandCase {
  const char* patch;
  PortBug bug;
  int form;
  std::vector<std::pair<float, float>> points; // the buggy port's distinct points, worked out by hand
};

// Integer factors 1, 2, 4 place edge points at k/2 and k/4 (exact); inside factors 2 x 2 give the one interior point
// (0.5, 0.5); a tri with inside 2 has its centre at 21845/65536 = round(65536/3)/65536 in u and v, so w there is
// 1 - 2 x 21845/65536 = 21846/65536.
const float kThird = 21845.0f / 65536.0f, kThirdW = 21846.0f / 65536.0f;
const HandCase kHandCases[] = {
    // Reference: Ueq0 = 2 -> (0, .5); Veq0 = 4 -> (.25, 0) (.5, 0) (.75, 0). By 1: Ueq0 gets Veq0's 4, Veq1 Ueq0's 2.
    {"quad integer point hw 2 4 1 1 2 2", PortBug::OuterFactorsRotated, 0,
     {{0, 0}, {0, .25f}, {0, .5f}, {0, .75f}, {0, 1}, {.5f, .5f}, {.5f, 1}, {1, 0}, {1, 1}}},
    // Ueq0<->Ueq1: the midpoint moves to u = 1.
    {"quad integer point hw 2 4 1 1 2 2", PortBug::OuterFactorsMirrored, 0,
     {{0, 0}, {0, 1}, {.25f, 0}, {.5f, 0}, {.75f, 0}, {.5f, .5f}, {1, 0}, {1, .5f}, {1, 1}}},
    // Veq0<->Veq1: the quarters move to v = 1.
    {"quad integer point hw 2 4 1 1 2 2", PortBug::OuterFactorsVFlipped, 0,
     {{0, 0}, {0, .5f}, {0, 1}, {.25f, 1}, {.5f, 1}, {.75f, 1}, {.5f, .5f}, {1, 0}, {1, 1}}},
    // (u, 1 - v): the same points as the v-flipped factors (the triangles differ: see below).
    {"quad integer triangle_cw hw 2 4 1 1 2 2", PortBug::DomainVFlipped, 0,
     {{0, 0}, {0, .5f}, {0, 1}, {.25f, 1}, {.5f, 1}, {.75f, 1}, {.5f, .5f}, {1, 0}, {1, 1}}},
    // (v, u): the quarters go to u = 0, the midpoint of Ueq0 to v = 0.
    {"quad integer point hw 2 4 1 1 2 2", PortBug::UvSwapped, 0,
     {{0, 0}, {0, .25f}, {0, .5f}, {0, .75f}, {0, 1}, {.5f, 0}, {.5f, .5f}, {1, 0}, {1, 1}}},
    // insideU 2, insideV 4: interior points (.5, k/4); swapped: (k/4, .5).
    {"quad integer point hw 1 1 1 1 2 4", PortBug::InsideFactorsSwapped, 0,
     {{0, 0}, {0, 1}, {.25f, .5f}, {.5f, .5f}, {.75f, .5f}, {1, 0}, {1, 1}}},
    // (u, w): corners (0,0) <-> (0,1), (1,0) stays, Ueq0's (0, .5) stays, the centre (t, t) becomes (t, w).
    {"tri integer point hw 2 1 1 2 0 0", PortBug::TriBarycentricsPermuted, 0,
     {{0, 0}, {0, .5f}, {0, 1}, {kThird, kThirdW}, {1, 0}}},
};

double area2(const std::vector<CapturedVertex>& v, size_t i) {
  const double ax = floatOf(v[i].u), ay = floatOf(v[i].v), bx = floatOf(v[i + 1].u), by = floatOf(v[i + 1].v),
               cx = floatOf(v[i + 2].u), cy = floatOf(v[i + 2].v);
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

} // namespace

TEST_CASE("compare: each bookkeeping bug on a tiny patch gives the points worked out by hand and is named",
          "[compare][bookkeeping]") {
  for (const HandCase& h : kHandCases) {
    const Patch p = patchOf(h.patch);
    INFO(h.patch << ": " << toString(h.bug));
    const CapturedPatch c = portBugCapture(h.bug, h.form, p, 0, {});
    std::set<std::pair<float, float>> expected(h.points.begin(), h.points.end());
    CHECK(pointSet(c) == expected);
    const PatchComparison r = run(p, c);
    CHECK(r.kind == DifferenceKind::PointsDiffer);
    const std::string* form = namedForm(r, h.bug);
    REQUIRE(form);
    CHECK(*form == portBugVariantName(h.bug, p, h.form));
    REQUIRE_FALSE(r.points.empty());
    for (const PointDifference& d : r.points) {
      CHECK(d.detail.find("no typical port bug") == std::string::npos);
      CHECK(d.detail.find("what the whole patch re-computed with ") != std::string::npos);
      CHECK_FALSE(d.step.empty());
    }
  }
}

TEST_CASE("compare: domain_v_flipped mirrors every triangle and only the flip, not the v-flipped factors, is named",
          "[compare][bookkeeping]") {
  const Patch p = patchOf("quad integer triangle_cw hw 2 4 1 1 2 2");
  const CapturedPatch ref = referenceCapture(p, 0, {});
  const CapturedPatch c = portBugCapture(PortBug::DomainVFlipped, 0, p, 0, {});
  REQUIRE(c.vertices.size() == ref.vertices.size());
  for (size_t i = 0; i < c.vertices.size(); i += 3) {
    CHECK(area2(ref.vertices, i) != 0.0);
    CHECK(area2(c.vertices, i) == -area2(ref.vertices, i)); // (u, 1 - v) reverses each triangle's orientation
  }
  const PatchComparison r = run(p, c);
  CHECK(namedForm(r, PortBug::DomainVFlipped));
  CHECK_FALSE(namedForm(r, PortBug::OuterFactorsVFlipped));
  CapturedPatch compensated = c;
  flip(compensated);
  const PatchComparison q = run(p, compensated);
  REQUIRE(namedForm(q, PortBug::DomainVFlipped));
  CHECK(*namedForm(q, PortBug::DomainVFlipped) == "winding flipped too");
}
