// The old Tessellator::tessellate body (scratch buffers, then copy), for the differential test only.
#include "legacy.h"

#include <cstring>

#include "generate.h"

namespace fftess::legacy {
namespace {

bool isTriangles(OutputPrimitive p) { return p == OutputPrimitive::TriangleCw || p == OutputPrimitive::TriangleCcw; }

void trivialIndices(OutputPrimitive prim, MeshWriter& out) {
  if (prim == OutputPrimitive::Point) {
    for (int p = 0; p < out.numPoints; ++p) out.indices[out.numIndices++] = p;
  } else {
    for (int p = 1; p < out.numPoints; ++p) {
      out.indices[out.numIndices++] = p - 1;
      out.indices[out.numIndices++] = p;
    }
  }
}

} // namespace

int tessellate(const Patch& patch, const Options& options, std::vector<DomainPoint>& points,
               std::vector<int32_t>& indices) {
  float f[6];
  if (patch.stage.hlsl) {
    const HlslFactors h = processHlslFactors(patch.domain, patch.partitioning, patch.stage, patch.factors, options);
    std::memcpy(f, h.rounded, sizeof h.rounded);
  } else {
    for (int i = 0; i < 6; ++i) f[i] = applyOptions(patch.factors[i], options);
  }
  thread_local std::vector<DomainPoint> pts(kMaxPoints);
  thread_local std::vector<int32_t> idx(kMaxIndices);
  MeshWriter out;
  out.points = pts.data();
  out.indices = idx.data();
  out.ccw = patch.primitive == OutputPrimitive::TriangleCcw;
  const bool triangles = isTriangles(patch.primitive);
  switch (patch.domain) {
  case Domain::Quad:
    generateQuad(processQuadFactors(f, patch.partitioning), triangles, out);
    if (!triangles) trivialIndices(patch.primitive, out);
    break;
  case Domain::Tri:
    generateTri(processTriFactors(f, patch.partitioning), triangles, out);
    if (!triangles) trivialIndices(patch.primitive, out);
    break;
  case Domain::Isoline:
    generateIsoline(processIsolineFactors(f[IsolineDensity], f[IsolineDetail], patch.partitioning),
                    patch.primitive == OutputPrimitive::Point, out);
    break;
  }
  points.assign(out.points, out.points + out.numPoints);
  indices.assign(out.indices, out.indices + out.numIndices);
  return out.numPoints;
}

} // namespace fftess::legacy
