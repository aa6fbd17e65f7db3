// The sweep's memo (SweepMemo, verify/internal.h; docs/verify.md, "Sweep shortcuts"): what one camera proved about a
// shared edge pair, kept for every later camera under a key that is the same for every camera. check.cpp asks it
// before evaluating a pair (decidedByMemo) and stores a pair's match after classifying it.
#include "verify/internal.h"
#include "verify/seam_proof.h"

namespace fftess::verify::detail {

namespace {

// The result cache's values for the seam proofs of pairs without a number (quadtree layouts); a factor pair never
// takes them (a side whose factor bits are 0 is culled, and a culled side is never classified).
constexpr uint64_t kSeamIdentical = 0, kSeamNotProven = 1;

} // namespace

SweepMemo::SweepMemo(size_t slots, size_t pairs)
    : results(slots), seams(new std::atomic<uint8_t>[pairs > 0 ? pairs : 1]()), seamCount(pairs) {}

uint64_t memoKey(const TerrainData& t, const EdgePair& p) {
  if (p.number >= 0) return static_cast<uint64_t>(p.number) + 1;
  if (!t.quadtree) return 0;
  const int na = t.patches[static_cast<size_t>(p.ia)].ref.patch, nb = t.patches[static_cast<size_t>(p.ib)].ref.patch;
  if (na < 0 || nb < 0 || na >= (1 << 29)) return 0;
  return (static_cast<uint64_t>(na) << 34) | (static_cast<uint64_t>(p.e) << 32) | static_cast<uint32_t>(nb);
}

SeamProof seamOf(SweepMemo& m, const TerrainData& t, const EdgePair& p, uint64_t key, WorkStats& work) {
  const TerrainPatch& A = t.patches[static_cast<size_t>(p.ia)];
  const TerrainPatch& B = t.patches[static_cast<size_t>(p.ib)];
  if (p.number >= 0 && static_cast<size_t>(p.number) < m.seamCount) {
    std::atomic<uint8_t>& slot = m.seams[static_cast<size_t>(p.number)];
    uint8_t v = slot.load(std::memory_order_relaxed);
    if (v == static_cast<uint8_t>(SeamProof::Unknown)) {
      ++work.seamProofs;
      v = static_cast<uint8_t>(proveSeam(t, A, p.e, B));
      slot.store(v, std::memory_order_relaxed); // a byte: whole or not at all; two threads may prove the same
    }
    return static_cast<SeamProof>(v);
  }
  if (m.results.contains(key, kSeamIdentical)) return SeamProof::Identical;
  if (m.results.contains(key, kSeamNotProven)) return SeamProof::NotProven;
  ++work.seamProofs;
  const SeamProof r = proveSeam(t, A, p.e, B);
  m.results.insert(key, r == SeamProof::Identical ? kSeamIdentical : kSeamNotProven);
  return r;
}

bool sameEdgePoints(const EdgePoints& a, const EdgePoints& b) {
  if (&a == &b) return true;
  if (a.count != b.count) return false;
  for (int j = 0; j < a.count; ++j)
    if (bitsOf(a.param[j]) != bitsOf(b.param[j])) return false;
  return true;
}

} // namespace fftess::verify::detail
