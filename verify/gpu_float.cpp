// GPU float freedom (CheckOptions::gpuFloat; docs/verify.md, "GPU float freedom"): each shared edge pair the check
// found matching is evaluated again, both sides jointly, with lod/lod_bound.h under lod::FloatModel::Conformant (every
// float a conformant GLSL compiler may produce: a * b + c contracted into an FMA or not, per operation; the spec's
// error bounds of division, sqrt, inversesqrt, exp2, log2, pow). The pair stays a match on every conformant GPU when,
// in every run of the joint evaluation (BoundContext::forEachPath: one run per combination of the comparisons the
// sets leave undecided), neither side may be culled or discarded and either
//   - both sides are the same size and their factors have the same trace node (the same operation sequence on the
//     same input bits: a deterministic GPU computes the same float on both sides, so the edge points are the same
//     on both sides, and the check's seam argument holds for any factor), or
//   - each side's factor set tessellates the edge as the C++ build's factor does (fftess::edgePoints of the set's lo,
//     its hi and the C++ factor are the same: the count and every parameter's bits; the tessellator's point count and
//     positions are monotone step functions of the factor, so every factor between lo and hi gives them too).
// Otherwise the pair is a GpuFloatFinding ("may crack on some GPUs"): the first operation where the two sides'
// traces differ (BoundContext::firstDifference, described on each side) and the fix.
#include "verify/internal.h"

#include "lod/lod_bound.h"
#include "verify/prove_internal.h" // patchLodBound (prove_bridge.cpp)
#include "verify/seam_proof.h" // sameEdgePoints

#include <algorithm>
#include <cmath>
#include <string>

namespace fftess::verify::detail {

namespace {

// What one run of the joint evaluation gave the pair's two edge factors.
struct PairRun {
  lod::Bound a, b;
  bool culledA = false, culledB = false;
};

// A factor the tessellator may discard the patch for (NaN, <= 0 or -Inf; D3D11.3 11.7.6) is in the set.
bool mayDiscard(const lod::Bound& f) { return f.nan || !(f.lo > 0.0f); }

// Every factor of the set tessellates the edge as `cpp` does (see the file comment).
bool sameTessellation(EdgeCache& cache, const lod::Bound& f, float cpp, WorkStats& work) {
  const EdgePoints& c = cache.get(cpp, work);
  const EdgePoints& lo = cache.get(f.lo, work);
  const EdgePoints& hi = cache.get(f.hi, work);
  return lo.culled == c.culled && hi.culled == c.culled && sameEdgePoints(lo, c) && sameEdgePoints(hi, c);
}

const char* const kFix = "declare the edge factor's computation precise (GLSL `precise`, HLSL `precise`) so that no "
                         "product is fused into an add, or compute the edge's value once from its two ends in a fixed "
                         "order (the same operand order on both sides, e.g. the ends sorted by position), as "
                         "lod.sphere_centre = \"half_sum\" does";

} // namespace

} // namespace fftess::verify::detail

namespace fftess::verify {

std::string gpuFloatRefusal(const Scene& s) {
  if (!s.lod.shader.empty())
    return "--gpu-float conformant: lod.shader is a user shader; the GPU float model covers lod/'s built-in schemes only "
           "(lod/lod_bound.h)";
  if (s.lod.scheme == LodScheme::Geomorph)
    return "--gpu-float conformant: lod.scheme = \"geomorph\" is not compiled with the GPU float model (its levels "
           "convert floats to ints; lod/lod_bound.h)";
  return "";
}

} // namespace fftess::verify

namespace fftess::verify::detail {

GpuFloatChecker::GpuFloatChecker(const TerrainData& t, const Camera& camera, int maxPaths)
    : t_(t), context_(std::make_unique<lod::BoundContext>(lod::FloatModel::Conformant, maxPaths)) {
  // The LOD's camera (its own convention), every entry a constant of this context's trace.
  lod::BoundContext::Scope scope(*context_);
  camera_ = std::make_unique<lod::BoundCamera>(lod::boundCamera(toLodCamera(camera)));
}

GpuFloatChecker::~GpuFloatChecker() = default;

void GpuFloatChecker::pair(size_t ia, int e, size_t ib, const std::vector<lod::PatchLod>& factors, EdgeCache& cache,
                           size_t maxFindings, Report& rep) {
  const TerrainPatch& A = t_.patches[ia];
  const TerrainPatch& B = t_.patches[ib];
  const int eb = kOpposite[e];
  ++rep.stats.gpuFloatPairs;
  std::vector<PairRun> runs;
  const bool complete = context_->forEachPath([&] {
    const lod::BoundPatchLod la = patchLodBound(t_, A, *camera_);
    const lod::BoundPatchLod lb = patchLodBound(t_, B, *camera_);
    // Read as the run's answers narrow them (after the shader's clamps: lod/bound.h, BoundContext::narrowed).
    runs.push_back(PairRun{context_->narrowed(la.factors[e]), context_->narrowed(lb.factors[eb]), la.culled, lb.culled});
  });
  const float fa = factors[ia].factors[e], fb = factors[ib].factors[eb];
  GpuFloatFinding g;
  g.a = A.ref;
  g.b = B.ref;
  g.edgeA = e;
  g.edgeB = eb;
  g.factorA = fa;
  g.factorB = fb;
  g.loA = g.hiA = fa;
  g.loB = g.hiB = fb;
  std::string why; // the first reason met
  uint32_t nodeA = 0, nodeB = 0;
  for (const PairRun& r : runs) {
    g.loA = std::min(g.loA, r.a.lo), g.hiA = std::max(g.hiA, r.a.hi);
    g.loB = std::min(g.loB, r.b.lo), g.hiB = std::max(g.hiB, r.b.hi);
    if (!why.empty()) continue;
    if (r.culledA || r.culledB) {
      why = std::string("the frustum test may cull ") + (r.culledA ? "side a" : "side b") + " (the C++ build draws it)";
    } else if (mayDiscard(r.a) || mayDiscard(r.b)) {
      why = std::string("the factor of ") + (mayDiscard(r.a) ? "side a" : "side b") +
            " may be NaN or <= 0 (the tessellator discards the patch)";
    } else if (r.a.node == r.b.node && r.a.node != 0 && A.size == B.size) {
      continue; // the same operation sequence on the same bits: the same float on both sides
    } else if (!sameTessellation(cache, r.a, fa, rep.work) || !sameTessellation(cache, r.b, fb, rep.work)) {
      why = "the two sides compute the factor through different operations, and the factors a conformant compiler "
            "may produce tessellate the edge differently";
      nodeA = r.a.node;
      nodeB = r.b.node;
    }
  }
  if (why.empty() && !complete)
    why = "more than " + std::to_string(runs.size()) + " evaluation paths (undecided comparisons): not decided";
  if (why.empty()) return;
  ++rep.stats.gpuFloatFindings;
  if (rep.gpuFloat.size() >= maxFindings) {
    rep.truncated = true;
    return;
  }
  uint32_t otherB = nodeB;
  const uint32_t firstA = nodeA != 0 ? context_->firstDifference(nodeA, nodeB, &otherB) : 0;
  g.why = why;
  if (firstA != 0) {
    g.operationA = context_->describe(firstA);
    g.operationB = context_->describe(otherB);
  }
  g.fix = nodeA != 0 ? kFix
                     : "compute the frustum test and the factor from the edge's ends in the same operation order on "
                       "both sides, or declare them precise";
  rep.gpuFloat.push_back(std::move(g));
}

void GpuFloatChecker::model(const std::vector<lod::PatchLod>& gpu, const std::vector<char>* need, Report& rep) {
  for (size_t i = 0; i < t_.patches.size() && i < gpu.size(); ++i) {
    if (need && !(*need)[i]) continue;
    lod::Bound u[6];
    bool any = false;
    const bool complete = context_->forEachPath([&] {
      const lod::BoundPatchLod l = patchLodBound(t_, t_.patches[i], *camera_);
      for (int k = 0; k < 6; ++k) {
        const lod::Bound f = context_->narrowed(l.factors[k]);
        if (!any) {
          u[k] = f;
          continue;
        }
        u[k].lo = std::min(u[k].lo, f.lo);
        u[k].hi = std::max(u[k].hi, f.hi);
        u[k].nan = u[k].nan || f.nan;
      }
      any = true;
    });
    if (!complete || !any) continue;
    for (int k = 0; k < 6; ++k) {
      ++rep.stats.gpuModelFactors;
      if (!u[k].contains(gpu[i].factors[k])) ++rep.stats.gpuModelOutside;
    }
  }
}

} // namespace fftess::verify::detail
