// The camera's picture of a check (check --view): what the camera sees, projected through the check's own camera
// (verify::lodCamera). Pure function of the report and the camera's layout: no I/O.
#pragma once

#include "verify/verify.h"

#include <cstddef>
#include <string>

namespace fftess::cli {

namespace vf = fftess::verify;

// Outline samples per patch edge: each outline is the patch's border on the displaced surface, its four edges each
// through kViewEdgeSegments + 1 points of verify::domainPosition (corners included; the camera-independent position).
constexpr int kViewEdgeSegments = 4;

// The picture's size: the camera's viewport scaled to fit kViewWidth x kViewWidth pixels. Layouts of millions of
// patches: at most kViewMaxOutlines outlines (the first patches in view, in layout order); the legend counts them all
// and says so.
constexpr double kViewWidth = 1200;
constexpr size_t kViewMaxOutlines = 200000;

// The picture: every drawn patch's outline (Report::drawn: CheckOptions::keepDrawn) clipped in homogeneous clip space
// against the six frustum planes (nothing behind the eye or outside the view is drawn), one <path class="lvN"> per
// patch in view in <g id="patches">, coloured by size level N; holes (red) and undecided patches (orange) filled where
// in view and circled (labelled "hole" / "undecided") where seen (Hole::visiblePoint) or where the decision stopped;
// every on-screen finding marked (<g id="findings">: a circle each, at the crack's on-screen gap vertex, labelled with
// its on-screen gap in pixels, or a T-junction's mismatch, labelled "T-junction"); then a legend that fits the page:
// the camera, one line per size level drawn, the counts (off-screen findings counted, not drawn), each cause on screen
// with its fix, and a ruler of 100 camera pixels. layout: layoutFor(terrain, camera) (the report's patch indices).
std::string viewSvg(const vf::Terrain& layout, const vf::Camera& camera, const vf::Report& r, const std::string& title,
                    bool countOffScreen);

} // namespace fftess::cli
