// Run-time choice of the vector kernels (internal header of fftess_tessellator). The AVX2 versions of the axis
// tables (spacing.cpp) and the transition corners (stitch.cpp) give the same bits as the portable loops; tests switch
// to the portable ones to check that.
#pragma once

namespace fftess::simd {

// True when the CPU has AVX2 and the portable loops were not forced.
bool useAvx2();
// Tests only, while no tessellation runs on another thread: true = portable loops from now on; false = back to the
// CPU's choice.
void forcePortable(bool portable);

} // namespace fftess::simd
