// Helpers of the comparison tests (test_compare): a batch line as a patch, one comparison with fresh options.
#pragma once

#include <catch2/catch.hpp>

#include "compare/compare.h"
#include "tessellator/batch.h"

namespace comparetest {

inline fftess::Patch patchOf(const char* line) {
  fftess::Patch p;
  fftess::BatchError e;
  REQUIRE(fftess::parseBatchLine(line, p, e));
  return p;
}

// comparePatch with default options but strictOrder and maxPrimitiveDetails.
inline fftess::PatchComparison run(const fftess::Patch& p, const fftess::CapturedPatch* c, bool strict = false,
                                   int details = 8) {
  fftess::Tessellator t;
  fftess::CompareOptions o;
  o.strictOrder = strict;
  o.maxPrimitiveDetails = details;
  return fftess::comparePatch(p, c, o, t);
}

} // namespace comparetest
