// Primitive-level differences (compare_internal.h): which triangles or segments only one side has, in each side's
// output order, with their indices; and strict order's "rotated" (the same primitives, some starting elsewhere).
#include "compare/compare_internal.h"

#include <algorithm>
#include <utility>

namespace fftess {
namespace {

uint64_t keyOf(CapturedVertex v) { return (uint64_t(v.u) << 32) | v.v; }

struct Keyed {
  PrimitiveKey key;
  int primitive; // position in the side's output
};
bool operator<(const Keyed& a, const Keyed& b) { return a.key != b.key ? a.key < b.key : a.primitive < b.primitive; }

// A side's primitives sorted by key, copies of one key in output order.
std::vector<Keyed> keyedPrimitives(const std::vector<CapturedVertex>& v, int arity) {
  std::vector<Keyed> out;
  out.reserve(v.size() / size_t(arity));
  for (size_t i = 0; i + size_t(arity) <= v.size(); i += size_t(arity))
    out.push_back(Keyed{primitiveKey(&v[i], arity), int(i / size_t(arity))});
  std::sort(out.begin(), out.end());
  return out;
}

// The multiset difference both ways round, as output positions in increasing order: the k-th copy of a key on one
// side pairs with the k-th copy on the other, so the surplus copies are the later ones.
void unpaired(const std::vector<Keyed>& a, const std::vector<Keyed>& b, std::vector<int>& onlyA,
              std::vector<int>& onlyB) {
  size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].key < b[j].key)) {
      onlyA.push_back(a[i++].primitive);
    } else if (i == a.size() || b[j].key < a[i].key) {
      onlyB.push_back(b[j++].primitive);
    } else {
      ++i, ++j;
    }
  }
  std::sort(onlyA.begin(), onlyA.end());
  std::sort(onlyB.begin(), onlyB.end());
}

// The reference's point array as (key, index) sorted by key: a vertex's index in tessellate's numbering.
class PointIndex {
public:
  explicit PointIndex(const std::vector<CapturedVertex>& points) {
    byKey_.reserve(points.size());
    for (size_t i = 0; i < points.size(); ++i) byKey_.emplace_back(keyOf(points[i]), int32_t(i));
    std::sort(byKey_.begin(), byKey_.end());
  }
  int32_t find(CapturedVertex v) const {
    const uint64_t k = keyOf(v);
    auto it = std::lower_bound(byKey_.begin(), byKey_.end(), std::make_pair(k, int32_t(-1)));
    return it != byKey_.end() && it->first == k ? it->second : -1;
  }

private:
  std::vector<std::pair<uint64_t, int32_t>> byKey_;
};

void listPrimitives(const std::vector<int>& positions, const std::vector<CapturedVertex>& v,
                    const std::vector<int32_t>* own, const PointIndex& points, int arity, int maxDetails,
                    std::vector<PrimitiveDifference>& out) {
  for (size_t n = 0; n < positions.size() && int(n) < maxDetails; ++n) {
    PrimitiveDifference d;
    d.primitive = positions[n];
    for (int k = 0; k < arity; ++k) {
      const size_t at = size_t(d.primitive) * size_t(arity) + size_t(k);
      d.vertices.push_back(v[at]);
      if (own) d.indices.push_back((*own)[at]);
      d.referenceIndices.push_back(points.find(v[at]));
    }
    out.push_back(std::move(d));
  }
}

} // namespace

PrimitiveKey primitiveKey(const CapturedVertex* v, int arity) {
  PrimitiveKey p{0, 0, 0};
  for (int k = 0; k < arity && k < 3; ++k) p[size_t(k)] = keyOf(v[k]);
  if (arity == 2) {
    if (p[1] < p[0]) std::swap(p[0], p[1]);
  } else if (arity == 3) {
    // The lexicographically smallest rotation, not "the smallest vertex first": with two coincident vertices
    // (A, A, B), the rotations (A, A, B) and (A, B, A) both start at A and are one triangle (a driver that starts
    // triangles at its own vertex gives either; docs/oracle.md "Real hardware").
    p = std::min({p, PrimitiveKey{p[1], p[2], p[0]}, PrimitiveKey{p[2], p[0], p[1]}});
  }
  return p;
}

bool sameUpToRotation(const std::vector<CapturedVertex>& ref, const std::vector<CapturedVertex>& cap, int arity,
                      int& rotated) {
  rotated = 0;
  if (arity < 2 || ref.size() != cap.size()) return false;
  for (size_t i = 0; i + size_t(arity) <= ref.size(); i += size_t(arity)) {
    if (primitiveKey(&ref[i], arity) != primitiveKey(&cap[i], arity)) return false;
    if (!std::equal(ref.begin() + long(i), ref.begin() + long(i) + arity, cap.begin() + long(i))) ++rotated;
  }
  return true;
}

void primitiveDifferences(const std::vector<CapturedVertex>& ref, const std::vector<int32_t>& refIndices,
                          const std::vector<CapturedVertex>& refPoints, const CapturedPatch* got, int arity,
                          int maxDetails, PatchComparison& c) {
  if (arity < 2) return;
  static const std::vector<CapturedVertex> kNone;
  const std::vector<CapturedVertex>& cap = got ? got->vertices : kNone;
  std::vector<int> onlyRef, onlyCap;
  unpaired(keyedPrimitives(ref, arity), keyedPrimitives(cap, arity), onlyRef, onlyCap);
  c.onlyInReferenceCount = int(onlyRef.size());
  c.onlyInCaptureCount = int(onlyCap.size());
  const PointIndex points(refPoints);
  const bool refOwn = refIndices.size() == ref.size();
  const bool capOwn = got && got->indices.size() == cap.size();
  listPrimitives(onlyRef, ref, refOwn ? &refIndices : nullptr, points, arity, maxDetails, c.onlyInReference);
  listPrimitives(onlyCap, cap, capOwn ? &got->indices : nullptr, points, arity, maxDetails, c.onlyInCapture);
}

} // namespace fftess
