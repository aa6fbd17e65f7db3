// fftess verify, stage 6: holes. A patch that is not drawn (lod/ culled it, or the tessellator discards it) is a
// hole when part of it would be on screen; whether it is is decided, not sampled, by splitting its (u, v) domain
// (docs/verify.md, "Holes"). This header is the record a check reports for such a patch (Hole) and the three-valued
// decision (Visibility); the limits of the decision are CheckOptions::visibilityDepth / visibilityBudget (check.h).
#pragma once

#include "verify/lod_bridge.h"
#include "verify/terrain.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace fftess::verify {

// A hole: a patch that is not drawn although part of it would be on screen.
//
// Not drawn: lod/ culled it (its Why::culled), or the tessellator discards it because an outer factor is NaN, <= 0
// or -Inf (D3D11.3 11.7.6; the reference's culling rule) while lod/ did not mean to cull it. Whether such a patch is
// on screen is decided, not sampled (docs/verify.md, "Holes"), in double from lod's float matrices, on the
// displaced surface as the scene's domain shader positions it (every (u, v) in [0, 1]^2):
//   * the patch's (u, v) domain is split into dyadic sub-rectangles, breadth first. Each gets a conservative box of
//     the surface over it: x/z from the exact bilinear interpolation of the corners, padded by 2^-20 of their
//     magnitude (the domain shader's float lerps); y from the displacement texels its footprint can read on every
//     mip level the domain shader samples there (bilinear and trilinear filtering and geomorph blending stay
//     between the texels they read), times height_scale, padded by 2^-16 (float rounding of the filters);
//   * a box wholly outside one plane of the view frustum: that part is invisible;
//   * its centre (and at the root and the finest level its corners), evaluated by the domain shader emulation,
//     strictly inside the frustum (clip space: |x|, |y| < w, -w < z < w): the patch is Visible;
//   * otherwise it is split, down to a side of 2^-CheckOptions::visibilityDepth (1/1024 of the patch), with at most
//     CheckOptions::visibilityBudget boxes per patch.
// Every part invisible: Invisible, nothing reported. A point found: a hole (Report::holes):
//   Discarded          the tessellator discards the patch but lod/ did not cull it;
//   CulledWhileVisible lod/'s frustum test culled the patch (a height bound too small, a wrong plane, a patch box
//                      that misses its displaced surface).
// Neither (a finest sub-rectangle still straddles a plane, or the budget ran out): Visibility::Undecided, listed in
// Report::undecided with the same record (kind: culled or discarded), counted in Stats::undecided; the verdict is
// Verdict::Undecided unless there are cracks or holes. Never a clean verdict.
enum class HoleKind : uint8_t { Discarded, CulledWhileVisible }; // how the patch was not drawn (see above)
enum class Visibility : uint8_t { Invisible, Visible, Undecided }; // the decision (see above)

// One patch not drawn and not proven invisible (Report::holes, or Report::undecided when Undecided).
struct Hole {
  HoleKind kind = HoleKind::Discarded;
  PatchRef patch;
  Visibility visibility = Visibility::Visible;
  glm::vec3 visiblePoint{};    // a point of the patch inside the frustum (Visibility::Visible)
  // Discarded: the first outer edge (FactorIndex order) whose factor made the tessellator discard the patch, and
  // its factor, bits and lod/'s record. CulledWhileVisible: edge -1; factor is the cull value lod/ wrote.
  int edge = -1;
  float hullFactor = 0;
  uint32_t hullFactorBits = 0;
  float factors[6] = {0, 0, 0, 0, 0, 0}; // the patch's six hull factors (Ueq0 Veq0 Ueq1 Veq1 insideU insideV)
  EdgeLod lod;                 // lod/'s record of that edge (CulledWhileVisible: of Ueq0)
  // The edge's midpoint (lod's corners) in view space: w = -z, the projection's divisor. 0: the eye lies in the
  // plane through the midpoint parallel to the image (a projected size of 0/0 or x/0).
  float midpointW = 0;
  // The y range of the box lod/'s frustum test culls with (its corners' y, widened by its height bounds), next to
  // the y where the surface was seen: a culled-while-visible hole with visiblePoint.y outside it is a height bound
  // too small.
  float lodBoxMinY = 0, lodBoxMaxY = 0;
  // On screen (docs/verify.md, "On screen"): true for every reported hole. A hole is never proven off screen: a
  // patch whose surface box is outside the frustum is Invisible and no hole; Visible holes have a point inside the
  // frustum; Undecided ones may be on screen and count as on screen.
  bool onScreen = true;
  // Visible: the (u, v) of visiblePoint. Undecided: the lower corner of the first sub-rectangle left undecided.
  DomainPoint domainPoint{};
  float undecidedSide = 0;     // Undecided: that sub-rectangle's side in (u, v) units (2^-visibilityDepth, or
                               // larger when the budget ran out first)
  bool budgetExhausted = false; // Undecided: CheckOptions::visibilityBudget boxes were built before a decision
};

const char* toString(HoleKind k);  // "discarded", "culled_while_visible"
const char* toString(Visibility v); // "invisible", "visible", "undecided"

} // namespace fftess::verify
