// fftess verify: the terrain as one camera draws it (viewMesh), for pictures of a check (`fftess check --gltf`).
// Every drawn patch tessellated fully by the emulator (fftess::Tessellator with the patch's hull factors, the
// scene's partitioning and stage, the check's denormal rule: what the whole-mesh check, mesh_check.h, tessellates)
// and every point put through the domain-shader emulation with this camera's domain state, so the world positions
// are the checker's, bit for bit. Patches the camera does not draw but a report lists (holes, undecided patches) can
// be filled with a grid over their domain, positioned the same way.
#pragma once

#include "tessellator/tessellator.h"
#include "verify/check.h"
#include "verify/scene.h"
#include "verify/terrain.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace fftess::verify {

// One patch of a ViewMesh: its points are ViewMesh::points[firstPoint .. firstPoint + pointCount) (and the same range
// of ViewMesh::domain), its triangles ViewMesh::indices[firstIndex .. firstIndex + indexCount) (three per triangle,
// indices into ViewMesh::points, in the order and winding the tessellator emits: OutputPrimitive::TriangleCw).
struct ViewPatch {
  PatchRef ref;                // ref.index: the patch's index in layoutFor(terrain, camera) and in a check's report
  float size = 0;              // world side of the patch (|corners[1] - corners[0]|, flat corners, float)
  float factors[6] = {0, 0, 0, 0, 0, 0}; // the hull factors tessellated (Ueq0 Veq0 Ueq1 Veq1 insideU insideV);
                               // all 0 for a fill (ViewMesh::fills: not drawn, not tessellated)
  uint32_t firstPoint = 0, pointCount = 0;
  uint32_t firstIndex = 0, indexCount = 0;
};

// The result of viewMesh.
struct ViewMesh {
  std::string error;               // non-empty: the camera is invalid (or its factors failed) and nothing was built
  std::vector<ViewPatch> patches;  // the drawn patches (tessellator output not empty), in layout order
  std::vector<int> drawnAt;        // per layout patch: its index into patches, -1 when the camera does not draw it
  std::vector<ViewPatch> fills;    // the patches asked for in `fill`, in the order asked
  std::vector<glm::vec3> points;   // world positions (the domain-shader emulation's float results)
  std::vector<DomainPoint> domain; // each point's (u, v) on its patch (the tessellator's; a fill's grid point)
  std::vector<uint32_t> indices;   // triangle list
  WorkStats work;                  // this camera's work (fullTessellations, domainEvaluations, lod/ calls, ...)
};

// The terrain as `camera` draws it. terrain: from prepareTerrain; camera as for checkScene; options: as
// checkSceneMesh reads them (the factors provider on the GPU path, flushDenormals, tessellator: the denormal rule).
// fill: patch indices (into layoutFor(terrain, camera)) to cover with a fillSegments x fillSegments grid of quads
// over their (u, v) domain, two triangles each, positioned by the domain-shader emulation with this camera's domain
// state ((fillSegments + 1)^2 points per patch; indices out of range are skipped). fillSegments: 1 .. 256.
ViewMesh viewMesh(const Terrain& terrain, const Camera& camera, const CheckOptions& options = {},
                  const std::vector<int>& fill = {}, int fillSegments = 8);

// The points of a drawn patch on its edge `edge` (FactorIndex) whose edge parameter (v on Ueq0 / Ueq1, u on Veq0 /
// Veq1) lies in [lo, hi], in increasing parameter order: the vertices of that part of the edge as drawn (a Finding's
// EdgeSide covers [paramLo, paramHi]). cover: also the last point before lo and the first after hi, so the polyline
// spans [lo, hi] where no vertex lies at lo or hi. Empty when the patch is not drawn.
std::vector<glm::vec3> edgePolyline(const ViewMesh& mesh, int patch, int edge, float lo = 0, float hi = 1,
                                    bool cover = false);

} // namespace fftess::verify
