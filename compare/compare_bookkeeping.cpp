// The whole-patch port bugs of compare.h as transforms of a patch's input (factors on the wrong edges, another
// winding, partitioning or denormal handling) and output (coordinates written in the wrong place), and their
// recognition: each bug and form re-computed as a whole patch through the emulator.
#include "compare/compare_internal.h"

#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "tessellator/fixed.h"

namespace fftess {
namespace {

const char* const kQuadEdges[4] = {"Ueq0", "Veq0", "Ueq1", "Veq1"};

// Factor permutations: edge e of the buggy port gets factor perm[e] (outer edges only; the rest stay).
constexpr int kQuadMirrored[3][4] = {{2, 1, 0, 3}, {1, 0, 3, 2}, {3, 2, 1, 0}};
constexpr int kTriMirrored[3][3] = {{1, 0, 2}, {0, 2, 1}, {2, 1, 0}};
constexpr int kVFlipped[4] = {0, 3, 2, 1};
const char* const kQuadMirroredNames[3] = {"Ueq0<->Ueq1", "transposed: Ueq0<->Veq0, Ueq1<->Veq1",
                                           "reversed: Ueq0<->Veq1, Veq0<->Ueq1"};
const char* const kTriMirroredNames[3] = {"Ueq0<->Veq0", "Veq0<->Weq0", "Ueq0<->Weq0"};

// tri_barycentrics_permuted: the output (u, v) as (a, b) of (u, v, w), 0 = u, 1 = v, 2 = w.
constexpr int kBarycentricPairs[5][2] = {{0, 2}, {1, 0}, {1, 2}, {2, 0}, {2, 1}};
const char* const kBarycentricNames[5] = {"(u, v) as (u, w)", "(u, v) as (v, u)", "(u, v) as (v, w)",
                                          "(u, v) as (w, u)", "(u, v) as (w, v)"};

bool isTriangles(const Patch& p) {
  return p.primitive == OutputPrimitive::TriangleCw || p.primitive == OutputPrimitive::TriangleCcw;
}

bool hasDenormalFactor(const Patch& p) {
  for (float f : p.factors) {
    const uint32_t b = fx::bitsOf(f) & ~fx::kSignBit;
    if (b != 0 && b < fx::kMinNormal) return true;
  }
  return false;
}

bool rewritesCoordinates(PortBug b) {
  return b == PortBug::DomainVFlipped || b == PortBug::UvSwapped || b == PortBug::TriBarycentricsPermuted;
}

bool movesFactors(PortBug b) {
  return b == PortBug::OuterFactorsRotated || b == PortBug::OuterFactorsMirrored ||
         b == PortBug::OuterFactorsVFlipped || b == PortBug::InsideFactorsSwapped ||
         b == PortBug::IsolineFactorsSwapped;
}

// The hardware-stage factors of the patch (an hlsl-stage patch preconditioned with 'options').
Patch hardwareStage(const Patch& patch, const Options& options) {
  if (!patch.stage.hlsl) return patch;
  Patch hw = patch;
  const HlslFactors h = processHlslFactors(patch.domain, patch.partitioning, patch.stage, patch.factors, options);
  std::memcpy(hw.factors, h.rounded, sizeof hw.factors);
  hw.stage = Stage{};
  return hw;
}

// Edge e of the result gets the factor perm[e] of the patch (n outer edges).
void permuteOuter(Patch& p, const int* perm, int n) {
  float f[4];
  for (int e = 0; e < n; ++e) f[e] = p.factors[perm[e]];
  for (int e = 0; e < n; ++e) p.factors[e] = f[e];
}

void moveFactors(PortBug b, int variant, Patch& p) {
  const bool quad = p.domain == Domain::Quad;
  const int n = quad ? 4 : 3;
  int rotated[4];
  switch (b) {
  case PortBug::OuterFactorsRotated:
    for (int e = 0; e < n; ++e) rotated[e] = (e + variant + 1) % n;
    permuteOuter(p, rotated, n);
    break;
  case PortBug::OuterFactorsMirrored: permuteOuter(p, quad ? kQuadMirrored[variant] : kTriMirrored[variant], n); break;
  case PortBug::OuterFactorsVFlipped: permuteOuter(p, kVFlipped, 4); break;
  case PortBug::InsideFactorsSwapped: std::swap(p.factors[InsideU], p.factors[InsideV]); break;
  case PortBug::IsolineFactorsSwapped: std::swap(p.factors[0], p.factors[1]); break; // density <-> detail
  default: break;
  }
}

// One vertex through a coordinate bug. Every operation is exact for 16.16 coordinates in [0, 1] (the tessellator's):
// 1 - v, and w = (1 - u) - v in that order.
CapturedVertex rewriteVertex(PortBug b, int variant, CapturedVertex x) {
  const float u = fx::floatOf(x.u), v = fx::floatOf(x.v);
  switch (b) {
  case PortBug::DomainVFlipped: return CapturedVertex{x.u, fx::bitsOf(1.0f - v)};
  case PortBug::UvSwapped: return CapturedVertex{x.v, x.u};
  case PortBug::TriBarycentricsPermuted: {
    const float w = (1.0f - u) - v;
    const float uvw[3] = {u, v, w};
    return CapturedVertex{fx::bitsOf(uvw[kBarycentricPairs[variant][0]]),
                          fx::bitsOf(uvw[kBarycentricPairs[variant][1]])};
  }
  default: return x;
  }
}

void flipWinding(std::vector<CapturedVertex>& v) {
  for (size_t i = 0; i + 2 < v.size(); i += 3) std::swap(v[i + 1], v[i + 2]);
}

} // namespace

bool portBugTransformsPatch(PortBug b) {
  switch (b) {
  case PortBug::FloatDivision:
  case PortBug::NoMirroring:
  case PortBug::NoSpecialMidpoint:
  case PortBug::LerpNotRounded:
  case PortBug::FactorsNotSnapped:
  case PortBug::Count: return false;
  default: return true;
  }
}

int portBugVariants(PortBug b, const Patch& patch) {
  const bool quad = patch.domain == Domain::Quad, tri = patch.domain == Domain::Tri;
  switch (b) {
  case PortBug::DenormalsFlushed: return hasDenormalFactor(patch) ? 1 : 0;
  case PortBug::Pow2AsFractionalEven:
  case PortBug::Pow2AsFractionalOdd: return patch.partitioning == Partitioning::Pow2 ? 1 : 0;
  case PortBug::WindingSwapped: return isTriangles(patch) ? 1 : 0;
  case PortBug::OuterFactorsRotated: return quad ? 3 : tri ? 2 : 0;
  case PortBug::OuterFactorsMirrored: return quad || tri ? 3 : 0;
  case PortBug::OuterFactorsVFlipped:
  case PortBug::InsideFactorsSwapped: return quad ? 1 : 0;
  case PortBug::DomainVFlipped: return tri ? 0 : 1;
  case PortBug::UvSwapped: return 1;
  case PortBug::TriBarycentricsPermuted: return tri ? 5 : 0;
  case PortBug::IsolineFactorsSwapped: return patch.domain == Domain::Isoline ? 1 : 0;
  default: return 0;
  }
}

std::string portBugVariantName(PortBug b, const Patch& patch, int variant) {
  if (variant < 0 || variant >= portBugVariants(b, patch)) return "";
  const bool quad = patch.domain == Domain::Quad;
  switch (b) {
  case PortBug::OuterFactorsRotated: {
    const int n = quad ? 4 : 3;
    const char* source = quad ? kQuadEdges[(variant + 1) % n] : (variant == 0 ? "Veq0" : "Weq0");
    return "by " + std::to_string(variant + 1) + ": Ueq0 gets " + source + "'s factor";
  }
  case PortBug::OuterFactorsMirrored: return quad ? kQuadMirroredNames[variant] : kTriMirroredNames[variant];
  case PortBug::TriBarycentricsPermuted: return kBarycentricNames[variant];
  default: return "";
  }
}

Patch portBugInput(PortBug b, int variant, const Patch& patch, const Options& options) {
  if (variant < 0 || variant >= portBugVariants(b, patch)) return patch;
  Patch p = patch;
  switch (b) {
  case PortBug::DenormalsFlushed:
    for (float& f : p.factors) f = fx::flushDenormal(f);
    break;
  case PortBug::Pow2AsFractionalEven: p.partitioning = Partitioning::FractionalEven; break;
  case PortBug::Pow2AsFractionalOdd: p.partitioning = Partitioning::FractionalOdd; break;
  case PortBug::WindingSwapped:
    p.primitive =
        p.primitive == OutputPrimitive::TriangleCw ? OutputPrimitive::TriangleCcw : OutputPrimitive::TriangleCw;
    break;
  default:
    if (movesFactors(b)) {
      p = hardwareStage(patch, options);
      moveFactors(b, variant, p);
    }
  }
  return p;
}

void portBugOutput(PortBug b, int variant, const Patch& patch, CapturedPatch& capture) {
  if (!rewritesCoordinates(b) || variant < 0 || variant >= portBugVariants(b, patch)) return;
  for (CapturedVertex& x : capture.vertices) x = rewriteVertex(b, variant, x);
}

CapturedPatch portBugCapture(PortBug b, int variant, const Patch& patch, int64_t index, const Options& options,
                             bool pointList) {
  CapturedPatch c = referenceCapture(portBugInput(b, variant, patch, options), index, options, pointList);
  portBugOutput(b, variant, patch, c);
  return c;
}

void recogniseWholePatch(const Patch& patch, const Options& options, const std::vector<CapturedVertex>& ref,
                         const std::vector<CapturedVertex>& got, int arity, Tessellator& tess, PatchComparison& c) {
  CapturedPatch model;
  model.verticesPerPrimitive = arity;
  for (int i = 0; i < int(PortBug::Count); ++i) {
    const PortBug b = PortBug(i);
    const int n = portBugVariants(b, patch); // 0 for the per-point bugs
    for (int k = 0; k < n; ++k) {
      tess.tessellate(portBugInput(b, k, patch, options), options);
      outputOf(tess, arity, model.vertices);
      portBugOutput(b, k, patch, model);
      if (sameOrderInsensitive(model.vertices, ref, arity)) continue; // this form changes nothing in this patch
      std::string form = portBugVariantName(b, patch, k);
      bool match = sameOrderInsensitive(model.vertices, got, arity);
      if (!match && arity == 3 && rewritesCoordinates(b)) { // a port that compensates the mirrored winding
        flipWinding(model.vertices);
        match = sameOrderInsensitive(model.vertices, got, arity);
        if (match) form += std::string(form.empty() ? "" : ", ") + "winding flipped too";
      }
      if (match) {
        nameBug(c, b, form);
        break;
      }
    }
  }
}

void nameBug(PatchComparison& c, PortBug b, const std::string& form) {
  c.bugs.push_back(b);
  c.bugVariants.push_back(form);
}

} // namespace fftess
