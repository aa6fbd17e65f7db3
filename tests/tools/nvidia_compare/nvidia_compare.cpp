// fftess_nvidia_compare: fftess against a real hardware tessellator (NVIDIA, through OpenGL 4.5 + headless EGL),
// compared as what is comparable when the hardware's order differs from the reference. See tests/tools/nvidia_compare/README.md
// and docs/oracle.md, "Real hardware: NVIDIA".
//
//   fftess_nvidia_compare gen [PATCHES [SEED]]            print the batch lines (sweep + seeded random patches)
//   fftess_nvidia_compare run [options] [PATCHES [SEED]]  capture on the GL driver, tessellate with fftess, compare
//     --batch FILE        take the patches from a batch file instead of the generator
//     --allow-llvmpipe    accept Mesa's llvmpipe (a self-test of this tool; default: refuse it)
//     --flush-denormals   run fftess with Options::flushDenormals = true (what llvmpipe does; default false = reference)
//     --no-sweep          random patches only
//     --diffs FILE        write every differing patch as "CLASS<TAB>batch line"
//
// Per patch, compared (no order assumed):
//   points      the multiset of (u bits, v bits) of the point_mode capture vs fftess's points;
//   triangles   (quad/tri triangle_cw/ccw) the multiset of triangles as coordinate triples, each rotated so its
//               smallest vertex comes first (winding kept), vs fftess's indices resolved to its points;
//   segments    (isoline line) the multiset of segments as ordered coordinate pairs.
// Also reported, not required: whether the point sequence / primitive sequence is identical in order too.
// Not compared: indices as numbers (the hardware's numbering is not observable without an order assumption), quad/tri
// 'line' and 'point' topologies beyond their points (GL has no such output), w of tri points, the HLSL stage.
//
// The generator is gl/random_patches.h, shared with tests/oracle/vs_emulator_test.cpp, so a seed gives
// the same patches as that llvmpipe test. The context is gl/gl_context.h (hardware EGL devices first).
#include "gl_capture.h"     // Patch, enums, parseBatch, batchLine, toString (batch.cpp); pointBound, glSpacing
#include "gl_context.h"     // headless EGL context, GL loader, renderer check
#include "random_patches.h" // the seeded generator (Rng, randomPatch, sweepPatches, generatePatches)

#include "tessellator/tessellator.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace fftess::oracle;
using fftess::bitsOf;  // base/bits.h
using fftess::floatOf;

namespace {

// ---------------------------------------------------------------- GL capture (no order assumed)

using fftess::gltest::GlFunctions;

enum class Capture { Points, GlCcw, GlCw, Lines };

// What the driver gave for one patch, in capture order.
struct Captured {
  std::vector<uint64_t> points;     // (u bits << 32) | v bits, point_mode order
  std::vector<uint64_t> primitives; // 3 (triangles) or 2 (lines) coordinates per primitive, capture order
};

// Domain points per draw (by the bound); triangles <= 2 per point. llvmpipe (self-test only) needs <= 65536 per draw
// (16-bit vertex numbering, docs/oracle.md).
constexpr int kDrawPointBudget = 200000;
constexpr int kLlvmpipeDrawPointBudget = 60000;
constexpr int kMaxPatchesPerDraw = 4096;
constexpr size_t kCaptureVertices = 6u * kDrawPointBudget;

struct GlCapture {
  fftess::gltest::GlContext context;
  GlFunctions& gl = context.gl;
  GLuint factorBuf = 0, captureBuf = 0, queries[2] = {0, 0};
  std::map<std::pair<int, int>, std::pair<GLuint, GLint>> programs; // (domain*3+spacing, capture) -> (program, patchBase)
  long drawCalls = 0;
  int drawPointBudget = kDrawPointBudget;
  bool patchOrderSeen = true; // every draw's capture arrived in gl_PrimitiveID order (information only)

  // Hardware EGL devices first; software devices and the surfaceless platform only as a self-test.
  bool create(bool allowSoftware, std::string& error) {
    fftess::gltest::ContextOptions options;
    options.order = fftess::gltest::DeviceOrder::HardwareFirst;
    options.allowSoftware = allowSoftware;
    if (!context.create(options, error) || !context.checkHardwareRenderer(allowSoftware, error)) return false;
    if (context.isLlvmpipe()) drawPointBudget = kLlvmpipeDrawPointBudget;
    GLuint fbo = 0, vao = 0;
    if (!fftess::gltest::prepareCaptureDraws(gl, fbo, vao, error)) return false;
    GLuint bufs[2];
    gl.glGenBuffers(2, bufs);
    factorBuf = bufs[0], captureBuf = bufs[1];
    gl.glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, captureBuf);
    gl.glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(kCaptureVertices * 16), nullptr,
                    GL_DYNAMIC_READ);
    gl.glGenQueries(2, queries);
    return checkGl("setup", error);
  }

  bool checkGl(const char* what, std::string& error) { return fftess::gltest::checkGl(gl, what, error); }

  std::pair<GLuint, GLint>* program(Domain domain, int spacing, Capture cap, std::string& error) {
    const std::pair<int, int> key{static_cast<int>(domain) * 3 + spacing, static_cast<int>(cap)};
    auto it = programs.find(key);
    if (it != programs.end()) return &it->second;
    const char* vs = "#version 450 core\nvoid main() { gl_Position = vec4(0.0); }\n";
    // Factors as raw bits; slots per patch: outer[0..3], inner[0..1].
    const char* tcs = R"(#version 450 core
layout(vertices = 1) out;
layout(std430, binding = 0) readonly buffer Factors { uint f[]; };
uniform uint patchBase;
void main() {
  uint b = (patchBase + uint(gl_PrimitiveID)) * 6u;
  gl_TessLevelOuter[0] = uintBitsToFloat(f[b + 0u]);
  gl_TessLevelOuter[1] = uintBitsToFloat(f[b + 1u]);
  gl_TessLevelOuter[2] = uintBitsToFloat(f[b + 2u]);
  gl_TessLevelOuter[3] = uintBitsToFloat(f[b + 3u]);
  gl_TessLevelInner[0] = uintBitsToFloat(f[b + 4u]);
  gl_TessLevelInner[1] = uintBitsToFloat(f[b + 5u]);
}
)";
    std::string layout = domain == Domain::Quad ? "quads" : domain == Domain::Tri ? "triangles" : "isolines";
    layout += spacing == 0 ? ", equal_spacing" : spacing == 1 ? ", fractional_odd_spacing" : ", fractional_even_spacing";
    if (cap == Capture::Points) layout += ", point_mode";
    if (cap == Capture::GlCcw) layout += ", ccw";
    if (cap == Capture::GlCw) layout += ", cw";
    const std::string tes = "#version 450 core\nlayout(" + layout +
                            ") in;\nflat out uvec4 cap;\n"
                            "void main() {\n  cap = uvec4(floatBitsToUint(gl_TessCoord.xy), uint(gl_PrimitiveID), 0u);\n"
                            "  gl_Position = vec4(0.0);\n}\n";
    GLuint s[3] = {gl.glCreateShader(GL_VERTEX_SHADER), gl.glCreateShader(GL_TESS_CONTROL_SHADER),
                   gl.glCreateShader(GL_TESS_EVALUATION_SHADER)};
    if (!fftess::gltest::compileShader(gl, s[0], vs, error) || !fftess::gltest::compileShader(gl, s[1], tcs, error) ||
        !fftess::gltest::compileShader(gl, s[2], tes, error))
      return nullptr;
    const GLuint prog = gl.glCreateProgram();
    for (GLuint sh : s) gl.glAttachShader(prog, sh);
    const char* varyings[] = {"cap"};
    gl.glTransformFeedbackVaryings(prog, 1, varyings, GL_INTERLEAVED_ATTRIBS);
    if (!fftess::gltest::linkProgram(gl, prog, error)) return nullptr;
    return &programs.emplace(key, std::make_pair(prog, gl.glGetUniformLocation(prog, "patchBase"))).first->second;
  }

  // Draws patches [first, first+count) of the uploaded factor array; files each captured primitive under its
  // gl_PrimitiveID. perPrim = vertices per captured primitive.
  bool draw(const std::pair<GLuint, GLint>& prog, Capture cap, int first, int count, std::vector<Captured*>& out,
            std::string& error) {
    gl.glUseProgram(prog.first);
    gl.glUniform1ui(prog.second, static_cast<GLuint>(first));
    const GLenum mode = cap == Capture::Points ? GL_POINTS : cap == Capture::Lines ? GL_LINES : GL_TRIANGLES;
    const int perPrim = cap == Capture::Points ? 1 : cap == Capture::Lines ? 2 : 3;
    gl.glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captureBuf);
    gl.glBeginQuery(GL_PRIMITIVES_GENERATED, queries[0]);
    gl.glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, queries[1]);
    gl.glBeginTransformFeedback(mode);
    gl.glDrawArrays(GL_PATCHES, 0, count);
    ++drawCalls;
    gl.glEndTransformFeedback();
    gl.glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    gl.glEndQuery(GL_PRIMITIVES_GENERATED);
    if (!checkGl("a draw", error)) return false;
    GLuint generated = 0, written = 0;
    gl.glGetQueryObjectuiv(queries[0], GL_QUERY_RESULT, &generated);
    gl.glGetQueryObjectuiv(queries[1], GL_QUERY_RESULT, &written);
    if (generated != written) {
      error = "transform feedback overflow: " + std::to_string(generated) + " primitives generated, " +
              std::to_string(written) + " written";
      return false;
    }
    std::vector<uint32_t> words(static_cast<size_t>(written) * perPrim * 4);
    gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.glBindBuffer(GL_COPY_READ_BUFFER, captureBuf);
    if (!words.empty())
      gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(words.size() * 4), words.data());
    if (!checkGl("reading the capture", error)) return false;
    uint32_t last = 0;
    for (size_t v = 0; v < words.size(); v += static_cast<size_t>(perPrim) * 4) {
      const uint32_t local = words[v + 2];
      if (local < last) patchOrderSeen = false;
      last = local;
      for (int k = 0; k < perPrim; ++k)
        if (words[v + 4 * k + 2] != local || local >= static_cast<uint32_t>(count)) {
          error = "a captured primitive names a patch outside the draw, or mixes patches";
          return false;
        }
      Captured& c = *out[local];
      for (int k = 0; k < perPrim; ++k) {
        const uint64_t key = uint64_t(words[v + 4 * k]) << 32 | words[v + 4 * k + 1];
        (cap == Capture::Points ? c.points : c.primitives).push_back(key);
      }
    }
    return true;
  }

  // Captures every patch of one (domain, spacing) group. GL slot order: quad outer = Ueq0 Veq0 Ueq1 Veq1, inner =
  // insideU insideV; tri outer[0..2] = Ueq0 Veq0 Weq0, inner[0] = inside; isoline outer[0] = density, [1] = detail.
  // D3D triangle_cw = GL ccw, D3D triangle_ccw = GL cw (docs/oracle.md).
  bool runGroup(const std::vector<Patch>& patches, const std::vector<int>& members, int spacing, Capture cap,
                std::vector<Captured>& results, std::string& error) {
    if (members.empty()) return true;
    const Domain domain = patches[members[0]].domain;
    std::vector<uint32_t> factors(members.size() * 6, 0u);
    for (size_t i = 0; i < members.size(); ++i) {
      const uint32_t* f = patches[members[i]].factorBits;
      uint32_t* g = &factors[i * 6];
      if (domain == Domain::Quad) std::copy_n(f, 6, g);
      else if (domain == Domain::Tri) g[0] = f[0], g[1] = f[1], g[2] = f[2], g[4] = f[3];
      else g[0] = f[0], g[1] = f[1];
    }
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, factorBuf);
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(factors.size() * 4), factors.data(),
                    GL_DYNAMIC_DRAW);
    gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, factorBuf);
    auto* prog = program(domain, spacing, cap, error);
    if (!prog) return false;
    const int n = static_cast<int>(members.size());
    for (int begin = 0; begin < n;) {
      int end = begin;
      long budget = 0;
      while (end < n && end - begin < kMaxPatchesPerDraw) {
        const int b = pointBound(patches[members[end]]);
        if (end > begin && budget + b > drawPointBudget) break;
        budget += b;
        ++end;
      }
      std::vector<Captured*> out;
      for (int i = begin; i < end; ++i) out.push_back(&results[members[i]]);
      if (!draw(*prog, cap, begin, end - begin, out, error)) return false;
      begin = end;
    }
    return true;
  }
};

// ---------------------------------------------------------------- comparison

fftess::Patch toEmulator(const Patch& p) {
  fftess::Patch e;
  e.domain = static_cast<fftess::Domain>(static_cast<int>(p.domain));
  e.partitioning = static_cast<fftess::Partitioning>(static_cast<int>(p.partitioning));
  e.primitive = static_cast<fftess::OutputPrimitive>(static_cast<int>(p.topology));
  for (int i = 0; i < 6; ++i) e.factors[i] = floatOf(p.factorBits[i]);
  return e;
}

bool drawsPrimitives(const Patch& p) {
  return p.domain == Domain::Isoline ? p.topology == Topology::Line
                                     : p.topology == Topology::TriangleCw || p.topology == Topology::TriangleCcw;
}

// Rotation-normalised primitives (triangles: smallest vertex first, cyclic order kept = winding kept; lines: as
// given), sorted. With 'unordered', the vertices of each primitive are sorted (winding / direction ignored).
std::vector<std::array<uint64_t, 3>> normalise(const std::vector<uint64_t>& verts, int per, bool unordered) {
  std::vector<std::array<uint64_t, 3>> out;
  out.reserve(verts.size() / per);
  for (size_t i = 0; i + per <= verts.size(); i += per) {
    std::array<uint64_t, 3> t{verts[i], verts[i + 1], per == 3 ? verts[i + 2] : 0};
    if (unordered) std::sort(t.begin(), t.begin() + per);
    else if (per == 3) {
      // The lexicographically smallest rotation: with two coincident vertices (A,A,B), (A,B,A) and (B,A,A) are the
      // same triangle, and its reverse is one of them (winding is not observable in coordinates there).
      const std::array<uint64_t, 3> r1{t[1], t[2], t[0]}, r2{t[2], t[0], t[1]};
      t = std::min({t, r1, r2});
    }
    out.push_back(t);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// Exact orientation of a triangle of domain points: the reference places every point on the 16.16 grid, so u*65536
// and v*65536 are integers (checked; 'offGrid' is set otherwise). +1 counter-clockwise in (u,v), -1 clockwise, 0
// degenerate (coincident or collinear vertices).
int orientation(const std::array<uint64_t, 3>& t, bool& offGrid) {
  int64_t x[3], y[3];
  for (int k = 0; k < 3; ++k) {
    const double u = static_cast<double>(floatOf(static_cast<uint32_t>(t[k] >> 32))) * 65536.0;
    const double v = static_cast<double>(floatOf(static_cast<uint32_t>(t[k]))) * 65536.0;
    if (u != std::floor(u) || v != std::floor(v) || std::fabs(u) > 1e6 || std::fabs(v) > 1e6) offGrid = true;
    x[k] = static_cast<int64_t>(u), y[k] = static_cast<int64_t>(v);
  }
  const int64_t d = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  return d > 0 ? 1 : d < 0 ? -1 : 0;
}

bool isDenormal(uint32_t b) { return (b & 0x7f800000u) == 0 && (b & 0x007fffffu) != 0; }
bool isNan(uint32_t b) { return (b & 0x7f800000u) == 0x7f800000u && (b & 0x007fffffu) != 0; }
bool isInf(uint32_t b) { return (b & 0x7fffffffu) == 0x7f800000u; }

// The special factors a patch uses, all of them (for the diffs file) and the one most likely to explain a
// difference (for the summary): outer before inner; denormal, NaN, Inf, > 64, <= 0, in that order.
std::string factorTag(uint32_t b, bool outer) {
  const char* where = outer ? "outer" : "inner";
  const float f = floatOf(b);
  if (isDenormal(b)) return std::string(b >> 31 ? "-" : "+") + "denormal-" + where;
  if (isNan(b)) return std::string("nan-") + where;
  if (isInf(b)) return std::string(b >> 31 ? "-" : "+") + "inf-" + where;
  if (f > 64.0f) return std::string(">64-") + where;
  if (f <= 0.0f) return std::string("<=0-") + where;
  return "";
}
std::string factorTags(const Patch& p, bool primaryOnly) {
  const int outer = p.domain == Domain::Quad ? 4 : p.domain == Domain::Tri ? 3 : 2;
  const int used = p.domain == Domain::Quad ? 6 : p.domain == Domain::Tri ? 4 : 2;
  std::vector<std::string> tags;
  for (int i = 0; i < used; ++i) {
    const std::string t = factorTag(p.factorBits[i], i < outer);
    if (!t.empty() && std::find(tags.begin(), tags.end(), t) == tags.end()) tags.push_back(t);
  }
  if (tags.empty()) return "ordinary factors";
  if (primaryOnly) {
    const char* order[] = {"+denormal-outer", "-denormal-outer", "nan-outer", "+inf-outer", "-inf-outer", ">64-outer",
                           "<=0-outer", "+denormal-inner", "-denormal-inner", "nan-inner", "+inf-inner", "-inf-inner",
                           ">64-inner", "<=0-inner"};
    for (const char* o : order)
      if (std::find(tags.begin(), tags.end(), o) != tags.end()) return std::string("has ") + o;
  }
  std::string all;
  for (const std::string& t : tags) all += (all.empty() ? "" : ",") + t;
  return all;
}

struct Stats {
  long patches = 0, agree = 0, culledBoth = 0, withPrims = 0, pointOrderSame = 0, primOrderSame = 0,
       primSetSameOrderDiffers = 0, pointsWithDuplicates = 0;
  // Triangles fftess emits with one winding and the driver with the other, by the exact orientation of fftess's one.
  long long coincidentTriangles = 0; // fftess triangles with two or three coincident vertices (information)
  long long flipped = 0, flippedDegenerate = 0, flippedCoincident = 0, flippedOffGrid = 0;
  long long points = 0, prims = 0;
  std::map<std::string, long> classes;                              // difference class -> patches
  std::map<std::string, std::vector<std::string>> examples;         // class -> first batch lines
  std::map<std::string, std::pair<long, long>> perMode;             // "domain partitioning" -> (patches, differ)
};

} // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || (args[0] != "gen" && args[0] != "run")) {
    std::fprintf(stderr, "usage: %s gen [PATCHES [SEED]] | run [--batch FILE] [--allow-llvmpipe] [--flush-denormals] "
                         "[--no-sweep] [--diffs FILE] [PATCHES [SEED]]\n", argv[0]);
    return 1;
  }
  const bool gen = args[0] == "gen";
  std::string batchFile, diffsFile;
  bool allowSoftware = false, flush = false, sweep = true;
  std::vector<std::string> pos;
  for (size_t i = 1; i < args.size(); ++i) {
    if (args[i] == "--batch" && i + 1 < args.size()) batchFile = args[++i];
    else if (args[i] == "--diffs" && i + 1 < args.size()) diffsFile = args[++i];
    else if (args[i] == "--allow-llvmpipe") allowSoftware = true;
    else if (args[i] == "--flush-denormals") flush = true;
    else if (args[i] == "--no-sweep") sweep = false;
    else if (!args[i].empty() && args[i][0] != '-') pos.push_back(args[i]);
    else {
      std::fprintf(stderr, "fftess_nvidia_compare: unknown argument '%s'\n", args[i].c_str());
      return 1;
    }
  }
  const long total = pos.size() > 0 ? std::strtol(pos[0].c_str(), nullptr, 0) : 30000;
  const uint64_t seed = pos.size() > 1 ? std::strtoull(pos[1].c_str(), nullptr, 0) : 20261122u;

  std::vector<Patch> patches;
  if (!batchFile.empty()) {
    std::ifstream in(batchFile, std::ios::binary);
    if (!in) {
      std::fprintf(stderr, "fftess_nvidia_compare: cannot read '%s'\n", batchFile.c_str());
      return 2;
    }
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::vector<BatchLine> lines;
    std::string error;
    if (!parseBatch(text, lines, error)) {
      std::fprintf(stderr, "fftess_nvidia_compare: %s: %s\n", batchFile.c_str(), error.c_str());
      return 2;
    }
    for (const BatchLine& b : lines) patches.push_back(b.patch);
  } else {
    patches = generatePatches(total, seed, sweep);
  }
  if (gen) {
    std::string out;
    for (const Patch& p : patches) out += batchLine(p) + "\n";
    std::fwrite(out.data(), 1, out.size(), stdout);
    return std::fflush(stdout) == 0 ? 0 : 1;
  }

  GlCapture glc;
  std::string error;
  if (!glc.create(allowSoftware, error)) {
    std::fprintf(stderr, "fftess_nvidia_compare: %s\n", error.c_str());
    return 3;
  }
  const fftess::gltest::GlContext& ctx = glc.context;
  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\nGL_VENDOR: %s\nEGL_VENDOR: %s (%s)\n", ctx.renderer().c_str(),
              ctx.version().c_str(), ctx.vendor().c_str(), ctx.eglVendor().c_str(), ctx.deviceNote().c_str());
  std::printf("patches: %zu (%s), fftess flushDenormals = %s\n", patches.size(),
              batchFile.empty() ? ("generator: " + std::string(sweep ? "sweep 6348 + " : "") + std::to_string(total) +
                                   " random, seed " + std::to_string(seed)).c_str()
                                : batchFile.c_str(),
              flush ? "true" : "false");
  std::fflush(stdout);

  // Capture in chunks (bounded memory), grouped per (domain, spacing) and per capture kind inside a chunk.
  constexpr size_t kChunk = 20000;
  fftess::Tessellator tess;
  fftess::Options options;
  options.flushDenormals = flush;
  Stats st;
  double glSeconds = 0, emuSeconds = 0, cmpSeconds = 0;
  std::FILE* diffs = diffsFile.empty() ? nullptr : std::fopen(diffsFile.c_str(), "w");
  for (size_t c0 = 0; c0 < patches.size(); c0 += kChunk) {
    const size_t c1 = std::min(patches.size(), c0 + kChunk);
    const std::vector<Patch> chunk(patches.begin() + static_cast<long>(c0), patches.begin() + static_cast<long>(c1));
    std::vector<Captured> got(chunk.size());
    std::map<std::tuple<int, int, int>, std::vector<int>> groups; // (domain, spacing, capture) -> members
    for (size_t i = 0; i < chunk.size(); ++i) {
      const Patch& p = chunk[i];
      const int d = static_cast<int>(p.domain), s = glSpacing(p.partitioning);
      groups[{d, s, static_cast<int>(Capture::Points)}].push_back(static_cast<int>(i));
      if (drawsPrimitives(p)) {
        const Capture cap = p.domain == Domain::Isoline             ? Capture::Lines
                            : p.topology == Topology::TriangleCw    ? Capture::GlCcw
                                                                    : Capture::GlCw;
        groups[{d, s, static_cast<int>(cap)}].push_back(static_cast<int>(i));
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    for (auto& kv : groups)
      if (!glc.runGroup(chunk, kv.second, std::get<1>(kv.first), static_cast<Capture>(std::get<2>(kv.first)), got,
                        error)) {
        std::fprintf(stderr, "fftess_nvidia_compare: capture failed: %s\n", error.c_str());
        return 4;
      }
    glSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    for (size_t i = 0; i < chunk.size(); ++i) {
      const Patch& p = chunk[i];
      const Captured& g = got[i];
      const auto e0 = std::chrono::steady_clock::now();
      tess.tessellate(toEmulator(p), options);
      std::vector<uint64_t> wantPoints;
      wantPoints.reserve(tess.points().size());
      for (const fftess::DomainPoint& pt : tess.points()) wantPoints.push_back(uint64_t(bitsOf(pt.u)) << 32 | bitsOf(pt.v));
      const bool prims = drawsPrimitives(p);
      const int per = p.domain == Domain::Isoline ? 2 : 3;
      std::vector<uint64_t> wantPrims;
      if (prims) {
        wantPrims.reserve(tess.indices().size());
        for (int32_t idx : tess.indices()) wantPrims.push_back(wantPoints.at(static_cast<size_t>(idx)));
        if (per == 3)
          for (size_t k = 0; k + 2 < wantPrims.size(); k += 3)
            st.coincidentTriangles += wantPrims[k] == wantPrims[k + 1] || wantPrims[k + 1] == wantPrims[k + 2] ||
                                      wantPrims[k] == wantPrims[k + 2];
      }
      const auto e1 = std::chrono::steady_clock::now();
      emuSeconds += std::chrono::duration<double>(e1 - e0).count();

      ++st.patches;
      st.points += static_cast<long long>(g.points.size());
      st.prims += static_cast<long long>(g.primitives.size() / per);
      const bool pointOrder = g.points == wantPoints;
      std::vector<uint64_t> a = g.points, b = wantPoints;
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      const bool pointSet = a == b;
      if (std::adjacent_find(b.begin(), b.end()) != b.end()) ++st.pointsWithDuplicates;
      bool primSet = true, primOrder = true;
      std::string cls;
      if (prims && !wantPoints.empty()) ++st.withPrims;
      if (prims) {
        primOrder = g.primitives == wantPrims;
        primSet = primOrder || normalise(g.primitives, per, false) == normalise(wantPrims, per, false);
      }
      if (g.points.empty() && wantPoints.empty()) ++st.culledBoth;
      if (!wantPoints.empty()) st.pointOrderSame += pointOrder;
      if (prims && !wantPoints.empty()) st.primOrderSame += primOrder, st.primSetSameOrderDiffers += primSet && !primOrder;
      if (!pointSet) {
        a.erase(std::unique(a.begin(), a.end()), a.end());
        b.erase(std::unique(b.begin(), b.end()), b.end());
        if (g.points.empty()) cls = "culled by GL only";
        else if (wantPoints.empty()) cls = "culled by fftess only";
        else if (a == b) cls = "same distinct points, multiplicity differs";
        else cls = "points differ";
      } else if (!primSet) {
        const bool unorderedSame = normalise(g.primitives, per, true) == normalise(wantPrims, per, true);
        cls = unorderedSame ? (per == 3 ? "triangles differ in winding only" : "segments differ in direction only")
                            : (per == 3 ? "triangles differ" : "segments differ");
        if (unorderedSame && per == 3) {
          const auto ga = normalise(g.primitives, per, false), wb = normalise(wantPrims, per, false);
          std::vector<std::array<uint64_t, 3>> only;
          std::set_difference(wb.begin(), wb.end(), ga.begin(), ga.end(), std::back_inserter(only));
          bool allDegenerate = true;
          for (const auto& t : only) {
            bool offGrid = false;
            const int o = orientation(t, offGrid);
            ++st.flipped;
            st.flippedOffGrid += offGrid;
            st.flippedDegenerate += o == 0;
            st.flippedCoincident += t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
            allDegenerate = allDegenerate && o == 0 && !offGrid;
          }
          if (allDegenerate) cls += ", every flipped triangle degenerate";
        }
      }
      cmpSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e1).count();
      auto& mode = st.perMode[std::string(toString(p.domain)) + " " + toString(p.partitioning)];
      ++mode.first;
      if (cls.empty()) {
        ++st.agree;
        continue;
      }
      ++mode.second;
      const std::string key = cls + " [" + factorTags(p, true) + "]";
      ++st.classes[key];
      auto& ex = st.examples[key];
      const std::string line = batchLine(p) + "   # GL " + std::to_string(g.points.size()) + " points " +
                               std::to_string(g.primitives.size() / per) + " prims, fftess " +
                               std::to_string(wantPoints.size()) + " points " + std::to_string(wantPrims.size() / per) +
                               " prims";
      if (ex.size() < 3) ex.push_back(line);
      if (diffs) std::fprintf(diffs, "%s [%s]\t%s\n", cls.c_str(), factorTags(p, false).c_str(), line.c_str());
    }
  }
  if (diffs) std::fclose(diffs);

  std::printf("\n%-26s %9s %9s\n", "mode", "patches", "differ");
  for (const auto& kv : st.perMode)
    std::printf("%-26s %9ld %9ld\n", kv.first.c_str(), kv.second.first, kv.second.second);
  std::printf("\ndifferences by class [the patch's first special factor: outer before inner]:\n");
  if (st.classes.empty()) std::printf("  none\n");
  for (const auto& kv : st.classes) {
    std::printf("  %7ld  %s\n", kv.second, kv.first.c_str());
    for (const std::string& e : st.examples[kv.first]) std::printf("           %s\n", e.c_str());
  }
  const long drawn = st.patches - st.culledBoth;
  std::printf("\nsummary: %ld patches (%ld culled by both, %ld with GL primitives, %ld with duplicate points in fftess), "
              "%lld GL points, %lld GL primitives\n"
              "  agree as multisets (points; rotation-normalised primitives with winding): %ld; differ: %ld\n"
              "  information: point sequence identical in order %ld of %ld non-culled; primitive sequence identical "
              "(order and first vertex) %ld of %ld, same set in another order %ld; captures in patch order: %s\n"
              "  fftess triangles with coincident vertices (winding not observable): %lld\n"
              "  winding-only differences: %lld triangles flipped; of them %lld degenerate (zero area, exact), %lld with "
              "coincident vertices, %lld off the 16.16 grid\n"
              "  time: GL capture %.2f s (%.0f patches/s, %ld draws), fftess %.2f s, comparison %.2f s\n",
              st.patches, st.culledBoth, st.withPrims, st.pointsWithDuplicates, st.points, st.prims, st.agree,
              st.patches - st.agree, st.pointOrderSame, drawn, st.primOrderSame, st.withPrims,
              st.primSetSameOrderDiffers, glc.patchOrderSeen ? "yes" : "no", st.coincidentTriangles, st.flipped, st.flippedDegenerate,
              st.flippedCoincident, st.flippedOffGrid, glSeconds,
              glSeconds > 0 ? static_cast<double>(st.patches) / glSeconds : 0.0, glc.drawCalls, emuSeconds, cmpSeconds);
  return st.agree == st.patches ? 0 : 5;
}
