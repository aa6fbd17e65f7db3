// lod/glsl_settings.h: the *Settings structs as GLSL text, field by field from lod/lod_fields.h.
#include "lod/glsl_settings.h"

#include <cstdio>

#include "base/bits.h"

namespace fftess::lod {

#define FFTESS_LOD_CODE_NAME(Enum, enumerator, constant, code)                                                     \
  case Enum::enumerator:                                                                                          \
    return #constant;
const char* glslCodeName(InsideRule v) {
  switch (v) { FFTESS_LOD_INSIDE_RULE_CODES(FFTESS_LOD_CODE_NAME) }
  return "kInsideAverage";
}
const char* glslCodeName(AdjacencyClamp v) {
  switch (v) { FFTESS_LOD_ADJACENCY_CLAMP_CODES(FFTESS_LOD_CODE_NAME) }
  return "kClampNone";
}
const char* glslCodeName(Reconstruction v) {
  switch (v) { FFTESS_LOD_RECONSTRUCTION_CODES(FFTESS_LOD_CODE_NAME) }
  return "kRebuildEdgeVector";
}
const char* glslCodeName(SphereCentre v) {
  switch (v) { FFTESS_LOD_SPHERE_CENTRE_CODES(FFTESS_LOD_CODE_NAME) }
  return "kCentreHalfSum";
}
#undef FFTESS_LOD_CODE_NAME

std::string glslFloat(float f) {
  char b[48];
  std::snprintf(b, sizeof b, "uintBitsToFloat(0x%08xu)", bitsOf(f));
  return b;
}

namespace {

// One statement "  PATH = VALUE;" per leaf field; a nested *Params recurses with PATH.member.
void put(std::string& out, const std::string& path, const std::string& value) {
  out += "  " + path + " = " + value + ";\n";
}
void put(std::string& out, const std::string& path, float v) { put(out, path, glslFloat(v)); }
void put(std::string& out, const std::string& path, bool v) { put(out, path, std::string(v ? "true" : "false")); }
void put(std::string& out, const std::string& path, InsideRule v) { put(out, path, std::string(glslCodeName(v))); }
void put(std::string& out, const std::string& path, AdjacencyClamp v) { put(out, path, std::string(glslCodeName(v))); }
void put(std::string& out, const std::string& path, Reconstruction v) { put(out, path, std::string(glslCodeName(v))); }
void put(std::string& out, const std::string& path, SphereCentre v) { put(out, path, std::string(glslCodeName(v))); }
void put(std::string& out, const std::string& path, const glm::vec3& v) {
  put(out, path, "vec3(" + glslFloat(v.x) + ", " + glslFloat(v.y) + ", " + glslFloat(v.z) + ")");
}

#define FFTESS_LOD_DECLARE_PUT(Params, Settings, file, FIELDS)                                                     \
  void put(std::string& out, const std::string& path, const Params& p);
FFTESS_LOD_SCHEMES(FFTESS_LOD_DECLARE_PUT)
#undef FFTESS_LOD_DECLARE_PUT

#define FFTESS_LOD_PUT_FIELD(cppType, cppName, cppDefault, shaderType, shaderName)                                 \
  put(out, path + "." #shaderName, p.cppName);
#define FFTESS_LOD_DEFINE_PUT(Params, Settings, file, FIELDS)                                                      \
  void put(std::string& out, const std::string& path, const Params& p) { FIELDS(FFTESS_LOD_PUT_FIELD) }
FFTESS_LOD_SCHEMES(FFTESS_LOD_DEFINE_PUT)
#undef FFTESS_LOD_DEFINE_PUT
#undef FFTESS_LOD_PUT_FIELD

} // namespace

#define FFTESS_LOD_DEFINE_SETTINGS(Params, Settings, file, FIELDS)                                                 \
  std::string glslSettings(const std::string& var, const Params& params) {                                        \
    std::string out = "  " #Settings " " + var + ";\n";                                                           \
    put(out, var, params);                                                                                        \
    return out;                                                                                                   \
  }
FFTESS_LOD_SCHEMES(FFTESS_LOD_DEFINE_SETTINGS)
#undef FFTESS_LOD_DEFINE_SETTINGS

} // namespace fftess::lod
