// The driver half of a hull shader as written (gpu_lod/hull.h HullCapture) on llvmpipe: the shader's levels land on
// fftess's edges by lod.domain_u / lod.domain_v (golden arrays), raw bits kept; uniforms, a std140 block (mat4,
// row_major mat4, vec4[6]) and the heightmap sampler bound; the per-camera named values; control points in
// lod.corner_order; the insertion path for a main that calls barrier(); the driver's errors as the user's file:line.
// The programs are built by hand (HullProgram: GLSL text, its inputs and resources) so this half is tested alone.
// Without an OpenGL 4.5 context the whole executable exits 77 (skipped), or fails when CI is set.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "base/bits.h"
#include "gpu_lod/hull.h"
#include "verify/internal.h" // buildMipChain

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace fftess;
using namespace fftess::gpulod::hull;
using verify::DomainAxis;

namespace {

gltest::GlContext* gContext = nullptr;

verify::UniformBinding numbers(const std::string& name, const std::vector<double>& values) {
  verify::UniformBinding b;
  b.name = name;
  b.numbers = values;
  return b;
}

verify::UniformBinding named(const std::string& name, const std::string& value) {
  verify::UniformBinding b;
  b.name = name;
  b.value = value;
  return b;
}

std::string formatDiagnosticsForTest(const std::vector<Diagnostic>& ds) {
  std::string s;
  for (const Diagnostic& d : ds) s += d.at.file + ":" + std::to_string(d.at.line) + ":" +
                                     std::to_string(d.at.column) + ": " + d.message + "\n";
  return s;
}

const char* const kScene = "[layout]\nkind = \"grid\"\npatches_x = 3\npatches_z = 2\npatch_size = 4.0\n"
                           "[displacement]\nkind = \"fbm\"\nresolution = 33\nheight_scale = 5.0\n"
                           "[lod]\nscheme = \"constant\"\n[tessellation]\npartitioning = \"fractional_even\"\n"
                           "[camera]\neye = [0.0, 15.0, -40.0]\ntarget = [0.0, 0.0, 0.0]\n";

verify::Terrain terrain(const verify::Lod& lod, const std::vector<std::string>& overrides = {}) {
  verify::SceneResult r = verify::parseScene(kScene, "scene.toml", overrides);
  INFO(r.error);
  REQUIRE(r);
  r.scene.lod.uniforms = lod.uniforms;
  r.scene.lod.inputs = lod.inputs;
  r.scene.lod.controlPoints = lod.controlPoints;
  r.scene.lod.cornerOrder = lod.cornerOrder;
  r.scene.lod.domainU = lod.domainU;
  r.scene.lod.domainV = lod.domainV;
  verify::TerrainResult t = verify::prepareTerrain(r.scene);
  INFO(t.error);
  REQUIRE(t);
  return t.terrain;
}

// A GLSL TCS as the front end would hand it over: `#line 1 0` so line 1 of `body` is line 1 of user.tesc.
HullProgram program(const std::string& body, int vertices = 4) {
  HullProgram p;
  p.file = "user.tesc";
  p.sourceFiles = {"user.tesc"};
  p.outputControlPoints = vertices;
  p.glsl = "#version 450\n#line 1 0\nlayout(vertices = " + std::to_string(vertices) + ") out;\n" + body;
  return p;
}

std::string levels(const std::string& o0, const std::string& o1, const std::string& o2, const std::string& o3,
                   const std::string& i0, const std::string& i1) {
  return "gl_TessLevelOuter[0] = " + o0 + "; gl_TessLevelOuter[1] = " + o1 + "; gl_TessLevelOuter[2] = " + o2 +
         "; gl_TessLevelOuter[3] = " + o3 + "; gl_TessLevelInner[0] = " + i0 + "; gl_TessLevelInner[1] = " + i1 + ";";
}

std::string simpleMain(const std::string& levelCode) {
  return "void main() {\n  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;\n"
         "  if (gl_InvocationID == 0) { " + levelCode + " }\n}\n";
}

// Runs `p` on the terrain for one camera: every patch's six factors (fftess order). Fails the test on an error.
std::vector<lod::PatchLod> capture(const HullProgram& p, const verify::Terrain& t, const lod::Camera& camera) {
  verify::LodPatches patches(t);
  std::vector<Diagnostic> errors;
  std::unique_ptr<HullCapture> c = HullCapture::create(*gContext, p, patches, errors);
  INFO(formatDiagnosticsForTest(errors));
  REQUIRE(c);
  std::vector<lod::PatchLod> out;
  std::string error;
  const bool ok = c->evaluate(patches, camera, out, error);
  INFO(error);
  REQUIRE(ok);
  REQUIRE(out.size() == patches.size());
  return out;
}

lod::Camera camera() {
  return lod::makeCamera({-3.0f, 9.0f, -5.0f}, {6.0f, 0.0f, 4.0f}, {0.0f, 1.0f, 0.0f}, 0.9f, 0.5f, 300.0f,
                         {1280.0f, 720.0f});
}

std::array<uint32_t, 6> bitsOfFactors(const lod::PatchLod& l) {
  std::array<uint32_t, 6> b{};
  for (int k = 0; k < 6; ++k) b[static_cast<size_t>(k)] = bitsOf(l.factors[k]);
  return b;
}

} // namespace

TEST_CASE("constant levels land on the edges lod.domain_u and lod.domain_v name", "[gpu_lod][hull]") {
  const HullProgram p = program(simpleMain(levels("1.0", "2.0", "3.0", "4.0", "5.0", "6.0")));
  // Golden: fftess order Ueq0 Veq0 Ueq1 Veq1 insideU insideV, written from the GL/D3D quad convention by hand.
  struct Case {
    DomainAxis u, v;
    std::array<float, 6> want;
  };
  const Case cases[] = {
      {DomainAxis::PlusX, DomainAxis::PlusZ, {1, 2, 3, 4, 5, 6}},
      {DomainAxis::PlusX, DomainAxis::MinusZ, {1, 4, 3, 2, 5, 6}},
      {DomainAxis::MinusX, DomainAxis::PlusZ, {3, 2, 1, 4, 5, 6}},
      {DomainAxis::MinusX, DomainAxis::MinusZ, {3, 4, 1, 2, 5, 6}},
      {DomainAxis::PlusZ, DomainAxis::PlusX, {2, 1, 4, 3, 6, 5}},
      {DomainAxis::PlusZ, DomainAxis::MinusX, {4, 1, 2, 3, 6, 5}},
      {DomainAxis::MinusZ, DomainAxis::PlusX, {2, 3, 4, 1, 6, 5}},
      {DomainAxis::MinusZ, DomainAxis::MinusX, {4, 3, 2, 1, 6, 5}},
  };
  for (const Case& c : cases) {
    verify::Lod lod;
    lod.domainU = c.u;
    lod.domainV = c.v;
    lod.inputs = {{"gl_Position", "position"}};
    const std::vector<lod::PatchLod> out = capture(p, terrain(lod), camera());
    INFO("domain_u " << int(c.u) << " domain_v " << int(c.v));
    for (const lod::PatchLod& l : out) {
      for (int k = 0; k < 6; ++k) CHECK(l.factors[k] == c.want[static_cast<size_t>(k)]);
      CHECK(l.why.factor[0].unclamped == l.factors[0]);
      CHECK_FALSE(l.why.culled);
    }
  }
}

TEST_CASE("raw level bits are kept, NaN payload, negative zero and a denormal included", "[gpu_lod][hull]") {
  const uint32_t bits[6] = {0x7fc00123u, 0x80000000u, 0x00000001u, 0x7f800000u, 0xc0400000u, 0x3f800001u};
  auto lit = [](uint32_t b) { return "uintBitsToFloat(" + std::to_string(b) + "u)"; };
  const HullProgram p =
      program(simpleMain(levels(lit(bits[0]), lit(bits[1]), lit(bits[2]), lit(bits[3]), lit(bits[4]), lit(bits[5]))));
  verify::Lod lod;
  const std::vector<lod::PatchLod> out = capture(p, terrain(lod), camera());
  for (const lod::PatchLod& l : out) {
    const std::array<uint32_t, 6> got = bitsOfFactors(l);
    for (int k = 0; k < 6; ++k) CHECK(got[static_cast<size_t>(k)] == bits[k]);
  }
}

TEST_CASE("a uniform, a std140 block and the heightmap sampler are bound from lod.uniforms", "[gpu_lod][hull]") {
  const std::string decl = "uniform float uScale;\n"
                           "layout(std140) uniform Params { vec4 pad; mat4 M; layout(row_major) mat4 R; "
                           "vec4 planes[6]; } params;\n"
                           "uniform sampler2D uHeight;\n";
  HullProgram p = program(decl + simpleMain(levels("uScale", "params.M[1][2]", "params.R[3][0]", "params.planes[4].w",
                                                  "texelFetch(uHeight, ivec2(3, 5), 0).r",
                                                  "texelFetch(uHeight, ivec2(1, 2), 1).r")));
  for (const char* member : {"M", "R", "planes"}) {
    Resource r;
    r.kind = Resource::Kind::BlockMember, r.name = member, r.block = "Params";
    p.resources.push_back(r);
  }
  verify::Lod lod;
  std::vector<double> m(16), r(16), planes(24);
  for (int k = 0; k < 16; ++k) m[k] = 0.5 + k, r[k] = 100.25 + k;
  for (int k = 0; k < 24; ++k) planes[k] = -1000.0 - k;
  lod.uniforms = {numbers("uScale", {7.25}), numbers("Params.M", m), numbers("R", r), numbers("planes", planes),
                  named("uHeight", "heightmap")};
  const verify::Terrain t = terrain(lod);
  const std::vector<lod::PatchLod> out = capture(p, t, camera());
  const verify::Displacement& d = t.scene().displacement;
  const std::vector<verify::MipLevel> mips = verify::detail::buildMipChain(*d.texels, d.texWidth, d.texHeight,
                                                                           d.format);
  REQUIRE(d.texWidth == 33);
  // m[i][j] = numbers[i * 4 + j] whatever the storage (row_major R included).
  const float want[6] = {7.25f, 0.5f + 6, 100.25f + 12, -1019.0f, (*d.texels)[5 * 33 + 3], mips[0].texels[2 * 16 + 1]};
  for (const lod::PatchLod& l : out)
    for (int k = 0; k < 6; ++k) CHECK(bitsOf(l.factors[k]) == bitsOf(want[k]));

  SECTION("an unbound member and an unbound sampler are errors naming them") {
    lod.uniforms = {numbers("uScale", {7.25}), numbers("M", m), numbers("planes", planes)};
    const verify::Terrain t2 = terrain(lod);
    verify::LodPatches patches(t2);
    std::vector<Diagnostic> errors;
    CHECK_FALSE(HullCapture::create(*gContext, p, patches, errors));
    const std::string all = formatDiagnosticsForTest(errors);
    CHECK_THAT(all, Catch::Contains("member 'R' of uniform block 'Params' is not bound"));
    CHECK_THAT(all, Catch::Contains("sampler 'uHeight' is not bound"));
  }
  SECTION("too few numbers for a matrix is an error naming the key") {
    lod.uniforms = {numbers("uScale", {7.25}), numbers("M", {1, 2, 3}), numbers("R", r), numbers("planes", planes),
                    named("uHeight", "heightmap")};
    const verify::Terrain t2 = terrain(lod);
    verify::LodPatches patches(t2);
    std::vector<Diagnostic> errors;
    CHECK_FALSE(HullCapture::create(*gContext, p, patches, errors));
    CHECK_THAT(formatDiagnosticsForTest(errors), Catch::Contains("[lod.uniforms] M (uniform 'Params.M', a 4x4 matrix): "
                                                                 "3 number(s) given, 16 needed"));
  }
}

namespace {

glm::vec4 rowOf(const glm::mat4& m, int r) { return {m[0][r], m[1][r], m[2][r], m[3][r]}; }

} // namespace

TEST_CASE("the per-camera values are fftess's own, bit for bit", "[gpu_lod][hull]") {
  const lod::Camera cam = camera();
  // The test's own arithmetic (float, glm): VP = P * V; planes GL = r3 +- r0, r3 +- r1, r3 + r2, r3 - r2.
  const glm::mat4 vp = cam.projection * cam.view;
  const glm::vec4 r0 = rowOf(vp, 0), r1 = rowOf(vp, 1), r2 = rowOf(vp, 2), r3 = rowOf(vp, 3);
  const glm::vec4 top = r3 - r1, nearGl = r3 + r2;
  const float len = std::sqrt((top.x * top.x + top.y * top.y) + top.z * top.z);
  (void)r0;
  glm::mat4 pd3d = cam.projection;
  for (int c = 0; c < 4; ++c) pd3d[c][2] = 0.5f * cam.projection[c][2] + 0.5f * cam.projection[c][3];
  const glm::vec4 nearD3d = rowOf(pd3d * cam.view, 2);
  const std::string decl = "uniform vec4 uPlanes[6]; uniform vec4 uPlanesGl[6]; uniform vec4 uPlanesD3d[6];\n"
                           "uniform mat4 uVP; uniform vec3 uEye; uniform float uNear;\n";
  HullProgram p = program(decl + simpleMain(levels("uPlanes[3].y", "uPlanesGl[4].w", "uPlanesD3d[4].z", "uVP[2][1]",
                                                  "uEye.z", "uNear")));
  verify::Lod lod;
  lod.uniforms = {named("uPlanes", "frustum_planes"), named("uPlanesGl", "frustum_planes_gl"),
                  named("uPlanesD3d", "frustum_planes_d3d"), named("uVP", "view_projection"), named("uEye", "eye"),
                  named("uNear", "near")};
  const verify::Terrain t = terrain(lod);
  const std::vector<lod::PatchLod> glsl = capture(p, t, cam);
  const float want[6] = {top.y / len, nearGl.w, nearD3d.z, vp[2][1], cam.eye.z, 0};
  for (int k = 0; k < 5; ++k) CHECK(bitsOf(glsl[0].factors[k]) == bitsOf(want[k]));
  CHECK(glsl[0].factors[5] == Approx(0.5f).epsilon(1e-5)); // near, derived from the projection
  // More named values: a normalised plane's d, the eye's x, the viewport, far and fov_y (derived), height_scale.
  const glm::vec4 farGl = r3 - r2;
  const float farLen = std::sqrt((farGl.x * farGl.x + farGl.y * farGl.y) + farGl.z * farGl.z);
  HullProgram more = program("uniform vec4 uPlanes[6]; uniform vec4 uEye; uniform vec2 uViewport; uniform float "
                             "uFar; uniform float uFov; uniform float uScale;\n" +
                             simpleMain(levels("uPlanes[5].w", "uEye.x + uEye.w * 1000.0", "uViewport.y", "uFar",
                                               "uFov", "uScale")));
  verify::Lod lod2;
  lod2.uniforms = {named("uPlanes", "frustum_planes"), named("uEye", "eye"), named("uViewport", "viewport"),
                   named("uFar", "far"), named("uFov", "fov_y"), named("uScale", "height_scale")};
  const std::vector<lod::PatchLod> m2 = capture(more, terrain(lod2), cam);
  CHECK(bitsOf(m2[0].factors[0]) == bitsOf(farGl.w / farLen));
  CHECK(m2[0].factors[1] == cam.eye.x + 1000.0f); // vec4 eye: w = 1
  CHECK(m2[0].factors[2] == 720.0f);
  CHECK(m2[0].factors[3] == Approx(300.0f).epsilon(1e-4));
  CHECK(m2[0].factors[4] == Approx(0.9f).epsilon(1e-6));
  CHECK(m2[0].factors[5] == 5.0f);
  // HLSL: the float4x4 becomes a GLSL mat holding M^T (mul(M, p) = M * p): the shader's [2][1] reads M's [1][2].
  p.language = Language::Hlsl;
  const std::vector<lod::PatchLod> hlsl = capture(p, t, cam);
  CHECK(bitsOf(hlsl[0].factors[3]) == bitsOf(vp[1][2]));
  // transpose(NAME) undoes it.
  lod.uniforms[3].transpose = true;
  CHECK(bitsOf(capture(p, terrain(lod), cam)[0].factors[3]) == bitsOf(vp[2][1]));
}

TEST_CASE("control points reach the shader in lod.corner_order", "[gpu_lod][hull]") {
  const std::string decl = "layout(location = 2) in vec3 vPos[];\n";
  HullProgram p = program(decl + simpleMain(levels("vPos[0].x", "vPos[1].x", "vPos[2].x", "vPos[3].x",
                                                  "vPos[2].z", "gl_in[3].gl_Position.z")));
  Input in;
  in.name = in.glslName = "vPos";
  in.location = 2;
  in.components = 3;
  p.inputs = {in};
  verify::Lod lod;
  lod.cornerOrder = {0, 2, 3, 1}; // Sascha Willems' order
  lod.inputs = {{"vPos", "position_flat"}, {"gl_Position", "position_flat"}};
  const verify::Terrain t = terrain(lod);
  const std::vector<lod::PatchLod> out = capture(p, t, camera());
  verify::LodPatches patches(t);
  for (size_t i = 0; i < out.size(); ++i) {
    for (int k = 0; k < 4; ++k) CHECK(out[i].factors[k] == patches.corner(i, lod.cornerOrder[k]).flat.x);
    CHECK(out[i].factors[4] == patches.corner(i, 3).flat.z);
    CHECK(out[i].factors[5] == patches.corner(i, 1).flat.z);
  }

  SECTION("an input the scene does not bind is an error at its declaration") {
    p.inputs[0].declared = {"user.tesc", 1, 27};
    lod.inputs = {{"gl_Position", "position_flat"}};
    const verify::Terrain psTerrain = terrain(lod); // the view must not outlive it
    verify::LodPatches ps(psTerrain);
    std::vector<Diagnostic> errors;
    CHECK_FALSE(HullCapture::create(*gContext, p, ps, errors));
    REQUIRE(errors.size() == 1);
    CHECK(errors[0].at.line == 1);
    CHECK_THAT(errors[0].message, Catch::StartsWith("input 'vPos' is not bound: add it to [lod.inputs]"));
  }
  SECTION("one control point per tile, inputs in a block") {
    HullProgram one = program("in VsOut { vec2 uv; float size; vec2 bounds; } tcIn[];\n" +
                                  simpleMain(levels("tcIn[0].uv.x", "tcIn[0].uv.y", "tcIn[0].size",
                                                    "tcIn[0].bounds.x", "tcIn[0].bounds.y", "1.0")),
                              1);
    Input uv, size, bounds;
    uv.name = "uv", uv.glslName = "VsOut.uv", uv.components = 2;
    size.name = "size", size.glslName = "VsOut.size", size.components = 1;
    bounds.name = "bounds", bounds.glslName = "VsOut.bounds", bounds.components = 2;
    one.inputs = {uv, size, bounds};
    lod.controlPoints = 1;
    lod.cornerOrder = {3, 0, 0, 0};
    lod.inputs = {{"uv", "uv"}, {"size", "patch_size"}, {"bounds", "bounds_y"}};
    const verify::Terrain t1 = terrain(lod);
    const std::vector<lod::PatchLod> o1 = capture(one, t1, camera());
    verify::LodPatches ps(t1);
    for (size_t i = 0; i < o1.size(); ++i) {
      CHECK(o1[i].factors[0] == ps.corner(i, 3).tex.x);
      CHECK(o1[i].factors[1] == ps.corner(i, 3).tex.y);
      CHECK(o1[i].factors[2] == 4.0f);
      CHECK(o1[i].factors[3] == ps[i].patch.minHeight);
      CHECK(o1[i].factors[4] == ps[i].patch.maxHeight);
    }
  }
}

TEST_CASE("every patch of a 64 x 64 grid records its own levels", "[gpu_lod][hull]") {
  for (int points : {4, 1}) {
    HullProgram p = program(simpleMain(levels("gl_in[0].gl_Position.x", "gl_in[0].gl_Position.z", "1.0", "1.0",
                                              "float(gl_PrimitiveID)", "1.0")), points);
    verify::Lod lod;
    lod.controlPoints = points;
    lod.inputs = {{"gl_Position", "position_flat"}};
    const verify::Terrain t = terrain(lod, {"layout.patches_x=64", "layout.patches_z=64"});
    const std::vector<lod::PatchLod> out = capture(p, t, camera());
    verify::LodPatches patches(t);
    INFO(points << " control point(s)");
    int wrong = 0;
    for (size_t i = 0; i < out.size(); ++i)
      wrong += out[i].factors[0] != patches.corner(i, 0).flat.x || out[i].factors[1] != patches.corner(i, 0).flat.z;
    CHECK(wrong == 0);
  }
}

TEST_CASE("a main that calls barrier gets the record inserted before its closing brace", "[gpu_lod][hull]") {
  // As SPIRV-Cross writes glslang's HLSL wrapper: control points, barrier(), invocation 0 runs the patch constants.
  const std::string body = "void hsConstant() {\n  " + levels("1.5", "2.5", "3.5", "4.5", "5.5", "6.5") +
                           "\n}\nvoid main()\n{\n  gl_out[gl_InvocationID].gl_Position = "
                           "gl_in[gl_InvocationID].gl_Position;\n  barrier();\n  if (gl_InvocationID == 0)\n  {\n"
                           "    hsConstant();\n  }\n}\n";
  HullProgram p = program(body);
  p.language = Language::Hlsl;
  verify::Lod lod;
  const std::vector<lod::PatchLod> out = capture(p, terrain(lod), camera());
  for (const lod::PatchLod& l : out)
    for (int k = 0; k < 6; ++k) CHECK(l.factors[k] == 1.5f + static_cast<float>(k));

  SECTION("an early return with barrier() is refused with a message") {
    HullProgram r = program("void main() {\n  barrier();\n  if (gl_InvocationID != 0) return;\n  " +
                            levels("1.0", "1.0", "1.0", "1.0", "1.0", "1.0") + "\n}\n");
    const verify::Terrain patchesTerrain = terrain(lod); // the view must not outlive it
    verify::LodPatches patches(patchesTerrain);
    std::vector<Diagnostic> errors;
    CHECK_FALSE(HullCapture::create(*gContext, r, patches, errors));
    CHECK_THAT(formatDiagnosticsForTest(errors), Catch::Contains("returns early"));
  }
}

// SPIRV-Cross's GLSL (spirv-cross --version 450 --no-es, Debian) of glslang's SPIR-V (glslangValidator -D -V -S tesc
// -e HS) for this HLSL, written by us:
//   cbuffer cbPerFrame { float4x4 gViewProj; float4 gPlanes[6]; };
//   struct VIn { float3 PosW : POSITION; };
//   struct PC { float E[4] : SV_TessFactor; float I[2] : SV_InsideTessFactor; };
//   PC ConstHS(InputPatch<VIn, 4> p, uint id : SV_PrimitiveID) {
//     PC o; float4 c = mul(gViewProj, float4(p[0].PosW, 1.0));
//     o.E[0] = c.x; o.E[1] = gViewProj[2][1]; o.E[2] = 3; o.E[3] = 4; o.I[0] = 5; o.I[1] = 6; return o; }
//   HS: [domain("quad")] ... [patchconstantfunc("ConstHS")], passes PosW through.
// mul(M, p) became p * G and M[2][1] became G[2].y: G's column i is the HLSL row i (a row_major mat4 in the block).
const char* const kSpirvCrossTcs = R"(layout(vertices = 4) out;
struct VIn
{
    vec3 PosW;
};
layout(binding = 0, std140) uniform cbPerFrame
{
    layout(row_major) mat4 gViewProj;
    vec4 gPlanes[6];
} _47;
layout(location = 0) in vec3 p_PosW[];
layout(location = 0) out vec3 _entryPointOutput_PosW[4];
mat4 spvWorkaroundRowMajor(mat4 wrap) { return wrap; }
void main()
{
    VIn param[4] = VIn[](VIn(p_PosW[0]), VIn(p_PosW[1]), VIn(p_PosW[2]), VIn(p_PosW[3]));
    _entryPointOutput_PosW[gl_InvocationID] = param[gl_InvocationID].PosW;
    barrier();
    if (int(gl_InvocationID) == 0)
    {
        gl_TessLevelOuter[0] = (vec4(p_PosW[0], 1.0) * spvWorkaroundRowMajor(_47.gViewProj)).x;
        gl_TessLevelOuter[1] = _47.gViewProj[2].y;
        gl_TessLevelOuter[2] = 3.0;
        gl_TessLevelOuter[3] = 4.0;
        gl_TessLevelInner[0] = 5.0;
        gl_TessLevelInner[1] = 6.0;
    }
}
)";

TEST_CASE("an HLSL cbuffer matrix through glslang and SPIRV-Cross multiplies as the HLSL source says",
          "[gpu_lod][hull]") {
  HullProgram p;
  p.language = Language::Hlsl;
  p.file = "terrain.hlsl";
  p.glsl = std::string("#version 450\n") + kSpirvCrossTcs;
  p.outputControlPoints = 4;
  Input pos;
  pos.name = "PosW", pos.semantic = "POSITION", pos.glslName = "p_PosW", pos.location = 0, pos.components = 3;
  p.inputs = {pos};
  Resource vp;
  vp.kind = Resource::Kind::BlockMember, vp.name = "gViewProj", vp.block = "cbPerFrame";
  p.resources = {vp};
  verify::Lod lod;
  lod.uniforms = {named("gViewProj", "view_projection")};
  lod.inputs = {{"POSITION", "position"}};
  const verify::Terrain t = terrain(lod);
  const lod::Camera cam = camera();
  const std::vector<lod::PatchLod> out = capture(p, t, cam);
  const glm::mat4 m = cam.projection * cam.view;
  verify::LodPatches patches(t);
  for (size_t i = 0; i < out.size(); ++i) {
    const glm::vec4 clip = m * glm::vec4(patches[i].patch.corners[0], 1.0f);
    CHECK(out[i].factors[0] == Approx(clip.x).epsilon(1e-5).margin(1e-5)); // the shader's own dot product order
    CHECK(bitsOf(out[i].factors[1]) == bitsOf(m[1][2]));                    // HLSL M[2][1]: row 2, column 1
  }
}

TEST_CASE("a driver compile error names the user's file and line", "[gpu_lod][hull]") {
  HullProgram p = program("void main() {\n  gl_TessLevelOuter[0] = 1.0;\n#line 7 1\n  float x = undefinedThing;\n}\n");
  p.sourceFiles.push_back("lib/include.glsl");
  verify::Lod lod;
  const verify::Terrain patchesTerrain = terrain(lod); // the view must not outlive it
  verify::LodPatches patches(patchesTerrain);
  std::vector<Diagnostic> errors;
  CHECK_FALSE(HullCapture::create(*gContext, p, patches, errors));
  REQUIRE_FALSE(errors.empty());
  INFO(formatDiagnosticsForTest(errors));
  CHECK(errors[0].at.file == "lib/include.glsl");
  CHECK(errors[0].at.line == 7);
  CHECK_THAT(errors[0].message, Catch::Contains("undefinedThing"));
  CHECK(errors[0].message.find("error:") == std::string::npos);
}

// Not run by ctest (hidden tag): the cost of one camera for a few thousand patches, printed.
TEST_CASE("cost of one camera on a 64 x 64 and a 128 x 80 grid", "[.cost]") {
  const std::string decl = "uniform mat4 uVP; uniform vec4 uPlanes[6]; uniform vec3 uEye;\n";
  HullProgram p = program(decl + simpleMain(levels("distance(uEye, gl_in[0].gl_Position.xyz)", "uVP[0][0]",
                                                  "uPlanes[0].x", "4.0", "5.0", "6.0")));
  verify::Lod lod;
  lod.uniforms = {named("uVP", "view_projection"), named("uPlanes", "frustum_planes"), named("uEye", "eye")};
  for (const char* x : {"64", "128"}) {
    const verify::Terrain t = terrain(lod, {std::string("layout.patches_x=") + x,
                                            std::string("layout.patches_z=") + (x[0] == '6' ? "64" : "80")});
    verify::LodPatches patches(t);
    std::vector<Diagnostic> errors;
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    std::unique_ptr<HullCapture> c = HullCapture::create(*gContext, p, patches, errors);
    INFO(formatDiagnosticsForTest(errors));
    REQUIRE(c);
    const auto t1 = Clock::now();
    std::vector<lod::PatchLod> out;
    std::string error;
    const int cameras = 20;
    for (int k = 0; k < cameras; ++k) {
      const bool ok = c->evaluate(patches, camera(), out, error);
      INFO(error);
      REQUIRE(ok);
  }
  const auto t2 = Clock::now();
  std::printf("%zu patches: create %.1f ms, %.2f ms per camera (%d cameras)\n", patches.size(),
              std::chrono::duration<double, std::milli>(t1 - t0).count(),
              std::chrono::duration<double, std::milli>(t2 - t1).count() / cameras, cameras);
  }
}

int main(int argc, char** argv) {
  gltest::GlContext ctx;
  std::string error;
  if (!ctx.create({}, error)) {
    if (std::getenv("CI")) {
      std::fprintf(stderr, "test_gpu_lod_hull_capture: FAILED: no OpenGL 4.5 context: %s (CI is set)\n", error.c_str());
      return 1;
    }
    std::fprintf(stderr, "test_gpu_lod_hull_capture: SKIPPED: no OpenGL 4.5 context: %s (would fail with CI set)\n",
                 error.c_str());
    return 77;
  }
  std::fprintf(stderr, "test_gpu_lod_hull_capture: renderer %s, %s\n", ctx.renderer().c_str(), ctx.version().c_str());
  gContext = &ctx;
  return Catch::Session().run(argc, argv);
}
