// Internal to gpu_lod/: the user's hull shader as written (docs/gpu_lod.md "Your hull shader as written"): a GLSL
// tessellation control shader or an HLSL hull shader, run on the driver's tessellation control stage, its factors
// captured per patch. Two halves:
//   hull_glsl.cpp, hull_hlsl.cpp, hull_diagnostics.cpp  the front end: the file (with its #includes) through glslang
//       (the library) into the GLSL 4.50 TCS the driver compiles (HLSL: glslang's HLSL front end -> SPIR-V ->
//       SPIRV-Cross), with what it declares and uses (HullProgram) or its diagnostics as file:line:col lines
//   hull_capture.cpp, hull_bind.cpp  the driver: a GL program of a generated vertex shader, the user's TCS with a
//       recording epilogue and a generated evaluation shader; the scene's [lod.uniforms] / [lod.inputs] bound, per
//       camera one draw of every patch, the factors read back and mapped onto fftess's edges (HullCapture)
// gpu_lod.cpp chooses this path for a file that is a hull shader (isHullShader) and wraps HullCapture in the
// provider.
#pragma once

#include "gl/gl_context.h"
#include "tessellator/tessellator.h"
#include "verify/verify.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fftess::gpulod::hull {

// A position in the user's files (file as the scene names it or as #include resolved it; line and column 1-based;
// 0 = unknown).
struct SourcePos {
  std::string file;
  int line = 0;
  int column = 0;
};

// One diagnostic: printed as "file:line:col: error: message" (formatDiagnostic); file "" when it has no place
// (then "fftess: error: message").
struct Diagnostic {
  SourcePos at;
  std::string message;
  bool warning = false;
};
std::string formatDiagnostic(const Diagnostic& d);
std::string formatDiagnostics(const std::vector<Diagnostic>& ds); // one per line, no trailing newline

enum class Language : uint8_t { Glsl, Hlsl };
enum class Domain : uint8_t { Unknown, Quad, Tri, Isoline };

// Whether `file` (its text `source`) is a hull shader as an engine ships it rather than a lodMain file:
// *.tesc / *.tesc.glsl, or GLSL text with "layout(vertices = N) out"; *.fx, or HLSL text with a
// [patchconstantfunc(...)] attribute. A file defining lodMain is never a hull shader.
bool isHullShader(const std::string& file, const std::string& source);
Language languageOf(const std::string& file); // .hlsl / .fx: Hlsl; else Glsl

// What the shader uses, as the scene binds it by name ([lod.uniforms]).
struct Resource {
  enum class Kind : uint8_t { Uniform, BlockMember, Sampler };
  Kind kind = Kind::Uniform;
  std::string name;   // the name the scene binds: the uniform's, the member's (without the block), the texture's
  std::string block;  // BlockMember: the uniform block / cbuffer name ("" otherwise)
  std::string glslBlock; // BlockMember: the block's name in HullProgram::glsl (GL introspection names the member
                         // "glslBlock.name"): GLSL the block's; HLSL the cbuffer's, "$Global" -> "_Global"
  SourcePos declared; // its declaration in the user's file(s) (line 0 when unknown)
  bool storage = false; // a member of a shader storage block (GLSL `buffer`, HLSL (RW)StructuredBuffer): refused
};

// A per-control-point input of the TCS that fftess's vertex shader must feed ([lod.inputs]); built-ins
// (gl_in[].gl_Position; HLSL SV_Position) are listed too with builtin = true.
struct Input {
  std::string name;      // the name the scene binds: the variable / block member (GLSL), the struct member (HLSL)
  std::string semantic;  // HLSL: the semantic ("POSITION", "TEXCOORD0"), "" for GLSL
  std::string glslName;  // the name in the GLSL TCS the driver compiles (the VS output of the same name / location)
  int location = -1;     // its location there (-1: matched by name)
  int components = 4;    // floats (1..4)
  bool builtin = false;  // gl_Position
  SourcePos declared;
};

// The user's hull shader, ready for the driver.
struct HullProgram {
  Language language = Language::Glsl;
  std::string file;        // the scene's lod.shader
  std::string entry;       // HLSL: the hull shader function (lod.entry or the one with [patchconstantfunc]); GLSL "main"
  std::string patchConstantFunction; // HLSL: [patchconstantfunc("...")]
  // The GLSL 4.50 TCS the driver compiles: GLSL: the user's text with #include expanded and `#line L S` directives
  // (S indexes sourceFiles); HLSL: SPIRV-Cross's output (its errors are fftess's, never the user's lines).
  std::string glsl;
  std::vector<std::string> sourceFiles; // GLSL: source-string number -> file, [0] = the main file
  int inputControlPoints = 0;  // HLSL InputPatch<T, N>; GLSL 0 (unknown: the scene's lod.control_points)
  SourcePos inputControlPointsAt; // HLSL: where InputPatch<T, N> is written
  int outputControlPoints = 0; // layout(vertices = N) / [outputcontrolpoints(N)]
  Domain domain = Domain::Unknown; // HLSL [domain(...)]; GLSL Unknown unless an evaluation shader said
  SourcePos domainAt;
  std::optional<Partitioning> partitioning; // HLSL [partitioning(...)] (pow2 included); from the evaluation shader
  SourcePos partitioningAt;
  std::optional<float> maxTessFactor; // HLSL [maxtessfactor(x)]
  SourcePos maxTessFactorAt;
  std::vector<Resource> resources; // every uniform, block member and sampler the shader uses (active)
  std::vector<Input> inputs;       // every per-control-point input it reads
};

// The front end. file: the scene's lod.shader (resolved path); entry: lod.entry ("" = find it). False with every
// diagnostic in `errors` (file:line:col of the user's files; glslang's own messages, one per diagnostic).
bool compileHull(const std::string& file, const std::string& entry, HullProgram& out, std::vector<Diagnostic>& errors);

// The user's evaluation (GLSL TES) / domain (HLSL) shader, lod.evaluation_shader: its domain and partitioning
// (GLSL layout(quads, fractional_odd_spacing) in; HLSL [domain(...)], and [partitioning] when the file has the hull
// shader too) into `program` where the hull shader did not say; a contradiction with the hull shader is an error at
// both places. False with diagnostics.
bool readEvaluationShader(const std::string& file, HullProgram& program, std::vector<Diagnostic>& errors);

// The scene against the program: lod.control_points / lod.corner_order against the input patch size, every used
// uniform / member / sampler bound in [lod.uniforms] and every input in [lod.inputs], the domain a quad, the
// partitioning the scene's tessellation.partitioning. One diagnostic per problem at the shader's position (or the
// scene's key). True when none.
bool checkAgainstScene(const HullProgram& program, const verify::Scene& scene, std::vector<Diagnostic>& errors);

// glslang 12 prints no columns: where a diagnostic of a GLSL hull shader has a line and no column, the driver's own
// compiler (ctx, created, not current) compiles program.glsl and its message on the same file and line gives the
// column (Mesa prints it; NVIDIA names the token, found on that line). Leaves the rest as it is.
void fillColumnsFromDriver(gltest::GlContext& ctx, const HullProgram& program, std::vector<Diagnostic>& errors);

// The driver half: built once per command on the provider's context (current while create/evaluate run).
class HullCapture {
public:
  ~HullCapture();
  // Builds the GL program and uploads every patch's control points and the camera-independent uniforms, the
  // heightmap texture. False with diagnostics (a driver compile/link error of the TCS named by the user's file and
  // line; a GL limit).
  static std::unique_ptr<HullCapture> create(gltest::GlContext& ctx, const HullProgram& program,
                                             const verify::LodPatches& patches, std::vector<Diagnostic>& errors);
  // One camera: the camera's uniforms, one draw of every patch (rasterizer discarded; the recording epilogue culls
  // each patch after reading its levels, so nothing is tessellated), the six factors of every patch in fftess's
  // edge order (Ueq0 Veq0 Ueq1 Veq1 insideU insideV, mapped from the shader's gl_TessLevelOuter/Inner by
  // lod.domain_u / lod.domain_v). out.size() == patches.size(); why.scheme = Shader, metric 0, unclamped = factor.
  bool evaluate(const verify::LodPatches& patches, const lod::Camera& camera, std::vector<lod::PatchLod>& out,
                std::string& error);

  // On llvmpipe: the statements writing gl_TessLevelOuter / Inner at a dynamic index that were made constant-index
  // (Mesa 22.3 loses such writes from several invocations; docs/gpu_lod.md); 0 elsewhere.
  int levelWritesRewritten() const;

  struct Impl;
  explicit HullCapture(std::unique_ptr<Impl> impl);

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace fftess::gpulod::hull
