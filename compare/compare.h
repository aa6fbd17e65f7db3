// fftess compare: is another tessellator's output (a GPU driver, a compute-shader port, a translation layer) the
// D3D11 reference's, bit for bit? And if not, which step of the 16.16 arithmetic did it get wrong?
//
// Usage (meshoptimizer style: plain structs in, plain structs out, no allocation you have to manage):
//
//   fftess::Tessellator ref;                              // or let comparePatch make its own
//   fftess::CapturedPatch got = ...;                      // from CaptureReader (capture.h) or built by hand
//   fftess::PatchComparison c = fftess::comparePatch(patch, &got, {}, ref);
//   if (c.kind != fftess::DifferenceKind::Same) puts(fftess::toString(c.kind));
//
// What "the same" means (docs/compare.md):
//   * default, order-insensitive: the multisets of points (point lists), of segments (unordered vertex pairs) or of
//     triangles (each in its lexicographically smallest rotation: the winding is kept, the first vertex is not) are
//     equal, every coordinate compared as IEEE bits;
//   * strictOrder: the same primitives in the same order with the same first vertex (what llvmpipe gives); the same
//     primitives in the same order, some starting at another vertex, are Rotated.
// A capture that is a point list (one vertex per primitive) is compared with the reference's point array whatever
// the patch's topology.
//
// A differing patch gets one DifferenceKind and the primitives only in the reference and only in the capture (with
// their indices); capture points that the reference does not have get their nearest
// reference point, the difference in 16.16 units and the step of the edge's fixed-point computation that explains
// them (the words of `fftess explain`); and the patch is re-computed under each typical port bug (PortBug) to name
// the ones that reproduce the capture. Findings only: nothing here decides an exit status.
//
// Standard library only.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compare/capture.h"
#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

namespace fftess {

enum class DifferenceKind : uint8_t {
  Same,
  CulledInCapture,   // the reference has output, the capture has none
  CulledInReference, // the reference culls the patch, the capture has output
  PointsDiffer,      // the sets of distinct points differ
  Multiplicity,      // the same distinct points (or primitives), each a different number of times
  WindingOnly,       // the same triangles up to winding
  PrimitivesDiffer,  // the same points, different segments (isoline lines, quad/tri line output)
  OrderDiffers,      // strictOrder only: the same multisets in another order
  TriangulationDiffers, // the same distinct points, joined into other triangles (triangleDiff lists them)
  Rotated,           // strictOrder only: the same triangles in the same order, some starting at another vertex
  Count
};
// culled_in_capture, culled_in_reference, points_differ, multiplicity, winding_only, primitives_differ,
// order_differs, triangulation_differs, rotated, same. Any other value: "?".
const char* toString(DifferenceKind k);

// Typical bugs of a tessellator port. The whole patch is re-computed under the bug and compared with the capture.
enum class PortBug : uint8_t {
  FloatDivision,        // k / n in float instead of k * round(65536 / n) in 16.16 (step: reciprocal rounding)
  NoMirroring,          // second half placed like the first, not as 1 - its mirror point (step: mirrored half)
  NoSpecialMidpoint,    // the middle point computed instead of the exact 0.5 (step: special midpoint)
  LerpNotRounded,       // the fractional blend kept in float, not rounded to 16.16 (step: lerp rounding)
  FactorsNotSnapped,    // fractional factors used as floats, not rounded to 16.16 (step: rounding of fract. factors)
  DenormalsFlushed,     // denormal factors flushed to zero before the cull test (step: denormal handling)
  Pow2AsFractionalEven, // pow2 not mapped to integer, tessellated as fractional_even (step: pow2 partitioning)
  Pow2AsFractionalOdd,  // pow2 partitioning not mapped to integer, tessellated as fractional_odd
  WindingSwapped,       // GL/D3D winding swapped: GL cw is D3D triangle_ccw (step: winding)
  // Bookkeeping bugs: the arithmetic is right, the factors or the coordinates go to the wrong place.
  OuterFactorsRotated,     // outer factors on the wrong edges, shifted round the domain (quad: by 1, 2 or 3; tri: 1, 2)
  OuterFactorsMirrored,    // outer factors on the wrong edges, reflected (quad: Ueq0<->Ueq1, transposed, reversed)
  OuterFactorsVFlipped,    // quad: Veq0 and Veq1 swapped (Vulkan's upper-left domain origin against GL's lower-left)
  DomainVFlipped,          // quad/isoline: the output's v written as 1 - v (the domain's v axis flipped)
  UvSwapped,               // the output's u and v swapped
  InsideFactorsSwapped,    // quad: insideU and insideV swapped
  TriBarycentricsPermuted, // tri: the output (u, v) taken from another pair of the barycentrics (u, v, w)
  IsolineFactorsSwapped,   // isoline: density and detail swapped (HLSL's ProcessIsolineTessFactors takes detail first)
  Count
};
// float_division, no_mirroring, no_special_midpoint, lerp_not_rounded, factors_not_snapped, denormals_flushed,
// pow2_as_fractional_even, pow2_as_fractional_odd, winding_swapped, outer_factors_rotated, outer_factors_mirrored,
// outer_factors_v_flipped, domain_v_flipped, uv_swapped, inside_factors_swapped, tri_barycentrics_permuted,
// isoline_factors_swapped. Any other value: "?".
const char* toString(PortBug b);
// The bug named s (toString's names); false for any other string.
bool parsePortBug(const char* s, PortBug& out);
// The bug in a sentence ("float division instead of the 16.16 reciprocal table").
const char* describe(PortBug b);
// The step of the edge's fixed-point computation the bug gets wrong, in `explain`'s words ("reciprocal rounding").
const char* stepOf(PortBug b);

// Whole-patch bugs as a port makes them (compare_bookkeeping.cpp): a change of the patch its fixed-function stage
// gets (portBugInput) and of the coordinates it writes (portBugOutput); any tessellator run between the two, the
// emulator (portBugCapture) or a GPU driver (driver-check --port-bug), behaves as a port with the bug.
//   outer_factors_rotated    quad: edge e gets the factor of edge (e + r) % 4, variants r = 1, 2, 3 (order Ueq0 Veq0
//                            Ueq1 Veq1 goes round the domain); tri: (e + r) % 3, r = 1, 2
//   outer_factors_mirrored   quad: Ueq0<->Ueq1, transposed (Ueq0<->Veq0, Ueq1<->Veq1), reversed (Ueq0<->Veq1,
//                            Veq0<->Ueq1); tri: Ueq0<->Veq0, Veq0<->Weq0, Ueq0<->Weq0
//   outer_factors_v_flipped  quad: Veq0<->Veq1          inside_factors_swapped  quad: insideU<->insideV
//   isoline_factors_swapped  isoline: density<->detail (the batch order is density, detail; HLSL's
//                            ProcessIsolineTessFactors and GL's gl_TessLevelOuter[0..1] order them otherwise)
//   domain_v_flipped         quad, isoline: (u, v) written as (u, 1 - v)
//   uv_swapped               any domain: (u, v) written as (v, u)
//   tri_barycentrics_permuted tri: (u, v) written as (u, w), (v, u), (v, w), (w, u), (w, v); w = (1 - u) - v in
//                            float, exact for 16.16 coordinates (as are 1 - v and the swaps: no rounding anywhere)
//   winding_swapped          triangles: the other triangle_cw / triangle_ccw
//   denormals_flushed        a denormal factor: every factor flushed to (signed) zero
//   pow2_as_fractional_even / _odd   pow2: that fractional partitioning
// The factor bugs act on the factors of the hardware stage: an hlsl-stage patch is preconditioned first (with
// 'options') and the result is a hardware-stage patch. The coordinate bugs keep the primitives' vertex order (a port
// that also flips the winding is recognised too: comparePatch tries both).
// True for the bugs above; false for the per-point arithmetic bugs (float_division ... factors_not_snapped).
bool portBugTransformsPatch(PortBug b);
// The number of forms of the bug for this patch: 0 when it does not apply (domain, topology, partitioning, no
// denormal factor; and every per-point arithmetic bug). Whether a form changes the output depends on the factors.
int portBugVariants(PortBug b, const Patch& patch);
// A form in words ("by 1: Ueq0 gets Veq0's factor", "(u, v) as (v, w)"); "" for bugs with one form.
std::string portBugVariantName(PortBug b, const Patch& patch, int variant);
// The patch a port with the bug feeds its fixed-function stage. A variant outside [0, portBugVariants) changes
// nothing (the patch is returned as it is).
Patch portBugInput(PortBug b, int variant, const Patch& patch, const Options& options = {});
// The port's output coordinates from the fixed-function stage's 'capture' (rewritten in place); 'patch' is the
// original patch. Only the coordinate bugs change anything.
void portBugOutput(PortBug b, int variant, const Patch& patch, CapturedPatch& capture);
// The output of an emulator port with the bug: portBugInput, tessellate with 'options', portBugOutput.
CapturedPatch portBugCapture(PortBug b, int variant, const Patch& patch, int64_t index, const Options& options,
                             bool pointList = false);

// One capture point that the reference does not have.
struct PointDifference {
  CapturedVertex got;     // the capture's point (float bits)
  CapturedVertex nearest; // the nearest reference point
  double du = 0, dv = 0;  // got - nearest, in 16.16 units (1/65536)
  std::string where;      // which axis and point the nearest reference coordinate is, e.g. "Ueq0 point 3 of 9"
  std::string step;       // the step that explains the capture's value ("reciprocal rounding"), or "" if none
  std::string detail;     // the two values and why, in a sentence
};

// One primitive (triangle or segment) that only one side has: the multiset difference of the primitives as compared
// (triangles rotated to their smallest vertex, segments unordered). A primitive that one side has twice and the other
// once is listed once.
struct PrimitiveDifference {
  int primitive = 0;                    // its position in its side's output (0-based)
  std::vector<CapturedVertex> vertices; // as that side emitted them (2 or 3)
  // Its side's point indices: the reference's index buffer; the capture's where it has them (hex blocks), else empty.
  std::vector<int32_t> indices;
  // Each vertex's index in the reference's point array (tessellate's numbering), -1 where the reference has no such
  // point. For a reference primitive the same as indices.
  std::vector<int32_t> referenceIndices;
};

struct CompareOptions {
  bool strictOrder = false;
  Options emulator{};      // the reference's options (flushDenormals: compare with a llvmpipe-like reference)
  int maxPointDetails = 8; // PointDifference entries per patch (the counts cover all points)
  int maxPrimitiveDetails = 8; // PrimitiveDifference entries per side and patch (the counts cover all primitives)
  bool recognise = true;   // re-run the patch under each PortBug
};

struct PatchComparison {
  DifferenceKind kind = DifferenceKind::Same;
  int referencePrimitives = 0, capturePrimitives = 0;
  int verticesPerPrimitive = 0;        // of the comparison (1 when the capture is a point list)
  int missingPoints = 0;               // distinct reference points the capture lacks
  int extraPoints = 0;                 // distinct capture points the reference lacks
  int flippedTriangles = 0;            // WindingOnly: triangles whose winding differs
  std::vector<PointDifference> points; // at most maxPointDetails
  int rotatedPrimitives = 0;           // Rotated: primitives that start at another vertex (a segment: reversed)
  // Primitives only in the reference / only in the capture (all kinds but same, order_differs and rotated, when the
  // comparison is of primitives, not of a point list): the counts cover all, the lists hold the first
  // maxPrimitiveDetails of each side in that side's output order. WindingOnly: the flipped ones, both ways round;
  // Multiplicity: the surplus copies.
  int onlyInReferenceCount = 0, onlyInCaptureCount = 0;
  std::vector<PrimitiveDifference> onlyInReference, onlyInCapture;
  std::vector<PortBug> bugs; // the port bugs that reproduce the capture exactly (or within 2^-20 per coordinate)
  // Parallel to bugs: the form that reproduces it (portBugVariantName, and ", winding flipped too" for a coordinate
  // bug whose port also flips the triangles); "" for bugs with one form.
  std::vector<std::string> bugVariants;
};

// Compares one patch. got: null when the capture lacks the patch (treated as no output: culled in the capture).
// Throws CaptureError when the capture's primitive size does not fit the patch's topology (message without
// file:line: the caller adds it). tess: scratch tessellator (reused, so no allocation per patch).
PatchComparison comparePatch(const Patch& patch, const CapturedPatch* got, const CompareOptions& options,
                             Tessellator& tess);

// The emulator's output for a patch as a capture (what a bit-exact port would write), to build test captures.
// pointList: one vertex per point instead of the topology's primitives.
CapturedPatch referenceCapture(const Patch& patch, int64_t index, const Options& options, bool pointList = false);

// Writes a capture as CSV rows (patch,primitive,vertex,u,v with 0x bits), appended to out.
void appendCsv(std::string& out, const CapturedPatch& c);

// The value a port with bug b computes for point k of an edge whose reference placement is 'trace' (traceEdge);
// rawFactor is the factor before 16.16 rounding (FactorsNotSnapped). Bugs that are not about one edge's points
// return the reference value.
float buggyEdgeParam(PortBug b, const EdgeTrace& trace, int k, float rawFactor);

// Running totals over a whole comparison.
struct CompareSummary {
  int64_t patches = 0, same = 0, differing = 0;
  int64_t byKind[size_t(DifferenceKind::Count)] = {}; // indexed by DifferenceKind
  int64_t byBug[int(PortBug::Count)] = {}; // differing patches each bug reproduces
  int64_t pointsCompared = 0;
  void add(const PatchComparison& c, int points);
  // The bugs that reproduce every differing patch (empty when none does, or nothing differs).
  std::vector<PortBug> explainingAll() const;
};

} // namespace fftess
