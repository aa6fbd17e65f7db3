// Shared by the oracle tests: context creation with the CI rule, reading .out files, and the comparison that
// decides what "the same" means between the GL oracle and another tessellator (docs/oracle.md).
#pragma once

#include "gl_capture.h"

#include <memory>
#include <string>
#include <vector>

namespace fftess {
namespace oracle {

// Exit status ctest reads as "skipped" (SKIP_RETURN_CODE).
constexpr int kSkipExitCode = 77;

// Creates the llvmpipe context. If impossible (or the renderer is not llvmpipe): prints why and exits, with failure
// when the environment variable CI is set, with kSkipExitCode otherwise.
std::unique_ptr<GlOracle> createOracleOrExit(const char* testName);

// Exits like createOracleOrExit for a missing prerequisite other than the context (e.g. the golden folder).
[[noreturn]] void unavailable(const char* testName, const std::string& why);

// Another tessellator's output for one patch, in the .out format's terms.
struct Expected {
  std::vector<uint32_t> points; // u, v bits per point
  std::vector<int32_t> indices;
};

// Reads a whole .out file (golden format). Returns false with 'error' naming the line.
bool readOutFile(const std::string& path, std::vector<Expected>& out, std::string& error);

// The comparison, per patch:
//   points:     the point arrays are identical (count, u/v bits, order);
//   primitives: the observed GL primitives, as (u,v) bits per vertex in order, equal the expected indices resolved
//               to expected points (triangle topologies and isoline lines; vacuously true otherwise);
//   indices:    the index arrays are identical (for triangles and isoline lines this rests on the vertex ids, see
//               docs/oracle.md; for point and quad/tri line they are derived from the point count).
struct Verdict {
  bool points = true;
  bool primitives = true;
  bool indices = true;
  std::string firstDifference; // empty when all equal
  bool all() const { return points && primitives && indices; }
};
Verdict compare(const Patch& patch, const Result& got, const Expected& want);

// True when two points of the result have the same (u,v) bits (the reference emits such duplicates for some
// fractional factors): there, index equality says more than coordinate equality.
bool hasDuplicatePoints(const Result& result);

// True when a factor the domain uses is a denormal (either sign): llvmpipe flushes those to zero.
bool hasDenormalFactor(const Patch& patch);
// True when an outer factor the domain uses is a denormal.
bool hasDenormalOuterFactor(const Patch& patch);

} // namespace oracle
} // namespace fftess
