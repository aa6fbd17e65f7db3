// fftess verify, stage 2: the prepared terrain (prepareTerrain). Everything about a scene that does not depend on
// the camera, computed once per scene: the layout's patches (uniform grid, NVIDIA tile rings, heightmap grid), their
// neighbours and corners, the corner heights, the LOD's height bounds, the sizes each patch sees across its edges and
// the far corners of larger neighbours, and the extent. Also the work counters (WorkStats) every later stage reports
// its work in.
#pragma once

#include "verify/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace fftess::verify {

// ---------------------------------------------------------------------------------------------------------------
// Work counters. Every function that does work reports it here, so that a test (or `fftess check --json`) can show
// that camera-independent work runs once per command and per-camera work is only the camera-dependent part.
struct WorkStats {
  int64_t terrainBuilds = 0;     // layouts built (prepareTerrain): 1 in Terrain::stats(), 0 in a camera's report
  int64_t heightSamples = 0;     // displacement texture samples (corner heights in Terrain::stats(); in a
                                 // camera's report only the domain shader's, one per displaced domain evaluation)
  int64_t domainEvaluations = 0; // domain-shader positions computed (edge points, mesh points)
  int64_t lodEvaluations = 0;    // lod/ calls (one per patch and camera; none for lod.scheme = "constant")
  int64_t edgeQueries = 0;       // fftess::edgePoints calls (the per-thread cache's misses)
  int64_t cgalCalls = 0;         // exact classifications of an edge pair, plus one per whole-mesh CGAL pipeline
  int64_t fullTessellations = 0; // whole patches tessellated (fftess::Tessellator; the whole-mesh check only)
  int64_t sharedEdgePoints = 0;  // edge points of a shared edge's second side that took the first side's height
                                 // (same flat x/z bits, height a function of x/z alone): neither a domain
                                 // evaluation nor a height sample
  int64_t visibilityEvaluations = 0; // domain evaluations of the hole check's grid (part of domainEvaluations):
                                 // culled or discarded patches whose box touches the view frustum (visibility.h, Hole)
  int64_t layoutSelections = 0; // camera-dependent layouts selected (layout.kind = "quadtree": one per camera
                                 // checked; 0 for static layouts)
  int64_t layoutNodes = 0;      // quadtree nodes visited by those selections (split tests and balance passes)
  // The sweep's shortcuts (docs/verify.md, "Sweep shortcuts"). Edge pairs decided without evaluating their points:
  int64_t cacheHits = 0;        // by the result cache: the same pair with the same two factor bits matched before
  int64_t seamHits = 0;         // by a seam proof: same-size sides with the same edge points (seam_proof.h)
  int64_t cacheMisses = 0;      // pairs the cache was asked about and did not know (classified, then stored on a match)
  int64_t seamProofs = 0;       // seam proofs made (once per shared edge and sweep, unless the cache dropped one)
  int64_t boxTests = 0;         // visible first: frustum tests of boxes (tree nodes, patches, pairs' joint boxes)
  WorkStats& operator+=(const WorkStats& o);
};

// Layouts built by prepareTerrain in this process so far (all threads). `fftess check --json` prints the count, so
// a test can see that one command builds one terrain.
int64_t terrainBuildCount();

// ---------------------------------------------------------------------------------------------------------------
// The prepared terrain: everything about the scene that does not depend on the camera, computed once.

// layout.kind = "quadtree": index is the leaf's place in this camera's list (depth first from the roots in row-major
// order, children -x-z, +x-z, -x+z, +x+z), ring 0, tile the root (row-major over roots_x x roots_z), patch the node's
// id in the prepared pyramid (the same node has the same id for every camera: root * nodes per root + the nodes of
// the coarser levels + row-major position on its level), level log2 of its size in leaves (0: a leaf of max_depth).
struct PatchRef {
  int index = -1;              // patch number in the layout's order
  int ring = 0;                // tile ring (0 for grids)
  int tile = 0;                // tile index in its ring (row-major over the ring's tile grid; 0 for grids)
  int patch = 0;               // patch index in its tile (row-major; grids: row-major over the grid)
  int level = 0;               // log2 of the patch size relative to the smallest patch
};

// One patch: its ref, its four flat corners (y = 0) exactly as the checker and the domain shader use them
// (layout.corners decides how they are computed), corners[u + 2v]: [0] (u0, v0), [1] (u1, v0), [2] (u0, v1),
// [3] (u1, v1); and the corner heights the vertex shader computes (displacement sampled at the corner's world x/z;
// 0 for displacement.kind = "none").
struct PatchGeometry {
  PatchRef ref;
  glm::vec3 corners[4];
  float heights[4] = {0, 0, 0, 0};
};

// Terrain extent in x/z: [minX, maxX] x [minZ, maxZ].
struct Extent {
  float minX = 0, minZ = 0, maxX = 0, maxZ = 0;
};

namespace detail {
struct TerrainData; // verify/internal.h
}
struct TerrainResult;
class Terrain;
TerrainResult prepareTerrain(const Scene& scene);

// Built by prepareTerrain; cheap to copy (shared, immutable). Holds its own copy of the scene. A default-constructed
// Terrain is empty (no patches) and must not be passed to the functions below.
class Terrain {
public:
  Terrain() = default;
  // The scene it was built from (its own copy; the texture shared).
  const Scene& scene() const;
  // Patches in the layout (> 0 for a built terrain).
  int patchCount() const;
  // One PatchGeometry per patch, in layout order: patches()[i] is patch i (PatchRef::index == i).
  const std::vector<PatchGeometry>& patches() const;
  // The x/z rectangle the patches cover (the displacement texture is spread over it).
  const Extent& extent() const;
  // The work of building it: terrainBuilds = 1, heightSamples = the corner heights sampled (4 per patch when
  // displaced, else 0; plus one per rebuilt corner with lod.reconstruction = "resampled" and raised corners; a
  // quadtree: one per lattice vertex, plus the rebuilt corners whose x/z are no vertex's, and the scene camera's
  // selection in layoutSelections / layoutNodes). Checking never adds to it.
  const WorkStats& stats() const;
  // The layout depends on the camera (layout.kind = "quadtree"): patches() are the scene camera's; layoutFor gives
  // any other camera's, and checkScene / sweep check each camera's own.
  bool cameraDependent() const;
  // Default-constructed (no patches): not to be checked.
  bool empty() const { return !data_; }
  // The prepared data itself (verify/internal.h): for verify's .cpp files, bench/ and cli/accuracy.cpp. Not empty().
  const detail::TerrainData& data() const { return *data_; }

private:
  friend TerrainResult prepareTerrain(const Scene& scene);
  friend Terrain layoutFor(const Terrain& terrain, const Camera& camera);
  std::shared_ptr<const detail::TerrainData> data_;
};

// Result of prepareTerrain: a terrain or an error message (the scene is invalid, e.g. built by hand without its
// displacement texture).
struct TerrainResult {
  bool ok = false;
  Terrain terrain;
  std::string error;
  explicit operator bool() const { return ok; }
};

// Builds the layout (patches, corners, neighbours, the sizes each patch sees across its edges and the far corners
// of its larger neighbours), samples every corner height once and fixes the LOD's height bounds.
// scene: from loadScene/parseScene (or built by hand: displacement.texels must be set unless kind is None).
TerrainResult prepareTerrain(const Scene& scene);

// The terrain as `camera` sees it: for a camera-dependent layout (Terrain::cameraDependent) a terrain that shares
// this one's prepared data (scene, texture, node pyramid) and holds the camera's patches, their corners, heights and
// neighbours (stats(): the selection's work, terrainBuilds = 0); for any other layout `terrain` itself. Patch
// indices in a report of checkScene(terrain, camera) are indices into layoutFor(terrain, camera).patches().
// terrain: built (not empty); camera: valid (validateCamera).
Terrain layoutFor(const Terrain& terrain, const Camera& camera);

// World position of domain point (u, v) of patch `patchIndex` as the scene's domain shader computes it.
// patchIndex: 0 .. terrain.patchCount() - 1 (else (0, 0, 0)). u, v in [0, 1].
glm::vec3 domainPosition(const Terrain& terrain, int patchIndex, float u, float v);

// A terrain's patches as a layout.kind = "patches" file (docs/verify.md, "Patches"; verify/layout_export.cpp), read
// back to the same patches in the same order with the same corner bits. Every number is the shortest decimal that
// reads back to the same float. layout: a static layout, or layoutFor's for a camera-dependent one.
// OBJ: a comment line per entry of `comments`, then "v x height z" once per distinct corner (its bits; the height
// the vertex shader samples there, ignored when read), then "f a b c d" per patch: corners[0], [2], [3], [1]
// (counter-clockwise seen from +y).
std::string layoutObj(const Terrain& layout, const std::vector<std::string>& comments = {});
// CSV: the header x0,z0,x1,z1,x2,z2,x3,z3, then one row per patch, corners[u + 2v] in that order.
std::string layoutCsv(const Terrain& layout);

} // namespace fftess::verify
