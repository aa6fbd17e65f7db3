// The check of one camera (checkTerrain), as the stages it runs in data-flow order (docs/architecture.md, "verify:
// the stages of a check"):
//   validateCamera        the camera is usable (cameras.cpp);
//   evaluateFactors       the LOD's hull factors (lod_bridge.cpp: lod/'s C++ build or the GPU provider), the denormal
//                         factors among them and, on the GPU path with a C++ reference, the factors that differ;
//   injectFactorFault     the fault-injection hook's factor perturbations (verify/testing.h; tests only);
//   findUndrawnPatches    which patches are drawn; of those that are not, the holes and the undecided ones;
//   checkSharedEdges      for every pair of patches that share (part of) an edge, the edge's world-space points from
//                         both sides (edgeWorld: fftess::edgePoints through the per-thread EdgeCache, then the
//                         domain-shader emulation), compared exactly (checkEdgePair, classifyExact) and reported
//                         (recordFinding).
// Only the outer edges are tessellated.
#include "verify/check.h"
#include "verify/internal.h"
#include "verify/seam_proof.h"
#include "verify/testing.h" // Fault: the hook this file implements

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace fftess::verify::detail {

namespace {

bool allFinite(const glm::vec3* p, int n) {
  for (int i = 0; i < n; ++i)
    if (!finite(p[i])) return false;
  return true;
}

// The fault's perturbation of a hull factor (Fault::FactorUlp, FactorStep, NanFactor).
float perturbFactor(const Fault& f, float x) {
  switch (f.kind) {
  case Fault::Kind::FactorUlp: {
    float y = x;
    const int n = f.direction < 0 ? -f.direction : f.direction;
    for (int i = 0; i < n; ++i) y = std::nextafter(y, f.direction < 0 ? -INFINITY : INFINITY);
    return y;
  }
  case Fault::Kind::FactorStep: return x + static_cast<float>(f.direction) * 0x1p-16f;
  case Fault::Kind::NanFactor: return std::numeric_limits<float>::quiet_NaN();
  default: return x;
  }
}

// w = -z of the edge's midpoint (lod's corners) in view space, in float as lod computes a view position:
// mid = (a + b) * 0.5, view = V[0]*x + V[1]*y + V[2]*z + V[3]. cam: the GL view (viewCamera); a D3D camera's w
// (+z of its left-handed view, whose z row is the GL one negated) has the same bits.
float midpointW(const lod::Camera& cam, const TerrainPatch& p, int e) {
  const glm::vec3 mid = (p.lod.corners[kEdgeCorners[e][0]] + p.lod.corners[kEdgeCorners[e][1]]) * 0.5f;
  const glm::mat4& v = cam.view;
  const float z = v[0].z * mid.x + v[1].z * mid.y + v[2].z * mid.z + v[3].z;
  return -z;
}

// Every denormal hull factor the source returned (before faults and before any flush): Report::denormalFactors.
void noteDenormals(const TerrainData& t, const std::vector<lod::PatchLod>& factors, bool flushed, size_t keep,
                   const std::vector<char>* need, Report& rep) {
  rep.denormalsFlushed = flushed;
  for (size_t i = 0; i < factors.size(); ++i)
    for (int k = 0; k < 6 && (!need || (*need)[i]); ++k) {
      const float f = factors[i].factors[k];
      if (std::fpclassify(f) != FP_SUBNORMAL) continue;
      ++rep.stats.denormalFactors;
      if (rep.denormalFactors.size() >= keep) continue;
      DenormalFactor d;
      d.patch = t.patches[i].ref;
      d.factor = k;
      d.value = f;
      d.bits = bitsOf(f);
      d.flushed = flushed;
      rep.denormalFactors.push_back(d);
    }
}

// The record of a patch not drawn whose visibility is not Invisible (a hole, or an undecided patch): how it was not
// drawn (lod/'s cull, or the first edge whose factor made the tessellator discard it: discardEdge, -1 if none),
// its factors, lod/'s record, the projection's w at that edge's midpoint, lod/'s box y range and the decision.
Hole holeRecord(const TerrainData& t, const TerrainPatch& P, const lod::PatchLod& l, int discardEdge,
                const VisibilityDecision& vis, const lod::Camera& view) {
  const bool lodCulled = l.why.culled;
  Hole h;
  h.kind = lodCulled ? HoleKind::CulledWhileVisible : HoleKind::Discarded;
  h.patch = P.ref;
  h.visibility = vis.visibility;
  h.visiblePoint = vis.point;
  h.domainPoint = vis.at;
  h.undecidedSide = vis.visibility == Visibility::Undecided ? vis.side : 0.0f;
  h.budgetExhausted = vis.workBound;
  h.edge = lodCulled || discardEdge < 0 ? -1 : discardEdge;
  const int e = h.edge < 0 ? 0 : h.edge;
  h.hullFactor = l.factors[e];
  h.hullFactorBits = bitsOf(h.hullFactor);
  for (int k = 0; k < 6; ++k) h.factors[k] = l.factors[k];
  h.lod.why = l.why.factor[e];
  h.lod.culled = lodCulled;
  neighbourRule(t, P, e, h.lod);
  h.midpointW = midpointW(view, P, e);
  h.lodBoxMinY = h.lodBoxMaxY = P.lod.corners[0].y;
  for (const glm::vec3& c : P.lod.corners) {
    h.lodBoxMinY = std::fmin(h.lodBoxMinY, c.y);
    h.lodBoxMaxY = std::fmax(h.lodBoxMaxY, c.y);
  }
  if (P.lod.useHeightBounds) {
    h.lodBoxMinY = std::fmin(h.lodBoxMinY, P.lod.minHeight);
    h.lodBoxMaxY = std::fmax(h.lodBoxMaxY, P.lod.maxHeight);
  }
  return h;
}

// The fault of one check, where it applies: `on` when a fault is set and names an existing patch and edge.
struct FaultSite {
  const Fault& fault;
  bool on = false;
  bool is(Fault::Kind k) const { return on && fault.kind == k; }
  bool atPatch(size_t i) const { return on && static_cast<size_t>(fault.patch) == i; }
};

const Fault kNoFault{};

FaultSite faultSite(const CheckOptions& options, size_t n) {
  const Fault& fault = options.fault ? *options.fault : kNoFault;
  const bool on = fault.kind != Fault::Kind::None && fault.patch >= 0 && static_cast<size_t>(fault.patch) < n &&
                  fault.edge >= 0 && fault.edge < 4;
  return {fault, on};
}

// The GPU path with a C++ reference: every factor whose bits differ (before any fault injection).
void compareFactors(const TerrainData& t, const std::vector<lod::PatchLod>& factors,
                    const std::vector<lod::PatchLod>& cpuFactors, size_t keep, EdgeCache& cache, Report& rep) {
  for (size_t i = 0; i < t.patches.size(); ++i)
    for (int k = 0; k < 6; ++k) {
      const float g = factors[i].factors[k], c = cpuFactors[i].factors[k];
      ++rep.stats.factorsCompared;
      const uint32_t gb = bitsOf(g), cb = bitsOf(c);
      if (gb == cb) continue;
      FactorDiff d;
      d.patch = t.patches[i].ref;
      d.factor = k;
      d.gpu = g;
      d.cpu = c;
      d.gpuBits = gb;
      d.cpuBits = cb;
      const EdgePoints& pg = cache.get(g, rep.work);
      const EdgePoints& pc = cache.get(c, rep.work);
      d.changesTessellation = pg.culled != pc.culled || pg.count != pc.count ||
                              !std::equal(pg.fixed, pg.fixed + pg.count, pc.fixed);
      ++rep.stats.factorDiffs;
      if (d.changesTessellation) ++rep.stats.factorDiffsTessellation;
      if (rep.factorDiffs.size() < keep) rep.factorDiffs.push_back(d);
    }
}

// Stage 2: the LOD's factors of every patch into cache.factors (computeFactorsFor), the denormals among them and the
// GPU-vs-C++ differences. False with rep.error when the factors cannot be had (the GPU path without a provider, or
// the provider failed).
bool evaluateFactors(const TerrainData& t, const Camera& camera, const CheckOptions& options,
                     const std::vector<char>* need, EdgeCache& cache, Report& rep) {
  std::vector<lod::PatchLod>& factors = cache.factors; // per-thread scratch, reused camera to camera
  std::vector<lod::PatchLod> cpuFactors;                // lod.evaluate = "gpu": the C++ build's, for comparison
  if (!computeFactorsFor(t, camera, options.factors.get(), factors, &cpuFactors, rep.work, rep.error, need))
    return false;
  noteDenormals(t, factors, denormalRule(t.scene, options).flush, options.maxFindings, need, rep);
  if (!cpuFactors.empty()) compareFactors(t, factors, cpuFactors, options.maxFindings, cache, rep);
  return true;
}

// Stage 3 (tests only): the fault's perturbation of the factors (NeighbourSize, CullPatch, FactorUlp, FactorStep,
// NanFactor); nothing without a fault.
void injectFactorFault(const TerrainData& t, const FaultSite& site, const lod::Camera& lodCamera,
                       std::vector<lod::PatchLod>& factors) {
  const Fault& fault = site.fault;
  if (site.is(Fault::Kind::NeighbourSize) && t.adjacency && t.scene.lod.scheme != LodScheme::Geomorph) {
    const TerrainPatch& P = t.patches[static_cast<size_t>(fault.patch)];
    lod::TileNeighbours wrong = P.tile;
    wrong.size[fault.edge] = fault.size;
    factors[static_cast<size_t>(fault.patch)] = patchLod(t, P, wrong, lodCamera);
  } else if (site.is(Fault::Kind::CullPatch)) {
    lod::PatchLod& c = factors[static_cast<size_t>(fault.patch)];
    c.why.culled = true; // as a wrong frustum test culls: every factor 0
    for (float& f : c.factors) f = 0.0f;
  } else if (site.on) {
    float& f = factors[static_cast<size_t>(fault.patch)].factors[fault.edge];
    f = perturbFactor(fault, f);
  }
}

// One camera's check after the factors are fixed: what every later stage reads (and the report it writes).
struct CameraCheck {
  const TerrainData& t;
  const Camera& camera;
  const CheckOptions& options;
  const FaultSite& fault;
  const std::vector<lod::PatchLod>& factors;
  const lod::Camera& viewCamera; // viewCamera(camera): the verifier's geometry (GL whatever camera.convention)
  const DomainCamera& domainCam;
  const FrustumTest& frustum;
  EdgeCache& cache; // edge points; cache.ep and cache.culled are filled by findUndrawnPatches
  Report& rep;
  const std::vector<char>* need; // visible first: the patches to evaluate (null: all)
  SweepMemo* memo;               // the sweep's result cache and seam proofs (null: none)
  GpuFloatChecker* gpuFloat;     // CheckOptions::gpuFloat: every matching pair goes to it (null: off)
};

// Adds a not-drawn patch's record to the report: a hole (Visible), or an undecided patch.
void recordUndrawn(const CameraCheck& c, size_t i, int discardEdge, const VisibilityDecision& vis) {
  Report& rep = c.rep;
  const bool lodCulled = c.factors[i].why.culled;
  const Hole h = holeRecord(c.t, c.t.patches[i], c.factors[i], discardEdge, vis, c.viewCamera);
  if (vis.visibility == Visibility::Undecided) {
    // Neither proven visible nor invisible: never clean (Verdict::Undecided), listed with the hole's record.
    ++rep.stats.undecided;
    if (lodCulled) ++rep.stats.culledUndecided;
    if (rep.undecided.size() < c.options.maxFindings) rep.undecided.push_back(h);
    else rep.truncated = true;
    return;
  }
  ++rep.stats.holes;
  ++(lodCulled ? rep.stats.holesCulledVisible : rep.stats.holesDiscarded);
  if (rep.holes.size() < c.options.maxFindings) rep.holes.push_back(h);
  else rep.truncated = true;
}

// The edge points of edge e of patch i (its hull factor through the per-thread EdgeCache), tessellated the first time
// a stage asks for them in this camera (cache.ep, reset by findUndrawnPatches).
const EdgePoints& edgeOf(const CameraCheck& c, size_t i, int e) {
  const EdgePoints*& p = c.cache.ep[i][static_cast<size_t>(e)];
  if (!p) p = &c.cache.get(c.factors[i].factors[e], c.rep.work);
  return *p;
}

// Stage 4: which patches are drawn (cache.culled: 1 for a patch not drawn; cache.ep reset: edgeOf fills it). lod/ culls some on purpose; the tessellator discards every patch with an outer factor NaN,
// <= 0 or -Inf (D3D11.3 11.7.6). A patch not drawn is a hole when it would be on screen (visibility.h, Hole).
void findUndrawnPatches(const CameraCheck& c) {
  const size_t n = c.t.patches.size();
  Report& rep = c.rep;
  std::vector<std::array<const EdgePoints*, 4>>& ep = c.cache.ep;
  ep.assign(n, {nullptr, nullptr, nullptr, nullptr});
  std::vector<char>& culled = c.cache.culled;
  culled.assign(n, 0);
  VisibilityLimits limits;
  limits.maxDepth = c.options.visibilityDepth;
  limits.maxSubRectangles = std::max<int64_t>(1, c.options.visibilityBudget);
  for (size_t i = 0; i < n; ++i) {
    if (c.need && !(*c.need)[i]) continue; // visible first: proven off screen, and no selected pair has it
    const bool lodCulled = c.factors[i].why.culled;
    // A patch lod/ culled is not drawn whatever its factors: no edge query, no domain point (only the hole check's
    // visibility decision below, when its box touches the frustum).
    int discardEdge = -1;
    // With the sweep's memo most edges are never tessellated (edgeOf when a pair needs them): the discard rule alone.
    for (int e = 0; e < 4 && !lodCulled && discardEdge < 0; ++e)
      if (c.memo ? c.cache.discards(c.factors[i].factors[e]) : edgeOf(c, i, e).culled) discardEdge = e;
    const bool dropped = c.fault.is(Fault::Kind::DropPatch) && c.fault.atPatch(i);
    if (!lodCulled && discardEdge < 0 && !dropped) continue;
    culled[i] = 1;
    ++rep.stats.culledPatches;
    const VisibilityDecision vis =
        patchVisibility(c.t, c.t.patches[i], c.domainCam.at(i), c.frustum, limits, rep.work);
    if (vis.visibility == Visibility::Invisible && vis.subRectangles == 0) continue; // its whole box is outside
    ++rep.stats.visibilityTests;
    if (vis.visibility == Visibility::Invisible) continue; // not on screen: no hole
    recordUndrawn(c, i, discardEdge, vis);
  }
}

// The points of the edges being compared: side a's whole edge (fullA, domA) and side b's (pb, domB), reused from
// pair to pair. shareHeights: side b may take side a's heights (edgeWorld's donor).
struct EdgeScratch {
  std::vector<glm::vec3> fullA, pb;
  std::vector<DomainPoint> domA, domB;
  bool shareHeights = false;
};

// World positions of the points of edge e of patch i, with the fault's edge perturbations (MirrorEdge, PointUlp).
// donor: side a's points at the same parameters (donor[j] is where out[j] should be), or nullptr: where the flat x
// and z of out[j] have the same bits as donor[j]'s, out[j] takes donor[j]'s height (WorkStats::sharedEdgePoints).
void edgeWorld(const CameraCheck& c, size_t i, int e, const EdgePoints& E, std::vector<glm::vec3>& out,
               std::vector<DomainPoint>* dom, const glm::vec3* donor = nullptr, int donorCount = 0) {
  const TerrainData& t = c.t;
  const Fault& fault = c.fault.fault;
  const bool here = c.fault.atPatch(i) && fault.edge == e;
  const bool mirror = here && fault.kind == Fault::Kind::MirrorEdge;
  out.resize(static_cast<size_t>(E.count));
  if (dom) dom->resize(static_cast<size_t>(E.count));
  for (int j = 0; j < E.count; ++j) {
    const float param = mirror ? 1.0f - E.param[E.count - 1 - j] : E.param[j];
    const DomainPoint d = edgeDomain(e, param);
    if (dom) (*dom)[static_cast<size_t>(j)] = d;
    if (donor && j < donorCount) {
      glm::vec3 w = flatDomain(t, t.patches[i], d.u, d.v);
      if (bitsOf(w.x) == bitsOf(donor[j].x) && bitsOf(w.z) == bitsOf(donor[j].z)) {
        w.y = donor[j].y;
        out[static_cast<size_t>(j)] = w;
        ++c.rep.work.sharedEdgePoints;
        continue;
      }
    }
    out[static_cast<size_t>(j)] = evalDomain(t, t.patches[i], d.u, d.v, c.domainCam.at(i), c.rep.work);
  }
  if (here && fault.kind == Fault::Kind::PointUlp && fault.point >= 0 && fault.point < E.count && fault.axis >= 0 &&
      fault.axis < 3) {
    float& v = out[static_cast<size_t>(fault.point)][fault.axis];
    v = std::nextafter(v, fault.direction < 0 ? -INFINITY : INFINITY);
  }
}

// One side of a finding: the patch edge, its hull factor and lod/'s record of it.
void fillSide(const CameraCheck& c, EdgeSide& s, const TerrainPatch& P, int edge, const EdgePoints& E, int pi) {
  s.patch = P.ref;
  s.edge = edge;
  s.hullFactor = c.factors[pi].factors[edge];
  s.hullFactorBits = bitsOf(s.hullFactor);
  s.processedFactor = E.processedFactor;
  s.culled = c.cache.culled[pi] != 0;
  s.lod.why = c.factors[pi].why.factor[edge];
  s.lod.culled = c.factors[pi].why.culled;
  neighbourRule(c.t, P, edge, s.lod);
}

// The shared part of one pair: side a's points [first, last) of its whole edge (fullA), covering [lo, hi] of its
// edge parameter; side b's points (pb).
struct SharedPart {
  size_t ia = 0, ib = 0;
  int e = 0, eb = 0;
  float lo = 0, hi = 1;
  int first = 0, last = 0;
};

// A finding of a classified pair (both sides' records, the first mismatch, the gap, on screen or not), counted in
// the stats and kept in the report while there is room.
void recordFinding(const CameraCheck& c, const EdgeScratch& s, const SharedPart& part, const ExactVerdict& v) {
  Report& rep = c.rep;
  const TerrainData& t = c.t;
  const TerrainPatch& A = t.patches[part.ia];
  const TerrainPatch& B = t.patches[part.ib];
  const EdgePoints& pa = edgeOf(c, part.ia, part.e);
  const EdgePoints& pbp = edgeOf(c, part.ib, part.eb);
  const glm::vec3* a = s.fullA.data() + part.first;
  const std::vector<glm::vec3>& pb = s.pb;
  const int na = part.last - part.first;
  if (rep.findings.size() >= c.options.maxFindings) {
    rep.truncated = true;
    // still count the worst gap
  }
  Finding f;
  f.classification = v.classification;
  f.partitioning = t.scene.partitioning;
  fillSide(c, f.a, A, part.e, pa, static_cast<int>(part.ia));
  fillSide(c, f.b, B, part.eb, pbp, static_cast<int>(part.ib));
  f.a.paramLo = part.lo;
  f.a.paramHi = part.hi;
  f.a.pointCount = na;
  f.b.pointCount = pbp.count;
  int i = 0;
  while (i < na && i < pbp.count && sameBits(a[i], pb[i])) ++i;
  if (i < na) {
    f.a.firstMismatch = i;
    f.a.mismatchDomain = s.domA[part.first + i];
    f.a.mismatchWorld = a[i];
  }
  if (i < pbp.count) {
    f.b.firstMismatch = i;
    f.b.mismatchDomain = s.domB[static_cast<size_t>(i)];
    f.b.mismatchWorld = pb[i];
  }
  f.edgeStart = B.corners[kEdgeCorners[part.eb][0]];
  f.edgeEnd = B.corners[kEdgeCorners[part.eb][1]];
  if (v.classification == Classification::Crack) {
    f.gapWorld = v.gap;
    f.gapSide = v.gapSide;
    f.gapVertex = v.gapSide == 0 ? a[v.gapIndex] : pb[v.gapIndex];
    f.gapPixels = pixelsAt(c.viewCamera, f.gapVertex, f.gapWorld);
    rep.stats.worstGapWorld = std::max(rep.stats.worstGapWorld, f.gapWorld);
    rep.stats.worstGapPixels = std::max(rep.stats.worstGapPixels, f.gapPixels);
  }
  if (v.classification != Classification::Match) // on screen or not (onscreen.cpp)
    markOnScreen(c.frustum, c.viewCamera, c.camera.nearZ, v, s.fullA.data(), pa.count, part.first, part.last,
                 pb.data(), pbp.count, f, rep.stats);
  if (rep.findings.size() < c.options.maxFindings) rep.findings.push_back(f);
}

// Stage 5b: one pair of sides, edge e of patch ia (its points already in s.fullA / s.domA) and the opposite edge of
// patch ib: side b's points, the shared part, bits compared, then (not a match) classifyExact. False with rep.error
// when a vertex is not finite (never handed to CGAL): the check ends there.
bool checkEdgePair(const CameraCheck& c, EdgeScratch& s, size_t ia, int e, size_t ib, uint64_t storeKey,
                   uint64_t storeValue) {
  Report& rep = c.rep;
  const TerrainPatch& A = c.t.patches[ia];
  const TerrainPatch& B = c.t.patches[ib];
  SharedPart part;
  part.ia = ia;
  part.ib = ib;
  part.e = e;
  part.eb = kOpposite[e];
  const EdgePoints& pa = edgeOf(c, ia, e);
  const EdgePoints& pbp = edgeOf(c, ib, part.eb);
  // The part of A's edge that B covers: [off, off + B.size] of A's [0, A.size] in base units. A point of A at edge
  // parameter t (a float) lies in it when off <= t * A.size <= off + B.size, decided exactly (t has 24 bits and the
  // sizes fewer than 29, so the products are exact in double).
  const bool alongX = e == Veq0 || e == Veq1;
  const int64_t off = B.size != A.size ? (alongX ? B.ux - A.ux : B.uz - A.uz) : 0;
  const double sizeA = static_cast<double>(A.size), lo = static_cast<double>(off);
  const double hi = static_cast<double>(off + std::min(B.size, A.size));
  part.lo = static_cast<float>(lo / sizeA);
  part.hi = static_cast<float>(hi / sizeA);
  part.first = 0;
  part.last = pa.count; // [first, last)
  // The parameters the points were taken at (MirrorEdge changes them), in base units along A's edge.
  auto unitsA = [&](int j) {
    const DomainPoint& d = s.domA[static_cast<size_t>(j)];
    return static_cast<double>(e == Ueq0 || e == Ueq1 ? d.v : d.u) * sizeA;
  };
  while (part.first < pa.count && unitsA(part.first) < lo) ++part.first;
  while (part.last > part.first && unitsA(part.last - 1) > hi) --part.last;
  const int na = part.last - part.first;
  const glm::vec3* a = s.fullA.data() + part.first;
  edgeWorld(c, ib, part.eb, pbp, s.pb, &s.domB, s.shareHeights ? a : nullptr, na);
  bool match = na == pbp.count;
  for (int j = 0; match && j < na; ++j) match = sameBits(a[j], s.pb[j]);

  ++rep.stats.edgesChecked;
  ExactVerdict v;
  if (!match) ++rep.work.cgalCalls;
  if (!match && !(allFinite(s.fullA.data(), pa.count) && allFinite(s.pb.data(), pbp.count))) {
    // Never hand inf or nan to CGAL (its exact predicates cannot take them): report instead.
    rep.error = "patch " + std::to_string(ia) + " edge " + std::to_string(e) + " / patch " + std::to_string(ib) +
                ": non-finite vertex (the scene's geometry overflows float); nothing checked";
    return false;
  }
  if (!match)
    v = classifyExact(c.options.kernel, a, na, s.fullA.data(), pa.count, s.pb.data(), pbp.count, &c.frustum);
  if (storeKey != 0 && v.classification == Classification::Match) c.memo->results.insert(storeKey, storeValue);
  switch (v.classification) {
  case Classification::Match: ++rep.stats.matches; break;
  case Classification::TJunction: ++rep.stats.tJunctions; break;
  case Classification::Crack: ++rep.stats.cracks; break;
  }
  if (v.classification == Classification::Match && !c.options.keepMatches) return true;
  recordFinding(c, s, part, v);
  return true;
}

// True when the memo decides the pair a match without evaluating a point: a same-size pair with the same edge points
// on both sides and a proven seam, or a pair whose two factor bits matched on an earlier camera. Otherwise storeKey /
// storeValue say where the pair's result goes if it is a match (storeKey 0: nowhere). The fault hook's patch never
// takes a shortcut: its pairs always see the perturbed computation.
bool decidedByMemo(const CameraCheck& c, const EdgePair& p, uint64_t& storeKey, uint64_t& storeValue) {
  storeKey = 0;
  if (!c.memo) return false;
  if (c.fault.atPatch(static_cast<size_t>(p.ia)) || c.fault.atPatch(static_cast<size_t>(p.ib))) return false;
  const uint64_t key = memoKey(c.t, p);
  if (key == 0) return false;
  const int eb = kOpposite[p.e];
  WorkStats& w = c.rep.work;
  const float fa = c.factors[static_cast<size_t>(p.ia)].factors[p.e];
  const float fb = c.factors[static_cast<size_t>(p.ib)].factors[eb];
  // Same factor bits: the same edge points (one EdgeCache entry), without tessellating.
  if (c.t.patches[static_cast<size_t>(p.ia)].size == c.t.patches[static_cast<size_t>(p.ib)].size &&
      (bitsOf(fa) == bitsOf(fb) ||
       sameEdgePoints(edgeOf(c, static_cast<size_t>(p.ia), p.e), edgeOf(c, static_cast<size_t>(p.ib), eb))) &&
      seamOf(*c.memo, c.t, p, key, w) == SeamProof::Identical) {
    ++w.seamHits;
    return true;
  }
  const uint64_t value = (static_cast<uint64_t>(bitsOf(fa)) << 32) | bitsOf(fb);
  if (c.memo->results.contains(key, value)) {
    ++w.cacheHits;
    return true;
  }
  ++w.cacheMisses;
  storeKey = key;
  storeValue = value;
  return false;
}

// Stage 5, one pair: skipped when a side is not drawn (Stats::skippedCulled), decided by the memo, or classified
// (side a's whole edge evaluated once for all its partners). False when checkEdgePair ended the check.
struct PairWalker {
  const CameraCheck& c;
  EdgeScratch s;
  int32_t fullPatch = -1;
  int32_t fullEdge = -1;

  bool visit(const EdgePair& p) {
    const std::vector<char>& culled = c.cache.culled;
    if (culled[static_cast<size_t>(p.ia)] || culled[static_cast<size_t>(p.ib)]) {
      ++c.rep.stats.skippedCulled;
      return true;
    }
    uint64_t storeKey = 0, storeValue = 0;
    if (decidedByMemo(c, p, storeKey, storeValue)) {
      ++c.rep.stats.edgesChecked;
      ++c.rep.stats.matches;
      return gpuFloat(p, true);
    }
    const size_t ia = static_cast<size_t>(p.ia);
    if (fullPatch != p.ia || fullEdge != p.e) {
      edgeWorld(c, ia, p.e, edgeOf(c, ia, p.e), s.fullA, &s.domA);
      fullPatch = p.ia;
      fullEdge = p.e;
    }
    const int64_t matches = c.rep.stats.matches;
    const bool ok = checkEdgePair(c, s, ia, p.e, static_cast<size_t>(p.ib), storeKey, storeValue);
    return gpuFloat(p, ok && c.rep.stats.matches > matches) && ok;
  }
  // A matching pair (matched) under CheckOptions::gpuFloat (gpu_float.cpp). True.
  bool gpuFloat(const EdgePair& p, bool matched) {
    if (matched && c.gpuFloat)
      c.gpuFloat->pair(static_cast<size_t>(p.ia), p.e, static_cast<size_t>(p.ib), c.factors, c.cache,
                       c.options.maxFindings, c.rep);
    return true;
  }
};

// Stage 5: every shared edge, once (forEachEdgePair: the bigger side or the lower index handles an edge), or with
// visible first the selected pairs (in the same order). False when checkEdgePair ended the check.
bool checkSharedEdges(const CameraCheck& c, const std::vector<EdgePair>* selected) {
  const TerrainData& t = c.t;
  PairWalker walker{c, {}};
  // Shared edge points are evaluated once: where the height is a function of the flat x/z alone (domain.height_uv =
  // "world", no per-camera domain state: no geomorph, no mip level) a point of side b whose flat x and z have the
  // same bits as side a's point at the same place takes a's height instead of sampling again (the same inputs give
  // the same float result). Counted in WorkStats::sharedEdgePoints, not in domainEvaluations / heightSamples.
  // Never with a fault (its perturbations of side a must not leak into side b).
  walker.s.shareHeights = t.scene.domain.heightUv == HeightUv::World && c.domainCam.patches.empty() && !c.fault.on &&
                          t.scene.displacement.kind != DisplacementKind::None;
  if (selected) {
    for (const EdgePair& p : *selected)
      if (!walker.visit(p)) return false;
    return true;
  }
  bool ok = true;
  int32_t number = 0; // static layouts number their pairs in this order (PatchTree::allPairs)
  forEachEdgePair(t, [&](int32_t ia, int e, int32_t ib) {
    const EdgePair p{ia, ib, e, t.tree ? number++ : -1};
    if (ok) ok = walker.visit(p);
  });
  return ok;
}

} // namespace

Report checkTerrain(const TerrainData& prepared, const Camera& camera, const CheckOptions& options, EdgeCache& cache,
                    SweepMemo* memo) {
  Report rep;
  cache.newCamera(); // no EdgePoints reference outlives a camera
  if (!validateCamera(camera, rep.error)) return rep;
  // A camera-dependent layout (quadtree): this camera's patches, selected into the per-thread scratch.
  if (prepared.quadtree) {
    if (!cache.layout) cache.layout = std::make_unique<TerrainData>();
    cameraLayout(prepared, camera, *cache.layout, rep.work);
  }
  const TerrainData& t = prepared.quadtree ? *cache.layout : prepared;
  rep.stats.patches = static_cast<int64_t>(t.patches.size());
  // The verifier's geometry (frustum, on-screen, pixels) in GL whatever camera.convention: the same frustum.
  const lod::Camera view = detail::viewCamera(camera);
  const FrustumTest frustum(view);
  // Visible first: what could show this camera something (visible_first.cpp); the rest is never evaluated. Not with
  // --gpu-float: its findings are of matching pairs, counted wherever the pair lies, so a pair left out would be a
  // finding dropped (the issue-42 audit: 510 findings with visible first, 535 without, on gpu_float_control.toml).
  rep.visibleFirst = options.visibleFirst && !options.countOffScreen && !options.keepDrawn &&
                     options.gpuFloat == GpuFloat::Off;
  if (rep.visibleFirst) {
    if (!cache.visible) cache.visible = std::make_unique<VisibleSelection>();
    selectVisible(t, frustum, *cache.visible, rep.stats, rep.work);
  }
  const std::vector<char>* need = rep.visibleFirst ? &cache.visible->need : nullptr;
  if (!evaluateFactors(t, camera, options, need, cache, rep)) return rep;
  const FaultSite fault = faultSite(options, t.patches.size());
  injectFactorFault(t, fault, toLodCamera(camera), cache.factors);
  const DomainCamera domainCam = domainCamera(t, cache.factors); // per-patch domain state (geomorph, mip levels)
  std::unique_ptr<GpuFloatChecker> gpu; // CheckOptions::gpuFloat (the cli refuses the scenes gpuFloatRefusal names)
  if (options.gpuFloat == GpuFloat::Conformant && (rep.error = gpuFloatRefusal(t.scene)).empty())
    gpu = std::make_unique<GpuFloatChecker>(t, camera);
  if (gpu && usesGpu(t.scene)) gpu->model(cache.factors, need, rep); // the GPU's factors against the model
  if (!rep.error.empty()) return rep;
  const CameraCheck c{t, camera, options, fault, cache.factors, view, domainCam, frustum, cache, rep, need, memo,
                      gpu.get()};
  findUndrawnPatches(c);
  if (options.keepDrawn)
    for (const char k : cache.culled) rep.drawn.push_back(k ? 0 : 1);
  checkSharedEdges(c, rep.visibleFirst ? &cache.visible->pairs : nullptr);
  return rep;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

Report checkScene(const Terrain& terrain, const Camera& camera, const CheckOptions& options) {
  const Scene& scene = terrain.scene();
  detail::EdgeCache cache(scene.partitioning, scene.stage, detail::tessellatorOptions(scene, options));
  return detail::checkTerrain(terrain.data(), camera, options, cache);
}

} // namespace fftess::verify
