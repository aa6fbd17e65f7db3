// layout.kind = "quadtree", per camera (verify/internal.h cameraLayout): the camera's leaves selected from the
// prepared node pyramid (layout_quadtree.cpp), balanced 2:1 when asked, linked by a walk of the tree, with the LOD's
// neighbour inputs from the prepared heights. No height is sampled here, and a warm scratch allocates nothing.
// docs/verify.md, "Quadtree".
#include "verify/layout_quadtree.h"

#include <atomic>
#include <cmath>

namespace fftess::verify::detail {

// cameraLayout's per-thread scratch (TerrainData::selection). A node's mark is 2 * stamp when it is split for this
// camera, 2 * stamp + 1 when it is one of its leaves (then leafOf holds its index); anything else: not selected.
struct QuadtreeSelection {
  std::shared_ptr<const QuadtreeNodes> nodes; // the pyramid the marks are sized for
  uint32_t stamp = 0;
  std::vector<uint32_t> mark;
  std::vector<int32_t> leafOf;
  std::vector<std::vector<NodeKey>> levels; // per level: the nodes made leaves while selecting (some split later)
  std::vector<NodeKey> leaves;              // the camera's leaves in order (depth first, children z-then-x)
};

namespace {

std::atomic<uint64_t> gLayoutGeneration{0};

struct Selector {
  const TerrainData& t;
  const QuadtreeNodes& q;
  QuadtreeSelection& sel;
  WorkStats& work;
  glm::dvec3 eye;
  double pixelScale = 0; // screen_error: viewport height / (2 tan(fov_y / 2))

  bool isSplit(const NodeKey& k) const { return sel.mark[size_t(q.id(k))] == 2 * sel.stamp; }
  bool isLeaf(const NodeKey& k) const { return sel.mark[size_t(q.id(k))] == 2 * sel.stamp + 1; }

  // The squared distance from the eye to node k's box: x/z from its corners, y from its surface bounds (the texels
  // its footprint reads, times height_scale; [0, 0] on flat terrain). In double.
  double boxDistance2(const NodeKey& k) const {
    const int64_t s = int64_t(1) << k.level;
    const size_t v0 = size_t(q.vertex(k.root, int64_t(k.ix) * s, int64_t(k.iz) * s));
    const size_t v1 = size_t(q.vertex(k.root, int64_t(k.ix + 1) * s, int64_t(k.iz + 1) * s));
    const NodeBounds& b = q.bounds[size_t(q.id(k))];
    const double lo[3] = {q.x[v0], b.surfaceMinY, q.z[v0]};
    const double hi[3] = {q.x[v1], b.surfaceMaxY, q.z[v1]};
    const double e[3] = {eye.x, eye.y, eye.z};
    double d2 = 0;
    for (int a = 0; a < 3; ++a) {
      const double d = e[a] < lo[a] ? lo[a] - e[a] : e[a] > hi[a] ? e[a] - hi[a] : 0.0;
      d2 += d * d;
    }
    return d2;
  }

  // layout.split: distance (CDLOD): the box within lod_distance * ratio^(level - 1) (the product in double, one
  // multiplication per level); screen_error (chunked LOD): geometric_error * node size * pixelScale > max_pixel_error
  // * distance.
  bool splits(const NodeKey& k) const {
    const Layout& L = t.scene.layout;
    const double d2 = boxDistance2(k);
    if (L.split == QuadtreeSplit::Distance) {
      double range = L.lodDistance;
      for (int l = 1; l < k.level; ++l) range *= double(L.lodDistanceRatio);
      return d2 < range * range;
    }
    const double size = double(int64_t(1) << k.level) * t.unit;
    return double(L.geometricError) * size * pixelScale > double(L.maxPixelError) * std::sqrt(d2);
  }

  void makeLeafCandidate(const NodeKey& k) {
    sel.mark[size_t(q.id(k))] = 2 * sel.stamp + 1;
    sel.levels[size_t(k.level)].push_back(k);
  }
  void splitNode(const NodeKey& k) {
    sel.mark[size_t(q.id(k))] = 2 * sel.stamp;
    for (int c = 0; c < 4; ++c) makeLeafCandidate({k.root, k.level - 1, 2 * k.ix + (c & 1), 2 * k.iz + (c >> 1)});
  }

  void select(const NodeKey& k) {
    ++work.layoutNodes;
    if (k.level == 0 || !splits(k)) {
      makeLeafCandidate(k);
      return;
    }
    sel.mark[size_t(q.id(k))] = 2 * sel.stamp;
    for (int c = 0; c < 4; ++c) select({k.root, k.level - 1, 2 * k.ix + (c & 1), 2 * k.iz + (c >> 1)});
  }

  // The node of `level` holding lattice cell (gx, gz) of that level's global grid.
  NodeKey at(int level, int64_t gx, int64_t gz) const {
    const int64_t n = q.side >> level;
    return {static_cast<int32_t>((gz / n) * q.rootsX + gx / n), level, static_cast<int32_t>(gx % n),
            static_cast<int32_t>(gz % n)};
  }
  NodeKey parent(const NodeKey& k) const { return {k.root, k.level + 1, k.ix / 2, k.iz / 2}; }
  // Global grid position of k on its level; false when (gx + dx, gz + dz) is outside the terrain.
  bool across(const NodeKey& k, int e, NodeKey& out) const {
    const int64_t n = q.side >> k.level;
    int64_t gx = (k.root % q.rootsX) * n + k.ix, gz = (k.root / q.rootsX) * n + k.iz;
    gx += e == Ueq0 ? -1 : e == Ueq1 ? 1 : 0;
    gz += e == Veq0 ? -1 : e == Veq1 ? 1 : 0;
    if (gx < 0 || gz < 0 || gx >= n * q.rootsX || gz >= n * q.rootsZ) return false;
    out = at(k.level, gx, gz);
    return true;
  }

  void ensureSplit(const NodeKey& k) {
    if (isSplit(k)) return;
    ++work.layoutNodes;
    if (k.level < q.depth) ensureSplit(parent(k)); // makes k a leaf candidate
    splitNode(k);
  }

  // layout.balance = "2to1": finest level first, every leaf's edge neighbours at its own level must lie in a split
  // node two levels up (then the leaf across is at most one level coarser). A forced split only makes leaves of
  // coarser levels, which are visited later.
  void balance() {
    for (int level = 0; level + 2 <= q.depth; ++level) {
      std::vector<NodeKey>& list = sel.levels[size_t(level)];
      for (size_t i = 0; i < list.size(); ++i) {
        const NodeKey k = list[i];
        if (!isLeaf(k)) continue;
        ++work.layoutNodes;
        for (int e = 0; e < 4; ++e) {
          NodeKey n;
          if (!across(k, e, n)) continue;
          ensureSplit(parent(parent(n)));
        }
      }
    }
  }

  void collect(const NodeKey& k) {
    if (isSplit(k)) {
      for (int c = 0; c < 4; ++c) collect({k.root, k.level - 1, 2 * k.ix + (c & 1), 2 * k.iz + (c >> 1)});
      return;
    }
    sel.leafOf[size_t(q.id(k))] = static_cast<int32_t>(sel.leaves.size());
    sel.leaves.push_back(k);
  }

  // The leaves across edge e of leaf k, in order along the edge (ascending x or z), into t.neighbourList.
  void neighbours(const NodeKey& k, int e, std::vector<int32_t>& list) const {
    NodeKey n;
    if (!across(k, e, n)) return;
    while (!isLeaf(n) && !isSplit(n)) n = parent(n); // inside a larger leaf
    gather(n, kOpposite[e], list);
  }
  // Leaves of n along its edge `side`.
  void gather(const NodeKey& n, int side, std::vector<int32_t>& list) const {
    if (!isSplit(n)) {
      list.push_back(sel.leafOf[size_t(q.id(n))]);
      return;
    }
    const bool alongX = side == Veq0 || side == Veq1;
    const int fixed = side == Ueq1 || side == Veq1 ? 1 : 0;
    for (int a = 0; a < 2; ++a) {
      const int cx = alongX ? a : fixed, cz = alongX ? fixed : a;
      gather({n.root, n.level - 1, 2 * n.ix + cx, 2 * n.iz + cz}, side, list);
    }
  }
};

void copyPrepared(const TerrainData& prepared, TerrainData& out) {
  if (&out == &prepared || out.quadtree == prepared.quadtree) return;
  out.scene = prepared.scene;
  out.extent = prepared.extent;
  out.invSizeX = prepared.invSizeX;
  out.invSizeZ = prepared.invSizeZ;
  out.unitsX = prepared.unitsX;
  out.unitsZ = prepared.unitsZ;
  out.unit = prepared.unit;
  out.adjacency = prepared.adjacency;
  out.quadtree = prepared.quadtree;
}

QuadtreeSelection& scratch(TerrainData& out, const std::shared_ptr<const QuadtreeNodes>& nodes) {
  const QuadtreeNodes& q = *nodes;
  if (!out.selection) out.selection = std::make_shared<QuadtreeSelection>();
  QuadtreeSelection& sel = *out.selection;
  if (sel.nodes != nodes || sel.stamp >= 0x7ffffff0u) {
    sel.nodes = nodes;
    sel.stamp = 0;
    sel.mark.assign(size_t(q.nodeCount()), 0);
    sel.leafOf.assign(size_t(q.nodeCount()), -1);
    sel.levels.resize(size_t(q.depth) + 1);
  }
  ++sel.stamp;
  for (std::vector<NodeKey>& l : sel.levels) l.clear();
  sel.leaves.clear();
  return sel;
}

// The leaves as patches: corners, heights, bounds, links, the LOD's neighbour inputs.
void fillPatches(Selector& s, TerrainData& out) {
  const QuadtreeNodes& q = s.q;
  const size_t n = s.sel.leaves.size();
  out.patches.resize(n);
  out.geometry.resize(n);
  out.neighbourList.clear();
  for (size_t i = 0; i < n; ++i) {
    TerrainPatch& p = out.patches[i];
    nodePatch(out, q, s.sel.leaves[i], static_cast<int>(i), p, out.geometry[i].heights);
    out.geometry[i].ref = p.ref;
    for (int c = 0; c < 4; ++c) out.geometry[i].corners[c] = p.corners[c];
    for (int e = 0; e < 4; ++e) {
      p.nbFirst[e] = static_cast<int32_t>(out.neighbourList.size());
      s.neighbours(s.sel.leaves[i], e, out.neighbourList);
      p.nbCount[e] = static_cast<int32_t>(out.neighbourList.size()) - p.nbFirst[e];
      p.nb[e][0] = p.nbCount[e] > 0 ? out.neighbourList[size_t(p.nbFirst[e])] : -1;
      p.nb[e][1] = p.nbCount[e] > 1 ? out.neighbourList.back() : -1;
    }
  }
  if (!out.adjacency) return;
  prepareNeighbours(out, false);
  if (!q.resampled) return;
  for (TerrainPatch& p : out.patches)
    for (int e = 0; e < 4; ++e)
      if (p.tile.size[e] == 2.0f) p.tile.rebuiltHeight[e] = q.bounds[size_t(p.ref.patch)].rebuiltHeight[e];
}

} // namespace

void cameraLayout(const TerrainData& prepared, const Camera& camera, TerrainData& out, WorkStats& work) {
  const std::shared_ptr<const QuadtreeNodes> keep = prepared.quadtree; // out may be prepared itself
  const QuadtreeNodes& q = *keep;
  copyPrepared(prepared, out);
  QuadtreeSelection& sel = scratch(out, keep);
  Selector s{out, q, sel, work, glm::dvec3(camera.eye), 0};
  if (out.scene.layout.split == QuadtreeSplit::ScreenError) {
    const double fov = double(camera.fovY) * (3.14159265358979323846 / 180.0);
    s.pixelScale = double(camera.height) / (2.0 * std::tan(0.5 * fov));
  }
  for (int root = 0; root < q.rootsX * q.rootsZ; ++root) s.select({root, q.depth, 0, 0});
  if (out.scene.layout.balance == QuadtreeBalance::TwoToOne) s.balance();
  for (int root = 0; root < q.rootsX * q.rootsZ; ++root) s.collect({root, q.depth, 0, 0});
  fillPatches(s, out);
  out.layoutGeneration = ++gLayoutGeneration;
  ++work.layoutSelections;
}

} // namespace fftess::verify::detail
