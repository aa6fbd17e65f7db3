// fftess verify: terrain scenes, domain-shader emulation and the exact crack verifier.
//
// This header is the whole public contract of the module. It speaks plain structs; CGAL and toml++ stay inside
// verify's .cpp files.
//
// Once per scene (prepareTerrain -> Terrain; everything that does not depend on the camera):
//   layout     patches of the terrain (uniform grid, NVIDIA tile rings, heightmap grid), their neighbours, corners,
//              corner heights, the LOD's height bounds, neighbour sizes and far corners, the extent.
// Per camera (each stage consumes only the previous stage's plain data, and is skipped when the scene does not
// call for it):
//   lod        per patch the four outer factors as the hull shader computes them (fftess::lod) and lod's record of
//              why, including the clamp at different-sized neighbours (tile rings only; a uniform grid never runs
//              adjacency code);
//   tessellate the 16.16 points of each outer edge (fftess::edgePoints; interiors only for the whole-mesh check);
//   domain     world position of each edge point as a domain shader computes it, in float, in a stated order;
//   check      per shared edge: match | T-junction | crack, decided with CGAL exact predicates.
//
// Findings are reports, not exceptions: nothing here turns a report into an exit status.
// Bad input (scene files, overrides) is returned as an error value naming the key and the file position;
// no exception escapes loadScene / parseScene.
#pragma once

#include "lod/lod.h"
#include "tessellator/names.h" // toString / parse of the tessellator enums in Scene and Finding
#include "tessellator/tessellator.h"

#include <glm/glm.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fftess::verify {

// ---------------------------------------------------------------------------------------------------------------
// Scene model. Every field has the default the scene format documents (docs/verify.md); the TOML key is named in
// each comment. The terrain lies in the x/z plane, y is up. Domain u runs along +x, v along +z:
//   Ueq0 = the patch's -x edge, Ueq1 = +x, Veq0 = -z, Veq1 = +z (D3D quad domain, see tessellator.h).

enum class LayoutKind : uint8_t {
  Grid,          // "grid": patches_x * patches_z patches of one size
  TileRings,     // "tile_rings": NVIDIA sample: ring 0 is tiles_per_ring_edge^2 tiles; each further ring is the same
                 // count of tiles of twice the size with the inner half (the previous ring) cut out
  HeightmapGrid, // "heightmap_grid": Luna/Richards: one patch per cells_per_patch heightmap cells
};

// How the four corners of a patch are obtained (layout.corners).
enum class CornerMode : uint8_t {
  Reconstructed, // "reconstructed": tile origin + (i / patches_per_tile_edge) * tile_size, in float, per tile, as the
                 // NVIDIA sample rebuilds them from the vertex id (neighbouring tiles may disagree in the last bit)
  Shared,        // "shared": every corner computed once (double, rounded to float) in a shared vertex buffer
};

struct Layout {
  LayoutKind kind = LayoutKind::TileRings; // layout.kind
  CornerMode corners = CornerMode::Reconstructed; // layout.corners
  float centerX = 0, centerZ = 0;          // layout.center = [x, z]: centre of the terrain (tile_rings, grid)
  // grid
  int patchesX = 16, patchesZ = 16;        // layout.patches_x, layout.patches_z (>= 1)
  float patchSize = 1;                     // layout.patch_size (> 0, finite); grid only
  // tile_rings
  int rings = 3;                           // layout.rings (1..16)
  int tilesPerRingEdge = 8;                // layout.tiles_per_ring_edge (even, >= 2)
  int patchesPerTileEdge = 8;              // layout.patches_per_tile_edge (>= 1)
  float basePatchSize = 1;                 // layout.base_patch_size (> 0): patch size in ring 0; ring r: 2^r times
  // heightmap_grid (needs displacement.kind = "raw" or a generator; texture size = cells_per_patch * k + 1)
  int cellsPerPatch = 64;                  // layout.cells_per_patch (>= 1)
  float cellSize = 1;                      // layout.cell_size (> 0): world size of one heightmap cell
};

enum class DisplacementKind : uint8_t {
  None,   // "none": flat; heights are never sampled
  Raw,    // "raw": 8- or 16-bit RAW heightmap file (16-bit little endian), values normalised to 0..1
  Fbm,    // "fbm": procedural fBm of value noise baked into a texture at load
  Ridge,  // "ridge": procedural ridged multifractal baked into a texture at load
};

// Mip selection of the displacement texture (displacement.mip; Bonaventura's coherence problem). Needs lod.scheme =
// "bonaventura" (its exponents are the levels) when not None.
enum class MipMode : uint8_t {
  None,      // "none" (default): level 0 only; no mip chain is built
  PerPatch,  // "per_patch": one level per patch, from its centre (neighbours sample a shared edge at different levels)
  PerVertex, // "per_vertex": the corner levels (lod::Why::cornerLevel) interpolated at each domain point
};

// Texel format the heights are uploaded in (displacement.format).
enum class TexelFormat : uint8_t {
  Float,    // "float" (default): 32-bit float, the loaded values as they are
  R16Float, // "r16_float": DXGI_FORMAT_R16_FLOAT (Luna): every texel rounded to IEEE half (nearest even) at load
};

// One level of the mip chain (level 1 and up; level 0 is Displacement::texels).
struct MipLevel {
  int width = 0, height = 0;
  std::vector<float> texels; // row-major, z rows of x texels
};

struct Displacement {
  DisplacementKind kind = DisplacementKind::Fbm; // displacement.kind
  float heightScale = 4;           // displacement.height_scale (finite): world height of texel value 1
  // raw
  std::string file;                // displacement.file (relative to the scene file)
  int width = 0, height = 0;       // displacement.width, displacement.height (raw: required; file size checked)
  int bits = 16;                   // displacement.bits: 8 | 16
  // fbm / ridge
  uint64_t seed = 1;               // displacement.seed
  int octaves = 6;                 // displacement.octaves (1..16)
  float frequency = 4;             // displacement.frequency (> 0): base cells across the texture
  float lacunarity = 2;            // displacement.lacunarity (> 0)
  float gain = 0.5f;               // displacement.gain (> 0)
  int resolution = 513;            // displacement.resolution (2..8192): generated texture is resolution^2
  // Sampler (all kinds): bilinear, clamp addressing, texture spread over the terrain's extent.
  int subtexelBits = 8;            // displacement.subtexel_bits (0..23, 0 = full float): filter weight precision
  TexelFormat format = TexelFormat::Float; // displacement.format: applied to the texels at load (r16_float: half)
  MipMode mip = MipMode::None;     // displacement.mip: the chain below is built at load only when not None
  // Filled by loadScene: texels (row-major, z rows of x texels, 0..1), texture size.
  std::shared_ptr<const std::vector<float>> texels;
  int texWidth = 0, texHeight = 0;
  // Filled by loadScene when mip != None: levels 1..n of a box-filtered chain down to 1 x 1 (after format).
  std::shared_ptr<const std::vector<MipLevel>> mips;
};

enum class LodScheme : uint8_t {
  Constant,       // "constant": every edge gets lod.factor (no camera, no lod/ call)
  ScreenSphere,   // "screen_sphere": NVIDIA (lod::screenSphere; on tile rings with size jumps lod::nvidiaTile)
  DistancePow2,   // "distance_pow2": Luna/Richards (lod::distancePow2; with size jumps lod::distancePow2Tile)
  Bonaventura,    // "bonaventura": rounded-exponent pow2 with camera-angle correction (lod::bonaventura; with size
                  // jumps lod::bonaventuraTile)
  ClipDiameter,   // "clip_diameter": clip-space sphere diameter (lod::clipDiameter; with size jumps
                  // lod::clipDiameterTile)
  PatchCenter,    // "patch_center": deliberately broken (lod::patchCenter): screen_sphere, but every edge's sphere
                  // sits at the patch centre instead of the edge midpoint (neighbours disagree); never gets the
                  // tile-ring neighbour rule (lod.adjacency_clamp / lod.reconstruction are refused with it)
  Geomorph,       // "geomorph": geomorphing (lod::geomorphLevel, lod::geomorph): float level per patch, integer
                  // partitioning at 2^(floor(L) + 1), borders at the coarser level, inserted vertices morphed by the
                  // domain shader (needs tessellation.partitioning = "integer" and patches of one size)
  Shader,         // "shader": the factors come from the user's shader (lod.shader) on the GPU, and nothing else;
                  // the default scheme when lod.shader is given (set lod.scheme to a built-in scheme instead to have
                  // a sweep compare the shader's factors with that scheme's C++ build)
};

// Where the hull factors are evaluated (lod.evaluate).
enum class LodEvaluate : uint8_t {
  Cpu, // "cpu" (default): lod/'s C++ build
  Gpu, // "gpu": the scheme's own lod/shaders/*.glsl (or lod.shader) on the local OpenGL driver, one compute dispatch
       // per camera (CheckOptions::factors provides them; the cli builds the provider, verify/gpu/gpu_lod.h); the
       // C++ build runs too, and where the two differ Report::factorDiffs says so. Not for "geomorph".
};

// Height bounds of each patch's culling box (lod.height_bounds).
enum class HeightBounds : uint8_t {
  Global,   // "global" (default): the displacement's whole range [min(0, scale), max(0, scale)] for every patch
  PerPatch, // "per_patch": Luna's BoundsY: min/max of the texels the patch's bilinear samples can reach (all mip
            // levels when displacement.mip is set), times height_scale
};
// Every scheme but patch_center gets the tile-ring neighbour rule (lod.h section 2 and 7: the smaller side
// rebuilds the larger neighbour's edge, takes the scheme's own factor of it and halves it; the clamp rounds both
// sides) on tile rings with more than one ring; "constant" through lod::constantTile.

// What the tessellator does with a denormal hull factor (lod.flush_denormals, CheckOptions::flushDenormals). The
// D3D11 reference keeps it: a denormal outer factor passes the cull test (x > 0) and the clamp makes it the minimum
// tessellation. Mesa's llvmpipe flushes it to zero first, so the patch is culled (docs/oracle.md; NVIDIA keeps it,
// measured on 306,348 patches). Which rule applies: DenormalRule / denormalRule below.
enum class DenormalFlush : uint8_t {
  Auto, // "auto" (default): the factor source's rule (the GPU path: the driver's, FactorProvider::flushesDenormals;
        // lod/'s C++ path: CheckOptions::tessellator.flushDenormals, default false = the D3D11 reference)
  On,   // true: flushed to zero before the tessellator (a denormal outer factor culls the patch)
  Off,  // false: kept (the reference)
};

// Clamp applied where a patch meets a neighbour of a different size (lod.adjacency_clamp = "none" | "integer" |
// "pow2"; tile rings with size jumps, every scheme but patch_center). See lod.h.
using AdjacencyClamp = lod::AdjacencyClamp;

// The scene's LOD: lod/'s own parameter structs, handed to lod/ as they are (no copies in between). A TOML key that
// several schemes share sets the field in each struct that has it (the parser does that, once). Defaults are
// lod.h's, except where a comment says otherwise.
struct Lod {
  LodScheme scheme = LodScheme::ScreenSphere; // lod.scheme
  float factor = 8;                           // lod.factor: constant
  // screen_sphere, patch_center. sphere.tessellatedTriWidth = lod.target_pixels (> 0); sphere.minFactor,
  // sphere.maxFactor = lod.min_factor, lod.max_factor (min <= max); sphere.frustumCull = lod.frustum_cull;
  // clamp = lod.adjacency_clamp; reconstruction = lod.reconstruction ("edge_vector" | "far_corner" | "resampled":
  // how the small side rebuilds its big neighbour's edge). clamp and reconstruction are the neighbour rule's for
  // every scheme (handed to the other schemes' lod::*Tile as a lod::TileAdjacency); they apply on tile rings with
  // size jumps only, and setting either key anywhere else is a scene error. reconstruction defaults to Resampled
  // here (lod.h's default for nvidiaTile alone is EdgeVector, which needs no heights).
  lod::NvidiaTileParams screenSphere = sceneTile();
  // distance_pow2: minDistance, maxDistance = lod.min_distance, lod.max_distance (max > min); minTessExponent,
  // maxTessExponent = lod.min_tess, lod.max_tess; frustumCull = lod.frustum_cull.
  lod::DistancePow2Params distancePow2{};
  // bonaventura: the distances as distance_pow2; minExponent, maxExponent = lod.min_tess, lod.max_tess;
  // angleCorrection = lod.angle_correction; rank = lod.rank (0..2; the scene's default is 0.4, the thesis' value;
  // lod.h's default for the scheme alone stays 0.5); minFactor, maxFactor; frustumCull.
  lod::BonaventuraParams bonaventura = sceneBonaventura();
  // clip_diameter: edgesPerScreenHeight = lod.edges_per_screen_height (> 0); minFactor, maxFactor; frustumCull =
  // lod.frustum_cull, which defaults to true here (lod.h's default for the scheme alone is false).
  lod::ClipDiameterParams clipDiameter = sceneClipDiameter();
  // geomorph: minDistance, maxDistance = lod.min_distance, lod.max_distance; finestLevel, coarsestLevel =
  // lod.finest_level, lod.coarsest_level (each in [0, 5]); literalArticleWeight = lod.literal_article_weight.
  lod::GeomorphParams geomorph{};
  // lod.shader: the user's LOD shader (docs/gpu_lod.md), the path as written resolved against the scene file's
  // folder; "" = none. Ends in .glsl (GLSL 4.50) or .hlsl (HLSL, through glslang and spirv-cross). Implies
  // evaluate = Gpu.
  std::string shader;
  LodEvaluate evaluate = LodEvaluate::Cpu; // lod.evaluate
  bool displacedCorners = true;  // lod.displaced_corners: corners raised to their height for the LOD (NVIDIA VS)
  HeightBounds heightBounds = HeightBounds::Global; // lod.height_bounds
  DenormalFlush flushDenormals = DenormalFlush::Auto; // lod.flush_denormals: "auto" | true | false

  static lod::BonaventuraParams sceneBonaventura() {
    lod::BonaventuraParams p;
    p.rank = 0.4f;
    return p;
  }
  static lod::NvidiaTileParams sceneTile() {
    lod::NvidiaTileParams p;
    p.reconstruction = lod::Reconstruction::Resampled;
    return p;
  }
  static lod::ClipDiameterParams sceneClipDiameter() {
    lod::ClipDiameterParams p;
    p.frustumCull = true;
    return p;
  }
};

// Domain-shader interpolation of the patch corners (domain.formula). lerp(a, b, t):
enum class LerpFormula : uint8_t {
  Nvidia,    // "nvidia" (default): the NVIDIA sample's Bilerp with HLSL lerp = a + t*(b - a), mul and add rounded
             // separately; identical to "lerp"
  Lerp,      // "lerp": a + t*(b - a)
  LerpFma,   // "lerp_fma": fma(t, b - a, a)
  Blend,     // "blend": a*(1 - t) + b*t
  BlendFma,  // "blend_fma": fma(b, t, a*(1 - t))
};

enum class LerpOrder : uint8_t {
  UFirst, // "u_first": lerp(lerp(c00, c10, u), lerp(c01, c11, u), v) (the NVIDIA sample)
  VFirst, // "v_first": lerp(lerp(c00, c01, v), lerp(c10, c11, v), u)
};

// Where the height texture coordinate comes from (domain.height_uv).
enum class HeightUv : uint8_t {
  World,        // "world": from the interpolated world x/z (NVIDIA): equal x/z means equal height
  Interpolated, // "interpolated": corner texture coordinates interpolated with domain.formula (Luna)
};

struct DomainShader {
  LerpFormula formula = LerpFormula::Nvidia; // domain.formula
  LerpOrder order = LerpOrder::UFirst;       // domain.order
  HeightUv heightUv = HeightUv::World;       // domain.height_uv
};

// A camera. fovY in degrees, viewport in pixels.
struct Camera {
  glm::vec3 eye{0, 40, -60}; // camera.eye (finite)
  glm::vec3 target{0, 0, 0}; // camera.target (finite, != eye)
  glm::vec3 up{0, 1, 0};     // camera.up (finite, not parallel to target - eye)
  float fovY = 60;           // camera.fov_y in (0, 180)
  float nearZ = 0.1f;        // camera.near (> 0)
  float farZ = 10000;        // camera.far (> near)
  int width = 1920;          // camera.width (>= 1)
  int height = 1200;         // camera.height (>= 1)
};

struct Scene {
  std::string source;          // file name the scene came from ("<string>" for parseScene)
  std::string name;            // name (optional)
  Layout layout;               // [layout]
  Displacement displacement;   // [displacement]
  Lod lod;                     // [lod]
  Partitioning partitioning = Partitioning::FractionalEven; // tessellation.partitioning
  Stage stage{};               // tessellation.stage: hw | hlsl-avg | hlsl-min | hlsl-max (+ -1axis)
  DomainShader domain;         // [domain]
  Camera camera;               // [camera]
  std::vector<Camera> cameraPath; // [[camera_path]]: each entry a full camera table (missing keys from [camera])
  // What the verdict depends on, hashed by the loader (sceneContentHash): FNV-1a 64 over the scene text, each
  // override, the heightmap's texels and the lod.shader file's bytes. Shards of one sweep must agree (fftess merge).
  uint64_t contentHash = 0;
};

// Result of loading: either a scene or an error message "file:line:col: key: what is wrong".
struct SceneResult {
  bool ok = false;
  Scene scene;
  std::string error;
  explicit operator bool() const { return ok; }
};

// Loads a scene file and applies overrides. Each override is "KEY=VALUE" with KEY a dotted path
// (lod.adjacency_clamp=integer, camera.eye=[0,10,0]); VALUE is parsed as a TOML value, a bare word as a string.
// Overrides are validated exactly like the file (unknown keys, types, ranges); their errors name "--set KEY".
// A heightmap file is read and its size checked; procedural displacement is baked into scene.displacement.texels.
SceneResult loadScene(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from text in memory; sourceName is used in messages and relative file paths resolve against baseDir.
SceneResult parseScene(const std::string& text, const std::string& sourceName = "<string>",
                       const std::vector<std::string>& overrides = {}, const std::string& baseDir = ".");

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
                                 // culled or discarded patches whose box touches the view frustum (verify.h, Hole)
  WorkStats& operator+=(const WorkStats& o);
};

// Layouts built by prepareTerrain in this process so far (all threads). `fftess check --json` prints the count, so
// a test can see that one command builds one terrain.
int64_t terrainBuildCount();

// ---------------------------------------------------------------------------------------------------------------
// The prepared terrain: everything about the scene that does not depend on the camera, computed once.

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
  const Scene& scene() const;
  int patchCount() const;
  const std::vector<PatchGeometry>& patches() const; // patches()[i] is patch i
  const Extent& extent() const;
  // The work of building it: terrainBuilds = 1, heightSamples = the corner heights sampled (4 per patch when
  // displaced, else 0; plus one per rebuilt corner with lod.reconstruction = "resampled" and raised corners).
  // Checking never adds to it.
  const WorkStats& stats() const;
  bool empty() const { return !data_; }
  const detail::TerrainData& data() const { return *data_; } // for verify's .cpp files

private:
  friend TerrainResult prepareTerrain(const Scene& scene);
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

// World position of domain point (u, v) of patch `patchIndex` as the scene's domain shader computes it.
// patchIndex: 0 .. terrain.patchCount() - 1 (else (0, 0, 0)). u, v in [0, 1].
glm::vec3 domainPosition(const Terrain& terrain, int patchIndex, float u, float v);

// ---------------------------------------------------------------------------------------------------------------
// Checking.

enum class Kernel : uint8_t {
  Epick,      // CGAL Exact_predicates_inexact_constructions_kernel: exact classification, gap in double (default)
  Epeck,      // CGAL Exact_predicates_exact_constructions_kernel: exact classification and exact gap
  FloatNaive, // CGAL Simple_cartesian<float>: predicates evaluated in float. Wrong on purpose (for comparison)
};

// One deliberate perturbation, applied inside checkScene, to prove that the checker sees it (the fault-injection
// suite, tests/verify/fault_injection_test.cpp). Kind::None (the default) changes nothing and costs nothing.
struct Fault {
  enum class Kind : uint8_t {
    None,
    FactorUlp,      // hull factor of (patch, edge) moved by `direction` ulps (std::nextafter), after the LOD
    FactorStep,     // hull factor of (patch, edge) plus direction * 2^-16 (one 16.16 step), in float
    PointUlp,       // world position of edge point `point` of (patch, edge): component `axis` (0 x, 1 y, 2 z)
                    // moved by one ulp towards +inf (direction > 0) or -inf, after the domain shader
    DropPatch,      // the patch is not drawn (as if the tessellator discarded it; the LOD did not cull it)
    NanFactor,      // hull factor of (patch, edge) set to NaN
    MirrorEdge,     // the edge points of (patch, edge) are taken at 1 - t instead of t (a port that walks the
                    // edge backwards); D3D's symmetric edge tessellation makes this a no-op for many factors
    NeighbourSize,  // the LOD is told that the neighbour across (patch, edge) has relative size `size`
    CullPatch,      // the LOD culls the patch (lod::Why::culled, every factor 0) as a wrong frustum test would
  };
  Kind kind = Kind::None;
  int patch = -1;       // PatchRef::index
  int edge = 0;         // FactorIndex: Ueq0 Veq0 Ueq1 Veq1
  int point = 0;        // PointUlp: index into the edge's points (0 = the edge's start corner)
  int axis = 0;         // PointUlp
  int direction = 1;    // FactorUlp, FactorStep, PointUlp: +1 or -1
  float size = 1;       // NeighbourSize: 0.5, 1 or 2
};

// ---------------------------------------------------------------------------------------------------------------
// Factors from somewhere else than lod/'s C++ build: the GPU path (lod.evaluate = "gpu", lod.shader). verify itself
// links no GL; verify/gpu/gpu_lod.h implements FactorProvider on an OpenGL driver and the cli hands it in
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
  explicit LodPatches(const Terrain& terrain);
  explicit LodPatches(const detail::TerrainData& data) : t_(&data) {}
  size_t size() const;
  LodInput operator[](size_t i) const;
  // The same for every view of one prepared terrain (a provider keys its uploaded inputs by it).
  const void* key() const { return t_; }
  // Patches of different sizes meet (tile rings with rings > 1): the built-in schemes run their *Tile variant.
  bool sizeJumps() const;
  const Scene& scene() const;

private:
  const detail::TerrainData* t_;
};

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

struct CheckOptions {
  Kernel kernel = Kernel::Epick;  // classification is exact with Epick and Epeck; they agree on every verdict
  size_t maxFindings = 1000;      // findings (and holes) kept in Report::findings / Report::holes (stats count all)
  bool keepMatches = false;       // also keep matching pairs as findings
  Options tessellator{};          // handed to fftess::edgePoints / Tessellator (flushDenormals)
  // Holes: whether a patch that is not drawn is visible is decided by splitting its (u, v) domain (see Hole):
  // sub-rectangles down to a side of 2^-visibilityDepth of the patch, at most visibilityBudget boxes per patch;
  // what is still open then is Visibility::Undecided (Report::undecided, never a clean verdict).
  int visibilityDepth = 10;       // 0..20 (10: 1/1024 of the patch side)
  int64_t visibilityBudget = 16384; // sub-rectangle boxes per patch (>= 1)
  Fault fault{};                  // testing the checker only
  // The GPU path: where the scene asks for it (lod.evaluate = "gpu" or lod.shader), the factors come from here.
  // Null there: every camera gets Report::error (verify links no GL; the cli builds it, verify/gpu/gpu_lod.h).
  std::shared_ptr<FactorProvider> factors;
  // Denormal hull factors (--flush-denormals on|off|auto): On/Off override the scene's lod.flush_denormals and the
  // driver's rule (denormalRule). tessellator.flushDenormals is the rule of lod/'s C++ path under Auto.
  DenormalFlush flushDenormals = DenormalFlush::Auto;
  // Findings the camera cannot see (Finding::onScreen false) count like the others: sweep's CameraResult::worst is
  // chosen among all findings. The Report and its Stats are the same either way (Stats keeps both numbers); pass
  // the same choice to verdictOf. The cli's --offscreen (whole-mesh comparisons, strict CI).
  bool countOffScreen = false;
};

// The denormal rule one check runs with, and where it came from: the first that is not Auto of
// CheckOptions::flushDenormals ("--flush-denormals"), lod.flush_denormals ("lod.flush_denormals"); else the driver's
// (FactorProvider::flushesDenormals, on the GPU path with a provider) or CheckOptions::tessellator.flushDenormals.
struct DenormalRule {
  bool flush = false;
  std::string why; // e.g. "--flush-denormals on", "the driver: llvmpipe (...) flushes denormal factors"
};
DenormalRule denormalRule(const Scene& scene, const CheckOptions& options);

enum class Classification : uint8_t {
  Match,      // every vertex on one side coincides exactly with a vertex on the other, in order, endpoints included
  TJunction,  // not a match, but every vertex of each side lies exactly on the other side's polyline
  Crack,      // some vertex lies off the other side's polyline: a visible gap
};

// The LOD's own record for one edge of one patch, as lod/ returned it (nothing guessed afterwards).
struct EdgeLod {
  LodScheme scheme = LodScheme::Constant; // the scene's scheme (Constant: lod/ did not run; why is empty)
  lod::FactorWhy why{};        // metric, unclamped factor, exponent and the fix bits (lod::Fix) of this edge
  bool culled = false;         // lod/ culled the patch (lod::Why::culled)
  // The neighbour rule: the neighbour's size relative to this patch as handed to lod::nvidiaTile / lod::*Tile (0.5:
  // this is the larger side, 2: the smaller side, which rebuilt the larger edge; 1: same size, or no adjacency code
  // ran),
  // the clamp applied at the jump and how the larger edge was rebuilt (both meaningful only when size != 1).
  float neighbourSize = 1;
  AdjacencyClamp clamp = AdjacencyClamp::None;
  lod::Reconstruction reconstruction = lod::Reconstruction::EdgeVector;
};

// One side of a shared edge.
struct EdgeSide {
  PatchRef patch;
  int edge = 0;                // FactorIndex of the edge in its patch: Ueq0 Veq0 Ueq1 Veq1
  float hullFactor = 0;        // factor the hull shader output (after the adjacency clamp)
  uint32_t hullFactorBits = 0; // its bits
  float processedFactor = 0;   // after the tessellator's processing (EdgePoints::processedFactor)
  bool culled = false;         // the patch is culled (by the LOD, or by the tessellator: some outer factor not > 0)
  EdgeLod lod;                 // where hullFactor came from
  float paramLo = 0, paramHi = 1; // the part of this edge that is shared, in its own edge parameter
  int pointCount = 0;          // edge points inside [paramLo, paramHi]
  int firstMismatch = -1;      // index (into those points) of the first vertex that differs, -1 if none
  DomainPoint mismatchDomain{};   // its (u, v)
  glm::vec3 mismatchWorld{};      // its world position
};

struct Finding {
  Classification classification = Classification::Match;
  EdgeSide a;                  // the bigger (or, same size, lower-index) patch
  EdgeSide b;
  Partitioning partitioning = Partitioning::FractionalEven; // the tessellator's partitioning (both sides)
  glm::vec3 edgeStart{}, edgeEnd{}; // the shared edge's ends (flat corners, world)
  // Crack: the vertex farthest from the other side's polyline and that distance (exact with Epeck; converted to
  // double for printing), whether or not the camera sees it. T-junction / match: 0.
  double gapWorld = 0;
  // gapWorld in pixels at the vertex's view depth, with lod's projection (lod::makeCamera): gapWorld *
  // projection[1][1] * viewport.y / 2 / depth, depth = -(view * vertex).z (0 if at or behind the eye plane).
  double gapPixels = 0;
  glm::vec3 gapVertex{};
  int gapSide = 0;             // 0: the vertex is on side a, 1: on side b
  // On screen (docs/verify.md, "On screen"): false only when the finding is proven outside the view frustum (near
  // and far planes included): every triangle of a strip zipped between its two sides has its box outside one plane.
  // Occlusion by other terrain is not considered. Matches: true.
  bool onScreen = true;
  // Crack on screen: the widest the gap is where the camera may see it: the largest of (1) the distance of each
  // off-polyline vertex whose gap segment (to the nearest point of the other side) is not proven off screen (exact
  // as gapWorld) and (2) the width (double) where either side's edge crosses the frustum's boundary; when neither
  // exists (no part of either edge in view, but the strip may be), gapWorld at gapVertex. onScreenGapVertex: where it
  // was measured (a vertex, or a point where an edge leaves the view). Pixels there, but never nearer than the near
  // plane: onScreenGapWorld * projection[1][1] * viewport.y / 2 / max(depth, camera.near). Off screen, T-junction,
  // match: 0.
  double onScreenGapWorld = 0;
  double onScreenGapPixels = 0;
  glm::vec3 onScreenGapVertex{};
  int onScreenGapSide = 0;     // 0: measured on side a, 1: on side b
};

// The LOD's record of one side in words: the fix names (lod::fixName, in bit order), then the neighbour rule
// ("neighbour 2x: rebuilt edge_vector", "neighbour 0.5x") and "culled"; "" when lod/ did not run or changed
// nothing. For printing; cli prints from the record itself where it needs more.
std::string lodWords(const EdgeSide& side);

// A hole: a patch that is not drawn although part of it would be on screen.
//
// Not drawn: lod/ culled it (its Why::culled), or the tessellator discards it because an outer factor is NaN, <= 0
// or -Inf (D3D11.3 11.7.6; the reference's culling rule) while lod/ did not mean to cull it. Whether such a patch is
// on screen is decided, not sampled (docs/verify.md, "Holes"), in double from lod's float matrices, on the
// displaced surface as the scene's domain shader positions it (every (u, v) in [0, 1]^2):
//   * the patch's (u, v) domain is split into dyadic sub-rectangles, breadth first. Each gets a conservative box of
//     the surface over it: x/z from the exact bilinear interpolation of the corners, padded by 2^-20 of their
//     magnitude (the domain shader's float lerps); y from the displacement texels its footprint can read on every
//     mip level the domain shader samples there (bilinear and trilinear filtering and geomorph blending stay
//     between the texels they read), times height_scale, padded by 2^-16 (float rounding of the filters);
//   * a box wholly outside one plane of the view frustum: that part is invisible;
//   * its centre (and at the root and the finest level its corners), evaluated by the domain shader emulation,
//     strictly inside the frustum (clip space: |x|, |y| < w, -w < z < w): the patch is Visible;
//   * otherwise it is split, down to a side of 2^-CheckOptions::visibilityDepth (1/1024 of the patch), with at most
//     CheckOptions::visibilityBudget boxes per patch.
// Every part invisible: Invisible, nothing reported. A point found: a hole (Report::holes):
//   Discarded          the tessellator discards the patch but lod/ did not cull it;
//   CulledWhileVisible lod/'s frustum test culled the patch (a height bound too small, a wrong plane, a patch box
//                      that misses its displaced surface).
// Neither (a finest sub-rectangle still straddles a plane, or the budget ran out): Visibility::Undecided, listed in
// Report::undecided with the same record (kind: culled or discarded), counted in Stats::undecided; the verdict is
// Verdict::Undecided unless there are cracks or holes. Never a clean verdict.
enum class HoleKind : uint8_t { Discarded, CulledWhileVisible };
enum class Visibility : uint8_t { Invisible, Visible, Undecided };

struct Hole {
  HoleKind kind = HoleKind::Discarded;
  PatchRef patch;
  Visibility visibility = Visibility::Visible;
  glm::vec3 visiblePoint{};    // a point of the patch inside the frustum (Visibility::Visible)
  // Discarded: the first outer edge (FactorIndex order) whose factor made the tessellator discard the patch, and
  // its factor, bits and lod/'s record. CulledWhileVisible: edge -1; factor is the cull value lod/ wrote.
  int edge = -1;
  float hullFactor = 0;
  uint32_t hullFactorBits = 0;
  float factors[6] = {0, 0, 0, 0, 0, 0}; // the patch's six hull factors (Ueq0 Veq0 Ueq1 Veq1 insideU insideV)
  EdgeLod lod;                 // lod/'s record of that edge (CulledWhileVisible: of Ueq0)
  // The edge's midpoint (lod's corners) in view space: w = -z, the projection's divisor. 0: the eye lies in the
  // plane through the midpoint parallel to the image (a projected size of 0/0 or x/0).
  float midpointW = 0;
  // The y range of the box lod/'s frustum test culls with (its corners' y, widened by its height bounds), next to
  // the y where the surface was seen: a culled-while-visible hole with visiblePoint.y outside it is a height bound
  // too small.
  float lodBoxMinY = 0, lodBoxMaxY = 0;
  // On screen (docs/verify.md, "On screen"): true for every reported hole. A hole is never proven off screen: a
  // patch whose surface box is outside the frustum is Invisible and no hole; Visible holes have a point inside the
  // frustum; Undecided ones may be on screen and count as on screen.
  bool onScreen = true;
  // Visible: the (u, v) of visiblePoint. Undecided: the lower corner of the first sub-rectangle left undecided.
  DomainPoint domainPoint{};
  float undecidedSide = 0;     // Undecided: that sub-rectangle's side in (u, v) units (2^-visibilityDepth, or
                               // larger when the budget ran out first)
  bool budgetExhausted = false; // Undecided: CheckOptions::visibilityBudget boxes were built before a decision
};

const char* toString(HoleKind k);  // "discarded", "culled_while_visible"
const char* toString(Visibility v); // "invisible", "visible", "undecided"

struct Stats {
  int64_t patches = 0;         // patches in the layout
  int64_t culledPatches = 0;   // culled by the LOD (frustum) or by the tessellator (factor not > 0)
  int64_t edgesChecked = 0;    // shared edge pairs classified (a 2x jump counts as two pairs)
  int64_t skippedCulled = 0;   // shared edge pairs not classified because a side is culled (or a hole)
  int64_t holes = 0;           // Hole findings (both kinds)
  int64_t holesDiscarded = 0;  // HoleKind::Discarded
  int64_t holesCulledVisible = 0; // HoleKind::CulledWhileVisible
  int64_t culledUndecided = 0; // lod-culled patches neither proven invisible nor visible (see Hole)
  int64_t visibilityTests = 0; // culled or discarded patches whose box touched the frustum (domain split)
  int64_t matches = 0;
  int64_t tJunctions = 0;
  int64_t cracks = 0;
  double worstGapWorld = 0;
  double worstGapPixels = 0;
  // Patches not drawn whose visibility stayed undecided (Report::undecided; culled ones also in culledUndecided):
  // the verdict is Undecided unless there are cracks or holes.
  int64_t undecided = 0;
  // The GPU path with a C++ reference (lod.evaluate = "gpu", or lod.shader with a built-in lod.scheme): factors
  // compared, those whose bits differ, and those of them that change the tessellation (FactorDiff).
  int64_t factorsCompared = 0;
  int64_t factorDiffs = 0;
  int64_t factorDiffsTessellation = 0;
  int64_t denormalFactors = 0; // hull factors the source returned as denormals (DenormalFactor), flushed or not
  // On screen (docs/verify.md, "On screen"). cracks, tJunctions, worstGapWorld and worstGapPixels above count every
  // finding (whole-mesh comparisons); of them, these are proven off screen (Finding::onScreen false): the factors
  // that made them belong to this camera, so no other camera sees them either. verdictOf counts only the on-screen
  // ones unless asked for all. Holes are on screen by construction (Hole::onScreen).
  int64_t cracksOffScreen = 0;
  int64_t tJunctionsOffScreen = 0;
  double worstGapWorldOnScreen = 0;  // the maxima of Finding::onScreenGapWorld / onScreenGapPixels
  double worstGapPixelsOnScreen = 0;
  int64_t cracksOnScreen() const { return cracks - cracksOffScreen; }
  int64_t tJunctionsOnScreen() const { return tJunctions - tJunctionsOffScreen; }
};

struct Report {
  std::string error;             // non-empty: the camera is invalid and nothing was checked
  std::vector<Finding> findings; // non-matching pairs (and matches with keepMatches), in layout order
  std::vector<Hole> holes;       // holes, in layout order (at most maxFindings; Stats::holes counts all)
  std::vector<Hole> undecided;   // patches not drawn, visibility undecided (Hole::visibility Undecided), in layout
                                 // order (at most maxFindings; Stats::undecided counts all)
  std::vector<FactorDiff> factorDiffs; // GPU vs C++ build, in layout order (at most maxFindings; Stats counts all)
  std::vector<DenormalFactor> denormalFactors; // in layout order (at most maxFindings; Stats counts all)
  bool denormalsFlushed = false; // the rule this camera ran with (denormalRule)
  bool truncated = false;        // more findings than maxFindings
  Stats stats;
  WorkStats work;                // this camera's work (camera-dependent only; see Terrain::stats())
};

// Checks every shared edge of the terrain from one camera.
// terrain: from prepareTerrain. camera: finite values; a camera behind, inside or on a patch is fine (the LOD
// decides what is culled); an invalid camera gives Report::error.
Report checkScene(const Terrain& terrain, const Camera& camera, const CheckOptions& options = {});

// Whole-mesh check: tessellates every patch fully (fftess::Tessellator), builds a CGAL polygon soup, merges
// exactly-equal points, repairs degenerate polygons, converts it to a CGAL Surface_mesh and lists every border
// edge (CGAL Polygon Mesh Processing) that is not on the terrain's outer boundary. Each such edge is attributed to
// the patch edge it came from. Agrees with checkScene: the set of patch edges with inner border edges equals the
// set of patch edges that take part in a T-junction or crack finding (see flaggedPatchEdges).
struct PatchEdgeRef {
  int patch = -1;              // PatchRef::index
  int edge = 0;                // FactorIndex
  bool operator<(const PatchEdgeRef& o) const { return patch != o.patch ? patch < o.patch : edge < o.edge; }
  bool operator==(const PatchEdgeRef& o) const { return patch == o.patch && edge == o.edge; }
};

struct MeshReport {
  std::string error;             // non-empty: the camera is invalid and nothing was checked
  int64_t patchesDrawn = 0;
  int64_t triangles = 0;         // after removing degenerate (repeated-vertex) triangles
  int64_t vertices = 0;          // after merging exactly-equal points
  int64_t borderEdges = 0;       // all border edges
  int64_t innerBorderEdges = 0;  // border edges not on the terrain's outer boundary (cracks and T-junctions)
  std::vector<PatchEdgeRef> flagged; // sorted, unique: patch edges holding an inner border edge
  WorkStats work;                // this camera's work
};

// terrain: from prepareTerrain; camera as for checkScene.
MeshReport checkSceneMesh(const Terrain& terrain, const Camera& camera, const CheckOptions& options = {});

// The patch edges of a report's non-matching findings (both sides), sorted and unique: compare with
// MeshReport::flagged. Needs maxFindings large enough that the report is not truncated.
std::vector<PatchEdgeRef> flaggedPatchEdges(const Report& report);

// ---------------------------------------------------------------------------------------------------------------
// Cameras for sweeps. All return cameras with the scene camera's fov, near, far and viewport; none builds a layout
// (they read terrain.extent()).

// The scene's camera path, or just the scene camera when it has none.
std::vector<Camera> pathCameras(const Terrain& terrain);
// count (>= 0) cameras on a circle around the terrain centre, looking at the centre. radius <= 0: half the extent;
// height <= 0: a quarter of the radius.
// cancel (all generators): when it becomes true, generation stops and the cameras made so far are returned.
std::vector<Camera> orbitCameras(const Terrain& terrain, int count, float radius = 0, float height = 0,
                                 const std::atomic<bool>* cancel = nullptr);
// count cameras on a straight line across the terrain (diagonal, -x-z to +x+z) at `height` above it (<= 0: 2% of
// the extent plus the displacement scale), looking along the flight direction and slightly down.
std::vector<Camera> flyoverCameras(const Terrain& terrain, int count, float height = 0,
                                   const std::atomic<bool>* cancel = nullptr);
// count cameras at uniform random positions over the extent, heights in (0, 25% of extent], random yaw, pitch
// in [-60, 0] degrees. Deterministic for a seed (splitmix64, same on every platform).
std::vector<Camera> randomCameras(const Terrain& terrain, int count, uint64_t seed,
                                  const std::atomic<bool>* cancel = nullptr);

// The same cameras by index: CameraSet::at(i) is camera i of the generator above with the same arguments (the same
// floats), computed when asked for (a random camera from (seed, i): splitmix64 is counter-based), so a set of any
// size costs the same memory; path() keeps the scene's list. at(i) needs i < size(); safe to call from several
// threads at once.
class CameraSet {
public:
  static CameraSet path(const Terrain& terrain);
  static CameraSet orbit(const Terrain& terrain, size_t count, float radius = 0, float height = 0);
  static CameraSet flyover(const Terrain& terrain, size_t count, float height = 0);
  static CameraSet random(const Terrain& terrain, size_t count, uint64_t seed);
  size_t size() const { return count_; }
  Camera at(size_t i) const;

private:
  enum class Kind : uint8_t { List, Orbit, Flyover, Random };
  CameraSet(Kind kind, const Terrain& terrain, size_t count);
  Camera looking(glm::vec3 eye, glm::vec3 target) const;
  Kind kind_;
  size_t count_;
  Camera base_;                 // the scene camera (fov, near, far, viewport), up = +y
  double cx_ = 0, cz_ = 0, size_ = 0; // the extent's centre and larger side
  double radius_ = 0, height_ = 0;    // orbit radius; orbit / flyover height
  uint64_t seed_ = 0;
  std::vector<Camera> list_;    // path()
};


struct CameraResult {
  size_t cameraIndex = 0;
  bool done = false;             // false: skipped because of cancel, or invalid (error set)
  std::string error;             // the camera could not be checked (Report::error); done is false
  Stats stats;
  bool hasFinding = false;
  // The finding with the largest gap (first crack or T-junction if no gap) among the findings that count: the
  // on-screen ones by their onScreenGapWorld, or with CheckOptions::countOffScreen all of them by gapWorld.
  Finding worst;
  bool hasHole = false;
  Hole firstHole;                // the first hole in layout order
  bool hasUndecided = false;
  Hole firstUndecided;           // the first undecided patch (Report::undecided) in layout order
};

struct SweepOptions {
  int threads = 0;               // 0: std::thread::hardware_concurrency()
  // Called after each camera from a worker thread (serialised by the driver): cameras done, cameras total.
  std::function<void(size_t done, size_t total)> progress;
  const std::atomic<bool>* cancel = nullptr; // set to true to stop; cameras not started are skipped
  bool keepReports = false;      // keep every camera's full report (else only its stats and first finding)
  // Called once per camera checked, with the camera's index into `cameras` and its full report (findings as
  // CheckOptions::maxFindings keeps them; Report::error set if the camera was invalid), before `progress` for that
  // camera. Thread-safety: called from worker threads, but never concurrently: sweep serialises it (with
  // `progress`) under one lock, so the callback needs no locking of its own. Order: the order cameras finish,
  // which with threads > 1 is not camera order; order-sensitive callers key their results by cameraIndex.
  // Cameras skipped because of cancel are not reported. The report is only valid during the call. Must not throw
  // (an exception on a worker thread ends the process).
  std::function<void(size_t cameraIndex, const Report& report)> onReport;
  // Called right after onReport for the same camera, under the same lock, with the camera's summary (what
  // SweepResult::cameras keeps). Same rules as onReport.
  std::function<void(const CameraResult& camera)> onCamera;
  // Keep one CameraResult per camera in SweepResult::cameras (default). false: SweepResult::cameras stays empty and
  // the sweep's memory does not grow with the camera count (the aggregates are kept; onCamera sees each camera).
  bool keepCameras = true;
};

struct SweepResult {
  std::vector<CameraResult> cameras; // one per input camera, in input order (empty unless SweepOptions::keepCameras)
  std::vector<Report> reports;       // keepReports: one per camera (empty reports for skipped cameras)
  Stats total;                       // summed over cameras done; worst gaps are maxima
  WorkStats work;                    // summed over cameras done (the terrain's own work is terrain.stats())
  size_t camerasDone = 0;            // cameras checked
  size_t camerasInvalid = 0;         // cameras that could not be checked (CameraResult::error)
  size_t camerasNothingChecked = 0;  // cameras done that classified no shared edge (everything culled, say)
  size_t camerasUndecided = 0;       // cameras done with Stats::undecided > 0 (not clean)
  bool cancelled = false;
};

// The verdict of a report or a sweep, in one place (the cli turns it into words and an exit status).
enum class Verdict : uint8_t {
  Watertight,      // at least one shared edge classified, every one a match, no hole, no undecided patch, every
                   // camera checked (by default: every finding off screen; see verdictOf)
  TJunctionsOnly,  // as Watertight but some T-junctions (no gap now; a gap once displacement differs)
  Cracks,          // at least one crack (holes may come with them)
  Holes,           // at least one hole, no crack
  NothingChecked,  // no shared edge was classified (and no crack or hole): not clean
  Unchecked,       // some cameras could not be checked (and no crack or hole): not clean
  Undecided,       // some patch not drawn could be neither proven visible nor invisible (and no crack or hole): not
                   // clean. Precedence: Cracks, Holes, Undecided, NothingChecked, Unchecked, TJunctionsOnly, Watertight
};
// countOffScreen false (default): cracks and T-junctions proven off screen (Stats::cracksOffScreen,
// tJunctionsOffScreen) do not count; true: every finding counts (CheckOptions::countOffScreen, the cli's --offscreen).
Verdict verdictOf(const Stats& s, bool countOffScreen = false);
Verdict verdictOf(const SweepResult& r, bool countOffScreen = false);

// Adds one camera's (or one shard's) stats to a total: every count summed, the worst gaps the maxima. What sweep
// does per camera; merging shards does it per shard.
void accumulate(Stats& total, const Stats& s);
const char* toString(Verdict v); // "watertight", "t_junctions", "cracks", "holes", "nothing_checked", "unchecked",
                                 // "undecided"

// Checks every camera against the one prepared terrain (shared read-only by the threads).
SweepResult sweep(const Terrain& terrain, const std::vector<Camera>& cameras, const CheckOptions& options = {},
                  const SweepOptions& sweepOptions = {});
// The same over `count` cameras made when needed: cameraAt(i) (i < count; called from the worker threads, possibly at
// once) is camera i. Memory does not grow with count unless SweepOptions::keepCameras / keepReports ask for it.
SweepResult sweep(const Terrain& terrain, size_t count, const std::function<Camera(size_t)>& cameraAt,
                  const CheckOptions& options = {}, const SweepOptions& sweepOptions = {});

// Names as the scene format spells them.
const char* toString(Classification c);
const char* toString(LayoutKind k);
const char* toString(DisplacementKind k);
const char* toString(LodScheme s);
const char* toString(AdjacencyClamp c);
const char* toString(lod::Reconstruction r);
const char* toString(LerpFormula f);
const char* toString(MipMode m);
const char* toString(TexelFormat f);
const char* toString(HeightBounds b);
const char* toString(LodEvaluate e); // "cpu", "gpu"
const char* toString(Kernel k);
bool parseKernel(const char* s, Kernel& out);

} // namespace fftess::verify
