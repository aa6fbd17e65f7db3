// The edge points cache of the check (EdgeCache, verify/internal.h): fftess::edgePoints per distinct hull factor of
// a camera, in an open-addressing table keyed by the factor's bits, so that a sweep tessellates each factor once per
// camera and allocates nothing per camera once warm.
#include "verify/internal.h"

#include <algorithm>
#include <cstring>

namespace fftess::verify::detail {

EdgeCache::EdgeCache(Partitioning p, const Stage& s, const Options& o)
    : partitioning_(p), stage_(s), options_(o), keys_(kSlots, 0), gen_(kSlots, 0), slot_(kSlots, -1) {}

void EdgeCache::newCamera() {
  used_ = 0;
  if (++generation_ == 0) { // wrapped: forget every stamp
    std::fill(gen_.begin(), gen_.end(), 0u);
    generation_ = 1;
  }
}

void EdgeCache::grow() {
  const size_t n = keys_.size() * 2, mask = n - 1;
  std::vector<uint32_t> keys(n, 0), gen(n, 0);
  std::vector<int32_t> slot(n, -1);
  for (size_t i = 0; i < keys_.size(); ++i) {
    if (gen_[i] != generation_) continue;
    size_t h = (static_cast<size_t>(keys_[i]) * 0x9E3779B1u) & mask;
    while (gen[h] == generation_) h = (h + 1) & mask;
    keys[h] = keys_[i];
    gen[h] = generation_;
    slot[h] = slot_[i];
  }
  keys_.swap(keys);
  gen_.swap(gen);
  slot_.swap(slot);
}

const EdgePoints& EdgeCache::get(float factor, WorkStats& work) {
  const uint32_t bits = bitsOf(factor);
  // Linear probing in a table kept at most half full: it grows (entries keep their addresses) within a camera.
  if (used_ * 2 >= keys_.size()) grow();
  const size_t mask = keys_.size() - 1;
  size_t h = (static_cast<size_t>(bits) * 0x9E3779B1u) & mask;
  for (; gen_[h] == generation_; h = (h + 1) & mask)
    if (keys_[h] == bits) return entries_[static_cast<size_t>(slot_[h])];
  ++work.edgeQueries;
  keys_[h] = bits;
  gen_[h] = generation_;
  slot_[h] = static_cast<int32_t>(used_);
  if (used_ == entries_.size()) entries_.emplace_back();
  EdgePoints& e = entries_[used_++];
  e = edgePoints(factor, partitioning_, stage_, options_);
  return e;
}

} // namespace fftess::verify::detail
