// Public entry points: Tessellator, edge query, output counts. (Traces: trace.cpp; names: names.cpp.)
#include "tessellator.h"

#include <cstring>

#include "generate.h"

namespace fftess {
namespace {

bool isTriangles(OutputPrimitive p) { return p == OutputPrimitive::TriangleCw || p == OutputPrimitive::TriangleCcw; }

// Factors as the hardware stage receives them: options applied, then the HLSL stage if asked (D3D11.3 11.7.2,
// 11.7.7.1: inside reduction and pow2 rounding are the HLSL compiler's shader code, not the hardware's).
void hardwareFactors(const Patch& patch, const Options& options, float out[6], HlslFactors* hlsl) {
  if (patch.stage.hlsl) {
    const HlslFactors h = processHlslFactors(patch.domain, patch.partitioning, patch.stage, patch.factors, options);
    std::memcpy(out, h.rounded, sizeof h.rounded);
    if (hlsl) *hlsl = h;
  } else {
    for (int i = 0; i < 6; ++i) out[i] = applyOptions(patch.factors[i], options);
    if (hlsl) *hlsl = HlslFactors{};
  }
}

// Quad/tri Point and Line outputs: every point once, or the points joined in generation order.
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

int finishCounts(const OutputCounts& c, int triangleCount, OutputPrimitive primitive) {
  if (isTriangles(primitive)) return 3 * triangleCount;
  if (primitive == OutputPrimitive::Point) return c.points;
  return c.points > 0 ? 2 * (c.points - 1) : 0;
}

// Closed-form output sizes of processed factors (independent of the generation code).
OutputCounts quadCounts(const ProcessedQuad& q, OutputPrimitive primitive) {
  OutputCounts c;
  if (q.culled) return c;
  int triangleCount = 0;
  if (q.minimum) {
    c.points = 4;
    triangleCount = 2;
  } else {
    const int n[2] = {q.inside[0].numPoints, q.inside[1].numPoints};
    c.points = (n[0] - 2) * (n[1] - 2) - 4;
    int rowPoints[4];
    for (int e = 0; e < 4; ++e) {
      c.points += q.outer[e].numPoints;
      rowPoints[e] = q.outer[e].numPoints;
    }
    const int rings = ((n[0] + 1) >> 1) < ((n[1] + 1) >> 1) ? (n[0] + 1) >> 1 : (n[1] + 1) >> 1;
    for (int ring = 1; ring < rings; ++ring)
      for (int e = 0; e < 4; ++e) {
        const int inside = n[(e + 1) & 1] - 2 * ring;
        triangleCount += inside + rowPoints[e] - 2;
        rowPoints[e] = inside;
      }
    if (n[0] > n[1] && q.inside[1].odd)
      triangleCount += 2 * ((((n[0] >> 1) - (n[1] >> 1)) << 1) + (q.inside[0].odd ? 1 : 2));
    else if (n[1] >= n[0] && q.inside[0].odd)
      triangleCount += 2 * ((((n[1] >> 1) - (n[0] >> 1)) << 1) + (q.inside[1].odd ? 1 : 2));
  }
  c.indices = finishCounts(c, triangleCount, primitive);
  return c;
}

OutputCounts triCounts(const ProcessedTri& t, OutputPrimitive primitive) {
  OutputCounts c;
  if (t.culled) return c;
  int triangleCount = 0;
  if (t.minimum) {
    c.points = 3;
    triangleCount = 1;
  } else {
    const int n = t.inside.numPoints;
    const int r = (n >> 1) - 1;
    c.points = -3 + (t.inside.odd ? 3 * (r * (r + 1) - r) : 3 * r * (r + 1) + 1);
    int rowPoints[3];
    for (int e = 0; e < 3; ++e) {
      c.points += t.outer[e].numPoints;
      rowPoints[e] = t.outer[e].numPoints;
    }
    for (int ring = 1; ring < (n + 1) >> 1; ++ring)
      for (int e = 0; e < 3; ++e) {
        triangleCount += n - 2 * ring + rowPoints[e] - 2;
        rowPoints[e] = n - 2 * ring;
      }
    if (t.inside.odd) triangleCount += 1;
  }
  c.indices = finishCounts(c, triangleCount, primitive);
  return c;
}

OutputCounts isolineCounts(const ProcessedIsoline& l, OutputPrimitive primitive) {
  OutputCounts c;
  if (l.culled) return c;
  c.points = l.numLines * l.detail.numPoints;
  c.indices = primitive == OutputPrimitive::Point ? c.points : l.numLines * (l.detail.numPoints - 1) * 2;
  return c;
}

} // namespace

Tessellator::Tessellator() {
  points_.reserve(kMaxPoints);
  indices_.reserve(kMaxIndices);
}

namespace {

// Factors through both stages, sizes from the closed-form counts, then generation into the buffers that
// prepare(counts, writer) points the writer at.
template <class Prepare>
int tessellateWith(const Patch& patch, const Options& options, HlslFactors* hlsl, Prepare&& prepare) {
  float f[6];
  hardwareFactors(patch, options, f, hlsl);
  const bool triangles = isTriangles(patch.primitive);
  MeshWriter out;
  out.ccw = patch.primitive == OutputPrimitive::TriangleCcw;
  switch (patch.domain) {
  case Domain::Quad: {
    const ProcessedQuad q = processQuadFactors(f, patch.partitioning);
    prepare(quadCounts(q, patch.primitive), out);
    generateQuad(q, triangles, out);
    if (!triangles) trivialIndices(patch.primitive, out);
    break;
  }
  case Domain::Tri: {
    const ProcessedTri t = processTriFactors(f, patch.partitioning);
    prepare(triCounts(t, patch.primitive), out);
    generateTri(t, triangles, out);
    if (!triangles) trivialIndices(patch.primitive, out);
    break;
  }
  case Domain::Isoline: {
    const ProcessedIsoline l = processIsolineFactors(f[IsolineDensity], f[IsolineDetail], patch.partitioning);
    prepare(isolineCounts(l, patch.primitive), out);
    generateIsoline(l, patch.primitive == OutputPrimitive::Point, out);
    break;
  }
  }
  return out.numPoints;
}

} // namespace

// The output is written once, straight into points_ / indices_: their sizes come first from the closed-form
// counts (resize within the reserved capacity never allocates, and only zero-fills what grows).
int Tessellator::tessellate(const Patch& patch, const Options& options) {
  return tessellateWith(patch, options, &hlsl_, [this](const OutputCounts& c, MeshWriter& out) {
    points_.resize(size_t(c.points));
    indices_.resize(size_t(c.indices));
    out.points = points_.data();
    out.indices = indices_.data();
  });
}

int tessellateInto(const Patch& patch, const Options& options, DomainPoint* points, int32_t* indices) {
  return tessellateWith(patch, options, nullptr, [&](const OutputCounts&, MeshWriter& out) {
    out.points = points;
    out.indices = indices;
  });
}

// ---------------------------------------------------------------------------------------------------------------

EdgePoints edgePoints(float factor, Partitioning partitioning, const Stage& stage, const Options& options) {
  EdgePoints r;
  const ProcessedEdge e = processEdgeThroughStages(factor, partitioning, stage, options, nullptr);
  if (e.culled) {
    r.culled = true;
    return r;
  }
  r.processedFactor = e.rounded;
  r.fixedFactor = e.fixed;
  r.oddParity = e.odd;
  const AxisSpacing s = makeAxisSpacing(e.fixed, e.odd);
  r.count = s.numPoints;
  for (int k = 0; k < s.numPoints; ++k) {
    r.fixed[k] = placePoint(s, k);
    r.param[k] = fx::fixedToFloat(r.fixed[k]);
  }
  return r;
}

bool edgeCulled(float factor, Partitioning partitioning, const Stage& stage, const Options& options) {
  return processEdgeThroughStages(factor, partitioning, stage, options, nullptr).culled;
}

// ---------------------------------------------------------------------------------------------------------------

OutputCounts outputCounts(const Patch& patch, const Options& options) {
  float f[6];
  hardwareFactors(patch, options, f, nullptr);
  switch (patch.domain) {
  case Domain::Quad: return quadCounts(processQuadFactors(f, patch.partitioning), patch.primitive);
  case Domain::Tri: return triCounts(processTriFactors(f, patch.partitioning), patch.primitive);
  case Domain::Isoline:
    return isolineCounts(processIsolineFactors(f[IsolineDensity], f[IsolineDetail], patch.partitioning),
                         patch.primitive);
  }
  return {};
}

} // namespace fftess
