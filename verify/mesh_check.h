// fftess verify: the whole-mesh check (checkSceneMesh), a second, independent check of one camera that agrees with
// checkScene (check.h) on which patch edges are not watertight. Slow (every patch tessellated fully); for tests and
// `fftess check --mesh`.
#pragma once

#include "verify/check.h"
#include "verify/scene.h"
#include "verify/terrain.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fftess::verify {

// Whole-mesh check: tessellates every patch fully (fftess::Tessellator), builds a CGAL polygon soup, merges
// exactly-equal points, repairs degenerate polygons, converts it to a CGAL Surface_mesh and lists every border
// edge (CGAL Polygon Mesh Processing) that is not on the terrain's outer boundary. Each such edge is attributed to
// the patch edge it came from. Agrees with checkScene: the set of patch edges with inner border edges equals the
// set of patch edges that take part in a T-junction or crack finding (see flaggedPatchEdges).
struct PatchEdgeRef {
  int patch = -1;              // PatchRef::index
  int edge = 0;                // FactorIndex
  bool operator<(const PatchEdgeRef& o) const { return patch != o.patch ? patch < o.patch : edge < o.edge; }
  bool operator==(const PatchEdgeRef& o) const { return patch == o.patch && edge == o.edge; }
};

// The result of one whole-mesh check (checkSceneMesh).
struct MeshReport {
  std::string error;             // non-empty: the camera is invalid and nothing was checked
  int64_t patchesDrawn = 0;
  int64_t triangles = 0;         // after removing degenerate (repeated-vertex) triangles
  int64_t vertices = 0;          // after merging exactly-equal points
  int64_t borderEdges = 0;       // all border edges
  int64_t innerBorderEdges = 0;  // border edges not on the terrain's outer boundary (cracks and T-junctions)
  std::vector<PatchEdgeRef> flagged; // sorted, unique: patch edges holding an inner border edge
  WorkStats work;                // this camera's work
};

// The whole-mesh check of one camera (see above). terrain: from prepareTerrain; camera as for checkScene; options:
// only its factors (the GPU path), flushDenormals and tessellator (the denormal rule) are used; no fault injection.
MeshReport checkSceneMesh(const Terrain& terrain, const Camera& camera, const CheckOptions& options = {});

// The patch edges of a report's non-matching findings (both sides), sorted and unique: compare with
// MeshReport::flagged. Needs maxFindings large enough that the report is not truncated.
std::vector<PatchEdgeRef> flaggedPatchEdges(const Report& report);

} // namespace fftess::verify
