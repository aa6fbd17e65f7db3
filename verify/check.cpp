// The edge check: for every pair of patches that share (part of) an edge, the edge's world-space vertices from
// both sides, compared exactly. Only the outer edges are tessellated (fftess::edgePoints).
#include "verify/internal.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fftess::verify::detail {

namespace {

bool sameBits(const glm::vec3& a, const glm::vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

} // namespace

const EdgePoints& EdgeCache::get(float factor, WorkStats& work) {
  uint32_t bits;
  std::memcpy(&bits, &factor, sizeof bits);
  auto it = map_.find(bits);
  if (it != map_.end()) return it->second;
  ++work.edgeQueries;
  return map_.emplace(bits, edgePoints(factor, partitioning_, stage_, options_)).first->second;
}

static bool allFinite(const glm::vec3* p, int n) {
  for (int i = 0; i < n; ++i)
    if (!finite(p[i])) return false;
  return true;
}

bool validateCamera(const Camera& c, std::string& error) {
  if (!finite(c.eye)) return error = "camera.eye: not finite", false;
  if (!finite(c.target)) return error = "camera.target: not finite", false;
  if (!finite(c.up)) return error = "camera.up: not finite", false;
  if (sameBits(c.eye, c.target)) return error = "camera.target: equals camera.eye", false;
  const double dx = double(c.target.x) - c.eye.x, dy = double(c.target.y) - c.eye.y, dz = double(c.target.z) - c.eye.z;
  const double cx = dy * c.up.z - dz * c.up.y, cy = dz * c.up.x - dx * c.up.z, cz = dx * c.up.y - dy * c.up.x;
  if (cx == 0 && cy == 0 && cz == 0) return error = "camera.up: parallel to the view direction", false;
  if (!(c.fovY > 0 && c.fovY < 180)) return error = "camera.fov_y: must be in (0, 180) degrees", false;
  if (!(c.nearZ > 0) || !std::isfinite(c.nearZ)) return error = "camera.near: must be > 0", false;
  if (!(c.farZ > c.nearZ) || !std::isfinite(c.farZ)) return error = "camera.far: must be > camera.near", false;
  if (c.width < 1) return error = "camera.width: must be >= 1", false;
  if (c.height < 1) return error = "camera.height: must be >= 1", false;
  return true;
}

Report checkTerrain(const TerrainData& t, const Camera& camera, const CheckOptions& options, EdgeCache& cache) {
  Report rep;
  cache.trim(); // no EdgePoints reference outlives a camera
  if (!validateCamera(camera, rep.error)) return rep;
  const size_t n = t.patches.size();
  rep.stats.patches = static_cast<int64_t>(n);

  std::vector<lod::PatchLod> factors;
  computeFactors(t, camera, factors, rep.work);
  const DomainCamera domainCam = domainCamera(t, factors);
  const lod::Camera lodCamera = toLodCamera(camera);

  std::vector<std::array<const EdgePoints*, 4>> ep(n);
  std::vector<char> culled(n, 0);
  for (size_t i = 0; i < n; ++i) {
    for (int e = 0; e < 4; ++e) {
      ep[i][e] = &cache.get(factors[i].factors[e], rep.work);
      if (ep[i][e]->culled) culled[i] = 1;
    }
    rep.stats.culledPatches += culled[i];
  }

  std::vector<glm::vec3> fullA, pb;
  std::vector<DomainPoint> domA;
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
          fullA.resize(pa.count);
          domA.resize(pa.count);
          for (int j = 0; j < pa.count; ++j) {
            domA[j] = edgeDomain(e, pa.param[j]);
            fullA[j] = evalDomain(t, A, domA[j].u, domA[j].v, domainCam.at(ia), rep.work);
          }
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
        while (first < pa.count && pa.param[first] < lo) ++first;
        while (last > first && pa.param[last - 1] > hi) --last;
        const int na = last - first;
        pb.resize(pbp.count);
        for (int j = 0; j < pbp.count; ++j) {
          const DomainPoint d = edgeDomain(eb, pbp.param[j]);
          pb[j] = evalDomain(t, B, d.u, d.v, domainCam.at(static_cast<size_t>(ib)), rep.work);
        }
        const glm::vec3* a = fullA.data() + first;
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
        if (!match) v = classifyExact(options.kernel, a, na, fullA.data(), pa.count, pb.data(), pbp.count);
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
          f.b.mismatchDomain = edgeDomain(eb, pbp.param[i]);
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
  detail::EdgeCache cache(scene.partitioning, scene.stage, options.tessellator);
  return detail::checkTerrain(terrain.data(), camera, options, cache);
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
