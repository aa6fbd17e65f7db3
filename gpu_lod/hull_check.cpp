// gpu_lod/hull.h front end: the evaluation / domain shader's domain and partitioning, and the scene against what the
// hull shader declares and uses (one diagnostic per problem, saying what to add or change).
#include "gpu_lod/hull_front.h"
#include "tessellator/names.h"

#include <regex>

namespace fftess::gpulod::hull {

namespace {

// The partitioning as the file's language spells it (GLSL layout qualifier / HLSL attribute).
std::string spelled(Partitioning p, const std::string& file) {
  if (languageOf(file) == Language::Hlsl) return "[partitioning(\"" + std::string(toString(p)) + "\")]";
  switch (p) {
  case Partitioning::Integer: return "layout(equal_spacing)";
  case Partitioning::FractionalOdd: return "layout(fractional_odd_spacing)";
  case Partitioning::FractionalEven: return "layout(fractional_even_spacing)";
  default: return "pow2";
  }
}

// "file:line:col" of p (as formatDiagnostic writes it).
std::string placeOf(const SourcePos& p) {
  const std::string d = formatDiagnostic({p, ""});
  return d.substr(0, d.rfind(": error: "));
}

struct Found {
  Domain domain = Domain::Unknown;
  SourcePos domainAt;
  std::optional<Partitioning> partitioning;
  SourcePos partitioningAt;
};

Domain domainNamed(const std::string& s) {
  if (s == "quads" || s == "quad") return Domain::Quad;
  if (s == "triangles" || s == "tri") return Domain::Tri;
  if (s == "isolines" || s == "isoline") return Domain::Isoline;
  return Domain::Unknown;
}

// GLSL: layout(quads, fractional_odd_spacing, ...) in; (equal_spacing when the domain is given without a spacing).
void readGlslLayout(const std::string& file, const std::string& original, Found& f) {
  const std::string text = detail::blankComments(original);
  static const std::regex layout(R"(layout\s*\(([^)]*)\)\s*in\s*;)");
  static const std::regex word(R"(\w+)");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), layout); it != std::sregex_iterator(); ++it) {
    const std::string args = (*it)[1];
    const size_t base = static_cast<size_t>(it->position(1));
    for (auto w = std::sregex_iterator(args.begin(), args.end(), word); w != std::sregex_iterator(); ++w) {
      const std::string t = w->str();
      const SourcePos at = detail::positionOf(file, original, base + static_cast<size_t>(w->position()));
      if (domainNamed(t) != Domain::Unknown) {
        f.domain = domainNamed(t);
        f.domainAt = at;
      } else if (t == "equal_spacing" || t == "fractional_odd_spacing" || t == "fractional_even_spacing") {
        f.partitioning = t == "equal_spacing"            ? Partitioning::Integer
                         : t == "fractional_odd_spacing" ? Partitioning::FractionalOdd
                                                         : Partitioning::FractionalEven;
        f.partitioningAt = at;
      }
    }
  }
  if (f.domain != Domain::Unknown && !f.partitioning) {
    f.partitioning = Partitioning::Integer; // GLSL's default spacing
    f.partitioningAt = f.domainAt;
  }
}

// HLSL: [domain("quad")] (the domain shader's, or the first), [partitioning("...")] (the hull shader's).
void readHlslAttributes(const std::string& file, const std::string& original, Found& f) {
  const std::string text = detail::blankComments(original);
  static const std::regex attr(R"re(\[\s*(domain|partitioning)\s*\(\s*"(\w+)"\s*\)\s*\])re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), attr); it != std::sregex_iterator(); ++it) {
    const SourcePos at = detail::positionOf(file, original, static_cast<size_t>(it->position()));
    Partitioning p{};
    if ((*it)[1] == "domain" && f.domain == Domain::Unknown) {
      f.domain = domainNamed((*it)[2]);
      f.domainAt = at;
    } else if ((*it)[1] == "partitioning" && !f.partitioning && parsePartitioning(std::string((*it)[2]).c_str(), p)) {
      f.partitioning = p;
      f.partitioningAt = at;
    }
  }
}

const char* domainName(Domain d) {
  return d == Domain::Quad ? "quad" : d == Domain::Tri ? "tri" : d == Domain::Isoline ? "isoline" : "?";
}

} // namespace

bool readEvaluationShader(const std::string& file, HullProgram& program, std::vector<Diagnostic>& errors) {
  std::string text;
  if (!detail::readFile(file, text)) {
    errors.push_back(detail::inFile(file, "cannot read the evaluation shader (lod.evaluation_shader)"));
    return false;
  }
  Found f;
  if (languageOf(file) == Language::Hlsl) readHlslAttributes(file, text, f);
  else readGlslLayout(file, text, f);
  const size_t before = errors.size();
  if (f.domain == Domain::Unknown)
    errors.push_back(
        detail::inFile(file, "no domain found: expected layout(quads, ...) in; (GLSL) or [domain(\"quad\")] (HLSL)"));
  else if (program.domain == Domain::Unknown) {
    program.domain = f.domain;
    program.domainAt = f.domainAt;
  } else if (program.domain != f.domain) {
    errors.push_back({f.domainAt, std::string("the evaluation shader's domain is ") + domainName(f.domain) +
                                      ", the hull shader's " + domainName(program.domain) + " (" +
                                      placeOf(program.domainAt) + "): make them agree"});
  }
  if (f.partitioning && !program.partitioning) {
    program.partitioning = f.partitioning;
    program.partitioningAt = f.partitioningAt;
  } else if (f.partitioning && *f.partitioning != *program.partitioning) {
    errors.push_back({f.partitioningAt, spelled(*f.partitioning, file) + " contradicts the hull shader's " +
                                            spelled(*program.partitioning, program.partitioningAt.file) + " (" +
                                            placeOf(program.partitioningAt) + "): make them agree"});
  }
  return errors.size() == before;
}

namespace {

template <typename Names> std::string joined(const Names& names) {
  std::string out;
  for (const char* n : names)
    out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

const verify::UniformBinding* bindingOf(const verify::Scene& scene, const Resource& r) {
  for (const verify::UniformBinding& b : scene.lod.uniforms)
    if (b.name == r.name || (!r.block.empty() && b.name == r.block + "." + r.name)) return &b;
  return nullptr;
}

// What the resource is called in the message: GLSL uniform / uniform block member / sampler; HLSL global /
// cbuffer member / texture.
std::string described(const Resource& r, Language lang) {
  const bool hlsl = lang == Language::Hlsl;
  switch (r.kind) {
  case Resource::Kind::Sampler: return (hlsl ? "texture '" : "sampler '") + r.name + "'";
  case Resource::Kind::BlockMember:
    if (hlsl && r.block == "$Global") return "global '" + r.name + "'";
    return "member '" + r.name + "' of " + (hlsl ? "cbuffer '" : "uniform block '") + r.block + "'";
  default: return "uniform '" + r.name + "'";
  }
}

void checkResource(const HullProgram& p, const verify::Scene& scene, const Resource& r,
                   std::vector<Diagnostic>& errors) {
  const SourcePos at = r.declared.line > 0 ? r.declared : SourcePos{p.file, 0, 0};
  if (r.storage) { // a storage buffer would read what nothing wrote: refused, not bound
    errors.push_back({at, "member '" + r.name + "' of storage buffer '" + r.block + "': fftess binds uniforms, uniform "
                              "blocks / cbuffers and the heightmap, not storage buffers (the shader would read data "
                              "fftess does not have; pass it as a uniform array to check this shader)"});
    return;
  }
  const verify::UniformBinding* b = bindingOf(scene, r);
  const bool sampler = r.kind == Resource::Kind::Sampler;
  const std::string key = r.block.empty() || r.block == "$Global" ? r.name : r.name + "' or '" + r.block + "." + r.name;
  if (!b && sampler)
    errors.push_back(
        {at, described(r, p.language) + " is not bound: add " + r.name +
                 " = \"heightmap\" to [lod.uniforms] (the scene's heightmap is the texture fftess binds)"});
  else if (!b)
    errors.push_back(
        {at, described(r, p.language) + " is not bound: add '" + key +
                 "' to [lod.uniforms] (a number, an array, or one of: " + joined(verify::kLodUniformValues) + ")"});
  else if (sampler && b->value != "heightmap")
    errors.push_back({at, described(r, p.language) + " is bound to " +
                              (b->value.empty() ? std::string("numbers") : "'" + b->value + "'") +
                              " in [lod.uniforms]: a sampler takes \"heightmap\""});
  else if (!sampler && b->value == "heightmap")
    errors.push_back({at, described(r, p.language) + " is bound to \"heightmap\" in [lod.uniforms], which only a " +
                              "sampler / texture takes"});
}

void checkInput(const HullProgram& p, const verify::Scene& scene, const Input& in, std::vector<Diagnostic>& errors) {
  if (in.builtin) return; // gl_Position / SV_Position: the input bound to "gl_Position", else "position"
  for (const verify::InputBinding& b : scene.lod.inputs)
    if (b.name == in.name || b.name == in.glslName || (!in.semantic.empty() && b.name == in.semantic)) return;
  const SourcePos at = in.declared.line > 0 ? in.declared : SourcePos{p.file, 0, 0};
  errors.push_back({at, "input '" + in.name + "'" + (in.semantic.empty() ? "" : " (" + in.semantic + ")") +
                            " is not bound: add it to [lod.inputs] (one of: " + joined(verify::kLodInputValues) + ", or a constant)"});
}

void checkPatch(const HullProgram& p, const verify::Scene& scene, std::vector<Diagnostic>& errors) {
  if (p.inputControlPoints > 0 && p.inputControlPoints != scene.lod.controlPoints)
    errors.push_back({p.inputControlPointsAt.line > 0 ? p.inputControlPointsAt : SourcePos{p.file, 0, 0},
                      "the hull shader takes " + std::to_string(p.inputControlPoints) +
                          " control points, the scene's lod.control_points is " +
                          std::to_string(scene.lod.controlPoints) +
                          ": set lod.control_points = " + std::to_string(p.inputControlPoints)});
  if (p.domain != Domain::Unknown && p.domain != Domain::Quad)
    errors.push_back({p.domainAt, std::string("the domain is ") + domainName(p.domain) +
                                      ": fftess verifies quad patches (a terrain's tiles)"});
  if (p.partitioning && *p.partitioning != scene.partitioning)
    errors.push_back({p.partitioningAt, spelled(*p.partitioning, p.partitioningAt.file) +
                                            " contradicts the scene's tessellation.partitioning = \"" +
                                            toString(scene.partitioning) + "\": set tessellation.partitioning = \"" +
                                            toString(*p.partitioning) + "\""});
}

} // namespace

bool checkAgainstScene(const HullProgram& program, const verify::Scene& scene, std::vector<Diagnostic>& errors) {
  const size_t before = errors.size();
  checkPatch(program, scene, errors);
  for (const Resource& r : program.resources)
    checkResource(program, scene, r, errors);
  for (const Input& in : program.inputs)
    checkInput(program, scene, in, errors);
  return errors.size() == before;
}

} // namespace fftess::gpulod::hull
