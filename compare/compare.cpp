#include "compare/compare.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "tessellator/batch.h"
#include "compare/compare_internal.h"
#include "tessellator/fixed.h"
#include "tessellator/names.h"

namespace fftess {
namespace {

using Verts = std::vector<CapturedVertex>;
using Prim = std::array<uint64_t, 3>;

uint64_t key(CapturedVertex v) { return (uint64_t(v.u) << 32) | v.v; }
float fu(CapturedVertex v) { return fx::floatOf(v.u); }
float fv(CapturedVertex v) { return fx::floatOf(v.v); }

// Primitives as sortable keys: triangles in their lexicographically smallest rotation (winding kept); sortAll:
// vertices of each primitive sorted (winding ignored; segments are always unordered).
std::vector<Prim> primitives(const Verts& v, int arity, bool sortAll) {
  std::vector<Prim> out;
  if (arity <= 0) return out;
  out.reserve(v.size() / size_t(arity));
  for (size_t i = 0; i + size_t(arity) <= v.size(); i += size_t(arity)) {
    Prim p = primitiveKey(&v[i], arity);
    if (sortAll && arity == 3) { // three compare-and-swaps (std::sort on a runtime-sized prefix of 3 trips GCC 12's
                                 // -Warray-bounds); a segment's key is already sorted
      if (p[1] < p[0]) std::swap(p[0], p[1]);
      if (p[2] < p[1]) std::swap(p[1], p[2]);
      if (p[1] < p[0]) std::swap(p[0], p[1]);
    }
    out.push_back(p);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<uint64_t> distinctPoints(const Verts& v) {
  std::vector<uint64_t> k;
  k.reserve(v.size());
  for (auto x : v) k.push_back(key(x));
  std::sort(k.begin(), k.end());
  k.erase(std::unique(k.begin(), k.end()), k.end());
  return k;
}

// Size of the multiset difference a \ b (both sorted).
template <class T> int differenceSize(const std::vector<T>& a, const std::vector<T>& b) {
  std::vector<T> d;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(d));
  return int(d.size());
}

} // namespace

bool sameOrderInsensitive(const Verts& a, const Verts& b, int arity) {
  return a.size() == b.size() && primitives(a, arity, false) == primitives(b, arity, false);
}

namespace {

// Every vertex of 'got' pairs with its own vertex of 'model' within tol in u and v (multisets of vertices).
bool nearSame(const Verts& model, const Verts& got, float tol) {
  if (model.size() != got.size()) return false;
  Verts m = model;
  std::sort(m.begin(), m.end(), [](CapturedVertex a, CapturedVertex b) { return fu(a) < fu(b); });
  std::vector<char> used(m.size(), 0);
  for (CapturedVertex g : got) {
    const float u = fu(g), v = fv(g);
    auto it = std::lower_bound(m.begin(), m.end(), u - tol, [](CapturedVertex a, float x) { return fu(a) < x; });
    bool found = false;
    for (; it != m.end() && fu(*it) <= u + tol; ++it) {
      const size_t i = size_t(it - m.begin());
      if (!used[i] && std::fabs(fv(*it) - v) <= tol) {
        used[i] = 1;
        found = true;
        break;
      }
    }
    if (!found) return false;
  }
  return true;
}

} // namespace

void outputOf(const Tessellator& t, int arity, Verts& out) {
  out.clear();
  const auto& pts = t.points();
  auto vert = [&](size_t i) { return CapturedVertex{fx::bitsOf(pts[i].u), fx::bitsOf(pts[i].v)}; };
  if (arity == 1) { // the point array (a point list of any topology)
    for (size_t i = 0; i < pts.size(); ++i) out.push_back(vert(i));
    return;
  }
  for (int32_t i : t.indices()) out.push_back(vert(size_t(i)));
}

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// The end of a point's sentence when no per-point bug explains it: the first whole-patch bug that reproduces the
// patch (c.bugs[whole]), if one does (whole < 0: none).
std::string wholePatchCredit(const PatchComparison& c, int whole, PointDifference& d) {
  if (whole < 0) return "; no typical port bug gives this value";
  const PortBug b = c.bugs[size_t(whole)];
  const std::string& form = c.bugVariants[size_t(whole)];
  d.step = stepOf(b);
  return std::string("; what the whole patch re-computed with ") + toString(b) + " gives (" + describe(b) +
         (form.empty() ? "" : "; " + form) + "): " + stepOf(b);
}

// The step that explains capture coordinate 'got' where the reference has 'ref' on this axis, and the sentence.
void explainCoordinate(const Axis& axis, int k, float ref, float got, const char* coord, const PatchComparison& c,
                       int whole, PointDifference& d) {
  d.where = std::string(axis.name) + " point " + std::to_string(k) + " of " + std::to_string(axis.trace.count);
  const EdgePointTrace& p = axis.trace.points[k];
  std::string sentence = std::string(coord) + " = " + num(got) + " where the reference has " + num(ref) + " (16.16 " +
                         std::to_string(p.fixed) + "/65536";
  if (p.midpoint)
    sentence += ", the special-cased middle";
  else
    sentence += std::string(p.mirrored ? ", mirrored: 1 - " : ", ") + "index " + std::to_string(p.indexOnCeil) +
                " x reciprocal " + std::to_string(axis.trace.reciprocalCeil) + "/65536 of 1/" +
                std::to_string(axis.trace.ceilSegments);
  sentence += ")";
  static const PortBug kEdgeBugs[] = {PortBug::FloatDivision, PortBug::NoMirroring, PortBug::NoSpecialMidpoint,
                                      PortBug::LerpNotRounded, PortBug::FactorsNotSnapped};
  for (bool exact : {true, false}) {
    for (PortBug b : kEdgeBugs) {
      const float model = buggyEdgeParam(b, axis.trace, k, axis.raw);
      if (fx::bitsOf(model) == fx::bitsOf(ref)) continue;
      if (exact ? fx::bitsOf(model) == fx::bitsOf(got) : std::fabs(model - got) <= 0x1p-20f) {
        d.step = stepOf(b);
        d.detail =
            sentence + "; " + (exact ? "exactly" : "within 2^-20 of") + " what " + describe(b) + " gives: " + stepOf(b);
        return;
      }
    }
  }
  d.detail = sentence + wholePatchCredit(c, whole, d);
}

void pointDetails(const Patch& patch, const Options& options, const Verts& ref, const Verts& got, int maxDetails,
                  PatchComparison& c) {
  const auto wholeIt = std::find_if(c.bugs.begin(), c.bugs.end(), portBugTransformsPatch);
  const int whole = wholeIt == c.bugs.end() ? -1 : int(wholeIt - c.bugs.begin());
  const auto dr = distinctPoints(ref), dg = distinctPoints(got);
  std::vector<uint64_t> extra, missing;
  std::set_difference(dg.begin(), dg.end(), dr.begin(), dr.end(), std::back_inserter(extra));
  std::set_difference(dr.begin(), dr.end(), dg.begin(), dg.end(), std::back_inserter(missing));
  c.extraPoints = int(extra.size());
  c.missingPoints = int(missing.size());
  if (dr.empty() || maxDetails <= 0) return;
  const PatchAxes axes = patchAxes(patch, options);
  for (size_t i = 0; i < extra.size() && int(i) < maxDetails; ++i) {
    PointDifference d;
    d.got = CapturedVertex{uint32_t(extra[i] >> 32), uint32_t(extra[i])};
    double best = 1e300;
    for (uint64_t r : dr) {
      const CapturedVertex rv{uint32_t(r >> 32), uint32_t(r)};
      const double du = double(fu(d.got)) - double(fu(rv)), dv = double(fv(d.got)) - double(fv(rv));
      if (du * du + dv * dv < best) {
        best = du * du + dv * dv;
        d.nearest = rv;
      }
    }
    d.du = (double(fu(d.got)) - double(fu(d.nearest))) * 65536.0;
    d.dv = (double(fv(d.got)) - double(fv(d.nearest))) * 65536.0;
    for (int coord = 0; coord < 2 && d.detail.empty(); ++coord) {
      const uint32_t gb = coord == 0 ? d.got.u : d.got.v, rb = coord == 0 ? d.nearest.u : d.nearest.v;
      if (gb == rb) continue;
      bool mirrorV = false;
      const Axis* axis = axisOf(axes, d.nearest, coord, mirrorV);
      const int k = axis ? pointOnAxis(*axis, rb) : -1;
      if (k < 0) {
        d.where = "a point not on one edge";
        d.detail = std::string(coord ? "v" : "u") + " differs; the reference point is not placed by one edge";
        if (whole >= 0) d.detail += wholePatchCredit(c, whole, d);
        continue;
      }
      explainCoordinate(*axis, k, fx::floatOf(rb), fx::floatOf(gb), coord ? "v" : "u", c, whole, d);
    }
    c.points.push_back(d);
  }
}

// Re-runs the patch under each typical port bug and keeps those that reproduce the capture.
void recognise(const Patch& patch, const Options& options, const Verts& ref, const Verts& got, int arity,
               Tessellator& tess, PatchComparison& c) {
  Verts model;
  auto rerun = [&](const Patch& p, const Options& o) {
    tess.tessellate(p, o);
    outputOf(tess, arity, model);
    return sameOrderInsensitive(model, got, arity);
  };
  recogniseWholePatch(patch, options, ref, got, arity, tess, c);
  // Unsnapped fractional factors change point counts where a factor lies between two 16.16 values: a port comparing
  // the float (f > 2) places points the 16.16 value (== 2) does not. Modelled as the factors moved to the next 16.16
  // value up (the blend fraction then differs by less than a unit); per-point differences: the edge model below.
  bool offGrid = false;
  Patch up = patch;
  if (!patch.stage.hlsl && (patch.partitioning == Partitioning::FractionalEven ||
                            patch.partitioning == Partitioning::FractionalOdd)) {
    for (float& f : up.factors) {
      const double scaled = double(f) * 65536.0;
      if (f > 0.0f && f < 64.0f && scaled != std::floor(scaled)) {
        f = float(std::ceil(scaled) / 65536.0);
        offGrid = true;
      }
    }
  }
  bool unsnapped = offGrid && rerun(up, options);
  if (unsnapped) nameBug(c, PortBug::FactorsNotSnapped);
  if (ref.empty() || ref.size() != got.size()) return;
  const PatchAxes axes = patchAxes(patch, options);
  for (PortBug b : {PortBug::FloatDivision, PortBug::NoMirroring, PortBug::NoSpecialMidpoint, PortBug::LerpNotRounded,
                    PortBug::FactorsNotSnapped}) {
    if (b == PortBug::FactorsNotSnapped && unsnapped) continue;
    for (bool corners : {true, false}) { // ports place the corners like any edge point, or write them as constants
      model.clear();
      for (CapturedVertex r : ref) model.push_back(applyBug(axes, b, r, corners));
      if (model == ref) continue; // the bug changes nothing in this patch
      if (sameOrderInsensitive(model, got, arity) || nearSame(model, got, 0x1p-20f)) {
        nameBug(c, b);
        break;
      }
    }
  }
}

} // namespace

const char* toString(DifferenceKind k) {
  switch (k) {
  case DifferenceKind::Same: return "same";
  case DifferenceKind::CulledInCapture: return "culled_in_capture";
  case DifferenceKind::CulledInReference: return "culled_in_reference";
  case DifferenceKind::PointsDiffer: return "points_differ";
  case DifferenceKind::Multiplicity: return "multiplicity";
  case DifferenceKind::WindingOnly: return "winding_only";
  case DifferenceKind::PrimitivesDiffer: return "primitives_differ";
  case DifferenceKind::OrderDiffers: return "order_differs";
  case DifferenceKind::TriangulationDiffers: return "triangulation_differs";
  case DifferenceKind::Rotated: return "rotated";
  case DifferenceKind::Count: break;
  }
  return "?";
}

namespace {
struct BugText {
  const char* name;
  const char* sentence;
  const char* step;
};
constexpr BugText kBugs[] = {
    {"float_division", "float division instead of the 16.16 reciprocal table", "reciprocal rounding"},
    {"no_mirroring", "no mirroring of the second half of the edge", "mirrored half"},
    {"no_special_midpoint", "the middle point computed instead of the exact 0.5", "special midpoint"},
    {"lerp_not_rounded", "the fractional blend not rounded back to 16.16", "lerp rounding"},
    {"factors_not_snapped", "float factors not snapped to 16.16", "rounding of fractional factors"},
    {"denormals_flushed", "denormal factors flushed to zero (the patch is culled)", "denormal handling"},
    {"pow2_as_fractional_even", "pow2 not mapped to integer (tessellated as fractional_even)", "pow2 partitioning"},
    {"pow2_as_fractional_odd", "pow2 not mapped to integer (tessellated as fractional_odd)", "pow2 partitioning"},
    {"winding_swapped", "GL/D3D winding swapped (GL cw is D3D triangle_ccw)", "winding"},
    {"outer_factors_rotated", "outer factors on the wrong edges, rotated round the domain", "edge bookkeeping"},
    {"outer_factors_mirrored", "outer factors on the wrong edges, mirrored", "edge bookkeeping"},
    {"outer_factors_v_flipped", "Veq0 and Veq1 factors swapped (the v axis flipped, as with Vulkan's upper-left "
                                "domain origin against GL's lower-left)", "edge bookkeeping"},
    {"domain_v_flipped", "the output's v written as 1 - v (the domain's v axis flipped)", "output bookkeeping"},
    {"uv_swapped", "the output's u and v swapped", "output bookkeeping"},
    {"inside_factors_swapped", "insideU and insideV swapped", "edge bookkeeping"},
    {"tri_barycentrics_permuted", "the output's (u, v) taken from another pair of the barycentrics (u, v, w)",
     "output bookkeeping"},
    {"isoline_factors_swapped", "isoline density and detail factors swapped", "edge bookkeeping"},
};
static_assert(std::size(kBugs) == size_t(PortBug::Count), "a name for every PortBug");
} // namespace

const char* toString(PortBug b) { return size_t(b) < std::size(kBugs) ? kBugs[size_t(b)].name : "?"; }
bool parsePortBug(const char* s, PortBug& out) {
  for (size_t i = 0; i < std::size(kBugs); ++i)
    if (std::strcmp(s, kBugs[i].name) == 0) {
      out = PortBug(i);
      return true;
    }
  return false;
}
const char* describe(PortBug b) { return size_t(b) < std::size(kBugs) ? kBugs[size_t(b)].sentence : "?"; }
const char* stepOf(PortBug b) { return size_t(b) < std::size(kBugs) ? kBugs[size_t(b)].step : "?"; }

PatchComparison comparePatch(const Patch& patch, const CapturedPatch* got, const CompareOptions& options,
                             Tessellator& tess) {
  PatchComparison c;
  tess.tessellate(patch, options.emulator);
  const int topology = indicesPerLine(patch);
  const int capArity = got ? got->verticesPerPrimitive : 0;
  const int arity = capArity == 1 ? 1 : topology;
  if (capArity != 0 && capArity != arity)
    throw CaptureError("patch " + std::to_string(got->patch) + ": the capture has " + std::to_string(capArity) +
                       " vertices per primitive, topology " + toString(patch.primitive) + " has " +
                       std::to_string(topology));
  Verts ref;
  outputOf(tess, arity, ref);
  static const Verts kNone;
  const Verts& cap = got ? got->vertices : kNone;
  c.verticesPerPrimitive = arity;
  c.referencePrimitives = int(ref.size()) / arity;
  c.capturePrimitives = int(cap.size()) / arity;

  if (ref.empty() || cap.empty()) {
    if (ref.empty() && cap.empty()) return c;
    c.kind = ref.empty() ? DifferenceKind::CulledInReference : DifferenceKind::CulledInCapture;
  } else if (options.strictOrder && ref == cap) {
    return c;
  } else {
    const auto pr = primitives(ref, arity, false), pc = primitives(cap, arity, false);
    if (pr == pc) {
      if (!options.strictOrder) return c;
      c.kind = sameUpToRotation(ref, cap, arity, c.rotatedPrimitives) ? DifferenceKind::Rotated
                                                                       : DifferenceKind::OrderDiffers;
      if (c.kind == DifferenceKind::OrderDiffers) c.rotatedPrimitives = 0;
      return c;
    } else if (distinctPoints(ref) != distinctPoints(cap)) {
      c.kind = DifferenceKind::PointsDiffer;
    } else if (arity == 1) {
      c.kind = DifferenceKind::Multiplicity;
    } else if (primitives(ref, arity, true) == primitives(cap, arity, true)) {
      c.kind = DifferenceKind::WindingOnly;
      c.flippedTriangles = differenceSize(pc, pr);
    } else {
      auto ur = pr, uc = pc;
      ur.erase(std::unique(ur.begin(), ur.end()), ur.end());
      uc.erase(std::unique(uc.begin(), uc.end()), uc.end());
      c.kind = ur == uc         ? DifferenceKind::Multiplicity
               : arity == 3     ? DifferenceKind::TriangulationDiffers
                                : DifferenceKind::PrimitivesDiffer;
    }
  }
  if (arity >= 2) { // before recognise(), which re-uses tess
    Verts refPoints;
    outputOf(tess, 1, refPoints);
    primitiveDifferences(ref, tess.indices(), refPoints, got, arity, options.maxPrimitiveDetails, c);
  }
  if (options.recognise && c.kind != DifferenceKind::OrderDiffers && c.kind != DifferenceKind::Rotated)
    recognise(patch, options.emulator, ref, cap, arity, tess, c);
  if (c.kind == DifferenceKind::PointsDiffer) // after recognise: a whole-patch bug explains the points it moves
    pointDetails(patch, options.emulator, ref, cap, options.maxPointDetails, c);
  return c;
}

CapturedPatch referenceCapture(const Patch& patch, int64_t index, const Options& options, bool pointList) {
  Tessellator t;
  t.tessellate(patch, options);
  CapturedPatch c;
  c.patch = index;
  const int arity = pointList ? 1 : indicesPerLine(patch);
  outputOf(t, arity, c.vertices);
  c.verticesPerPrimitive = c.vertices.empty() ? 0 : arity;
  return c;
}

void appendCsv(std::string& out, const CapturedPatch& c) {
  char buf[96];
  const int n = c.verticesPerPrimitive;
  for (size_t i = 0; n > 0 && i < c.vertices.size(); ++i) {
    std::snprintf(buf, sizeof buf, "%lld,%zu,%zu,0x%08x,0x%08x\n", static_cast<long long>(c.patch), i / size_t(n),
                  i % size_t(n), c.vertices[i].u, c.vertices[i].v);
    out += buf;
  }
}

void CompareSummary::add(const PatchComparison& c, int points) {
  ++patches;
  pointsCompared += points;
  ++byKind[size_t(c.kind)];
  if (c.kind == DifferenceKind::Same) {
    ++same;
    return;
  }
  ++differing;
  for (PortBug b : c.bugs) ++byBug[size_t(b)];
}

std::vector<PortBug> CompareSummary::explainingAll() const {
  std::vector<PortBug> out;
  if (differing == 0) return out;
  for (int b = 0; b < int(PortBug::Count); ++b)
    if (byBug[b] == differing) out.push_back(PortBug(b));
  return out;
}

} // namespace fftess
