// Internal header of fftess_verify (not installed): the sweep-wide result cache (docs/verify.md, "Sweep shortcuts"),
// a fixed-capacity set of 128-bit items (key, value) shared by a sweep's threads. The sweep keeps in it what it
// proved about a shared edge that no later camera needs to prove again: "this edge pair with these two factor bits
// matched" and the edge's seam proof (seam_proof.h).
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>

namespace fftess::verify::detail {

// A set of (key, value) pairs of 64-bit words, written once and never removed, in one allocation made by the
// constructor: memory is bytes() whatever is inserted (plus the object itself, about 1 KiB of counters). Lock-free:
// contains() is two atomic loads per probed slot and never waits; insert() claims an empty slot with one
// compare-and-swap and never waits either (a slot being written by another thread is passed over). A reader sees an
// item only once it is completely written (the value is stored first, the key word is published last, with release
// order; readers load the key with acquire order), so a torn item is never seen. When the probe window of an item
// (kProbe slots from its hash, wrapping around) holds no empty slot, insert() drops the item and counts it
// (dropped()): the set is bounded, and a dropped item only costs the work of proving it again.
// Probing: an item's window starts at a splitmix64 hash of both words. A probe stops at the first empty slot (the
// item cannot be further on, since nothing is removed and insert() takes the first empty slot of the window) and
// passes over slots being written.
// Duplicates: two threads that insert the same item at once may both claim a slot (each passes over the other's
// slot while it is being written), so an item can occupy two slots. That is harmless: both hold the same item,
// contains() finds the first, and the duplicate only takes a slot (size() counts it twice).
// Reserved keys 0 (empty) and ~0 (being written): contains() is false and insert() refuses them (returns false,
// counts nothing) in every build, so a caller's bad key costs a miss, never a wrong answer.
class ResultCache {
public:
  // capacity: slots, rounded up to a power of two, at least kProbe (std::length_error above the largest power of two
  // of size_t). Memory: 16 bytes per slot. Drops begin well before every slot is taken (random items: from about
  // 40 % of the slots taken; 10 % of inserts are dropped at 75 %): give it about twice the items it is to keep.
  explicit ResultCache(size_t capacity);
  ResultCache(const ResultCache&) = delete;
  ResultCache& operator=(const ResultCache&) = delete;

  // key: any value but 0 and ~0 (reserved: empty and being written). value: any.
  bool contains(uint64_t key, uint64_t value) const;
  // True when the item is in the set afterwards (inserted now, or already there). False when it was dropped (or
  // its key is reserved); another thread may still be inserting the same item at that moment.
  bool insert(uint64_t key, uint64_t value);

  size_t capacity() const { return mask_ + 1; }
  size_t bytes() const { return capacity() * sizeof(Slot); }
  size_t size() const;     // items inserted (slots published; a duplicate counts twice)
  int64_t dropped() const; // items insert() dropped because their window was full

  static constexpr size_t kProbe = 16; // slots probed from an item's hash, linearly

private:
  struct Slot {
    std::atomic<uint64_t> key{0};
    std::atomic<uint64_t> value{0};
  };
  // The counters, striped by the item's hash over cache lines of their own, so that threads inserting different
  // items do not all write one cache line (size() and dropped() sum the stripes).
  struct alignas(64) Counters {
    std::atomic<int64_t> used{0};
    std::atomic<int64_t> dropped{0};
  };
  static constexpr size_t kStripes = 16;

  std::unique_ptr<Slot[]> slots_;
  size_t mask_ = 0;
  Counters counters_[kStripes];
};

} // namespace fftess::verify::detail
