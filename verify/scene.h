// fftess verify, stage 1: the scene (docs/verify.md, "Scene files"). A scene file (TOML) or text in memory, plus
// KEY=VALUE overrides, parsed and validated into a Scene: the layout, the displacement texture (read or generated,
// format applied, mip chain built), the LOD scheme and its parameters, the tessellator's partitioning and stage, the
// domain shader's interpolation and the cameras. Parse and validate happen together: a Scene is only returned
// valid, and bad input is an error value naming the key and its file position (or the override), never an
// exception. Every other stage starts from a Scene (terrain.h: prepareTerrain).
#pragma once

#include "lod/lod.h"
#include "tessellator/names.h" // toString / parse of the tessellator enums in Scene
#include "tessellator/tessellator.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fftess::verify {

// Scene model. Every field has the default the scene format documents (docs/verify.md); the TOML key is named in
// each comment. The terrain lies in the x/z plane, y is up. Domain u runs along +x, v along +z:
//   Ueq0 = the patch's -x edge, Ueq1 = +x, Veq0 = -z, Veq1 = +z (D3D quad domain, see tessellator.h).

enum class LayoutKind : uint8_t {
  Grid,          // "grid": patches_x * patches_z patches of one size
  TileRings,     // "tile_rings": NVIDIA sample: ring 0 is tiles_per_ring_edge^2 tiles; each further ring is the same
                 // count of tiles of twice the size with the inner half (the previous ring) cut out
  HeightmapGrid, // "heightmap_grid": Luna/Richards: one patch per cells_per_patch heightmap cells
  Quadtree,      // "quadtree": a restricted quadtree over roots_x * roots_z roots, rebuilt per camera (CDLOD's
                 // distance ranges or a screen-space error bound; balance 2:1 or none): docs/verify.md, "Quadtree"
  Patches,       // "patches": the user's own static layout, one square patch per face of an OBJ of quads or per
                 // row of a CSV of corners (layout.file); adjacency derived exactly from the coordinates
};

// How a quadtree node decides to split (layout.split).
enum class QuadtreeSplit : uint8_t {
  Distance,    // "distance" (default): CDLOD (Strugar 2009): a node of level L > 0 (leaves are level 0) splits when
               // its bounding box comes within lod_distance * lod_distance_ratio^(L - 1) of the eye
  ScreenError, // "screen_error": chunked LOD (Ulrich 2002): splits while its projected geometric error
               // geometric_error * node size * (viewport height / 2) / tan(fov_y / 2) / distance exceeds
               // max_pixel_error
};
// Whether the selected leaves are balanced (layout.balance).
enum class QuadtreeBalance : uint8_t {
  TwoToOne, // "2to1" (default): restricted quadtree: leaves that share an edge differ by at most one level
  None,     // "none": as selected (a leaf may meet a neighbour 4x, 8x ... its size)
};

// How the four corners of a patch are obtained (layout.corners).
enum class CornerMode : uint8_t {
  Reconstructed, // "reconstructed": tile origin + (i / patches_per_tile_edge) * tile_size, in float, per tile, as the
                 // NVIDIA sample rebuilds them from the vertex id (neighbouring tiles may disagree in the last bit)
  Shared,        // "shared": every corner computed once (double, rounded to float) in a shared vertex buffer
};

// layout.kind = "patches": one patch of layout.file as the loader read it: its four corners in fftess's corner order
// (corners[u + 2v]: [0] the -x-z corner, [1] +x-z, [2] -x+z, [3] +x+z; y ignored) and the line it came from.
struct LayoutPatch {
  glm::vec2 corners[4]; // (x, z)
  int line = 0;         // 1-based line of layout.file (the OBJ face or the CSV row)
};

// [layout]: which patches make the terrain. Defaults as initialised (docs/verify.md, the scene format).
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
  // quadtree (centred on layout.center; corners: layout.corners, "reconstructed" = per root, root origin +
  // (i / 2^max_depth) * root_size in float, "shared" = from the integer lattice in double; docs/verify.md, "Quadtree")
  float rootSize = 64;                     // layout.root_size (> 0): world size of a root node
  int rootsX = 1, rootsZ = 1;              // layout.roots_x, layout.roots_z (1..64)
  int maxDepth = 5;                        // layout.max_depth (0..10): leaves are root_size / 2^max_depth
  QuadtreeSplit split = QuadtreeSplit::Distance; // layout.split
  float lodDistance = 16;                  // layout.lod_distance (> 0): CDLOD's finest range (split = distance)
  float lodDistanceRatio = 2;              // layout.lod_distance_ratio (>= 1): range growth per level
  float maxPixelError = 4;                 // layout.max_pixel_error (> 0): split = screen_error
  float geometricError = 0.0625f;          // layout.geometric_error (> 0): a node's world error per unit of size
  QuadtreeBalance balance = QuadtreeBalance::TwoToOne; // layout.balance
  // patches
  std::shared_ptr<const std::vector<struct LayoutPatch>> patchList; // layout.file as read by the loader
  std::string file;                        // layout.file: the OBJ (.obj) or CSV (.csv) of patches, resolved
                                           // against the scene file's folder (docs/verify.md, "Patches")
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

// [displacement]: the height texture, its sampler and its mip chain. Defaults as initialised.
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
       // per camera (CheckOptions::factors provides them; the cli builds the provider, gpu_lod/gpu_lod.h); the
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
// [lod.uniforms] of a hull shader as written: one uniform, uniform-block / cbuffer member or sampler of the shader,
// bound by its name to numbers or to a value fftess computes (kLodUniformValues).
struct UniformBinding {
  std::string name;            // the key: the uniform's, the member's (without or with "Block."), the sampler's /
                               // the HLSL texture's name
  std::vector<double> numbers; // a number, a boolean (1 / 0) or an array of them, nested arrays flattened in the
                               // order the shader indexes them (m[i][j]: GLSL mat column i, HLSL matrix row i)
  std::string value;           // or a named value (one of kLodUniformValues), "" for numbers
  bool transpose = false;      // "transpose(NAME)": the matrix NAME transposed (for mul(v, M) row-vector code)
  int line = 0, column = 0;    // the value's position in the scene file (0: from --set)
};
// The named values of [lod.uniforms] (docs/gpu_lod.md lists what each is). Matrices map column vectors
// (clip = M * p in GLSL, mul(M, p) in HLSL); *_d3d: the projection with depth in [0, w] (D3D), others as the camera.
inline const char* const kLodUniformValues[] = {
    "view", "projection", "view_projection", "projection_d3d", "view_projection_d3d", "world", "eye", "viewport",
    "frustum_planes", "frustum_planes_gl", "frustum_planes_d3d", "near", "far", "fov_y", "heightmap",
    "height_scale", "terrain_min", "terrain_size", "patch_size", "heightmap_size", "heightmap_texel",
    "projection_vulkan", "view_projection_vulkan"};
// [lod.inputs]: a per-control-point input of the hull shader, bound by its name to what the control point carries.
struct InputBinding {
  std::string name;  // the key: the GLSL input variable / block member, the HLSL struct member or semantic
  std::string value; // one of kLodInputValues, or "" for a constant
  std::vector<double> numbers; // a constant, the same for every control point (e.g. a normal [0, 1, 0])
  int line = 0, column = 0;
};
inline const char* const kLodInputValues[] = {"position", "position_flat", "position_xz", "uv", "bounds_y",
                                              "patch_size"};
// The world direction of a hull shader's domain axis (lod.domain_u / lod.domain_v).
enum class DomainAxis : uint8_t { PlusX, MinusX, PlusZ, MinusZ };

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
  // folder; "" = none. A lodMain file (.glsl GLSL 4.50, .hlsl HLSL) or a hull shader as written (.tesc,
  // .tesc.glsl, .glsl with layout(vertices = N) out; .hlsl / .fx with [patchconstantfunc]). Implies evaluate = Gpu.
  std::string shader;
  // A hull shader as written (lod.shader a GLSL tessellation control shader or an HLSL hull shader; docs/gpu_lod.md
  // "Your hull shader as written"): how the scene feeds it. Refused with a lodMain file.
  std::string entry;            // lod.entry: the HLSL hull shader function ("" = the one with [patchconstantfunc])
  int entryLine = 0, entryColumn = 0; // lod.entry's position in the scene file (0: from --set or absent)
  std::string evaluationShader; // lod.evaluation_shader: the GLSL TES / HLSL domain shader (resolved like lod.shader;
                                // "" = none): its domain and partitioning are checked against the scene
  std::vector<UniformBinding> uniforms; // [lod.uniforms], in file order
  std::vector<InputBinding> inputs;     // [lod.inputs], in file order
  int controlPoints = 4;                // lod.control_points: 4 (a patch's corners) or 1 (one point per patch)
  std::array<int, 4> cornerOrder{{0, 1, 2, 3}}; // lod.corner_order: fftess's corner (u + 2v) of each control point
  DomainAxis domainU = DomainAxis::PlusX;       // lod.domain_u: the world direction of the shader's domain u
  DomainAxis domainV = DomainAxis::PlusZ;       // lod.domain_v: ... of its v (the other axis)
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

// Clip-space convention of a camera (camera.convention): what the LOD's inputs (lod::Camera's projection and
// frustum planes, a hull shader's projection / frustum_planes uniforms) are built in. The frustum itself, and so every
// verdict, is the same in both.
enum class CameraConvention : uint8_t {
  Gl,  // "gl" (default): right-handed view (looking down -z), depth in [-w, w]
  D3d, // "d3d": left-handed view (looking down +z, D3DXMatrixLookAtLH / PerspectiveFovLH), depth in [0, w]
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
  CameraConvention convention = CameraConvention::Gl; // camera.convention
};

// A whole scene: what loadScene / parseScene return, valid (every key checked). Defaults as initialised.
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
  // override, the heightmap's texels, the lod.shader file's bytes and (layout.kind = "patches") layout.file's bytes.
  // Shards of one sweep must agree (fftess merge).
  uint64_t contentHash = 0;
  // Where the file sets each key: dotted key ("lod.adjacency_clamp", "camera.eye"; a table's own name for its header,
  // "lod") -> its 1-based line in the file. Keys of the file only: a key --set adds has no line, one --set replaces
  // keeps the file's. Arrays of tables ([[camera_path]]) are not listed. For reports that point at the key
  // (fftess check --sarif / --junit).
  std::map<std::string, int> keyLines;
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

// Names as the scene format spells them (the TOML values above; "?" for a value out of range).
const char* toString(LayoutKind k);
const char* toString(QuadtreeSplit s);    // "distance", "screen_error"
const char* toString(QuadtreeBalance b);  // "2to1", "none"
const char* toString(CameraConvention c); // "gl", "d3d"
const char* toString(DisplacementKind k);
const char* toString(LodScheme s);
const char* toString(AdjacencyClamp c);
const char* toString(lod::Reconstruction r);
const char* toString(LerpFormula f);
const char* toString(MipMode m);
const char* toString(TexelFormat f);
const char* toString(HeightBounds b);
const char* toString(LodEvaluate e); // "cpu", "gpu"

} // namespace fftess::verify
