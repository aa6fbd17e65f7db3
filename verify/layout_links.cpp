// Neighbours of a layout's patches and the LOD's neighbour inputs: the links from the integer lattice (any layout of
// squares at integer base-unit positions whose edges nest), the lists of the fixed layouts, and the sizes, parity,
// far corners and rebuilt heights lod/'s neighbour rule reads.
#include "verify/internal.h"

#include <algorithm>
#include <cstdio>

namespace fftess::verify::detail {

namespace {

// One side of a grid line: a patch edge lying on the line, covering [lo, hi) along it.
struct LineSide {
  int64_t line, lo, hi;
  int32_t patch;
  bool operator<(const LineSide& o) const { return line != o.line ? line < o.line : lo < o.lo; }
};

// A link found: edge e of patch `patch` meets `other`, whose part of the edge starts at lo.
struct Link {
  int32_t patch;
  int8_t edge;
  int64_t lo;
  int32_t other;
  bool operator<(const Link& o) const {
    return patch != o.patch ? patch < o.patch : edge != o.edge ? edge < o.edge : lo < o.lo;
  }
};

std::string overlapMessage(const TerrainData& t, int32_t a, int32_t b, const char* what) {
  const TerrainPatch& A = t.patches[static_cast<size_t>(a)];
  const TerrainPatch& B = t.patches[static_cast<size_t>(b)];
  // layout.kind = "patches": the file's lines first (patch i is the file's i-th patch).
  const Layout& L = t.scene.layout;
  std::string where;
  if (L.kind == LayoutKind::Patches && L.patchList && size_t(std::max(a, b)) < L.patchList->size())
    where = L.file + ":" + std::to_string((*L.patchList)[size_t(a)].line) + " and line " +
            std::to_string((*L.patchList)[size_t(b)].line) + ": ";
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "patches %d (x %.9g, z %.9g, size %.9g) and %d (x %.9g, z %.9g, size %.9g) %s", a,
                double(A.corners[0].x), double(A.corners[0].z), double(A.corners[1].x - A.corners[0].x), b,
                double(B.corners[0].x), double(B.corners[0].z), double(B.corners[1].x - B.corners[0].x), what);
  return where + buf;
}

// The links across the lines of one axis: low holds the edges whose patch lies below the line (its +x or +z edge,
// lowEdge), high the edges whose patch lies above it (highEdge). Both sorted.
bool linkAxis(const TerrainData& t, const std::vector<LineSide>& low, const std::vector<LineSide>& high, int lowEdge,
              int highEdge, std::vector<Link>& links, std::string& error) {
  for (const std::vector<LineSide>* v : {&low, &high})
    for (size_t i = 1; i < v->size(); ++i)
      if ((*v)[i].line == (*v)[i - 1].line && (*v)[i].lo < (*v)[i - 1].hi) {
        error = overlapMessage(t, (*v)[i - 1].patch, (*v)[i].patch, "overlap");
        return false;
      }
  size_t j0 = 0;
  for (const LineSide& a : low) {
    while (j0 < high.size() && (high[j0].line < a.line || (high[j0].line == a.line && high[j0].hi <= a.lo))) ++j0;
    for (size_t j = j0; j < high.size() && high[j].line == a.line && high[j].lo < a.hi; ++j) {
      const LineSide& b = high[j];
      const int64_t lo = std::max(a.lo, b.lo), hi = std::min(a.hi, b.hi);
      const bool nested = (lo == a.lo && hi == a.hi) || (lo == b.lo && hi == b.hi);
      if (!nested) {
        error = overlapMessage(t, a.patch, b.patch, "share part of an edge without one edge containing the other "
                                                    "(edges must nest: one patch of the same or a larger size, or "
                                                    "several smaller ones, across each edge)");
        return false;
      }
      links.push_back({a.patch, static_cast<int8_t>(lowEdge), b.lo, b.patch});
      links.push_back({b.patch, static_cast<int8_t>(highEdge), a.lo, a.patch});
    }
  }
  return true;
}

} // namespace

bool linkLattice(TerrainData& t, std::string& error) {
  std::vector<LineSide> lowX, highX, lowZ, highZ;
  const size_t n = t.patches.size();
  lowX.reserve(n);
  highX.reserve(n);
  lowZ.reserve(n);
  highZ.reserve(n);
  for (const TerrainPatch& p : t.patches) {
    const int32_t i = p.ref.index;
    lowX.push_back({p.ux + p.size, p.uz, p.uz + p.size, i});  // its Ueq1 (+x) edge
    highX.push_back({p.ux, p.uz, p.uz + p.size, i});          // its Ueq0 (-x) edge
    lowZ.push_back({p.uz + p.size, p.ux, p.ux + p.size, i});  // its Veq1 (+z) edge
    highZ.push_back({p.uz, p.ux, p.ux + p.size, i});          // its Veq0 (-z) edge
  }
  for (std::vector<LineSide>* v : {&lowX, &highX, &lowZ, &highZ}) std::sort(v->begin(), v->end());
  std::vector<Link> links;
  links.reserve(4 * n);
  if (!linkAxis(t, lowX, highX, Ueq1, Ueq0, links, error) || !linkAxis(t, lowZ, highZ, Veq1, Veq0, links, error))
    return false;
  std::sort(links.begin(), links.end());
  t.neighbourList.clear();
  t.neighbourList.reserve(links.size());
  size_t k = 0;
  for (TerrainPatch& p : t.patches)
    for (int e = 0; e < 4; ++e) {
      p.nbFirst[e] = static_cast<int32_t>(t.neighbourList.size());
      while (k < links.size() && links[k].patch == p.ref.index && links[k].edge == e)
        t.neighbourList.push_back(links[k++].other);
      p.nbCount[e] = static_cast<int32_t>(t.neighbourList.size()) - p.nbFirst[e];
      p.nb[e][0] = p.nbCount[e] > 0 ? t.neighbourList[static_cast<size_t>(p.nbFirst[e])] : -1;
      p.nb[e][1] = p.nbCount[e] > 1 ? t.neighbourList.back() : -1;
    }
  return true;
}

void listEndNeighbours(TerrainData& t) {
  t.neighbourList.clear();
  for (TerrainPatch& p : t.patches)
    for (int e = 0; e < 4; ++e) {
      p.nbFirst[e] = static_cast<int32_t>(t.neighbourList.size());
      for (int k = 0; k < 2; ++k)
        if (p.nb[e][k] >= 0) t.neighbourList.push_back(p.nb[e][k]);
      p.nbCount[e] = static_cast<int32_t>(t.neighbourList.size()) - p.nbFirst[e];
    }
}

// Each edge's neighbour size relative to the patch: one neighbour: its size ratio (1, 2, 4, ...; a single smaller
// one: 0.5, 0.25, ...); several (all smaller): the smallest one's. Parity from the lattice (ux / size), or, where a
// neighbour twice the size lies across an edge, from where the patch sits on that neighbour's edge. 2x neighbours
// also get the far corner and (lod.reconstruction = "resampled" with raised corners) the rebuilt corner's height.
void prepareNeighbours(TerrainData& t, bool sampleRebuilt) {
  const Scene& s = t.scene;
  const bool raise = s.lod.displacedCorners && s.displacement.kind != DisplacementKind::None;
  const bool resample =
      sampleRebuilt && raise && s.lod.screenSphere.reconstruction == lod::Reconstruction::Resampled;
  for (TerrainPatch& p : t.patches) {
    lod::TileNeighbours& tn = p.tile;
    tn = lod::TileNeighbours{};
    tn.oddU = ((p.ux / p.size) & 1) != 0;
    tn.oddV = ((p.uz / p.size) & 1) != 0;
    for (int e = 0; e < 4; ++e) {
      if (p.nbCount[e] == 0) continue; // outer border
      const bool alongX = e == Veq0 || e == Veq1;
      double ratio = 0;
      for (const int32_t* q = t.neighboursBegin(p, e); q != t.neighboursEnd(p, e); ++q) {
        const double r = double(t.patches[static_cast<size_t>(*q)].size) / double(p.size);
        ratio = ratio == 0 ? r : std::min(ratio, r);
      }
      tn.size[e] = static_cast<float>(ratio);
      if (ratio == 2.0) {
        const TerrainPatch& q = t.patches[static_cast<size_t>(p.nb[e][0])];
        const int64_t lo = alongX ? p.ux : p.uz, qlo = alongX ? q.ux : q.uz;
        (alongX ? tn.oddU : tn.oddV) = qlo != lo;
      }
    }
    for (int e = 0; e < 4; ++e) {
      if (tn.size[e] != 2.0f) continue;
      const TerrainPatch& q = t.patches[static_cast<size_t>(p.nb[e][0])];
      // The far end of the larger neighbour's edge: its corner on the shared edge not shared with us.
      const int oe = kOpposite[e];
      const bool alongX = e == Veq0 || e == Veq1;
      const bool odd = alongX ? tn.oddU : tn.oddV;
      const bool second = (alongX ? q.ux != p.ux : q.uz != p.uz); // we are the second half of q's edge
      const int farIdx = second ? kEdgeCorners[oe][0] : kEdgeCorners[oe][1];
      tn.farCorner[e] = q.lod.corners[farIdx];
      // lod.reconstruction = "resampled": the height the vertex shader would sample at the corner the small side
      // rebuilds by the edge vector (lod::rebuiltCorner, the shader's own function, so the x/z bits agree).
      if (resample) {
        const glm::vec3 c = lod::rebuiltCorner(p.lod.corners[kEdgeCorners[e][0]], p.lod.corners[kEdgeCorners[e][1]], odd);
        tn.rebuiltHeight[e] = heightAt(t, c.x, c.z, t.work);
      }
    }
  }
}

} // namespace fftess::verify::detail
