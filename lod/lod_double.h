// The screen-space sphere LOD (lod/shaders/screen_sphere.glsl and nvidia_tile.glsl) evaluated in double precision:
// the same shader source compiled through GLM with every float, vec and mat in double, from the same float inputs
// (corners, camera matrices, parameters), the factors rounded to float at the end. Not the hull shader (which is
// single precision): a measuring stick for `fftess bench` (what float precision in the LOD changes). Only this one
// scheme; the others are not compiled in double.
#pragma once

#include "lod/lod.h"

namespace fftess::lod {

PatchLod screenSphereDouble(const Patch& patch, const Camera& camera, const ScreenSphereParams& params);
PatchLod nvidiaTileDouble(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const NvidiaTileParams& params);

} // namespace fftess::lod
