// Whole-mesh check: full tessellation of every drawn patch -> polygon soup -> exactly-equal points merged ->
// degenerate polygons removed -> Surface_mesh -> border edges (CGAL Polygon Mesh Processing). Border edges on the
// terrain's outer boundary (or beside a culled patch, which the edge check skips too) are not cracks.
#include "verify/mesh_check.h"
#include "verify/internal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <map>
#include <unordered_map>

namespace fftess::verify {

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

struct Key {
  float x, y, z;
  bool operator<(const Key& o) const {
    if (x != o.x) return x < o.x;
    if (y != o.y) return y < o.y;
    return z < o.z;
  }
};

// Patch edges a domain point lies on, as a bit mask over FactorIndex.
unsigned edgeMask(const DomainPoint& d) {
  unsigned m = 0;
  if (d.u == 0.0f) m |= 1u << Ueq0;
  if (d.u == 1.0f) m |= 1u << Ueq1;
  if (d.v == 0.0f) m |= 1u << Veq0;
  if (d.v == 1.0f) m |= 1u << Veq1;
  return m;
}

} // namespace

MeshReport checkSceneMesh(const Terrain& terrain, const Camera& camera, const CheckOptions& options) {
  MeshReport rep;
  if (!detail::validateCamera(camera, rep.error)) return rep;
  const Terrain view = layoutFor(terrain, camera); // the camera's own patches for a quadtree
  const detail::TerrainData& t = view.data();
  // Every drawn patch tessellated fully and positioned (view_mesh.h): the polygon soup.
  const ViewMesh vm = detail::buildViewMesh(t, camera, options);
  rep.work = vm.work;
  if (!vm.error.empty()) {
    rep.error = vm.error;
    return rep;
  }
  const size_t n = t.patches.size();
  std::vector<char> drawn(n, 0);
  for (size_t i = 0; i < n; ++i) drawn[i] = vm.drawnAt[i] >= 0;
  rep.patchesDrawn = static_cast<int64_t>(vm.patches.size());
  struct EdgeVertex {
    int patch;
    unsigned mask;  // the patch edges the point lies on
    DomainPoint d;  // its domain point on that patch
  };
  std::map<Key, std::vector<EdgeVertex>> where; // edge points -> where they came from
  std::vector<Point> points;
  points.reserve(vm.points.size());
  for (const glm::vec3& w : vm.points) points.emplace_back(w.x, w.y, w.z);
  std::vector<std::vector<std::size_t>> polygons;
  for (const ViewPatch& vp : vm.patches) {
    for (uint32_t k = vp.firstPoint; k < vp.firstPoint + vp.pointCount; ++k) {
      const glm::vec3& w = vm.points[k];
      if (unsigned m = edgeMask(vm.domain[k])) where[Key{w.x, w.y, w.z}].push_back({vp.ref.index, m, vm.domain[k]});
    }
    for (uint32_t k = vp.firstIndex; k + 2 < vp.firstIndex + vp.indexCount; k += 3)
      polygons.push_back({vm.indices[k], vm.indices[k + 1], vm.indices[k + 2]});
  }
  if (polygons.empty()) return rep;
  ++rep.work.cgalCalls;

  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  PMP::repair_polygon_soup(points, polygons); // drops polygons with a repeated vertex (zero-area duplicates)
  rep.triangles = static_cast<int64_t>(polygons.size());
  rep.vertices = static_cast<int64_t>(points.size());
  PMP::orient_polygon_soup(points, polygons);
  Mesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

  std::vector<Mesh::Halfedge_index> border;
  PMP::border_halfedges(faces(mesh), mesh, std::back_inserter(border));
  rep.borderEdges = static_cast<int64_t>(border.size());

  // A border segment [t0, t1] (edge parameter) on edge e of a patch is a crack or T-junction only where the
  // patch across is drawn: the edge check skips pairs with a culled side, per pair. Beside two half-size neighbours
  // each covers half of the edge (in the edge parameter, as the edge check splits it): the segment counts when a
  // drawn neighbour's half overlaps it (a segment over the middle of the edge beside one drawn half is a finding
  // of that half: the small side's corner at the middle is no vertex of the big side); within a culled half, it
  // does not (that half is not drawn: the edge check skips that pair too).
  auto acrossDrawn = [&](int patch, int e, float t0, float t1) {
    const detail::TerrainPatch& A = t.patches[static_cast<size_t>(patch)];
    const auto& nb = A.nb[e];
    if (nb[0] < 0) return false; // outer boundary
    if (nb[1] < 0) return drawn[static_cast<size_t>(nb[0])] != 0;
    const float lo = std::fmin(t0, t1), hi = std::fmax(t0, t1);
    for (int q : nb) {
      const detail::TerrainPatch& B = t.patches[static_cast<size_t>(q)];
      const bool alongX = e == Veq0 || e == Veq1;
      const float halfLo = (alongX ? B.ux - A.ux : B.uz - A.uz) == 0 ? 0.0f : 0.5f;
      if (drawn[static_cast<size_t>(q)] && lo < halfLo + 0.5f && hi > halfLo) return true;
    }
    return false;
  };
  for (auto h : border) {
    const Point& p = mesh.point(mesh.source(h));
    const Point& q = mesh.point(mesh.target(h));
    const Key kp{static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
    const Key kq{static_cast<float>(q.x()), static_cast<float>(q.y()), static_cast<float>(q.z())};
    auto ip = where.find(kp), iq = where.find(kq);
    bool inner = false;
    if (ip != where.end() && iq != where.end()) {
      for (const EdgeVertex& a : ip->second)
        for (const EdgeVertex& b : iq->second) {
          if (a.patch != b.patch) continue;
          const unsigned common = a.mask & b.mask;
          for (int e = 0; e < 4; ++e)
            if ((common >> e) & 1u) {
              const bool alongU = e == Veq0 || e == Veq1; // the edge's parameter is u, else v
              if (!acrossDrawn(a.patch, e, alongU ? a.d.u : a.d.v, alongU ? b.d.u : b.d.v)) continue;
              inner = true;
              rep.flagged.push_back({a.patch, e});
            }
        }
    }
    if (inner) ++rep.innerBorderEdges;
  }
  std::sort(rep.flagged.begin(), rep.flagged.end());
  rep.flagged.erase(std::unique(rep.flagged.begin(), rep.flagged.end()), rep.flagged.end());
  return rep;
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
