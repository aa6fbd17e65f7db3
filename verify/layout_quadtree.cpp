// layout.kind = "quadtree" (verify/internal.h). PLACEHOLDER: the quadtree helper replaces this file.
#include "verify/internal.h"

namespace fftess::verify::detail {

struct QuadtreeNodes {};

bool prepareQuadtree(TerrainData& t, std::string& error) {
  (void)t;
  error = "layout.kind = \"quadtree\" is not implemented yet";
  return false;
}

void cameraLayout(const TerrainData& prepared, const Camera& camera, TerrainData& out, WorkStats& work) {
  (void)prepared;
  (void)camera;
  (void)out;
  (void)work;
}

} // namespace fftess::verify::detail
