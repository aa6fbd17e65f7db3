// Capture of a real OpenGL tessellator (Mesa llvmpipe) through transform feedback. See gl_capture.h and
// docs/oracle.md.
#include "gl_capture.h"
#include "capture_records.h"
#include "gl_context.h"

#include "base/splitmix64.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>
#include <sstream>

namespace fftess {
namespace oracle {

namespace {

using gltest::GlFunctions;

using records::kCaptureStride; // uvec4 per vertex: u bits, v bits, patch in draw, vertex id (Strict) or 0

// llvmpipe numbers the tessellated vertices of one draw with 16-bit indices (each patch padded to a multiple of 4):
// past 65536 domain points per draw it captures wrong vertices without any error (shared facts). Stay well below.
// Other drivers take more (tests/tools/nvidia_compare draws 200,000 on NVIDIA).
constexpr int kSoftwareDrawPointBudget = 60000;
constexpr int kHardwareDrawPointBudget = 200000;
constexpr int kMaxPatchesPerDraw = 2048;
// Transform feedback room per draw, in captured vertices per budget point (a triangle list has < 2 triangles per
// point: 6 vertices).
constexpr int kCaptureVerticesPerPoint = 8;

int padTo4(int n) { return (n + 3) & ~3; }

// Program variants: one per (domain, spacing, what is captured).
enum class Capture : uint8_t { Points, TrianglesGlCw, TrianglesGlCcw, Lines };

struct ProgramKey {
  Domain domain;
  int spacing; // 0 equal, 1 fractional_odd, 2 fractional_even
  Capture capture;
  bool ids; // primitives with vertex ids (CaptureOrder::Strict); points and order-free primitives have none
  bool operator<(const ProgramKey& o) const {
    return std::tie(domain, spacing, capture, ids) < std::tie(o.domain, o.spacing, o.capture, o.ids);
  }
};

const char* kVertexShader = R"(#version 450 core
void main() { gl_Position = vec4(0.0); }
)";

// Factors arrive as raw bits so NaN payloads, denormals and exact values reach the fixed-function unit untouched.
// Slot order per patch: outer[0..3], inner[0..1] (the CPU side maps D3D's factor order onto it).
const char* kControlShader = R"(#version 450 core
layout(vertices = 1) out;
layout(std430, binding = 0) readonly buffer Factors { uint factorBits[]; };
uniform uint patchBase;
void main() {
  uint b = (patchBase + uint(gl_PrimitiveID)) * 6u;
  gl_TessLevelOuter[0] = uintBitsToFloat(factorBits[b + 0u]);
  gl_TessLevelOuter[1] = uintBitsToFloat(factorBits[b + 1u]);
  gl_TessLevelOuter[2] = uintBitsToFloat(factorBits[b + 2u]);
  gl_TessLevelOuter[3] = uintBitsToFloat(factorBits[b + 3u]);
  gl_TessLevelInner[0] = uintBitsToFloat(factorBits[b + 4u]);
  gl_TessLevelInner[1] = uintBitsToFloat(factorBits[b + 5u]);
}
)";

std::string evaluationShader(const ProgramKey& k) {
  std::string layout = k.domain == Domain::Quad ? "quads" : k.domain == Domain::Tri ? "triangles" : "isolines";
  layout += k.spacing == 0 ? ", equal_spacing" : k.spacing == 1 ? ", fractional_odd_spacing" : ", fractional_even_spacing";
  if (k.capture == Capture::TrianglesGlCw) layout += ", cw";
  if (k.capture == Capture::TrianglesGlCcw) layout += ", ccw";
  if (k.capture == Capture::Points) layout += ", point_mode";
  std::string s = "#version 450 core\nlayout(" + layout + ") in;\nflat out uvec4 cap;\n";
  if (!k.ids) {
    s += R"(void main() {
  cap = uvec4(floatBitsToUint(gl_TessCoord.xy), uint(gl_PrimitiveID), 0u);
  gl_Position = vec4(0.0);
}
)";
  } else {
    // Vertex ids: each TES invocation takes the next number of its patch and stores its coordinate under it.
    // The host checks that the stored array equals the point_mode capture, so the numbering is the point order.
    s += R"(layout(std430, binding = 1) coherent buffer Counters { uint counter[]; };
layout(std430, binding = 2) readonly buffer Slots { uint slotBase[]; };
layout(std430, binding = 3) writeonly buffer Stored { uvec2 stored[]; };
void main() {
  uint p = uint(gl_PrimitiveID);
  uvec2 bits = floatBitsToUint(gl_TessCoord.xy);
  uint id = atomicAdd(counter[p], 1u);
  uint slot = slotBase[p] + id;
  if (slot < slotBase[p + 1u]) stored[slot] = bits;
  cap = uvec4(bits, p, id);
  gl_Position = vec4(0.0);
}
)";
  }
  return s;
}

} // namespace

struct GlOracle::Impl {
  gltest::GlContext context;
  GlFunctions& gl = context.gl;
  GLuint vao = 0, fbo = 0;
  GLuint factorBuf = 0, counterBuf = 0, slotBuf = 0, storedBuf = 0, captureBuf = 0;
  GLuint queryGenerated = 0, queryWritten = 0;
  size_t factorCapacity = 0;
  struct Program {
    GLuint id = 0;
    GLint patchBase = -1;
  };
  std::map<ProgramKey, Program> programs;
  std::vector<uint32_t> captured;
  int drawCalls = 0;
  int drawPointBudget = kSoftwareDrawPointBudget;
  GLint tesStorageBlocks = 0;
  RunOptions options;        // of the current run()
  bool orderMismatch = false; // the last run() failed on the reference order (Strict)

  Program* program(const ProgramKey& key, std::string& error) {
    auto it = programs.find(key);
    if (it != programs.end()) return &it->second;
    GLuint vs = gl.glCreateShader(GL_VERTEX_SHADER);
    GLuint tcs = gl.glCreateShader(GL_TESS_CONTROL_SHADER);
    GLuint tes = gl.glCreateShader(GL_TESS_EVALUATION_SHADER);
    bool ok = gltest::compileShader(gl, vs, kVertexShader, error) &&
              gltest::compileShader(gl, tcs, kControlShader, error) &&
              gltest::compileShader(gl, tes, evaluationShader(key), error);
    GLuint prog = 0;
    if (ok) {
      prog = gl.glCreateProgram();
      gl.glAttachShader(prog, vs);
      gl.glAttachShader(prog, tcs);
      gl.glAttachShader(prog, tes);
      const char* varyings[] = {"cap"};
      gl.glTransformFeedbackVaryings(prog, 1, varyings, GL_INTERLEAVED_ATTRIBS);
      if (!gltest::linkProgram(gl, prog, error)) {
        gl.glDeleteProgram(prog);
        ok = false;
      }
    }
    gl.glDeleteShader(vs);
    gl.glDeleteShader(tcs);
    gl.glDeleteShader(tes);
    if (!ok) return nullptr;
    Program p;
    p.id = prog;
    p.patchBase = gl.glGetUniformLocation(prog, "patchBase");
    return &programs.emplace(key, p).first->second;
  }

  bool checkGl(const char* what, std::string& error) { return gltest::checkGl(gl, what, error); }

  // One draw of patches [first, first+count) of the group; 'slotBases' (Strict primitives only, else empty): where
  // each patch's vertex ids store their coordinates. Fills 'captured' with the draw's vertices (kCaptureStride words
  // each), permuted when options.permuteSeed is set.
  bool draw(Program& prog, Capture capture, int first, int count, const std::vector<uint32_t>& slotBases,
            std::string& error) {
    gl.glUseProgram(prog.id);
    gl.glUniform1ui(prog.patchBase, static_cast<GLuint>(first));
    if (!slotBases.empty()) { // vertex ids (Strict primitives): counters from 0, the slots of each patch
      std::vector<uint32_t> zeros(static_cast<size_t>(count), 0u);
      gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, counterBuf);
      gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(zeros.size() * 4), zeros.data());
      gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, slotBuf);
      gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(slotBases.size() * 4), slotBases.data());
    }
    const GLenum mode = capture == Capture::Points ? GL_POINTS : capture == Capture::Lines ? GL_LINES : GL_TRIANGLES;
    const int perPrim = capture == Capture::Points ? 1 : capture == Capture::Lines ? 2 : 3;
    gl.glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, captureBuf);
    gl.glBeginQuery(GL_PRIMITIVES_GENERATED, queryGenerated);
    gl.glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, queryWritten);
    gl.glBeginTransformFeedback(mode);
    gl.glDrawArrays(GL_PATCHES, 0, count);
    ++drawCalls;
    gl.glEndTransformFeedback();
    gl.glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
    gl.glEndQuery(GL_PRIMITIVES_GENERATED);
    if (!checkGl("the draw", error)) return false;
    GLuint generated = 0, written = 0;
    gl.glGetQueryObjectuiv(queryGenerated, GL_QUERY_RESULT, &generated);
    gl.glGetQueryObjectuiv(queryWritten, GL_QUERY_RESULT, &written);
    if (generated != written) {
      std::ostringstream s;
      s << "transform feedback overflow: " << generated << " primitives generated, " << written << " written";
      error = s.str();
      return false;
    }
    const size_t words = static_cast<size_t>(written) * perPrim * kCaptureStride;
    captured.assign(words, 0u);
    gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.glBindBuffer(GL_COPY_READ_BUFFER, captureBuf);
    if (words) gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(words * 4), captured.data());
    if (options.permuteSeed) records::permute(captured, perPrim, SplitMix64::mix(options.permuteSeed + drawCalls));
    return checkGl("reading the transform feedback buffer", error);
  }

  bool readBuffer(GLuint buf, size_t words, std::vector<uint32_t>& out, std::string& error) {
    out.resize(words);
    gl.glBindBuffer(GL_COPY_READ_BUFFER, buf);
    if (words) gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(words * 4), out.data());
    return checkGl("reading a storage buffer", error);
  }

  // One group of patches that share domain and spacing: upload their factors, capture their points (pass 1), derive
  // the primitives GL has no output for, capture the others per GL winding (pass 2).
  bool runGroup(const std::vector<Patch>& patches, const std::vector<int>& members, std::vector<Result>& results,
                std::string& error);

  // The group's factors in GL slot order, six words a patch, uploaded to the factor buffer.
  std::vector<uint32_t> uploadFactors(const std::vector<Patch>& patches, const std::vector<int>& members);
  // Pass 1: point_mode, one captured vertex per domain point in the tessellator's order.
  bool capturePoints(const std::vector<Patch>& patches, const std::vector<int>& members, std::vector<Result>& results,
                     std::string& error);
  // Strict: the draw's points filed under their patches, which must come in patch order (else orderMismatch).
  bool splitPointsInOrder(const std::vector<int>& members, int begin, int end, std::vector<Result>& results,
                          std::string& error);
  // Point and (quad/tri) line outputs, which GL cannot draw, derived from the points; returns the members (indices
  // into `members`) whose primitives pass 2 must capture.
  std::vector<int> derivePrimitives(const std::vector<Patch>& patches, const std::vector<int>& members,
                                    std::vector<Result>& results);
  // Pass 2 for the selected members `sel` (one GL winding or isolines): draws in batches; Strict checks each
  // captured vertex against the point capture and the TES invocation order, Free files the primitives by patch.
  bool capturePrimitives(const std::vector<Patch>& patches, const std::vector<int>& members,
                         const std::vector<int>& sel, const std::vector<uint32_t>& factors, Capture cap,
                         std::vector<Result>& results, std::string& error);
  // One draw of pass 2, Strict: selected members [begin, end) with their slot bases; the captured primitives
  // appended to their results.
  bool readPrimitiveBatch(const std::vector<Patch>& patches, const std::vector<int>& members,
                          const std::vector<int>& sel, int begin, int end, int perPrim,
                          const std::vector<uint32_t>& slotBases, std::vector<Result>& results, std::string& error);
};

GlOracle::GlOracle() : impl_(new Impl) {}

GlOracle::~GlOracle() {
  Impl& m = *impl_;
  if (!m.context.renderer().empty()) { // the context is current and its functions are loaded
    auto& gl = m.gl;
    for (auto& kv : m.programs) gl.glDeleteProgram(kv.second.id);
    GLuint bufs[] = {m.factorBuf, m.counterBuf, m.slotBuf, m.storedBuf, m.captureBuf};
    gl.glDeleteBuffers(5, bufs);
    GLuint queries[] = {m.queryGenerated, m.queryWritten};
    gl.glDeleteQueries(2, queries);
    gl.glDeleteVertexArrays(1, &m.vao);
    gl.glDeleteFramebuffers(1, &m.fbo);
  }
  // m.context releases the EGL context and display.
}

std::unique_ptr<GlOracle> GlOracle::create(std::string& error, bool hardwareFirst) {
  std::unique_ptr<GlOracle> o(new GlOracle);
  Impl& m = *o->impl_;
  gltest::ContextOptions options;
  options.order = hardwareFirst ? gltest::DeviceOrder::HardwareFirst  // a GPU's EGL device, then the software ones
                                : gltest::DeviceOrder::SoftwareFirst; // llvmpipe's software EGL device first
  if (!m.context.create(options, error)) {
    if (m.context.renderer().empty() && error.rfind("cannot create", 0) == 0)
      error += "; install libegl-mesa0 and libgl1-mesa-dri";
    return nullptr;
  }
  auto& gl = m.gl;
  o->renderer_ = m.context.renderer();
  o->version_ = m.context.version();

  // Strict primitives need 3 storage blocks in the evaluation shader (checked by run()); the order-free capture none.
  gl.glGetIntegerv(GL_MAX_TESS_EVALUATION_SHADER_STORAGE_BLOCKS, &m.tesStorageBlocks);
  m.drawPointBudget = m.context.isSoftware() ? kSoftwareDrawPointBudget : kHardwareDrawPointBudget;

  // Draws need a complete framebuffer; an attachment-less one will do under rasterizer discard.
  if (!gltest::prepareCaptureDraws(gl, m.fbo, m.vao, error)) return nullptr;

  GLuint bufs[5];
  gl.glGenBuffers(5, bufs);
  m.factorBuf = bufs[0], m.counterBuf = bufs[1], m.slotBuf = bufs[2], m.storedBuf = bufs[3], m.captureBuf = bufs[4];
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.counterBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, kMaxPatchesPerDraw * 4, nullptr, GL_DYNAMIC_DRAW);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.slotBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, (kMaxPatchesPerDraw + 1) * 4, nullptr, GL_DYNAMIC_DRAW);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.storedBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(m.drawPointBudget) * 8, nullptr, GL_DYNAMIC_READ);
  gl.glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, m.captureBuf);
  gl.glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER,
                  static_cast<GLsizeiptr>(m.drawPointBudget) * kCaptureVerticesPerPoint * kCaptureStride * 4, nullptr,
                  GL_DYNAMIC_READ);
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, m.counterBuf);
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, m.slotBuf);
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, m.storedBuf);
  GLuint queries[2];
  gl.glGenQueries(2, queries);
  m.queryGenerated = queries[0], m.queryWritten = queries[1];
  if (!m.checkGl("setting up the context", error)) return nullptr;
  return o;
}

bool GlOracle::Impl::runGroup(const std::vector<Patch>& patches, const std::vector<int>& members,
                              std::vector<Result>& results, std::string& error) {
  const Patch& first = patches[members[0]];
  const std::vector<uint32_t> factors = uploadFactors(patches, members);
  if (!capturePoints(patches, members, results, error)) return false;
  const std::vector<int> prim = derivePrimitives(patches, members, results);
  // Draw the primitive patches, one program per GL winding. D3D triangle_cw is GL ccw (same first vertex).
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> sel;
    for (int i : prim) {
      const Topology t = patches[members[i]].topology;
      const bool glCw = t == Topology::TriangleCcw;
      if ((pass == 0) != glCw) sel.push_back(i);
    }
    if (sel.empty()) continue;
    const Capture cap = first.domain == Domain::Isoline ? Capture::Lines
                        : pass == 0                     ? Capture::TrianglesGlCcw
                                                        : Capture::TrianglesGlCw;
    if (!capturePrimitives(patches, members, sel, factors, cap, results, error)) return false;
  }
  if (options.order == CaptureOrder::Free)
    for (int i : prim) records::indicesByCoordinates(results[members[i]]);
  return true;
}

std::vector<uint32_t> GlOracle::Impl::uploadFactors(const std::vector<Patch>& patches, const std::vector<int>& members) {
  const Patch& first = patches[members[0]];
  const int n = static_cast<int>(members.size());
  // Factors in GL slot order: quad outer = Ueq0 Veq0 Ueq1 Veq1, inner = insideU insideV; tri outer[0..2] =
  // Ueq0 Veq0 Weq0, inner[0] = inside; isolines outer[0] = density, outer[1] = detail.
  std::vector<uint32_t> factors(static_cast<size_t>(n) * 6, 0u);
  for (int i = 0; i < n; ++i) {
    const uint32_t* f = patches[members[i]].factorBits;
    uint32_t* g = &factors[static_cast<size_t>(i) * 6];
    switch (first.domain) {
    case Domain::Quad:
      for (int k = 0; k < 6; ++k) g[k] = f[k];
      break;
    case Domain::Tri:
      g[0] = f[0], g[1] = f[1], g[2] = f[2], g[4] = f[3];
      break;
    case Domain::Isoline:
      g[0] = f[0], g[1] = f[1];
      break;
    }
  }
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, factorBuf);
  if (factors.size() * 4 > factorCapacity) {
    factorCapacity = factors.size() * 4;
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(factorCapacity), nullptr, GL_DYNAMIC_DRAW);
  }
  gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(factors.size() * 4), factors.data());
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, factorBuf);
  return factors;
}

bool GlOracle::Impl::capturePoints(const std::vector<Patch>& patches, const std::vector<int>& members,
                                   std::vector<Result>& results, std::string& error) {
  const Patch& first = patches[members[0]];
  const int n = static_cast<int>(members.size());
  Program* pointProg = program({first.domain, glSpacing(first.partitioning), Capture::Points, false}, error);
  if (!pointProg) return false;
  std::vector<int> bounds(n);
  for (int i = 0; i < n; ++i) bounds[i] = pointBound(patches[members[i]]);
  for (int begin = 0; begin < n;) {
    int end = begin, budget = 0;
    while (end < n && end - begin < kMaxPatchesPerDraw && budget + padTo4(bounds[end]) <= drawPointBudget)
      budget += padTo4(bounds[end++]);
    if (!draw(*pointProg, Capture::Points, begin, end - begin, {}, error)) return false;
    if (options.order == CaptureOrder::Free) {
      std::vector<std::vector<uint32_t>*> out;
      for (int i = begin; i < end; ++i) out.push_back(&results[members[i]].points);
      if (!records::fileByPatch(captured, 1, out, error)) return false;
    } else if (!splitPointsInOrder(members, begin, end, results, error)) {
      return false;
    }
    for (int i = begin; i < end; ++i) {
      const int count = results[members[i]].pointCount();
      if (count > bounds[i]) {
        error = "patch '" + batchLine(patches[members[i]]) + "' gave " + std::to_string(count) +
                " points, above the harness bound " + std::to_string(bounds[i]) + " (the per-draw limit is unsafe)";
        return false;
      }
    }
    begin = end;
  }
  return true;
}

bool GlOracle::Impl::splitPointsInOrder(const std::vector<int>& members, int begin, int end,
                                        std::vector<Result>& results, std::string& error) {
  int last = 0;
  for (size_t v = 0; v < captured.size(); v += kCaptureStride) {
    const int local = static_cast<int>(captured[v + 2]);
    if (begin + local >= end) {
      error = "a captured point names patch " + std::to_string(local) + " of a draw of " + std::to_string(end - begin);
      return false;
    }
    if (local < last) {
      error = "point capture out of patch order (patch " + std::to_string(local) + " after " + std::to_string(last) +
              ")";
      orderMismatch = true;
      return false;
    }
    last = local;
    Result& r = results[members[begin + local]];
    r.points.push_back(captured[v]);
    r.points.push_back(captured[v + 1]);
  }
  return true;
}

std::vector<int> GlOracle::Impl::derivePrimitives(const std::vector<Patch>& patches, const std::vector<int>& members,
                                                  std::vector<Result>& results) {
  std::vector<int> prim;
  for (int i = 0; i < static_cast<int>(members.size()); ++i) {
    const Patch& p = patches[members[i]];
    Result& r = results[members[i]];
    const int count = r.pointCount();
    if (p.topology == Topology::Point) {
      r.verticesPerPrimitive = 1;
      for (int k = 0; k < count; ++k) r.indices.push_back(k);
    } else if (p.topology == Topology::Line && p.domain != Domain::Isoline) {
      // D3D quad/tri "line" output: the points joined in generation order. GL has no such output; derived here from
      // the reference order (Strict); an order-free capture does not know the generation order (indices empty).
      r.verticesPerPrimitive = 2;
      if (options.order == CaptureOrder::Strict)
        for (int k = 0; k + 1 < count; ++k) r.indices.push_back(k), r.indices.push_back(k + 1);
    } else {
      prim.push_back(i);
    }
  }
  return prim;
}

bool GlOracle::Impl::capturePrimitives(const std::vector<Patch>& patches, const std::vector<int>& members,
                                       const std::vector<int>& sel, const std::vector<uint32_t>& factors, Capture cap,
                                       std::vector<Result>& results, std::string& error) {
  const Patch& first = patches[members[0]];
  const int perPrim = cap == Capture::Lines ? 2 : 3;
  const bool ids = options.order == CaptureOrder::Strict;
  Program* prog = program({first.domain, glSpacing(first.partitioning), cap, ids}, error);
  if (!prog) return false;
  // Re-upload factors in the order of 'sel' so gl_PrimitiveID indexes them directly.
  std::vector<uint32_t> selFactors(sel.size() * 6);
  for (size_t j = 0; j < sel.size(); ++j)
    std::copy_n(&factors[static_cast<size_t>(sel[j]) * 6], 6, &selFactors[j * 6]);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, factorBuf);
  gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(selFactors.size() * 4), selFactors.data());
  const int m = static_cast<int>(sel.size());
  for (int begin = 0; begin < m;) {
    int end = begin, budget = 0;
    std::vector<uint32_t> slotBases(1, 0u); // Strict: where each patch's vertex ids store their coordinates
    while (end < m && end - begin < kMaxPatchesPerDraw &&
           budget + padTo4(results[members[sel[end]]].pointCount()) <= drawPointBudget) {
      const int c = results[members[sel[end]]].pointCount();
      budget += padTo4(c);
      slotBases.push_back(slotBases.back() + static_cast<uint32_t>(c));
      ++end;
    }
    if (!ids) slotBases.clear();
    if (!draw(*prog, cap, begin, end - begin, slotBases, error)) return false;
    if (ids) {
      if (!readPrimitiveBatch(patches, members, sel, begin, end, perPrim, slotBases, results, error)) return false;
    } else {
      std::vector<std::vector<uint32_t>*> out;
      for (int i = begin; i < end; ++i) {
        results[members[sel[i]]].verticesPerPrimitive = perPrim;
        out.push_back(&results[members[sel[i]]].primitives);
      }
      if (!records::fileByPatch(captured, perPrim, out, error)) return false;
    }
    begin = end;
  }
  return true;
}

bool GlOracle::Impl::readPrimitiveBatch(const std::vector<Patch>& patches, const std::vector<int>& members,
                                        const std::vector<int>& sel, int begin, int end, int perPrim,
                                        const std::vector<uint32_t>& slotBases, std::vector<Result>& results,
                                        std::string& error) {
  std::vector<uint32_t> counters, stored;
  if (!readBuffer(counterBuf, static_cast<size_t>(end - begin), counters, error)) return false;
  if (!readBuffer(storedBuf, static_cast<size_t>(slotBases.back()) * 2, stored, error)) return false;
  int last = 0;
  const size_t primWords = static_cast<size_t>(perPrim) * kCaptureStride;
  for (size_t v = 0; v < captured.size(); v += primWords) {
    const int local = static_cast<int>(captured[v + 2]);
    if (begin + local >= end) {
      error = "a captured primitive names patch " + std::to_string(local) + " of a draw of " +
              std::to_string(end - begin);
      return false;
    }
    if (local < last) {
      error = "primitive capture out of patch order";
      orderMismatch = true;
      return false;
    }
    last = local;
    const Patch& p = patches[members[sel[begin + local]]];
    Result& r = results[members[sel[begin + local]]];
    for (int k = 0; k < perPrim; ++k) {
      const uint32_t* c = &captured[v + static_cast<size_t>(k) * kCaptureStride];
      const uint32_t id = c[3];
      if (c[2] != captured[v + 2] || id >= static_cast<uint32_t>(r.pointCount()) ||
          r.points[2 * id] != c[0] || r.points[2 * id + 1] != c[1]) {
        error = "patch '" + batchLine(p) + "': a captured vertex does not match the point_mode capture at its id";
        orderMismatch = true;
        return false;
      }
      r.primitives.push_back(c[0]);
      r.primitives.push_back(c[1]);
      r.indices.push_back(static_cast<int32_t>(id));
    }
    r.verticesPerPrimitive = perPrim;
  }
  // The id numbering must be the point order: every TES invocation once, storing exactly the point array.
  for (int i = begin; i < end; ++i) {
    Result& r = results[members[sel[i]]];
    r.verticesPerPrimitive = perPrim;
    const uint32_t base = slotBases[i - begin];
    bool same = counters[i - begin] == static_cast<uint32_t>(r.pointCount());
    for (int k = 0; same && k < r.pointCount(); ++k)
      same = stored[2 * (base + k)] == r.points[2 * k] && stored[2 * (base + k) + 1] == r.points[2 * k + 1];
    if (!same) {
      error = "patch '" + batchLine(patches[members[sel[i]]]) + "': TES invocations (" +
              std::to_string(counters[i - begin]) + ") do not run once per point in point order (" +
              std::to_string(r.pointCount()) + " points); vertex ids cannot be trusted";
      orderMismatch = true;
      return false;
    }
  }
  return true;
}

int GlOracle::drawCalls() const { return impl_->drawCalls; }

int GlOracle::drawPointBudget() const { return impl_->drawPointBudget; }

bool GlOracle::orderMismatch() const { return impl_->orderMismatch; }

bool GlOracle::run(const std::vector<Patch>& patches, std::vector<Result>& results, std::string& error,
                   const RunOptions& options) {
  results.assign(patches.size(), Result{});
  impl_->drawCalls = 0;
  impl_->options = options;
  impl_->orderMismatch = false;
  if (options.order == CaptureOrder::Strict && impl_->tesStorageBlocks < 3) {
    error = "the GL implementation (" + renderer_ + ") offers " + std::to_string(impl_->tesStorageBlocks) +
            " storage blocks to tessellation evaluation shaders; the strict-order capture needs 3";
    return false;
  }
  // Group by domain and spacing: one upload of factors and one program per pass.
  std::map<std::pair<int, int>, std::vector<int>> groups;
  for (size_t i = 0; i < patches.size(); ++i)
    groups[{static_cast<int>(patches[i].domain), glSpacing(patches[i].partitioning)}].push_back(static_cast<int>(i));
  for (auto& kv : groups) {
    // All members share domain and spacing; runGroup takes the partitioning of the first only for the spacing.
    if (!impl_->runGroup(patches, kv.second, results, error)) return false;
  }
  return true;
}

} // namespace oracle
} // namespace fftess
