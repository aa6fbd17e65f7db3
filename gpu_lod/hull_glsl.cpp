// gpu_lod/hull.h front end: a GLSL tessellation control shader through glslang (the library): its diagnostics, the
// text the driver compiles (#include expanded, `#line L S`), what it uses (glslang's reflection). compileHull.
#include "gpu_lod/hull_front.h"

#include <glslang/Include/Types.h>
#include <glslang/MachineIndependent/localintermediate.h>

#include <algorithm>
#include <regex>
#include <sstream>
#include <tuple>

namespace fftess::gpulod::hull {
namespace detail {

namespace {

const std::regex kInclude(R"(^\s*#\s*include\s*["<]([^">]+)[">].*$)");
const std::regex kIncludeExtension(R"(^\s*#\s*extension\s+GL_GOOGLE_(include|cpp_style_line)_directive\b.*$)");

// Vulkan GLSL's descriptor sets (`layout(set = 0, binding = 1)`, as Vulkan samples write their TCS) are not OpenGL
// GLSL: `set = N` is blanked with spaces (columns stay; Vulkan GLSL always has a binding beside it, so the layout is
// not left empty). fftess binds by name, so the binding does not matter either.
std::string withoutDescriptorSets(const std::string& line) {
  static const std::regex layout(R"(layout\s*\(([^)]*)\))");
  static const std::regex set(R"(\bset\s*=\s*\d+\s*(,\s*)?)");
  std::string out = line;
  for (auto it = std::sregex_iterator(line.begin(), line.end(), layout); it != std::sregex_iterator(); ++it) {
    const std::string args = (*it)[1];
    for (auto s = std::sregex_iterator(args.begin(), args.end(), set); s != std::sregex_iterator(); ++s)
      out.replace(static_cast<size_t>(it->position(1) + s->position()), static_cast<size_t>(s->length()),
                  static_cast<size_t>(s->length()), ' ');
  }
  return out;
}

// `text` (file `file`) with each #include line replaced by `#line 1 S`, the included text, `#line L+1 P`; the
// GL_GOOGLE_include_directive extension lines blanked (drivers do not know them). Line numbers stay the user's.
// Files not found were reported by glslang already.
} // namespace

std::string expandIncludes(const std::string& file, const std::string& text, SourceSet& sources, int depth) {
  const int self = sources.add(file, text);
  std::string out;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  std::smatch m;
  while (std::getline(in, line)) {
    ++n;
    std::string body;
    if (std::regex_match(line, kIncludeExtension)) {
      line.clear();
    } else if (depth < 32 && std::regex_match(line, m, kInclude) && readFile(resolveInclude(m[1], file), body)) {
      const std::string path = resolveInclude(m[1], file);
      const int s = sources.add(path, body);
      out += "#line 1 " + std::to_string(s) + "\n" + expandIncludes(path, body, sources, depth + 1);
      if (!out.empty() && out.back() != '\n') out += '\n';
      line = "#line " + std::to_string(n + 1) + " " + std::to_string(self);
    }
    out += withoutDescriptorSets(line) + "\n";
  }
  return out;
}

namespace {

int componentsOf(const glslang::TType& t) {
  if (t.isMatrix()) return t.getMatrixCols() * t.getMatrixRows();
  return t.getVectorSize() > 0 ? t.getVectorSize() : 1;
}

// Per-control-point inputs the TCS reads: glslang's pipe inputs (blocks unwrapped into "Block.member"), gl_in's
// gl_Position as a builtin.
void reflectGlslInputs(glslang::TProgram& program, const std::string& glsl, const SourceSet& sources,
                       std::vector<Input>& out) {
  for (int i = 0; i < program.getNumPipeInputs(); ++i) {
    const glslang::TObjectReflection& r = program.getPipeInput(i);
    Input in;
    const size_t dot = r.name.rfind('.');
    in.name = dot == std::string::npos ? r.name : r.name.substr(dot + 1);
    in.glslName = r.name;
    in.builtin = r.name.rfind("gl_", 0) == 0 || in.name.rfind("gl_", 0) == 0;
    if (in.builtin && in.name != "gl_Position") continue; // gl_PrimitiveID, gl_InvocationID: not fed by fftess
    if (in.builtin) in.glslName = "gl_Position";
    const glslang::TType* t = r.getType();
    if (t && t->getQualifier().hasLocation()) in.location = static_cast<int>(t->getQualifier().layoutLocation);
    if (t) in.components = componentsOf(*t);
    if (!in.builtin) in.declared = findDeclaration(sources, in.name, "");
    out.push_back(in);
  }
  if (std::regex_search(glsl, std::regex(R"(\bgl_in\s*\[[^\]]*\]\s*\.\s*gl_Position\b)")) &&
      std::none_of(out.begin(), out.end(), [](const Input& i) { return i.name == "gl_Position"; })) {
    Input in;
    in.name = in.glslName = "gl_Position";
    in.builtin = true;
    out.push_back(in);
  }
}

} // namespace

void reflectResources(glslang::TProgram& program, const SourceSet& sources, bool hlsl, std::vector<Resource>& out) {
  for (int i = 0; i < program.getNumUniformVariables(); ++i) {
    const glslang::TObjectReflection& u = program.getUniform(i);
    const glslang::TType* t = u.getType();
    Resource r;
    r.name = u.name;
    if (t && t->getBasicType() == glslang::EbtSampler) {
      if (t->getSampler().isPureSampler()) continue; // HLSL SamplerState: the texture names the combined sampler
      r.kind = Resource::Kind::Sampler;
    }
    if (u.index >= 0) {
      r.kind = Resource::Kind::BlockMember;
      r.block = program.getUniformBlock(u.index).name;
      const glslang::TType* bt = program.getUniformBlock(u.index).getType();
      r.storage = bt && bt->getQualifier().storage == glslang::EvqBuffer;
      r.glslBlock = r.block;
      for (char& c : r.glslBlock) // SPIRV-Cross's names: [A-Za-z0-9_]
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
      const size_t dot = r.name.find('.');
      if (dot != std::string::npos && r.name.compare(0, dot, r.block) == 0) r.name = r.name.substr(dot + 1);
    }
    const size_t bracket = r.name.find('[');
    if (bracket != std::string::npos) r.name = r.name.substr(0, bracket);
    const size_t dot = r.name.find('.'); // a struct member: the scene binds the whole uniform
    const std::string declName = dot == std::string::npos ? r.name : r.name.substr(0, dot);
    const bool member = r.kind == Resource::Kind::BlockMember;
    r.declared = findDeclaration(sources, declName, hlsl || member ? "" : "uniform",
                                 member && r.block != "$Global" ? r.block : "");
    out.push_back(r);
  }
  // In the order of the user's files (glslang's reflection order is its own).
  const auto rank = [&sources](const SourcePos& p) {
    const auto f = std::find(sources.files.begin(), sources.files.end(), p.file);
    return std::make_tuple(f - sources.files.begin(), p.line, p.column);
  };
  std::stable_sort(out.begin(), out.end(),
                   [&](const Resource& a, const Resource& b) { return rank(a.declared) < rank(b.declared); });
}

bool compileGlsl(const std::string& file, HullProgram& out, std::vector<Diagnostic>& errors) {
  SourceSet sources;
  MainSource main;
  if (!main.read(file, sources, errors)) return false;
  const std::string& text = main.text;
  if (!std::regex_search(blankComments(text), std::regex(R"((^|\n)\s*#\s*version\b)"))) {
    // glslang would take its default version; the driver would take GLSL 1.10, which has no tessellation stage
    errors.push_back(inFile(file, "no #version line: a tessellation control shader needs #version 400 or later "
                                  "(add #version 450 as the first line)"));
    errors.back().at.line = errors.back().at.column = 1;
    return false;
  }
  glslang::TShader shader(EShLangTessControl);
  main.attach(shader);
  // fftess turns glslang's include support on itself (a preamble: the user's line numbers stay).
  shader.setPreamble("#extension GL_GOOGLE_include_directive : enable\n");
  // OpenGL GLSL; glslang accepts Vulkan's layout(set = N, binding = M) there (the driver gets it without the set).
  shader.setEnvInput(glslang::EShSourceGlsl, EShLangTessControl, glslang::EShClientNone, 0);
  // The driver's text first: a failed parse keeps it (hull::fillColumnsFromDriver compiles it for the columns).
  out.language = Language::Glsl;
  out.file = file;
  out.entry = "main";
  SourceSet expanded;
  out.glsl = expandIncludes(file, text, expanded, 0);
  out.sourceFiles = expanded.files;
  glslang::TProgram program;
  if (!parseAndLink(shader, program, sources, EShMsgCascadingErrors, 450, ECoreProfile, errors)) return false;
  program.buildReflection(EShReflectionIntermediateIO | EShReflectionUnwrapIOBlocks);
  out.outputControlPoints = shader.getIntermediate()->getVertices();
  reflectResources(program, sources, false, out.resources);
  reflectGlslInputs(program, out.glsl, sources, out.inputs);
  return true;
}

} // namespace detail

bool compileHull(const std::string& file, const std::string& entry, HullProgram& out, std::vector<Diagnostic>& errors) {
  out = HullProgram{};
  errors.clear();
  return languageOf(file) == Language::Hlsl ? detail::compileHlsl(file, entry, out, errors)
                                            : detail::compileGlsl(file, out, errors);
}

} // namespace fftess::gpulod::hull
