// The power-of-two workaround explained by the 16.16 arithmetic: an edge of factor B beside two half-length edges
// of factor B/2 (a 2x patch-size jump) meets vertex for vertex only when the segment counts divide 65536.
// Parameters are compared exactly in units of 1/131072 of the big edge (big t = v, first small t = v1/2, second
// small t = 1/2 + v2/2) by the library's analysis, compareHalfEdges (tessellator/edge_analysis.h).
#include <catch2/catch.hpp>

#include <vector>

#include "factor_samples.h"
#include "tessellator/edge_analysis.h"

using namespace fftess;
using namespace fftess::testing;

TEST_CASE("12 beside 2x6 cracks, 8 beside 2x4 meets (integer partitioning)", "[tessellator][pow2]") {
  const EdgePoints big = edgePoints(12.0f, Partitioning::Integer), small = edgePoints(6.0f, Partitioning::Integer);
  // r(12) = round(65536/12) = 5461; points i*5461 up to the middle, the second half mirrored from 1.
  CHECK(std::vector<uint32_t>(big.fixed, big.fixed + big.count) ==
        std::vector<uint32_t>{0, 5461, 10922, 16383, 21844, 27305, 32768, 38231, 43692, 49153, 54614, 60075, 65536});
  // r(6) = 10923 = 2 * 5461 + 1.
  CHECK(std::vector<uint32_t>(small.fixed, small.fixed + small.count) ==
        std::vector<uint32_t>{0, 10923, 21846, 32768, 43690, 54613, 65536});
  const HalfEdgeComparison c = compareHalfEdges(12.0f, 6.0f, Partitioning::Integer);
  CHECK_FALSE(c.match);
  // First small point 10923/2 = 5461.5 against 5461 ... the worst miss is 1.5/65536 of the edge (3/131072).
  CHECK(c.worstGap == 3);

  const HalfEdgeComparison ok = compareHalfEdges(8.0f, 4.0f, Partitioning::Integer);
  CHECK(ok.match);
  CHECK(ok.worstGap == 0);
}

TEST_CASE("which B beside 2x(B/2) meet: integer and fractional_even", "[tessellator][pow2]") {
  std::vector<int> integerMatches, evenMatches;
  int64_t worst = 0;
  std::vector<int> worstAt;
  for (int B = 2; B <= 64; B += 2) {
    const HalfEdgeComparison ci = compareHalfEdges(float(B), float(B / 2), Partitioning::Integer);
    if (ci.match) integerMatches.push_back(B);
    if (ci.worstGap > worst) worst = ci.worstGap, worstAt.clear();
    if (ci.worstGap == worst) worstAt.push_back(B);
    if (compareHalfEdges(float(B), float(B / 2), Partitioning::FractionalEven).match) evenMatches.push_back(B);
  }
  CHECK(integerMatches == std::vector<int>{2, 4, 8, 16, 32, 64});
  CHECK(evenMatches == std::vector<int>{4, 8, 16, 32, 64});
  CHECK(worst == 19); // 9.5 / 65536 of the big edge
  CHECK(worstAt == std::vector<int>{44, 54});
}

TEST_CASE("S = 7: r(7) = 2 r(14) but 14 r(14) = 65534", "[tessellator][pow2]") {
  const EdgeTrace big = traceEdge(14.0f, Partitioning::Integer), small = traceEdge(7.0f, Partitioning::Integer);
  CHECK(big.reciprocalCeil == 4681u);
  CHECK(small.reciprocalCeil == 9362u);
  CHECK(14u * big.reciprocalCeil == 65534u);
  CHECK_FALSE(compareHalfEdges(14.0f, 7.0f, Partitioning::Integer).match);
}

TEST_CASE("causes: 12 beside 2x6 is the reciprocal table (and the special 0.5), 7 beside 2x3.5 the point count",
          "[tessellator][pow2]") {
  const HalfEdgeComparison c = compareHalfEdges(12.0f, 6.0f, Partitioning::Integer);
  REQUIRE(c.paired);
  int attributed = 0;
  for (const HalfEdgeRow& r : c.rows) {
    if (r.match) continue;
    INFO("row big " << r.big << " small " << r.small);
    CHECK(r.attributed);
    // The small edges' exact middles (big t = 1/4, 3/4) are special-cased 0.5 there and computed on the big edge.
    if (r.bigBudget.midpoint != r.smallBudget.midpoint)
      CHECK(r.causes == std::vector<MismatchCause>{MismatchCause::SpecialHalf, MismatchCause::ReciprocalTable});
    else
      CHECK(r.causes == std::vector<MismatchCause>{MismatchCause::ReciprocalTable});
    ++attributed;
  }
  CHECK(attributed == c.mismatches);
  CHECK(c.mismatches == 10);

  const HalfEdgeComparison odd = compareHalfEdges(7.0f, 3.5f, Partitioning::Integer); // 8 points vs 2 x 5 - 1
  CHECK_FALSE(odd.paired);
  int alone = 0;
  for (const HalfEdgeRow& r : odd.rows)
    if (r.big < 0 || r.small < 0) {
      CHECK(r.causes == std::vector<MismatchCause>{MismatchCause::PointCount});
      ++alone;
    }
  CHECK(alone > 0);
}

TEST_CASE("point budgets reproduce every traced point exactly", "[tessellator][pow2]") {
  int points = 0;
  for (Partitioning part :
       {Partitioning::Integer, Partitioning::Pow2, Partitioning::FractionalOdd, Partitioning::FractionalEven})
    for (float f : specialFactors()) {
      const EdgeTrace tr = traceEdge(f, part);
      for (int k = 0; k < tr.count; ++k) {
        INFO(toString(part) << " factor " << hex(f) << " point " << k);
        REQUIRE(pointBudget(tr, k).consistent);
        ++points;
      }
    }
  CHECK(points > 1000);
}

TEST_CASE("shared-edge ticks of a 2x jump agree with compareHalfEdges", "[tessellator][pow2]") {
  for (int B = 2; B <= 64; B += 2) {
    const HalfEdgeComparison c = compareHalfEdges(float(B), float(B / 2), Partitioning::Integer);
    // The big edge's first half against the first small edge, as a crack report's inset sees them.
    const SharedEdgeTicks t =
        sharedEdgeTicks({float(B), 0.0f, 0.5f}, {float(B / 2), 0.0f, 1.0f}, Partitioning::Integer);
    INFO("B = " << B);
    REQUIRE_FALSE(t.culled);
    CHECK(int(t.b.size()) == c.small.edge.count);
    CHECK(int(t.a.size()) == c.big.edge.count / 2 + 1);
    bool allPartnered = true;
    for (const SharedEdgeTick& x : t.a) allPartnered = allPartnered && x.partner;
    for (const SharedEdgeTick& x : t.b) allPartnered = allPartnered && x.partner;
    // By symmetry the second half behaves as the first: the halves meet exactly when the whole edge does.
    CHECK(allPartnered == c.match);
  }
}
