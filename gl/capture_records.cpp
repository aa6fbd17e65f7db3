// The capture's bookkeeping apart from GL: point bounds, the D3D-to-GL spacing, and the records of a draw split by
// patch, permuted (test hook) or resolved to indices by coordinates. See capture_records.h and docs/oracle.md.
#include "capture_records.h"

#include "base/bits.h"
#include "base/splitmix64.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fftess {
namespace oracle {

namespace {

// Segments an edge can have for this factor, never underestimated: clamp to [.., 64] (NaN and +Inf as 64),
// +1 for the rounding up to even/odd of the fractional partitionings, at least 2.
int segmentBound(uint32_t bits) {
  const float f = floatOf(bits);
  if (std::isnan(f) || !(f < 64.0f)) return 64;
  const int s = static_cast<int>(std::ceil(std::max(f, 0.0f))) + 1;
  return std::max(2, std::min(64, s));
}

// GL 4.5 section 11.2.2: a patch whose relevant outer levels include one <= 0 or NaN is discarded.
bool outerDiscards(uint32_t bits) {
  const float f = floatOf(bits);
  return std::isnan(f) || !(f > 0.0f);
}

uint64_t pointKey(uint32_t u, uint32_t v) { return uint64_t(u) << 32 | v; }

} // namespace

int pointBound(const Patch& p) {
  const uint32_t* f = p.factorBits;
  switch (p.domain) {
  case Domain::Quad: {
    for (int i = 0; i < 4; ++i)
      if (outerDiscards(f[i])) return 0;
    int n = 0;
    for (int i = 0; i < 4; ++i) n += segmentBound(f[i]);
    return n + (segmentBound(f[4]) + 1) * (segmentBound(f[5]) + 1);
  }
  case Domain::Tri: {
    for (int i = 0; i < 3; ++i)
      if (outerDiscards(f[i])) return 0;
    int n = 0;
    for (int i = 0; i < 3; ++i) n += segmentBound(f[i]);
    return n + (segmentBound(f[3]) + 1) * (segmentBound(f[3]) + 1);
  }
  case Domain::Isoline:
    if (outerDiscards(f[0]) || outerDiscards(f[1])) return 0;
    return segmentBound(f[0]) * (segmentBound(f[1]) + 1);
  }
  return 0;
}

int glSpacing(Partitioning p) {
  switch (p) {
  // D3D11.3 spec 11.7: pow2 rounding is the HLSL compiler's; the fixed-function unit treats pow2 as integer.
  case Partitioning::Integer:
  case Partitioning::Pow2: return 0;
  case Partitioning::FractionalOdd: return 1;
  case Partitioning::FractionalEven: return 2;
  }
  return 0;
}

namespace records {

void permute(std::vector<uint32_t>& words, int perPrim, uint64_t seed) {
  const size_t recordWords = static_cast<size_t>(perPrim) * kCaptureStride;
  const size_t n = words.size() / recordWords;
  SplitMix64 rng{seed};
  std::vector<uint32_t> tmp(recordWords);
  for (size_t i = n; i > 1; --i) { // Fisher-Yates: record i-1 swapped with a record in [0, i)
    const size_t j = rng.below(i);
    if (j != i - 1)
      std::swap_ranges(words.begin() + long(j * recordWords), words.begin() + long((j + 1) * recordWords),
                       words.begin() + long((i - 1) * recordWords));
  }
  if (perPrim != 3) return;
  for (size_t r = 0; r < n; ++r) {
    const auto first = words.begin() + long(r * recordWords);
    std::rotate(first, first + long(rng.below(3)) * kCaptureStride, first + long(recordWords));
  }
}

bool fileByPatch(const std::vector<uint32_t>& words, int perPrim, const std::vector<std::vector<uint32_t>*>& out,
                 std::string& error) {
  const size_t recordWords = static_cast<size_t>(perPrim) * kCaptureStride;
  for (size_t r = 0; r + recordWords <= words.size(); r += recordWords) {
    const uint32_t local = words[r + 2];
    if (local >= out.size()) {
      error = "a captured record names patch " + std::to_string(local) + " of a draw of " +
              std::to_string(out.size()) + " patches";
      return false;
    }
    for (int k = 1; k < perPrim; ++k)
      if (words[r + static_cast<size_t>(k) * kCaptureStride + 2] != local) {
        error = "a captured primitive mixes vertices of patches " + std::to_string(local) + " and " +
                std::to_string(words[r + static_cast<size_t>(k) * kCaptureStride + 2]);
        return false;
      }
    for (int k = 0; k < perPrim; ++k) {
      out[local]->push_back(words[r + static_cast<size_t>(k) * kCaptureStride]);
      out[local]->push_back(words[r + static_cast<size_t>(k) * kCaptureStride + 1]);
    }
  }
  return true;
}

void indicesByCoordinates(Result& r) {
  r.indices.clear();
  if (r.primitives.empty()) return;
  // (u, v) bits -> index in the point array: open addressing, linear probing, at most half full.
  size_t size = 16;
  while (size < 2 * static_cast<size_t>(r.pointCount())) size *= 2;
  std::vector<uint64_t> keys(size);
  std::vector<int32_t> slots(size, -1);
  auto find = [&](uint64_t key) {
    size_t h = static_cast<size_t>(SplitMix64::mix(key)) & (size - 1);
    while (slots[h] >= 0 && keys[h] != key) h = (h + 1) & (size - 1);
    return h;
  };
  for (int i = 0; i < r.pointCount(); ++i) {
    const uint64_t key = pointKey(r.points[2 * i], r.points[2 * i + 1]);
    const size_t h = find(key);
    if (slots[h] >= 0) return; // coincident points: which one a vertex is, is not observable
    keys[h] = key, slots[h] = i;
  }
  std::vector<int32_t> indices;
  indices.reserve(r.primitives.size() / 2);
  for (size_t k = 0; k + 1 < r.primitives.size(); k += 2) {
    const size_t h = find(pointKey(r.primitives[k], r.primitives[k + 1]));
    if (slots[h] < 0) return; // a vertex that is no point of the point capture
    indices.push_back(slots[h]);
  }
  r.indices = std::move(indices);
}

} // namespace records
} // namespace oracle
} // namespace fftess
