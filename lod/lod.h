// fftess lod: the patch-constant ("hull constant") functions terrain engines use to choose tessellation factors.
//
// This header is the public contract of the module, with lod/lod_fields.h (the one field list per scheme: the
// *Params members below, their defaults and documentation) and lod/glsl_settings.h (those settings as GLSL text, for a
// GPU port). The arithmetic itself lives once, in
// lod/shaders/*.glsl, written in the subset GLSL and GLM share; the .cpp files compile those files as C++ through
// GLM (single precision, in the order written, no contraction into FMA) and tests/lod compiles the same files as a
// GLSL tessellation control shader with glslangValidator. The CPU path and the GPU path are the same source.
//
// Conventions (all schemes):
//   * Quad patch corners: corners[i] is the world position of domain point (u, v) with i = u + 2*v, i.e.
//       corners[0] = (0,0), corners[1] = (1,0), corners[2] = (0,1), corners[3] = (1,1).
//     The edges, in D3D's words: Ueq0 = corners 0-2, Veq0 = corners 0-1, Ueq1 = corners 1-3, Veq1 = corners 2-3.
//     For a terrain laid out on the x-z plane: u along +x, v along +z, so Ueq0 faces -x, Ueq1 +x, Veq0 -z, Veq1 +z.
//   * Output factor order is the tessellator's: Ueq0 Veq0 Ueq1 Veq1 insideU insideV (fftess::FactorIndex in
//     tessellator/tessellator.h; indices 0..5).
//     insideU subdivides along u, so it is reduced from the edges that run along u (Veq0, Veq1); insideV from
//     Ueq0, Ueq1 (the HLSL compiler's two-axis rule).
//   * Camera: view = glm::lookAt (right-handed, the camera looks down -z in view space), projection =
//     glm::perspective (GLM's default OpenGL clip space: after the divide x, y, z are in [-1, 1], w = -z_view > 0
//     in front of the camera). Set Camera::depthZeroToOne when the projection came from glm::perspectiveZO
//     (D3D / Vulkan clip space, z in [0, w]); it changes only the near plane of frustum culling. makeCameraD3d
//     builds D3D's camera (lookAtLH, perspectiveLH_ZO: w = +z_view): every scheme takes it as it is.
//     Pixels: a clip-space x difference dx/w maps to dx/w * viewport.x / 2 pixels (NDC spans 2 units).
//   * Matrix-vector products are evaluated as m[0]*x + m[1]*y + m[2]*z + m[3]*w, left to right, column by column
//     (not GLM's operator*, whose pairing differs); every other expression in the order docs/lod.md states.
//   * Factors are what a hull shader would write to SV_TessFactor / gl_TessLevel*: not yet clamped, rounded or
//     culled by the tessellator. A culled patch has every factor set to the scheme's cull value (-1 for the
//     NVIDIA schemes, 0 for the others; both are culled by the tessellator).
//   * Two patches that share an edge and pass the same two corner positions for it (in either order) get
//     bitwise the same factor for that edge, in every scheme (tests/lod checks it).
//   * Every function is pure: no allocation, no global state, safe to call from any thread.
//
// Known GPU divergence (details per scheme in docs/lod.md): GPUs evaluate exp2, log2, pow, sqrt, acos and
// division approximately (a few ulp), so a factor can move by a few ulp, and a rounded exponent (Bonaventura,
// geomorphing levels) can flip by one level exactly at a rounding boundary.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

#include "lod/lod_fields.h"

namespace fftess::lod {

// ---------------------------------------------------------------------------------------------------------------
// Inputs

struct Camera {
  glm::mat4 view{1.0f};       // world -> view, glm::lookAt
  glm::mat4 projection{1.0f}; // view -> clip, glm::perspective (or perspectiveZO with depthZeroToOne)
  glm::vec2 viewport{1920.0f, 1200.0f}; // pixels; both > 0
  glm::vec3 eye{0.0f};        // world position of the camera (the lookAt eye)
  bool depthZeroToOne = false; // clip z in [0, w] instead of [-w, w]
};

// Convenience: view = lookAt(eye, target, up), projection = perspective(fovyRadians, viewport.x / viewport.y,
// zNear, zFar). fovyRadians in (0, pi); 0 < zNear < zFar; viewport components > 0.
Camera makeCamera(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fovyRadians, float zNear, float zFar,
                  glm::vec2 viewport);

// The same camera as a D3D engine builds it: view = glm::lookAtLH(eye, target, up) (D3DXMatrixLookAtLH: left-handed,
// the camera looks down +z in view space), projection = glm::perspectiveLH_ZO(fovyRadians, viewport.x / viewport.y,
// zNear, zFar) (D3DXMatrixPerspectiveFovLH's matrix: w = z_view, clip z in [0, w]), depthZeroToOne = true. The same
// frustum as makeCamera's: in float, the view's x and z rows are makeCamera's negated (bit for bit) and its y row is
// makeCamera's; the projection's x and y scales are makeCamera's; only the depth row and w's sign differ. Arguments
// as makeCamera.
Camera makeCameraD3d(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float fovyRadians, float zNear, float zFar,
                     glm::vec2 viewport);

// The six frustum planes every scheme culls with (lod/shaders/common.glsl lodFrustumPlanes): the rows of
// projection * view (Gribb-Hartmann, inward, unnormalised; a point p is inside plane k when
// dot(planes[k].xyz, p) + planes[k].w >= 0), in D3D's order left (w + x), right (w - x), bottom (w + y), top
// (w - y), near (w + z, or z alone with depthZeroToOne), far (w - z). Each component is one float sum or difference
// of the product's rows (the product in lod's column order, common.glsl mulMat).
struct FrustumPlanes {
  glm::vec4 planes[6]{};
};
FrustumPlanes frustumPlanes(const Camera& camera);

struct Patch {
  glm::vec3 corners[4]{}; // world positions (displaced heights allowed), corners[u + 2v]
  // Culling box: the axis-aligned box of the four corners; with useHeightBounds its y range is widened to
  // include [minHeight, maxHeight] (the heights the displacement can reach inside the patch, as Luna's BoundsY).
  bool useHeightBounds = false;
  float minHeight = 0.0f; // <= maxHeight
  float maxHeight = 0.0f;
};

// How the two edge factors of an axis become that axis' inside factor.
enum class InsideRule : uint8_t { Average, Min, Max };

// Where screen_sphere puts an edge's sphere (ScreenSphereParams::sphereCentre; scene key lod.sphere_centre).
// HalfSum: the edge's midpoint (p0 + p1) * 0.5, the same operations on the same bits from both sides. AroundQuadScaled:
// a negative control for --gpu-float (docs/verify.md, "GPU float freedom"): (from * 3 + to * 3) * (1/6) with the ends
// in the order the patch passes them going around its quad, so the two sides of an edge add the same two rounded
// products in opposite orders: the same bits in the C++ build, different where a GPU compiler fuses one product into
// the add.
enum class SphereCentre : uint8_t { HalfSum, AroundQuadScaled };

// ---------------------------------------------------------------------------------------------------------------
// Outputs: factors plus the reason for each.

enum class Scheme : uint8_t { ScreenSphere, NvidiaTile, DistancePow2, Bonaventura, ClipDiameter, Geomorph, PatchCenter,
                              Constant };

// Bits of FactorWhy::fixes: which clamp, fix or literal-source switch changed a factor.
enum Fix : uint32_t {
  FixNone = 0,
  FixClampedMin = 1u << 0,        // raised to the scheme's minimum factor
  FixClampedMax = 1u << 1,        // lowered to the scheme's maximum factor
  FixCulled = 1u << 2,            // the patch was culled; the factor is the cull value
  FixLargerNeighbour = 1u << 3,   // tile rings: neighbour twice the size; its edge was rebuilt and half its factor taken
  FixSmallerNeighbour = 1u << 4,  // tile rings: neighbour half the size; this is the larger side of the jump
  FixIntegerClamp = 1u << 5,      // tile rings: the integer adjacency clamp rounded this factor
  FixPow2Clamp = 1u << 6,         // tile rings: the power-of-two adjacency clamp rounded this factor
  FixAngleCorrection = 1u << 7,   // Bonaventura camera-angle correction applied
  FixRoundedExponent = 1u << 8,   // Bonaventura: exponent rounded to an integer
  FixCoarserNeighbour = 1u << 9,  // geomorphing: the edge follows the coarser neighbour's level
  FixLiteralSource = 1u << 10,    // a literal-source switch (see the params) changed this factor
};

// What a factor came from. metric: projected diameter in pixels (ScreenSphere, NvidiaTile), distance in world
// units (DistancePow2, Bonaventura, Geomorph level input), clip-space diameter term (ClipDiameter).
struct FactorWhy {
  float metric = 0.0f;    // the measured quantity
  float unclamped = 0.0f; // the factor (or, for exponent schemes, the value 2^exponent) before clamps and rounding
  float exponent = 0.0f;  // exponent schemes: the exponent after correction, before rounding; else 0
  uint32_t fixes = FixNone;
};

struct Why {
  Scheme scheme = Scheme::ScreenSphere;
  bool culled = false;
  FactorWhy factor[6]{};      // same order as PatchLod::factors
  float cornerLevel[4]{};     // Bonaventura: corrected exponent at each corner (mip selection); Geomorph: 0
};

struct PatchLod {
  float factors[6] = {1.0f, 1.0f, 1.0f, 1.0f, 1.0f, 1.0f}; // Ueq0 Veq0 Ueq1 Veq1 insideU insideV
  Why why{};
};

// ---------------------------------------------------------------------------------------------------------------
// 1. Screen-space sphere (NVIDIA DX11 terrain sample). Per edge: a sphere centred on the edge midpoint with the
// edge length as diameter, placed in view space, projected; factor = projected diameter in pixels /
// tessellatedTriWidth, clamped to [minFactor, maxFactor]. Inside factors from the edges by `inside`.
// Frustum culling: if the patch box is wholly outside one frustum plane, every factor is culledFactor.
struct ScreenSphereParams {
  FFTESS_LOD_SCREEN_SPHERE_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

PatchLod screenSphere(const Patch& patch, const Camera& camera, const ScreenSphereParams& params = {});

// 1b. Deliberately broken (a negative control for the verifier; lod/shaders/screen_sphere.glsl patchCenterLod):
// screenSphere, but every edge's sphere is centred on the patch centre ((c0 + c1 + c2 + c3) * 0.25) instead of the
// edge midpoint, with the edge's direction and length. Two patches sharing an edge disagree on its factor.
PatchLod patchCenter(const Patch& patch, const Camera& camera, const ScreenSphereParams& params = {});

// ---------------------------------------------------------------------------------------------------------------
// 2. Non-uniform patches in tile rings (same sample). Tiles of 8x8 patches in concentric rings, each ring doubling
// the patch size. On a tile border the neighbour can be half (0.5), the same (1) or twice (2) the size.
//   * neighbour 2 (this patch is the smaller side): rebuild the neighbour's edge, which is this edge extended by
//     its own length: by parity, the far end lies beyond corner "end" (even index along the edge) or before
//     corner "start" (odd index). Its sphere factor is computed and halved.
//   * neighbour 0.5 (this patch is the larger side): its own edge factor.
//   * the adjacency clamp, applied to both sides of a jump (a switch, so the verifier can show what each buys):
//       None:    as above;
//       Integer: larger side rounded up to an even integer and kept in [4, 64], smaller side = that / 2, in
//                [2, 32] (the sample's recipe); NaN stays NaN;
//       Pow2:    larger side rounded up to a power of two in [4, 64], smaller side = that / 2, in [2, 32]
//                (a NaN factor becomes 4, by comparisons).
// The eight boundary cases of the sample's constant hull shader are these two cases on each of the four edges.
// The same rule for the other schemes (their own edge factor on the rebuilt edge): section 7.
enum class AdjacencyClamp : uint8_t { None, Integer, Pow2 };

// How the smaller patch gets the far end of its larger neighbour's edge.
enum class Reconstruction : uint8_t {
  // The sample's vector math, literally: move the corner by the edge vector (rebuiltCorner: p1 + (p1 - p0) or
  // p0 - (p1 - p0)) and keep the height (y) of the corner it was moved from. Bitwise agreement with the larger
  // patch only where that height equals the far corner's (flat terrain, or corners not raised) and the positions
  // are exact in float.
  EdgeVector,
  // The far end is TileNeighbours::farCorner[edge] (the larger patch's own corner, displaced height included):
  // the two sides compute the same factor from the same two points, so they agree bitwise.
  FarCorner,
  // The sample's intent ("MakeVertexHeightsAgree": re-acquire the moved vertex's height): x/z from rebuiltCorner
  // as EdgeVector, y = TileNeighbours::rebuiltHeight[edge], the displacement sampled at that x/z as the vertex
  // shader samples corner heights. Agrees with the larger patch bitwise when rebuiltCorner's x/z equal the far
  // corner's x/z (the sampler is a function of x/z).
  Resampled,
};

struct TileNeighbours {
  // Relative size of the neighbour across each edge, indexed by fftess::FactorIndex (Ueq0, Veq0, Ueq1, Veq1):
  // 0.5, 1 or 2 (any other value is treated as 1). Edges inside a tile are 1.
  float size[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  // Parity of this patch's index along u (x) and v (z), counted from a corner that the larger patches share
  // (tiles hold an even number of patches per side, so the index inside the tile works). Ueq0/Ueq1 run along v
  // and use oddV; Veq0/Veq1 run along u and use oddU. Even: the patch is the first half of the larger edge.
  bool oddU = false;
  bool oddV = false;
  // Reconstruction::FarCorner only: the far end of the larger neighbour's edge, per edge with size 2.
  glm::vec3 farCorner[4]{};
  // Reconstruction::Resampled only: per edge with size 2, the height of the terrain at the x/z of
  // rebuiltCorner(start, end, odd) of that edge (what the vertex shader would sample there). Finite.
  float rebuiltHeight[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};

struct NvidiaTileParams {
  FFTESS_LOD_NVIDIA_TILE_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

PatchLod nvidiaTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                    const NvidiaTileParams& params = {});

// The far end of the larger neighbour's edge by the edge vector (lod/shaders/nvidia_tile.glsl rebuiltCorner), for
// edge start -> end of a patch (corners in D3D edge order, see edgeStartCorner in common.glsl: Ueq0 = 0-2, Veq0 =
// 0-1, Ueq1 = 1-3, Veq1 = 2-3). In float: edge = end - start; odd == false: end + edge, y = end.y; odd == true:
// start - edge, y = start.y. odd: TileNeighbours::oddV for Ueq0/Ueq1, oddU for Veq0/Veq1. A caller that fills
// TileNeighbours::rebuiltHeight samples its height at this x/z: the shader rebuilds the same bits.
//   start, end: any floats (finite for a meaningful result).
glm::vec3 rebuiltCorner(glm::vec3 start, glm::vec3 end, bool odd);

// The sample's AssignNeighbourSizes for one tile of one ring. A ring is a square of outerWidth x outerWidth tiles
// with a centred hole of holeWidth x holeWidth tiles (holeWidth = 0 for the innermost ring; outerWidth and
// holeWidth even, holeWidth < outerWidth). The next ring out has tiles twice the size; the hole holds the ring in,
// whose tiles are half the size. Returns the relative sizes for the tile's -x, -z, +x, +z sides in the
// FactorIndex order of TileNeighbours::size (Ueq0 = -x, Veq0 = -z, Ueq1 = +x, Veq1 = +z). outermost: no ring
// outside (sides on the outer border are 1).
struct TileSides {
  float size[4] = {1.0f, 1.0f, 1.0f, 1.0f};
};
TileSides assignNeighbourSizes(int tileX, int tileZ, int holeWidth, int outerWidth, bool outermost);

// Per-patch neighbours from the tile's sides: only patches on the tile border see a size other than 1.
// patchX, patchZ in [0, patchesPerTile); patchesPerTile even (the sample: 8). farCorner left zero.
TileNeighbours patchNeighbours(const TileSides& tile, int patchX, int patchZ, int patchesPerTile);

// ---------------------------------------------------------------------------------------------------------------
// 3. Distance-based power of two (Luna, "3D Game Programming with DirectX 11", terrain chapter; Richards).
// factor = 2^(maxTessExponent + s * (minTessExponent - maxTessExponent)),
// s = clamp((d - minDistance) / (maxDistance - minDistance), 0, 1), d = distance from the edge midpoint (edges)
// or the patch centre (both inside factors) to the eye. Culling: patch box (use the height bounds) against the
// six frustum planes; culled factors are 0.
struct DistancePow2Params {
  FFTESS_LOD_DISTANCE_POW2_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

PatchLod distancePow2(const Patch& patch, const Camera& camera, const DistancePow2Params& params = {});

// ---------------------------------------------------------------------------------------------------------------
// 4. Rounded-exponent power of two with camera-angle correction (Bonaventura, "Terrain and Ocean Rendering with
// Hardware Tessellation"). At a point p (edge midpoint, patch centre or corner), d = distance(p, eye):
//   e0 = maxExponent + s * (minExponent - maxExponent), s as in DistancePow2;
//   angle correction a = ((pi/2 - acos|c.e|) / (pi/2)) * rank + 1 - rank/2, c = normalize(p - eye), e = up;
//   exponent = e0 * a; factor = 2^floor(exponent + 0.5), clamped to [minFactor, maxFactor].
// cornerLevel[i] (in Why) = the corrected, unrounded exponent at corner i: four patches sharing a corner agree.
// The thesis writes the fourth corner's angle without acos; literalFourthCornerAngle reproduces that.
struct BonaventuraParams {
  FFTESS_LOD_BONAVENTURA_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

PatchLod bonaventura(const Patch& patch, const Camera& camera, const BonaventuraParams& params = {});

// ---------------------------------------------------------------------------------------------------------------
// 5. Clip-space sphere diameter (the "recommended method" of the tessellation-basics article). Per edge:
// clip = projection * view * (midpoint, 1); factor = max(minFactor, distance(p0, p1) * projection[1][1] / clip.w
// * edgesPerScreenHeight), then min(maxFactor, ...). A midpoint behind the camera (clip.w <= 0) gets minFactor.
struct ClipDiameterParams {
  FFTESS_LOD_CLIP_DIAMETER_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

PatchLod clipDiameter(const Patch& patch, const Camera& camera, const ClipDiameterParams& params = {});

// ---------------------------------------------------------------------------------------------------------------
// 6. Geomorphing tween factors (the hardware geomorphing article). A patch has a float level
// L = finestLevel + s * (coarsestLevel - finestLevel) (s from its centre's distance as in DistancePow2): its integer
// part is the level, its fraction the tween. The patch is drawn with integer partitioning at 2^(floor(L) + 1)
// segments; the vertices that level floor(L) + 1 inserts morph from the midpoint of their two coarse neighbours
// (tween 0) to their true height (tween 1). A border follows the coarser side: its level is min(L_self,
// L_neighbour), which both sides compute alike.
struct GeomorphParams {
  FFTESS_LOD_GEOMORPH_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

// The float level of a patch (from its centre).
float geomorphLevel(const Patch& patch, const Camera& camera, const GeomorphParams& params = {});

// Factors from the patch's level and its neighbours' levels (per edge, FactorIndex order; pass the patch's own
// level where there is no neighbour). Edges: 2^(floor(min(L, Ln)) + 1); inside: 2^(floor(L) + 1).
PatchLod geomorph(float level, const float neighbourLevel[4]);

// The vertex heights one side produces along a shared border. fineHeights: the true heights at t = i/64,
// i = 0..64, in the same order for both sides. Output: segments n (a power of two, 2..64) and heights[k] at
// t = k/n, k = 0..n. Both sides produce the same result for the same border (unless literalArticleWeight).
struct GeomorphEdge {
  int segments = 0;
  float heights[65]{};
};
GeomorphEdge geomorphEdgeHeights(float level, float neighbourLevel, const float fineHeights[65],
                                 const GeomorphParams& params = {});

// The pieces of geomorphEdgeHeights, for a domain shader that morphs one vertex at a time (verify/domain.cpp):
// geomorphWeight: the weight of an inserted vertex's true height on the border between levels `level` (this patch)
// and `neighbourLevel` (pass `level` for the patch's interior): the tween of min(level, neighbourLevel), or with
// literalArticleWeight (1 - tween(neighbourLevel)) * tween(level).
float geomorphWeight(float level, float neighbourLevel, const GeomorphParams& params = {});
// geomorphHeight: m = (previousHeight + nextHeight) * 0.5; m + weight * (height - m), rounded in that order.
float geomorphHeight(float height, float previousHeight, float nextHeight, float weight);

// ---------------------------------------------------------------------------------------------------------------
// 7. The tile-ring neighbour rule for every other scheme (nvidiaTile is the screen-space sphere's). Each function
// is the scheme's own function (same culling, same inside factors, same edges without a jump), except on an edge
// whose TileNeighbours::size is 2 or 0.5:
//   * size 2 (smaller side): the larger neighbour's edge is rebuilt (adjacency.reconstruction, as for nvidiaTile),
//     the scheme's own edge rule is evaluated on it, and larger(that factor) / 2 is written; the record (metric,
//     unclamped, exponent, fixes) is the rebuilt edge's, plus FixLargerNeighbour and the clamp's bit;
//   * size 0.5 (larger side): larger(own edge factor), plus FixSmallerNeighbour and the clamp's bit;
//   * larger(F) is adjacency.clamp's rule (section 2): F, the integer clamp or the power-of-two clamp.
// A culled patch is returned as the scheme culls it (no adjacency fix).
struct TileAdjacency {
  FFTESS_LOD_TILE_ADJACENCY_FIELDS(FFTESS_LOD_DECLARE_PARAM) // lod/lod_fields.h: members, defaults, documentation
};

// distancePow2 with the neighbour rule: the rebuilt edge's factor is 2^exponent of its midpoint's distance.
// patch, camera, params: as distancePow2. neighbours: sizes 0.5 / 1 / 2 per edge, parity, and farCorner or
// rebuiltHeight where the reconstruction needs them.
PatchLod distancePow2Tile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const DistancePow2Params& params = {}, const TileAdjacency& adjacency = {});

// bonaventura with the neighbour rule: the rebuilt edge's factor is Bonaventura's at its midpoint (angle
// correction, rounded exponent, factor clamps). Why::cornerLevel stays the patch's own.
// patch, camera, params: as bonaventura. neighbours: as distancePow2Tile.
PatchLod bonaventuraTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                         const BonaventuraParams& params = {}, const TileAdjacency& adjacency = {});

// clipDiameter with the neighbour rule: the rebuilt edge's factor is clipDiameter's edge rule on its two ends.
// patch, camera, params: as clipDiameter. neighbours: as distancePow2Tile.
PatchLod clipDiameterTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const ClipDiameterParams& params = {}, const TileAdjacency& adjacency = {});

// A constant factor on every edge and inside, with the neighbour rule: the rebuilt edge's factor is `factor` too,
// so the smaller side writes larger(factor) / 2 and the larger side larger(factor). No camera, no culling; the
// record's metric is 0 and unclamped = factor; Why::scheme is Scheme::Constant.
// factor: any float (> 0 to be drawn; NaN stays NaN with None and Integer).
PatchLod constantTile(float factor, const TileNeighbours& neighbours, const TileAdjacency& adjacency = {});

// ---------------------------------------------------------------------------------------------------------------
// Printing helpers for the CLI.
const char* schemeName(Scheme scheme);   // "screen_sphere", "nvidia_tile", "distance_pow2", "bonaventura", ...,
                                         // "patch_center" (snake_case, as every name fftess prints)
const char* fixName(Fix fix);            // one bit's name ("pow2_clamp"), "" for FixNone or several bits

// The shader sources, in the order GLSL needs them concatenated (common first): for a GPU port or an oracle.
// Each entry is one .glsl file's text; count via glslSourceCount().
int glslSourceCount();
const char* glslSourceName(int index);
const char* glslSource(int index);

} // namespace fftess::lod
