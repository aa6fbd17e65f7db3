// Visible first (CheckOptions::visibleFirst; docs/verify.md, "Sweep shortcuts"): what a camera's check leaves out
// must be off screen. Checked here against the harness's own projection (lod's camera in double, verify_test_util.h's
// inView), not against verify's FrustumTest, and the bounding-volume tree against testing every patch and pair.
#include "verify_test_util.h"

#include "verify/internal.h"

#include <set>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

struct Selection {
  std::vector<char> need, live;
  std::vector<std::array<int32_t, 3>> pairs;
  int64_t patchesOff = 0, edgesOff = 0;
};

Selection select(const detail::TerrainData& t, const Camera& camera) {
  const detail::FrustumTest frustum(detail::viewCamera(camera));
  detail::VisibleSelection s;
  Stats stats;
  WorkStats work;
  detail::selectVisible(t, frustum, s, stats, work);
  Selection out{s.need, s.live, {}, stats.patchesOffScreen, stats.edgesOffScreen};
  for (const detail::EdgePair& p : s.pairs) out.pairs.push_back({p.ia, p.e, p.ib});
  return out;
}

// Any of an n x n grid of domain points of patch i (edges included) in view, by the harness's projection.
bool gridInView(const detail::TerrainData& t, size_t i, const lod::Camera& cam, int n) {
  WorkStats work;
  for (int a = 0; a <= n; ++a)
    for (int b = 0; b <= n; ++b) {
      const glm::vec3 p = detail::evalDomain(t, t.patches[i], float(a) / float(n), float(b) / float(n), nullptr, work);
      if (inView(cam, p)) return true;
    }
  return false;
}

const char* kScenes[] = {"terrain.toml", "rings_small.toml", "grid.toml", "patches.toml", "heightmap_offscreen.toml",
                         "luna.toml"};

} // namespace

TEST_CASE("Visible first: the tree selects exactly what testing every patch and every pair selects",
          "[verify][visible_first]") {
  for (const char* name : kScenes) {
    const Terrain terrain = prepared(loadExample(name));
    const detail::TerrainData& t = terrain.data();
    REQUIRE(t.tree != nullptr);
    detail::TerrainData flat = t; // the same layout without its tree: selectVisible tests every patch and pair
    flat.tree = nullptr;
    int64_t selected = 0, bothOff = 0;
    for (const Camera& camera : randomCameras(terrain, 60, 2201)) {
      INFO(name);
      const Selection a = select(t, camera), b = select(flat, camera);
      CHECK(a.need == b.need);
      CHECK(a.live == b.live);
      CHECK(a.pairs == b.pairs);
      CHECK(a.patchesOff == b.patchesOff);
      CHECK(a.edgesOff == b.edgesOff);
      selected += static_cast<int64_t>(a.pairs.size());
      for (const auto& p : a.pairs) bothOff += !a.live[size_t(p[0])] && !a.live[size_t(p[2])];
    }
    CHECK(selected > 0);
    WARN(name << ": " << selected << " pairs selected over 60 cameras, " << bothOff
              << " of them with both sides off screen (selected by their joint box)");
  }
}

TEST_CASE("Visible first: no patch or edge pair left out has a point in view", "[verify][visible_first]") {
  for (const char* name : kScenes) {
    const Terrain terrain = prepared(loadExample(name));
    const detail::TerrainData& t = terrain.data();
    int64_t leftOut = 0, kept = 0;
    for (const Camera& camera : randomCameras(terrain, 12, 2202)) {
      INFO(name);
      const lod::Camera cam = lodCameraOf(camera);
      const Selection s = select(t, camera);
      std::set<std::array<int32_t, 3>> chosen(s.pairs.begin(), s.pairs.end());
      for (size_t i = 0; i < t.patches.size(); ++i) {
        if (s.need[i]) {
          ++kept;
          continue;
        }
        ++leftOut;
        INFO("patch " << i);
        CHECK_FALSE(gridInView(t, i, cam, 8));
      }
      // Every pair left out: both its patches' grids out of view (its findings are made of their points).
      detail::forEachEdgePair(t, [&](int32_t ia, int e, int32_t ib) {
        if (chosen.count({ia, e, ib})) return;
        CHECK_FALSE(gridInView(t, size_t(ia), cam, 4));
        CHECK_FALSE(gridInView(t, size_t(ib), cam, 4));
      });
    }
    CHECK(leftOut > 0);
    CHECK(kept > 0);
  }
}

TEST_CASE("Visible first: the tree's nodes hold their patches' boxes and every pair sits at a node holding both sides",
          "[verify][visible_first]") {
  const Terrain terrain = prepared(loadExample("terrain.toml"));
  const detail::PatchTree& tree = *terrain.data().tree;
  std::vector<int32_t> first(tree.nodes.size()), last(tree.nodes.size());
  // Subtree patch ranges: leaves hold order[first, first + count); an inner node spans its children.
  for (size_t k = tree.nodes.size(); k-- > 0;) {
    const detail::PatchTree::Node& n = tree.nodes[k];
    if (n.child[0] < 0) {
      first[k] = n.first, last[k] = n.first + n.count;
      continue;
    }
    first[k] = std::min(first[size_t(n.child[0])], first[size_t(n.child[1])]);
    last[k] = std::max(last[size_t(n.child[0])], last[size_t(n.child[1])]);
  }
  std::vector<int32_t> position(tree.order.size());
  for (size_t k = 0; k < tree.order.size(); ++k) position[size_t(tree.order[k])] = int32_t(k);
  size_t filed = 0;
  for (size_t k = 0; k < tree.nodes.size(); ++k) {
    const detail::PatchTree::Node& n = tree.nodes[k];
    for (int32_t j = first[k]; j < last[k]; ++j) {
      const size_t i = size_t(tree.order[size_t(j)]);
      CHECK(glm::all(glm::lessThanEqual(n.lo, tree.boxLo[i])));
      CHECK(glm::all(glm::greaterThanEqual(n.hi, tree.boxHi[i])));
    }
    for (int32_t j = n.pairFirst; j < n.pairFirst + n.pairCount; ++j) {
      const detail::EdgePair& p = tree.allPairs[size_t(tree.pairs[size_t(j)])];
      CHECK(position[size_t(p.ia)] >= first[k]);
      CHECK(position[size_t(p.ia)] < last[k]);
      CHECK(position[size_t(p.ib)] >= first[k]);
      CHECK(position[size_t(p.ib)] < last[k]);
      ++filed;
    }
  }
  CHECK(first[0] == 0);
  CHECK(size_t(last[0]) == tree.order.size());
  CHECK(filed == tree.allPairs.size());
}
