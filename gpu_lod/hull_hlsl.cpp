// gpu_lod/hull.h front end: an HLSL hull shader through glslang's HLSL front end (the library) -> SPIR-V ->
// SPIRV-Cross (C API) -> the GLSL 4.50 TCS the driver compiles; its attributes, InputPatch and inputs from the text.
//
// What glslang and SPIRV-Cross make of a hull shader (checked with tests/gpu_lod/data/hull.hlsl through this file;
// test_gpu_lod_hull_front compares the end of the GLSL): glslang writes a wrapper main() that calls the control-point
// function for gl_InvocationID, stores its output, then `barrier()`, and `if (gl_InvocationID == 0)` calls the
// patch-constant function and copies SV_TessFactor[i] -> gl_TessLevelOuter[i] (i = 0..3) and SV_InsideTessFactor[j] ->
// gl_TessLevelInner[j] (j = 0..1) for [domain("quad")], element by element in the same order (no permutation);
// main has no `return`. SPIRV-Cross keeps that shape (docs/gpu_lod.md "Hull shaders as written: the front end").
// Its uniform blocks: cbuffers by their name, globals in "_Global" (glslang's "$Global"), both may say binding = 0
// (the driver half assigns block bindings itself); float4x4 members are layout(row_major).
#include "gpu_lod/hull_front.h"

#include <glslang/Include/Types.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <spirv_cross/spirv_cross_c.h>

#include <algorithm>
#include <regex>

namespace fftess::gpulod::hull::detail {

namespace {

struct Attribute {
  std::string name, argument;
  SourcePos at;
};

struct Function {
  std::string name;
  SourcePos at;
  std::vector<Attribute> attributes;
  size_t paramsAt = 0; // offset of '(' in the text
};

// Every function definition of the (comment-blanked) text with the attributes in front of it.
std::vector<Function> functionsOf(const std::string& file, const std::string& original) {
  const std::string text = blankComments(original);
  static const std::regex fn(R"(((?:\[\s*\w+\s*(?:\([^\]]*\))?\s*\]\s*)*)\b(\w+)\s+(\w+)\s*\()");
  static const std::regex attr(R"re(\[\s*(\w+)\s*(?:\(\s*"?([^"\)]*)"?\s*\))?\s*\])re");
  std::vector<Function> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), fn); it != std::sregex_iterator(); ++it) {
    const std::smatch& m = *it;
    const std::string ret = m[2];
    if (ret == "return" || ret == "else" || ret == "new") continue;
    Function f;
    f.name = m[3];
    f.at = positionOf(file, original, static_cast<size_t>(m.position(3)));
    f.paramsAt = static_cast<size_t>(m.position(0) + m.length(0) - 1);
    // only definitions: the parameter list is followed by '{' (or ': SEMANTIC {')
    const size_t close = text.find(')', f.paramsAt);
    if (close == std::string::npos) continue;
    const size_t next = text.find_first_not_of(" \t\r\n", close + 1);
    if (next == std::string::npos || (text[next] != '{' && text[next] != ':')) continue;
    const std::string attrs = m[1];
    const size_t base = static_cast<size_t>(m.position(1));
    for (auto a = std::sregex_iterator(attrs.begin(), attrs.end(), attr); a != std::sregex_iterator(); ++a)
      f.attributes.push_back(
          {(*a)[1], (*a)[2], positionOf(file, original, base + static_cast<size_t>(a->position(0)))});
    out.push_back(f);
  }
  return out;
}

const Attribute* attributeOf(const Function& f, const std::string& name) {
  for (const Attribute& a : f.attributes)
    if (a.name == name) return &a;
  return nullptr;
}

// The hull shader function: lod.entry, or the only function with [patchconstantfunc].
const Function* findEntry(const std::string& file, const std::vector<Function>& fns, const std::string& entry,
                          std::vector<Diagnostic>& errors) {
  std::string hulls;
  const Function* only = nullptr;
  int count = 0;
  for (const Function& f : fns)
    if (attributeOf(f, "patchconstantfunc")) {
      hulls += (count++ ? ", " : "") + f.name;
      only = &f;
    }
  if (entry.empty()) {
    if (count == 1) return only;
    errors.push_back(inFile(file, count == 0 ? "no hull shader: no function has a [patchconstantfunc(...)] attribute"
                                             : "several hull shaders (" + hulls + "): name one in lod.entry"));
    return nullptr;
  }
  for (const Function& f : fns) {
    if (f.name != entry) continue;
    if (attributeOf(f, "patchconstantfunc")) return &f;
    errors.push_back({f.at, "lod.entry '" + entry + "' is not a hull shader (no [patchconstantfunc(...)] attribute)" +
                                (hulls.empty() ? std::string() : ": the hull shaders here: " + hulls)});
    return nullptr;
  }
  errors.push_back(inFile(file, "lod.entry '" + entry + "' names no function in this file" +
                                    (hulls.empty() ? std::string() : " (hull shaders here: " + hulls + ")")));
  return nullptr;
}

void readAttributes(const Function& f, HullProgram& out, std::vector<Diagnostic>& errors) {
  if (const Attribute* a = attributeOf(f, "domain")) {
    out.domainAt = a->at;
    out.domain = a->argument == "quad"      ? Domain::Quad
                 : a->argument == "tri"     ? Domain::Tri
                 : a->argument == "isoline" ? Domain::Isoline
                                            : Domain::Unknown;
    if (out.domain == Domain::Unknown)
      errors.push_back({a->at, "[domain(\"" + a->argument + "\")]: expected \"quad\", \"tri\" or \"isoline\""});
  }
  if (const Attribute* a = attributeOf(f, "partitioning")) {
    out.partitioningAt = a->at;
    const std::string& p = a->argument;
    if (p == "integer") out.partitioning = Partitioning::Integer;
    else if (p == "pow2") out.partitioning = Partitioning::Pow2;
    else if (p == "fractional_odd") out.partitioning = Partitioning::FractionalOdd;
    else if (p == "fractional_even") out.partitioning = Partitioning::FractionalEven;
    else
      errors.push_back({a->at, "[partitioning(\"" + p +
                                   "\")]: expected \"integer\", \"pow2\", \"fractional_odd\" or "
                                   "\"fractional_even\""});
  }
  if (const Attribute* a = attributeOf(f, "outputcontrolpoints"))
    out.outputControlPoints = std::atoi(a->argument.c_str());
  if (const Attribute* a = attributeOf(f, "maxtessfactor")) {
    out.maxTessFactor = std::strtof(a->argument.c_str(), nullptr);
    out.maxTessFactorAt = a->at;
  }
  if (const Attribute* a = attributeOf(f, "patchconstantfunc")) out.patchConstantFunction = a->argument;
}

// SPIR-V -> GLSL 4.50 core: combined image samplers named after the HLSL texture; stage inputs' locations.
bool crossCompile(const std::vector<unsigned>& spirv, HullProgram& out, std::vector<std::pair<std::string, int>>& locs,
                  std::string& error) {
  spvc_context ctx = nullptr;
  if (spvc_context_create(&ctx) != SPVC_SUCCESS) return false;
  spvc_parsed_ir ir = nullptr;
  spvc_compiler comp = nullptr;
  spvc_compiler_options opts = nullptr;
  const char* glsl = nullptr;
  bool ok = spvc_context_parse_spirv(ctx, spirv.data(), spirv.size(), &ir) == SPVC_SUCCESS &&
            spvc_context_create_compiler(ctx, SPVC_BACKEND_GLSL, ir, SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &comp) ==
                SPVC_SUCCESS &&
            spvc_compiler_create_compiler_options(comp, &opts) == SPVC_SUCCESS;
  if (ok) {
    spvc_compiler_options_set_uint(opts, SPVC_COMPILER_OPTION_GLSL_VERSION, 450);
    spvc_compiler_options_set_bool(opts, SPVC_COMPILER_OPTION_GLSL_ES, SPVC_FALSE);
    spvc_compiler_options_set_bool(opts, SPVC_COMPILER_OPTION_GLSL_VULKAN_SEMANTICS, SPVC_FALSE);
    spvc_compiler_install_compiler_options(comp, opts);
    ok = spvc_compiler_build_combined_image_samplers(comp) == SPVC_SUCCESS;
  }
  const spvc_combined_image_sampler* samplers = nullptr;
  size_t count = 0;
  if (ok) spvc_compiler_get_combined_image_samplers(comp, &samplers, &count);
  for (size_t i = 0; ok && i < count; ++i)
    spvc_compiler_set_name(comp, samplers[i].combined_id, spvc_compiler_get_name(comp, samplers[i].image_id));
  spvc_resources res = nullptr;
  const spvc_reflected_resource* list = nullptr;
  if (ok && spvc_compiler_create_shader_resources(comp, &res) == SPVC_SUCCESS &&
      spvc_resources_get_resource_list_for_type(res, SPVC_RESOURCE_TYPE_STAGE_INPUT, &list, &count) == SPVC_SUCCESS)
    for (size_t i = 0; i < count; ++i)
      locs.emplace_back(list[i].name,
                        static_cast<int>(spvc_compiler_get_decoration(comp, list[i].id, SpvDecorationLocation)));
  ok = ok && spvc_compiler_compile(comp, &glsl) == SPVC_SUCCESS;
  if (ok) out.glsl = glsl;
  else error = spvc_context_get_last_error_string(ctx);
  spvc_context_destroy(ctx);
  return ok;
}

int componentsOfHlsl(const std::string& type) {
  std::smatch m;
  if (std::regex_match(type, m, std::regex(R"((?:float|half|int|uint|min16float)([1-4])?)")))
    return m[1].matched ? std::stoi(m[1]) : 1;
  return 4;
}

// The members of `struct T { ... }` (name, semantic, type) as inputs, from whichever of the user's files declares it.
void readStructInputs(const SourceSet& sources, const std::string& type, HullProgram& out) {
  static const std::regex member(R"((\w+)\s+(\w+)\s*:\s*(\w+)\s*;)");
  for (size_t f = 0; f < sources.files.size(); ++f) {
    const std::string text = blankComments(sources.texts[f]);
    std::smatch st;
    if (!std::regex_search(text, st, std::regex("\\bstruct\\s+" + type + "\\s*\\{([^}]*)\\}"))) continue;
    const std::string body = st[1];
    const size_t base = static_cast<size_t>(st.position(1));
    for (auto it = std::sregex_iterator(body.begin(), body.end(), member); it != std::sregex_iterator(); ++it) {
      Input in;
      in.name = (*it)[2];
      in.semantic = (*it)[3];
      in.components = componentsOfHlsl((*it)[1]);
      in.builtin = in.semantic == "SV_Position" || in.semantic == "SV_POSITION";
      if (in.builtin) in.glslName = "gl_Position";
      in.declared = positionOf(sources.files[f], sources.texts[f], base + static_cast<size_t>(it->position(2)));
      out.inputs.push_back(in);
    }
    return;
  }
}

// InputPatch<T, N> of the entry's parameters: N, and T's members as the inputs.
void readInputPatch(const SourceSet& sources, const Function& entry, HullProgram& out) {
  const std::string& original = *sources.textOf(entry.at.file);
  const std::string text = blankComments(original);
  const std::string params = text.substr(entry.paramsAt, text.find(')', entry.paramsAt) - entry.paramsAt);
  std::smatch m;
  if (!std::regex_search(params, m, std::regex(R"(InputPatch\s*<\s*(\w+)\s*,\s*(\d+)\s*>)"))) return;
  out.inputControlPoints = std::stoi(m[2]);
  out.inputControlPointsAt =
      positionOf(entry.at.file, original, entry.paramsAt + static_cast<size_t>(m.position(0)));
  readStructInputs(sources, m[1], out);
}

// The SPIR-V stage inputs (names and locations) matched to the struct members: glslang names the flattened input
// "<param>.<member>", SPIRV-Cross writes it "<param>_<member>" (every character not [A-Za-z0-9_] becomes '_').
void matchInputLocations(const std::vector<std::pair<std::string, int>>& locs, HullProgram& out) {
  for (Input& in : out.inputs) {
    if (in.builtin) continue;
    for (const auto& [name, loc] : locs) {
      std::string glsl = name;
      for (char& c : glsl)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') c = '_';
      const std::string tail = "_" + in.name;
      if (glsl == in.name ||
          (glsl.size() > tail.size() && glsl.compare(glsl.size() - tail.size(), tail.size(), tail) == 0)) {
        in.glslName = glsl;
        in.location = loc;
      }
    }
  }
}

} // namespace

bool compileHlsl(const std::string& file, const std::string& entryName, HullProgram& out,
                 std::vector<Diagnostic>& errors) {
  SourceSet sources;
  MainSource main;
  if (!main.read(file, sources, errors)) return false;
  const std::string& text = main.text;
  expandIncludes(file, text, sources, 0); // the #included files too: the functions may be there
  std::vector<Function> fns;
  for (size_t i = 0; i < sources.files.size(); ++i) {
    const std::vector<Function> more = functionsOf(sources.files[i], sources.texts[i]);
    fns.insert(fns.end(), more.begin(), more.end());
  }
  const Function* entry = findEntry(file, fns, entryName, errors);
  if (!entry) return false;
  out.language = Language::Hlsl;
  out.file = file;
  out.entry = entry->name;
  out.sourceFiles = {file};
  readAttributes(*entry, out, errors);
  if (!errors.empty()) return false;
  glslang::TShader shader(EShLangTessControl);
  // glslang knows no [partitioning("pow2")] (D3D's): it reads "integer" there; the factors do not depend on it (fftess
  // tessellates them with pow2) and the attribute's position and value are fftess's (readAttributes).
  if (out.partitioning == Partitioning::Pow2)
    main.text = std::regex_replace(main.text, std::regex(R"re((\[\s*partitioning\s*\(\s*")pow2("))re"), "$1integer$2");
  main.attach(shader);
  shader.setEntryPoint(out.entry.c_str());
  shader.setEnvInput(glslang::EShSourceHlsl, EShLangTessControl, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
  shader.setAutoMapLocations(true);
  shader.setAutoMapBindings(true);
  glslang::TProgram program;
  const EShMessages messages = static_cast<EShMessages>(EShMsgReadHlsl | EShMsgSpvRules | EShMsgVulkanRules);
  const size_t before = errors.size();
  if (!parseAndLink(shader, program, sources, messages, 100, ENoProfile, errors)) {
    // glslang says "'F' : patch constant function not found" without a place: the attribute's
    const Attribute* pcf = attributeOf(*entry, "patchconstantfunc");
    for (size_t i = before; i < errors.size(); ++i)
      if (errors[i].at.line == 0 && errors[i].message.find("patch constant function not found") != std::string::npos)
        errors[i].at = pcf->at;
    return false;
  }
  std::vector<unsigned> spirv;
  glslang::GlslangToSpv(*program.getIntermediate(EShLangTessControl), spirv);
  std::vector<std::pair<std::string, int>> locs;
  std::string error;
  if (!crossCompile(spirv, out, locs, error)) {
    errors.push_back(inFile(file, "SPIRV-Cross could not translate glslang's SPIR-V to GLSL (fftess's problem, not "
                                  "the shader's): " +
                                      error));
    return false;
  }
  program.buildReflection();
  reflectResources(program, sources, true, out.resources);
  readInputPatch(sources, *entry, out);
  matchInputLocations(locs, out);
  return true;
}

} // namespace fftess::gpulod::hull::detail
