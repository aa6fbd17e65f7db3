// Visible first (CheckOptions::visibleFirst; docs/verify.md, "Sweep shortcuts"): per camera, the patches and the
// shared edge pairs that could show the camera something. What is left out is proven off screen by
// FrustumTest::boxOffScreen (in double, with a margin for a GPU's clip-space rounding), and that test is monotone: a
// box inside a box proven off screen is off screen too. Every point the check evaluates for a patch lies in its
// patchBox, so:
//   - a patch whose box is off screen cannot be a hole or an undecided patch (holes are on screen by construction);
//   - every finding of a pair lies in the joint box of its two patches (markOnScreen's strip of triangles is made of
//     the two sides' points), so a pair whose joint box is off screen can only give off-screen findings.
// Static layouts walk a bounding-volume tree: a node off screen settles its patches and the pairs filed at it or
// below in one test. Quadtree layouts (patches change per camera) test every patch and pair.
#include "verify/internal.h"

#include <algorithm>

namespace fftess::verify::detail {

void patchBox(const TerrainPatch& p, glm::dvec3& lo, glm::dvec3& hi) {
  lo = hi = glm::dvec3(p.corners[0]);
  for (const glm::vec3& c : p.corners) {
    lo = glm::min(lo, glm::dvec3(c));
    hi = glm::max(hi, glm::dvec3(c));
  }
  const double padX = std::fmax(std::fabs(lo.x), std::fabs(hi.x)) * 0x1p-20 + 1e-30;
  const double padZ = std::fmax(std::fabs(lo.z), std::fabs(hi.z)) * 0x1p-20 + 1e-30;
  lo.x -= padX, hi.x += padX, lo.z -= padZ, hi.z += padZ;
  lo.y = p.surfaceMinY;
  hi.y = p.surfaceMaxY;
}

namespace {

constexpr int32_t kLeafPatches = 8;

struct TreeBuilder {
  const TerrainData& t;
  PatchTree& tree;
  std::vector<int32_t> leafOf, parent, depth;

  int32_t build(int32_t first, int32_t count, int32_t up, int32_t level) {
    const int32_t id = static_cast<int32_t>(tree.nodes.size());
    tree.nodes.emplace_back();
    parent.push_back(up);
    depth.push_back(level);
    glm::dvec3 lo = tree.boxLo[static_cast<size_t>(tree.order[static_cast<size_t>(first)])], hi = lo;
    int64_t minX = INT64_MAX, maxX = INT64_MIN, minZ = INT64_MAX, maxZ = INT64_MIN;
    for (int32_t k = first; k < first + count; ++k) {
      const size_t i = static_cast<size_t>(tree.order[static_cast<size_t>(k)]);
      lo = glm::min(lo, tree.boxLo[i]);
      hi = glm::max(hi, tree.boxHi[i]);
      const TerrainPatch& p = t.patches[i];
      minX = std::min(minX, 2 * p.ux + p.size), maxX = std::max(maxX, 2 * p.ux + p.size);
      minZ = std::min(minZ, 2 * p.uz + p.size), maxZ = std::max(maxZ, 2 * p.uz + p.size);
    }
    tree.nodes[static_cast<size_t>(id)].lo = lo;
    tree.nodes[static_cast<size_t>(id)].hi = hi;
    if (count <= kLeafPatches) {
      tree.nodes[static_cast<size_t>(id)].first = first;
      tree.nodes[static_cast<size_t>(id)].count = count;
      for (int32_t k = first; k < first + count; ++k) leafOf[static_cast<size_t>(tree.order[static_cast<size_t>(k)])] = id;
      return id;
    }
    // Split at the median of the patch centres (doubled, integer) along the longer side of their extent.
    const bool alongX = maxX - minX >= maxZ - minZ;
    auto centre = [&](int32_t i) {
      const TerrainPatch& p = t.patches[static_cast<size_t>(i)];
      return alongX ? 2 * p.ux + p.size : 2 * p.uz + p.size;
    };
    const int32_t half = count / 2;
    auto b = tree.order.begin() + first;
    std::nth_element(b, b + half, b + count, [&](int32_t x, int32_t y) {
      const int64_t cx = centre(x), cy = centre(y);
      return cx != cy ? cx < cy : x < y;
    });
    const int32_t left = build(first, half, id, level + 1);
    const int32_t right = build(first + half, count - half, id, level + 1);
    tree.nodes[static_cast<size_t>(id)].child[0] = left;
    tree.nodes[static_cast<size_t>(id)].child[1] = right;
    return id;
  }

  int32_t lowestCommon(int32_t a, int32_t b) const {
    while (depth[static_cast<size_t>(a)] > depth[static_cast<size_t>(b)]) a = parent[static_cast<size_t>(a)];
    while (depth[static_cast<size_t>(b)] > depth[static_cast<size_t>(a)]) b = parent[static_cast<size_t>(b)];
    while (a != b) a = parent[static_cast<size_t>(a)], b = parent[static_cast<size_t>(b)];
    return a;
  }
};

// A pair whose one side is on screen is selected without a test (its joint box contains that side's box); a pair
// of two off-screen sides needs its joint box tested (the two may be off screen beyond different planes).
bool pairSelected(const FrustumTest& frustum, const std::vector<char>& live, const glm::dvec3& loA,
                  const glm::dvec3& hiA, const glm::dvec3& loB, const glm::dvec3& hiB, int32_t a, int32_t b,
                  WorkStats& work) {
  if (live[static_cast<size_t>(a)] || live[static_cast<size_t>(b)]) return true;
  ++work.boxTests;
  return !frustum.boxOffScreen(glm::min(loA, loB), glm::max(hiA, hiB));
}

// Quadtree layouts: every patch's box, then every pair.
void selectLinear(const TerrainData& t, const FrustumTest& frustum, VisibleSelection& s, Stats& stats,
                  WorkStats& work) {
  const size_t n = t.patches.size();
  std::vector<glm::dvec3>& lo = s.boxLo; // per-thread scratch: no allocation once warm
  std::vector<glm::dvec3>& hi = s.boxHi;
  lo.resize(n);
  hi.resize(n);
  for (size_t i = 0; i < n; ++i) {
    patchBox(t.patches[i], lo[i], hi[i]);
    ++work.boxTests;
    s.live[i] = frustum.boxOffScreen(lo[i], hi[i]) ? 0 : 1;
    s.need[i] = s.live[i];
  }
  int64_t total = 0;
  forEachEdgePair(t, [&](int32_t ia, int e, int32_t ib) {
    ++total;
    const size_t a = static_cast<size_t>(ia), b = static_cast<size_t>(ib);
    if (!pairSelected(frustum, s.live, lo[a], hi[a], lo[b], hi[b], ia, ib, work)) return;
    s.pairs.push_back(EdgePair{ia, ib, e, -1});
    s.need[a] = s.need[b] = 1;
  });
  stats.edgesOffScreen = total - static_cast<int64_t>(s.pairs.size());
}

void selectTree(const PatchTree& tree, const FrustumTest& frustum, VisibleSelection& s,
                Stats& stats, WorkStats& work) {
  // The stack holds node ids, negated minus one for a node inside a node proven wholly in view (boxInside): its
  // patches are on screen without a test.
  s.stack.assign(1, 0);
  s.liveNodes.clear();
  while (!s.stack.empty()) {
    const int32_t top = s.stack.back();
    s.stack.pop_back();
    bool inside = top < 0;
    const int32_t id = inside ? -top - 1 : top;
    const PatchTree::Node& node = tree.nodes[static_cast<size_t>(id)];
    if (!inside) {
      ++work.boxTests;
      if (frustum.boxOffScreen(node.lo, node.hi)) continue;
      inside = frustum.boxInside(node.lo, node.hi);
    }
    s.liveNodes.push_back(id);
    if (node.child[0] >= 0) {
      s.stack.push_back(inside ? -node.child[1] - 1 : node.child[1]);
      s.stack.push_back(inside ? -node.child[0] - 1 : node.child[0]);
      continue;
    }
    for (int32_t k = node.first; k < node.first + node.count; ++k) {
      const size_t i = static_cast<size_t>(tree.order[static_cast<size_t>(k)]);
      if (!inside) ++work.boxTests;
      s.live[i] = inside || !frustum.boxOffScreen(tree.boxLo[i], tree.boxHi[i]) ? 1 : 0;
      s.need[i] = s.live[i];
    }
  }
  // The pairs filed at nodes not proven off screen, marked by their number so that they come out in the check's order.
  s.pairBits.assign((tree.allPairs.size() + 63) / 64, 0);
  for (const int32_t id : s.liveNodes) {
    const PatchTree::Node& node = tree.nodes[static_cast<size_t>(id)];
    for (int32_t k = node.pairFirst; k < node.pairFirst + node.pairCount; ++k) {
      const int32_t q = tree.pairs[static_cast<size_t>(k)];
      const EdgePair& p = tree.allPairs[static_cast<size_t>(q)];
      const size_t a = static_cast<size_t>(p.ia), b = static_cast<size_t>(p.ib);
      if (!pairSelected(frustum, s.live, tree.boxLo[a], tree.boxHi[a], tree.boxLo[b], tree.boxHi[b], p.ia, p.ib, work))
        continue;
      s.pairBits[static_cast<size_t>(q) / 64] |= uint64_t(1) << (q % 64);
      s.need[a] = s.need[b] = 1;
    }
  }
  for (size_t w = 0; w < s.pairBits.size(); ++w)
    for (uint64_t bits = s.pairBits[w]; bits != 0; bits &= bits - 1)
      s.pairs.push_back(tree.allPairs[w * 64 + static_cast<size_t>(__builtin_ctzll(bits))]);
  stats.edgesOffScreen = static_cast<int64_t>(tree.allPairs.size() - s.pairs.size());
}

} // namespace

std::shared_ptr<const PatchTree> buildPatchTree(const TerrainData& t) {
  auto tree = std::make_shared<PatchTree>();
  const size_t n = t.patches.size();
  if (n == 0) return tree;
  tree->boxLo.resize(n);
  tree->boxHi.resize(n);
  for (size_t i = 0; i < n; ++i) patchBox(t.patches[i], tree->boxLo[i], tree->boxHi[i]);
  tree->order.resize(n);
  for (size_t i = 0; i < n; ++i) tree->order[i] = static_cast<int32_t>(i);
  TreeBuilder b{t, *tree, std::vector<int32_t>(n, -1), {}, {}};
  b.build(0, static_cast<int32_t>(n), -1, 0);
  forEachEdgePair(t, [&](int32_t ia, int e, int32_t ib) {
    tree->allPairs.push_back(EdgePair{ia, ib, e, static_cast<int32_t>(tree->allPairs.size())});
  });
  // File every pair at the lowest node holding both its patches (a counting sort by node).
  std::vector<int32_t> at(tree->allPairs.size());
  for (size_t q = 0; q < at.size(); ++q) {
    const EdgePair& p = tree->allPairs[q];
    at[q] = b.lowestCommon(b.leafOf[static_cast<size_t>(p.ia)], b.leafOf[static_cast<size_t>(p.ib)]);
    ++tree->nodes[static_cast<size_t>(at[q])].pairCount;
  }
  int32_t next = 0;
  for (PatchTree::Node& node : tree->nodes) node.pairFirst = next, next += node.pairCount, node.pairCount = 0;
  tree->pairs.resize(at.size());
  for (size_t q = 0; q < at.size(); ++q) {
    PatchTree::Node& node = tree->nodes[static_cast<size_t>(at[q])];
    tree->pairs[static_cast<size_t>(node.pairFirst + node.pairCount++)] = static_cast<int32_t>(q);
  }
  return tree;
}

void selectVisible(const TerrainData& t, const FrustumTest& frustum, VisibleSelection& s, Stats& stats,
                   WorkStats& work) {
  const size_t n = t.patches.size();
  s.need.assign(n, 0);
  s.live.assign(n, 0);
  s.pairs.clear();
  if (t.tree && t.tree->boxLo.size() == n) selectTree(*t.tree, frustum, s, stats, work);
  else selectLinear(t, frustum, s, stats, work);
  int64_t needed = 0;
  for (const char k : s.need) needed += k;
  stats.patchesOffScreen = static_cast<int64_t>(n) - needed;
}

} // namespace fftess::verify::detail
