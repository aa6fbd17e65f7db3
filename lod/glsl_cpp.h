// Internal: the shared lod/shaders/*.glsl compiled as C++ through GLM.
//
// The shim: the .glsl files are included inside namespace fftess::lod::glsl with `using namespace glm;`, so vec3,
// mat4, min, max, floor, ceil, exp2, sqrt, acos and abs resolve to GLM's (single precision; GLM's scalar
// functions call the float overloads of <cmath>). Nothing else is needed: the files avoid every construct the two
// languages spell differently (array constructors, out/inout, swizzle writes of more than one component,
// unsuffixed float literals). Compile with -ffp-contract=off (the top-level CMake does) so no FMA is formed.
#pragma once

#include <glm/glm.hpp>

#include "lod/lod.h"

namespace fftess::lod::glsl {
using namespace glm;
#include "shaders/common.glsl"
#include "shaders/screen_sphere.glsl"
#include "shaders/nvidia_tile.glsl"
#include "shaders/distance_pow2.glsl"
#include "shaders/bonaventura.glsl"
#include "shaders/clip_diameter.glsl"
#include "shaders/geomorph.glsl"
} // namespace fftess::lod::glsl

namespace fftess::lod::detail {
// Public structs -> shader structs, and the shader result -> PatchLod (defined in lod_common.cpp).
glsl::LodCamera toGlsl(const Camera& camera);
PatchLod fromGlsl(const glsl::LodResult& result, Scheme scheme);
int insideRuleCode(InsideRule rule);
glsl::ScreenSphereSettings toGlsl(const ScreenSphereParams& params); // screen_sphere.cpp
} // namespace fftess::lod::detail
