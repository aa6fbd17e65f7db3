// fftess lod: the shaders' settings as GLSL text, for whoever runs lod::glslSource(...) on a GPU (the GPU LOD
// provider in gpu_lod/, tests/lod/test_glsl.cpp, tests/tools/lod_gpu_drift). Produced from the field lists in
// lod/lod_fields.h: every field of a *Settings struct is set by name (never by a positional constructor), floats as
// their exact bits, enum members as the GLSL constant of their code.
#pragma once

#include <string>

#include "lod/lod.h"

namespace fftess::lod {

// The int a shader takes for an enum value (lod_fields.h FFTESS_LOD_*_CODES). A value outside the enum gets the
// first entry's code (Average, None, EdgeVector: 0).
#define FFTESS_LOD_CODE_CASE(Enum, enumerator, constant, code)                                                     \
  case Enum::enumerator:                                                                                          \
    return code;
inline int shaderCode(InsideRule v) {
  switch (v) { FFTESS_LOD_INSIDE_RULE_CODES(FFTESS_LOD_CODE_CASE) }
  return 0;
}
inline int shaderCode(AdjacencyClamp v) {
  switch (v) { FFTESS_LOD_ADJACENCY_CLAMP_CODES(FFTESS_LOD_CODE_CASE) }
  return 0;
}
inline int shaderCode(Reconstruction v) {
  switch (v) { FFTESS_LOD_RECONSTRUCTION_CODES(FFTESS_LOD_CODE_CASE) }
  return 0;
}
inline int shaderCode(SphereCentre v) {
  switch (v) { FFTESS_LOD_SPHERE_CENTRE_CODES(FFTESS_LOD_CODE_CASE) }
  return 0;
}
#undef FFTESS_LOD_CODE_CASE

// The GLSL constant that holds shaderCode(v): "kInsideMin", "kClampPow2", "kRebuildResampled".
const char* glslCodeName(InsideRule v);
const char* glslCodeName(AdjacencyClamp v);
const char* glslCodeName(Reconstruction v);
const char* glslCodeName(SphereCentre v); // "kCentreHalfSum", "kCentreAroundQuadScaled"

// A float as exact GLSL, no decimal round trip: "uintBitsToFloat(0x40400000u)" for 3.0f (NaN payloads, -0 and
// denormals kept).
std::string glslFloat(float f);

// GLSL statements (two-space indent, one a line) that declare `var` as the scheme's *Settings struct and set every
// field from `params`, e.g. for ScreenSphereParams and var "ss":
//   ScreenSphereSettings ss;
//   ss.triWidth = uintBitsToFloat(0x40400000u);
//   ss.minFactor = ...; ss.maxFactor = ...; ss.insideRule = kInsideAverage; ss.frustumCull = true; ...
// A nested struct is set field by field too (TileSettings: ts.sphere.triWidth = ...). Needs the .glsl that declares
// the struct (and common.glsl / nvidia_tile.glsl for the constants) before it.
std::string glslSettings(const std::string& var, const ScreenSphereParams& params);  // ScreenSphereSettings
std::string glslSettings(const std::string& var, const NvidiaTileParams& params);    // TileSettings
std::string glslSettings(const std::string& var, const TileAdjacency& params);       // AdjacencySettings
std::string glslSettings(const std::string& var, const DistancePow2Params& params);  // DistancePow2Settings
std::string glslSettings(const std::string& var, const BonaventuraParams& params);   // BonaventuraSettings
std::string glslSettings(const std::string& var, const ClipDiameterParams& params);  // ClipDiameterSettings
std::string glslSettings(const std::string& var, const GeomorphParams& params);      // GeomorphSettings

} // namespace fftess::lod
