// The power-of-two workaround explained by the 16.16 arithmetic: an edge of factor B beside two half-length edges
// of factor B/2 (a 2x patch-size jump) meets vertex for vertex only when the segment counts divide 65536.
// Parameters are compared exactly in units of 1/131072 of the big edge: big t = v, first small t = v1/2,
// second small t = 1/2 + v2/2.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "factor_samples.h"

using namespace fftess;
using namespace fftess::testing;

namespace {

struct Comparison {
  std::vector<int64_t> big, small; // in 1/131072 of the big edge
  int64_t worstGap = 0;            // in 1/131072: max over points of the distance to the other side's nearest point
  bool match() const { return big == small; }
};

int64_t nearest(const std::vector<int64_t>& sorted, int64_t x) {
  int64_t best = INT64_MAX;
  for (int64_t y : sorted) best = std::min<int64_t>(best, y > x ? y - x : x - y);
  return best;
}

Comparison compare(float bigFactor, float smallFactor, Partitioning part) {
  const EdgePoints b = edgePoints(bigFactor, part), s = edgePoints(smallFactor, part);
  Comparison c;
  for (int k = 0; k < b.count; ++k) c.big.push_back(2 * int64_t(b.fixed[k]));
  for (int k = 0; k < s.count; ++k) c.small.push_back(int64_t(s.fixed[k]));
  for (int k = 1; k < s.count; ++k) c.small.push_back(65536 + int64_t(s.fixed[k]));
  for (int64_t x : c.big) c.worstGap = std::max(c.worstGap, nearest(c.small, x));
  for (int64_t x : c.small) c.worstGap = std::max(c.worstGap, nearest(c.big, x));
  return c;
}

} // namespace

TEST_CASE("12 beside 2x6 cracks; 8 beside 2x4 meets (integer partitioning)", "[pow2]") {
  const EdgePoints big = edgePoints(12.0f, Partitioning::Integer), small = edgePoints(6.0f, Partitioning::Integer);
  // r(12) = round(65536/12) = 5461; points i*5461 up to the middle, the second half mirrored from 1.
  CHECK(std::vector<uint32_t>(big.fixed, big.fixed + big.count) ==
        std::vector<uint32_t>{0, 5461, 10922, 16383, 21844, 27305, 32768, 38231, 43692, 49153, 54614, 60075, 65536});
  // r(6) = 10923 = 2 * 5461 + 1.
  CHECK(std::vector<uint32_t>(small.fixed, small.fixed + small.count) ==
        std::vector<uint32_t>{0, 10923, 21846, 32768, 43690, 54613, 65536});
  const Comparison c = compare(12.0f, 6.0f, Partitioning::Integer);
  CHECK_FALSE(c.match());
  // First small point 10923/2 = 5461.5 against 5461 ... the worst miss is 1.5/65536 of the edge (3/131072).
  CHECK(c.worstGap == 3);

  const Comparison ok = compare(8.0f, 4.0f, Partitioning::Integer);
  CHECK(ok.match());
  CHECK(ok.worstGap == 0);
}

TEST_CASE("which B beside 2x(B/2) meet: integer and fractional_even", "[pow2]") {
  std::vector<int> integerMatches, evenMatches;
  int64_t worst = 0;
  std::vector<int> worstAt;
  for (int B = 2; B <= 64; B += 2) {
    const Comparison ci = compare(float(B), float(B / 2), Partitioning::Integer);
    if (ci.match()) integerMatches.push_back(B);
    if (ci.worstGap > worst) worst = ci.worstGap, worstAt.clear();
    if (ci.worstGap == worst) worstAt.push_back(B);
    if (compare(float(B), float(B / 2), Partitioning::FractionalEven).match()) evenMatches.push_back(B);
  }
  CHECK(integerMatches == std::vector<int>{2, 4, 8, 16, 32, 64});
  CHECK(evenMatches == std::vector<int>{4, 8, 16, 32, 64});
  CHECK(worst == 19); // 9.5 / 65536 of the big edge
  CHECK(worstAt == std::vector<int>{44, 54});
}

TEST_CASE("S = 7: r(7) = 2 r(14) but 14 r(14) = 65534", "[pow2]") {
  const EdgeTrace big = traceEdge(14.0f, Partitioning::Integer), small = traceEdge(7.0f, Partitioning::Integer);
  CHECK(big.reciprocalCeil == 4681u);
  CHECK(small.reciprocalCeil == 9362u);
  CHECK(14u * big.reciprocalCeil == 65534u);
  CHECK_FALSE(compare(14.0f, 7.0f, Partitioning::Integer).match());
}
