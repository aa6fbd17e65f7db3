// Internal: the shared lod/shaders/*.glsl compiled as C++ through GLM.
//
// The shim: the .glsl files are included inside an unnamed namespace in fftess::lod (so each .cpp gets its own
// internal copy and nothing clashes at link time), in namespace glsl with `using namespace glm;`, so vec3, mat4,
// min, max, floor, ceil, exp2, sqrt, acos and abs resolve to GLM's (single precision; GLM's scalar functions call
// the float overloads of <cmath>). Nothing else is needed: the files avoid every construct the two languages spell
// differently (array constructors, out/inout, multi-component swizzle writes, unsuffixed float literals).
// Compile with -ffp-contract=off (lod/CMakeLists.txt and the top level do) so no FMA is formed.
#pragma once

#include <glm/glm.hpp>

#include "lod/lod.h"
#include "lod/shader_convert.h"

namespace fftess::lod {
namespace {

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
namespace glsl {
using namespace glm;
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#include "shaders/distance_pow2.glsl"
#include "shaders/bonaventura.glsl"
#include "shaders/clip_diameter.glsl"
#include "shaders/geomorph.glsl"
} // namespace glsl

// The shader's fix bits are the public enum's.
static_assert(glsl::kFixClampedMin == FixClampedMin && glsl::kFixClampedMax == FixClampedMax &&
                  glsl::kFixCulled == FixCulled && glsl::kFixLargerNeighbour == FixLargerNeighbour &&
                  glsl::kFixSmallerNeighbour == FixSmallerNeighbour && glsl::kFixIntegerClamp == FixIntegerClamp &&
                  glsl::kFixPow2Clamp == FixPow2Clamp && glsl::kFixAngleCorrection == FixAngleCorrection &&
                  glsl::kFixRoundedExponent == FixRoundedExponent &&
                  glsl::kFixCoarserNeighbour == FixCoarserNeighbour && glsl::kFixLiteralSource == FixLiteralSource,
              "lod/shaders/common.glsl fix bits must equal fftess::lod::Fix");

// The shaders' enum constants are lod/lod_fields.h's codes.
#define FFTESS_LOD_CHECK_CODE(Enum, enumerator, constant, code)                                                    \
  static_assert(glsl::constant == (code), "lod/shaders/*.glsl: " #constant " must equal lod/lod_fields.h's code");
FFTESS_LOD_ENUM_CODES(FFTESS_LOD_CHECK_CODE)
#undef FFTESS_LOD_CHECK_CODE

namespace detail {

// Public structs -> shader structs, and the shader result -> PatchLod. lod.h's parameter structs and the shaders'
// settings structs cannot be one type: a GLSL struct has no default member initialisers and no constructors, GLSL
// has no enums (the shaders take int codes; lod.h takes InsideRule, AdjacencyClamp, Reconstruction), and the shader
// structs are compiled per translation unit inside an unnamed namespace, so they cannot appear in a public header.
// Both are spelled by one field list per scheme, lod/lod_fields.h.
glsl::LodCamera toGlsl(const Camera& camera) {
  glsl::LodCamera c;
  c.view = camera.view;
  c.proj = camera.projection;
  c.viewport = camera.viewport;
  c.eye = camera.eye;
  c.depthZeroToOne = camera.depthZeroToOne;
  return c;
}

// lod.h's *Params -> the shaders' *Settings, field by field from lod/lod_fields.h (lod/shader_convert.h).
#define FFTESS_LOD_TO_GLSL(Params, Settings, file, FIELDS)                                                         \
  glsl::Settings toGlsl(const Params& p) { return convert::ShaderValue<glsl::Settings>::from(p); }
FFTESS_LOD_SCHEMES(FFTESS_LOD_TO_GLSL)
#undef FFTESS_LOD_TO_GLSL

glsl::TileNeighbourInfo toGlsl(const TileNeighbours& t) {
  glsl::TileNeighbourInfo n;
  for (int i = 0; i < 4; ++i) {
    n.size[i] = t.size[i];
    n.farCorner[i] = t.farCorner[i];
    n.rebuiltHeight[i] = t.rebuiltHeight[i];
  }
  n.oddU = t.oddU;
  n.oddV = t.oddV;
  return n;
}

PatchLod fromGlsl(const glsl::LodResult& result, Scheme scheme) {
  PatchLod out;
  out.why.scheme = scheme;
  out.why.culled = result.culled;
  for (int i = 0; i < 6; ++i) {
    const glsl::EdgeLod& e = result.e[i];
    out.factors[i] = e.factor;
    out.why.factor[i].metric = e.metric;
    out.why.factor[i].unclamped = e.unclamped;
    out.why.factor[i].exponent = e.exponent;
    out.why.factor[i].fixes = static_cast<uint32_t>(e.fixes);
  }
  for (int i = 0; i < 4; ++i) {
    out.why.cornerLevel[i] = result.cornerLevel[i];
  }
  return out;
}

} // namespace detail
#pragma GCC diagnostic pop

} // namespace
} // namespace fftess::lod
