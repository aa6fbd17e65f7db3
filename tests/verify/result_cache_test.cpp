// The sweep-wide result cache (verify/result_cache.h; docs/verify.md, "Sweep shortcuts" -> "Result cache"): a
// bounded, write-once set of (key, value) pairs shared by threads. Hand-checked cases on tiny tables, then threads
// inserting overlapping items while they and others read.
#include "base/splitmix64.h"
#include "verify/result_cache.h"

#include <catch2/catch.hpp>

#include <atomic>
#include <cstdint>
#include <set>
#include <thread>
#include <utility>
#include <vector>

using fftess::SplitMix64;
using fftess::verify::detail::ResultCache;

namespace {

constexpr uint64_t kAllOnes = ~uint64_t(0);

} // namespace

TEST_CASE("a result cache holds what was inserted and nothing else", "[verify][result_cache]") {
  ResultCache c(64);
  CHECK(c.size() == 0);
  CHECK_FALSE(c.contains(7, 3));
  CHECK(c.insert(7, 3));
  CHECK(c.contains(7, 3));
  CHECK_FALSE(c.contains(7, 4));
  CHECK_FALSE(c.contains(8, 3));
  CHECK(c.size() == 1);
  CHECK(c.insert(7, 3)); // already there: true, no second slot
  CHECK(c.size() == 1);
  CHECK(c.dropped() == 0);
}

TEST_CASE("a result cache tells apart the values under one key", "[verify][result_cache]") {
  ResultCache c(64);
  REQUIRE(c.insert(42, 1));
  CHECK_FALSE(c.contains(42, 0));
  CHECK_FALSE(c.contains(42, 2));
  REQUIRE(c.insert(42, 2));
  CHECK(c.contains(42, 1));
  CHECK(c.contains(42, 2));
  CHECK_FALSE(c.contains(42, 3));
  CHECK(c.size() == 2);
  // Values that differ in one bit only, the high word of a factor-bits pair included.
  REQUIRE(c.insert(42, uint64_t(0x3f800000) << 32 | 0x3f800001));
  CHECK_FALSE(c.contains(42, uint64_t(0x3f800000) << 32 | 0x3f800000));
  CHECK_FALSE(c.contains(42, uint64_t(0x3f800001) << 32 | 0x3f800001));
  CHECK(c.size() == 3);
}

TEST_CASE("a full result cache compares the value of every slot it passes", "[verify][result_cache]") {
  // 16 slots = one window, all taken by key 42: every probe passes slots of key 42 until it finds its item or has
  // seen all 16 (no empty slot ends it early), whatever the hashes.
  ResultCache c(16);
  for (uint64_t v = 1; v <= 16; ++v) REQUIRE(c.insert(42, v));
  REQUIRE(c.size() == 16);
  for (uint64_t v = 1; v <= 16; ++v) CHECK(c.contains(42, v));
  CHECK_FALSE(c.contains(42, 0));
  CHECK_FALSE(c.contains(42, 17));
  CHECK_FALSE(c.contains(42, kAllOnes));
  CHECK_FALSE(c.contains(43, 1));
  CHECK_FALSE(c.insert(42, 17)); // no slot left for it: dropped, not taken for an item with another value
  CHECK(c.dropped() == 1);
}

TEST_CASE("a result cache refuses the reserved keys 0 and all ones", "[verify][result_cache]") {
  ResultCache c(64);
  CHECK_FALSE(c.insert(0, 5));
  CHECK_FALSE(c.insert(kAllOnes, 5));
  CHECK_FALSE(c.contains(0, 5));
  CHECK_FALSE(c.contains(0, 0)); // an empty slot is key 0, value 0: not an item
  CHECK_FALSE(c.contains(kAllOnes, 5));
  CHECK(c.size() == 0);
  CHECK(c.dropped() == 0); // refused, not dropped
  // The keys next to them are ordinary keys.
  CHECK(c.insert(1, 0));
  CHECK(c.insert(kAllOnes - 1, 0));
  CHECK(c.contains(1, 0));
  CHECK(c.contains(kAllOnes - 1, 0));
  CHECK(c.size() == 2);
}

TEST_CASE("a result cache rounds its capacity up to a power of two of at least the probe window", "[verify][result_cache]") {
  STATIC_REQUIRE(ResultCache::kProbe == 16);
  const std::pair<size_t, size_t> cases[] = {{0, 16}, {1, 16}, {15, 16}, {16, 16}, {17, 32},
                                             {1000, 1024}, {1024, 1024}, {1025, 2048}};
  for (const auto& [asked, slots] : cases) {
    ResultCache c(asked);
    INFO("asked " << asked);
    CHECK(c.capacity() == slots);
    CHECK(c.bytes() == slots * 16);
  }
  CHECK(ResultCache(size_t(1) << 18).bytes() == 4u << 20); // the sweep's default: 4 MiB
}

TEST_CASE("a result cache drops an item when its window is full and says so", "[verify][result_cache]") {
  // 16 slots = one window: every item probes the whole table, whatever its hash.
  ResultCache c(16);
  for (uint64_t k = 1; k <= 16; ++k) REQUIRE(c.insert(k, k * 10));
  CHECK(c.size() == 16);
  CHECK(c.dropped() == 0);
  CHECK_FALSE(c.insert(17, 170));
  CHECK(c.dropped() == 1);
  CHECK_FALSE(c.contains(17, 170));
  CHECK_FALSE(c.insert(5, 51)); // a new value under a present key needs a slot too
  CHECK(c.dropped() == 2);
  CHECK_FALSE(c.contains(5, 51));
  // What is there stays there, and inserting it again is no drop.
  for (uint64_t k = 1; k <= 16; ++k) {
    CHECK(c.contains(k, k * 10));
    CHECK(c.insert(k, k * 10));
  }
  CHECK(c.size() == 16);
  CHECK(c.dropped() == 2);
}

TEST_CASE("a larger result cache finds every item it kept past collisions and none it dropped",
          "[verify][result_cache]") {
  ResultCache c(64);
  SplitMix64 rng{3};
  std::vector<std::pair<uint64_t, uint64_t>> kept, dropped;
  while (kept.size() < c.capacity() && dropped.size() < 200) {
    const uint64_t key = 1 + rng.below(40), value = rng.next(); // 40 keys: many values under each
    if (c.insert(key, value))
      kept.emplace_back(key, value);
    else
      dropped.emplace_back(key, value);
  }
  REQUIRE(!dropped.empty());
  CHECK(c.size() == kept.size()); // random 64-bit values: no item twice
  CHECK(c.dropped() == static_cast<int64_t>(dropped.size()));
  for (const auto& [k, v] : kept) CHECK(c.contains(k, v));
  for (const auto& [k, v] : dropped) CHECK_FALSE(c.contains(k, v));
}

namespace {

// What one round of the threads test found wrong (all zero when right).
struct RoundFaults {
  int64_t lostOwn = 0;  // an item insert() kept, not contained right after, by the thread that inserted it
  int64_t invented = 0; // an item never inserted, contained
  int64_t lost = 0;     // an item insert() kept, not contained after the join
  int64_t counts = 0;   // counters that do not add up
  int64_t drops = 0;    // items dropped (the table is made too small: the drop path runs under contention)
};

// One round: kThreads threads released at once, two on each seeded sequence (the same items at the same moment),
// over 24 keys, into a fresh table too small for all. Items never inserted: value 0 (a value stored after its key
// would show as 0 for a moment) and values with the top bit set (inserts use neither).
RoundFaults threadsRound(uint64_t round) {
  constexpr int kThreads = 8, kItems = 300;
  ResultCache c(512);
  std::atomic<int64_t> lostOwn{0}, invented{0}, drops{0};
  std::atomic<int> ready{0};
  std::vector<std::vector<std::pair<uint64_t, uint64_t>>> kept(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t)
    threads.emplace_back([&, t] {
      SplitMix64 rng{round * 64 + uint64_t(t / 2)}, probe{round * 64 + 32 + uint64_t(t)};
      ready.fetch_add(1);
      while (ready.load() < kThreads) std::this_thread::yield();
      for (int i = 0; i < kItems; ++i) {
        const uint64_t key = 1 + rng.below(24), value = 1 + (rng.next() >> 2); // value in [1, 2^62]
        if (c.insert(key, value)) {
          kept[t].emplace_back(key, value);
          if (!c.contains(key, value)) ++lostOwn;
        } else {
          ++drops;
        }
        const uint64_t other = 1 + probe.below(24);
        if (c.contains(other, 0) || c.contains(other, probe.next() | uint64_t(1) << 63)) ++invented;
      }
    });
  for (std::thread& th : threads) th.join();
  RoundFaults f{lostOwn.load(), invented.load(), 0, 0, drops.load()};
  std::set<std::pair<uint64_t, uint64_t>> distinct;
  int64_t successes = 0;
  for (const auto& items : kept)
    for (const auto& [k, v] : items) {
      distinct.insert({k, v});
      ++successes;
      if (!c.contains(k, v)) ++f.lost;
    }
  for (uint64_t k = 1; k <= 24; ++k)
    if (c.contains(k, 0)) ++f.invented;
  // Every kept item took a slot once or more (duplicates), and a slot only for a successful insert.
  const int64_t used = static_cast<int64_t>(c.size());
  if (c.dropped() != f.drops || successes + f.drops != kThreads * kItems || used < int64_t(distinct.size()) ||
      used > successes || c.size() > c.capacity())
    ++f.counts;
  return f;
}

} // namespace

TEST_CASE("threads share a result cache without losing or inventing items", "[verify][result_cache]") {
  RoundFaults total;
  for (uint64_t round = 0; round < 100; ++round) {
    const RoundFaults f = threadsRound(round);
    total.lostOwn += f.lostOwn, total.invented += f.invented, total.lost += f.lost, total.counts += f.counts;
    total.drops += f.drops;
  }
  CHECK(total.lostOwn == 0);
  CHECK(total.invented == 0);
  CHECK(total.lost == 0);
  CHECK(total.counts == 0);
  CHECK(total.drops > 0);
}
