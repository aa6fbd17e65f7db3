// Internal header of the comparison (compare.cpp, compare_bugs.cpp, compare_bookkeeping.cpp, triangle_diff.cpp): the
// axes of a patch as traced edges, the output helpers the bug models share, primitives as keys and their differences.
#pragma once

#include "compare/compare.h"

#include <array>
#include <cstdint>
#include <vector>
#include "tessellator/trace.h"

namespace fftess {

// One axis of a patch (an outer edge, a quad inside axis, an isoline's detail or density) as a traced edge.
struct Axis {
  bool valid = false;
  const char* name = "";
  float raw = 0; // the factor before 16.16 rounding (after the clamp)
  EdgeTrace trace;
};

struct PatchAxes {
  Domain domain = Domain::Quad;
  Axis outer[4];  // quad Ueq0 Veq0 Ueq1 Veq1; tri Ueq0 Veq0 Weq0
  Axis inside[2]; // quad insideU insideV; isoline detail (u) and density (v)
};

PatchAxes patchAxes(const Patch& patch, const Options& options);
// The axis that gives coordinate c (0 u, 1 v) of reference vertex r, or null (tri interior points, and corners
// unless 'corners': the corners an edge reaches by mirroring, as a port that places them like any point would).
const Axis* axisOf(const PatchAxes& a, CapturedVertex r, int c, bool& mirrorV, bool corners = true);
// The index of the point with these float bits on the axis, or -1.
int pointOnAxis(const Axis& axis, uint32_t bits);
// A primitive as a comparable key: a triangle rotated so its smallest vertex comes first (winding kept), a segment's
// two vertices sorted, unused slots 0 (triangle_diff.cpp).
using PrimitiveKey = std::array<uint64_t, 3>;
PrimitiveKey primitiveKey(const CapturedVertex* v, int arity);
// strictOrder: whether primitive i of cap is primitive i of ref up to its first vertex, for every i (same sizes);
// 'rotated' counts those that start at another vertex.
bool sameUpToRotation(const std::vector<CapturedVertex>& ref, const std::vector<CapturedVertex>& cap, int arity,
                      int& rotated);
// Fills c's onlyInReference/onlyInCapture lists and counts (arity 2 or 3). ref: the reference's primitives, refIndices
// its index buffer, refPoints its point array; got: the capture (null: none).
void primitiveDifferences(const std::vector<CapturedVertex>& ref, const std::vector<int32_t>& refIndices,
                          const std::vector<CapturedVertex>& refPoints, const CapturedPatch* got, int arity,
                          int maxDetails, PatchComparison& c);

// Reference vertex r as a port with edge bug b computes it.
// corners: also re-place the corners an edge reaches by mirroring (else they stay: a port that writes them as
// constants).
CapturedVertex applyBug(const PatchAxes& a, PortBug b, CapturedVertex r, bool corners);

// The tessellator's output as vertices: its primitives (arity 2 or 3), or its point array (arity 1).
void outputOf(const Tessellator& t, int arity, std::vector<CapturedVertex>& out);
// The same multiset of primitives (triangles compared up to their first vertex, segments unordered).
bool sameOrderInsensitive(const std::vector<CapturedVertex>& a, const std::vector<CapturedVertex>& b, int arity);
// Adds bug b (and its form, "" for none) to the bugs that reproduce the capture.
void nameBug(PatchComparison& c, PortBug b, const std::string& form = "");
// The whole-patch bugs (compare_bookkeeping.cpp): each bug and form of portBugVariants re-computed through the
// emulator; a bug is named (once, with the first form that matches) when its output is the capture's.
void recogniseWholePatch(const Patch& patch, const Options& options, const std::vector<CapturedVertex>& ref,
                         const std::vector<CapturedVertex>& got, int arity, Tessellator& tess, PatchComparison& c);

} // namespace fftess
