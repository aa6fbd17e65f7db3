// Internal header of fftess_verify (not installed, not part of the contract). No CGAL here.
#pragma once

#include "base/bits.h"
#include "verify/check.h" // and through it every stage header up to the check
#include "verify/result_cache.h"
#include "verify/view_mesh.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <deque>
#include <memory>
#include <vector>

namespace fftess::lod {
class BoundContext;
struct BoundCamera;
} // namespace fftess::lod

namespace fftess::verify::detail {

// ---------------------------------------------------------------------------------------------------------------
// heightfield.cpp

// Bakes a procedural generator (fbm / ridge) into texels; values in [0, 1].
std::vector<float> generateHeightfield(const Displacement& d);
// Reads a RAW heightmap; returns false with a message on a missing file or a wrong size.
bool readRawHeightmap(const std::string& path, int width, int height, int bits, std::vector<float>& out,
                      std::string& error);

// Bilinear sampling as a GPU sampler does it, clamp addressing. (tx, tz) in texture coordinates 0..1.
// Order of float operations:
//   s = tx * width - 0.5; i0 = floor(s); f = s - i0; f quantised to subtexelBits (round to nearest);
//   t = t0 + f * (t1 - t0) per row (x first), then across rows (z), each product and sum rounded to float.
float sampleBilinear(const Displacement& d, float tx, float tz);
// The same on mip level `level` (0 = d.texels, k >= 1 = (*d.mips)[k - 1]); level must exist.
float sampleBilinearLevel(const Displacement& d, int level, float tx, float tz);
// Trilinear sampling (displacement.mip): l = level clamped to [0, number of levels - 1] (NaN: 0); l0 = floor(l);
// f = l - l0, quantised to subtexelBits like the bilinear weights; h0 = bilinear on l0; f > 0: h1 = bilinear on
// l0 + 1 and h = h0 + f * (h1 - h0) (product and sum rounded separately); else h = h0.
float sampleTrilinear(const Displacement& d, float tx, float tz, float level);

// IEEE 754 binary16 (DXGI_FORMAT_R16_FLOAT), our own conversion: float -> half rounds to nearest, ties to even;
// overflow (|x| >= 65520) gives infinity, NaN stays NaN (quiet, sign and top payload bits kept); half -> float is
// exact.
uint16_t floatToHalf(float f);
float halfToFloat(uint16_t h);
// Applies displacement.format to texels (r16_float: each texel through floatToHalf and back).
void applyTexelFormat(TexelFormat format, std::vector<float>& texels);
// Box-filtered mip chain of a width x height texture, levels 1.. down to 1 x 1: level k + 1 has max(1, w / 2) x
// max(1, h / 2) texels (D3D's floor rule; an odd level's last row/column is not read), texel (i, j) =
// ((a + b) + (c + d)) * 0.25 with a = (2i, 2j), b = (2i + 1, 2j), c = (2i, 2j + 1), d = (2i + 1, 2j + 1) of the level
// above (an index past a 1-texel side is clamped), each level then put through `format` (a GPU stores R16 mips in
// half too).
std::vector<MipLevel> buildMipChain(const std::vector<float>& texels, int width, int height, TexelFormat format);

// ---------------------------------------------------------------------------------------------------------------
// layout.cpp: the prepared terrain.

struct QuadtreeNodes; // layout_quadtree.cpp
struct PatchTree;     // visible_first.cpp

struct TerrainPatch {
  PatchRef ref;
  int64_t ux = 0, uz = 0;       // lower corner in base units (smallest patch size) from the terrain's min corner
  int64_t size = 1;             // in base units (2^level)
  glm::vec3 corners[4];         // flat corners (y = 0), corners[u + 2v] (lod.h's convention)
  float tex[4][2];              // corner texture coordinates (domain.height_uv = interpolated)
  // Neighbours across each edge (FactorIndex order): the patch just across the edge's start and the one just across
  // its end (-1 where none; [1] is -1 when the same patch holds both ends).
  std::array<std::array<int, 2>, 4> nb{{{-1, -1}, {-1, -1}, {-1, -1}, {-1, -1}}};
  // Every neighbour across each edge, in order along the edge: TerrainData::neighbourList[nbFirst[e] ..
  // nbFirst[e] + nbCount[e]) (one of the same or a larger size, or several smaller ones; layouts nest edges).
  std::array<int32_t, 4> nbFirst{{0, 0, 0, 0}};
  std::array<int32_t, 4> nbCount{{0, 0, 0, 0}};
  lod::Patch lod;               // what lod/ sees: corners raised to their heights (lod.displaced_corners), bounds
  // Bounds of the true displaced surface's y (the texels the footprint samples, times height_scale, padded for
  // float rounding): the hole check's visibility box (visibility.h, Hole). [0, 0] on flat terrain.
  float surfaceMinY = 0, surfaceMaxY = 0;
  lod::TileNeighbours tile;     // tile rings with adjacency: sizes across each edge, parity, far corners
};

// The scene key that sets the patch size of its layout ("layout.base_patch_size", ...), for messages.
const char* patchSizeKey(const Scene& s);
// lod.height_bounds = "per_patch": the lowest and highest texel any bilinear sample of p's footprint can read, on
// every level the scene samples (0..1, before height_scale). Displacement must not be None.
void patchTexelRange(const Displacement& d, const TerrainPatch& p, float& lo, float& hi);
// What lod/ sees of every patch (corner heights sampled into t.geometry and p.lod, height bounds) and, with
// t.adjacency, prepareNeighbours. Needs the patches' corners, tex and links.
void prepareLod(TerrainData& t);
// Every patch's surfaceMinY / surfaceMaxY (the hole check's box).
void prepareSurfaceBounds(TerrainData& t);
// The same for one patch (p.tex set): prepareLod's height bounds (p.lod.useHeightBounds, minHeight, maxHeight, per
// lod.height_bounds; nothing on flat terrain) and prepareSurfaceBounds' box.
void patchHeightBounds(const Scene& s, TerrainPatch& p);
void patchSurfaceBounds(const Displacement& d, TerrainPatch& p);
// prepareTerrain's refusals of one patch's float corners: a non-finite corner (patchCornersFinite), or that and zero
// area (patchCornersFit, the error naming patchSizeKey).
bool patchCornersFinite(const TerrainPatch& p, std::string& error);
bool patchCornersFit(const Scene& s, const TerrainPatch& p, std::string& error);
// The terrain's float geometry must be finite and resolve every patch (patchWorld: a base unit's world size; minX,
// minZ: the extent's lower corner in double; t.extent, invSize*, units* set). False with error naming patchSizeKey.
bool geometryFits(const Scene& s, double patchWorld, double minX, double minZ, const TerrainData& t,
                  std::string& error);

struct TerrainData {
  Scene scene;
  std::vector<TerrainPatch> patches;
  std::vector<PatchGeometry> geometry; // the public view of patches
  Extent extent;
  float invSizeX = 1, invSizeZ = 1; // 1 / extent size, float
  int64_t unitsX = 0, unitsZ = 0;   // extent in base units
  double unit = 1;                  // world size of a base unit
  bool adjacency = false;           // patches of different sizes may meet (tile rings with rings > 1, quadtree,
                                    // patches with sizes that differ): the LOD's neighbour rule runs
  std::vector<int32_t> neighbourList; // TerrainPatch::nbFirst / nbCount index it
  // layout.kind = "quadtree": the camera-independent node pyramid (layout_quadtree.cpp), shared by every camera's
  // layout; patches then hold one camera's leaves (prepareTerrain: the scene camera's; cameraLayout: any camera's).
  std::shared_ptr<const QuadtreeNodes> quadtree;
  // Static layouts: the bounding-volume tree visible first walks (visible_first.cpp); null for quadtree layouts.
  std::shared_ptr<const PatchTree> tree;
  // cameraLayout's scratch (a per-thread layout reused from camera to camera: the selection's marks and lists).
  std::shared_ptr<struct QuadtreeSelection> selection;
  // Changes whenever cameraLayout puts another camera's patches here (0: a static layout), so that a consumer that
  // keeps something per terrain (gpu_lod's uploaded patch inputs, LodPatches::generation) sees the new patches.
  uint64_t layoutGeneration = 0;
  WorkStats work;                   // the build's work
  // The neighbours across edge e of p, in order along the edge.
  const int32_t* neighboursBegin(const TerrainPatch& p, int e) const { return neighbourList.data() + p.nbFirst[e]; }
  const int32_t* neighboursEnd(const TerrainPatch& p, int e) const {
    return neighbourList.data() + p.nbFirst[e] + p.nbCount[e];
  }
};

// ---------------------------------------------------------------------------------------------------------------
// layout_links.cpp: neighbours from the integer lattice (any layout whose patches are squares at integer base-unit
// positions with nesting edges: an edge meets one patch of the same or a larger size, or several smaller ones).

// Fills every patch's nb, nbFirst / nbCount and t.neighbourList from ux, uz and size (patches sorted along each
// grid line; O(n log n)). False with error naming the two patches when edges overlap without nesting or patches
// overlap (a "patches" layout refuses that; quadtree leaves never do).
bool linkLattice(TerrainData& t, std::string& error);
// Fills neighbourList / nbFirst / nbCount from nb (the end neighbours), for layouts whose edges meet at most two
// patches (grid, tile rings, heightmap grid).
void listEndNeighbours(TerrainData& t);
// The LOD's neighbour inputs of every patch from the links (TerrainPatch::tile: the size across each edge relative to
// the patch, 0.5 / 2 with the parity, far corner and rebuilt height lod/ reads, or the true ratio (4, 0.25, ...) where
// a jump exceeds 2x, which lod/ treats as 1: its neighbour rule handles 2x jumps). Samples rebuilt heights into
// t.work (lod.reconstruction = "resampled").
// sampleRebuilt false: rebuiltHeight is left 0 (the caller fills it from heights it sampled before: the quadtree).
void prepareNeighbours(TerrainData& t, bool sampleRebuilt = true);

// ---------------------------------------------------------------------------------------------------------------
// layout_quadtree.cpp: layout.kind = "quadtree".

// Builds the node pyramid (t.quadtree: every node's corners, heights, LOD bounds and surface bounds, sampled once)
// and selects the scene camera's leaves into t (cameraLayout). False with error naming the layout key.
bool prepareQuadtree(TerrainData& t, std::string& error);
// The layout camera `camera` sees: out becomes a copy of prepared's camera-independent state (scene, extent, node
// pyramid: shared, not copied once out holds them) with the camera's leaves as patches, linked, with their
// neighbour inputs. out is a scratch reused from camera to camera (no allocation once warm). Adds the selection's
// work to work (WorkStats::layoutNodes). prepared: a quadtree terrain.
void cameraLayout(const TerrainData& prepared, const Camera& camera, TerrainData& out, WorkStats& work);

// ---------------------------------------------------------------------------------------------------------------
// layout_patches.cpp: layout.kind = "patches".

// The patches of scene.layout.patchList on their integer lattice (the coordinates' common dyadic step), linked
// (linkLattice). False with error "FILE:LINE: what is wrong" for a patch that is not an axis-aligned square, patches
// that overlap or leave a gap inside their bounding rectangle, edges that meet without nesting.
bool buildPatchesLayout(const Scene& s, TerrainData& t, std::string& error);
// d = a - b in double, true when that is exact (TwoSum's error term is 0; false only for floats of magnitudes more
// than 2^28 apart). The patches file's sides and lattice are decided with it.
bool exactDifference(float a, float b, double& d);

// The same point, compared with == per component (+0 equals -0, NaN equals nothing): the check's "same bits" for
// points that are never NaN once finite() holds. finite: every component finite.
inline bool sameBits(const glm::vec3& a, const glm::vec3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }
inline bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Corner indices (lod.h convention) of each edge: Ueq0 = 0-2, Veq0 = 0-1, Ueq1 = 1-3, Veq1 = 2-3.
constexpr int kEdgeCorners[4][2] = {{0, 2}, {0, 1}, {1, 3}, {2, 3}};
constexpr int kOpposite[4] = {Ueq1, Veq1, Ueq0, Veq0};

// ---------------------------------------------------------------------------------------------------------------
// domain.cpp: the domain-shader emulation.

// Height of the displacement at world (x, z) as the vertex and domain shaders sample it (NVIDIA: texture
// coordinate from world x/z over the extent). Displacement must not be None. Adds one to work.heightSamples.
float heightAt(const TerrainData& t, float x, float z, WorkStats& work);
// World position of (u, v) on patch p. Adds one to work.domainEvaluations and, when displaced, work.heightSamples.
// camera: this camera's state of patch p (DomainCamera::at), nullptr for the camera-independent position (no
// geomorph, mip level 0). Geomorph adds the two heights an inserted vertex morphs between to work.heightSamples.
struct PatchDomain;
// The flat x/z of (u, v) as evalDomain computes them (y = 0), without the height; counts no work.
glm::vec3 flatDomain(const TerrainData& t, const TerrainPatch& p, float u, float v);
glm::vec3 evalDomain(const TerrainData& t, const TerrainPatch& p, float u, float v, const PatchDomain* camera,
                     WorkStats& work);

// ---------------------------------------------------------------------------------------------------------------
// lod_bridge.cpp: the scene's LOD settings -> lod/ calls, per camera.

// What the LOD sees: lod::makeCamera for camera.convention = "gl", lod::makeCameraD3d for "d3d" (left-handed view,
// depth in [0, w]); fov in radians = fovY * float(pi / 180).
lod::Camera toLodCamera(const Camera& c);
// The verifier's own view of the camera, whatever camera.convention says: lod::makeCamera (GL). The frustum test,
// on-screen decisions, pixel gaps and the projection's w of a hole record use it, so a scene's verdicts change with
// the convention only through the LOD's factors (docs/verify.md, "camera.convention").
lod::Camera viewCamera(const Camera& c);
// Hull-shader factors and lod/'s record of every patch for a camera (lod.h order). Adds the lod/ calls to
// work.lodEvaluations. Constant scheme: every factor lod.factor, an empty record.
// need: null, or only the patches i with (*need)[i] != 0 (the others' entries are left as they are), except for
// geomorph, whose factors need every patch's level (all are computed).
void computeFactors(const TerrainData& t, const Camera& camera, std::vector<lod::PatchLod>& out, WorkStats& work,
                    const std::vector<char>* need = nullptr);
// The scene asks for the GPU path (lod.shader, or lod.evaluate = "gpu").
// Scene files (scene_content.cpp): the size limit of a scene file and of a lod.shader file; readBounded reads a file
// whole when it holds at most limit bytes (1), else -1 (larger: read only up to the limit) or 0 (cannot read);
// hashSceneContent sets Scene::contentHash (false with error: the shader cannot be read or is too large).
constexpr size_t kMaxSceneBytes = size_t(16) << 20;
int readBounded(const std::string& path, size_t limit, std::string& out);
bool hashSceneContent(const std::string& text, const std::vector<std::string>& overrides, Scene& s,
                      std::string& error);

bool usesGpu(const Scene& s);
// CheckOptions::tessellator with flushDenormals set by denormalRule (the options every tessellation of a check takes).
Options tessellatorOptions(const Scene& s, const CheckOptions& options);
// The factors the check uses: computeFactors, or (usesGpu) the provider's, and then, when cpu is given and
// lod.scheme is a built-in scheme, the C++ build's into *cpu (not counted in work). False with error when the GPU
// path is asked for without a provider or the provider fails. need: computeFactors' (the GPU path computes all).
bool computeFactorsFor(const TerrainData& t, const Camera& camera, FactorProvider* gpu,
                       std::vector<lod::PatchLod>& out, std::vector<lod::PatchLod>* cpu, WorkStats& work,
                       std::string& error, const std::vector<char>* need = nullptr);
// One patch's factors with the given tile neighbours (every scheme but geomorph, whose factors need its
// neighbours' levels): what computeFactors runs per patch; the fault injection's NeighbourSize runs it with a
// wrong size.
lod::PatchLod patchLod(const TerrainData& t, const TerrainPatch& p, const lod::TileNeighbours& neighbours,
                       const lod::Camera& cam);
// The neighbour rule of edge e of patch p as the LOD applied it (EdgeLod's neighbourSize, clamp, reconstruction).
void neighbourRule(const TerrainData& t, const TerrainPatch& p, int e, EdgeLod& out);
// Per camera, per patch: what the domain shader reads besides the prepared terrain. Built by domainCamera from the
// factors lod/ returned (no further lod/ call, no height sample).
struct PatchDomain {
  // lod.scheme = "geomorph": segments (the hull factor, a power of two) and the weight of the inserted vertices' true
  // height (lod::geomorphWeight), per edge in FactorIndex order ([e]: the border level min(L, L_neighbour)) and for
  // the interior ([4]: the patch's own level).
  float morphSegments[5] = {0, 0, 0, 0, 0};
  float morphWeight[5] = {0, 0, 0, 0, 0};
  // displacement.mip: the mip level at each corner, maxExponent - lod::Why::cornerLevel[c] (per_vertex), or the
  // patch's level maxExponent - exponent at its centre in [0] (per_patch).
  float mipLevel[4] = {0, 0, 0, 0};
};
struct DomainCamera {
  std::vector<PatchDomain> patches; // one per patch; empty when the scene's domain shader needs no camera state
  const PatchDomain* at(size_t i) const { return patches.empty() ? nullptr : &patches[i]; }
};
// Empty (no allocation) unless lod.scheme = "geomorph" on a displaced scene or displacement.mip != "none".
DomainCamera domainCamera(const TerrainData& t, const std::vector<lod::PatchLod>& factors);
// A world length at a point in pixels, with lod's projection (see Finding::gapPixels).
double pixelsAt(const lod::Camera& camera, const glm::vec3& at, double world);

// Per-thread state of the edge check, reused from camera to camera: the edge points cache (edgePoints() keyed by
// the factor's bits; an open-addressing table, no allocation per lookup once warm) and the per-camera scratch
// vectors (one entry per patch), so a sweep allocates nothing per camera once its first cameras are done.
// The cache lives for one camera (newCamera() forgets it in O(1)): a camera's edgeQueries are its distinct factors,
// the same whatever thread or shard checks it, and memory is bounded by the largest camera, not the camera count.
class EdgeCache {
public:
  EdgeCache(Partitioning p, const Stage& s, const Options& o);
  // Adds a miss to work.edgeQueries. The reference stays valid until the next newCamera().
  const EdgePoints& get(float factor, WorkStats& work);
  // get(factor).culled (the patch is discarded) without placing points (fftess::edgeCulled with the cache's settings); no work counted.
  bool discards(float factor) const { return edgeCulled(factor, partitioning_, stage_, options_); }
  void newCamera();
  size_t size() const { return used_; }

  // Scratch of checkTerrain (contents meaningless between calls).
  std::unique_ptr<TerrainData> layout; // layout.kind = "quadtree": the camera's layout (cameraLayout)
  std::vector<lod::PatchLod> factors;
  std::vector<std::array<const EdgePoints*, 4>> ep;
  std::vector<char> culled;
  std::unique_ptr<struct VisibleSelection> visible; // CheckOptions::visibleFirst's selection

private:
  void grow();
  static constexpr size_t kSlots = 1 << 15; // initial table size (a power of two); grows within a large camera
  Partitioning partitioning_;
  Stage stage_;
  Options options_;
  uint32_t generation_ = 1;          // a slot is in use when gen_[slot] == generation_
  std::vector<uint32_t> keys_;       // factor bits (size a power of two)
  std::vector<uint32_t> gen_;
  std::vector<int32_t> slot_;        // index into entries_
  std::deque<EdgePoints> entries_;   // stable addresses; the first used_ are this camera's
  size_t used_ = 0;
};

// Domain coordinates of parameter t on edge e of a quad.
inline DomainPoint edgeDomain(int e, float t) {
  switch (e) {
  case Ueq0: return {0.0f, t};
  case Ueq1: return {1.0f, t};
  case Veq0: return {t, 0.0f};
  default: return {t, 1.0f};
  }
}

// ---------------------------------------------------------------------------------------------------------------
// visible_first.cpp: CheckOptions::visibleFirst (docs/verify.md, "Sweep shortcuts").

class FrustumTest;

// One shared edge pair as the check classifies it: edge e of patch ia against the opposite edge of patch ib (ia is
// the bigger side or, between equals, the lower index).
struct EdgePair {
  int32_t ia = 0, ib = 0;
  int32_t e = 0;
  int32_t number = -1; // static layouts: the pair's number in PatchTree::allPairs (the same for every camera)
};
// Calls fn(ia, e, ib) for every shared edge pair of t in the check's order (layout order of ia, then e, then the
// neighbours along the edge): the order findings are reported in.
template <class Fn> void forEachEdgePair(const TerrainData& t, Fn&& fn) {
  for (size_t ia = 0; ia < t.patches.size(); ++ia) {
    const TerrainPatch& A = t.patches[ia];
    for (int e = 0; e < 4; ++e) {
      const int32_t* first = t.neighboursBegin(A, e);
      const int32_t* last = t.neighboursEnd(A, e);
      if (first == last) continue;
      const TerrainPatch& B0 = t.patches[static_cast<size_t>(*first)];
      if (B0.size > A.size || (B0.size == A.size && *first < static_cast<int>(ia))) continue;
      for (const int32_t* k = first; k != last; ++k) fn(static_cast<int32_t>(ia), e, *k);
    }
  }
}
// The box every domain point of p lies in, for any camera (the hole check's whole-patch box, patchVisibility's
// first test): the flat corners' bounds padded by 2^-20 of their magnitude in x and z, y from surfaceMinY /
// surfaceMaxY (every level the scene samples). In double.
void patchBox(const TerrainPatch& p, glm::dvec3& lo, glm::dvec3& hi);
// A bounding-volume tree over a static layout's patch boxes (prepareTerrain builds it; quadtree layouts, whose
// patches change per camera, have none and are scanned linearly), with every shared edge pair filed at the lowest
// node that holds both its patches: a node proven off screen proves its pairs off screen too (their joint box lies
// in the node's box).
struct PatchTree {
  struct Node {
    glm::dvec3 lo{0}, hi{0};
    int32_t child[2] = {-1, -1};  // -1: a leaf
    int32_t first = 0, count = 0; // a leaf's patches: order[first .. first + count)
    int32_t pairFirst = 0, pairCount = 0; // pairs[pairFirst .. + pairCount): the pairs filed here
  };
  std::vector<Node> nodes;        // nodes[0] is the root
  std::vector<int32_t> order;     // patch indices, leaf by leaf
  std::vector<int32_t> pairs;     // pair numbers (into allPairs), grouped by node
  std::vector<EdgePair> allPairs; // every shared edge pair, in the check's order (forEachEdgePair)
  std::vector<glm::dvec3> boxLo, boxHi; // patchBox of every patch
};
std::shared_ptr<const PatchTree> buildPatchTree(const TerrainData& t);
// The camera's selection (visible first), into the per-thread scratch: need[i] = 1 for the patches whose factors
// the check needs (their box is not proven off screen, or they are a side of a selected pair), pairs = the shared
// edge pairs whose joint box is not proven off screen, in the check's order. Sets stats.patchesOffScreen and
// stats.edgesOffScreen; adds the frustum tests to work.boxTests.
struct VisibleSelection {
  std::vector<char> need, live;
  std::vector<EdgePair> pairs;
  std::vector<uint64_t> pairBits;
  std::vector<int32_t> stack, liveNodes;
  std::vector<glm::dvec3> boxLo, boxHi; // quadtree layouts: this camera's patch boxes (the tree keeps static ones)
};
void selectVisible(const TerrainData& t, const FrustumTest& frustum, VisibleSelection& out, Stats& stats,
                   WorkStats& work);

// What a sweep's cameras proved about its shared edges, for every later camera (SweepOptions::resultCache; docs/
// verify.md, "Sweep shortcuts"): the result cache (matched factor pairs; seam proofs of quadtree layouts, whose pairs
// have no fixed number) and, for static layouts, the seam proof of every pair by its number (SeamProof as a byte,
// 0 = not asked yet). Memory: 16 bytes per cache slot plus one byte per pair, allocated once.
struct SweepMemo {
  SweepMemo(size_t slots, size_t pairs);
  ResultCache results;
  std::unique_ptr<std::atomic<uint8_t>[]> seams;
  size_t seamCount = 0;
  size_t bytes() const { return results.bytes() + seamCount; }
};

// ---------------------------------------------------------------------------------------------------------------
// check_exact.cpp (CGAL)

struct ExactVerdict {
  Classification classification = Classification::Match;
  double gap = 0;      // crack: the largest distance of a vertex to the other polyline
  int gapSide = 0;     // 0: side a, 1: side b
  int gapIndex = -1;   // index into that side's points
  // With a frustum (crack only): the same over the off-polyline vertices whose gap segment (to the nearest point of the
  // other polyline) is not proven off screen; onScreenAny false when there is none.
  bool onScreenAny = false;
  double onScreenGap = 0;
  int onScreenGapSide = 0;
  int onScreenGapIndex = -1;
};

class FrustumTest;

// a: side a's points inside the shared part (in order); aFull: side a's whole polyline (a vertex of b is tested
// against it); b: side b's points (all of them are in the shared part). All in the same direction.
// frustum: also the worst gap on screen (ExactVerdict::onScreen*); a must then point into aFull.
ExactVerdict classifyExact(Kernel kernel, const glm::vec3* a, int na, const glm::vec3* aFull, int naFull, const glm::vec3* b,
                           int nb, const FrustumTest* frustum = nullptr);

// ---------------------------------------------------------------------------------------------------------------
// gpu_float.cpp: CheckOptions::gpuFloat (docs/verify.md, "GPU float freedom").

// One camera's GPU float check: a BoundContext under lod::FloatModel::Conformant and the camera as its constants.
class GpuFloatChecker {
public:
  // t: the camera's layout; camera: the check's (the LOD gets toLodCamera's). maxPaths: BoundContext's.
  GpuFloatChecker(const TerrainData& t, const Camera& camera, int maxPaths = 256);
  ~GpuFloatChecker();
  // The pair edge e of patch ia / the opposite edge of patch ib, which the check found matching with the C++ build's
  // factors (factors: the check's, lod/'s C++ build): counts Stats::gpuFloatPairs and, where its match depends on a
  // conformant compiler's choices, Stats::gpuFloatFindings and a Report::gpuFloat entry (at most maxFindings kept).
  void pair(size_t ia, int e, size_t ib, const std::vector<lod::PatchLod>& factors, EdgeCache& cache,
            size_t maxFindings, Report& rep);
  // The GPU path (lod.evaluate = "gpu"): each factor the GPU returned (gpu, in patch order; need: visible first's
  // patches, null: all) against the union of the conformant runs' sets for its patch: Stats::gpuModelFactors,
  // gpuModelOutside. A patch whose runs exceed maxPaths is not counted.
  void model(const std::vector<lod::PatchLod>& gpu, const std::vector<char>* need, Report& rep);

private:
  const TerrainData& t_;
  std::unique_ptr<lod::BoundContext> context_;
  std::unique_ptr<lod::BoundCamera> camera_;
};

// ---------------------------------------------------------------------------------------------------------------
// check.cpp

// memo: the sweep's (SweepOptions::resultCache), or null (no cache; checkScene).
Report checkTerrain(const TerrainData& t, const Camera& camera, const CheckOptions& options, EdgeCache& cache,
                    SweepMemo* memo = nullptr);
bool validateCamera(const Camera& c, std::string& error);

// ---------------------------------------------------------------------------------------------------------------
// view_mesh.cpp

// viewMesh (view_mesh.h) on a layout already selected for the camera (t: layoutFor(terrain, camera).data()).
ViewMesh buildViewMesh(const TerrainData& t, const Camera& camera, const CheckOptions& options,
                       const std::vector<int>& fill = {}, int fillSegments = 8);

// ---------------------------------------------------------------------------------------------------------------
// visibility.cpp: is a patch that is not drawn on screen? (visibility.h, Hole)

// The box of points (float values, exact in double): grown one point at a time.
struct PointBox {
  glm::dvec3 lo{0}, hi{0};
  bool empty = true;
  void add(const glm::vec3& p) {
    const glm::dvec3 d(p);
    lo = empty ? d : glm::min(lo, d);
    hi = empty ? d : glm::max(hi, d);
    empty = false;
  }
};

class FrustumTest {
public:
  explicit FrustumTest(const lod::Camera& camera); // clip = projection * view, in double
  // The box [lo, hi] lies wholly outside one frustum plane.
  bool boxOutside(const glm::dvec3& lo, const glm::dvec3& hi) const;
  // The point is strictly inside the frustum.
  bool inside(const glm::vec3& p) const;
  // On screen or not (docs/verify.md, "On screen"): the box [lo, hi] lies outside one frustum plane by more than the
  // float rounding of a GPU's clip coordinates could undo (2^-16 of a bound on the magnitudes of the plane's terms
  // over the box). Conservative: false whenever a point of the box may be on screen. Monotone: true for a box also
  // holds for every box inside it.
  bool boxOffScreen(const glm::dvec3& lo, const glm::dvec3& hi) const;
  // The box [lo, hi] lies strictly inside all six planes (double, no margin): no box inside it is boxOffScreen (nor
  // boxOutside). Visible first's shortcut for tree nodes wholly in view.
  bool boxInside(const glm::dvec3& lo, const glm::dvec3& hi) const;
  // The part [t0, t1] (within the given [t0, t1]) of the segment p + t (q - p) inside the frustum's six planes
  // (double, no margin). False: no part of it is inside.
  bool clipSegment(const glm::dvec3& p, const glm::dvec3& q, double& t0, double& t1) const;

private:
  double m_[4][4]; // row-major clip matrix
  // The six planes w + x, w - x, w + y, w - y, w + z (near, GL clip space), w - z (far) as rows of m_ (plane_[p][c] =
  // m_[3][c] +- m_[row][c]), and the magnitudes |m_[3][c]| + |m_[row][c]| boxOffScreen's margin is made of.
  double plane_[6][4];
  double planeScale_[6][4];
};

// ---------------------------------------------------------------------------------------------------------------
// onscreen.cpp: on screen or not (docs/verify.md, "On screen").

// Sets f.onScreen (a non-matching finding: false only when the box of all its vertices is proven off screen, counted
// in stats.cracksOffScreen / tJunctionsOffScreen) and, for a crack on screen, f.onScreenGap* (the worst of: the
// classifier's on-screen vertex gap v.onScreenGap, and the gap where either side's edge crosses the frustum's
// boundary; nothing of either edge in view: the farthest vertex's) with stats' on-screen worst gaps. Side a is
// fullA[0..naFull) with the shared part [first, last); side b is b[0..nb). f's gap* fields must be set.
void markOnScreen(const FrustumTest& frustum, const lod::Camera& cam, float nearZ, const ExactVerdict& v,
                  const glm::vec3* fullA, int naFull, int first, int last, const glm::vec3* b, int nb, Finding& f,
                  Stats& stats);

// The decision for one patch that is not drawn (visibility.h, Hole; docs/verify.md, "Holes"): its (u, v) domain split
// breadth first into dyadic sub-rectangles; each one's conservative box of the displaced surface (x/z from the
// exact bilinear interpolation of the corners, padded for the domain shader's float rounding; y from the texels its
// footprint can read on every mip level the domain shader samples) outside one frustum plane is invisible; its centre
// (and, at the root and at the finest level, its corners) strictly inside the frustum proves the patch visible;
// otherwise it is split, down to side 2^-maxDepth. Undecided: a finest-level sub-rectangle was neither, or the work
// bound (maxSubRectangles) was reached first.
struct VisibilityLimits {
  int maxDepth = 10;                 // finest sub-rectangle: 2^-maxDepth of the patch side (0..20)
  int64_t maxSubRectangles = 16384;  // boxes per patch, then Undecided
};
struct VisibilityDecision {
  Visibility visibility = Visibility::Invisible;
  glm::vec3 point{};           // Visible: the domain point inside the frustum (world)
  DomainPoint at{};            // Visible: its (u, v); Undecided: the lower corner of the first undecided sub-rectangle
  float side = 0;              // Undecided: that sub-rectangle's side (domain units)
  bool workBound = false;      // Undecided because maxSubRectangles was reached
  int64_t subRectangles = 0;   // boxes built
};
// The conservative box of the displaced surface over the sub-rectangle [u0, u0 + 2^-depth] x [v0, v0 + 2^-depth]
// (u0, v0 multiples of 2^-depth): every evalDomain(t, p, u, v, domain) with (u, v) in it lies inside [lo, hi].
void surfaceBox(const TerrainData& t, const TerrainPatch& p, const PatchDomain* domain, float u0, float v0, int depth,
                glm::dvec3& lo, glm::dvec3& hi);
// Adds the domain evaluations to work (domainEvaluations, visibilityEvaluations).
VisibilityDecision patchVisibility(const TerrainData& t, const TerrainPatch& p, const PatchDomain* domain,
                                   const FrustumTest& frustum, const VisibilityLimits& limits, WorkStats& work);

} // namespace fftess::verify::detail
