// fftess lod, scheme 5: clip-space sphere diameter. The arithmetic is lod/shaders/clip_diameter.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod clipDiameter(const Patch& patch, const Camera& camera, const ClipDiameterParams& params) {
  const glsl::ClipDiameterSettings s = detail::toGlsl(params);
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::clipDiameterLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                            patch.maxHeight, detail::toGlsl(camera), s);
  return detail::fromGlsl(r, Scheme::ClipDiameter);
}

PatchLod clipDiameterTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                          const ClipDiameterParams& params, const TileAdjacency& adjacency) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::clipDiameterTileLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                                patch.maxHeight, detail::toGlsl(neighbours), detail::toGlsl(camera),
                                                detail::toGlsl(params), detail::toGlsl(adjacency));
  return detail::fromGlsl(r, Scheme::ClipDiameter);
}

} // namespace fftess::lod
