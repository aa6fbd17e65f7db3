// The GPU path of the LOD: the provider (the GL program, the buffers, the dispatch). See gpu_lod.h and
// docs/gpu_lod.md; the compute source comes from gpu_lod/wrapper.h (wrapper_glsl.cpp, wrapper_hlsl.cpp).
#include "gpu_lod/gpu_lod.h"
#include "gl/gl_context.h"
#include "gpu_lod/hull.h"
#include "gpu_lod/wrapper.h"

#include "base/bits.h"

#include <chrono>
#include <mutex>
#include <regex>
#include <string>
#include <vector>

namespace fftess::gpulod {

namespace {

namespace vf = fftess::verify;
using gltest::GlFunctions;
using namespace detail;

} // namespace

struct GpuLodProvider::Impl {
  gltest::GlContext ctx;
  std::mutex mutex;
  GLuint program = 0;
  GLuint buffers[3] = {0, 0, 0}; // in, out, camera
  const void* inputKey = nullptr;
  uint64_t inputGeneration = 0; // LodPatches::generation() of the uploaded inputs (a quadtree reselects per camera)
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
  std::unique_ptr<hull::HullCapture> hull; // a hull shader as written (hull.h): the driver's TCS, not the compute path
};

GpuLodProvider::GpuLodProvider(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
GpuLodProvider::~GpuLodProvider() {
  if (impl_ && impl_->ctx.makeCurrent()) {
    impl_->hull.reset(); // its GL objects, on its context
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

namespace {

bool endsWith(const std::string& s, const char* tail) {
  const size_t n = std::char_traits<char>::length(tail);
  return s.size() > n && s.compare(s.size() - n, n, tail) == 0;
}

// The compute source of the scene's LOD: the user's GLSL file, the user's HLSL file through glslang and
// spirv-cross, or the built-in scheme's lod/shaders/*.glsl. description: what runs (GpuLodProvider::description).
bool computeSource(const vf::Lod& L, bool sizeJumps, std::string& source, std::string& description,
                   std::string& error, GpuLodError& kind) {
  const std::string& file = L.shader;
  if (file.empty()) {
    description = std::string("built-in ") + vf::toString(L.scheme) + " (lod/shaders/*.glsl)";
    source = glslComputeSource(L, "", sizeJumps);
    return true;
  }
  const bool hlsl = endsWith(file, ".hlsl");
  std::string user;
  kind = GpuLodError::Shader;
  if (!readFile(file, user)) {
    error = file + ": cannot read the shader";
    return false;
  }
  if (!hasEntryPoint(user)) {
    error = file + ": no entry point lodMain: the file must define " +
            std::string(hlsl ? kSignatureHlsl : kSignatureGlsl) + " (docs/gpu_lod.md)";
    return false;
  }
  kind = GpuLodError::None;
  if (hlsl) {
    description = "lod.shader " + file + " (HLSL -> SPIR-V -> GLSL)";
    return hlslToGlsl(L, source, error, kind);
  }
  description = "lod.shader " + file + " (GLSL)";
  source = glslComputeSource(L, user, sizeJumps);
  return true;
}

// A lodMain file takes everything as parameters: a uniform it reads (GLSL `uniform float x;`, an HLSL global or cbuffer
// member) would read 0 on the compute path, so every active uniform of the linked program (fftess's wrapper declares
// none) is an error at its declaration in the user's file. False with error ("WHAT:\nDIAGNOSTICS").
bool refuseUniforms(GpuLodProvider::Impl& impl, const std::string& file, bool hlsl, std::string& error) {
  const GlFunctions& gl = impl.ctx.gl;
  GLint count = 0;
  gl.glGetProgramInterfaceiv(impl.program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
  if (count <= 0) return true;
  std::string text, lines;
  readFile(file, text);
  for (GLint i = 0; i < count; ++i) {
    char name[256] = {0};
    gl.glGetProgramResourceName(impl.program, GL_UNIFORM, static_cast<GLuint>(i), sizeof name, nullptr, name);
    std::string n = name;
    const size_t dot = n.find_last_of('.'); // "Block.member" (an HLSL cbuffer or global)
    if (dot != std::string::npos) n = n.substr(dot + 1);
    if (n.size() > 3 && n.compare(n.size() - 3, 3, "[0]") == 0) n.resize(n.size() - 3);
    // Its declaration: the first line naming it as a whole word (after "uniform" in GLSL).
    int line = 0, column = 0, l = 1;
    const std::regex word("\\b" + n + "\\b");
    for (size_t start = 0; start <= text.size() && line == 0; ++l) {
      const size_t end = std::min(text.find('\n', start), text.size());
      const std::string t = text.substr(start, end - start);
      std::smatch m;
      if ((hlsl || t.find("uniform") != std::string::npos) && std::regex_search(t, m, word)) {
        line = l;
        column = static_cast<int>(m.position(0)) + 1;
      }
      start = end + 1;
    }
    lines += "\n" + file + (line > 0 ? ":" + std::to_string(line) + ":" + std::to_string(column) : std::string()) +
             ": error: " + (hlsl ? "global or cbuffer member '" : "uniform '") + n +
             "' in a lodMain file: it would read 0 (lodMain takes everything as parameters; make it a constant, or "
             "check the shader as written: a hull shader with [lod.uniforms], docs/gpu_lod.md)";
  }
  error = file + ": the lodMain file uses uniforms fftess does not set:" + lines;
  return false;
}

// Compiles and links `source` on the provider's context (current on return, released by the caller). error names
// the user's file and line where the driver's log does.
bool buildProgram(GpuLodProvider::Impl& impl, const vf::Lod& L, const std::string& source, std::string& error,
                         GpuLodError& kind) {
  const std::string& file = L.shader;
  const bool hlsl = endsWith(file, ".hlsl");
  const GlFunctions& gl = impl.ctx.gl;
  const GLuint sh = gl.glCreateShader(GL_COMPUTE_SHADER);
  const char* src = source.c_str();
  gl.glShaderSource(sh, 1, &src, nullptr);
  gl.glCompileShader(sh);
  GLint ok = 0;
  gl.glGetShaderiv(sh, GL_COMPILE_STATUS, &ok);
  std::string log(16384, '\0');
  kind = GpuLodError::Shader;
  if (!ok) {
    gl.glGetShaderInfoLog(sh, static_cast<GLsizei>(log.size()), nullptr, log.data());
    log = trimLog(log.c_str());
    const std::string where = file.empty() ? std::string("built-in ") + vf::toString(L.scheme) : file;
    bool wrapper = false;
    const std::string named = hlsl ? log : driverLog(log, file, wrapper);
    if (!hlsl && !file.empty() && wrapper)
      error = file + ": lodMain has the wrong signature or return type: expected " + kSignatureGlsl +
              " (docs/gpu_lod.md); the driver (" + impl.ctx.renderer() + ") says:\n" + named;
    else
      error = where + ": GLSL compile failed on " + impl.ctx.renderer() + ":\n" + named;
    gl.glDeleteShader(sh);
    return false;
  }
  impl.program = gl.glCreateProgram();
  gl.glAttachShader(impl.program, sh);
  gl.glLinkProgram(impl.program);
  gl.glGetProgramiv(impl.program, GL_LINK_STATUS, &ok);
  gl.glDetachShader(impl.program, sh);
  gl.glDeleteShader(sh);
  if (!ok) {
    gl.glGetProgramInfoLog(impl.program, static_cast<GLsizei>(log.size()), nullptr, log.data());
    error = (file.empty() ? std::string("built-in LOD") : file) + ": GL program link failed on " +
            impl.ctx.renderer() + ":\n" + trimLog(log.c_str());
    return false;
  }
  if (!file.empty() && !refuseUniforms(impl, file, hlsl, error)) return false;
  gl.glGenBuffers(3, impl.buffers);
  if (!gltest::checkGl(gl, "creating the GPU LOD program", error)) {
    kind = GpuLodError::Gl;
    return false;
  }
  kind = GpuLodError::None;
  return true;
}

} // namespace

namespace {

// The scene keys that feed a hull shader as written, set with a lodMain file: the first one's name, or nullptr.
const char* hullKeySet(const vf::Lod& L) {
  const vf::Lod d;
  if (!L.entry.empty()) return "lod.entry";
  if (!L.evaluationShader.empty()) return "lod.evaluation_shader";
  if (!L.uniforms.empty()) return "lod.uniforms";
  if (!L.inputs.empty()) return "lod.inputs";
  if (L.controlPoints != d.controlPoints || L.cornerOrder != d.cornerOrder) return "lod.control_points / lod.corner_order";
  if (L.domainU != d.domainU || L.domainV != d.domainV) return "lod.domain_u / lod.domain_v";
  return nullptr;
}

// "WHAT:" and the diagnostics, one per line (the cli prints them as they are: file:line:col: error: ...).
std::string diagnosticError(const std::string& what, const std::vector<hull::Diagnostic>& ds) {
  return what + ":\n" + hull::formatDiagnostics(ds);
}

// A wrong lod.entry is the scene's mistake: the diagnostic without a place goes to lod.entry's position in the scene.
void entryAtSceneKey(const vf::Scene& scene, std::vector<hull::Diagnostic>& diags) {
  for (hull::Diagnostic& d : diags) {
    if (d.at.line > 0 || d.message.rfind("lod.entry", 0) != 0) continue;
    const std::string shader = d.at.file;
    d.at = {scene.source, scene.lod.entryLine, scene.lod.entryColumn};
    const size_t here = d.message.find("in this file");
    if (here != std::string::npos) d.message.replace(here, 12, "in " + shader);
    else d.message += " (lod.shader " + shader + ")";
  }
}

// A hull shader as written (hull.h): the front end, the scene against it, then the driver's program. impl's context
// is created here.
bool createHull(GpuLodProvider::Impl& impl, const vf::LodPatches& patches, const GpuLodOptions& options,
                std::string& error, GpuLodError& kind) {
  const vf::Lod& L = patches.scene().lod;
  hull::HullProgram program;
  std::vector<hull::Diagnostic> diags;
  kind = GpuLodError::Shader;
  if (!hull::compileHull(L.shader, L.entry, program, diags)) {
    entryAtSceneKey(patches.scene(), diags);
    gltest::ContextOptions co; // the driver's columns where glslang 12 prints none (GLSL)
    co.order = options.hardware ? gltest::DeviceOrder::HardwareFirst : gltest::DeviceOrder::SoftwareFirst;
    std::string ignored;
    if (program.language == hull::Language::Glsl && impl.ctx.create(co, ignored)) {
      impl.ctx.releaseCurrent();
      hull::fillColumnsFromDriver(impl.ctx, program, diags);
    }
    error = diagnosticError(L.shader + ": the hull shader does not compile", diags);
    return false;
  }
  if (!L.evaluationShader.empty() && !hull::readEvaluationShader(L.evaluationShader, program, diags)) {
    error = diagnosticError(L.shader + ": the hull shader and its evaluation shader " + L.evaluationShader + " disagree", diags);
    return false;
  }
  if (!hull::checkAgainstScene(program, patches.scene(), diags)) {
    error = diagnosticError(L.shader + ": the scene and the hull shader disagree (" +
                                patches.scene().source + ")", diags);
    return false;
  }
  impl.description = "hull shader " + L.shader +
                     (program.language == hull::Language::Hlsl ? " (HLSL " + program.entry + " -> SPIR-V -> GLSL TCS)"
                                                               : std::string(" (GLSL TCS)")) +
                     " on the driver's tessellation control stage";
  // The one input with a default (docs/gpu_lod.md): said in the summary, so a scene never relies on it unseen.
  bool readsPosition = false, boundPosition = false;
  for (const hull::Input& in : program.inputs) readsPosition = readsPosition || in.builtin;
  for (const vf::InputBinding& b : L.inputs) boundPosition = boundPosition || b.name == "gl_Position";
  if (readsPosition && !boundPosition)
    impl.description += std::string(" (gl_in[].gl_Position: the default, lod.inputs.gl_Position = \"position\": ") +
                        (L.displacedCorners ? "the corners raised to the terrain)" : "the flat corners)");
  gltest::ContextOptions co;
  co.order = options.hardware ? gltest::DeviceOrder::HardwareFirst : gltest::DeviceOrder::SoftwareFirst;
  co.allowSoftware = !options.hardware;
  if (!impl.ctx.create(co, error)) {
    kind = GpuLodError::NoContext;
    return false;
  }
  impl.hull = hull::HullCapture::create(impl.ctx, program, patches, diags);
  impl.ctx.releaseCurrent();
  if (!impl.hull) {
    error = diagnosticError(L.shader + ": the driver (" + impl.ctx.renderer() + ") refused the hull shader", diags);
    return false;
  }
  if (const int n = impl.hull->levelWritesRewritten())
    impl.description += " (llvmpipe: " + std::to_string(n) + " write" + (n == 1 ? "" : "s") +
                        " of gl_TessLevelOuter/Inner at a dynamic index made constant-index: Mesa 22.3 loses them)";
  kind = GpuLodError::None;
  return true;
}

} // namespace

std::shared_ptr<GpuLodProvider> createGpuLod(const vf::LodPatches& patches, const GpuLodOptions& options,
                                             std::string& error, GpuLodError& kind) {
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  const vf::Lod& L = patches.scene().lod;
  auto impl = std::make_unique<GpuLodProvider::Impl>();
  impl->scheme = L.scheme;
  kind = GpuLodError::None;
  if (!L.shader.empty()) {
    std::string text;
    if (!readFile(L.shader, text)) {
      kind = GpuLodError::Shader;
      error = L.shader + ": cannot read the shader";
      return nullptr;
    }
    if (hull::isHullShader(L.shader, text)) {
      if (!createHull(*impl, patches, options, error, kind)) return nullptr;
      impl->compileSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
      return std::make_shared<GpuLodProvider>(std::move(impl));
    }
    if (const char* key = hullKeySet(L)) {
      kind = GpuLodError::Shader;
      error = L.shader + ": " + key + " feeds a hull shader as written, and this file is a lodMain file (its inputs "
              "are lodMain's parameters; docs/gpu_lod.md)";
      return nullptr;
    }
  }
  if (L.shader.empty() && L.scheme == vf::LodScheme::Geomorph) {
    kind = GpuLodError::Shader;
    error = "lod.scheme = \"geomorph\" has no GPU path";
    return nullptr;
  }
  // 1. The GLSL compute source (HLSL: through glslang and spirv-cross first).
  std::string source;
  if (!computeSource(L, patches.sizeJumps(), source, impl->description, error, kind)) return nullptr;
  // 2. The context and the program.
  gltest::ContextOptions co;
  co.order = options.hardware ? gltest::DeviceOrder::HardwareFirst : gltest::DeviceOrder::SoftwareFirst;
  co.allowSoftware = !options.hardware;
  if (!impl->ctx.create(co, error)) {
    kind = GpuLodError::NoContext;
    return nullptr;
  }
  const bool built = buildProgram(*impl, L, source, error, kind);
  impl->ctx.releaseCurrent(); // sweep threads take it in turn (evaluate)
  if (!built) return nullptr;
  impl->compileSeconds = std::chrono::duration<double>(Clock::now() - t0).count();
  return std::make_shared<GpuLodProvider>(std::move(impl));
}

namespace {

// The patches' inputs as the buffer's words (kInWords per patch, docs/gpu_lod.md "Buffers").
void inputWords(const vf::LodPatches& patches, std::vector<uint32_t>& words) {
  const size_t n = patches.size();
  words.assign(n * kInWords, 0);
  for (size_t i = 0; i < n; ++i) {
    const vf::LodInput in = patches[i];
    uint32_t* w = words.data() + i * kInWords;
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
}

// The camera and the patch count as the camera buffer's kCamWords words.
void cameraWords(const lod::Camera& camera, size_t patchCount, uint32_t (&cam)[kCamWords]) {
  for (int k = 0; k < 16; ++k) {
    cam[k] = bitsOf(camera.view[k / 4][k % 4]);
    cam[16 + k] = bitsOf(camera.projection[k / 4][k % 4]);
  }
  cam[32] = bitsOf(camera.viewport.x);
  cam[33] = bitsOf(camera.viewport.y);
  for (int k = 0; k < 3; ++k) cam[34 + k] = bitsOf(camera.eye[k]);
  cam[37] = camera.depthZeroToOne ? 1u : 0u;
  cam[38] = static_cast<uint32_t>(patchCount);
}

lod::Scheme lodScheme(vf::LodScheme s) {
  return s == vf::LodScheme::DistancePow2   ? lod::Scheme::DistancePow2
         : s == vf::LodScheme::Bonaventura  ? lod::Scheme::Bonaventura
         : s == vf::LodScheme::ClipDiameter ? lod::Scheme::ClipDiameter
         : s == vf::LodScheme::PatchCenter  ? lod::Scheme::PatchCenter
         : s == vf::LodScheme::Constant     ? lod::Scheme::Constant
                                            : lod::Scheme::ScreenSphere;
}

// The output buffer's words (kOutWords per patch) -> PatchLod.
void readResults(const std::vector<uint32_t>& words, lod::Scheme scheme, std::vector<lod::PatchLod>& out) {
  for (size_t i = 0; i < out.size(); ++i) {
    const uint32_t* w = words.data() + i * kOutWords;
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
}

} // namespace

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
  if (m.hull) {
    const auto t0 = Clock::now();
    if (!m.hull->evaluate(patches, camera, out, error)) return false;
    ++m.dispatches;
    m.dispatchSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
    return true;
  }
  // The patches' inputs: once per terrain.
  if (m.inputKey != patches.key() || m.inputGeneration != patches.generation() || m.inputCount != n) {
    const auto t0 = Clock::now();
    inputWords(patches, m.words);
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
    m.inputGeneration = patches.generation();
    m.inputCount = n;
    m.uploadSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
  }
  const auto t0 = Clock::now();
  uint32_t cam[kCamWords];
  cameraWords(camera, n, cam);
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
  readResults(m.words, lodScheme(m.scheme), out);
  ++m.dispatches;
  m.dispatchSeconds += std::chrono::duration<double>(Clock::now() - t0).count();
  return true;
}

} // namespace fftess::gpulod
