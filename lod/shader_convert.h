// Internal (lod/glsl_cpp.h, lod/lod_double.cpp): lod.h's *Params -> a C++ build's *Settings structs, field by field
// and by name from lod/lod_fields.h. The same template serves the float build (glsl::*Settings: float, vec3) and
// the double build (glsld::*Settings: double, dvec3): each member is converted to its own type.
#pragma once

#include "lod/glsl_settings.h" // shaderCode
#include "lod/lod.h"

namespace fftess::lod::convert {

// T: the type of one shader struct member. A *Settings struct is value-initialised first (every member zero / false),
// then every field of the list is set: no member is left uninitialised, whatever the .glsl struct holds.
template <class T>
struct ShaderValue {
  // float, bool, glm vectors: T(v) (float -> float or double, exact; vec3 -> vec3 or dvec3, exact).
  template <class V>
  static T from(const V& v) {
    return T(v);
  }
  static T from(InsideRule v) { return T(shaderCode(v)); }
  static T from(AdjacencyClamp v) { return T(shaderCode(v)); }
  static T from(Reconstruction v) { return T(shaderCode(v)); }
  static T from(SphereCentre v) { return T(shaderCode(v)); }

#define FFTESS_LOD_ASSIGN_SETTING(cppType, cppName, cppDefault, shaderType, shaderName)                            \
  s.shaderName = ShaderValue<decltype(s.shaderName)>::from(p.cppName);
#define FFTESS_LOD_SETTINGS_FROM(Params, Settings, file, FIELDS)                                                   \
  static T from(const Params& p) {                                                                                \
    T s{};                                                                                                        \
    FIELDS(FFTESS_LOD_ASSIGN_SETTING)                                                                             \
    return s;                                                                                                     \
  }
  FFTESS_LOD_SCHEMES(FFTESS_LOD_SETTINGS_FROM)
#undef FFTESS_LOD_SETTINGS_FROM
#undef FFTESS_LOD_ASSIGN_SETTING
};

} // namespace fftess::lod::convert
