// gpu_lod/wrapper.h: the GLSL 4.50 compute source of the GPU LOD. Prelude (lod/shaders/*.glsl, the interface types,
// the scene's LodSettings), then the user's file or the built-in scheme's evaluation, then the buffer main.
#include "gpu_lod/wrapper.h"

#include "lod/glsl_settings.h"

namespace fftess::gpulod::detail {

const char* const kSignatureGlsl = "LodFactors lodMain(LodPatch quad, TileNeighbourInfo neighbours, LodCamera camera, "
                                   "LodSettings settings)";

namespace {

namespace vf = fftess::verify;

const char* const kGlslTypes = R"(
// fftess GPU LOD interface (docs/gpu_lod.md).
struct LodPatch {
  vec3 corners[4];       // corners[u + 2v], displaced as lod.displaced_corners says
  bool useHeightBounds;  // widen the culling box's y to [minHeight, maxHeight]
  float minHeight;
  float maxHeight;
};
struct LodFactors {
  float factor[6];       // Ueq0 Veq0 Ueq1 Veq1 insideU insideV
  bool culled;           // you culled the patch on purpose (write factors <= 0 too, or the tessellator draws it)
};
)";

// The built-in scheme's evaluation, with the scene's parameters as exact constants, every settings field set by name
// (lod::glslSettings, from lod/lod_fields.h): what lod_bridge.cpp patchLod calls on the CPU.
std::string glslBuiltin(const vf::Lod& L, bool tile) {
  const std::string corners = "p.corners[0], p.corners[1], p.corners[2], p.corners[3], p.useHeightBounds, "
                              "p.minHeight, p.maxHeight";
  const lod::TileAdjacency adjacency{L.screenSphere.clamp, L.screenSphere.reconstruction};
  const std::string adj = tile ? lod::glslSettings("adj", adjacency) : std::string();
  // settings: the statements that set `var`; plain / tiled: the function without / with the neighbour rule.
  auto call = [&](const std::string& settings, const char* var, const char* plain, const char* tiled) {
    return settings + (tile ? adj + "  return " + tiled + "(" + corners + ", n, cam, " + var + ", adj);\n"
                            : "  return " + std::string(plain) + "(" + corners + ", cam, " + var + ");\n");
  };
  std::string s = "LodResult fftessEvaluate(LodPatch p, TileNeighbourInfo n, LodCamera cam) {\n";
  switch (L.scheme) {
  case vf::LodScheme::ScreenSphere:
    s += tile ? lod::glslSettings("ts", L.screenSphere) + "  return nvidiaTileLod(" + corners + ", n, cam, ts);\n"
              : lod::glslSettings("ss", L.screenSphere.sphere) + "  return screenSphereLod(" + corners + ", cam, ss);\n";
    break;
  case vf::LodScheme::PatchCenter:
    s += lod::glslSettings("ss", L.screenSphere.sphere) + "  return patchCenterLod(" + corners + ", cam, ss);\n";
    break;
  case vf::LodScheme::DistancePow2:
    s += call(lod::glslSettings("ds", L.distancePow2), "ds", "distancePow2Lod", "distancePow2TileLod");
    break;
  case vf::LodScheme::Bonaventura:
    s += call(lod::glslSettings("bs", L.bonaventura), "bs", "bonaventuraLod", "bonaventuraTileLod");
    break;
  case vf::LodScheme::ClipDiameter:
    s += call(lod::glslSettings("cs", L.clipDiameter), "cs", "clipDiameterLod", "clipDiameterTileLod");
    break;
  case vf::LodScheme::Constant:
    s += tile ? adj + "  return constantTileLod(" + lod::glslFloat(L.factor) + ", n, adj);\n"
              : "  LodResult r = emptyLodResult();\n  for (int i = 0; i < 6; ++i) { r.e[i].factor = " +
                    lod::glslFloat(L.factor) + "; }\n  return r;\n";
    break;
  case vf::LodScheme::Geomorph:
  case vf::LodScheme::Shader: s += "  return emptyLodResult();\n"; break;
  }
  return s + "}\n";
}

// The user's lodMain, wrapped into a LodResult (no record: metric 0, unclamped = factor, no fix bits).
const char* const kGlslUserEvaluate = R"(LodResult fftessEvaluate(LodPatch p, TileNeighbourInfo n, LodCamera cam) {
  LodFactors f = lodMain(p, n, cam, fftessSettings());
  LodResult r = emptyLodResult();
  for (int i = 0; i < 6; ++i) {
    r.e[i] = makeEdgeLod(f.factor[i], 0.0f, f.factor[i], 0.0f, 0);
  }
  // Culled on purpose only where the tessellator discards the patch (some outer factor NaN or <= 0).
  bool discards = false;
  for (int i = 0; i < 4; ++i) {
    if (!(f.factor[i] > 0.0f)) { discards = true; }
  }
  r.culled = f.culled && discards;
  if (r.culled) {
    for (int i = 0; i < 6; ++i) { r.e[i].fixes = kFixCulled; }
  }
  return r;
}
)";

// The buffers (kInWords, kCamWords, kOutWords in wrapper.h) -> fftessEvaluate -> the output buffer.
const char* const kGlslMain = R"(
float fftessInF(uint w) { return uintBitsToFloat(fftessIn[w]); }
vec3 fftessInV3(uint w) { return vec3(fftessInF(w), fftessInF(w + 1u), fftessInF(w + 2u)); }
float fftessCamF(uint w) { return uintBitsToFloat(fftessCam[w]); }
void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= fftessCam[38]) { return; }
  LodCamera cam;
  for (int k = 0; k < 4; ++k) {
    cam.view[k] = vec4(fftessCamF(uint(k * 4)), fftessCamF(uint(k * 4 + 1)), fftessCamF(uint(k * 4 + 2)),
                       fftessCamF(uint(k * 4 + 3)));
    cam.proj[k] = vec4(fftessCamF(uint(16 + k * 4)), fftessCamF(uint(16 + k * 4 + 1)), fftessCamF(uint(16 + k * 4 + 2)),
                       fftessCamF(uint(16 + k * 4 + 3)));
  }
  cam.viewport = vec2(fftessCamF(32u), fftessCamF(33u));
  cam.eye = vec3(fftessCamF(34u), fftessCamF(35u), fftessCamF(36u));
  cam.depthZeroToOne = fftessCam[37] != 0u;
  uint b = i * 37u;
  LodPatch p;
  for (int c = 0; c < 4; ++c) { p.corners[c] = fftessInV3(b + uint(c * 3)); }
  p.useHeightBounds = fftessIn[b + 12u] != 0u;
  p.minHeight = fftessInF(b + 13u);
  p.maxHeight = fftessInF(b + 14u);
  TileNeighbourInfo n;
  for (int e = 0; e < 4; ++e) {
    n.size[e] = fftessInF(b + 15u + uint(e));
    n.farCorner[e] = fftessInV3(b + 21u + uint(e * 3));
    n.rebuiltHeight[e] = fftessInF(b + 33u + uint(e));
  }
  n.oddU = fftessIn[b + 19u] != 0u;
  n.oddV = fftessIn[b + 20u] != 0u;
  LodResult r = fftessEvaluate(p, n, cam);
  uint o = i * 35u;
  for (int k = 0; k < 6; ++k) {
    fftessOut[o + uint(k * 5)] = floatBitsToUint(r.e[k].factor);
    fftessOut[o + uint(k * 5 + 1)] = floatBitsToUint(r.e[k].metric);
    fftessOut[o + uint(k * 5 + 2)] = floatBitsToUint(r.e[k].unclamped);
    fftessOut[o + uint(k * 5 + 3)] = floatBitsToUint(r.e[k].exponent);
    fftessOut[o + uint(k * 5 + 4)] = uint(r.e[k].fixes);
  }
  for (int c = 0; c < 4; ++c) { fftessOut[o + 30u + uint(c)] = floatBitsToUint(r.cornerLevel[c]); }
  fftessOut[o + 34u] = r.culled ? 1u : 0u;
}
)";

} // namespace

std::string glslComputeSource(const vf::Lod& L, const std::string& user, bool sizeJumps) {
  std::string s = "#version 450\n#line " + std::to_string(kPreludeLine) + "\n" +
                  "layout(local_size_x = 64) in;\n"
                  "layout(std430, binding = 0) readonly buffer FftessIn { uint fftessIn[]; };\n"
                  "layout(std430, binding = 1) writeonly buffer FftessOut { uint fftessOut[]; };\n"
                  "layout(std430, binding = 2) readonly buffer FftessCam { uint fftessCam[]; };\n";
  for (int i = 0; i < lod::glslSourceCount(); ++i) s += std::string(lod::glslSource(i)) + "\n";
  s += kGlslTypes + lodSettingsStruct() + lodSettingsFunction(L, false);
  const std::string wrapperLine = "#line " + std::to_string(kWrapperLine) + "\n";
  if (!user.empty()) {
    s += "#line 1\n" + user + "\n" + wrapperLine + kGlslUserEvaluate;
  } else {
    s += wrapperLine + glslBuiltin(L, sizeJumps);
  }
  return s + kGlslMain;
}

} // namespace fftess::gpulod::detail
