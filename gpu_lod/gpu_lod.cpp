// The GPU path of the LOD. See gpu_lod.h and docs/gpu_lod.md.
#include "gpu_lod/gpu_lod.h"
#include "gl/gl_context.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <mutex>
#include <regex>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace fftess::gpulod {

namespace {

namespace vf = fftess::verify;
using gltest::GlFunctions;

// Buffer layouts, in 32-bit words (docs/gpu_lod.md, "Buffers").
constexpr int kInWords = 37;  // per patch: corners 12, useHeightBounds, minHeight, maxHeight, size 4, oddU, oddV,
                              // farCorner 12, rebuiltHeight 4
constexpr int kCamWords = 39; // view 16, proj 16 (column-major), viewport 2, eye 3, depthZeroToOne, patch count
constexpr int kOutWords = 35; // per patch: 6 x (factor, metric, unclamped, exponent, fixes), cornerLevel 4, culled

uint32_t bitsOf(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return u;
}
float floatOf(uint32_t u) {
  float f;
  std::memcpy(&f, &u, 4);
  return f;
}
std::string glslFloat(float f) {
  char b[48];
  std::snprintf(b, sizeof b, "uintBitsToFloat(0x%08xu)", bitsOf(f));
  return b;
}
std::string hlslFloat(float f) {
  char b[48];
  std::snprintf(b, sizeof b, "asfloat(0x%08xu)", bitsOf(f));
  return b;
}
const char* boolText(bool v) { return v ? "true" : "false"; }

int clampCode(lod::AdjacencyClamp c) {
  return c == lod::AdjacencyClamp::Integer ? 1 : c == lod::AdjacencyClamp::Pow2 ? 2 : 0;
}
int rebuildCode(lod::Reconstruction r) {
  return r == lod::Reconstruction::FarCorner ? 1 : r == lod::Reconstruction::Resampled ? 2 : 0;
}
int insideCode(lod::InsideRule r) { return r == lod::InsideRule::Min ? 1 : r == lod::InsideRule::Max ? 2 : 0; }

// The scene's LOD settings as the user's shader receives them (LodSettings, docs/gpu_lod.md), field by field.
struct SettingField {
  const char* name;
  bool isFloat;
  float f;
  int i;
};
std::vector<SettingField> settingFields(const vf::Lod& L) {
  const lod::ScreenSphereParams& sp = L.screenSphere.sphere;
  return {{"clampMode", false, 0, clampCode(L.screenSphere.clamp)},
          {"rebuild", false, 0, rebuildCode(L.screenSphere.reconstruction)},
          {"targetPixels", true, sp.tessellatedTriWidth, 0},
          {"minFactor", true, sp.minFactor, 0},
          {"maxFactor", true, sp.maxFactor, 0},
          {"minDistance", true, L.distancePow2.minDistance, 0},
          {"maxDistance", true, L.distancePow2.maxDistance, 0},
          {"minTess", true, L.distancePow2.minTessExponent, 0},
          {"maxTess", true, L.distancePow2.maxTessExponent, 0},
          {"frustumCull", false, 0, sp.frustumCull ? 1 : 0},
          {"edgesPerScreenHeight", true, L.clipDiameter.edgesPerScreenHeight, 0},
          {"factor", true, L.factor, 0}};
}

// ---- GLSL ----------------------------------------------------------------------------------------------------------
const char* kGlslTypes = R"(
// fftess GPU LOD interface (docs/gpu_lod.md).
struct LodPatch {
  vec3 corners[4];       // corners[u + 2v], displaced as lod.displaced_corners says
  bool useHeightBounds;  // widen the culling box's y to [minHeight, maxHeight]
  float minHeight;
  float maxHeight;
};
struct LodSettings {
  int clampMode;         // lod.adjacency_clamp: kClampNone 0, kClampInteger 1, kClampPow2 2
  int rebuild;           // lod.reconstruction: kRebuildEdgeVector 0, kRebuildFarCorner 1, kRebuildResampled 2
  float targetPixels;    // lod.target_pixels
  float minFactor;       // lod.min_factor
  float maxFactor;       // lod.max_factor
  float minDistance;     // lod.min_distance
  float maxDistance;     // lod.max_distance
  float minTess;         // lod.min_tess
  float maxTess;         // lod.max_tess
  bool frustumCull;      // lod.frustum_cull
  float edgesPerScreenHeight; // lod.edges_per_screen_height
  float factor;          // lod.factor
};
struct LodFactors {
  float factor[6];       // Ueq0 Veq0 Ueq1 Veq1 insideU insideV
  bool culled;           // you culled the patch on purpose (write factors <= 0 too, or the tessellator draws it)
};
)";

std::string glslSettings(const vf::Lod& L) {
  std::string s = "LodSettings fftessSettings() {\n  LodSettings s;\n";
  for (const SettingField& f : settingFields(L)) {
    s += std::string("  s.") + f.name + " = ";
    if (f.isFloat) s += glslFloat(f.f);
    else if (std::strcmp(f.name, "frustumCull") == 0) s += boolText(f.i != 0);
    else s += std::to_string(f.i);
    s += ";\n";
  }
  return s + "  return s;\n}\n";
}

// The built-in scheme's evaluation, with the scene's parameters as exact constants (what lod_bridge.cpp patchLod
// calls on the CPU).
std::string glslBuiltin(const vf::Lod& L, bool tile) {
  const lod::ScreenSphereParams& sp = L.screenSphere.sphere;
  const lod::DistancePow2Params& dp = L.distancePow2;
  const lod::BonaventuraParams& bp = L.bonaventura;
  const lod::ClipDiameterParams& cp = L.clipDiameter;
  const std::string corners = "p.corners[0], p.corners[1], p.corners[2], p.corners[3], p.useHeightBounds, "
                              "p.minHeight, p.maxHeight";
  std::string s = "LodResult fftessEvaluate(LodPatch p, TileNeighbourInfo n, LodCamera cam) {\n";
  s += "  ScreenSphereSettings ss = ScreenSphereSettings(" + glslFloat(sp.tessellatedTriWidth) + ", " +
       glslFloat(sp.minFactor) + ", " + glslFloat(sp.maxFactor) + ", " + std::to_string(insideCode(sp.inside)) +
       ", " + boolText(sp.frustumCull) + ", " + glslFloat(sp.culledFactor) + ");\n";
  s += "  AdjacencySettings adj = AdjacencySettings(" + std::to_string(clampCode(L.screenSphere.clamp)) + ", " +
       std::to_string(rebuildCode(L.screenSphere.reconstruction)) + ");\n";
  switch (L.scheme) {
  case vf::LodScheme::ScreenSphere:
    s += tile ? "  return nvidiaTileLod(" + corners + ", n, cam, TileSettings(ss, adj.clampMode, adj.rebuild, " +
                     boolText(L.screenSphere.insideFromFixedEdges) + "));\n"
              : "  return screenSphereLod(" + corners + ", cam, ss);\n";
    break;
  case vf::LodScheme::PatchCenter: s += "  return patchCenterLod(" + corners + ", cam, ss);\n"; break;
  case vf::LodScheme::DistancePow2:
    s += "  DistancePow2Settings ds = DistancePow2Settings(" + glslFloat(dp.minDistance) + ", " +
         glslFloat(dp.maxDistance) + ", " + glslFloat(dp.minTessExponent) + ", " + glslFloat(dp.maxTessExponent) +
         ", " + boolText(dp.frustumCull) + ");\n";
    s += tile ? "  return distancePow2TileLod(" + corners + ", n, cam, ds, adj);\n"
              : "  return distancePow2Lod(" + corners + ", cam, ds);\n";
    break;
  case vf::LodScheme::Bonaventura:
    s += "  BonaventuraSettings bs = BonaventuraSettings(" + glslFloat(bp.minDistance) + ", " +
         glslFloat(bp.maxDistance) + ", " + glslFloat(bp.minExponent) + ", " + glslFloat(bp.maxExponent) + ", " +
         boolText(bp.angleCorrection) + ", " + glslFloat(bp.rank) + ", vec3(" + glslFloat(bp.up.x) + ", " +
         glslFloat(bp.up.y) + ", " + glslFloat(bp.up.z) + "), " + glslFloat(bp.minFactor) + ", " +
         glslFloat(bp.maxFactor) + ", " + boolText(bp.frustumCull) + ", " + glslFloat(bp.culledFactor) + ", " +
         boolText(bp.literalFourthCornerAngle) + ");\n";
    s += tile ? "  return bonaventuraTileLod(" + corners + ", n, cam, bs, adj);\n"
              : "  return bonaventuraLod(" + corners + ", cam, bs);\n";
    break;
  case vf::LodScheme::ClipDiameter:
    s += "  ClipDiameterSettings cs = ClipDiameterSettings(" + glslFloat(cp.edgesPerScreenHeight) + ", " +
         glslFloat(cp.minFactor) + ", " + glslFloat(cp.maxFactor) + ", " + std::to_string(insideCode(cp.inside)) +
         ", " + boolText(cp.frustumCull) + ", " + glslFloat(cp.culledFactor) + ");\n";
    s += tile ? "  return clipDiameterTileLod(" + corners + ", n, cam, cs, adj);\n"
              : "  return clipDiameterLod(" + corners + ", cam, cs);\n";
    break;
  case vf::LodScheme::Constant:
    if (tile) {
      s += "  return constantTileLod(" + glslFloat(L.factor) + ", n, adj);\n";
    } else {
      s += "  LodResult r = emptyLodResult();\n  for (int i = 0; i < 6; ++i) { r.e[i].factor = " +
           glslFloat(L.factor) + "; }\n  return r;\n";
    }
    break;
  case vf::LodScheme::Geomorph:
  case vf::LodScheme::Shader: s += "  return emptyLodResult();\n"; break;
  }
  return s + "}\n";
}

// The user's lodMain, wrapped into a LodResult (no record: metric 0, unclamped = factor, no fix bits).
const char* kGlslUserEvaluate = R"(LodResult fftessEvaluate(LodPatch p, TileNeighbourInfo n, LodCamera cam) {
  LodFactors f = lodMain(p, n, cam, fftessSettings());
  LodResult r = emptyLodResult();
  for (int i = 0; i < 6; ++i) {
    r.e[i] = makeEdgeLod(f.factor[i], 0.0f, f.factor[i], 0.0f, 0);
  }
  // Culled on purpose only where the tessellator discards the patch (some outer factor NaN or <= 0).
  bool discards = false;
  for (int i = 0; i < 4; ++i) {
    if (!(f.factor[i] > 0.0f)) { discards = true; }
  }
  r.culled = f.culled && discards;
  if (r.culled) {
    for (int i = 0; i < 6; ++i) { r.e[i].fixes = kFixCulled; }
  }
  return r;
}
)";

const char* kGlslMain = R"(
float fftessInF(uint w) { return uintBitsToFloat(fftessIn[w]); }
vec3 fftessInV3(uint w) { return vec3(fftessInF(w), fftessInF(w + 1u), fftessInF(w + 2u)); }
float fftessCamF(uint w) { return uintBitsToFloat(fftessCam[w]); }
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= fftessCam[38]) { return; }
  LodCamera cam;
  for (int k = 0; k < 4; ++k) {
    cam.view[k] = vec4(fftessCamF(uint(k * 4)), fftessCamF(uint(k * 4 + 1)), fftessCamF(uint(k * 4 + 2)),
                       fftessCamF(uint(k * 4 + 3)));
    cam.proj[k] = vec4(fftessCamF(uint(16 + k * 4)), fftessCamF(uint(16 + k * 4 + 1)), fftessCamF(uint(16 + k * 4 + 2)),
                       fftessCamF(uint(16 + k * 4 + 3)));
  }
  cam.viewport = vec2(fftessCamF(32u), fftessCamF(33u));
  cam.eye = vec3(fftessCamF(34u), fftessCamF(35u), fftessCamF(36u));
  cam.depthZeroToOne = fftessCam[37] != 0u;
  uint b = i * 37u;
  LodPatch p;
  for (int c = 0; c < 4; ++c) { p.corners[c] = fftessInV3(b + uint(c * 3)); }
  p.useHeightBounds = fftessIn[b + 12u] != 0u;
  p.minHeight = fftessInF(b + 13u);
  p.maxHeight = fftessInF(b + 14u);
  TileNeighbourInfo n;
  for (int e = 0; e < 4; ++e) {
    n.size[e] = fftessInF(b + 15u + uint(e));
    n.farCorner[e] = fftessInV3(b + 21u + uint(e * 3));
    n.rebuiltHeight[e] = fftessInF(b + 33u + uint(e));
  }
  n.oddU = fftessIn[b + 19u] != 0u;
  n.oddV = fftessIn[b + 20u] != 0u;
  LodResult r = fftessEvaluate(p, n, cam);
  uint o = i * 35u;
  for (int k = 0; k < 6; ++k) {
    fftessOut[o + uint(k * 5)] = floatBitsToUint(r.e[k].factor);
    fftessOut[o + uint(k * 5 + 1)] = floatBitsToUint(r.e[k].metric);
    fftessOut[o + uint(k * 5 + 2)] = floatBitsToUint(r.e[k].unclamped);
    fftessOut[o + uint(k * 5 + 3)] = floatBitsToUint(r.e[k].exponent);
    fftessOut[o + uint(k * 5 + 4)] = uint(r.e[k].fixes);
  }
  for (int c = 0; c < 4; ++c) { fftessOut[o + 30u + uint(c)] = floatBitsToUint(r.cornerLevel[c]); }
  fftessOut[o + 34u] = r.culled ? 1u : 0u;
}
)";

std::string glslHeader() {
  std::string s = "#version 450\nlayout(local_size_x = 64) in;\n"
                  "layout(std430, binding = 0) readonly buffer FftessIn { uint fftessIn[]; };\n"
                  "layout(std430, binding = 1) writeonly buffer FftessOut { uint fftessOut[]; };\n"
                  "layout(std430, binding = 2) readonly buffer FftessCam { uint fftessCam[]; };\n";
  for (int i = 0; i < lod::glslSourceCount(); ++i) s += std::string(lod::glslSource(i)) + "\n";
  return s + kGlslTypes;
}

// ---- HLSL ----------------------------------------------------------------------------------------------------------
const char* kHlslTypes = R"(// fftess GPU LOD interface, HLSL (docs/gpu_lod.md). Generated; your file is included below.
struct LodCamera {
  float4x4 view;         // world -> view: mul(cam.view, float4(p, 1)) (column vectors, m[row][column])
  float4x4 proj;         // view -> clip: mul(cam.proj, v)
  float2 viewport;       // pixels
  float3 eye;            // world
  bool depthZeroToOne;   // clip z in [0, w] instead of [-w, w]
};
struct LodPatch {
  float3 corners[4];     // corners[u + 2v]
  bool useHeightBounds;
  float minHeight;
  float maxHeight;
};
struct TileNeighbourInfo {
  float size[4];         // per edge (Ueq0 Veq0 Ueq1 Veq1): 0.5, 1 or 2
  bool oddU;
  bool oddV;
  float3 farCorner[4];
  float rebuiltHeight[4];
};
struct LodSettings {
  int clampMode; int rebuild; float targetPixels; float minFactor; float maxFactor; float minDistance;
  float maxDistance; float minTess; float maxTess; bool frustumCull; float edgesPerScreenHeight; float factor;
};
struct LodFactors {
  float factor[6];       // Ueq0 Veq0 Ueq1 Veq1 insideU insideV (SV_TessFactor[0..3], SV_InsideTessFactor[0..1])
  bool culled;
};
static const int kClampNone = 0;
static const int kClampInteger = 1;
static const int kClampPow2 = 2;
static const int kRebuildEdgeVector = 0;
static const int kRebuildFarCorner = 1;
static const int kRebuildResampled = 2;
[[vk::binding(0)]] ByteAddressBuffer fftessIn;
[[vk::binding(1)]] RWByteAddressBuffer fftessOut;
[[vk::binding(2)]] ByteAddressBuffer fftessCam;
)";

std::string hlslSettings(const vf::Lod& L) {
  std::string s = "LodSettings fftessSettings() {\n  LodSettings s;\n";
  for (const SettingField& f : settingFields(L)) {
    s += std::string("  s.") + f.name + " = ";
    if (f.isFloat) s += hlslFloat(f.f);
    else if (std::strcmp(f.name, "frustumCull") == 0) s += boolText(f.i != 0);
    else s += std::to_string(f.i);
    s += ";\n";
  }
  return s + "  return s;\n}\n";
}

const char* kHlslMain = R"(
float fftessInF(uint w) { return asfloat(fftessIn.Load(w * 4)); }
float3 fftessInV3(uint w) { return float3(fftessInF(w), fftessInF(w + 1), fftessInF(w + 2)); }
float fftessCamF(uint w) { return asfloat(fftessCam.Load(w * 4)); }
[numthreads(64, 1, 1)]
void main(uint3 id : SV_DispatchThreadID) {
  uint i = id.x;
  if (i >= fftessCam.Load(38 * 4)) { return; }
  LodCamera cam;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      cam.view[r][c] = fftessCamF(c * 4 + r);
      cam.proj[r][c] = fftessCamF(16 + c * 4 + r);
    }
  }
  cam.viewport = float2(fftessCamF(32), fftessCamF(33));
  cam.eye = float3(fftessCamF(34), fftessCamF(35), fftessCamF(36));
  cam.depthZeroToOne = fftessCam.Load(37 * 4) != 0;
  uint b = i * 37;
  LodPatch p;
  for (int k = 0; k < 4; ++k) { p.corners[k] = fftessInV3(b + k * 3); }
  p.useHeightBounds = fftessIn.Load((b + 12) * 4) != 0;
  p.minHeight = fftessInF(b + 13);
  p.maxHeight = fftessInF(b + 14);
  TileNeighbourInfo n;
  for (int e = 0; e < 4; ++e) {
    n.size[e] = fftessInF(b + 15 + e);
    n.farCorner[e] = fftessInV3(b + 21 + e * 3);
    n.rebuiltHeight[e] = fftessInF(b + 33 + e);
  }
  n.oddU = fftessIn.Load((b + 19) * 4) != 0;
  n.oddV = fftessIn.Load((b + 20) * 4) != 0;
  LodFactors f = lodMain(p, n, cam, fftessSettings());
  bool discards = false;
  for (int d = 0; d < 4; ++d) {
    if (!(f.factor[d] > 0.0)) { discards = true; }
  }
  bool culled = f.culled && discards;
  uint o = i * 35;
  for (int q = 0; q < 6; ++q) {
    fftessOut.Store((o + q * 5) * 4, asuint(f.factor[q]));
    fftessOut.Store((o + q * 5 + 1) * 4, 0u);
    fftessOut.Store((o + q * 5 + 2) * 4, asuint(f.factor[q]));
    fftessOut.Store((o + q * 5 + 3) * 4, 0u);
    fftessOut.Store((o + q * 5 + 4) * 4, culled ? 4u : 0u);
  }
  for (int m = 0; m < 4; ++m) { fftessOut.Store((o + 30 + m) * 4, 0u); }
  fftessOut.Store((o + 34) * 4, culled ? 1u : 0u);
}
)";

// ---- helpers -------------------------------------------------------------------------------------------------------
bool readFile(const std::string& path, std::string& out) {
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  std::ostringstream ss;
  ss << f.rdbuf();
  out = ss.str();
  return true;
}

// Runs argv (PATH lookup), stdout+stderr into 'output'. Returns the exit status, or -1 when it could not run.
int runTool(const std::vector<std::string>& argv, std::string& output) {
  std::string cmd;
  for (const std::string& a : argv) {
    std::string q = "'";
    for (char c : a) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    cmd += q + "' ";
  }
  cmd += "2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return -1;
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) output.append(buf, n);
  const int st = ::pclose(p);
  if (st == -1 || !WIFEXITED(st)) return -1;
  return WEXITSTATUS(st);
}

bool onPath(const char* tool) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string dirs = path;
  size_t start = 0;
  while (start <= dirs.size()) {
    const size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string f = dirs.substr(start, end - start) + "/" + tool;
    if (::access(f.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

bool hasEntryPoint(const std::string& src) { return std::regex_search(src, std::regex(R"(\blodMain\s*\()")); }

const char* kSignatureGlsl = "LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, "
                             "LodSettings settings)";

// Lines of the compute source: the user's file keeps its own numbers (#line 1); fftess's prelude (lod/shaders/*.glsl
// and the interface types) is numbered from kPreludeLine, the wrapper from kWrapperLine, so a log line names its
// origin whatever the driver prints as the source-string number (Mesa "0:12(5): error: ...", NVIDIA
// "0(12) : error ...").
constexpr int kWrapperLine = 100001;
constexpr int kPreludeLine = 200001;

struct LogLine {
  int line = 0; // 0: no position
  int column = 0;
  std::string text; // after the position
};
LogLine parseLogLine(const std::string& l) {
  LogLine out;
  out.text = l;
  std::smatch m;
  if (std::regex_search(l, m, std::regex(R"(^(?:ERROR: |WARNING: )?\d+:(\d+)\((\d+)\):?\s*)"))) {
    out.line = std::stoi(m[1]);
    out.column = std::stoi(m[2]);
    out.text = m.suffix();
  } else if (std::regex_search(l, m, std::regex(R"(^\d+\((\d+)\)\s*:?\s*)"))) {
    out.line = std::stoi(m[1]);
    out.text = m.suffix();
  }
  return out;
}
bool isWarning(const std::string& text) {
  return text.find("warning") != std::string::npos && text.find("error") == std::string::npos;
}

// The driver's log: errors only (warnings dropped), user lines as FILE:LINE:COLUMN. wrapper: set when an error lies
// in fftess's wrapper (the call of lodMain: a wrong signature).
std::string driverLog(const std::string& log, const std::string& file, bool& wrapper) {
  std::string out;
  std::istringstream in(log);
  std::string l;
  wrapper = false;
  while (std::getline(in, l)) {
    if (l.empty()) continue;
    const LogLine p = parseLogLine(l);
    if (isWarning(p.text)) continue;
    std::string where;
    if (p.line > 0 && p.line < kWrapperLine && !file.empty()) {
      where = file + ":" + std::to_string(p.line) + (p.column > 0 ? ":" + std::to_string(p.column) : "") + ": ";
    } else if (p.line >= kPreludeLine) {
      where = "(fftess prelude, lod/shaders/*.glsl and the interface types) ";
    } else if (p.line >= kWrapperLine) {
      where = "(fftess wrapper) ";
      wrapper = true;
    }
    out += (out.empty() ? "" : "\n") + (p.line > 0 ? where + p.text : l);
  }
  return out.empty() ? log : out;
}

std::string trimLog(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ' || s.back() == '\0')) s.pop_back();
  return s;
}

} // namespace

struct GpuLodProvider::Impl {
  gltest::GlContext ctx;
  std::mutex mutex;
  GLuint program = 0;
  GLuint buffers[3] = {0, 0, 0}; // in, out, camera
  const void* inputKey = nullptr;
  size_t inputCount = static_cast<size_t>(-1);
  size_t outCapacity = 0;
  std::string description;
  vf::LodScheme scheme = vf::LodScheme::Shader;
  int64_t dispatches = 0;
  double dispatchSeconds = 0, uploadSeconds = 0, compileSeconds = 0;
  std::mutex cpuMutex;
  int64_t cpuCameras = 0;
  double cpuSeconds = 0;
  std::vector<uint32_t> words;
};

GpuLodProvider::GpuLodProvider(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuLodProvider::~GpuLodProvider() {
  if (impl_ && impl_->ctx.makeCurrent()) {
    const GlFunctions& gl = impl_->ctx.gl;
    gl.glDeleteBuffers(3, impl_->buffers);
    if (impl_->program) gl.glDeleteProgram(impl_->program);
    impl_->ctx.releaseCurrent();
  }
}
void GpuLodProvider::noteCpuSeconds(double seconds) {
  std::lock_guard<std::mutex> lock(impl_->cpuMutex);
  ++impl_->cpuCameras;
  impl_->cpuSeconds += seconds;
}
bool flushesDenormalsFor(const std::string& renderer, std::string* why) {
  bool flush = true;
  std::string w;
  if (renderer.find("llvmpipe") != std::string::npos) {
    w = "the driver: " + renderer + " flushes denormal factors (measured, docs/oracle.md)";
  } else if (renderer.find("NVIDIA") != std::string::npos) {
    flush = false;
    w = "the driver: " + renderer + " keeps denormal factors like the D3D11 reference (NVIDIA measured, docs/oracle.md)";
  } else {
    w = "the driver: " + renderer + " is not measured; assumed to flush denormal factors (--flush-denormals=off for "
        "the other rule)";
  }
  if (why) *why = w;
  return flush;
}

bool GpuLodProvider::flushesDenormals(std::string* why) const { return flushesDenormalsFor(impl_->ctx.renderer(), why); }

int64_t GpuLodProvider::cpuCameras() const { return impl_->cpuCameras; }
double GpuLodProvider::cpuSeconds() const { return impl_->cpuSeconds; }
const std::string& GpuLodProvider::renderer() const { return impl_->ctx.renderer(); }
const std::string& GpuLodProvider::version() const { return impl_->ctx.version(); }
const std::string& GpuLodProvider::description() const { return impl_->description; }
int64_t GpuLodProvider::dispatches() const { return impl_->dispatches; }
double GpuLodProvider::dispatchSeconds() const { return impl_->dispatchSeconds; }
double GpuLodProvider::uploadSeconds() const { return impl_->uploadSeconds; }
double GpuLodProvider::compileSeconds() const { return impl_->compileSeconds; }

std::shared_ptr<GpuLodProvider> createGpuLod(const vf::LodPatches& patches, const GpuLodOptions& options,
                                             std::string& error, GpuLodError& kind) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const vf::Lod& L = patches.scene().lod;
  auto impl = std::make_unique<GpuLodProvider::Impl>();
  impl->scheme = L.scheme;
  kind = GpuLodError::None;
  if (L.shader.empty() && L.scheme == vf::LodScheme::Geomorph) {
    kind = GpuLodError::Shader;
    error = "lod.scheme = \"geomorph\" has no GPU path";
    return nullptr;
  }

  // 1. The GLSL compute source (HLSL: through glslang and spirv-cross first).
  std::string source;
  const std::string& file = L.shader;
  const bool hlsl = file.size() > 5 && file.compare(file.size() - 5, 5, ".hlsl") == 0;
  std::string user;
  if (!file.empty()) {
    if (!readFile(file, user)) {
      kind = GpuLodError::Shader;
      error = file + ": cannot read the shader";
      return nullptr;
    }
    if (!hasEntryPoint(user)) {
      kind = GpuLodError::Shader;
      error = file + ": no entry point lodMain: the file must define " +
              (hlsl ? std::string("LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera "
                                  "camera, LodSettings settings) (HLSL)")
                    : std::string(kSignatureGlsl)) +
              " (docs/gpu_lod.md)";
      return nullptr;
    }
  }
  if (hlsl) {
    impl->description = "lod.shader " + file + " (HLSL -> SPIR-V -> GLSL)";
    for (const char* tool : {"glslangValidator", "spirv-cross"})
      if (!onPath(tool)) {
        kind = GpuLodError::Tools;
        error = file + ": HLSL needs " + tool + " on PATH (Debian: apt-get install glslang-tools spirv-cross)";
        return nullptr;
      }
    char dirTemplate[] = "/tmp/fftess_hlsl_XXXXXX";
    if (!::mkdtemp(dirTemplate)) {
      kind = GpuLodError::Tools;
      error = "cannot create a temporary folder for the HLSL compile";
      return nullptr;
    }
    const std::string dir = dirTemplate;
    const size_t slash = file.find_last_of('/');
    const std::string userDir = slash == std::string::npos ? "." : file.substr(0, slash);
    const std::string base = slash == std::string::npos ? file : file.substr(slash + 1);
    const std::string wrapper = dir + "/fftess_lod_wrapper.hlsl", spv = dir + "/lod.spv", glsl = dir + "/lod.comp";
    {
      std::ofstream w(wrapper, std::ios::binary);
      w << kHlslTypes << hlslSettings(L) << "#include \"" << base << "\"\n" << kHlslMain;
    }
    std::string log;
    const int rc = runTool({"glslangValidator", "-D", "-V", "-S", "comp", "-e", "main", "-I" + userDir, "-o", spv,
                            wrapper},
                           log);
    auto cleanup = [&]() {
      for (const std::string& f : {wrapper, spv, glsl}) ::unlink(f.c_str());
      ::rmdir(dir.c_str());
    };
    if (rc != 0) {
      kind = rc < 0 ? GpuLodError::Tools : GpuLodError::Shader;
      // glslang names the included file by the path it found ("DIR/FILE:LINE"); errors in the wrapper are a wrong
      // signature of lodMain (its only contact with your code).
      // Errors only, the wrapper's temporary path as "(fftess wrapper)", glslang's summary lines dropped.
      std::string msg;
      bool inWrapper = false, inUser = false;
      {
        std::istringstream in(log);
        std::string l;
        while (std::getline(in, l)) {
          if (l.empty() || l == wrapper || l.find("compilation errors") != std::string::npos ||
              l.find("SPIR-V is not generated") != std::string::npos || isWarning(l))
            continue;
          for (size_t at; (at = l.find(wrapper)) != std::string::npos;) {
            l.replace(at, wrapper.size(), "(fftess wrapper)");
            inWrapper = true;
          }
          if (l.find(base + ":") != std::string::npos) inUser = true;
          msg += (msg.empty() ? "" : "\n") + l;
        }
      }
      if (msg.empty()) msg = trimLog(log);
      if (inWrapper && !inUser)
        error = file + ": lodMain has the wrong signature or return type: expected LodFactors lodMain(LodPatch quad, "
                       "TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) (docs/gpu_lod.md); "
                       "glslang says:\n" + msg;
      else
        error = file + ": HLSL compile failed (glslangValidator):\n" + msg;
      cleanup();
      return nullptr;
    }
    log.clear();
    const int rc2 = runTool({"spirv-cross", "--version", "450", "--no-es", "--output", glsl, spv}, log);
    if (rc2 != 0 || !readFile(glsl, source)) {
      kind = GpuLodError::Tools;
      error = file + ": spirv-cross failed:\n" + trimLog(log);
      cleanup();
      return nullptr;
    }
    cleanup();
  } else {
    const std::string header = glslHeader();
    const size_t firstNewline = header.find('\n');
    source = header.substr(0, firstNewline + 1) + "#line " + std::to_string(kPreludeLine) + "\n" +
             header.substr(firstNewline + 1) + glslSettings(L);
    const std::string wrapperLine = "#line " + std::to_string(kWrapperLine) + "\n";
    if (!file.empty()) {
      impl->description = "lod.shader " + file + " (GLSL)";
      source += "#line 1\n" + user + "\n" + wrapperLine + kGlslUserEvaluate;
    } else {
      impl->description = std::string("built-in ") + vf::toString(L.scheme) + " (lod/shaders/*.glsl)";
      source += wrapperLine + glslBuiltin(L, patches.sizeJumps());
    }
    source += kGlslMain;
  }

  // 2. The context and the program.
  gltest::ContextOptions co;
  co.order = options.hardware ? gltest::DeviceOrder::HardwareFirst : gltest::DeviceOrder::SoftwareFirst;
  co.allowSoftware = !options.hardware;
  if (!impl->ctx.create(co, error)) {
    kind = GpuLodError::NoContext;
    return nullptr;
  }
  const GlFunctions& gl = impl->ctx.gl;
  const GLuint sh = gl.glCreateShader(GL_COMPUTE_SHADER);
  const char* src = source.c_str();
  gl.glShaderSource(sh, 1, &src, nullptr);
  gl.glCompileShader(sh);
  GLint ok = 0;
  gl.glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  std::string log(16384, '\0');
  if (!ok) {
    gl.glGetShaderInfoLog(sh, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log = trimLog(log.c_str());
    kind = GpuLodError::Shader;
    const std::string where = file.empty() ? std::string("built-in ") + vf::toString(L.scheme) : file;
    bool wrapper = false;
    const std::string named = hlsl ? log : driverLog(log, file, wrapper);
    if (!hlsl && !file.empty() && wrapper)
      error = file + ": lodMain has the wrong signature or return type: expected " + kSignatureGlsl +
              " (docs/gpu_lod.md); the driver (" + impl->ctx.renderer() + ") says:\n" + named;
    else
      error = where + ": GLSL compile failed on " + impl->ctx.renderer() + ":\n" + named;
    gl.glDeleteShader(sh);
    impl->ctx.releaseCurrent();
    return nullptr;
  }
  impl->program = gl.glCreateProgram();
  gl.glAttachShader(impl->program, sh);
  gl.glLinkProgram(impl->program);
  gl.glGetProgramiv(impl->program, GL_LINK_STATUS, &ok);
  gl.glDetachShader(impl->program, sh);
  gl.glDeleteShader(sh);
  if (!ok) {
    gl.glGetProgramInfoLog(impl->program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    kind = GpuLodError::Shader;
    error = (file.empty() ? std::string("built-in LOD") : file) + ": GL program link failed on " +
            impl->ctx.renderer() + ":\n" + trimLog(log.c_str());
    impl->ctx.releaseCurrent();
    return nullptr;
  }
  gl.glGenBuffers(3, impl->buffers);
  if (!gltest::checkGl(gl, "creating the GPU LOD program", error)) {
    kind = GpuLodError::Gl;
    impl->ctx.releaseCurrent();
    return nullptr;
  }
  impl->ctx.releaseCurrent(); // sweep threads take it in turn (evaluate)
  impl->compileSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return std::make_shared<GpuLodProvider>(std::move(impl));
}

bool GpuLodProvider::evaluate(const vf::LodPatches& patches, const lod::Camera& camera,
                              std::vector<lod::PatchLod>& out, std::string& error) {
  using Clock = std::chrono::steady_clock;
  Impl& m = *impl_;
  std::lock_guard<std::mutex> lock(m.mutex);
  if (!m.ctx.makeCurrent()) {
    error = "GPU LOD: cannot make the OpenGL context current";
    return false;
  }
  struct Release {
    gltest::GlContext& c;
    ~Release() { c.releaseCurrent(); }
  } release{m.ctx};
  const GlFunctions& gl = m.ctx.gl;
  const size_t n = patches.size();
  if (n == 0) {
    out.clear();
    return true;
  }
  // The patches' inputs: once per terrain.
  if (m.inputKey != patches.key() || m.inputCount != n) {
    const auto t0 = Clock::now();
    m.words.assign(n * kInWords, 0);
    for (size_t i = 0; i < n; ++i) {
      const vf::LodInput in = patches[i];
      uint32_t* w = m.words.data() + i * kInWords;
      for (int c = 0; c < 4; ++c)
        for (int k = 0; k < 3; ++k) w[c * 3 + k] = bitsOf(in.patch.corners[c][k]);
      w[12] = in.patch.useHeightBounds ? 1u : 0u;
      w[13] = bitsOf(in.patch.minHeight);
      w[14] = bitsOf(in.patch.maxHeight);
      for (int e = 0; e < 4; ++e) {
        w[15 + e] = bitsOf(in.neighbours.size[e]);
        for (int k = 0; k < 3; ++k) w[21 + e * 3 + k] = bitsOf(in.neighbours.farCorner[e][k]);
        w[33 + e] = bitsOf(in.neighbours.rebuiltHeight[e]);
      }
      w[19] = in.neighbours.oddU ? 1u : 0u;
      w[20] = in.neighbours.oddV ? 1u : 0u;
    }
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[0]);
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(m.words.size() * 4), m.words.data(),
                    GL_STATIC_DRAW);
    if (m.outCapacity < n) {
      gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[1]);
      gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(n * kOutWords * 4), nullptr,
                      GL_DYNAMIC_READ);
      m.outCapacity = n;
    }
    m.inputKey = patches.key();
    m.inputCount = n;
    m.uploadSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  const auto t0 = Clock::now();
  uint32_t cam[kCamWords];
  for (int k = 0; k < 16; ++k) {
    cam[k] = bitsOf(camera.view[k / 4][k % 4]);
    cam[16 + k] = bitsOf(camera.projection[k / 4][k % 4]);
  }
  cam[32] = bitsOf(camera.viewport.x);
  cam[33] = bitsOf(camera.viewport.y);
  for (int k = 0; k < 3; ++k) cam[34 + k] = bitsOf(camera.eye[k]);
  cam[37] = camera.depthZeroToOne ? 1u : 0u;
  cam[38] = static_cast<uint32_t>(n);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[2]);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof cam, cam, GL_DYNAMIC_DRAW);
  gl.glUseProgram(m.program);
  for (GLuint b = 0; b < 3; ++b) gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, b, m.buffers[b]);
  gl.glDispatchCompute(static_cast<GLuint>((n + 63) / 64), 1, 1);
  gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  m.words.resize(n * kOutWords);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.buffers[1]);
  gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * kOutWords * 4), m.words.data());
  if (!gltest::checkGl(gl, "the GPU LOD dispatch", error)) {
    m.inputKey = nullptr; // upload again next time
    return false;
  }
  out.resize(n);
  const lod::Scheme scheme = m.scheme == vf::LodScheme::DistancePow2   ? lod::Scheme::DistancePow2
                             : m.scheme == vf::LodScheme::Bonaventura  ? lod::Scheme::Bonaventura
                             : m.scheme == vf::LodScheme::ClipDiameter ? lod::Scheme::ClipDiameter
                             : m.scheme == vf::LodScheme::PatchCenter  ? lod::Scheme::PatchCenter
                             : m.scheme == vf::LodScheme::Constant     ? lod::Scheme::Constant
                                                                       : lod::Scheme::ScreenSphere;
  for (size_t i = 0; i < n; ++i) {
    const uint32_t* w = m.words.data() + i * kOutWords;
    lod::PatchLod& r = out[i];
    r.why.scheme = scheme;
    for (int k = 0; k < 6; ++k) {
      r.factors[k] = floatOf(w[k * 5]);
      r.why.factor[k].metric = floatOf(w[k * 5 + 1]);
      r.why.factor[k].unclamped = floatOf(w[k * 5 + 2]);
      r.why.factor[k].exponent = floatOf(w[k * 5 + 3]);
      r.why.factor[k].fixes = w[k * 5 + 4];
    }
    for (int c = 0; c < 4; ++c) r.why.cornerLevel[c] = floatOf(w[30 + c]);
    r.why.culled = w[34] != 0;
  }
  ++m.dispatches;
  m.dispatchSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
  return true;
}

} // namespace fftess::gpulod
