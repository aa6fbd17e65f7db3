// The tessellation path as it was before the table kernels (issue 11), kept only for the differential test
// (tests/tessellator/differential_test.cpp): same factor processing, the old per-point placement and row stitching.
#pragma once

#include <vector>

#include "tessellator/tessellator.h"

namespace fftess::legacy {

// What Tessellator::tessellate produced before issue 11, into the given vectors. Returns the number of points.
int tessellate(const Patch& patch, const Options& options, std::vector<DomainPoint>& points,
               std::vector<int32_t>& indices);

} // namespace fftess::legacy
