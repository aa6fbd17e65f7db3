// The sweep-wide result cache (verify/result_cache.h; docs/verify.md, "Sweep shortcuts" -> "Result cache"): the cost
// of one contains() and one insert(), hit and miss, on a table of the sweep's default size (2^18 slots, 4 MiB) half
// full or full, on 1 and several threads sharing the one table. Items are spread over the table in random order
// (the keys a sweep asks for are edge pairs in no useful order).
#include "base/splitmix64.h"
#include "verify/result_cache.h"

#include <benchmark/benchmark.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>

namespace {

using fftess::SplitMix64;
using fftess::verify::detail::ResultCache;

constexpr size_t kSlots = size_t(1) << 18; // SweepOptions::resultCacheSlots' default

// Item i: 4,096 keys (edge pairs) with many values each (factor bits of the two sides); key never 0 or ~0.
uint64_t keyOf(uint64_t i) { return 1 + (SplitMix64::mix(i) & 4095); }
uint64_t valueOf(uint64_t i) { return SplitMix64::mix(i ^ 0x5bd1e995); }

// Items [0, n) inserted: the table for contains() and insert() hits; items from n on are misses.
struct Filled {
  std::unique_ptr<ResultCache> cache = std::make_unique<ResultCache>(kSlots);
  uint64_t n = 0; // items 0 .. n-1 inserted (those kept)
};

Filled fill(int load) {
  Filled f;
  const size_t want = load ? kSlots : kSlots / 2;
  while (f.cache->size() < want && f.n < uint64_t(64) * kSlots) {
    f.cache->insert(keyOf(f.n), valueOf(f.n)); // a few are dropped already at half load (docs/verify.md)
    ++f.n;
  }
  if (f.cache->size() != want) {
    std::fprintf(stderr, "result cache bench: could not fill the table (%zu slots)\n", f.cache->size());
    std::exit(2);
  }
  return f;
}

// load 0: half full (2^17 items); load 1: full (every slot taken: every miss probes kProbe slots). Made once, by
// the first thread that asks (a function's statics are initialised once, threads waiting).
const Filled& filled(int load) {
  static const Filled half = fill(0), full = fill(1);
  return load ? full : half;
}

// Query i of a thread: a hit is one of the first 2^17 items inserted (a few of them were dropped: "found" says how
// many were there), a miss one never inserted (found: 0, else the bench stops with an error).
uint64_t queryOf(uint64_t i, bool hit, const Filled& f) {
  return hit ? SplitMix64::mix(i) % (kSlots / 2) : f.n + (SplitMix64::mix(i) & ((uint64_t(1) << 40) - 1));
}

void BM_ResultCacheContains(benchmark::State& state) {
  const bool hit = state.range(0) != 0;
  const Filled& f = filled(static_cast<int>(state.range(1)));
  uint64_t i = uint64_t(state.thread_index()) << 32, found = 0;
  for (auto _ : state) {
    const uint64_t q = queryOf(i++, hit, f);
    found += f.cache->contains(keyOf(q), valueOf(q));
  }
  if (!hit && found != 0) state.SkipWithError("a miss was found");
  state.SetItemsProcessed(state.iterations());
  state.counters["found"] = benchmark::Counter(double(found) / double(state.iterations()), benchmark::Counter::kAvgThreads);
}
// args: hit (1) or miss (0), table half full (0) or full (1)
BENCHMARK(BM_ResultCacheContains)->ArgsProduct({{1, 0}, {0, 1}})->ArgNames({"hit", "full"})
    ->ThreadRange(1, 8)->UseRealTime();

// insert(): "hit" inserts an item already there (the answer contains() gives, and nothing written); "new" inserts a
// fresh item into a table that stays at most a quarter full (a fixed number of items per thread, into a table made
// for the run); "drop" inserts a fresh item into a full table (probes kProbe slots, counts the drop).
std::unique_ptr<ResultCache> freshTable;

void BM_ResultCacheInsert(benchmark::State& state) {
  const int mode = static_cast<int>(state.range(0)); // 0 hit, 1 new, 2 drop
  const Filled& f = filled(mode == 2 ? 1 : 0);
  if (mode == 1 && state.thread_index() == 0) freshTable = std::make_unique<ResultCache>(kSlots * 8);
  // The other threads wait at the loop's start until thread 0 is there, so freshTable is made before any uses it.
  uint64_t i = uint64_t(state.thread_index()) << 32, kept = 0;
  for (auto _ : state) {
    if (mode == 1) {
      const uint64_t q = i++;
      kept += freshTable->insert(keyOf(q), valueOf(q));
    } else {
      const uint64_t q = queryOf(i++, mode == 0, f);
      kept += f.cache->insert(keyOf(q), valueOf(q)); // the table is const, the cache it points to is not
    }
  }
  if (mode == 2 && kept != 0) state.SkipWithError("an item was kept by a full table");
  state.SetItemsProcessed(state.iterations());
  state.counters["kept"] = benchmark::Counter(double(kept) / double(state.iterations()), benchmark::Counter::kAvgThreads);
  state.SetLabel(mode == 0 ? "hit" : mode == 1 ? "new" : "drop (full table)");
}
// arg: 0 hit, 1 new item (2^16 per thread into 2^21 slots), 2 drop (full table)
BENCHMARK(BM_ResultCacheInsert)->Arg(0)->Arg(2)->ArgName("mode")->ThreadRange(1, 8)->UseRealTime();
BENCHMARK(BM_ResultCacheInsert)->Arg(1)->ArgName("mode")->ThreadRange(1, 8)->Iterations(1 << 16)->UseRealTime();

} // namespace
