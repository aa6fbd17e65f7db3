// The driver half of the user's hull shader: the GL program (generated vertex shader, the user's TCS with a recording
// epilogue, generated evaluation shader), one draw per camera, the levels read back and mapped onto fftess's edges.
// See hull.h and docs/gpu_lod.md "The driver half".
#include "gpu_lod/hull.h"
#include "gpu_lod/hull_bind.h"

#include "base/bits.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

namespace fftess::gpulod::hull {

namespace {

// The text with comments blanked (newlines kept): offsets are the original's.
std::string withoutComments(const std::string& s) {
  std::string out = s;
  for (size_t i = 0; i + 1 < s.size(); ++i) {
    if (s[i] == '/' && s[i + 1] == '/') {
      for (; i < s.size() && s[i] != '\n'; ++i) out[i] = ' ';
    } else if (s[i] == '/' && s[i + 1] == '*') {
      const size_t end = s.find("*/", i + 2);
      const size_t stop = end == std::string::npos ? s.size() : end + 2;
      for (; i < stop; ++i)
        if (s[i] != '\n') out[i] = ' ';
      --i;
    }
  }
  return out;
}

bool isIdent(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The offset of identifier `word` followed by optional blanks and '(' in `code` from `from`, or npos.
size_t findCall(const std::string& code, const std::string& word, size_t from = 0) {
  for (size_t p = code.find(word, from); p != std::string::npos; p = code.find(word, p + 1)) {
    if (p > 0 && isIdent(code[p - 1])) continue;
    size_t q = p + word.size();
    if (q < code.size() && isIdent(code[q])) continue;
    while (q < code.size() && std::isspace(static_cast<unsigned char>(code[q]))) ++q;
    if (q < code.size() && code[q] == '(') return p;
  }
  return std::string::npos;
}

// The offset of `void main(` (the definition: `main` preceded by `void`), or npos.
size_t findMain(const std::string& code) {
  for (size_t p = findCall(code, "main"); p != std::string::npos; p = findCall(code, "main", p + 1)) {
    size_t q = p;
    while (q > 0 && std::isspace(static_cast<unsigned char>(code[q - 1]))) --q;
    if (q >= 4 && code.compare(q - 4, 4, "void") == 0 && (q == 4 || !isIdent(code[q - 5]))) return p;
  }
  return std::string::npos;
}

std::string recordStatements() {
  return "if (gl_InvocationID == 0) { uint fftessPatch = fftessPatchBase + uint(gl_PrimitiveID); "
         "uint fftessAt = fftessPatch * 6u; "
         "fftessLevels[fftessAt] = floatBitsToUint(gl_TessLevelOuter[0]); "
         "fftessLevels[fftessAt + 1u] = floatBitsToUint(gl_TessLevelOuter[1]); "
         "fftessLevels[fftessAt + 2u] = floatBitsToUint(gl_TessLevelOuter[2]); "
         "fftessLevels[fftessAt + 3u] = floatBitsToUint(gl_TessLevelOuter[3]); "
         "fftessLevels[fftessAt + 4u] = floatBitsToUint(gl_TessLevelInner[0]); "
         "fftessLevels[fftessAt + 5u] = floatBitsToUint(gl_TessLevelInner[1]); "
         "fftessLevels[fftessPatchCount * 6u + fftessPatch] = 1u; "
         "gl_TessLevelOuter[0] = 0.0; } ";
}


// Line numbers the driver prints name their file whatever it does with `#line L S`'s source-string number (Mesa
// prints 0): every `#line L [S]` becomes `#line S * kLineStride + L S`, and a log's line N is file N / kLineStride,
// line N % kLineStride (lines before the first directive: string 0).
constexpr int kLineStride = 100000;

// Patches per draw: gl_PrimitiveID counts from 0 in each draw (the record adds fftessPatchBase). llvmpipe (Mesa 22)
// restarts gl_PrimitiveID within one draw of 4096 four-point patches at patch 1024 (seen: patch 1024's levels were
// never recorded), so draws stay well below that.
constexpr size_t kPatchesPerDraw = 256;

std::string encodeLineDirectives(const std::string& glsl) {
  std::istringstream in(glsl);
  std::string line, out;
  int source = 0;
  while (std::getline(in, line)) {
    size_t p = line.find_first_not_of(" \t");
    if (p != std::string::npos && line[p] == '#') {
      p = line.find_first_not_of(" \t", p + 1);
      long l = 0, s = -1;
      if (p != std::string::npos && line.compare(p, 4, "line") == 0 &&
          std::sscanf(line.c_str() + p + 4, "%ld %ld", &l, &s) >= 1) {
        if (s >= 0) source = static_cast<int>(s);
        line = "#line " + std::to_string(static_cast<long>(source) * kLineStride + l) + " " + std::to_string(source);
      }
    }
    out += line + "\n";
  }
  return out;
}

// The TCS the driver compiles: program.glsl with the recording epilogue (docs/gpu_lod.md "The driver half"). The
// SSBO declaration goes before main (on main's own line, so no line moves); numbered as source string
// `generatedString` where it adds lines. False with a message when main cannot be found or the record cannot be
// placed.
bool tcsWithEpilogue(const std::string& glsl, int binding, int generatedString, std::string& out,
                     std::string& error) {
  const std::string code = withoutComments(glsl);
  const size_t main = findMain(code);
  if (main == std::string::npos) {
    error = "the tessellation control shader has no 'void main()' fftess can find";
    return false;
  }
  const std::string ssbo = "layout(std430, binding = " + std::to_string(binding) +
                           ") buffer FftessLevels { uint fftessLevels[]; }; uniform uint fftessPatchCount; "
                           "uniform uint fftessPatchBase; ";
  size_t voidAt = code.rfind("void", main);
  if (findCall(code, "barrier") == std::string::npos) {
    // Rename the user's main; a new main after it runs it, waits for every invocation and records.
    out = glsl.substr(0, voidAt) + ssbo + glsl.substr(voidAt, main - voidAt) + "fftessUserMain" +
          glsl.substr(main + 4);
    out += "\n#line " + std::to_string(static_cast<long>(generatedString) * kLineStride + 1) + " " +
           std::to_string(generatedString) + "\nvoid main() { fftessUserMain(); barrier(); " +
           recordStatements() + "}\n";
    return true;
  }
  // The text calls barrier() (HLSL through SPIRV-Cross always does): the record goes just before main's closing
  // brace, on that line.
  const size_t open = code.find('{', main);
  int depth = 0;
  size_t close = std::string::npos;
  for (size_t i = open; open != std::string::npos && i < code.size(); ++i) {
    if (code[i] == '{') ++depth;
    if (code[i] == '}' && --depth == 0) {
      close = i;
      break;
    }
  }
  if (close == std::string::npos) {
    error = "the body of the tessellation control shader's main() has no closing brace fftess can find";
    return false;
  }
  const std::string body = code.substr(open, close - open);
  bool returns = false; // the word `return` anywhere in main's body
  for (size_t p = body.find("return"); p != std::string::npos; p = body.find("return", p + 1))
    returns = returns || ((p == 0 || !isIdent(body[p - 1])) && (p + 6 >= body.size() || !isIdent(body[p + 6])));
  if (returns) {
    error = "the tessellation control shader's main() calls barrier() and returns early: fftess cannot place the "
            "record of its levels after the last write (remove the return from main, or the barrier())";
    return false;
  }
  out = glsl.substr(0, voidAt) + ssbo + glsl.substr(voidAt, close - voidAt) + " barrier(); " +
        recordStatements() + glsl.substr(close);
  return true;
}

// llvmpipe (Mesa 22.3) loses writes to gl_TessLevelOuter / gl_TessLevelInner at a dynamic index when several
// invocations write (measured: invocation i writing gl_TessLevelOuter[gl_InvocationID] = i + 1 left [0, 0, 0, 4]; with
// constant indices, or through a function that branches to constant-index writes, all four arrive; NVIDIA has no such
// loss, docs/gpu_lod.md). Each statement `gl_TessLevel{Outer,Inner}[INDEX] = VALUE;` whose INDEX is not a literal
// becomes `fftessSet{Outer,Inner}(int(INDEX), VALUE);` on its own line, and the two setters go after the #version and
// #extension lines (a `#line` keeps the user's numbering): the GLSL meaning is the same. count: statements rewritten.
std::string constantLevelWrites(const std::string& glsl, int& count) {
  static const std::regex write(R"(gl_TessLevel(Outer|Inner)\s*\[\s*([^\]\[;]+?)\s*\]\s*=(?!=)\s*([^;]+);)");
  std::string out;
  count = 0;
  auto from = glsl.cbegin();
  for (std::sregex_iterator it(glsl.begin(), glsl.end(), write), end; it != end; ++it) {
    const std::smatch& m = *it;
    const std::string index = m[2];
    out.append(from, m[0].first);
    if (index.find_first_not_of("0123456789u") == std::string::npos) out += m[0].str();
    else {
      out += "fftessSet" + m[1].str() + "(int(" + index + "), " + m[3].str() + ");";
      ++count;
    }
    from = m[0].second;
  }
  out.append(from, glsl.cend());
  if (count == 0) return glsl;
  // After the last #version / #extension line (directives must come first), numbered back with #line.
  static const std::regex head(R"((^|\n)[ \t]*#[ \t]*(version|extension)[^\n]*)");
  size_t at = 0;
  for (std::sregex_iterator it(out.begin(), out.end(), head), end; it != end; ++it)
    at = static_cast<size_t>(it->position(0) + it->length(0));
  if (at == 0 || at >= out.size()) return glsl;
  const long next = 2 + static_cast<long>(std::count(out.begin(), out.begin() + static_cast<long>(at), '\n'));
  std::string setters;
  for (const char* kind : {"Outer", "Inner"}) {
    setters += std::string("void fftessSet") + kind + "(int i, float v) {";
    for (int k = 0; k < (kind[0] == 'O' ? 4 : 2); ++k)
      setters += std::string(k ? " else" : "") + " if (i == " + std::to_string(k) + ") { gl_TessLevel" + kind + "[" +
                 std::to_string(k) + "] = v; }";
    setters += " }\n";
  }
  return out.substr(0, at + 1) + setters + "#line " + std::to_string(next) + " 0\n" + out.substr(at + 1);
}

// A shader of #version 400 to 420 (LearnOpenGL's TCS is 410 core) has no storage blocks and no layout(binding): the
// record needs GL_ARB_shader_storage_buffer_object and GL_ARB_shading_language_420pack (both in every GL 4.3+
// driver). They go right after the #version line, which keeps its number; `#line` puts the user's next line back.
std::string withRecordExtensions(const std::string& glsl) {
  const std::string code = withoutComments(glsl);
  const size_t at = code.find("#version");
  if (at == std::string::npos) return glsl;
  int version = 0;
  char profile[8] = "";
  const int fields = std::sscanf(code.c_str() + at + 8, "%d %7s", &version, profile);
  if (fields < 1 || version >= 430 || std::string(profile) == "es") return glsl; // ES 3.10+: storage blocks are core
  const size_t eol = glsl.find('\n', at);
  if (eol == std::string::npos) return glsl;
  const long line = 1 + static_cast<long>(std::count(glsl.begin(), glsl.begin() + static_cast<long>(eol), '\n'));
  return glsl.substr(0, eol + 1) +
         "#extension GL_ARB_shader_storage_buffer_object : require\n"
         "#extension GL_ARB_shading_language_420pack : require\n"
         "#line " + std::to_string(line + 1) + " 0\n" + glsl.substr(eol + 1);
}


// One line of a driver's info log as a diagnostic: Mesa "S:L(C): error: MSG", NVIDIA "S(L) : error CNNNN: MSG".
// S (decoded from the line, encodeLineDirectives) indexes the program's sourceFiles (a GLSL TCS); other strings
// (fftess's epilogue, SPIRV-Cross's GLSL of an HLSL
// file) are fftess's: the diagnostic has no place and says so.
Diagnostic driverDiagnostic(const HullProgram& program, const std::string& line) {
  int s = -1, l = 0, c = 0, n = 0;
  std::string rest;
  if (std::sscanf(line.c_str(), "%d:%d(%d): %n", &s, &l, &c, &n) == 3 && n > 0) rest = line.substr(n);
  else if (std::sscanf(line.c_str(), "%d(%d) : %n", &s, &l, &n) == 2 && n > 0) rest = line.substr(n), c = 0;
  else return diagnostic({}, "the driver: " + line);
  s = l / kLineStride; // encodeLineDirectives
  l %= kLineStride;
  for (const char* word : {"error: ", "error ", "warning: ", "warning "})
    if (rest.compare(0, std::strlen(word), word) == 0) {
      rest = rest.substr(std::strlen(word));
      break;
    }
  // NVIDIA's error code ("C1008: ...") stays in the message.
  if (program.language == Language::Glsl && s >= 0 && s < static_cast<int>(program.sourceFiles.size()))
    return diagnostic({program.sourceFiles[static_cast<size_t>(s)], l, c}, rest);
  const std::string origin = program.language == Language::Hlsl ? "the GLSL SPIRV-Cross made from " + program.file
                                                                 : "fftess's recording epilogue";
  return diagnostic({}, "the driver rejected " + origin + " (line " + std::to_string(l) + "): " + rest);
}

void logDiagnostics(const HullProgram& program, const std::string& log, std::vector<Diagnostic>& errors) {
  std::istringstream in(log);
  std::string line;
  const size_t before = errors.size();
  while (std::getline(in, line)) {
    while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
    if (line.empty() || line.find("warning") != std::string::npos) continue;
    errors.push_back(driverDiagnostic(program, line));
  }
  if (errors.size() == before) errors.push_back(diagnostic({}, "the driver: " + log));
}

bool compileStage(const gltest::GlFunctions& gl, GLuint program, GLenum stage, const std::string& src,
                  const HullProgram& hull, bool user, std::vector<Diagnostic>& errors) {
  const GLuint shader = gl.glCreateShader(stage);
  std::string error;
  const bool ok = gltest::compileShader(gl, shader, src, error);
  if (ok) gl.glAttachShader(program, shader);
  gl.glDeleteShader(shader); // an attached shader is freed with the program
  if (ok) return true;
  // error = "GL shader compile failed: " + LOG + "\n" + src (gl_context.h): the log alone.
  const std::string prefix = "GL shader compile failed: ";
  const size_t end = error.size() >= prefix.size() + src.size() + 1 ? error.size() - src.size() - 1 : error.size();
  const std::string log =
      error.compare(0, prefix.size(), prefix) == 0 ? error.substr(prefix.size(), end - prefix.size()) : error;
  if (user) logDiagnostics(hull, log, errors);
  else errors.push_back(diagnostic({}, "fftess's generated shader does not compile on this driver: " + log));
  return false;
}

// Line `line` (1-based) of `file`, "" when it has none.
std::string lineOf(const std::string& file, int line) {
  std::ifstream f(file, std::ios::binary);
  std::string text;
  for (int l = 1; l <= line && std::getline(f, text); ++l) {
  }
  return text;
}

// NVIDIA names the token, not the column ("... at token \"foo\""): its first whole-word occurrence on that line of the
// file, 1-based; 0 when the message names none or the line lacks it.
int columnOfToken(const Diagnostic& d, const std::string& message) {
  const size_t at = message.find("at token \"");
  if (at == std::string::npos || d.at.file.empty() || d.at.line <= 0) return 0;
  const size_t end = message.find('"', at + 10);
  if (end == std::string::npos || end == at + 10) return 0;
  const std::string token = message.substr(at + 10, end - at - 10);
  const std::string line = lineOf(d.at.file, d.at.line);
  for (size_t p = line.find(token); p != std::string::npos; p = line.find(token, p + 1)) {
    const bool start = p == 0 || !isIdent(line[p - 1]), stop = p + token.size() >= line.size() || !isIdent(line[p + token.size()]);
    if (start && stop) return static_cast<int>(p) + 1;
  }
  return 0;
}

// Mesa's column (seen on Mesa 22.3: 1 + the characters before the token, each run of blanks counted as one) as the
// column in the file; 0 when it does not land on the start of a token.
int columnOfMesa(const Diagnostic& d, int mesa) {
  const std::string line = lineOf(d.at.file, d.at.line);
  int counted = 1;
  for (size_t i = 0; i < line.size();) {
    const bool blank = line[i] == ' ' || line[i] == '\t';
    if (counted == mesa)
      return blank || (i > 0 && isIdent(line[i - 1]) && isIdent(line[i])) ? 0 : static_cast<int>(i) + 1;
    if (blank) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    } else {
      ++i;
    }
    ++counted;
  }
  return 0;
}

const char* spacingOf(Partitioning p) {
  return p == Partitioning::FractionalOdd ? "fractional_odd_spacing"
         : p == Partitioning::FractionalEven ? "fractional_even_spacing"
                                             : "equal_spacing";
}

} // namespace

void fillColumnsFromDriver(gltest::GlContext& ctx, const HullProgram& program, std::vector<Diagnostic>& errors) {
  bool missing = false;
  for (const Diagnostic& d : errors) missing = missing || (d.at.line > 0 && d.at.column == 0);
  if (!missing || program.language != Language::Glsl || program.glsl.empty() || !ctx.makeCurrent()) return;
  const gltest::GlFunctions& gl = ctx.gl;
  const GLuint shader = gl.glCreateShader(GL_TESS_CONTROL_SHADER);
  std::string error;
  const bool ok = gltest::compileShader(gl, shader, encodeLineDirectives(program.glsl), error);
  gl.glDeleteShader(shader);
  ctx.releaseCurrent();
  if (ok) return;
  // error = "GL shader compile failed: " + LOG + "\n" + source (gl_context.h): the log alone.
  const std::string prefix = "GL shader compile failed: ";
  std::string log = error.compare(0, prefix.size(), prefix) == 0 ? error.substr(prefix.size()) : error;
  log = log.substr(0, log.find("\n#version"));
  std::vector<Diagnostic> driver;
  logDiagnostics(program, log, driver);
  for (Diagnostic& d : errors) {
    if (d.at.line <= 0 || d.at.column != 0) continue;
    // Only the driver's message of the same kind: both syntax errors, or the driver's column on glslang's quoted token.
    const size_t q = d.message.find('\'');
    const size_t q2 = q == std::string::npos ? q : d.message.find('\'', q + 1);
    const std::string quoted = q2 == std::string::npos ? "" : d.message.substr(q + 1, q2 - q - 1);
    for (const Diagnostic& g : driver) {
      if (g.at.file != d.at.file || g.at.line != d.at.line) continue;
      const int column = g.at.column > 0 ? columnOfMesa(g, g.at.column) : columnOfToken(g, g.message);
      const bool syntax = d.message.find("syntax error") != std::string::npos &&
                          g.message.find("syntax error") != std::string::npos;
      const std::string line = lineOf(d.at.file, d.at.line);
      const bool token = !quoted.empty() && column > 0 && line.compare(static_cast<size_t>(column - 1), quoted.size(), quoted) == 0;
      if (column > 0 && (syntax || token)) {
        d.at.column = column;
        break;
      }
    }
  }
}

namespace {

// Which fftess factor (Ueq0 Veq0 Ueq1 Veq1 insideU insideV) each of the shader's levels lands on: index k = outer 0..3,
// inner 0..1 (GL and D3D agree for quads: outer 0 is the edge u = 0, 1 v = 0, 2 u = 1, 3 v = 1; inner 0 along u).
std::array<int, 6> levelTargets(verify::DomainAxis u, verify::DomainAxis v) {
  using A = verify::DomainAxis;
  auto low = [](A a) { return a == A::PlusX ? 0 : a == A::MinusX ? 2 : a == A::PlusZ ? 1 : 3; };
  auto high = [&](A a) { return (low(a) + 2) % 4; };
  auto inside = [](A a) { return a == A::PlusX || a == A::MinusX ? 4 : 5; };
  return {low(u), low(v), high(u), high(v), inside(u), inside(v)};
}

} // namespace

struct HullCapture::Impl {
  gltest::GlContext* ctx = nullptr;
  GLuint program = 0, framebuffer = 0, vertexArray = 0, vertices = 0, levels = 0;
  GLint ssboBinding = 0;
  size_t patchCount = 0;
  int controlPoints = 4;
  std::array<int, 6> targets{};
  std::unique_ptr<UniformBinder> binder;
  std::vector<uint32_t> words;
  // The patches the control points were uploaded for (LodPatches::key, generation): a camera-dependent layout
  // (quadtree) puts each camera's leaves in the same per-thread terrain, so evaluate uploads them again on a change.
  HullProgram source;
  int slots = 0;
  const void* key = nullptr;
  uint64_t generation = 0;
  int levelWritesRewritten = 0; // llvmpipe: dynamically indexed level writes made constant-index (constantLevelWrites)
};

HullCapture::HullCapture(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

HullCapture::~HullCapture() {
  if (!impl_ || !impl_->ctx) return;
  const gltest::GlFunctions& gl = impl_->ctx->gl;
  impl_->binder.reset();
  const GLuint buffers[] = {impl_->vertices, impl_->levels};
  gl.glDeleteBuffers(2, buffers);
  if (impl_->vertexArray) gl.glDeleteVertexArrays(1, &impl_->vertexArray);
  if (impl_->framebuffer) gl.glDeleteFramebuffers(1, &impl_->framebuffer);
  if (impl_->program) gl.glDeleteProgram(impl_->program);
}

namespace {

// The program: generated VS, the user's TCS with the epilogue, generated TES. False with diagnostics.
bool buildProgram(HullCapture::Impl& m, const HullProgram& hull, const verify::Scene& scene,
                  std::vector<Diagnostic>& errors) {
  const gltest::GlFunctions& gl = m.ctx->gl;
  GLint ssboBlocks = 0, bindings = 0;
  gl.glGetIntegerv(GL_MAX_TESS_CONTROL_SHADER_STORAGE_BLOCKS, &ssboBlocks);
  gl.glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  if (ssboBlocks < 1 || bindings < 1) {
    errors.push_back(diagnostic({}, "this driver allows no shader storage block in a tessellation control shader "
                          "(GL_MAX_TESS_CONTROL_SHADER_STORAGE_BLOCKS = " + std::to_string(ssboBlocks) +
                          "): fftess records the hull shader's levels in one"));
    return false;
  }
  m.ssboBinding = bindings - 1;
  std::string tcs, error;
  const int generated = static_cast<int>(hull.sourceFiles.size() + 1000);
  const std::string user =
      m.ctx->isLlvmpipe() ? constantLevelWrites(hull.glsl, m.levelWritesRewritten) : hull.glsl;
  if (!tcsWithEpilogue(encodeLineDirectives(withRecordExtensions(user)), m.ssboBinding, generated, tcs, error)) {
    errors.push_back(diagnostic({hull.file, 0, 0}, error));
    return false;
  }
  const Partitioning p = hull.partitioning ? *hull.partitioning : scene.partitioning;
  const std::string tes = generatedVersion(hull, true) + "layout(quads, " + spacingOf(p) +
                          ", ccw) in;\nvoid main() { gl_Position = vec4(0.0); }\n";
  m.program = gl.glCreateProgram();
  if (!compileStage(gl, m.program, GL_VERTEX_SHADER, vertexShaderSource(hull), hull, false, errors) ||
      !compileStage(gl, m.program, GL_TESS_CONTROL_SHADER, tcs, hull, true, errors) ||
      !compileStage(gl, m.program, GL_TESS_EVALUATION_SHADER, tes, hull, false, errors))
    return false;
  gl.glLinkProgram(m.program);
  GLint linked = 0;
  gl.glGetProgramiv(m.program, GL_LINK_STATUS, &linked);
  if (!linked) {
    char log[8192] = {};
    gl.glGetProgramInfoLog(m.program, sizeof log, nullptr, log);
    errors.push_back(diagnostic({hull.file, 0, 0}, "the driver does not link the hull shader with fftess's vertex and "
                                         "evaluation shaders: " + std::string(log)));
    return false;
  }
  return true;
}

} // namespace

std::unique_ptr<HullCapture> HullCapture::create(gltest::GlContext& ctx, const HullProgram& program,
                                                 const verify::LodPatches& patches, std::vector<Diagnostic>& errors) {
  auto impl = std::make_unique<Impl>();
  Impl& m = *impl;
  m.ctx = &ctx;
  HullCapture capture(std::move(impl)); // frees what was made on failure
  const gltest::GlFunctions& gl = ctx.gl;
  const verify::Scene& scene = patches.scene();
  m.patchCount = patches.size();
  m.controlPoints = scene.lod.controlPoints;
  m.targets = levelTargets(scene.lod.domainU, scene.lod.domainV);
  std::vector<float> data;
  int slots = 0;
  if (!controlPointData(program, patches, data, slots, errors) || !buildProgram(m, program, scene, errors))
    return nullptr;
  std::string error;
  if (!gltest::prepareCaptureDraws(gl, m.framebuffer, m.vertexArray, error)) {
    errors.push_back(diagnostic({}, error));
    return nullptr;
  }
  gl.glGenBuffers(1, &m.vertices);
  gl.glGenBuffers(1, &m.levels);
  gl.glBindBuffer(GL_ARRAY_BUFFER, m.vertices);
  gl.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
  for (int s = 0; s < slots; ++s) {
    gl.glVertexAttribPointer(static_cast<GLuint>(s), 4, GL_FLOAT, GL_FALSE, slots * 16,
                             reinterpret_cast<const void*>(static_cast<uintptr_t>(s * 16)));
    gl.glEnableVertexAttribArray(static_cast<GLuint>(s));
  }
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.levels);
  gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(m.patchCount * 7 * 4), nullptr, GL_DYNAMIC_READ);
  m.source = program;
  m.slots = slots;
  m.key = patches.key();
  m.generation = patches.generation();
  m.binder = std::make_unique<UniformBinder>(gl, m.program);
  if (!m.binder->create(program, patches, errors)) return nullptr;
  if (!gltest::checkGl(gl, "setting up the hull shader's draw", error)) {
    errors.push_back(diagnostic({}, error));
    return nullptr;
  }
  return std::make_unique<HullCapture>(std::move(capture.impl_));
}

int HullCapture::levelWritesRewritten() const { return impl_->levelWritesRewritten; }

bool HullCapture::evaluate(const verify::LodPatches& patches, const lod::Camera& camera,
                           std::vector<lod::PatchLod>& out, std::string& error) {
  Impl& m = *impl_;
  const gltest::GlFunctions& gl = m.ctx->gl;
  if (patches.key() != m.key || patches.generation() != m.generation || patches.size() != m.patchCount) {
    // Other patches (a quadtree's next camera): their control points, in the same layout of vertex attributes.
    std::vector<float> data;
    int slots = 0;
    std::vector<Diagnostic> errors;
    if (!controlPointData(m.source, patches, data, slots, errors) || slots != m.slots) {
      error = "the hull shader's control points of the camera's patches: " + formatDiagnostics(errors);
      return false;
    }
    gl.glBindBuffer(GL_ARRAY_BUFFER, m.vertices);
    gl.glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STATIC_DRAW);
    gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.levels);
    gl.glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(patches.size() * 7 * 4), nullptr, GL_DYNAMIC_READ);
    m.patchCount = patches.size();
    m.key = patches.key();
    m.generation = patches.generation();
  }
  const size_t n = m.patchCount;
  gl.glUseProgram(m.program);
  if (!m.binder->bind(camera, error)) return false;
  gl.glUniform1ui(gl.glGetUniformLocation(m.program, "fftessPatchCount"), static_cast<GLuint>(n));
  m.words.assign(n * 7, 0);
  gl.glBindBuffer(GL_SHADER_STORAGE_BUFFER, m.levels);
  gl.glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * 7 * 4), m.words.data());
  gl.glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(m.ssboBinding), m.levels);
  gl.glBindFramebuffer(GL_FRAMEBUFFER, m.framebuffer);
  gl.glBindVertexArray(m.vertexArray);
  gl.glEnable(GL_RASTERIZER_DISCARD);
  gl.glPatchParameteri(GL_PATCH_VERTICES, m.controlPoints);
  const GLint base = gl.glGetUniformLocation(m.program, "fftessPatchBase");
  for (size_t first = 0; first < n; first += kPatchesPerDraw) {
    const size_t count = std::min(kPatchesPerDraw, n - first);
    gl.glUniform1ui(base, static_cast<GLuint>(first));
    gl.glDrawArrays(GL_PATCHES, static_cast<GLint>(first * static_cast<size_t>(m.controlPoints)),
                    static_cast<GLsizei>(count * static_cast<size_t>(m.controlPoints)));
  }
  gl.glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  gl.glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(n * 7 * 4), m.words.data());
  if (!gltest::checkGl(gl, "the hull shader's draw", error)) return false;
  out.assign(n, lod::PatchLod{});
  for (size_t i = 0; i < n; ++i) {
    if (m.words[n * 6 + i] != 1u) {
      error = "the hull shader's levels of patch " + std::to_string(i) + " were not recorded (its invocation 0 did "
              "not reach the end of main)";
      return false;
    }
    lod::PatchLod& r = out[i];
    // lod::Scheme has no "shader": what the compute path reports for lod.scheme = "shader" (gpu_lod.cpp lodScheme).
    r.why.scheme = lod::Scheme::ScreenSphere;
    for (int k = 0; k < 6; ++k) {
      const float f = floatOf(m.words[i * 6 + static_cast<size_t>(k)]);
      const int t = m.targets[static_cast<size_t>(k)];
      r.factors[t] = f;
      r.why.factor[t].unclamped = f;
      r.why.factor[t].metric = 0;
    }
    r.why.culled = false;
  }
  return true;
}

} // namespace fftess::gpulod::hull
