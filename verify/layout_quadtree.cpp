// layout.kind = "quadtree", the camera-independent part (verify/internal.h, layout_quadtree.h): the node pyramid,
// prepared once per scene. Every lattice vertex's flat corner, texture coordinate and height is computed once, and
// every node's LOD height bounds, hole-check box and (lod.reconstruction = "resampled") rebuilt-corner heights; a
// camera's layout (layout_quadtree_select.cpp) only reads them. docs/verify.md, "Quadtree".
#include "verify/layout_quadtree.h"

#include <cstdio>

namespace fftess::verify::detail {

namespace {

// The lattice: extent, vertex positions (layout.corners), texture coordinates and heights.
//   shared:        x = float(minX + double(i) * unit), i the global lattice index (as layout.cpp's shared grid);
//   reconstructed: per root, ox = float(minX + double(rootX * 2^depth) * unit) and
//                  x = float(float(i) / float(2^depth)) * root_size + ox, two float roundings (product, then sum),
//                  i the index inside the root: the NVIDIA sample's per-tile rebuild with the root as the tile
//                  (neighbouring roots may disagree in the last bit where they meet).
// The same for z. Heights sampled once per vertex (heightAt).
bool buildLattice(TerrainData& t, QuadtreeNodes& q, std::string& error) {
  const Layout& L = t.scene.layout;
  const double unit = double(L.rootSize) / double(q.side);
  t.unit = unit;
  t.unitsX = q.rootsX * q.side;
  t.unitsZ = q.rootsZ * q.side;
  const double minX = L.centerX - 0.5 * double(t.unitsX) * unit, minZ = L.centerZ - 0.5 * double(t.unitsZ) * unit;
  t.extent.minX = static_cast<float>(minX);
  t.extent.minZ = static_cast<float>(minZ);
  t.extent.maxX = static_cast<float>(minX + double(t.unitsX) * unit);
  t.extent.maxZ = static_cast<float>(minZ + double(t.unitsZ) * unit);
  t.invSizeX = 1.0f / (t.extent.maxX - t.extent.minX);
  t.invSizeZ = 1.0f / (t.extent.maxZ - t.extent.minZ);
  if (!geometryFits(t.scene, unit, minX, minZ, t, error)) return false;
  q.vertexRow = q.sharedCorners ? t.unitsX + 1 : q.side + 1;
  const int64_t count = q.sharedCorners ? (t.unitsX + 1) * (t.unitsZ + 1) : q.rootsX * q.rootsZ * (q.side + 1) * (q.side + 1);
  for (std::vector<float>* v : {&q.x, &q.z, &q.tu, &q.tv, &q.height}) v->assign(static_cast<size_t>(count), 0.0f);
  const bool displaced = t.scene.displacement.kind != DisplacementKind::None;
  const float sideF = static_cast<float>(q.side);
  for (int root = 0; root < q.rootsX * q.rootsZ; ++root) {
    const int64_t rx = (root % q.rootsX) * q.side, rz = (root / q.rootsX) * q.side;
    const float ox = static_cast<float>(minX + double(rx) * unit), oz = static_cast<float>(minZ + double(rz) * unit);
    for (int64_t j = 0; j <= q.side; ++j)
      for (int64_t i = 0; i <= q.side; ++i) {
        const size_t v = static_cast<size_t>(q.vertex(root, i, j));
        if (q.sharedCorners) {
          if (root > 0 && ((i == 0 && rx > 0) || (j == 0 && rz > 0))) continue; // the root before set it
          q.x[v] = static_cast<float>(minX + double(rx + i) * unit);
          q.z[v] = static_cast<float>(minZ + double(rz + j) * unit);
        } else {
          q.x[v] = static_cast<float>(i) / sideF * L.rootSize + ox;
          q.z[v] = static_cast<float>(j) / sideF * L.rootSize + oz;
        }
        q.tu[v] = (q.x[v] - t.extent.minX) * t.invSizeX;
        q.tv[v] = (q.z[v] - t.extent.minZ) * t.invSizeZ;
        if (displaced) q.height[v] = heightAt(t, q.x[v], q.z[v], t.work);
      }
  }
  return true;
}

// The lattice vertex of corner c (u + 2v) of node k, in its root's lattice coordinates.
void cornerLattice(const QuadtreeNodes& q, const NodeKey& k, int c, int64_t& i, int64_t& j) {
  const int64_t s = int64_t(1) << k.level;
  i = (int64_t(k.ix) + (c & 1)) * s;
  j = (int64_t(k.iz) + (c >> 1)) * s;
  (void)q;
}

// lod.reconstruction = "resampled": the height at the corner node k rebuilds across edge e (lod::rebuiltCorner of
// its raised corners, odd = its parity along the edge, as prepareNeighbours sets it where a node twice its size lies
// across), sampled once here. The rebuilt corner is the far end of the parent's edge; where its x/z bits equal that
// lattice vertex's, the vertex's height is taken (the same inputs: the same sample).
void rebuiltHeights(TerrainData& t, QuadtreeNodes& q, const NodeKey& k, const TerrainPatch& p, NodeBounds& b) {
  const int64_t s = int64_t(1) << k.level;
  const int64_t gx = (k.root % q.rootsX) * q.side + int64_t(k.ix) * s, gz = (k.root / q.rootsX) * q.side + int64_t(k.iz) * s;
  for (int e = 0; e < 4; ++e) {
    const bool border = (e == Ueq0 && gx == 0) || (e == Veq0 && gz == 0) || (e == Ueq1 && gx + s == t.unitsX) ||
                        (e == Veq1 && gz + s == t.unitsZ);
    if (border || k.level >= q.depth) continue; // no node twice the size across
    const bool alongX = e == Veq0 || e == Veq1;
    const bool odd = ((alongX ? k.ix : k.iz) & 1) != 0;
    const int c0 = kEdgeCorners[e][0], c1 = kEdgeCorners[e][1];
    const glm::vec3 c = lod::rebuiltCorner(p.lod.corners[c0], p.lod.corners[c1], odd);
    int64_t i0, j0, i1, j1;
    cornerLattice(q, k, c0, i0, j0);
    cornerLattice(q, k, c1, i1, j1);
    const int64_t fi = odd ? 2 * i0 - i1 : 2 * i1 - i0, fj = odd ? 2 * j0 - j1 : 2 * j1 - j0;
    const size_t v = static_cast<size_t>(q.vertex(k.root, fi, fj));
    b.rebuiltHeight[e] = c.x == q.x[v] && c.z == q.z[v] ? q.height[v] : heightAt(t, c.x, c.z, t.work);
  }
}

// Every node: corners from the lattice (refused when they do not fit in float), LOD height bounds, hole-check box,
// rebuilt heights.
bool prepareNodes(TerrainData& t, QuadtreeNodes& q, std::string& error) {
  q.bounds.assign(static_cast<size_t>(q.nodeCount()), NodeBounds{});
  TerrainPatch p;
  float heights[4];
  for (int root = 0; root < q.rootsX * q.rootsZ; ++root)
    for (int level = q.depth; level >= 0; --level) {
      const int32_t n = static_cast<int32_t>(q.side >> level);
      for (int32_t iz = 0; iz < n; ++iz)
        for (int32_t ix = 0; ix < n; ++ix) {
          const NodeKey k{root, level, ix, iz};
          nodePatch(t, q, k, static_cast<int>(q.id(k)), p, heights);
          if (level == 0 && !patchCornersFit(t.scene, p, error)) return false;
          NodeBounds& b = q.bounds[static_cast<size_t>(q.id(k))];
          patchHeightBounds(t.scene, p);
          patchSurfaceBounds(t.scene.displacement, p);
          b.minHeight = p.lod.minHeight;
          b.maxHeight = p.lod.maxHeight;
          b.surfaceMinY = p.surfaceMinY;
          b.surfaceMaxY = p.surfaceMaxY;
          if (q.resampled) rebuiltHeights(t, q, k, p, b);
        }
    }
  return true;
}

} // namespace

void nodePatch(const TerrainData& t, const QuadtreeNodes& q, const NodeKey& k, int leafIndex, TerrainPatch& p,
               float heights[4]) {
  const Scene& s = t.scene;
  const bool raise = s.lod.displacedCorners && s.displacement.kind != DisplacementKind::None;
  p = TerrainPatch{};
  p.ref.index = leafIndex;
  p.ref.ring = 0;
  p.ref.tile = k.root;
  p.ref.patch = static_cast<int>(q.id(k));
  p.ref.level = k.level;
  p.size = int64_t(1) << k.level;
  p.ux = (k.root % q.rootsX) * q.side + int64_t(k.ix) * p.size;
  p.uz = (k.root / q.rootsX) * q.side + int64_t(k.iz) * p.size;
  for (int c = 0; c < 4; ++c) {
    int64_t i, j;
    cornerLattice(q, k, c, i, j);
    const size_t v = static_cast<size_t>(q.vertex(k.root, i, j));
    p.corners[c] = glm::vec3(q.x[v], 0.0f, q.z[v]);
    p.tex[c][0] = q.tu[v];
    p.tex[c][1] = q.tv[v];
    heights[c] = q.height[v];
    p.lod.corners[c] = glm::vec3(q.x[v], raise ? q.height[v] : 0.0f, q.z[v]);
  }
  if (q.bounds.empty()) return; // being prepared
  const NodeBounds& b = q.bounds[static_cast<size_t>(p.ref.patch)];
  p.lod.useHeightBounds = s.displacement.kind != DisplacementKind::None;
  p.lod.minHeight = b.minHeight;
  p.lod.maxHeight = b.maxHeight;
  p.surfaceMinY = b.surfaceMinY;
  p.surfaceMaxY = b.surfaceMaxY;
}

bool prepareQuadtree(TerrainData& t, std::string& error) {
  const Scene& s = t.scene;
  const Displacement& d = s.displacement;
  if (d.kind != DisplacementKind::None &&
      (!d.texels || d.texWidth < 1 || d.texHeight < 1 || d.texels->size() != size_t(d.texWidth) * d.texHeight)) {
    error = "displacement: texture not loaded (use loadScene / parseScene)";
    return false;
  }
  auto q = std::make_shared<QuadtreeNodes>();
  const Layout& L = s.layout;
  q->depth = L.maxDepth;
  q->rootsX = L.rootsX;
  q->rootsZ = L.rootsZ;
  q->side = int64_t(1) << L.maxDepth;
  q->perRoot = 0;
  for (int level = L.maxDepth; level >= 0; --level) {
    q->levelOffset[level] = q->perRoot;
    q->perRoot += (q->side >> level) * (q->side >> level);
  }
  q->sharedCorners = L.corners == CornerMode::Shared;
  q->resampled = s.lod.displacedCorners && d.kind != DisplacementKind::None &&
                 s.lod.screenSphere.reconstruction == lod::Reconstruction::Resampled;
  t.adjacency = L.maxDepth >= 1;
  if (!buildLattice(t, *q, error) || !prepareNodes(t, *q, error)) return false;
  t.quadtree = std::move(q);
  // The scene camera's leaves (Terrain::patches()); the selection's work is the build's.
  cameraLayout(t, s.camera, t, t.work);
  t.selection.reset(); // the prepared terrain keeps no per-camera scratch
  return true;
}

} // namespace fftess::verify::detail
