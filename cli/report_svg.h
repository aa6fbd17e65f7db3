// SVG pictures of check and sweep: the layout from above (every patch, every tile), the findings on it, and for a
// check an inset of the worst finding's shared edge. Pure functions of the reports: no I/O.
#pragma once

#include "findings.h"

#include <string>
#include <vector>

namespace fftess::cli {

// The check picture: layout, T-junctions (orange) and cracks (red, the gap vertex circled), the worst finding's
// edge zoomed in an inset.
std::string checkSvg(const vf::Terrain& terrain, const vf::Report& r, const std::string& title);

// The sweep picture: layout, every camera's eye as a dot coloured by its verdict (joined in order unless
// randomOrder), each camera's worst crack circled, and the first camera of each cause numbered in the order of
// firstCameras.
std::string sweepSvg(const vf::Terrain& terrain, const std::vector<vf::Camera>& cams, const vf::SweepResult& res,
                     const std::vector<size_t>& firstCameras, bool randomOrder, const std::string& title);

} // namespace fftess::cli
