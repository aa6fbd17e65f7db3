// The sweep-wide result cache (result_cache.h; docs/verify.md, "Sweep shortcuts" -> "Result cache").
//
// Publication protocol of one slot (key word: 0 empty -> ~0 being written -> the item's key, never changed again):
//   writer: CAS key 0 -> ~0 (acq_rel), value.store (relaxed), key.store(key, release)
//   reader: key.load (acquire); when it is the key sought, value.load (relaxed)
// The release store of the key orders the value store before it, and the reader's acquire load of that key orders
// its value load after it: a reader that sees the key sees the value written with it (never 0 or a torn word).
#include "verify/result_cache.h"

#include "base/splitmix64.h"

#include <limits>
#include <stdexcept>

namespace fftess::verify::detail {

namespace {

constexpr uint64_t kEmpty = 0;
constexpr uint64_t kWriting = ~uint64_t(0);

// A hash of both words: splitmix64's finaliser of the key mixed with the finalised value (the value is offset by
// the generator's increment so that value 0 does not hash to 0 and leave the key alone).
uint64_t hashItem(uint64_t key, uint64_t value) {
  return SplitMix64::mix(key ^ SplitMix64::mix(value + SplitMix64::kIncrement));
}

// The stripe of an item's counters: the hash's top bits (the slot index takes its low bits).
size_t stripeOf(uint64_t hash, size_t stripes) { return static_cast<size_t>(hash >> 58) & (stripes - 1); }

size_t roundCapacity(size_t capacity) {
  constexpr size_t kLargest = (std::numeric_limits<size_t>::max() >> 1) + 1; // the largest power of two
  if (capacity > kLargest) throw std::length_error("ResultCache: capacity over the largest power of two");
  size_t c = ResultCache::kProbe;
  while (c < capacity) c <<= 1;
  return c;
}

bool reserved(uint64_t key) { return key == kEmpty || key == kWriting; }

} // namespace

ResultCache::ResultCache(size_t capacity) {
  const size_t slots = roundCapacity(capacity);
  slots_ = std::make_unique<Slot[]>(slots); // every key 0: empty
  mask_ = slots - 1;
}

bool ResultCache::contains(uint64_t key, uint64_t value) const {
  if (reserved(key)) return false;
  const uint64_t h = hashItem(key, value);
  for (size_t i = 0; i < kProbe; ++i) {
    const Slot& s = slots_[(h + i) & mask_];
    const uint64_t k = s.key.load(std::memory_order_acquire);
    if (k == kEmpty) return false; // insert() takes the first empty slot: the item is not further on
    if (k == key && s.value.load(std::memory_order_relaxed) == value) return true;
    // kWriting or another item: go on
  }
  return false;
}

bool ResultCache::insert(uint64_t key, uint64_t value) {
  if (reserved(key)) return false;
  const uint64_t h = hashItem(key, value);
  Counters& counters = counters_[stripeOf(h, kStripes)];
  for (size_t i = 0; i < kProbe; ++i) {
    Slot& s = slots_[(h + i) & mask_];
    uint64_t k = s.key.load(std::memory_order_acquire);
    if (k == kEmpty) {
      // On failure k is what the winner wrote (acquire: if it is a published key, its value is visible).
      if (s.key.compare_exchange_strong(k, kWriting, std::memory_order_acq_rel, std::memory_order_acquire)) {
        s.value.store(value, std::memory_order_relaxed);
        s.key.store(key, std::memory_order_release);
        counters.used.fetch_add(1, std::memory_order_relaxed);
        return true;
      }
    }
    if (k == key && s.value.load(std::memory_order_relaxed) == value) return true;
    // kWriting (perhaps this very item: a duplicate then, harmless) or another item: go on
  }
  counters.dropped.fetch_add(1, std::memory_order_relaxed);
  return false;
}

size_t ResultCache::size() const {
  int64_t n = 0;
  for (const Counters& c : counters_) n += c.used.load(std::memory_order_relaxed);
  return static_cast<size_t>(n);
}

int64_t ResultCache::dropped() const {
  int64_t n = 0;
  for (const Counters& c : counters_) n += c.dropped.load(std::memory_order_relaxed);
  return n;
}

} // namespace fftess::verify::detail
