// Capture of a real OpenGL tessellator (Mesa llvmpipe) through transform feedback. See gl_capture.h and
// docs/oracle.md.
#include "gl_capture.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/glcorearb.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>
#include <sstream>

namespace fftess {
namespace oracle {

namespace {

// GL entry points, loaded through eglGetProcAddress (EGL 1.5 returns core functions too).
#define FFTESS_GL_FUNCTIONS(X)                                                                                        \
  X(PFNGLGETSTRINGPROC, glGetString)                                                                                   \
  X(PFNGLGETERRORPROC, glGetError)                                                                                     \
  X(PFNGLGETINTEGERVPROC, glGetIntegerv)                                                                               \
  X(PFNGLENABLEPROC, glEnable)                                                                                         \
  X(PFNGLFINISHPROC, glFinish)                                                                                         \
  X(PFNGLCREATESHADERPROC, glCreateShader)                                                                             \
  X(PFNGLSHADERSOURCEPROC, glShaderSource)                                                                             \
  X(PFNGLCOMPILESHADERPROC, glCompileShader)                                                                           \
  X(PFNGLGETSHADERIVPROC, glGetShaderiv)                                                                               \
  X(PFNGLGETSHADERINFOLOGPROC, glGetShaderInfoLog)                                                                     \
  X(PFNGLDELETESHADERPROC, glDeleteShader)                                                                             \
  X(PFNGLCREATEPROGRAMPROC, glCreateProgram)                                                                           \
  X(PFNGLATTACHSHADERPROC, glAttachShader)                                                                             \
  X(PFNGLTRANSFORMFEEDBACKVARYINGSPROC, glTransformFeedbackVaryings)                                                   \
  X(PFNGLLINKPROGRAMPROC, glLinkProgram)                                                                               \
  X(PFNGLGETPROGRAMIVPROC, glGetProgramiv)                                                                             \
  X(PFNGLGETPROGRAMINFOLOGPROC, glGetProgramInfoLog)                                                                   \
  X(PFNGLDELETEPROGRAMPROC, glDeleteProgram)                                                                           \
  X(PFNGLUSEPROGRAMPROC, glUseProgram)                                                                                 \
  X(PFNGLGETUNIFORMLOCATIONPROC, glGetUniformLocation)                                                                 \
  X(PFNGLUNIFORM1UIPROC, glUniform1ui)                                                                                 \
  X(PFNGLGENVERTEXARRAYSPROC, glGenVertexArrays)                                                                       \
  X(PFNGLBINDVERTEXARRAYPROC, glBindVertexArray)                                                                       \
  X(PFNGLDELETEVERTEXARRAYSPROC, glDeleteVertexArrays)                                                                 \
  X(PFNGLGENBUFFERSPROC, glGenBuffers)                                                                                 \
  X(PFNGLBINDBUFFERPROC, glBindBuffer)                                                                                 \
  X(PFNGLBUFFERDATAPROC, glBufferData)                                                                                 \
  X(PFNGLBUFFERSUBDATAPROC, glBufferSubData)                                                                           \
  X(PFNGLGETBUFFERSUBDATAPROC, glGetBufferSubData)                                                                     \
  X(PFNGLBINDBUFFERBASEPROC, glBindBufferBase)                                                                         \
  X(PFNGLDELETEBUFFERSPROC, glDeleteBuffers)                                                                           \
  X(PFNGLGENFRAMEBUFFERSPROC, glGenFramebuffers)                                                                       \
  X(PFNGLBINDFRAMEBUFFERPROC, glBindFramebuffer)                                                                       \
  X(PFNGLFRAMEBUFFERPARAMETERIPROC, glFramebufferParameteri)                                                           \
  X(PFNGLCHECKFRAMEBUFFERSTATUSPROC, glCheckFramebufferStatus)                                                         \
  X(PFNGLDELETEFRAMEBUFFERSPROC, glDeleteFramebuffers)                                                                 \
  X(PFNGLVIEWPORTPROC, glViewport)                                                                                     \
  X(PFNGLPATCHPARAMETERIPROC, glPatchParameteri)                                                                       \
  X(PFNGLGENQUERIESPROC, glGenQueries)                                                                                 \
  X(PFNGLDELETEQUERIESPROC, glDeleteQueries)                                                                           \
  X(PFNGLBEGINQUERYPROC, glBeginQuery)                                                                                 \
  X(PFNGLENDQUERYPROC, glEndQuery)                                                                                     \
  X(PFNGLGETQUERYOBJECTUIVPROC, glGetQueryObjectuiv)                                                                   \
  X(PFNGLBEGINTRANSFORMFEEDBACKPROC, glBeginTransformFeedback)                                                         \
  X(PFNGLENDTRANSFORMFEEDBACKPROC, glEndTransformFeedback)                                                             \
  X(PFNGLDRAWARRAYSPROC, glDrawArrays)                                                                                 \
  X(PFNGLMEMORYBARRIERPROC, glMemoryBarrier)

struct GlFunctions {
#define FFTESS_DECLARE(type, name) type name = nullptr;
  FFTESS_GL_FUNCTIONS(FFTESS_DECLARE)
#undef FFTESS_DECLARE
};

// llvmpipe numbers the tessellated vertices of one draw with 16-bit indices (each patch padded to a multiple of 4):
// past 65536 domain points per draw it captures wrong vertices without any error (shared facts). Stay well below.
constexpr int kDrawPointBudget = 60000;
constexpr int kMaxPatchesPerDraw = 2048;
// Transform feedback room per draw, in captured vertices (a triangle list has < 2 triangles per point: 6 vertices).
constexpr int kCaptureVertices = 8 * kDrawPointBudget;
constexpr int kCaptureStride = 4; // uvec4 per vertex: u bits, v bits, patch in draw, vertex id

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const size_t n = std::strlen(name);
  for (const char* p = list; (p = std::strstr(p, name)) != nullptr; p += n) {
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  }
  return false;
}

std::string eglErrorString(EGLint e) {
  std::ostringstream s;
  s << "EGL error 0x" << std::hex << e;
  return s.str();
}

float bitsToFloat(uint32_t b) {
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// Segments an edge can have for this factor, never underestimated: clamp to [.., 64] (NaN and +Inf as 64),
// +1 for the rounding up to even/odd of the fractional partitionings, at least 2.
int segmentBound(uint32_t bits) {
  const float f = bitsToFloat(bits);
  if (std::isnan(f) || !(f < 64.0f)) return 64;
  const int s = static_cast<int>(std::ceil(std::max(f, 0.0f))) + 1;
  return std::max(2, std::min(64, s));
}

// GL 4.5 section 11.2.2: a patch whose relevant outer levels include one <= 0 or NaN is discarded.
bool outerDiscards(uint32_t bits) {
  const float f = bitsToFloat(bits);
  return std::isnan(f) || !(f > 0.0f);
}

// Conservative number of domain points of a patch (checked against the observed count after the draw).
int pointBound(const Patch& p) {
  const uint32_t* f = p.factorBits;
  switch (p.domain) {
  case Domain::Quad: {
    for (int i = 0; i < 4; ++i)
      if (outerDiscards(f[i])) return 0;
    int n = 0;
    for (int i = 0; i < 4; ++i) n += segmentBound(f[i]);
    return n + (segmentBound(f[4]) + 1) * (segmentBound(f[5]) + 1);
  }
  case Domain::Tri: {
    for (int i = 0; i < 3; ++i)
      if (outerDiscards(f[i])) return 0;
    int n = 0;
    for (int i = 0; i < 3; ++i) n += segmentBound(f[i]);
    return n + (segmentBound(f[3]) + 1) * (segmentBound(f[3]) + 1);
  }
  case Domain::Isoline:
    if (outerDiscards(f[0]) || outerDiscards(f[1])) return 0;
    return segmentBound(f[0]) * (segmentBound(f[1]) + 1);
  }
  return 0;
}

int padTo4(int n) { return (n + 3) & ~3; }

// Program variants: one per (domain, spacing, what is captured).
enum class Capture : uint8_t { Points, TrianglesGlCw, TrianglesGlCcw, Lines };

struct ProgramKey {
  Domain domain;
  int spacing; // 0 equal, 1 fractional_odd, 2 fractional_even
  Capture capture;
  bool operator<(const ProgramKey& o) const {
    return std::tie(domain, spacing, capture) < std::tie(o.domain, o.spacing, o.capture);
  }
};

int spacingOf(Partitioning p) {
  switch (p) {
  // D3D11.3 spec 11.7: pow2 rounding is the HLSL compiler's; the fixed-function unit treats pow2 as integer.
  case Partitioning::Integer:
  case Partitioning::Pow2: return 0;
  case Partitioning::FractionalOdd: return 1;
  case Partitioning::FractionalEven: return 2;
  }
  return 0;
}

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
  if (k.capture == Capture::Points) {
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
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  GlFunctions gl;
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

  bool compile(GLuint shader, const std::string& src, std::string& error) {
    const char* p = src.c_str();
    gl.glShaderSource(shader, 1, &p, nullptr);
    gl.glCompileShader(shader);
    GLint ok = 0;
    gl.glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok) return true;
    char log[4096] = {};
    gl.glGetShaderInfoLog(shader, sizeof log, nullptr, log);
    error = "GL shader compile failed: " + std::string(log) + "\n" + src;
    return false;
  }

  Program* program(const ProgramKey& key, std::string& error) {
    auto it = programs.find(key);
    if (it != programs.end()) return &it->second;
    GLuint vs = gl.glCreateShader(GL_VERTEX_SHADER);
    GLuint tcs = gl.glCreateShader(GL_TESS_CONTROL_SHADER);
    GLuint tes = gl.glCreateShader(GL_TESS_EVALUATION_SHADER);
    bool ok = compile(vs, kVertexShader, error) && compile(tcs, kControlShader, error) &&
              compile(tes, evaluationShader(key), error);
    GLuint prog = 0;
    if (ok) {
      prog = gl.glCreateProgram();
      gl.glAttachShader(prog, vs);
      gl.glAttachShader(prog, tcs);
      gl.glAttachShader(prog, tes);
      const char* varyings[] = {"cap"};
      gl.glTransformFeedbackVaryings(prog, 1, varyings, GL_INTERLEAVED_ATTRIBS);
      gl.glLinkProgram(prog);
      GLint linked = 0;
      gl.glGetProgramiv(prog, GL_LINK_STATUS, &linked);
      if (!linked) {
        char log[4096] = {};
        gl.glGetProgramInfoLog(prog, sizeof log, nullptr, log);
        error = "GL program link failed: " + std::string(log);
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

  bool checkGl(const char* what, std::string& error) {
    GLenum e = gl.glGetError();
    if (e == GL_NO_ERROR) return true;
    std::ostringstream s;
    s << "GL error 0x" << std::hex << e << " after " << what;
    error = s.str();
    return false;
  }

  // One draw of patches [first, first+count) of the group; 'stored' sizes per patch for the vertex-id pass.
  // Appends the captured vertices (kCaptureStride words each) to 'captured'.
  bool draw(Program& prog, Capture capture, int first, int count, const std::vector<uint32_t>& slotBases,
            std::string& error) {
    gl.glUseProgram(prog.id);
    gl.glUniform1ui(prog.patchBase, static_cast<GLuint>(first));
    if (capture != Capture::Points) {
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
    const size_t old = captured.size();
    captured.resize(old + words);
    gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    gl.glBindBuffer(GL_COPY_READ_BUFFER, captureBuf);
    if (words) gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(words * 4), captured.data() + old);
    return checkGl("reading the transform feedback buffer", error);
  }

  bool readBuffer(GLuint buf, size_t words, std::vector<uint32_t>& out, std::string& error) {
    out.resize(words);
    gl.glBindBuffer(GL_COPY_READ_BUFFER, buf);
    if (words) gl.glGetBufferSubData(GL_COPY_READ_BUFFER, 0, static_cast<GLsizeiptr>(words * 4), out.data());
    return checkGl("reading a storage buffer", error);
  }

  bool runGroup(const std::vector<Patch>& patches, const std::vector<int>& members, std::vector<Result>& results,
                std::string& error);
};

GlOracle::GlOracle() : impl_(new Impl) {}

GlOracle::~GlOracle() {
  Impl& m = *impl_;
  if (m.context != EGL_NO_CONTEXT) {
    auto& gl = m.gl;
    for (auto& kv : m.programs) gl.glDeleteProgram(kv.second.id);
    GLuint bufs[] = {m.factorBuf, m.counterBuf, m.slotBuf, m.storedBuf, m.captureBuf};
    gl.glDeleteBuffers(5, bufs);
    GLuint queries[] = {m.queryGenerated, m.queryWritten};
    gl.glDeleteQueries(2, queries);
    gl.glDeleteVertexArrays(1, &m.vao);
    gl.glDeleteFramebuffers(1, &m.fbo);
    eglMakeCurrent(m.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(m.display, m.context);
  }
  if (m.display != EGL_NO_DISPLAY) eglTerminate(m.display);
}

std::unique_ptr<GlOracle> GlOracle::create(std::string& error) {
  std::unique_ptr<GlOracle> o(new GlOracle);
  Impl& m = *o->impl_;
  std::string log;

  // Candidate displays: EGL devices (the software one first), then the surfaceless Mesa platform.
  const char* clientExt = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  std::vector<std::pair<EGLenum, void*>> candidates;
  if (hasExtension(clientExt, "EGL_EXT_device_enumeration") || hasExtension(clientExt, "EGL_EXT_device_base")) {
    auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
    EGLDeviceEXT devices[16];
    EGLint n = 0;
    if (queryDevices && queryDevices(16, devices, &n)) {
      std::vector<std::pair<EGLenum, void*>> hardware;
      for (EGLint i = 0; i < n; ++i) {
        const char* ext = queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
        if (hasExtension(ext, "EGL_MESA_device_software"))
          candidates.emplace_back(EGL_PLATFORM_DEVICE_EXT, devices[i]);
        else
          hardware.emplace_back(EGL_PLATFORM_DEVICE_EXT, devices[i]);
      }
      candidates.insert(candidates.end(), hardware.begin(), hardware.end());
    } else {
      log += "eglQueryDevicesEXT failed; ";
    }
  } else {
    log += "no EGL_EXT_device_enumeration; ";
  }
  if (hasExtension(clientExt, "EGL_MESA_platform_surfaceless"))
    candidates.emplace_back(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY);
  if (!getPlatformDisplay) candidates.clear(), log += "no eglGetPlatformDisplayEXT; ";

  for (auto& cand : candidates) {
    EGLDisplay dpy = getPlatformDisplay(cand.first, cand.second, nullptr);
    EGLint major = 0, minor = 0;
    if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
      log += "display init: " + eglErrorString(eglGetError()) + "; ";
      continue;
    }
    if (!eglBindAPI(EGL_OPENGL_API)) {
      log += "eglBindAPI(OpenGL): " + eglErrorString(eglGetError()) + "; ";
      eglTerminate(dpy);
      continue;
    }
    EGLConfig config = nullptr;
    const char* dpyExt = eglQueryString(dpy, EGL_EXTENSIONS);
    if (!hasExtension(dpyExt, "EGL_KHR_no_config_context")) {
      const EGLint cfgAttribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_SURFACE_TYPE, 0, EGL_NONE};
      EGLint count = 0;
      if (!eglChooseConfig(dpy, cfgAttribs, &config, 1, &count) || count < 1) {
        log += "no OpenGL EGLConfig; ";
        eglTerminate(dpy);
        continue;
      }
    }
    const EGLint ctxAttribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext ctx = eglCreateContext(dpy, config, EGL_NO_CONTEXT, ctxAttribs);
    if (ctx == EGL_NO_CONTEXT) {
      log += "OpenGL 4.5 core context: " + eglErrorString(eglGetError()) + "; ";
      eglTerminate(dpy);
      continue;
    }
    if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx)) {
      log += "eglMakeCurrent without surface: " + eglErrorString(eglGetError()) + "; ";
      eglDestroyContext(dpy, ctx);
      eglTerminate(dpy);
      continue;
    }
    m.display = dpy;
    m.context = ctx;
    break;
  }
  if (m.context == EGL_NO_CONTEXT) {
    error = "cannot create a headless OpenGL 4.5 core context through EGL (" + log +
            "tried " + std::to_string(candidates.size()) + " display(s)); install libegl-mesa0 and libgl1-mesa-dri";
    return nullptr;
  }

  bool loaded = true;
  std::string missing;
#define FFTESS_LOAD(type, name)                                                                                       \
  m.gl.name = reinterpret_cast<type>(eglGetProcAddress(#name));                                                     \
  if (!m.gl.name) loaded = false, missing += " " #name;
  FFTESS_GL_FUNCTIONS(FFTESS_LOAD)
#undef FFTESS_LOAD
  if (!loaded) {
    error = "OpenGL entry points missing:" + missing;
    return nullptr;
  }
  auto& gl = m.gl;
  o->renderer_ = reinterpret_cast<const char*>(gl.glGetString(GL_RENDERER));
  o->version_ = reinterpret_cast<const char*>(gl.glGetString(GL_VERSION));

  GLint tesBlocks = 0;
  gl.glGetIntegerv(GL_MAX_TESS_EVALUATION_SHADER_STORAGE_BLOCKS, &tesBlocks);
  if (tesBlocks < 3) {
    error = "the GL implementation (" + o->renderer_ + ") offers " + std::to_string(tesBlocks) +
            " storage blocks to tessellation evaluation shaders; the oracle needs 3";
    return nullptr;
  }

  // Draws need a complete framebuffer; an attachment-less one will do under rasterizer discard.
  gl.glGenFramebuffers(1, &m.fbo);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
  gl.glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_WIDTH, 16);
  gl.glFramebufferParameteri(GL_FRAMEBUFFER, GL_FRAMEBUFFER_DEFAULT_HEIGHT, 16);
  if (gl.glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "attachment-less framebuffer incomplete";
    return nullptr;
  }
  gl.glViewport(0, 0, 16, 16);
  gl.glEnable(GL_RASTERIZER_DISCARD);
  gl.glGenVertexArrays(1, &m.vao);
  gl.glBindVertexArray(m.vao);
  gl.glPatchParameteri(GL_PATCH_VERTICES, 1);

  GLuint bufs[5];
  gl.glGenBuffers(5, bufs);
  m.factorBuf = bufs[0], m.counterBuf = bufs[1], m.slotBuf = bufs[2], m.storedBuf = bufs[3], m.captureBuf = bufs[4];
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.counterBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, kMaxPatchesPerDraw * 4, nullptr, GL_DYNAMIC_DRAW);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.slotBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, (kMaxPatchesPerDraw + 1) * 4, nullptr, GL_DYNAMIC_DRAW);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.storedBuf);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, kDrawPointBudget * 8, nullptr, GL_DYNAMIC_READ);
  gl.glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, m.captureBuf);
  gl.glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, static_cast<GLsizeiptr>(kCaptureVertices) * kCaptureStride * 4,
                  nullptr, GL_DYNAMIC_READ);
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

  // Pass 1: point_mode. One captured vertex per domain point, in the tessellator's order.
  const int spacing = spacingOf(first.partitioning);
  Program* pointProg = program({first.domain, spacing, Capture::Points}, error);
  if (!pointProg) return false;
  std::vector<int> bounds(n);
  for (int i = 0; i < n; ++i) bounds[i] = pointBound(patches[members[i]]);
  for (int begin = 0; begin < n;) {
    int end = begin, budget = 0;
    while (end < n && end - begin < kMaxPatchesPerDraw && budget + padTo4(bounds[end]) <= kDrawPointBudget)
      budget += padTo4(bounds[end++]);
    captured.clear();
    if (!draw(*pointProg, Capture::Points, begin, end - begin, {}, error)) return false;
    int last = 0;
    for (size_t v = 0; v < captured.size(); v += kCaptureStride) {
      const int local = static_cast<int>(captured[v + 2]);
      if (local < last || begin + local >= end) {
        error = "point capture out of patch order (patch " + std::to_string(local) + " after " + std::to_string(last) + ")";
        return false;
      }
      last = local;
      Result& r = results[members[begin + local]];
      r.points.push_back(captured[v]);
      r.points.push_back(captured[v + 1]);
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

  // Pass 2: primitives, for the topologies that have them in GL.
  std::vector<int> prim;
  for (int i = 0; i < n; ++i) {
    const Patch& p = patches[members[i]];
    Result& r = results[members[i]];
    const int count = r.pointCount();
    if (p.topology == Topology::Point) {
      r.verticesPerPrimitive = 1;
      for (int k = 0; k < count; ++k) r.indices.push_back(k);
    } else if (p.topology == Topology::Line && p.domain != Domain::Isoline) {
      // D3D quad/tri "line" output: the points joined in generation order. GL has no such output; derived here.
      r.verticesPerPrimitive = 2;
      for (int k = 0; k + 1 < count; ++k) r.indices.push_back(k), r.indices.push_back(k + 1);
    } else {
      prim.push_back(i);
    }
  }
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
    const int perPrim = cap == Capture::Lines ? 2 : 3;
    Program* prog = program({first.domain, spacing, cap}, error);
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
      std::vector<uint32_t> slotBases(1, 0u);
      while (end < m && end - begin < kMaxPatchesPerDraw &&
             budget + padTo4(results[members[sel[end]]].pointCount()) <= kDrawPointBudget) {
        const int c = results[members[sel[end]]].pointCount();
        budget += padTo4(c);
        slotBases.push_back(slotBases.back() + static_cast<uint32_t>(c));
        ++end;
      }
      captured.clear();
      if (!draw(*prog, cap, begin, end - begin, slotBases, error)) return false;
      std::vector<uint32_t> counters, stored;
      if (!readBuffer(counterBuf, static_cast<size_t>(end - begin), counters, error)) return false;
      if (!readBuffer(storedBuf, static_cast<size_t>(slotBases.back()) * 2, stored, error)) return false;
      int last = 0;
      const size_t primWords = static_cast<size_t>(perPrim) * kCaptureStride;
      for (size_t v = 0; v < captured.size(); v += primWords) {
        const int local = static_cast<int>(captured[v + 2]);
        if (local < last || begin + local >= end) {
          error = "primitive capture out of patch order";
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
          return false;
        }
      }
      begin = end;
    }
  }
  return true;
}

int GlOracle::drawCalls() const { return impl_->drawCalls; }

bool GlOracle::run(const std::vector<Patch>& patches, std::vector<Result>& results, std::string& error) {
  results.assign(patches.size(), Result{});
  impl_->drawCalls = 0;
  // Group by domain and spacing: one upload of factors and one program per pass.
  std::map<std::pair<int, int>, std::vector<int>> groups;
  for (size_t i = 0; i < patches.size(); ++i)
    groups[{static_cast<int>(patches[i].domain), spacingOf(patches[i].partitioning)}].push_back(static_cast<int>(i));
  for (auto& kv : groups) {
    // All members share domain and spacing; runGroup takes the partitioning of the first only for the spacing.
    if (!impl_->runGroup(patches, kv.second, results, error)) return false;
  }
  return true;
}

} // namespace oracle
} // namespace fftess
