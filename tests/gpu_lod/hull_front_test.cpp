// gpu_lod/hull.h, the front end: the user's GLSL tessellation control shader / HLSL hull shader through glslang and
// SPIRV-Cross (libraries, no GL context), the diagnostics as file:line:col lines, what the shader uses, and the
// scene checked against it. Fixtures: tests/gpu_lod/data/<case>. And the named camera values a hull shader's uniforms
// get (hull_bind.h cameraValues) for GL and D3D cameras.
#include "gpu_lod/hull.h"
#include "gpu_lod/hull_bind.h"
#include "lod/lod.h"
#include "verify/scene.h"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <string>
#include <vector>

using namespace fftess;
using namespace fftess::gpulod::hull;
namespace hull = fftess::gpulod::hull;

namespace {

Diagnostic diag(const std::string& file, int line, int column, const std::string& message, bool warning = false) {
  Diagnostic d;
  d.at.file = file;
  d.at.line = line;
  d.at.column = column;
  d.message = message;
  d.warning = warning;
  return d;
}

std::string data(const std::string& f) { return std::string(FFTESS_HULL_DATA) + "/" + f; }

// The diagnostics of compiling `file` (entry "" = found), one string each.
std::vector<std::string> compileErrors(const std::string& file, const std::string& entry = "") {
  HullProgram p;
  std::vector<Diagnostic> errors;
  CHECK_FALSE(compileHull(data(file), entry, p, errors));
  std::vector<std::string> out;
  for (const Diagnostic& d : errors)
    out.push_back(formatDiagnostic(d));
  return out;
}

HullProgram compiled(const std::string& file, const std::string& entry = "") {
  HullProgram p;
  std::vector<Diagnostic> errors;
  const bool ok = compileHull(data(file), entry, p, errors);
  INFO(formatDiagnostics(errors));
  REQUIRE(ok);
  return p;
}

// Resources as "kind name [block] file:line:col" (file relative to the data folder).
std::vector<std::string> resourcesOf(const HullProgram& p) {
  static const char* kinds[] = {"uniform", "member", "sampler"};
  std::vector<std::string> out;
  for (const Resource& r : p.resources)
    out.push_back(std::string(kinds[static_cast<int>(r.kind)]) + " " + r.name +
                  (r.block.empty() ? "" : " [" + r.block + "]") + " " + r.declared.file.substr(data("").size()) + ":" +
                  std::to_string(r.declared.line) + ":" + std::to_string(r.declared.column));
  return out;
}

// Inputs as "name semantic glslName location components builtin".
std::vector<std::string> inputsOf(const HullProgram& p) {
  std::vector<std::string> out;
  for (const Input& i : p.inputs)
    out.push_back(i.name + " " + (i.semantic.empty() ? "-" : i.semantic) + " " + i.glslName + " " +
                  std::to_string(i.location) + " " + std::to_string(i.components) + (i.builtin ? " builtin" : ""));
  return out;
}

std::vector<std::string> sceneErrors(const HullProgram& p, const verify::Scene& scene) {
  std::vector<Diagnostic> errors;
  const bool ok = checkAgainstScene(p, scene, errors);
  CHECK(ok == errors.empty());
  std::vector<std::string> out;
  for (const Diagnostic& d : errors)
    out.push_back(formatDiagnostic(d));
  return out;
}

verify::UniformBinding bound(const std::string& name, const std::string& value = "") {
  verify::UniformBinding b;
  b.name = name;
  b.value = value;
  if (value.empty()) b.numbers = {1.0};
  return b;
}

verify::InputBinding input(const std::string& name, const std::string& value) {
  verify::InputBinding b;
  b.name = name;
  b.value = value;
  return b;
}

const std::string kValues = "(a number, an array, or one of: view, projection, view_projection, projection_d3d, "
                            "view_projection_d3d, world, eye, viewport, frustum_planes, frustum_planes_gl, "
                            "frustum_planes_d3d, near, far, fov_y, heightmap, height_scale, terrain_min, terrain_size, "
                            "patch_size, heightmap_size, heightmap_texel, projection_vulkan, view_projection_vulkan)";

} // namespace

TEST_CASE("A diagnostic prints as file:line:col, file:line, or fftess without a file") {
  CHECK(formatDiagnostic(diag("a.tesc", 3, 7, "bad")) == "a.tesc:3:7: error: bad");
  CHECK(formatDiagnostic(diag("a.tesc", 3, 0, "bad")) == "a.tesc:3: error: bad");
  CHECK(formatDiagnostic(diag("a.tesc", 0, 0, "bad")) == "a.tesc: error: bad");
  CHECK(formatDiagnostic(diag("", 0, 0, "bad")) == "fftess: error: bad");
  CHECK(formatDiagnostic(diag("a.fx", 1, 2, "odd", true)) == "a.fx:1:2: warning: odd");
  CHECK(formatDiagnostics({diag("a", 1, 1, "x"), diag("b", 2, 2, "y")}) == "a:1:1: error: x\nb:2:2: error: y");
}

TEST_CASE("Hull shaders are told from lodMain files by name and by text") {
  CHECK(isHullShader("t.tesc", "void main() {}"));
  CHECK(isHullShader("t.tesc.glsl", "void main() {}"));
  CHECK(isHullShader("t.glsl", "#version 450\nlayout (vertices = 4) out;\nvoid main() {}"));
  CHECK_FALSE(isHullShader("t.glsl", "#version 450\n// layout(vertices = 4) out;\nvoid main() {}"));
  CHECK_FALSE(isHullShader("t.glsl", "LodResult lodMain(LodPatch p) {}"));
  CHECK(isHullShader("t.hlsl", "[patchconstantfunc(\"P\")] H HS() {}"));
  CHECK(isHullShader("t.fx", "float4 VS() {}"));
  CHECK_FALSE(isHullShader("t.fx", "LodResult lodMain(LodPatch p) {}"));
  CHECK_FALSE(isHullShader("t.tesc", "layout(vertices = 4) out;\nLodResult lodMain(LodPatch p) {}"));
  CHECK(languageOf("a.hlsl") == Language::Hlsl);
  CHECK(languageOf("a.fx") == Language::Hlsl);
  CHECK(languageOf("a.tesc") == Language::Glsl);
}

TEST_CASE("A GLSL TCS with an include reaches the driver with line directives and lists what it uses") {
  const HullProgram p = compiled("uniforms.tesc");
  CHECK(p.language == Language::Glsl);
  CHECK(p.outputControlPoints == 4);
  CHECK(p.sourceFiles == std::vector<std::string>{data("uniforms.tesc"), data("includes/camera.glsl")});
  // the include replaced by `#line 1 1` + its text + `#line 7 0`; the extension line blanked (line numbers kept)
  CHECK(
      p.glsl.find("#line 1 1\n// The camera's uniforms, included by uniforms.tesc.\nuniform vec3 uEye;\n#line 7 0\n") !=
      std::string::npos);
  CHECK(p.glsl.find("GL_GOOGLE_include_directive") == std::string::npos);
  CHECK(p.glsl.rfind("#version 450\n\n// A distance TCS", 0) == 0);
  // used only: uUnused and notRead are left out
  CHECK(resourcesOf(p) == std::vector<std::string>{"uniform uMinTess uniforms.tesc:8:15",
                                                   "uniform uMaxTess uniforms.tesc:9:15",
                                                   "sampler uHeightMap uniforms.tesc:11:19",
                                                   "member heightScale [Terrain] uniforms.tesc:14:9",
                                                   "uniform uEye includes/camera.glsl:2:14"});
  CHECK(inputsOf(p) == std::vector<std::string>{"vUv - vUv -1 2", "gl_Position - gl_Position -1 4 builtin",
                                                "worldPos - Corner.worldPos -1 3"});
}

TEST_CASE("A Vulkan GLSL TCS reaches the driver without descriptor sets and with its columns") {
  const HullProgram p = compiled("vulkan_sets.tesc");
  CHECK(p.glsl.find("\nlayout(         binding = 0) uniform UBO\n") != std::string::npos);
  CHECK(p.glsl.find("\nlayout(         binding = 1) uniform sampler2D samplerHeight;\n") != std::string::npos);
  CHECK(p.glsl.find("set =") == std::string::npos);
  CHECK(resourcesOf(p) == std::vector<std::string>{"member frustumPlanes [UBO] vulkan_sets.tesc:7:7",
                                                   "member tessellationFactor [UBO] vulkan_sets.tesc:8:8",
                                                   "sampler samplerHeight vulkan_sets.tesc:11:48"});
  CHECK(inputsOf(p) == std::vector<std::string>{"inUV - inUV 1 2", "gl_Position - gl_Position -1 4 builtin",
                                                "inNormal - inNormal 0 3"});
}

TEST_CASE("A GLSL syntax error is a diagnostic at the user's line") {
  CHECK(compileErrors("syntax_error.tesc") ==
        std::vector<std::string>{data("syntax_error.tesc") +
                                 ":8: error: syntax error, unexpected IDENTIFIER, expecting COMMA or SEMICOLON"});
}

TEST_CASE("Each of glslang's errors is its own diagnostic line") {
  const std::string at = data("two_errors.tesc");
  // glslang quotes 'assign', which is not in the line: no column
  CHECK(compileErrors("two_errors.tesc") ==
        std::vector<std::string>{at + ":5:26: error: 'uFar' : undeclared identifier",
                                 at + ":6: error: 'assign' :  cannot convert from ' const 2-component vector of float' "
                                      "to ' patch temp float TessLevelOuter'"});
}

TEST_CASE("A GLSL TCS without a version line is a diagnostic at its first line") {
  CHECK(compileErrors("no_version.tesc") ==
        std::vector<std::string>{data("no_version.tesc") + ":1:1: error: no #version line: a tessellation control "
                                                           "shader needs #version 400 or later (add #version 450 as "
                                                           "the first line)"});
}

TEST_CASE("A GLSL include that is not found is a diagnostic at the include line") {
  CHECK(compileErrors("include_missing.tesc") ==
        std::vector<std::string>{data("include_missing.tesc") +
                                 ":5:1: error: '#include' : Could not process include directive for header name: "
                                 "includes/nowhere.glsl"});
}

TEST_CASE("An error in an included GLSL file is reported at that file's line") {
  CHECK(compileErrors("include_error.tesc") ==
        std::vector<std::string>{data("includes/broken.glsl") + ":3:10: error: 'uUndeclared' : undeclared identifier"});
}

TEST_CASE("An unbound uniform is an error at its declaration that names lod.uniforms") {
  const HullProgram p = compiled("unbound_uniform.tesc");
  verify::Scene scene;
  scene.lod.uniforms = {bound("gBound")};
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("unbound_uniform.tesc") +
                                 ":4:14: error: uniform 'gEyePosW' is not bound: add 'gEyePosW' "
                                 "to [lod.uniforms] " +
                                 kValues});
  scene.lod.uniforms.push_back(bound("gEyePosW", "eye"));
  CHECK(sceneErrors(p, scene).empty());
}

TEST_CASE("A missing sampler and a sampler bound to a number are errors at the sampler") {
  const HullProgram p = compiled("uniforms.tesc");
  verify::Scene scene;
  scene.lod.uniforms = {bound("uMinTess"), bound("uMaxTess"), bound("Terrain.heightScale", "height_scale"),
                        bound("uEye", "eye")};
  scene.lod.inputs = {input("vUv", "uv"), input("worldPos", "position")};
  const std::string at = data("uniforms.tesc") + ":11:19: error: sampler 'uHeightMap' is ";
  CHECK(sceneErrors(p, scene) == std::vector<std::string>{at + "not bound: add uHeightMap = \"heightmap\" to "
                                                               "[lod.uniforms] (the scene's heightmap is the texture "
                                                               "fftess binds)"});
  scene.lod.uniforms.push_back(bound("uHeightMap"));
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{at + "bound to numbers in [lod.uniforms]: a sampler takes \"heightmap\""});
  scene.lod.uniforms.back() = bound("uHeightMap", "heightmap");
  CHECK(sceneErrors(p, scene).empty());
}

TEST_CASE("An HLSL hull shader goes through glslang and SPIRV-Cross with its attributes, cbuffer, texture and inputs") {
  const HullProgram p = compiled("hull.hlsl");
  CHECK(p.language == Language::Hlsl);
  CHECK(p.entry == "HS");
  CHECK(p.patchConstantFunction == "ConstantHS");
  CHECK(p.domain == hull::Domain::Quad);
  CHECK(p.domainAt.line == 55);
  CHECK(p.partitioning == Partitioning::FractionalEven);
  CHECK(p.partitioningAt.line == 56);
  CHECK(p.partitioningAt.column == 1);
  CHECK(p.maxTessFactor == 64.0f);
  CHECK(p.maxTessFactorAt.line == 60);
  CHECK(p.outputControlPoints == 4);
  CHECK(p.inputControlPoints == 4);
  CHECK(p.inputControlPointsAt.line == 61);
  CHECK(p.inputControlPointsAt.column == 12);
  // used only: gViewProj, gUnusedMember and the SamplerState are left out
  CHECK(resourcesOf(p) == std::vector<std::string>{"member gEyePosW [cbPerFrame] hull.hlsl:5:10",
                                                   "member gMinDist [cbPerFrame] hull.hlsl:6:9",
                                                   "member gMaxDist [cbPerFrame] hull.hlsl:7:9",
                                                   "member gMaxTess [$Global] hull.hlsl:11:7",
                                                   "sampler gHeightMap hull.hlsl:12:11"});
  CHECK(p.resources[3].glslBlock == "_Global");
  CHECK(p.glsl.find("uniform _Global\n{\n    float gMaxTess;\n}") != std::string::npos);
  CHECK(p.resources[0].glslBlock == "cbPerFrame");
  CHECK(inputsOf(p) == std::vector<std::string>{"PosW POSITION p_PosW 0 3", "Tex TEXCOORD0 p_Tex 1 2",
                                                "BoundsY TEXCOORD1 p_BoundsY 2 2"});
  // SPIRV-Cross's GLSL: the combined sampler named after the texture; glslang's wrapper main: the control-point
  // function, barrier(), then invocation 0 runs the patch-constant function and copies SV_TessFactor[i] to
  // gl_TessLevelOuter[i], SV_InsideTessFactor[j] to gl_TessLevelInner[j]
  CHECK(p.glsl.rfind("#version 450\nlayout(vertices = 4) out;\n", 0) == 0);
  CHECK(p.glsl.find("uniform sampler2D gHeightMap;") != std::string::npos);
  CHECK(p.glsl.find("layout(location = 1) in vec2 p_Tex[];") != std::string::npos);
  const std::string tail = "    barrier();\n"
                           "    if (int(gl_InvocationID) == 0)\n"
                           "    {\n"
                           "        VertexOut param_3[4] = p;\n"
                           "        uint param_4 = uint(gl_PrimitiveID);\n"
                           "        PatchTess _patchConstantResult = ConstantHS(param_3, param_4);\n"
                           "        gl_TessLevelOuter[0] = _patchConstantResult.EdgeTess[0];\n"
                           "        gl_TessLevelOuter[1] = _patchConstantResult.EdgeTess[1];\n"
                           "        gl_TessLevelOuter[2] = _patchConstantResult.EdgeTess[2];\n"
                           "        gl_TessLevelOuter[3] = _patchConstantResult.EdgeTess[3];\n"
                           "        gl_TessLevelInner[0] = _patchConstantResult.InsideTess[0];\n"
                           "        gl_TessLevelInner[1] = _patchConstantResult.InsideTess[1];\n"
                           "    }\n"
                           "}\n\n";
  REQUIRE(p.glsl.size() > tail.size());
  CHECK(p.glsl.substr(p.glsl.size() - tail.size()) == tail);
  const std::string main = p.glsl.substr(p.glsl.find("void main()"));
  CHECK(main.find("return") == std::string::npos);
}

TEST_CASE("An HLSL cbuffer and input struct from an include are found in the included file") {
  const HullProgram p = compiled("include.hlsl");
  CHECK(resourcesOf(p) == std::vector<std::string>{"member gEyePosW [cbPerFrame] includes/common.hlsli:4:10"});
  CHECK(inputsOf(p) ==
        std::vector<std::string>{"PosH SV_Position gl_Position -1 4 builtin", "PosW POSITION p_PosW 0 3"});
  CHECK(p.inputs[1].declared.file == data("includes/common.hlsli"));
}

TEST_CASE("An HLSL hull shader defined in an included file is found there with its attributes") {
  const HullProgram p = compiled("hs_in_include.hlsl");
  CHECK(p.entry == "TerrainHS");
  CHECK(p.partitioning == Partitioning::FractionalOdd);
  const std::string hs = data("includes/terrain_hs.hlsli");
  CHECK(formatDiagnostic(diag(p.partitioningAt.file, p.partitioningAt.line, p.partitioningAt.column, "x")) ==
        hs + ":13:18: error: x");
  CHECK(formatDiagnostic(diag(p.inputControlPointsAt.file, p.inputControlPointsAt.line, p.inputControlPointsAt.column,
                              "x")) == hs + ":15:18: error: x");
  CHECK(resourcesOf(p) == std::vector<std::string>{"member EyeW [PerView] hs_in_include.hlsl:2:26",
                                                   "member Scale [PerView] hs_in_include.hlsl:2:38"});
  CHECK(inputsOf(p) == std::vector<std::string>{"W POSITION c_W 0 3"});
}

TEST_CASE("An HLSL include that is not found and an HLSL syntax error are diagnostics at the user's lines") {
  CHECK(compileErrors("include_missing.hlsl") ==
        std::vector<std::string>{data("include_missing.hlsl") +
                                 ":1:1: error: '#include' : Could not process include directive for header name: "
                                 "includes/nowhere.hlsli"});
  const std::string at = data("syntax_error.hlsl");
  CHECK(compileErrors("syntax_error.hlsl") == std::vector<std::string>{at + ":8:3: error: 'pt' : redefinition",
                                                                       at + ":8: error: 'swizzle or member' : Expected",
                                                                       at + ":8: error: 'declaration' : Expected"});
}

TEST_CASE("A wrong HLSL entry point is a diagnostic naming the hull shaders") {
  const std::string at = data("wrong_entry.hlsl");
  CHECK(compileErrors("wrong_entry.hlsl", "Main") ==
        std::vector<std::string>{at + ": error: lod.entry 'Main' names no function in this file (hull shaders here: "
                                      "NearHS, FarHS)"});
  CHECK(compileErrors("wrong_entry.hlsl", "NearPatch") ==
        std::vector<std::string>{at + ":6:9: error: lod.entry 'NearPatch' is not a hull shader (no "
                                      "[patchconstantfunc(...)] attribute): the hull shaders here: NearHS, FarHS"});
  CHECK(compileErrors("wrong_entry.hlsl") ==
        std::vector<std::string>{at + ": error: several hull shaders (NearHS, FarHS): name one in lod.entry"});
  const HullProgram far = compiled("wrong_entry.hlsl", "FarHS");
  CHECK(far.entry == "FarHS");
  CHECK(far.patchConstantFunction == "FarPatch");
  CHECK(far.glsl.find("FarPatch(") != std::string::npos);
  CHECK(far.glsl.find("NearPatch(") == std::string::npos);
}

TEST_CASE("An HLSL pow2 partitioning goes through glslang and stays pow2") {
  const HullProgram p = compiled("pow2.hlsl");
  CHECK(p.partitioning == Partitioning::Pow2);
  CHECK(p.partitioningAt.line == 7);
  CHECK(p.glsl.find("gl_TessLevelOuter[3] = ") != std::string::npos);
}

TEST_CASE("A patch-constant function that does not exist is a diagnostic at the attribute") {
  CHECK(compileErrors("patchconstantfunc_missing.hlsl") ==
        std::vector<std::string>{data("patchconstantfunc_missing.hlsl") +
                                 ":8:1: error: 'PatchFactors' : patch constant function not found"});
}

TEST_CASE("A partitioning attribute that contradicts the scene is an error at the attribute") {
  const HullProgram p = compiled("partitioning_contradicts.hlsl");
  verify::Scene scene;
  scene.lod.inputs = {input("POSITION", "position")}; // bound by its semantic
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("partitioning_contradicts.hlsl") +
                                 ":13:3: error: [partitioning(\"fractional_odd\")] contradicts "
                                 "the scene's tessellation.partitioning = \"fractional_even\": "
                                 "set tessellation.partitioning = \"fractional_odd\""});
  scene.partitioning = Partitioning::FractionalOdd;
  CHECK(sceneErrors(p, scene).empty());
  scene.lod.controlPoints = 1;
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("partitioning_contradicts.hlsl") +
                                 ":17:14: error: the hull shader takes 4 control points, the "
                                 "scene's lod.control_points is 1: set lod.control_points = 4"});
}

TEST_CASE("An unbound HLSL input names its semantic and lod.inputs") {
  const HullProgram p = compiled("partitioning_contradicts.hlsl");
  verify::Scene scene;
  scene.partitioning = Partitioning::FractionalOdd;
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("partitioning_contradicts.hlsl") +
                                 ":1:27: error: input 'PosW' (POSITION) is not bound: add it to [lod.inputs] (one of: "
                                 "position, position_flat, position_xz, uv, bounds_y, patch_size, or a constant)"});
}

TEST_CASE("The evaluation shader gives the domain and partitioning and a contradiction is an error") {
  HullProgram p = compiled("unbound_uniform.tesc");
  std::vector<Diagnostic> errors;
  CHECK(readEvaluationShader(data("quad_odd.tese"), p, errors));
  CHECK(errors.empty());
  CHECK(p.domain == hull::Domain::Quad);
  CHECK(p.partitioning == Partitioning::FractionalOdd);
  CHECK(formatDiagnostic(diag(p.partitioningAt.file, p.partitioningAt.line, p.partitioningAt.column, "x")) ==
        data("quad_odd.tese") + ":2:15: error: x");
  verify::Scene scene;
  scene.lod.uniforms = {bound("gBound"), bound("gEyePosW", "eye")};
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("quad_odd.tese") + ":2:15: error: layout(fractional_odd_spacing) contradicts the "
                                                         "scene's tessellation.partitioning = \"fractional_even\": set "
                                                         "tessellation.partitioning = \"fractional_odd\""});

  HullProgram hlsl = compiled("hull.hlsl");
  errors.clear();
  CHECK_FALSE(readEvaluationShader(data("quad_odd.tese"), hlsl, errors));
  CHECK(formatDiagnostics(errors) == data("quad_odd.tese") +
                                         ":2:15: error: layout(fractional_odd_spacing) contradicts the hull shader's "
                                         "[partitioning(\"fractional_even\")] (" +
                                         data("hull.hlsl") + ":56:1): make them agree");
  errors.clear();
  CHECK(readEvaluationShader(data("domain.hlsl"), hlsl, errors));
  CHECK(errors.empty());
}

TEST_CASE("A triangle domain from the evaluation shader is refused for the scene") {
  HullProgram p = compiled("unbound_uniform.tesc");
  std::vector<Diagnostic> errors;
  CHECK(readEvaluationShader(data("tri.tese"), p, errors));
  CHECK(p.domain == hull::Domain::Tri);
  CHECK(p.partitioning == Partitioning::Integer); // GLSL's default spacing
  verify::Scene scene;
  scene.partitioning = Partitioning::Integer;
  scene.lod.uniforms = {bound("gBound"), bound("gEyePosW", "eye")};
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("tri.tese") + ":3:8: error: the domain is tri: fftess verifies quad patches "
                                                    "(a terrain's tiles)"});
}

TEST_CASE("An Effects file keeps its lines with the technique and state blocks blanked for glslang") {
  // effects.fx: hull.hlsl with a SamplerState initialiser, a RasterizerState and a technique11 block (Luna's .fx form)
  const HullProgram p = compiled("effects.fx");
  CHECK(p.language == Language::Hlsl);
  CHECK(p.entry == "HS");
  CHECK(p.partitioningAt.line == 56);
  CHECK(resourcesOf(p) == std::vector<std::string>{"member gEyePosW [cbPerFrame] effects.fx:5:10",
                                                   "member gMinDist [cbPerFrame] effects.fx:6:9",
                                                   "member gMaxDist [cbPerFrame] effects.fx:7:9",
                                                   "member gMaxTess [$Global] effects.fx:11:7",
                                                   "sampler gHeightMap effects.fx:12:11"});
  CHECK(p.glsl.find("uniform sampler2D gHeightMap;") != std::string::npos);
}

TEST_CASE("A storage buffer the shader reads is refused and a block input binds as Block.member") {
  // storage_buffer.tesc: `buffer LodData { float bias[]; }` (fftess would have nothing to put there) and the input
  // block VS_OUT, bound by "VS_OUT.pos"
  const HullProgram p = compiled("storage_buffer.tesc");
  verify::Scene scene;
  scene.lod.inputs = {input("VS_OUT.pos", "position"), input("VS_OUT.uv", "uv")};
  CHECK(sceneErrors(p, scene) ==
        std::vector<std::string>{data("storage_buffer.tesc") +
                                 ":3:61: error: member 'bias' of storage buffer 'LodData': fftess binds uniforms, "
                                 "uniform blocks / cbuffers and the heightmap, not storage buffers (the shader would "
                                 "read data fftess does not have; pass it as a uniform array to check this shader)"});
}

// ---------------------------------------------------------------------------------------------------------------
// The named camera values of [lod.uniforms] for a camera of each convention (hull_bind.h cameraValues; no GL needed).

namespace {

glm::vec4 unitPlane(const glm::vec4& p) {
  const double n = std::sqrt(double(p.x) * p.x + double(p.y) * p.y + double(p.z) * p.z);
  return glm::vec4(float(p.x / n), float(p.y / n), float(p.z / n), float(p.w / n));
}

void checkPlanesAgree(const std::array<glm::vec4, 6>& a, const std::array<glm::vec4, 6>& b) {
  for (int k = 0; k < 6; ++k) {
    INFO("plane " << k);
    const glm::vec4 x = unitPlane(a[k]), y = unitPlane(b[k]);
    const float tol = k == 5 ? 2e-3f : 2e-5f; // far: w - z of nearly equal rows (far / near = 10^4 here)
    for (int c = 0; c < 3; ++c) CHECK(std::fabs(x[c] - y[c]) < tol);
    CHECK(std::fabs(x.w - y.w) < tol * 100.0f);
  }
}

} // namespace

TEST_CASE("A D3D camera's named values: its own projection and planes, the GL planes of the same frustum, its near and far") {
  using fftess::gpulod::hull::cameraValues;
  const glm::vec3 eye(13.5f, 21.0f, -64.0f), target(2.0f, -1.5f, 3.0f), up(0.0f, 1.0f, 0.0f);
  const float fov = 1.1f, zn = 0.5f, zf = 5000.0f;
  const glm::vec2 vp(1600.0f, 900.0f);
  const lod::Camera d3d = lod::makeCameraD3d(eye, target, up, fov, zn, zf, vp);
  const lod::Camera gl = lod::makeCamera(eye, target, up, fov, zn, zf, vp);
  const auto d = cameraValues(d3d), g = cameraValues(gl);
  CHECK(d.projection == d3d.projection);
  CHECK(d.projectionD3d == d3d.projection);
  CHECK(d.view == d3d.view);
  CHECK(std::fabs(d.nearPlane - zn) < 1e-5f * zn);
  CHECK(std::fabs(d.farPlane - zf) < 1e-3f * zf);
  CHECK(g.nearPlane == gl.projection[3][2] / (gl.projection[2][2] - 1.0f)); // GL's: the bits as before
  CHECK(g.farPlane == gl.projection[3][2] / (gl.projection[2][2] + 1.0f));
  CHECK(std::fabs(g.nearPlane - zn) < 1e-5f * zn);
  // frustum_planes: the camera's convention (D3D's, normalised); the GL and D3D planes of one camera bound the same
  // frustum; the D3D camera's near plane passes through the point at the near distance.
  for (int k = 0; k < 6; ++k) { // docs/gpu_lod.md: each divided by sqrt((x*x + y*y) + z*z), in float
    const glm::vec4 p = d.planesD3d[k];
    const float len = std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
    CHECK(d.planes[k] == glm::vec4(p.x / len, p.y / len, p.z / len, p.w / len));
  }
  checkPlanesAgree(d.planesGl, d.planesD3d);
  checkPlanesAgree(g.planesGl, g.planesD3d);
  const glm::vec3 axis = glm::normalize(target - eye), atNear = eye + axis * zn;
  const glm::vec4 n = unitPlane(d.planesGl[4]);
  CHECK(std::fabs(n.x * atNear.x + n.y * atNear.y + n.z * atNear.z + n.w) < 1e-4f);
  // The D3D view mirrors x: the D3D camera's left plane is the GL camera's right one.
  const int mirror[6] = {1, 0, 2, 3, 4, 5};
  std::array<glm::vec4, 6> swapped;
  for (int k = 0; k < 6; ++k) swapped[k] = g.planes[mirror[k]];
  checkPlanesAgree(d.planes, swapped);
}
