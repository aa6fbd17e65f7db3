// SVG pictures of check and sweep: the layout from above (every patch, every tile), the findings on it, and for a
// check an inset of the worst finding's shared edge. Pure functions of the reports: no I/O.
#pragma once

#include "verify/verify.h"

#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

// The check picture: layout, T-junctions (orange) and cracks (red, the on-screen gap vertex circled) on screen,
// findings off screen (Finding::onScreen false) grey and dashed, the worst finding that counts (countOffScreen:
// --offscreen) zoomed in an inset.
std::string checkSvg(const vf::Terrain& terrain, const vf::Report& r, const std::string& title, bool countOffScreen);

// What the sweep picture draws of one camera checked (kept per camera instead of its CameraResult).
struct SvgCamera {
  size_t index = 0;          // global camera index
  float x = 0, z = 0;        // eye
  int64_t cracks = 0;
  char verdict = 'o';        // 'o' clean, 'w' T-junctions, 'b' cracks, holes or undecided patches
  bool crackMark = false;    // worst crack circled at (gx, gz)
  float gx = 0, gz = 0;
};
// A camera's first hole: the patch filled, with a title.
struct SvgHole {
  int patch = -1;
  std::string title;
  bool hasCorners = false; // a camera-dependent layout (quadtree): the patch's corners in its camera's layout
  glm::vec3 corners[4]{};
};
// countOffScreen (--offscreen): the camera's off-screen findings count for its colour and mark.
SvgCamera svgCamera(size_t globalIndex, const vf::Camera& cam, const vf::CameraResult& c, bool countOffScreen);

// The sweep picture: layout, every checked camera's eye as a dot coloured by its verdict (all of `cams` joined in
// order unless randomOrder), each camera's worst crack circled, each camera's first hole filled, and the first
// camera of each cause numbered in the order of firstCameras (indices into cams).
std::string sweepSvg(const vf::Terrain& terrain, const std::vector<vf::Camera>& cams, const std::vector<SvgCamera>& dots,
                     const std::vector<SvgHole>& holes, const std::vector<size_t>& firstCameras, bool randomOrder,
                     const std::string& title, bool countOffScreen);

} // namespace fftess::cli
