// The tile-ring neighbour rule for every LOD scheme (lod.h sections 2 and 7, verify/lod_bridge.cpp): with the
// power-of-two clamp every scheme is watertight on tile rings; without a clamp the schemes whose factors are not
// powers of two crack; with the integer clamp the cracks that remain are exactly the ones the 16.16 model
// (tessellator/edge_analysis.h) predicts from the two sides' factors.
#include "verify_test_util.h"

#include "tessellator/edge_analysis.h"

#include <cmath>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

const char* const kSchemes[] = {"screen_sphere", "distance_pow2", "bonaventura", "clip_diameter", "constant"};

std::vector<Camera> someCameras(const Terrain& terrain, int flyover, int random) {
  std::vector<Camera> cams = flyoverCameras(terrain, flyover);
  for (const Camera& c : randomCameras(terrain, random, 20260611)) cams.push_back(c);
  return cams;
}

SweepResult sweepAll(const Scene& s, int flyover, int random) {
  const Terrain terrain = prepared(s);
  SweepOptions so;
  so.threads = 2;
  return sweep(terrain, someCameras(terrain, flyover, random), {}, so);
}

// Does the 16.16 model predict a mismatch on the half of the big edge this finding covers? Big edge of factor
// a.hullFactor beside half-length edges of factor b.hullFactor (compareHalfEdges), rows restricted to the half.
bool predictedMismatch(const Finding& f, const Scene& s) {
  const fftess::HalfEdgeComparison c =
      fftess::compareHalfEdges(f.a.hullFactor, f.b.hullFactor, s.partitioning, s.stage);
  const bool second = f.a.paramLo == 0.5f;
  for (const fftess::HalfEdgeRow& r : c.rows) {
    if (r.match) continue;
    const int64_t t = r.big >= 0 ? c.bigPoints[static_cast<size_t>(r.big)].t : c.smallPoints[static_cast<size_t>(r.small)].t;
    if (second ? t >= 65536 : t <= 65536) return true;
  }
  return false;
}

} // namespace

TEST_CASE("adjacency: pow2 clamp, every scheme sweeps watertight on rings_small", "[verify][adjacency][sweep][slow]") {
  for (const char* scheme : kSchemes) {
    INFO(scheme);
    const Scene s = loadExample("rings_small.toml", {std::string("lod.scheme=") + scheme, "lod.adjacency_clamp=pow2"});
    const SweepResult r = sweepAll(s, 200, 100);
    CHECK(r.camerasDone == 300);
    CHECK(r.total.edgesChecked > 100000);
    CHECK(r.total.cracks == 0);
    CHECK(r.total.tJunctions == 0);
  }
  // Displaced corners (the default scene's setting) with the resampled rebuild: watertight for every scheme too.
  for (const char* scheme : kSchemes) {
    INFO(scheme << " displaced corners, resampled");
    const Scene s = loadExample("rings_small.toml", {std::string("lod.scheme=") + scheme, "lod.displaced_corners=true",
                                                     "lod.reconstruction=resampled"});
    const SweepResult r = sweepAll(s, 100, 50);
    CHECK(r.total.cracks == 0);
    CHECK(r.total.tJunctions == 0);
  }
}

TEST_CASE("adjacency: without a clamp the schemes crack at ring borders (unless their factors are powers of two)",
          "[verify][adjacency][sweep]") {
  for (const char* scheme : {"screen_sphere", "distance_pow2", "clip_diameter"}) {
    INFO(scheme);
    const Scene s = loadExample("rings_small.toml", {std::string("lod.scheme=") + scheme, "lod.adjacency_clamp=none"});
    CHECK(sweepAll(s, 40, 0).total.cracks > 0);
  }
  // A constant factor that is not a power of two: 6 beside 2 x 3 cracks (fractional_even rounds 3 up to 4)...
  Scene s = loadExample("rings_small.toml", {"lod.scheme=constant", "lod.factor=6", "lod.adjacency_clamp=none"});
  CHECK(checkScene(prepared(s), s.camera).stats.cracks > 0);
  // ... and the power-of-two clamp closes it (8 beside 2 x 4).
  s = loadExample("rings_small.toml", {"lod.scheme=constant", "lod.factor=6", "lod.adjacency_clamp=pow2"});
  CHECK(checkScene(prepared(s), s.camera).stats.cracks == 0);
}

TEST_CASE("adjacency: with the integer clamp the remaining cracks are exactly the 16.16 model's", "[verify][adjacency][sweep]") {
  for (const char* scheme : {"screen_sphere", "distance_pow2", "clip_diameter", "bonaventura"}) {
    const Scene s = loadExample("rings_small.toml", {std::string("lod.scheme=") + scheme, "lod.adjacency_clamp=integer"});
    CheckOptions o;
    o.keepMatches = true;
    o.maxFindings = 1u << 22;
    const Terrain terrain = prepared(s);
    const std::vector<Camera> cams = someCameras(terrain, 40, 20);
    // Each report is looked at once, as it finishes (sweep serialises onReport), and only counted here; the
    // assertions run afterwards on this thread.
    int64_t jumps = 0, predicted = 0, found = 0, sameSizeMismatch = 0, recipeBroken = 0, truncated = 0;
    std::vector<std::string> disagreements;
    SweepOptions so;
    so.threads = 2;
    so.onReport = [&](size_t, const Report& rep) {
      truncated += rep.truncated;
      for (const Finding& f : rep.findings) {
        if (f.a.patch.level == f.b.patch.level) {
          sameSizeMismatch += f.classification != Classification::Match; // both sides compute the same factor
          continue;
        }
        ++jumps;
        // The recipe: big side even, in [4, 64] (no "2 beside 2 x 1"), small side exactly half of it.
        recipeBroken += !(f.a.hullFactor >= 4.0f && f.a.hullFactor <= 64.0f &&
                          std::fmod(f.a.hullFactor, 2.0f) == 0.0f && f.b.hullFactor * 2.0f == f.a.hullFactor);
        const bool want = predictedMismatch(f, s);
        const bool got = f.classification != Classification::Match;
        predicted += want;
        found += got;
        if (want != got && disagreements.size() < 5)
          disagreements.push_back(std::to_string(f.a.hullFactor) + " beside " + std::to_string(f.b.hullFactor) + ": " +
                                  toString(f.classification));
      }
    };
    const SweepResult r = sweep(terrain, cams, o, so);
    CHECK(r.camerasDone == cams.size());
    CHECK(truncated == 0);
    CHECK(sameSizeMismatch == 0);
    CHECK(recipeBroken == 0);
    for (const std::string& d : disagreements) FAIL_CHECK(scheme << ": " << d);
    INFO(scheme << ": " << jumps << " jump pairs, " << predicted << " predicted mismatches, " << found << " found");
    CHECK(jumps > 1000);
    CHECK(predicted == found);
    if (std::string(scheme) != "bonaventura") CHECK(found > 0); // bonaventura's factors are powers of two already
  }
}
