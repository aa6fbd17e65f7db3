// fftess verify, stage 4: the LOD bridge, per camera. The hull-shader factors of every patch come from lod/'s C++
// build (the scene's scheme and parameters, handed to lod/ as they are) or from a FactorProvider (the GPU path);
// this header is what crosses that bridge: the LOD's inputs per patch (LodInput, LodPatches), the provider
// interface, lod/'s record of each edge (EdgeLod) and the two factor reports a check makes before tessellating
// (DenormalFactor, FactorDiff).
#pragma once

#include "lod/lod.h"
#include "verify/scene.h"
#include "verify/terrain.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fftess::verify {

// Factors from somewhere else than lod/'s C++ build: the GPU path (lod.evaluate = "gpu", lod.shader). verify itself
// links no GL; gpu_lod/gpu_lod.h implements FactorProvider on an OpenGL driver and the cli hands it in
// CheckOptions::factors.

// What lod/ gets for one patch: its corners (displaced as lod.displaced_corners says), the culling box's height
// bounds and, on tile rings, the sizes across its edges, its parity, the far corners and the rebuilt heights.
struct LodInput {
  lod::Patch patch;
  lod::TileNeighbours neighbours;
};

// A view of a prepared terrain's LOD inputs (cheap; valid while the terrain lives).
class LodPatches {
public:
  // terrain: built (not Terrain::empty()); the view must not outlive it.
  explicit LodPatches(const Terrain& terrain);
  explicit LodPatches(const detail::TerrainData& data) : t_(&data) {}
  // Patches in the terrain (the size of FactorProvider::evaluate's out).
  size_t size() const;
  // Patch i's LOD input (i < size()), as lod/'s C++ build gets it for the same patch.
  LodInput operator[](size_t i) const;
  // The same for every view of one prepared terrain (a provider keys its uploaded inputs by it).
  const void* key() const { return t_; }
  // Changes whenever the terrain behind key() holds other patches (a camera-dependent layout reselected into the same
  // per-thread scratch, layout.kind = "quadtree"); 0 for a static layout. A provider keys its inputs by both.
  uint64_t generation() const;
  // Patches of different sizes meet (tile rings with rings > 1): the built-in schemes run their *Tile variant.
  bool sizeJumps() const;
  // The terrain's scene (lod.scheme and its parameters, lod.shader).
  const Scene& scene() const;
  // Corner c (0..3, u + 2v) of patch i as a hull shader's control point may carry it ([lod.inputs]): the flat
  // world position (y = 0), the height the vertex shader samples there, the corner's texture coordinate.
  struct Corner {
    glm::vec3 flat{0.0f};
    float height = 0;
    glm::vec2 tex{0.0f};
  };
  Corner corner(size_t i, int c) const;
  // The terrain's extent in x/z (the heightmap spans it).
  Extent extent() const;

private:
  const detail::TerrainData* t_;
};

// The source of a check's hull factors on the GPU path (CheckOptions::factors, check.h), implemented outside verify.
class FactorProvider {
public:
  virtual ~FactorProvider() = default;
  // Every patch's factors and record for one camera, in patch order (out.size() == patches.size()). Called from
  // the sweep's worker threads, possibly at once (an implementation serialises what it must). False with error: the
  // camera is reported as not checked (Report::error).
  virtual bool evaluate(const LodPatches& patches, const lod::Camera& camera, std::vector<lod::PatchLod>& out,
                        std::string& error) = 0;
  // Called after each camera whose C++ reference ran (the factor comparison), with its time on the calling thread:
  // for a cost report next to the provider's own. Default: ignored.
  virtual void noteCpuSeconds(double seconds) { (void)seconds; }
  // The rule of the driver behind these factors for a denormal hull factor in its tessellation stage: true when it
  // flushes it to zero (a denormal outer factor culls the patch). DenormalFlush::Auto takes it. why: one line saying
  // what decided it (e.g. the renderer string). Default: false, "the D3D11 reference (the provider states no rule)".
  virtual bool flushesDenormals(std::string* why = nullptr) const {
    if (why) *why = "the D3D11 reference (the provider states no rule)";
    return false;
  }
};

// A hull factor the factor source returned as a denormal (nonzero, |x| < 2^-126), before any flush: reported from
// every source (a GPU's included) whether flushed or not, since drivers differ (DenormalFlush).
struct DenormalFactor {
  PatchRef patch;
  int factor = 0;              // FactorIndex: Ueq0 Veq0 Ueq1 Veq1 insideU insideV
  float value = 0;
  uint32_t bits = 0;
  bool flushed = false;        // the check flushed it to zero (DenormalRule::flush)
};

// One factor where the GPU's value is not the C++ build's (lod.evaluate = "gpu", or lod.shader with a built-in
// lod.scheme): the patch, the factor (FactorIndex: Ueq0 Veq0 Ueq1 Veq1 insideU insideV), both values and bits, and
// whether the tessellation changes (fftess::edgePoints of the two differ: point count or any 16.16 position, under
// the scene's partitioning and stage; inside factors judged by the same edge rule). The GPU's factor is the one
// checked.
struct FactorDiff {
  PatchRef patch;
  int factor = 0;
  float gpu = 0, cpu = 0;
  uint32_t gpuBits = 0, cpuBits = 0;
  bool changesTessellation = false;
};

// The LOD's own record for one edge of one patch, as lod/ returned it (nothing guessed afterwards).
struct EdgeLod {
  LodScheme scheme = LodScheme::Constant; // the scene's scheme (Constant: lod/ did not run; why is empty)
  lod::FactorWhy why{};        // metric, unclamped factor, exponent and the fix bits (lod::Fix) of this edge
  bool culled = false;         // lod/ culled the patch (lod::Why::culled)
  // The neighbour rule: the neighbour's size relative to this patch as handed to lod::nvidiaTile / lod::*Tile (0.5:
  // this is the larger side, 2: the smaller side, which rebuilt the larger edge; 1: same size, or no adjacency code
  // ran; 4, 8, ... or 0.25, 0.125, ...: a jump beyond 2x, where lod/ runs no neighbour rule, since it handles 2x jumps
  // only: an unbalanced quadtree, a patches layout), the clamp applied at the jump (None beyond 2x) and how the
  // larger edge was rebuilt (both meaningful only when size is 2 or 0.5).
  float neighbourSize = 1;
  AdjacencyClamp clamp = AdjacencyClamp::None;
  lod::Reconstruction reconstruction = lod::Reconstruction::EdgeVector;
};

// The check's own camera of a verify camera (lod::makeCamera: GL view and projection, viewport) exactly as every
// check builds it: the matrices Finding::gapPixels and the on-screen decisions use, the same for camera.convention =
// "gl" and "d3d" (the LOD's factors take the camera in its own convention). For pictures and tests that project what a
// check found (the cli's check --view).
lod::Camera viewCamera(const Camera& camera);

} // namespace fftess::verify
