// The terrain as one camera draws it (view_mesh.h): every patch tessellated fully with its hull factors, each point
// positioned by the domain-shader emulation; fills for patches not drawn. The whole-mesh check (mesh_check.cpp)
// builds its polygon soup from the same mesh.
#include "verify/view_mesh.h"
#include "verify/internal.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace fftess::verify {

namespace detail {

namespace {

// Appends patch i tessellated with its factors (drawn: the tessellator's output is not empty).
void appendDrawn(const TerrainData& t, size_t i, const lod::PatchLod& lodOut, const PatchDomain* domain,
                 Tessellator& tess, const Options& tessOptions, ViewMesh& out) {
  Patch p;
  p.domain = Domain::Quad;
  p.partitioning = t.scene.partitioning;
  p.primitive = OutputPrimitive::TriangleCw;
  p.stage = t.scene.stage;
  std::memcpy(p.factors, lodOut.factors, sizeof p.factors);
  const int count = tess.tessellate(p, tessOptions);
  ++out.work.fullTessellations;
  if (count == 0) return;
  const TerrainPatch& tp = t.patches[i];
  ViewPatch vp;
  vp.ref = tp.ref;
  vp.size = glm::length(tp.corners[1] - tp.corners[0]);
  std::memcpy(vp.factors, lodOut.factors, sizeof vp.factors);
  vp.firstPoint = static_cast<uint32_t>(out.points.size());
  vp.firstIndex = static_cast<uint32_t>(out.indices.size());
  for (const DomainPoint& d : tess.points()) {
    out.points.push_back(evalDomain(t, tp, d.u, d.v, domain, out.work));
    out.domain.push_back(d);
  }
  for (const auto k : tess.indices()) out.indices.push_back(vp.firstPoint + static_cast<uint32_t>(k));
  vp.pointCount = static_cast<uint32_t>(out.points.size()) - vp.firstPoint;
  vp.indexCount = static_cast<uint32_t>(out.indices.size()) - vp.firstIndex;
  out.drawnAt[i] = static_cast<int>(out.patches.size());
  out.patches.push_back(vp);
}

// Appends a segs x segs grid over patch i's domain: u = a / segs, v = b / segs (float division), row by row (v
// outer), two triangles per quad: (u0 v0, u0 v1, u1 v0) and (u1 v0, u0 v1, u1 v1).
void appendFill(const TerrainData& t, size_t i, const PatchDomain* domain, int segs, ViewMesh& out) {
  const TerrainPatch& tp = t.patches[i];
  ViewPatch vp;
  vp.ref = tp.ref;
  vp.size = glm::length(tp.corners[1] - tp.corners[0]);
  vp.firstPoint = static_cast<uint32_t>(out.points.size());
  vp.firstIndex = static_cast<uint32_t>(out.indices.size());
  const float n = static_cast<float>(segs);
  for (int b = 0; b <= segs; ++b)
    for (int a = 0; a <= segs; ++a) {
      const DomainPoint d{static_cast<float>(a) / n, static_cast<float>(b) / n};
      out.points.push_back(evalDomain(t, tp, d.u, d.v, domain, out.work));
      out.domain.push_back(d);
    }
  const uint32_t row = static_cast<uint32_t>(segs) + 1;
  for (uint32_t b = 0; b < static_cast<uint32_t>(segs); ++b)
    for (uint32_t a = 0; a < static_cast<uint32_t>(segs); ++a) {
      const uint32_t p00 = vp.firstPoint + b * row + a, p10 = p00 + 1, p01 = p00 + row, p11 = p01 + 1;
      for (uint32_t k : {p00, p01, p10, p10, p01, p11}) out.indices.push_back(k);
    }
  vp.pointCount = static_cast<uint32_t>(out.points.size()) - vp.firstPoint;
  vp.indexCount = static_cast<uint32_t>(out.indices.size()) - vp.firstIndex;
  out.fills.push_back(vp);
}

} // namespace

ViewMesh buildViewMesh(const TerrainData& t, const Camera& camera, const CheckOptions& options,
                       const std::vector<int>& fill, int fillSegments) {
  ViewMesh out;
  if (!validateCamera(camera, out.error)) return out;
  std::vector<lod::PatchLod> factors;
  if (!computeFactorsFor(t, camera, options.factors.get(), factors, nullptr, out.work, out.error)) return out;
  const DomainCamera domainCam = domainCamera(t, factors);
  const size_t n = t.patches.size();
  out.drawnAt.assign(n, -1);
  Tessellator tess;
  const Options tessOptions = tessellatorOptions(t.scene, options); // the denormal rule (denormalRule)
  for (size_t i = 0; i < n; ++i) appendDrawn(t, i, factors[i], domainCam.at(i), tess, tessOptions, out);
  const int segs = std::clamp(fillSegments, 1, 256);
  for (int i : fill) {
    const size_t k = static_cast<size_t>(i);
    if (i >= 0 && k < n) appendFill(t, k, domainCam.at(k), segs, out);
  }
  return out;
}

} // namespace detail

ViewMesh viewMesh(const Terrain& terrain, const Camera& camera, const CheckOptions& options,
                  const std::vector<int>& fill, int fillSegments) {
  ViewMesh out;
  if (!detail::validateCamera(camera, out.error)) return out; // layoutFor needs a valid camera
  const Terrain view = layoutFor(terrain, camera); // the camera's own patches for a quadtree
  return detail::buildViewMesh(view.data(), camera, options, fill, fillSegments);
}

std::vector<glm::vec3> edgePolyline(const ViewMesh& mesh, int patch, int edge, float lo, float hi, bool cover) {
  std::vector<glm::vec3> out;
  if (patch < 0 || static_cast<size_t>(patch) >= mesh.drawnAt.size() || mesh.drawnAt[static_cast<size_t>(patch)] < 0)
    return out;
  const ViewPatch& vp = mesh.patches[static_cast<size_t>(mesh.drawnAt[static_cast<size_t>(patch)])];
  const bool alongU = edge == Veq0 || edge == Veq1; // the edge's parameter is u, else v
  const float fixed = edge == Ueq1 || edge == Veq1 ? 1.0f : 0.0f;
  std::vector<std::pair<float, uint32_t>> on; // (parameter, point) of every point on the edge
  for (uint32_t k = vp.firstPoint; k < vp.firstPoint + vp.pointCount; ++k) {
    const DomainPoint& d = mesh.domain[k];
    if ((alongU ? d.v : d.u) == fixed) on.emplace_back(alongU ? d.u : d.v, k);
  }
  std::sort(on.begin(), on.end());
  size_t first = 0, end = on.size();
  while (first < on.size() && on[first].first < lo) ++first;
  while (end > first && on[end - 1].first > hi) --end;
  if (cover) {
    if (first > 0 && (first == on.size() || on[first].first > lo)) --first;
    if (end < on.size() && (end == 0 || on[end - 1].first < hi)) ++end;
  }
  for (size_t k = first; k < end; ++k) out.push_back(mesh.points[on[k].second]);
  return out;
}

} // namespace fftess::verify
