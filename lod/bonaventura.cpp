// fftess lod, scheme 4: rounded-exponent power of two with camera-angle correction.
// The arithmetic is lod/shaders/bonaventura.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod bonaventura(const Patch& patch, const Camera& camera, const BonaventuraParams& params) {
  const glsl::BonaventuraSettings s = detail::toGlsl(params);
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::bonaventuraLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                           patch.maxHeight, detail::toGlsl(camera), s);
  return detail::fromGlsl(r, Scheme::Bonaventura);
}

PatchLod bonaventuraTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                         const BonaventuraParams& params, const TileAdjacency& adjacency) {
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::bonaventuraTileLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                               patch.maxHeight, detail::toGlsl(neighbours), detail::toGlsl(camera),
                                               detail::toGlsl(params), detail::toGlsl(adjacency));
  return detail::fromGlsl(r, Scheme::Bonaventura);
}

} // namespace fftess::lod
