// fftess_lod_gpu_drift: how far the GLSL build of lod/shaders/*.glsl drifts from the C++ (GLM) build, bit for bit,
// on a real GPU. See tests/tools/lod_gpu_drift/README.md and docs/lod.md, "Known GPU divergence" / "Measured on NVIDIA".
//
//   fftess_lod_gpu_drift [options] [CASES [SEED]]      (defaults: 200000 cases, seed 1)
//     --precise          declare the shader's result variables `precise` (the LodResult each scheme returns, the
//                        geomorph levels); the shared sources have no macro for their own intermediates
//     --nv-pragmas       put NVIDIA's `#pragma optionNV(fastmath off)` and `optionNV(fastprecision off)` first
//     --allow-llvmpipe   accept a software renderer (the local self-test); default: hardware only
//     --examples N       print up to N differing factors per scheme (default 3)
//
// One case = a camera over a terrain and a patch (corners with displaced heights, its four neighbours for
// geomorphing, tile-neighbour sizes and parities). Both sides evaluate, on the same input bits:
//   screen-sphere, nvidia-tile with adjacency clamp none / integer / pow2 (EdgeVector rebuild), distance-pow2,
//   bonaventura, clip-diameter (frustumCull on), geomorph (the patch's and its neighbours' levels, then factors),
// every parameter at the lod.h default. The GPU side is a GL 4.5 compute shader built by text concatenation of
// lod::glslSource(0..n-1) after "#version 450" (what tests/lod/glsl_test.cpp does), writing floatBitsToUint of every
// value to an SSBO. Compared per scheme: bit-identical factors, max ulp distance, factors culled on one side only,
// and whether a difference changes the tessellation: fftess::edgePoints(factor, FractionalEven / Integer) differ
// (point count or any 16.16 position). Exit status: 0 = measured (differences are results, not failures);
// 1 = usage; 3 = no suitable GL 4.5 context; 4 = shader compile/link or GL error.
#include "base/bits.h"
#include "base/splitmix64.h"
#include "lod/glsl_settings.h"
#include "lod/lod.h"
#include "tessellator/tessellator.h"
#include "gl/gl_context.h" // headless EGL context, GL loader, renderer check (the GL module, fftess_gl)

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using fftess::lod::Camera;
using fftess::lod::Patch;

// ---------------------------------------------------------------- input layout (uint words per case)
constexpr int kInView = 0;       // 16 floats, column-major
constexpr int kInProj = 16;      // 16 floats
constexpr int kInViewport = 32;  // 2
constexpr int kInEye = 34;       // 3
constexpr int kInZeroToOne = 37; // uint
constexpr int kInGrid = 38;      // 4x4 grid of vec3, row j (z) major, column i (x): 48 floats; patch = rows/cols 1..2
constexpr int kInHeightBounds = 86; // uint useHeightBounds, float minHeight, float maxHeight
constexpr int kInTileSize = 89;  // 4 floats (0.5, 1, 2)
constexpr int kInOddU = 93;      // uint
constexpr int kInOddV = 94;      // uint
constexpr int kInCategory = 95;  // uint (camera category, host only)
constexpr int kInStride = 96;

// ---------------------------------------------------------------- output layout
constexpr int kSchemes = 8;
const char* const kSchemeNames[kSchemes] = {"screen-sphere",  "nvidia-tile none", "nvidia-tile integer",
                                            "nvidia-tile pow2", "distance-pow2",    "bonaventura",
                                            "clip-diameter",  "geomorph"};
// per scheme: 6 factors, 6 unclamped, 1 culled flag -> 13 words
constexpr int kOutPerScheme = 13;
constexpr int kOutCorner = kSchemes * kOutPerScheme;   // bonaventura cornerLevel[4]
constexpr int kOutLevels = kOutCorner + 4;             // geomorph level of the patch and its 4 neighbours
constexpr int kOutStride = kOutLevels + 5;

constexpr int kCategories = 5;
const char* const kCategoryNames[kCategories] = {"general", "near", "far", "edge-on", "random"};

using fftess::bitsOf;
using fftess::floatOf;

// ---------------------------------------------------------------- generator
// splitmix64 (base/splitmix64.h), with the draws this tool has always made.
struct Rng {
  fftess::SplitMix64 g;
  double uni() { return g.unitDouble(); } // [0, 1)
  double range(double a, double b) { return a + (b - a) * uni(); }
  int below(int n) { return static_cast<int>(g.next() % static_cast<uint64_t>(n)); }
};

// Displaced terrain: a few octaves of sines (double, rounded once to float).
float terrainHeight(double x, double z, int kind) {
  if (kind == 0) return 0.0f; // flat
  double h = 40.0 * std::sin(0.013 * x) * std::cos(0.011 * z) + 8.0 * std::sin(0.07 * x + 0.3) * std::sin(0.05 * z) +
             1.5 * std::sin(0.9 * x) * std::cos(0.7 * z);
  if (kind == 2) h *= 6.0; // mountains
  return static_cast<float>(h);
}

struct Case {
  uint32_t w[kInStride];
  Camera cam;
  glm::vec3 grid[4][4]; // [j][i]
  Patch patch;
  fftess::lod::TileNeighbours tile;
  int category = 0;
};

void buildCase(Rng& rng, Case& c) {
  const int kind = rng.below(4) == 0 ? 0 : (rng.below(4) == 0 ? 2 : 1);
  const float size = std::ldexp(1.0f, rng.below(7)); // 1 .. 64
  const int gi = rng.below(128) - 64, gj = rng.below(128) - 64;
  // Origin on the grid (exact floats) or, for a quarter of the cases, at an arbitrary float offset.
  double ox = static_cast<double>(gi) * size, oz = static_cast<double>(gj) * size;
  if (rng.below(4) == 0) ox += rng.range(-0.5, 0.5) * size, oz += rng.range(-0.5, 0.5) * size;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const float x = static_cast<float>(ox + (i - 1) * static_cast<double>(size));
      const float z = static_cast<float>(oz + (j - 1) * static_cast<double>(size));
      c.grid[j][i] = glm::vec3(x, terrainHeight(x, z, kind), z);
    }
  Patch& p = c.patch;
  p.corners[0] = c.grid[1][1];
  p.corners[1] = c.grid[1][2];
  p.corners[2] = c.grid[2][1];
  p.corners[3] = c.grid[2][2];
  p.useHeightBounds = rng.below(2) == 0;
  float lo = p.corners[0].y, hi = p.corners[0].y;
  for (const glm::vec3& q : p.corners) lo = std::min(lo, q.y), hi = std::max(hi, q.y);
  p.minHeight = lo - static_cast<float>(rng.range(0.0, 20.0));
  p.maxHeight = hi + static_cast<float>(rng.range(0.0, 20.0));

  const double cx = ox + 0.5 * size, cz = oz + 0.5 * size;
  const double cy = 0.25 * (p.corners[0].y + p.corners[1].y + p.corners[2].y + p.corners[3].y);
  c.category = rng.below(kCategories);
  double ex = 0, ey = 0, ez = 0, tx = 0, ty = 0, tz = 0;
  const double ang = rng.range(0.0, 6.283185307179586);
  switch (c.category) {
  case 0: { // general: somewhere over the terrain, looking near the patch
    const double r = rng.range(20.0, 1500.0);
    ex = cx + r * std::cos(ang), ez = cz + r * std::sin(ang), ey = cy + rng.range(2.0, 400.0);
    tx = cx + rng.range(-50.0, 50.0), ty = cy + rng.range(-10.0, 10.0), tz = cz + rng.range(-50.0, 50.0);
    break;
  }
  case 1: { // near: within a couple of patch sizes, low
    const double r = rng.range(0.05, 2.0) * size;
    ex = cx + r * std::cos(ang), ez = cz + r * std::sin(ang), ey = cy + rng.range(0.2, 10.0);
    tx = cx + rng.range(-0.5, 0.5) * size, ty = cy, tz = cz + rng.range(-0.5, 0.5) * size;
    break;
  }
  case 2: { // far: beyond the distance ramps
    const double r = rng.range(600.0, 4000.0);
    ex = cx + r * std::cos(ang), ez = cz + r * std::sin(ang), ey = cy + rng.range(50.0, 800.0);
    tx = cx, ty = cy, tz = cz;
    break;
  }
  case 3: { // edge-on: the eye just above the patch's height, looking horizontally across it
    const double r = rng.range(5.0, 500.0);
    ex = cx + r * std::cos(ang), ez = cz + r * std::sin(ang), ey = cy + rng.range(0.001, 2.0);
    tx = cx - r * std::cos(ang), ty = ey + rng.range(-0.01, 0.01), tz = cz - r * std::sin(ang);
    break;
  }
  default: { // random: anything, often culled or behind
    ex = rng.range(-5000.0, 5000.0), ez = rng.range(-5000.0, 5000.0), ey = rng.range(-100.0, 2000.0);
    tx = ex + rng.range(-1000.0, 1000.0), tz = ez + rng.range(-1000.0, 1000.0), ty = ey + rng.range(-1000.0, 300.0);
    break;
  }
  }
  const glm::vec3 eye(static_cast<float>(ex), static_cast<float>(ey), static_cast<float>(ez));
  glm::vec3 target(static_cast<float>(tx), static_cast<float>(ty), static_cast<float>(tz));
  if (std::fabs(target.x - eye.x) + std::fabs(target.z - eye.z) < 1e-3f) target.x += 1.0f; // lookAt needs it
  const float fovy = static_cast<float>(rng.range(20.0, 100.0) * 3.141592653589793 / 180.0);
  const float zNear = static_cast<float>(rng.range(0.05, 2.0));
  const float zFar = static_cast<float>(rng.range(2000.0, 20000.0));
  const int vp = rng.below(8);
  const glm::vec2 viewport = vp < 5 ? glm::vec2(1920.0f, 1200.0f) : vp < 7 ? glm::vec2(3840.0f, 2160.0f)
                                                                          : glm::vec2(800.0f, 600.0f);
  c.cam = fftess::lod::makeCamera(eye, target, glm::vec3(0.0f, 1.0f, 0.0f), fovy, zNear, zFar, viewport);
  if (rng.below(8) == 0) { // D3D / Vulkan depth range
    c.cam.projection = glm::perspectiveZO(fovy, viewport.x / viewport.y, zNear, zFar);
    c.cam.depthZeroToOne = true;
  }
  // Tile neighbours: 70% same size, 15% half, 15% twice; random parities.
  for (int e = 0; e < 4; ++e) {
    const int r = rng.below(20);
    c.tile.size[e] = r < 14 ? 1.0f : r < 17 ? 0.5f : 2.0f;
  }
  c.tile.oddU = rng.below(2) == 1;
  c.tile.oddV = rng.below(2) == 1;

  uint32_t* w = c.w;
  std::memset(w, 0, sizeof(c.w));
  for (int k = 0; k < 16; ++k) {
    w[kInView + k] = bitsOf(c.cam.view[k / 4][k % 4]);
    w[kInProj + k] = bitsOf(c.cam.projection[k / 4][k % 4]);
  }
  w[kInViewport] = bitsOf(c.cam.viewport.x), w[kInViewport + 1] = bitsOf(c.cam.viewport.y);
  for (int k = 0; k < 3; ++k) w[kInEye + k] = bitsOf(c.cam.eye[k]);
  w[kInZeroToOne] = c.cam.depthZeroToOne ? 1u : 0u;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      for (int k = 0; k < 3; ++k) w[kInGrid + (j * 4 + i) * 3 + k] = bitsOf(c.grid[j][i][k]);
  w[kInHeightBounds] = p.useHeightBounds ? 1u : 0u;
  w[kInHeightBounds + 1] = bitsOf(p.minHeight);
  w[kInHeightBounds + 2] = bitsOf(p.maxHeight);
  for (int e = 0; e < 4; ++e) w[kInTileSize + e] = bitsOf(c.tile.size[e]);
  w[kInOddU] = c.tile.oddU ? 1u : 0u;
  w[kInOddV] = c.tile.oddV ? 1u : 0u;
  w[kInCategory] = static_cast<uint32_t>(c.category);
}

// The patch across edge e (FactorIndex order) from the 4x4 grid, corners in u + 2v order.
Patch neighbourPatch(const Case& c, int e) {
  static const int base[4][2] = {{1, 0}, {0, 1}, {1, 2}, {2, 1}}; // {row j, col i} of corner 0
  Patch n;
  const int j = base[e][0], i = base[e][1];
  n.corners[0] = c.grid[j][i];
  n.corners[1] = c.grid[j][i + 1];
  n.corners[2] = c.grid[j + 1][i];
  n.corners[3] = c.grid[j + 1][i + 1];
  return n;
}

// The three nvidia-tile variants both sides run: adjacency clamp none / integer / pow2, EdgeVector rebuild.
fftess::lod::NvidiaTileParams tileParams(int k) {
  using namespace fftess::lod;
  const AdjacencyClamp clamps[3] = {AdjacencyClamp::None, AdjacencyClamp::Integer, AdjacencyClamp::Pow2};
  NvidiaTileParams tp;
  tp.clamp = clamps[k];
  tp.reconstruction = Reconstruction::EdgeVector;
  return tp;
}

// ---------------------------------------------------------------- C++ side
void evaluateCpu(const Case& c, uint32_t* out) {
  using namespace fftess::lod;
  std::memset(out, 0, kOutStride * 4);
  auto put = [&](int scheme, const PatchLod& r) {
    uint32_t* o = out + scheme * kOutPerScheme;
    for (int i = 0; i < 6; ++i) o[i] = bitsOf(r.factors[i]), o[6 + i] = bitsOf(r.why.factor[i].unclamped);
    o[12] = r.why.culled ? 1u : 0u;
  };
  put(0, screenSphere(c.patch, c.cam));
  for (int k = 0; k < 3; ++k) put(1 + k, nvidiaTile(c.patch, c.tile, c.cam, tileParams(k)));
  put(4, distancePow2(c.patch, c.cam));
  const PatchLod b = bonaventura(c.patch, c.cam);
  put(5, b);
  for (int i = 0; i < 4; ++i) out[kOutCorner + i] = bitsOf(b.why.cornerLevel[i]);
  put(6, clipDiameter(c.patch, c.cam));
  const float level = geomorphLevel(c.patch, c.cam);
  float n[4];
  for (int e = 0; e < 4; ++e) n[e] = geomorphLevel(neighbourPatch(c, e), c.cam);
  put(7, geomorph(level, n));
  out[kOutLevels] = bitsOf(level);
  for (int e = 0; e < 4; ++e) out[kOutLevels + 1 + e] = bitsOf(n[e]);
}

// ---------------------------------------------------------------- GLSL side
// "#version 450", the buffers, lod/shaders/*.glsl and the tool's helpers.
std::string shaderPrelude(bool precise, bool nvPragmas) {
  using namespace fftess::lod;
  std::string s = "#version 450\n";
  if (nvPragmas) s += "#pragma optionNV(fastmath off)\n#pragma optionNV(fastprecision off)\n";
  s += "layout(local_size_x = 64) in;\n"
       "layout(std430, binding = 0) readonly buffer LodIn { uint inw[]; };\n"
       "layout(std430, binding = 1) writeonly buffer LodOut { uint outw[]; };\n"
       "uniform uint caseCount;\n";
  s += precise ? "#define LOD_RESULT precise\n" : "#define LOD_RESULT\n";
  // The shared sources, concatenated in order, exactly as the project's GLSL path does.
  for (int i = 0; i < glslSourceCount(); ++i) {
    s += glslSource(i);
    s += "\n";
  }
  s += "float inF(uint i) { return uintBitsToFloat(inw[i]); }\n"
       "vec3 inV3(uint i) { return vec3(inF(i), inF(i + 1u), inF(i + 2u)); }\n"
       "vec3 gridAt(uint b, int j, int i) { return inV3(b + " + std::to_string(kInGrid) + "u + uint(j * 4 + i) * 3u); }\n"
       "void putResult(uint o, LodResult r) {\n"
       "  for (int i = 0; i < 6; ++i) {\n"
       "    outw[o + uint(i)] = floatBitsToUint(r.e[i].factor);\n"
       "    outw[o + 6u + uint(i)] = floatBitsToUint(r.e[i].unclamped);\n"
       "  }\n"
       "  outw[o + 12u] = r.culled ? 1u : 0u;\n"
       "}\n"
       "float levelOf(uint b, int j, int i, LodCamera cam, GeomorphSettings gs) {\n"
       "  LOD_RESULT float l = geomorphLevelAt(patchCentre(gridAt(b, j, i), gridAt(b, j, i + 1), gridAt(b, j + 1, i),"
       " gridAt(b, j + 1, i + 1)), cam, gs);\n"
       "  return l;\n"
       "}\n";
  return s;
}

// main() up to the inputs: the case's camera, the patch corners c0..c3 and its height bounds.
std::string shaderInputs() {
  return "void main() {\n"
       "  uint c = gl_GlobalInvocationID.x;\n"
       "  if (c >= caseCount) { return; }\n"
       "  uint b = c * " + std::to_string(kInStride) + "u;\n"
       "  uint o = c * " + std::to_string(kOutStride) + "u;\n"
       "  LodCamera cam;\n"
       "  for (int k = 0; k < 4; ++k) {\n"
       "    cam.view[k] = vec4(inF(b + uint(k * 4)), inF(b + uint(k * 4 + 1)), inF(b + uint(k * 4 + 2)), inF(b + uint(k * 4 + 3)));\n"
       "    cam.proj[k] = vec4(inF(b + 16u + uint(k * 4)), inF(b + 16u + uint(k * 4 + 1)), inF(b + 16u + uint(k * 4 + 2)), inF(b + 16u + uint(k * 4 + 3)));\n"
       "  }\n"
       "  cam.viewport = vec2(inF(b + " + std::to_string(kInViewport) + "u), inF(b + " + std::to_string(kInViewport + 1) + "u));\n"
       "  cam.eye = inV3(b + " + std::to_string(kInEye) + "u);\n"
       "  cam.depthZeroToOne = inw[b + " + std::to_string(kInZeroToOne) + "u] != 0u;\n"
       "  vec3 c0 = gridAt(b, 1, 1);\n"
       "  vec3 c1 = gridAt(b, 1, 2);\n"
       "  vec3 c2 = gridAt(b, 2, 1);\n"
       "  vec3 c3 = gridAt(b, 2, 2);\n"
       "  bool hb = inw[b + " + std::to_string(kInHeightBounds) + "u] != 0u;\n"
       "  float hmin = inF(b + " + std::to_string(kInHeightBounds + 1) + "u);\n"
       "  float hmax = inF(b + " + std::to_string(kInHeightBounds + 2) + "u);\n";
}

// The schemes into the case's output words. The settings are lod::glslSettings of the *Params the C++ side passes
// (lod/lod_fields.h: every field by name, floats as exact bits): lod.h's defaults, tileParams for nvidia-tile.
std::string shaderSchemes() {
  using namespace fftess::lod;
  const std::string stride = std::to_string(kOutPerScheme);
  std::string s = glslSettings("ss", ScreenSphereParams{}) +
       "  LOD_RESULT LodResult r0 = screenSphereLod(c0, c1, c2, c3, hb, hmin, hmax, cam, ss);\n"
       "  putResult(o, r0);\n"
       "  TileNeighbourInfo ni;\n"
       "  for (int e = 0; e < 4; ++e) {\n"
       "    ni.size[e] = inF(b + " + std::to_string(kInTileSize) + "u + uint(e));\n"
       "    ni.farCorner[e] = vec3(0.0f);\n"
       "    ni.rebuiltHeight[e] = 0.0f;\n"
       "  }\n"
       "  ni.oddU = inw[b + " + std::to_string(kInOddU) + "u] != 0u;\n"
       "  ni.oddV = inw[b + " + std::to_string(kInOddV) + "u] != 0u;\n";
  for (int k = 0; k < 3; ++k) {
    const std::string ts = "ts" + std::to_string(k), rt = "rt" + std::to_string(k);
    s += glslSettings(ts, tileParams(k)) + "  LOD_RESULT LodResult " + rt +
         " = nvidiaTileLod(c0, c1, c2, c3, hb, hmin, hmax, ni, cam, " + ts + ");\n" + "  putResult(o + " +
         std::to_string(1 + k) + "u * " + stride + "u, " + rt + ");\n";
  }
  s += glslSettings("ds", DistancePow2Params{}) +
       "  LOD_RESULT LodResult r4 = distancePow2Lod(c0, c1, c2, c3, hb, hmin, hmax, cam, ds);\n"
       "  putResult(o + 4u * " + stride + "u, r4);\n";
  s += glslSettings("bs", BonaventuraParams{}) +
       "  LOD_RESULT LodResult r5 = bonaventuraLod(c0, c1, c2, c3, hb, hmin, hmax, cam, bs);\n"
       "  putResult(o + 5u * " + stride + "u, r5);\n"
       "  for (int i = 0; i < 4; ++i) { outw[o + " + std::to_string(kOutCorner) +
       "u + uint(i)] = floatBitsToUint(r5.cornerLevel[i]); }\n";
  s += glslSettings("cs", ClipDiameterParams{}) +
       "  LOD_RESULT LodResult r6 = clipDiameterLod(c0, c1, c2, c3, hb, hmin, hmax, cam, cs);\n"
       "  putResult(o + 6u * " + stride + "u, r6);\n";
  // Geomorph: the patch's level and its neighbours' (grid cells as neighbourPatch), then the factors.
  const char* const levels[5] = {"level", "n0", "n1", "n2", "n3"};
  const char* const cells[5] = {"1, 1", "1, 0", "0, 1", "1, 2", "2, 1"};
  s += glslSettings("gs", GeomorphParams{});
  for (int k = 0; k < 5; ++k)
    s += std::string("  LOD_RESULT float ") + levels[k] + " = levelOf(b, " + cells[k] + ", cam, gs);\n";
  s += "  LOD_RESULT LodResult r7 = geomorphLod(level, n0, n1, n2, n3);\n"
       "  putResult(o + 7u * " + stride + "u, r7);\n";
  for (int k = 0; k < 5; ++k)
    s += "  outw[o + " + std::to_string(kOutLevels + k) + "u] = floatBitsToUint(" + levels[k] + ");\n";
  return s + "}\n";
}

std::string buildShader(bool precise, bool nvPragmas) {
  return shaderPrelude(precise, nvPragmas) + shaderInputs() + shaderSchemes();
}

using fftess::gltest::GlFunctions;

// A headless GL 4.5 core context: hardware EGL devices first; software devices and Mesa's surfaceless platform
// only with allowSoftware (the same choice as tests/tools/nvidia_compare). 'info' = the renderer lines this tool prints.
bool createContext(bool allowSoftware, fftess::gltest::GlContext& ctx, std::string& info, std::string& error) {
  fftess::gltest::ContextOptions options;
  options.order = fftess::gltest::DeviceOrder::HardwareFirst;
  options.allowSoftware = allowSoftware;
  if (!ctx.create(options, error)) return false;
  info = "GL_RENDERER: " + ctx.renderer() + "\nGL_VERSION: " + ctx.version() + "\nGL_VENDOR: " + ctx.vendor() +
         "\nEGL_VENDOR: " + ctx.eglVendor() + " (" + ctx.deviceNote() + ")\n";
  return ctx.checkHardwareRenderer(allowSoftware, error);
}

bool runGpu(const GlFunctions& gl, const std::string& source, const std::vector<uint32_t>& in, size_t cases,
            std::vector<uint32_t>& out, std::string& error) {
  // The gl module's compile and link (their messages: the driver's log; the compile's also the source).
  GLuint sh = gl.glCreateShader(GL_COMPUTE_SHADER);
  if (!fftess::gltest::compileShader(gl, sh, source, error)) return false;
  GLuint prog = gl.glCreateProgram();
  gl.glAttachShader(prog, sh);
  if (!fftess::gltest::linkProgram(gl, prog, error)) return false;
  gl.glUseProgram(prog);
  GLuint bufs[2];
  gl.glGenBuffers(2, bufs);
  out.assign(cases * kOutStride, 0xDEADBEEFu);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[0]);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(in.size() * 4), in.data(), GL_STATIC_DRAW);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[1]);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(out.size() * 4), out.data(), GL_DYNAMIC_READ);
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, bufs[0]);
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, bufs[1]);
  gl.glUniform1ui(gl.glGetUniformLocation(prog, "caseCount"), static_cast<GLuint>(cases));
  const GLuint groups = static_cast<GLuint>((cases + 63) / 64);
  gl.glDispatchCompute(groups, 1, 1);
  gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.glFinish();
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, bufs[1]);
  gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(out.size() * 4), out.data());
  return fftess::gltest::checkGl(gl, "the drift dispatch", error);
}

// ---------------------------------------------------------------- comparison
int64_t orderedKey(uint32_t u) {
  return (u & 0x80000000u) ? -static_cast<int64_t>(u & 0x7fffffffu) : static_cast<int64_t>(u);
}
bool isNan(uint32_t u) { return (u & 0x7f800000u) == 0x7f800000u && (u & 0x007fffffu) != 0; }
using Count = unsigned long long; // printf's %llu
Count ulpDistance(uint32_t a, uint32_t b) {
  const int64_t d = orderedKey(a) - orderedKey(b);
  return static_cast<Count>(d < 0 ? -d : d);
}

bool tessellationDiffers(uint32_t a, uint32_t b, fftess::Partitioning part) {
  const fftess::EdgePoints ea = fftess::edgePoints(floatOf(a), part);
  const fftess::EdgePoints eb = fftess::edgePoints(floatOf(b), part);
  if (ea.culled != eb.culled || ea.count != eb.count) return true;
  return std::memcmp(ea.fixed, eb.fixed, static_cast<size_t>(ea.count) * sizeof(uint32_t)) != 0;
}

struct Stat {
  Count values = 0, identical = 0, nanMismatch = 0, maxUlp = 0, tessEven = 0, tessInteger = 0;
  Count byCategory[kCategories] = {}, identicalByCategory[kCategories] = {};
  Count cullOneSide = 0, culledBoth = 0, cases = 0;
  void add(uint32_t cpu, uint32_t gpu, int category, bool tess) {
    ++values;
    ++byCategory[category];
    if (cpu == gpu) {
      ++identical;
      ++identicalByCategory[category];
      return;
    }
    if (isNan(cpu) || isNan(gpu)) {
      ++nanMismatch;
    } else {
      maxUlp = std::max(maxUlp, ulpDistance(cpu, gpu));
    }
    if (tess) {
      tessEven += tessellationDiffers(cpu, gpu, fftess::Partitioning::FractionalEven) ? 1 : 0;
      tessInteger += tessellationDiffers(cpu, gpu, fftess::Partitioning::Integer) ? 1 : 0;
    }
  }
};

double pct(Count a, Count b) { return b ? 100.0 * static_cast<double>(a) / static_cast<double>(b) : 100.0; }

struct Options {
  bool precise = false, nvPragmas = false, allowSoftware = false;
  int examples = 3;
  long cases = 200000;
  unsigned long long seed = 1;
};

// The command line; false (after the message) on a usage error.
bool parseOptions(int argc, char** argv, Options& o) {
  std::vector<std::string> pos;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--precise") {
      o.precise = true;
    } else if (a == "--nv-pragmas") {
      o.nvPragmas = true;
    } else if (a == "--allow-llvmpipe") {
      o.allowSoftware = true;
    } else if (a == "--examples" && i + 1 < argc) {
      o.examples = std::atoi(argv[++i]);
    } else if (!a.empty() && a[0] != '-') {
      pos.push_back(a);
    } else {
      std::fprintf(stderr, "fftess_lod_gpu_drift: unknown option '%s' (argument %d)\n", a.c_str(), i);
      return false;
    }
  }
  char* end = nullptr;
  if (pos.size() > 0) o.cases = std::strtol(pos[0].c_str(), &end, 10);
  if (pos.size() > 0 && (*end != '\0' || o.cases < 1 || o.cases > 2000000)) {
    std::fprintf(stderr, "fftess_lod_gpu_drift: CASES '%s' (argument 1) must be an integer in [1, 2000000]\n",
                 pos[0].c_str());
    return false;
  }
  if (pos.size() > 1) o.seed = std::strtoull(pos[1].c_str(), &end, 10);
  if (pos.size() > 1 && *end != '\0') {
    std::fprintf(stderr, "fftess_lod_gpu_drift: SEED '%s' (argument 2) must be an unsigned integer\n", pos[1].c_str());
    return false;
  }
  if (pos.size() > 2) {
    std::fprintf(stderr, "fftess_lod_gpu_drift: too many arguments ('%s')\n", pos[2].c_str());
    return false;
  }
  return true;
}

// Compares the two sides per scheme and prints the tables (and up to `examples` differing factors per scheme).
void report(const std::vector<Case>& all, const std::vector<uint32_t>& cpu, const std::vector<uint32_t>& gpu,
            int examples) {
  const long cases = static_cast<long>(all.size());
  Stat factor[kSchemes], unclamped[kSchemes], corner, levels;
  std::vector<std::string> shown[kSchemes];
  static const char* const kFactorNames[6] = {"Ueq0", "Veq0", "Ueq1", "Veq1", "insideU", "insideV"};
  for (long i = 0; i < cases; ++i) {
    const uint32_t* c = &cpu[static_cast<size_t>(i) * kOutStride];
    const uint32_t* g = &gpu[static_cast<size_t>(i) * kOutStride];
    const int cat = all[static_cast<size_t>(i)].category;
    for (int s = 0; s < kSchemes; ++s) {
      const uint32_t* cs = c + s * kOutPerScheme;
      const uint32_t* gs = g + s * kOutPerScheme;
      ++factor[s].cases;
      if (cs[12] != gs[12]) ++factor[s].cullOneSide;
      if (cs[12] && gs[12]) ++factor[s].culledBoth;
      for (int k = 0; k < 6; ++k) {
        factor[s].add(cs[k], gs[k], cat, true);
        unclamped[s].add(cs[6 + k], gs[6 + k], cat, false);
        if (cs[k] != gs[k] && static_cast<int>(shown[s].size()) < examples) {
          char b[256];
          std::snprintf(b, sizeof b, "case %ld (%s) %s: C++ %.9g (0x%08x) GPU %.9g (0x%08x), %llu ulp", i,
                        kCategoryNames[cat], kFactorNames[k], floatOf(cs[k]), cs[k], floatOf(gs[k]), gs[k],
                        ulpDistance(cs[k], gs[k]));
          shown[s].push_back(b);
        }
      }
    }
    for (int k = 0; k < 4; ++k) corner.add(c[kOutCorner + k], g[kOutCorner + k], cat, false);
    for (int k = 0; k < 5; ++k) levels.add(c[kOutLevels + k], g[kOutLevels + k], cat, false);
  }

  std::printf("\nfactors (6 per case; tess = factors whose fftess::edgePoints differ):\n");
  std::printf("%-20s %8s %9s %12s %8s %6s %10s %10s %9s %9s\n", "scheme", "cases", "factors", "bit-identical",
              "max ulp", "NaN", "tess even", "tess int", "cull 1side", "culled");
  for (int s = 0; s < kSchemes; ++s) {
    const Stat& t = factor[s];
    std::printf("%-20s %8llu %9llu %11.4f%% %8llu %6llu %10llu %10llu %9llu %9llu\n", kSchemeNames[s], t.cases,
                t.values, pct(t.identical, t.values), t.maxUlp, t.nanMismatch, t.tessEven, t.tessInteger,
                t.cullOneSide, t.culledBoth);
  }
  std::printf("\nbefore the clamps (why.unclamped; for exponent schemes 2^exponent before clamping):\n");
  for (int s = 0; s < kSchemes; ++s) {
    const Stat& t = unclamped[s];
    std::printf("%-20s %9llu values %11.4f%% bit-identical, max %llu ulp, %llu NaN mismatches\n", kSchemeNames[s],
                t.values, pct(t.identical, t.values), t.maxUlp, t.nanMismatch);
  }
  for (const Stat* t : {&corner, &levels})
    std::printf("%-20s %9llu values %11.4f%% bit-identical, max %llu ulp\n",
                t == &corner ? "bonaventura corners" : "geomorph levels", t->values, pct(t->identical, t->values),
                t->maxUlp);
  std::printf("\nbit-identical factors by camera category:\n%-20s", "scheme");
  for (const char* n : kCategoryNames) std::printf(" %10s", n);
  std::printf("\n");
  for (int s = 0; s < kSchemes; ++s) {
    std::printf("%-20s", kSchemeNames[s]);
    for (int k = 0; k < kCategories; ++k)
      std::printf(" %9.3f%%", pct(factor[s].identicalByCategory[k], factor[s].byCategory[k]));
    std::printf("\n");
  }
  if (examples > 0) {
    std::printf("\nfirst differing factors per scheme:\n");
    for (int s = 0; s < kSchemes; ++s)
      for (const std::string& e : shown[s]) std::printf("  %-20s %s\n", kSchemeNames[s], e.c_str());
  }
}
} // namespace

int main(int argc, char** argv) {
  Options o;
  if (!parseOptions(argc, argv, o)) return 1;
  const long cases = o.cases;
  fftess::gltest::GlContext context;
  std::string info, error;
  if (!createContext(o.allowSoftware, context, info, error)) {
    std::fprintf(stderr, "fftess_lod_gpu_drift: %s\n", error.c_str());
    return 3;
  }
  std::printf("%s", info.c_str());
  std::printf("variant: %s%s; cases %ld, seed %llu\n", o.precise ? "precise results" : "plain",
              o.nvPragmas ? " + optionNV(fastmath off, fastprecision off)" : "", cases, o.seed);

  Rng rng{o.seed};
  std::vector<Case> all(static_cast<size_t>(cases));
  std::vector<uint32_t> in(static_cast<size_t>(cases) * kInStride);
  for (long i = 0; i < cases; ++i) {
    buildCase(rng, all[static_cast<size_t>(i)]);
    std::memcpy(&in[static_cast<size_t>(i) * kInStride], all[static_cast<size_t>(i)].w, sizeof(Case::w));
  }
  std::vector<uint32_t> gpu;
  if (!runGpu(context.gl, buildShader(o.precise, o.nvPragmas), in, static_cast<size_t>(cases), gpu, error)) {
    std::fprintf(stderr, "fftess_lod_gpu_drift: %s\n", error.c_str());
    return 4;
  }
  std::vector<uint32_t> cpu(static_cast<size_t>(cases) * kOutStride);
  for (long i = 0; i < cases; ++i) evaluateCpu(all[static_cast<size_t>(i)], &cpu[static_cast<size_t>(i) * kOutStride]);

  // FNV-1a of the C++ results: the C++ side calls the host's libm (acosf, exp2f), so compare this line between
  // the machine that ran and the one the doc's C++ numbers come from.
  uint64_t fnv = 0xcbf29ce484222325ull;
  for (uint32_t w : cpu)
    for (int k = 0; k < 4; ++k) fnv = (fnv ^ ((w >> (8 * k)) & 0xffu)) * 0x100000001b3ull;
  std::printf("C++ results FNV-1a: %016llx\n", static_cast<unsigned long long>(fnv));

  report(all, cpu, gpu, o.examples);
  return 0;
}
