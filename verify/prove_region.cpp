// fftess prove: one region's evaluation (evaluateRegion): every shared edge pair of the layout decided for every
// camera of the region, by trace (both sides compute the same factor and the seam is proven identical), by value
// (each side's factor set gives one tessellation; the pair classified as the check classifies it) or off screen;
// with the patches' culling and discarding (docs/verify.md, "Proofs").
#include "verify/prove_internal.h"
#include "verify/seam_proof.h"

#include <algorithm>
#include <cstdio>

namespace fftess::verify::detail {

ProveScratch::ProveScratch(const TerrainData& t, int maxPaths)
    : context(lod::FloatModel::Conformant, maxPaths),
      edges(t.scene.partitioning, t.scene.stage, tessellatorOptions(t.scene, CheckOptions{})) {}

namespace {

std::string range(const lod::Bound& b) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.9g..%.9g%s", double(b.lo), double(b.hi), b.nan ? " or NaN" : "");
  return buf;
}

// Every camera of the region gives the same edge points for every float of b (a monotone step function: the same
// fixed-point factor at both ends). b: not NaN.
bool oneTessellation(ProveScratch& s, const lod::Bound& b) {
  WorkStats w;
  const EdgePoints& lo = s.edges.get(b.lo, w);
  const EdgePoints& hi = s.edges.get(b.hi, w);
  return lo.culled == hi.culled && lo.fixedFactor == hi.fixedFactor && sameEdgePoints(lo, hi);
}

struct RegionEval {
  const TerrainData& t;
  ProveScratch& s;
  const RegionCameras& cams;
  const RegionFrustum& frustum;
  RegionResult& res;

  void fail(RegionOutcome o, const std::string& why) {
    if (res.outcome == RegionOutcome::Decided || (o == RegionOutcome::Suspect && res.outcome != o)) {
      res.outcome = o;
      res.why = why;
    }
  }

  // A culled run of patch i: harmless when it is off screen for the whole region or by the culling argument.
  bool cullOk(size_t i) {
    if (s.offScreen[i]) return true;
    if (!s.cullChecked[i]) {
      glm::dvec3 llo, lhi;
      lodBox(t.patches[i], llo, lhi);
      std::string why;
      s.cullOk[i] = frustum.cullHarmless(llo, lhi, t.tree->boxLo[i], t.tree->boxHi[i], why) ? 1 : 0;
      s.cullWhy[i] = why;
      s.cullChecked[i] = 1;
    }
    if (!s.cullOk[i]) fail(RegionOutcome::Undecided, "patch " + std::to_string(i) + " may be culled while on screen (" +
                                                         s.cullWhy[i] + ")");
    return s.cullOk[i] != 0;
  }

  // One run's result for patch i: false when the run culls it (harmlessly or not) or when a factor may discard it.
  bool drawnIn(size_t i, const lod::BoundPatchLod& l, bool& problem) {
    if (l.culled) {
      if (!cullOk(i)) problem = true;
      return false;
    }
    if (s.offScreen[i]) return true;
    for (int k = 0; k < 4; ++k) {
      const lod::Bound f = s.context.narrowed(l.factors[k]); // after the shader's clamp (lod/bound.h)
      if (f.nan || s.edges.discards(f.lo)) {
        fail(RegionOutcome::Suspect, "patch " + std::to_string(i) + " edge " + std::to_string(k) +
                                         " may be discarded while on screen (factor " + range(f) + ")");
        problem = true;
        return false;
      }
    }
    return true;
  }

  // The joint evaluation of pair number `number` over every path. False: the region is not decided (res says why).
  bool pair(const EdgePair& p, uint8_t& seam) {
    const size_t ia = static_cast<size_t>(p.ia), ib = static_cast<size_t>(p.ib);
    const int eb = kOpposite[p.e];
    const TerrainPatch& A = t.patches[ia];
    const TerrainPatch& B = t.patches[ib];
    bool problem = false, allTrace = true;
    const bool complete = s.context.forEachPath([&]() {
      if (problem) return;
      ++res.lodPaths;
      const lod::BoundPatchLod la = patchLodBound(t, A, cams.lod);
      const lod::BoundPatchLod lb = patchLodBound(t, B, cams.lod);
      s.evaluated[ia] = s.evaluated[ib] = 1;
      const bool da = drawnIn(ia, la, problem);
      const bool db = drawnIn(ib, lb, problem);
      if (problem || !da || !db) return;
      const lod::Bound fa = s.context.narrowed(la.factors[p.e]);
      const lod::Bound fb = s.context.narrowed(lb.factors[eb]);
      if (A.size == B.size && fa.node != 0 && fa.node == fb.node) {
        if (seam == 0) seam = static_cast<uint8_t>(proveSeam(t, A, p.e, B));
        if (static_cast<SeamProof>(seam) == SeamProof::Identical) return;
      }
      allTrace = false;
      const std::string name = "pair " + std::to_string(p.number) + " (patch " + std::to_string(ia) + " edge " +
                               std::to_string(p.e) + " / patch " + std::to_string(ib) + " edge " + std::to_string(eb) +
                               ")";
      if (!oneTessellation(s, fa) || !oneTessellation(s, fb)) {
        fail(RegionOutcome::Undecided, name + ": factors " + range(fa) + " / " + range(fb) +
                                           " round to different tessellations");
        problem = true;
        return;
      }
      const Classification c = classifyPairFactors(t, ia, p.e, ib, fa.lo, fb.lo, s, Kernel::Epick);
      if (c != Classification::Match) {
        fail(RegionOutcome::Suspect, name + ": factors " + range(fa) + " / " + range(fb) + " give a " +
                                         (c == Classification::Crack ? "crack" : "T-junction"));
        problem = true;
      }
    });
    if (!problem && !complete) {
      fail(RegionOutcome::Undecided, "pair " + std::to_string(p.number) + ": more than maxPaths paths");
      problem = true;
    }
    if (problem) return false;
    ++(allTrace ? res.pairsByTrace : res.pairsByValue);
    return true;
  }

  // A patch in no live pair that may be on screen: its culling and discarding alone.
  bool single(size_t i) {
    bool problem = false;
    s.context.forEachPath([&]() {
      if (problem) return;
      ++res.lodPaths;
      drawnIn(i, patchLodBound(t, t.patches[i], cams.lod), problem);
    });
    return !problem;
  }
};

} // namespace

RegionResult evaluateRegion(const TerrainData& t, const CameraRegion& region, ProveScratch& s,
                            std::vector<uint8_t>& seams) {
  RegionResult res;
  s.context.clearTrace();
  s.edges.newCamera();
  lod::BoundContext::Scope scope(s.context);
  const RegionCameras cams = regionCameras(t.scene.camera, region);
  // A view matrix that may be NaN belongs to cameras near the degenerate set (regionInvalidCameras decides the set
  // itself): every later step would reason about NaN planes and factors. Never decided; split.
  for (const lod::BoundCamera* cam : {&cams.view, &cams.lod})
    for (int c = 0; c < 4; ++c)
      for (int l = 0; l < 4; ++l)
        if (!cam->view[c][l].finite()) {
          res.outcome = RegionOutcome::Undecided;
          res.why = "the view matrix of some camera of the region may be NaN or infinite (near eye == target or a view "
                    "direction parallel to up)";
          res.onScreen = true;
          return res;
        }
  const RegionFrustum frustum(cams.view);
  const PatchTree& tree = *t.tree;
  const size_t n = t.patches.size();
  s.offScreen.assign(n, 0);
  s.cullChecked.assign(n, 0);
  s.cullOk.assign(n, 0);
  s.cullWhy.assign(n, std::string());
  s.evaluated.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    s.offScreen[i] = frustum.boxOffScreen(tree.boxLo[i], tree.boxHi[i]) ? 1 : 0;
    res.patchesOffScreen += s.offScreen[i];
    if (!s.offScreen[i]) res.onScreen = true;
  }
  RegionEval ev{t, s, cams, frustum, res};
  for (const EdgePair& p : tree.allPairs) {
    const size_t ia = static_cast<size_t>(p.ia), ib = static_cast<size_t>(p.ib);
    if (s.offScreen[ia] && s.offScreen[ib]) {
      const glm::dvec3 lo = glm::min(tree.boxLo[ia], tree.boxLo[ib]), hi = glm::max(tree.boxHi[ia], tree.boxHi[ib]);
      if (frustum.boxOffScreen(lo, hi)) {
        ++res.pairsOffScreen;
        continue;
      }
    }
    if (!ev.pair(p, seams[static_cast<size_t>(p.number)])) return res; // the first reason met: split
  }
  for (size_t i = 0; i < n; ++i)
    if (!s.evaluated[i] && !s.offScreen[i] && !ev.single(i)) return res;
  return res;
}

} // namespace fftess::verify::detail
