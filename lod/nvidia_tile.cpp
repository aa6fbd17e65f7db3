// fftess lod, scheme 2: non-uniform patches in tile rings. The arithmetic is lod/shaders/nvidia_tile.glsl.
#include "lod/glsl_cpp.h"
#include "lod/lod.h"

namespace fftess::lod {

PatchLod nvidiaTile(const Patch& patch, const TileNeighbours& neighbours, const Camera& camera,
                    const NvidiaTileParams& params) {
  const glsl::TileSettings s = detail::toGlsl(params);
  const glsl::TileNeighbourInfo n = detail::toGlsl(neighbours);
  const glm::vec3* c = patch.corners;
  glsl::LodResult r = glsl::nvidiaTileLod(c[0], c[1], c[2], c[3], patch.useHeightBounds, patch.minHeight,
                                          patch.maxHeight, n, detail::toGlsl(camera), s);
  return detail::fromGlsl(r, Scheme::NvidiaTile);
}

glm::vec3 rebuiltCorner(glm::vec3 start, glm::vec3 end, bool odd) { return glsl::rebuiltCorner(start, end, odd); }

PatchLod constantTile(float factor, const TileNeighbours& neighbours, const TileAdjacency& adjacency) {
  return detail::fromGlsl(glsl::constantTileLod(factor, detail::toGlsl(neighbours), detail::toGlsl(adjacency)),
                          Scheme::Constant);
}

// The sample's AssignNeighbourSizes: a tile on the ring's outer border faces the next ring out (tiles twice the
// size) unless this ring is the outermost; a tile bordering the hole faces the ring in (tiles half the size).
TileSides assignNeighbourSizes(int tileX, int tileZ, int holeWidth, int outerWidth, bool outermost) {
  TileSides t;
  const float outer = outermost ? 1.0f : 2.0f;
  const int h0 = (outerWidth - holeWidth) / 2; // first hole tile
  const int h1 = h0 + holeWidth;               // one past the last hole tile
  const bool hole = holeWidth > 0;
  const bool xInHole = tileX >= h0 && tileX < h1;
  const bool zInHole = tileZ >= h0 && tileZ < h1;
  // Ueq0 (-x), Veq0 (-z), Ueq1 (+x), Veq1 (+z)
  if (tileX == 0) {
    t.size[0] = outer;
  } else if (hole && tileX == h1 && zInHole) {
    t.size[0] = 0.5f;
  }
  if (tileZ == 0) {
    t.size[1] = outer;
  } else if (hole && tileZ == h1 && xInHole) {
    t.size[1] = 0.5f;
  }
  if (tileX == outerWidth - 1) {
    t.size[2] = outer;
  } else if (hole && tileX == h0 - 1 && zInHole) {
    t.size[2] = 0.5f;
  }
  if (tileZ == outerWidth - 1) {
    t.size[3] = outer;
  } else if (hole && tileZ == h0 - 1 && xInHole) {
    t.size[3] = 0.5f;
  }
  return t;
}

TileNeighbours patchNeighbours(const TileSides& tile, int patchX, int patchZ, int patchesPerTile) {
  TileNeighbours n;
  n.size[0] = patchX == 0 ? tile.size[0] : 1.0f;
  n.size[1] = patchZ == 0 ? tile.size[1] : 1.0f;
  n.size[2] = patchX == patchesPerTile - 1 ? tile.size[2] : 1.0f;
  n.size[3] = patchZ == patchesPerTile - 1 ? tile.size[3] : 1.0f;
  n.oddU = (patchX & 1) != 0;
  n.oddV = (patchZ & 1) != 0;
  return n;
}

} // namespace fftess::lod
