// Public entry points: Tessellator, edge query, trace, names, output counts.
#include "tessellator.h"

#include <cstring>

#include "generate.h"

namespace fftess {
namespace {

bool isTriangles(OutputPrimitive p) { return p == OutputPrimitive::TriangleCw || p == OutputPrimitive::TriangleCcw; }

// Factors as the hardware stage receives them: options applied, then the HLSL stage if asked.
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

static ProcessedEdge edgeThroughStages(float factor, Partitioning p, const Stage& stage, const Options& options,
                                       float* hlslFactor) {
  float f = applyOptions(factor, options);
  if (stage.hlsl && f > 0.0f) f = hlslOuterEdge(f, p);
  if (hlslFactor) *hlslFactor = f;
  return processOuterEdge(f, p);
}

EdgePoints edgePoints(float factor, Partitioning partitioning, const Stage& stage, const Options& options) {
  EdgePoints r;
  const ProcessedEdge e = edgeThroughStages(factor, partitioning, stage, options, nullptr);
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

EdgeTrace traceEdge(float factor, Partitioning partitioning, const Stage& stage, const Options& options) {
  EdgeTrace t;
  t.input = factor;
  t.flushedDenormal = fx::bitsOf(applyOptions(factor, options)) != fx::bitsOf(factor);
  const ProcessedEdge e = edgeThroughStages(factor, partitioning, stage, options, &t.hlslFactor);
  if (e.culled) {
    t.culled = true;
    return t;
  }
  t.clamped = e.clamped;
  t.rounded = e.rounded;
  t.oddParity = e.odd;
  t.fixedFactor = e.fixed;
  const AxisSpacing s = makeAxisSpacing(e.fixed, e.odd);
  t.halfFactor = s.halfFactor;
  t.floorHalf = s.floorHalf;
  t.ceilHalf = s.ceilHalf;
  t.halfFraction = s.halfFraction;
  t.numHalfPoints = s.numHalfPoints;
  t.splitPoint = s.splitPoint;
  t.floorSegments = s.floorSegments;
  t.ceilSegments = s.ceilSegments;
  t.reciprocalFloor = s.invFloorSegments;
  t.reciprocalCeil = s.invCeilSegments;
  t.count = s.numPoints;
  for (int k = 0; k < s.numPoints; ++k) {
    placePoint(s, k, &t.points[k]);
    t.points[k].param = fx::fixedToFloat(t.points[k].fixed);
  }
  return t;
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

// ---------------------------------------------------------------------------------------------------------------

const char* toString(Domain d) {
  switch (d) {
  case Domain::Quad: return "quad";
  case Domain::Tri: return "tri";
  case Domain::Isoline: return "isoline";
  }
  return "?";
}
const char* toString(Partitioning p) {
  switch (p) {
  case Partitioning::Integer: return "integer";
  case Partitioning::Pow2: return "pow2";
  case Partitioning::FractionalOdd: return "fractional_odd";
  case Partitioning::FractionalEven: return "fractional_even";
  }
  return "?";
}
const char* toString(OutputPrimitive p) {
  switch (p) {
  case OutputPrimitive::Point: return "point";
  case OutputPrimitive::Line: return "line";
  case OutputPrimitive::TriangleCw: return "triangle_cw";
  case OutputPrimitive::TriangleCcw: return "triangle_ccw";
  }
  return "?";
}

bool parseDomain(const char* s, Domain& out) {
  for (Domain d : {Domain::Quad, Domain::Tri, Domain::Isoline})
    if (std::strcmp(s, toString(d)) == 0) return out = d, true;
  return false;
}
bool parsePartitioning(const char* s, Partitioning& out) {
  for (Partitioning p :
       {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd, Partitioning::FractionalEven})
    if (std::strcmp(s, toString(p)) == 0) return out = p, true;
  return false;
}
bool parseOutputPrimitive(const char* s, OutputPrimitive& out) {
  for (OutputPrimitive p :
       {OutputPrimitive::Point, OutputPrimitive::Line, OutputPrimitive::TriangleCw, OutputPrimitive::TriangleCcw})
    if (std::strcmp(s, toString(p)) == 0) return out = p, true;
  return false;
}

namespace {
struct StageName {
  const char* name;
  Stage stage;
};
const StageName kStages[] = {
    {"hw", {false, Reduction::Average, ReductionAxes::TwoAxis}},
    {"hlsl-avg", {true, Reduction::Average, ReductionAxes::TwoAxis}},
    {"hlsl-min", {true, Reduction::Min, ReductionAxes::TwoAxis}},
    {"hlsl-max", {true, Reduction::Max, ReductionAxes::TwoAxis}},
    {"hlsl-avg-1axis", {true, Reduction::Average, ReductionAxes::OneAxis}},
    {"hlsl-min-1axis", {true, Reduction::Min, ReductionAxes::OneAxis}},
    {"hlsl-max-1axis", {true, Reduction::Max, ReductionAxes::OneAxis}},
};
} // namespace

bool parseStage(const char* s, Stage& out) {
  for (const StageName& n : kStages)
    if (std::strcmp(s, n.name) == 0) return out = n.stage, true;
  return false;
}
const char* toString(const Stage& s) {
  if (!s.hlsl) return "hw";
  for (const StageName& n : kStages)
    if (n.stage.hlsl && n.stage.reduction == s.reduction && n.stage.axes == s.axes) return n.name;
  return "?";
}

} // namespace fftess
