// Internal header of fftess_verify: layout.kind = "quadtree" (layout_quadtree.cpp prepares the node pyramid once per
// scene, layout_quadtree_select.cpp selects a camera's leaves from it). docs/verify.md, "Quadtree".
#pragma once

#include "verify/internal.h"

#include <cstdint>
#include <vector>

namespace fftess::verify::detail {

// A node: root index, level (0 = leaf size, depth = the root), position in its root's grid of that level.
struct NodeKey {
  int32_t root = 0;
  int32_t level = 0;
  int32_t ix = 0, iz = 0;
};

// What a node holds besides what its lattice vertices give (corners, texture coordinates, corner heights).
struct NodeBounds {
  float minHeight = 0, maxHeight = 0;     // lod.height_bounds (lod::Patch::minHeight / maxHeight)
  float surfaceMinY = 0, surfaceMaxY = 0; // the hole check's box (TerrainPatch::surfaceMinY / MaxY)
  float rebuiltHeight[4] = {0, 0, 0, 0};  // lod.reconstruction = "resampled": the height at the corner this node
                                          // rebuilds across edge e when a node twice its size lies there
};

// The camera-independent node pyramid (TerrainData::quadtree): every node of every root, prepared once per scene.
// Node ids (PatchRef::patch): root * perRoot + levelOffset[level] + iz * (side >> level) + ix; a root's levels are
// stored coarsest first (the root is its node 0).
struct QuadtreeNodes {
  int depth = 0;              // layout.max_depth
  int rootsX = 1, rootsZ = 1;
  int64_t side = 1;           // 2^depth: a root's side in base units (leaves)
  int64_t perRoot = 1;        // nodes per root: (4^(depth + 1) - 1) / 3
  int64_t levelOffset[11] = {};
  bool sharedCorners = true;  // layout.corners = "shared": one lattice over the extent; else one per root
  int64_t vertexRow = 0;      // vertices per lattice row
  // Per lattice vertex: flat x, z (float), texture coordinate, height (0 on flat terrain).
  std::vector<float> x, z, tu, tv, height;
  std::vector<NodeBounds> bounds; // per node id
  bool resampled = false;     // bounds' rebuiltHeight hold heights (lod.reconstruction = "resampled", raised corners)

  int64_t nodeCount() const { return perRoot * rootsX * rootsZ; }
  int64_t id(const NodeKey& k) const {
    return k.root * perRoot + levelOffset[k.level] + int64_t(k.iz) * (side >> k.level) + k.ix;
  }
  // The lattice vertex at (i, j) of root `root` (i, j in 0 .. side).
  int64_t vertex(int root, int64_t i, int64_t j) const {
    if (!sharedCorners) return root * (side + 1) * (side + 1) + j * (side + 1) + i;
    return (j + (root / rootsX) * side) * vertexRow + i + (root % rootsX) * side;
  }
};

// Node key's TerrainPatch as the camera's leaf: ref (index = leafIndex, ring 0, tile = root, patch = node id,
// level), ux, uz, size, corners, tex, lod corners and bounds, surface bounds; heights[4] get the corner heights.
// Neighbours and tile are left default.
void nodePatch(const TerrainData& t, const QuadtreeNodes& q, const NodeKey& k, int leafIndex, TerrainPatch& p,
               float heights[4]);

} // namespace fftess::verify::detail
