// fftess lod, scheme 3: distance-based power of two. The arithmetic is lod/shaders/distance_pow2.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod distancePow2(const Patch& patch, const Camera& camera, const DistancePow2Params& params) {
  const glsl::DistancePow2Settings s = detail::toGlsl(params);
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::distancePow2Lod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                            patch.maxHeight, detail::toGlsl(camera), s);
  return detail::fromGlsl(r, Scheme::DistancePow2);
}

PatchLod distancePow2Tile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const DistancePow2Params& params, const TileAdjacency& adjacency) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::distancePow2TileLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                                patch.maxHeight, detail::toGlsl(neighbours), detail::toGlsl(camera),
                                                detail::toGlsl(params), detail::toGlsl(adjacency));
  return detail::fromGlsl(r, Scheme::DistancePow2);
}

} // namespace fftess::lod
