// Batch API (tessellator/parallel.h): packed outputs equal Tessellator::tessellate patch by patch, for any thread
// count; the layout is what outputCounts says.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "factor_samples.h"
#include "tessellator/fixed.h"
#include "tessellator/parallel.h"

using namespace fftess;

TEST_CASE("tessellateBatch equals tessellate patch by patch on 1, 2, 3 and all threads", "[tessellator][parallel]") {
  testing::FactorDraw draw(77);
  std::vector<Patch> patches(3000);
  for (Patch& p : patches) p = draw.patch();
  Options o;
  std::vector<BatchSlot> slots(patches.size());
  const BatchTotals totals = planBatch(patches.data(), patches.size(), slots.data(), o);
  Tessellator t;
  int64_t points = 0, indices = 0;
  for (size_t i = 0; i < patches.size(); ++i) {
    const OutputCounts c = outputCounts(patches[i], o);
    CHECK(slots[i].firstPoint == points);
    CHECK(slots[i].firstIndex == indices);
    CHECK(slots[i].points == c.points);
    CHECK(slots[i].indices == c.indices);
    points += c.points;
    indices += c.indices;
  }
  CHECK(totals.points == points);
  CHECK(totals.indices == indices);
  for (int threads : {1, 2, 3, 0}) {
    INFO("threads " << threads);
    std::vector<DomainPoint> pts(size_t(totals.points));
    std::vector<int32_t> idx(size_t(totals.indices));
    tessellateBatch(patches.data(), patches.size(), slots.data(), pts.data(), idx.data(), threads, o);
    int mismatches = 0;
    for (size_t i = 0; i < patches.size(); ++i) {
      t.tessellate(patches[i], o);
      const bool same =
          std::memcmp(t.points().data(), pts.data() + slots[i].firstPoint, sizeof(DomainPoint) * t.points().size()) ==
              0 &&
          std::memcmp(t.indices().data(), idx.data() + slots[i].firstIndex, 4 * t.indices().size()) == 0;
      if (!same) ++mismatches;
    }
    CHECK(mismatches == 0);
  }
}

TEST_CASE("forEachBatchRange covers every patch once, in contiguous ranges", "[tessellator][parallel]") {
  std::vector<BatchSlot> slots(1000);
  for (size_t i = 0; i < slots.size(); ++i) slots[i] = {int64_t(i) * 10, int64_t(i) * 30, 10, 30};
  for (int threads : {1, 2, 7, 2000}) {
    std::vector<int> seen(slots.size(), 0);
    std::vector<std::pair<size_t, size_t>> ranges(size_t(threads > 1000 ? 1000 : threads));
    forEachBatchRange(slots.size(), slots.data(), threads, [&](int t, size_t b, size_t e) {
      ranges[size_t(t)] = {b, e};
      for (size_t i = b; i < e; ++i) ++seen[i];
    });
    for (int s : seen) CHECK(s == 1);
    for (size_t r = 1; r < ranges.size(); ++r) CHECK(ranges[r].first == ranges[r - 1].second);
  }
  CHECK_THROWS(forEachBatchRange(slots.size(), slots.data(), 2, [](int t, size_t, size_t) {
    if (t == 1) throw std::runtime_error("x");
  }));
}

TEST_CASE("one float conversion equals fixedToFloat for every 16.16 value", "[tessellator][parallel]") {
  // fillAxisTable converts with float(x) * 2^-16 (spacing.cpp); fx::fixedToFloat adds integer part and fraction.
  auto same = [](uint32_t x) {
    return fx::bitsOf(float(x) * (1.0f / 65536.0f)) == fx::bitsOf(fx::fixedToFloat(x));
  };
  int bad = 0;
  for (uint32_t x = 0; x <= 0x00400000u; ++x) bad += same(x) ? 0 : 1;
  uint64_t s = 1;
  for (int i = 0; i < 2000000; ++i) {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    bad += same(uint32_t(s >> 32)) ? 0 : 1;
  }
  for (uint32_t x : {0x7fffffffu, 0x80000000u, 0xffffffffu, 0x01000001u, 0x00ffffffu}) bad += same(x) ? 0 : 1;
  CHECK(bad == 0);
}
