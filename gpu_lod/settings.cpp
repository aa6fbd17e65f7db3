// gpu_lod/wrapper.h: the user's LodSettings (docs/gpu_lod.md), one list for the GLSL and the HLSL struct and for the
// values the wrapper's fftessSettings() returns.
#include "gpu_lod/wrapper.h"

#include "base/bits.h"
#include "lod/glsl_settings.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace fftess::gpulod::detail {

namespace {

namespace vf = fftess::verify;

// "kClampNone 0, kClampInteger 1, kClampPow2 2": the codes of one enum (lod/lod_fields.h).
#define FFTESS_GPULOD_CODE_TEXT(Enum, enumerator, constant, code) ", " #constant " " #code
const std::string kClampCodes = std::string(FFTESS_LOD_ADJACENCY_CLAMP_CODES(FFTESS_GPULOD_CODE_TEXT)).substr(2);
const std::string kRebuildCodes = std::string(FFTESS_LOD_RECONSTRUCTION_CODES(FFTESS_GPULOD_CODE_TEXT)).substr(2);
#undef FFTESS_GPULOD_CODE_TEXT

enum class Type { Int, Float, Bool };

struct Setting {
  Type type;
  const char* name;
  std::string doc; // the scene key it comes from
  float f = 0.0f;  // Float
  int i = 0;       // Int, Bool (0 / 1)
};

// The fields of LodSettings, in order, with the scene's values (a default-constructed Lod for the declaration).
std::vector<Setting> settings(const vf::Lod& L) {
  const lod::ScreenSphereParams& sp = L.screenSphere.sphere;
  const lod::DistancePow2Params& dp = L.distancePow2;
  return {{Type::Int, "clampMode", "lod.adjacency_clamp: " + kClampCodes, 0, lod::shaderCode(L.screenSphere.clamp)},
          {Type::Int, "rebuild", "lod.reconstruction: " + kRebuildCodes, 0,
           lod::shaderCode(L.screenSphere.reconstruction)},
          {Type::Float, "targetPixels", "lod.target_pixels", sp.tessellatedTriWidth},
          {Type::Float, "minFactor", "lod.min_factor", sp.minFactor},
          {Type::Float, "maxFactor", "lod.max_factor", sp.maxFactor},
          {Type::Float, "minDistance", "lod.min_distance", dp.minDistance},
          {Type::Float, "maxDistance", "lod.max_distance", dp.maxDistance},
          {Type::Float, "minTess", "lod.min_tess", dp.minTessExponent},
          {Type::Float, "maxTess", "lod.max_tess", dp.maxTessExponent},
          {Type::Bool, "frustumCull", "lod.frustum_cull", 0.0f, sp.frustumCull ? 1 : 0},
          {Type::Float, "edgesPerScreenHeight", "lod.edges_per_screen_height", L.clipDiameter.edgesPerScreenHeight},
          {Type::Float, "factor", "lod.factor", L.factor}};
}

const char* typeName(Type t) { return t == Type::Int ? "int" : t == Type::Float ? "float" : "bool"; }

std::string hlslFloat(float f) {
  char b[48];
  std::snprintf(b, sizeof b, "asfloat(0x%08xu)", bitsOf(f));
  return b;
}

} // namespace

std::string lodSettingsStruct() {
  std::string s = "struct LodSettings {\n";
  for (const Setting& f : settings(vf::Lod{})) {
    std::string line = std::string("  ") + typeName(f.type) + " " + f.name + ";";
    line.resize(std::max<size_t>(line.size() + 1, 25), ' ');
    s += line + "// " + f.doc + "\n";
  }
  return s + "};\n";
}

std::string lodSettingsFunction(const vf::Lod& L, bool hlsl) {
  std::string s = "LodSettings fftessSettings() {\n  LodSettings s;\n";
  for (const Setting& f : settings(L)) {
    s += std::string("  s.") + f.name + " = ";
    if (f.type == Type::Float) s += hlsl ? hlslFloat(f.f) : lod::glslFloat(f.f);
    else if (f.type == Type::Bool) s += f.i != 0 ? "true" : "false";
    else s += std::to_string(f.i);
    s += ";\n";
  }
  return s + "  return s;\n}\n";
}

} // namespace fftess::gpulod::detail
