// The edge check: for every pair of patches that share (part of) an edge, the edge's world-space vertices from
// both sides, compared exactly. Only the outer edges are tessellated (fftess::edgePoints).
#include "verify/internal.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <limits>

namespace fftess::verify::detail {

namespace {

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

EdgeCache::EdgeCache(Partitioning p, const Stage& s, const Options& o)
    : partitioning_(p), stage_(s), options_(o), keys_(kSlots, 0), gen_(kSlots, 0), slot_(kSlots, -1) {}

void EdgeCache::newCamera() {
  used_ = 0;
  if (++generation_ == 0) { // wrapped: forget every stamp
    std::fill(gen_.begin(), gen_.end(), 0u);
    generation_ = 1;
  }
}

void EdgeCache::grow() {
  const size_t n = keys_.size() * 2, mask = n - 1;
  std::vector<uint32_t> keys(n, 0), gen(n, 0);
  std::vector<int32_t> slot(n, -1);
  for (size_t i = 0; i < keys_.size(); ++i) {
    if (gen_[i] != generation_) continue;
    size_t h = (static_cast<size_t>(keys_[i]) * 0x9E3779B1u) & mask;
    while (gen[h] == generation_) h = (h + 1) & mask;
    keys[h] = keys_[i];
    gen[h] = generation_;
    slot[h] = slot_[i];
  }
  keys_.swap(keys);
  gen_.swap(gen);
  slot_.swap(slot);
}

const EdgePoints& EdgeCache::get(float factor, WorkStats& work) {
  uint32_t bits;
  std::memcpy(&bits, &factor, sizeof bits);
  // Linear probing in a table kept at most half full: it grows (entries keep their addresses) within a camera.
  if (used_ * 2 >= keys_.size()) grow();
  const size_t mask = keys_.size() - 1;
  size_t h = (static_cast<size_t>(bits) * 0x9E3779B1u) & mask;
  for (; gen_[h] == generation_; h = (h + 1) & mask)
    if (keys_[h] == bits) return entries_[static_cast<size_t>(slot_[h])];
  ++work.edgeQueries;
  keys_[h] = bits;
  gen_[h] = generation_;
  slot_[h] = static_cast<int32_t>(used_);
  if (used_ == entries_.size()) entries_.emplace_back();
  EdgePoints& e = entries_[used_++];
  e = edgePoints(factor, partitioning_, stage_, options_);
  return e;
}

static bool allFinite(const glm::vec3* p, int n) {
  for (int i = 0; i < n; ++i)
    if (!finite(p[i])) return false;
  return true;
}

namespace {

std::string vecText(const glm::vec3& v) {
  char b[96];
  std::snprintf(b, sizeof b, "(%g, %g, %g)", double(v.x), double(v.y), double(v.z));
  return b;
}

// glm::lookAt in float, as lod::makeCamera runs it: f = normalize(target - eye), s = normalize(cross(f, up)), with
// normalize(v) = v * inversesqrt(dot(v, v)). Each dot must be a finite normal float (>= 2^-126): below, it underflows
// (0 or a denormal with few bits) and the view matrix is NaN or meaningless (a view direction of float noise).
bool lookAtFits(const Camera& c, std::string& error) {
  const glm::vec3 d = c.target - c.eye;
  const float dd = glm::dot(d, d);
  if (!std::isfinite(dd) || !(dd >= FLT_MIN)) {
    char b[96];
    std::snprintf(b, sizeof b, "%g", double(dd));
    error = "camera.target: the view direction target - eye = " + vecText(d) + " (eye " + vecText(c.eye) +
            ", target " + vecText(c.target) + ") " +
            (std::isfinite(dd) ? "is too short for float: |target - eye|^2 = " + std::string(b) +
                                     " is below 2^-126; move camera.target away from camera.eye"
                               : std::string("overflows float: |target - eye|^2 is not finite"));
    return false;
  }
  const glm::vec3 f = d * (1.0f / std::sqrt(dd));
  const glm::vec3 x = glm::cross(f, c.up);
  const float xx = glm::dot(x, x);
  if (!std::isfinite(xx) || !(xx >= FLT_MIN)) {
    error = "camera.up: " + vecText(c.up) + " is (nearly) parallel to the view direction target - eye = " + vecText(d) +
            " in float (|cross|^2 below 2^-126 or not finite)";
    return false;
  }
  return true;
}

} // namespace

bool validateCamera(const Camera& c, std::string& error) {
  if (!finite(c.eye)) return error = "camera.eye: not finite", false;
  if (!finite(c.target)) return error = "camera.target: not finite", false;
  if (!finite(c.up)) return error = "camera.up: not finite", false;
  if (sameBits(c.eye, c.target)) return error = "camera.target: equals camera.eye", false;
  const double dx = double(c.target.x) - c.eye.x, dy = double(c.target.y) - c.eye.y, dz = double(c.target.z) - c.eye.z;
  const double cx = dy * c.up.z - dz * c.up.y, cy = dz * c.up.x - dx * c.up.z, cz = dx * c.up.y - dy * c.up.x;
  if (cx == 0 && cy == 0 && cz == 0) return error = "camera.up: parallel to the view direction", false;
  if (!lookAtFits(c, error)) return false;
  if (!(c.fovY > 0 && c.fovY < 180)) return error = "camera.fov_y: must be in (0, 180) degrees", false;
  if (!(c.nearZ > 0) || !std::isfinite(c.nearZ)) return error = "camera.near: must be > 0", false;
  if (!(c.farZ > c.nearZ) || !std::isfinite(c.farZ)) return error = "camera.far: must be > camera.near", false;
  if (c.width < 1) return error = "camera.width: must be >= 1", false;
  if (c.height < 1) return error = "camera.height: must be >= 1", false;
  return true;
}

namespace {

uint32_t bitsOf(float f) {
  uint32_t b;
  std::memcpy(&b, &f, sizeof b);
  return b;
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
// mid = (a + b) * 0.5, view = V[0]*x + V[1]*y + V[2]*z + V[3].
float midpointW(const lod::Camera& cam, const TerrainPatch& p, int e) {
  const glm::vec3 mid = (p.lod.corners[kEdgeCorners[e][0]] + p.lod.corners[kEdgeCorners[e][1]]) * 0.5f;
  const glm::mat4& v = cam.view;
  const float z = v[0].z * mid.x + v[1].z * mid.y + v[2].z * mid.z + v[3].z;
  return -z;
}

// Every denormal hull factor the source returned (before faults and before any flush): Report::denormalFactors.
void noteDenormals(const TerrainData& t, const std::vector<lod::PatchLod>& factors, bool flushed, size_t keep,
                   Report& rep) {
  rep.denormalsFlushed = flushed;
  for (size_t i = 0; i < factors.size(); ++i)
    for (int k = 0; k < 6; ++k) {
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
                const VisibilityDecision& vis, const lod::Camera& lodCamera) {
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
  h.midpointW = midpointW(lodCamera, P, e);
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

} // namespace

Report checkTerrain(const TerrainData& t, const Camera& camera, const CheckOptions& options, EdgeCache& cache) {
  Report rep;
  cache.newCamera(); // no EdgePoints reference outlives a camera
  if (!validateCamera(camera, rep.error)) return rep;
  const size_t n = t.patches.size();
  rep.stats.patches = static_cast<int64_t>(n);
  const Fault& fault = options.fault;
  const bool faultPatch = fault.kind != Fault::Kind::None && fault.patch >= 0 && static_cast<size_t>(fault.patch) < n &&
                          fault.edge >= 0 && fault.edge < 4;

  std::vector<lod::PatchLod>& factors = cache.factors; // per-thread scratch, reused camera to camera
  std::vector<lod::PatchLod> cpuFactors;                // lod.evaluate = "gpu": the C++ build's, for comparison
  if (!computeFactorsFor(t, camera, options.factors.get(), factors, &cpuFactors, rep.work, rep.error)) return rep;
  const lod::Camera lodCamera = toLodCamera(camera);
  noteDenormals(t, factors, denormalRule(t.scene, options).flush, options.maxFindings, rep);
  // The GPU path with a C++ reference: every factor whose bits differ (before any fault injection).
  if (!cpuFactors.empty()) {
    for (size_t i = 0; i < n; ++i)
      for (int k = 0; k < 6; ++k) {
        const float g = factors[i].factors[k], c = cpuFactors[i].factors[k];
        ++rep.stats.factorsCompared;
        uint32_t gb, cb;
        std::memcpy(&gb, &g, 4);
        std::memcpy(&cb, &c, 4);
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
        if (rep.factorDiffs.size() < options.maxFindings) rep.factorDiffs.push_back(d);
      }
  }
  if (faultPatch && fault.kind == Fault::Kind::NeighbourSize && t.adjacency &&
      t.scene.lod.scheme != LodScheme::Geomorph) {
    const TerrainPatch& P = t.patches[static_cast<size_t>(fault.patch)];
    lod::TileNeighbours wrong = P.tile;
    wrong.size[fault.edge] = fault.size;
    factors[static_cast<size_t>(fault.patch)] = patchLod(t, P, wrong, lodCamera);
  } else if (faultPatch && fault.kind == Fault::Kind::CullPatch) {
    lod::PatchLod& c = factors[static_cast<size_t>(fault.patch)];
    c.why.culled = true; // as a wrong frustum test culls: every factor 0
    for (float& f : c.factors) f = 0.0f;
  } else if (faultPatch) {
    float& f = factors[static_cast<size_t>(fault.patch)].factors[fault.edge];
    f = perturbFactor(fault, f);
  }
  const DomainCamera domainCam = domainCamera(t, factors); // per-patch domain state (geomorph, mip levels)

  // Which patches are drawn. lod/ culls some on purpose; the tessellator discards every patch with an outer factor
  // NaN, <= 0 or -Inf (D3D11.3 11.7.6). A patch not drawn is a hole when it would be on screen (verify.h, Hole).
  std::vector<std::array<const EdgePoints*, 4>>& ep = cache.ep;
  ep.assign(n, {nullptr, nullptr, nullptr, nullptr});
  std::vector<char>& culled = cache.culled;
  culled.assign(n, 0);
  const FrustumTest frustum(lodCamera);
  VisibilityLimits limits;
  limits.maxDepth = options.visibilityDepth;
  limits.maxSubRectangles = std::max<int64_t>(1, options.visibilityBudget);
  for (size_t i = 0; i < n; ++i) {
    const bool lodCulled = factors[i].why.culled;
    // A patch lod/ culled is not drawn whatever its factors: no edge query, no domain point (only the hole check's
    // visibility decision below, when its box touches the frustum).
    int discardEdge = -1;
    for (int e = 0; e < 4 && !lodCulled; ++e) {
      ep[i][e] = &cache.get(factors[i].factors[e], rep.work);
      if (ep[i][e]->culled && discardEdge < 0) discardEdge = e;
    }
    const bool dropped = faultPatch && fault.kind == Fault::Kind::DropPatch && static_cast<size_t>(fault.patch) == i;
    if (!lodCulled && discardEdge < 0 && !dropped) continue;
    culled[i] = 1;
    ++rep.stats.culledPatches;
    const TerrainPatch& P = t.patches[i];
    const VisibilityDecision vis = patchVisibility(t, P, domainCam.at(i), frustum, limits, rep.work);
    if (vis.visibility == Visibility::Invisible && vis.subRectangles == 0) continue; // its whole box is outside
    ++rep.stats.visibilityTests;
    if (vis.visibility == Visibility::Invisible) continue; // not on screen: no hole
    const Hole h = holeRecord(t, P, factors[i], discardEdge, vis, lodCamera);
    if (vis.visibility == Visibility::Undecided) {
      // Neither proven visible nor invisible: never clean (Verdict::Undecided), listed with the hole's record.
      ++rep.stats.undecided;
      if (lodCulled) ++rep.stats.culledUndecided;
      if (rep.undecided.size() < options.maxFindings) rep.undecided.push_back(h);
      else rep.truncated = true;
      continue;
    }
    ++rep.stats.holes;
    ++(lodCulled ? rep.stats.holesCulledVisible : rep.stats.holesDiscarded);
    if (rep.holes.size() < options.maxFindings) rep.holes.push_back(h);
    else rep.truncated = true;
  }

  // Shared edge points are evaluated once: where the height is a function of the flat x/z alone (domain.height_uv =
  // "world", no per-camera domain state: no geomorph, no mip level) a point of side b whose flat x and z have the
  // same bits as side a's point at the same place takes a's height instead of sampling again (the same inputs give
  // the same float result). Counted in WorkStats::sharedEdgePoints, not in domainEvaluations / heightSamples.
  // Never with a fault (its perturbations of side a must not leak into side b).
  const bool shareHeights = t.scene.domain.heightUv == HeightUv::World && domainCam.patches.empty() && !faultPatch &&
                            t.scene.displacement.kind != DisplacementKind::None;
  auto sameXZBits = [](const glm::vec3& p, const glm::vec3& q) {
    return bitsOf(p.x) == bitsOf(q.x) && bitsOf(p.z) == bitsOf(q.z);
  };
  // World positions of the points of edge e of patch i, with the fault's edge perturbations (MirrorEdge, PointUlp).
  // donor: side a's points at the same parameters (donor[j] is where out[j] should be), or nullptr.
  auto edgeWorld = [&](size_t i, int e, const EdgePoints& E, std::vector<glm::vec3>& out, std::vector<DomainPoint>* dom,
                       const glm::vec3* donor = nullptr, int donorCount = 0) {
    const bool here = faultPatch && static_cast<size_t>(fault.patch) == i && fault.edge == e;
    const bool mirror = here && fault.kind == Fault::Kind::MirrorEdge;
    out.resize(static_cast<size_t>(E.count));
    if (dom) dom->resize(static_cast<size_t>(E.count));
    for (int j = 0; j < E.count; ++j) {
      const float param = mirror ? 1.0f - E.param[E.count - 1 - j] : E.param[j];
      const DomainPoint d = edgeDomain(e, param);
      if (dom) (*dom)[static_cast<size_t>(j)] = d;
      if (donor && j < donorCount) {
        glm::vec3 w = flatDomain(t, t.patches[i], d.u, d.v);
        if (sameXZBits(w, donor[j])) {
          w.y = donor[j].y;
          out[static_cast<size_t>(j)] = w;
          ++rep.work.sharedEdgePoints;
          continue;
        }
      }
      out[static_cast<size_t>(j)] = evalDomain(t, t.patches[i], d.u, d.v, domainCam.at(i), rep.work);
    }
    if (here && fault.kind == Fault::Kind::PointUlp && fault.point >= 0 && fault.point < E.count && fault.axis >= 0 &&
        fault.axis < 3) {
      float& c = out[static_cast<size_t>(fault.point)][fault.axis];
      c = std::nextafter(c, fault.direction < 0 ? -INFINITY : INFINITY);
    }
  };

  std::vector<glm::vec3> fullA, pb;
  std::vector<DomainPoint> domA, domB;
  for (size_t ia = 0; ia < n; ++ia) {
    const TerrainPatch& A = t.patches[ia];
    for (int e = 0; e < 4; ++e) {
      int partners[2] = {-1, -1};
      const int n0 = A.nb[e][0], n1 = A.nb[e][1];
      if (n0 < 0) continue;
      if (n1 >= 0) {
        partners[0] = n0; // two half-size neighbours
        partners[1] = n1;
      } else if (t.patches[n0].size == A.size && n0 > static_cast<int>(ia)) {
        partners[0] = n0;
      } else {
        continue; // the bigger side or the lower index handles this edge
      }
      bool fullDone = false;
      for (int k = 0; k < 2; ++k) {
        const int ib = partners[k];
        if (ib < 0) continue;
        if (culled[ia] || culled[ib]) {
          ++rep.stats.skippedCulled;
          continue;
        }
        const TerrainPatch& B = t.patches[ib];
        const int eb = kOpposite[e];
        const EdgePoints& pa = *ep[ia][e];
        const EdgePoints& pbp = *ep[ib][eb];
        if (!fullDone) {
          edgeWorld(ia, e, pa, fullA, &domA);
          fullDone = true;
        }
        // The part of A's edge that B covers, in A's edge parameter.
        float lo = 0, hi = 1;
        if (B.size != A.size) {
          const bool alongX = e == Veq0 || e == Veq1;
          const int64_t off = alongX ? B.ux - A.ux : B.uz - A.uz;
          lo = off == 0 ? 0.0f : 0.5f;
          hi = lo + 0.5f;
        }
        int first = 0, last = pa.count; // [first, last)
        // The parameters the points were taken at (MirrorEdge changes them).
        auto paramA = [&](int j) {
          const DomainPoint& d = domA[static_cast<size_t>(j)];
          return e == Ueq0 || e == Ueq1 ? d.v : d.u;
        };
        while (first < pa.count && paramA(first) < lo) ++first;
        while (last > first && paramA(last - 1) > hi) --last;
        const int na = last - first;
        const glm::vec3* a = fullA.data() + first;
        edgeWorld(static_cast<size_t>(ib), eb, pbp, pb, &domB, shareHeights ? a : nullptr, na);
        bool match = na == pbp.count;
        for (int j = 0; match && j < na; ++j) match = sameBits(a[j], pb[j]);

        ++rep.stats.edgesChecked;
        ExactVerdict v;
        if (!match) ++rep.work.cgalCalls;
        if (!match && !(allFinite(fullA.data(), pa.count) && allFinite(pb.data(), pbp.count))) {
          // Never hand inf or nan to CGAL (its exact predicates cannot take them): report instead.
          rep.error = "patch " + std::to_string(ia) + " edge " + std::to_string(e) + " / patch " + std::to_string(ib) +
                      ": non-finite vertex (the scene's geometry overflows float); nothing checked";
          return rep;
        }
        if (!match) v = classifyExact(options.kernel, a, na, fullA.data(), pa.count, pb.data(), pbp.count, &frustum);
        switch (v.classification) {
        case Classification::Match: ++rep.stats.matches; break;
        case Classification::TJunction: ++rep.stats.tJunctions; break;
        case Classification::Crack: ++rep.stats.cracks; break;
        }
        if (v.classification == Classification::Match && !options.keepMatches) continue;
        if (rep.findings.size() >= options.maxFindings) {
          rep.truncated = true;
          // still count the worst gap
        }
        Finding f;
        f.classification = v.classification;
        f.partitioning = t.scene.partitioning;
        auto fillSide = [&](EdgeSide& s, const TerrainPatch& P, int edge, const EdgePoints& E, int pi) {
          s.patch = P.ref;
          s.edge = edge;
          s.hullFactor = factors[pi].factors[edge];
          std::memcpy(&s.hullFactorBits, &s.hullFactor, sizeof s.hullFactorBits);
          s.processedFactor = E.processedFactor;
          s.culled = culled[pi] != 0;
          s.lod.why = factors[pi].why.factor[edge];
          s.lod.culled = factors[pi].why.culled;
          neighbourRule(t, P, edge, s.lod);
        };
        fillSide(f.a, A, e, pa, static_cast<int>(ia));
        fillSide(f.b, B, eb, pbp, ib);
        f.a.paramLo = lo;
        f.a.paramHi = hi;
        f.a.pointCount = na;
        f.b.pointCount = pbp.count;
        int i = 0;
        while (i < na && i < pbp.count && sameBits(a[i], pb[i])) ++i;
        if (i < na) {
          f.a.firstMismatch = i;
          f.a.mismatchDomain = domA[first + i];
          f.a.mismatchWorld = a[i];
        }
        if (i < pbp.count) {
          f.b.firstMismatch = i;
          f.b.mismatchDomain = domB[static_cast<size_t>(i)];
          f.b.mismatchWorld = pb[i];
        }
        f.edgeStart = B.corners[kEdgeCorners[eb][0]];
        f.edgeEnd = B.corners[kEdgeCorners[eb][1]];
        if (v.classification == Classification::Crack) {
          f.gapWorld = v.gap;
          f.gapSide = v.gapSide;
          f.gapVertex = v.gapSide == 0 ? a[v.gapIndex] : pb[v.gapIndex];
          f.gapPixels = pixelsAt(lodCamera, f.gapVertex, f.gapWorld);
          rep.stats.worstGapWorld = std::max(rep.stats.worstGapWorld, f.gapWorld);
          rep.stats.worstGapPixels = std::max(rep.stats.worstGapPixels, f.gapPixels);
        }
        if (v.classification != Classification::Match) // on screen or not (onscreen.cpp)
          markOnScreen(frustum, lodCamera, camera.nearZ, v, fullA.data(), pa.count, first, last, pb.data(), pbp.count, f,
                       rep.stats);
        if (rep.findings.size() < options.maxFindings) rep.findings.push_back(f);
      }
    }
  }
  return rep;
}

} // namespace fftess::verify::detail

namespace fftess::verify {

Report checkScene(const Terrain& terrain, const Camera& camera, const CheckOptions& options) {
  const Scene& scene = terrain.scene();
  detail::EdgeCache cache(scene.partitioning, scene.stage, detail::tessellatorOptions(scene, options));
  return detail::checkTerrain(terrain.data(), camera, options, cache);
}

Verdict verdictOf(const Stats& s, bool countOffScreen) {
  if ((countOffScreen ? s.cracks : s.cracksOnScreen()) > 0) return Verdict::Cracks;
  if (s.holes > 0) return Verdict::Holes;
  if (s.undecided > 0) return Verdict::Undecided;
  if (s.edgesChecked == 0) return Verdict::NothingChecked;
  if ((countOffScreen ? s.tJunctions : s.tJunctionsOnScreen()) > 0) return Verdict::TJunctionsOnly;
  return Verdict::Watertight;
}

Verdict verdictOf(const SweepResult& r, bool countOffScreen) {
  const Verdict v = verdictOf(r.total, countOffScreen);
  if (v == Verdict::Cracks || v == Verdict::Holes || v == Verdict::Undecided) return v;
  if (r.camerasInvalid > 0) return Verdict::Unchecked;
  return v;
}

const char* toString(Verdict v) {
  switch (v) {
  case Verdict::Watertight: return "watertight";
  case Verdict::TJunctionsOnly: return "t_junctions";
  case Verdict::Cracks: return "cracks";
  case Verdict::Holes: return "holes";
  case Verdict::NothingChecked: return "nothing_checked";
  case Verdict::Unchecked: return "unchecked";
  case Verdict::Undecided: return "undecided";
  }
  return "?";
}

const char* toString(HoleKind k) { return k == HoleKind::Discarded ? "discarded" : "culled_while_visible"; }

const char* toString(Visibility v) {
  switch (v) {
  case Visibility::Invisible: return "invisible";
  case Visibility::Visible: return "visible";
  case Visibility::Undecided: return "undecided";
  }
  return "?";
}

std::vector<PatchEdgeRef> flaggedPatchEdges(const Report& report) {
  std::vector<PatchEdgeRef> out;
  for (const Finding& f : report.findings) {
    if (f.classification == Classification::Match) continue;
    out.push_back({f.a.patch.index, f.a.edge});
    out.push_back({f.b.patch.index, f.b.edge});
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

} // namespace fftess::verify
