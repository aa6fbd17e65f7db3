// gpu_lod/wrapper.h: the user's HLSL file through glslang's HLSL front end. fftess writes a compute wrapper that
// #includes the file (so glslang names the file's own lines), compiles it to SPIR-V with glslangValidator and
// translates that back to GLSL 4.50 with spirv-cross; the GLSL then takes the same GL path as a GLSL file.
#include "gpu_lod/wrapper.h"

#include "lod/lod_fields.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace fftess::gpulod::detail {

const char* const kSignatureHlsl = "LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, "
                                   "LodSettings settings) (HLSL)";

namespace {

namespace vf = fftess::verify;

const char* const kHlslTypes = R"(// fftess GPU LOD interface, HLSL (docs/gpu_lod.md). Generated; your file is included below.
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
struct LodFactors {
  float factor[6];       // Ueq0 Veq0 Ueq1 Veq1 insideU insideV (SV_TessFactor[0..3], SV_InsideTessFactor[0..1])
  bool culled;
};
)";

// The codes of LodSettings' clampMode and rebuild (lod/lod_fields.h), as the GLSL prelude has them.
#define FFTESS_GPULOD_HLSL_CODE(Enum, enumerator, constant, code) "static const int " #constant " = " #code ";\n"
const char* const kHlslCodes =
    FFTESS_LOD_ADJACENCY_CLAMP_CODES(FFTESS_GPULOD_HLSL_CODE) FFTESS_LOD_RECONSTRUCTION_CODES(FFTESS_GPULOD_HLSL_CODE);
#undef FFTESS_GPULOD_HLSL_CODE

const char* const kHlslBuffers = R"([[vk::binding(0)]] ByteAddressBuffer fftessIn;
[[vk::binding(1)]] RWByteAddressBuffer fftessOut;
[[vk::binding(2)]] ByteAddressBuffer fftessCam;
)";

// The buffers (wrapper.h) -> lodMain -> the output buffer, as the GLSL wrapper does for a GLSL file.
const char* const kHlslMain = R"(
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

// The temporary folder of one HLSL compile: the wrapper, the SPIR-V and the GLSL; removed when it goes.
struct HlslFiles {
  std::string dir, wrapper, spv, glsl;
  ~HlslFiles() {
    if (dir.empty()) return;
    for (const std::string& f : {wrapper, spv, glsl}) ::unlink(f.c_str());
    ::rmdir(dir.c_str());
  }
};

// glslang's log for the message: errors only, the wrapper's temporary path as "(fftess wrapper)", glslang's summary
// lines dropped. inWrapper / inUser: whether an error names the wrapper / the user's file (base: its name).
std::string glslangErrors(const std::string& log, const std::string& wrapper, const std::string& base,
                          bool& inWrapper, bool& inUser) {
  std::string msg;
  inWrapper = inUser = false;
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
    // "ERROR: FILE:LINE: text" -> "FILE:LINE: error: text" (the form an editor reads, as the GLSL path prints).
    static const std::regex glslangError(R"(^ERROR: ([^:]+:\d+(?::\d+)?): (.*)$)");
    std::smatch m;
    if (std::regex_match(l, m, glslangError)) l = m[1].str() + ": error: " + m[2].str();
    msg += (msg.empty() ? "" : "\n") + l;
  }
  return msg.empty() ? trimLog(log) : msg;
}

} // namespace

bool hlslToGlsl(const vf::Lod& L, std::string& glsl, std::string& error, GpuLodError& kind) {
  const std::string& file = L.shader;
  for (const char* tool : {"glslangValidator", "spirv-cross"})
    if (!onPath(tool)) {
      kind = GpuLodError::Tools;
      error = file + ": HLSL needs " + tool + " on PATH (Debian: apt-get install glslang-tools spirv-cross)";
      return false;
    }
  char dirTemplate[] = "/tmp/fftess_hlsl_XXXXXX";
  if (!::mkdtemp(dirTemplate)) {
    kind = GpuLodError::Tools;
    error = "cannot create a temporary folder for the HLSL compile";
    return false;
  }
  HlslFiles t;
  t.dir = dirTemplate;
  t.wrapper = t.dir + "/fftess_lod_wrapper.hlsl", t.spv = t.dir + "/lod.spv", t.glsl = t.dir + "/lod.comp";
  const size_t slash = file.find_last_of('/');
  const std::string userDir = slash == std::string::npos ? "." : file.substr(0, slash);
  const std::string base = slash == std::string::npos ? file : file.substr(slash + 1);
  {
    std::ofstream w(t.wrapper, std::ios::binary);
    w << kHlslTypes << lodSettingsStruct() << kHlslCodes << kHlslBuffers << lodSettingsFunction(L, true)
      << "#include \"" << base << "\"\n"
      << kHlslMain;
  }
  std::string log;
  const int rc = runTool(
      {"glslangValidator", "-D", "-V", "-S", "comp", "-e", "main", "-I" + userDir, "-o", t.spv, t.wrapper}, log);
  if (rc != 0) {
    kind = rc < 0 ? GpuLodError::Tools : GpuLodError::Shader;
    // glslang names the included file by the path it found ("DIR/FILE:LINE"); errors in the wrapper are a wrong
    // signature of lodMain (its only contact with your code).
    bool inWrapper = false, inUser = false;
    const std::string msg = glslangErrors(log, t.wrapper, base, inWrapper, inUser);
    if (inWrapper && !inUser)
      error = file + ": lodMain has the wrong signature or return type: expected LodFactors lodMain(LodPatch quad, "
                     "TileNeighbourInfo neighbours, LodCamera camera, LodSettings settings) (docs/gpu_lod.md); "
                     "glslang says:\n" + msg;
    else
      error = file + ": HLSL compile failed (glslangValidator):\n" + msg;
    return false;
  }
  log.clear();
  const int rc2 = runTool({"spirv-cross", "--version", "450", "--no-es", "--output", t.glsl, t.spv}, log);
  if (rc2 != 0 || !readFile(t.glsl, glsl)) {
    kind = GpuLodError::Tools;
    error = file + ": spirv-cross failed:\n" + trimLog(log);
    return false;
  }
  return true;
}

} // namespace fftess::gpulod::detail
