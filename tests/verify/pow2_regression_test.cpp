// The power-of-two workaround of the NVIDIA terrain sample, as regression tests (see shared facts and
// docs/verify.md): fractional_even at a 2x size jump cracks without a clamp; the integer clamp still cracks
// (12 beside 2 x 6) exactly where the 16.16 arithmetic says; the power-of-two clamp never cracks.
#include "verify_test_util.h"

#include <cmath>
#include <set>

using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

// The 16.16 model of an even integer factor n's points (independent of the tessellator's code): a point i before
// the middle lands at i * round(65536 / n), the second half is mirrored from 1, the midpoint is exactly 0.5.
uint32_t modelPoint(int i, int n) {
  const uint32_t r = static_cast<uint32_t>(std::lround(65536.0 / n));
  if (2 * i < n) return static_cast<uint32_t>(i) * r;
  if (2 * i == n) return 32768;
  return 65536u - static_cast<uint32_t>(n - i) * r;
}

// First index (along the big edge's half starting at point `first`) where the big edge (B) and one small edge
// (B/2) disagree, in exact arithmetic on the big edge's parameter scaled by 2^17; -1 if they agree.
int modelFirstMismatch(int big, bool secondHalf) {
  const int small = big / 2;
  for (int j = 0; j <= small; ++j) {
    const uint64_t b = 2ull * modelPoint(j + (secondHalf ? small : 0), big);
    const uint64_t s = (secondHalf ? 65536ull : 0ull) + modelPoint(j, small);
    if (b != s) return j;
  }
  return -1;
}

bool isPow2(float f) { return f >= 1 && std::exp2(std::round(std::log2(f))) == f; }

double along(const Finding& f, const fftess::DomainPoint& d, int edge) {
  (void)f;
  return (edge == fftess::Ueq0 || edge == fftess::Ueq1) ? d.v : d.u;
}

} // namespace

TEST_CASE("pow2 regression: without a clamp a 2x jump cracks", "[verify][pow2]") {
  Scene s = loadExample("terrain.toml", {"lod.adjacency_clamp=none"});
  for (Kernel k : {Kernel::Epick, Kernel::Epeck}) {
    CheckOptions o;
    o.kernel = k;
    Report r = checkScene(prepared(s), s.camera, o);
    INFO(toString(k));
    CHECK(r.stats.cracks > 0);
    for (const Finding& f : r.findings) {
      CHECK(f.a.patch.level == f.b.patch.level + 1); // only at the ring borders
      CHECK(f.partitioning == fftess::Partitioning::FractionalEven);
    }
  }
}

TEST_CASE("pow2 regression: with the integer clamp 12 beside 2x6 cracks where 16.16 predicts", "[verify][pow2]") {
  // The model first: B = 12 misses 2 x 6 from point 1 on, by 1.5/65536 of the big edge in the second half.
  REQUIRE(modelPoint(1, 12) == 5461);
  REQUIRE(modelPoint(1, 6) == 10923);
  REQUIRE(modelFirstMismatch(12, false) == 1);
  REQUIRE(modelFirstMismatch(12, true) == 1);
  // Only the powers of two from 4 on pass (fractional_even; B = 2 clamps its small side to 2).
  for (int B = 4; B <= 64; B += 2) {
    INFO("B = " << B);
    CHECK((modelFirstMismatch(B, false) < 0 && modelFirstMismatch(B, true) < 0) == isPow2(float(B)));
  }

  Scene s = loadExample("terrain.toml", {"lod.adjacency_clamp=integer"});

  const Terrain terrain = prepared(s);
  for (Kernel k : {Kernel::Epick, Kernel::Epeck}) {
    CheckOptions o;
    o.kernel = k;
    o.maxFindings = 100000;
    int seen12 = 0;
    std::vector<Camera> cams = {s.camera};
    for (const Camera& c : orbitCameras(terrain, 4, 80.0f, 25.0f)) cams.push_back(c);
    for (const Camera& cam : cams) {
      Report r = checkScene(terrain, cam, o);
      for (const Finding& f : r.findings) {
        INFO(toString(k) << " big " << f.a.processedFactor << " small " << f.b.processedFactor);
        CHECK(f.classification == Classification::Crack);
        // Integer clamp: big even, small = big / 2; every crack has a big factor that is not a power of two.
        CHECK(f.a.processedFactor == 2 * f.b.processedFactor);
        CHECK_FALSE(isPow2(f.a.processedFactor));
        const int B = static_cast<int>(f.a.processedFactor);
        const bool second = f.a.paramLo == 0.5f;
        // The model is integer placement; fractional_even places an odd small factor (B = 4k + 2) differently.
        if (B % 4 == 0) CHECK(f.a.firstMismatch == modelFirstMismatch(B, second));
        if (B != 12) continue;
        ++seen12;
        // The exact points: big point 1 (or 7) against small point 1, as 16.16 parameters.
        CHECK(along(f, f.a.mismatchDomain, f.a.edge) == modelPoint(second ? 7 : 1, 12) / 65536.0);
        CHECK(along(f, f.b.mismatchDomain, f.b.edge) == modelPoint(1, 6) / 65536.0);
      }
      // A power-of-two big factor beside its half never appears as a finding (checked above); and some edges
      // did match, so the jumps are not all cracks.
      CHECK(r.stats.matches > 0);
    }
    CHECK(seen12 > 0);
  }
}

TEST_CASE("pow2 regression: the pow2 clamp never cracks over 1000 cameras", "[verify][pow2][sweep][slow]") {
  Scene s = loadExample("rings_small.toml");
  const Terrain terrain = prepared(s);
  std::vector<Camera> cams = randomCameras(terrain, 900, 20261122);
  for (const Camera& c : orbitCameras(terrain, 50, 60.0f, 10.0f)) cams.push_back(c);
  for (const Camera& c : flyoverCameras(terrain, 50, 6.0f)) cams.push_back(c);
  REQUIRE(cams.size() >= 1000);
  SweepOptions so;
  so.threads = 2;
  SweepResult r = sweep(terrain, cams, {}, so);
  CHECK(r.camerasDone == cams.size());
  CHECK(r.total.edgesChecked > 1000000);
  CHECK(r.total.cracks == 0);
  CHECK(r.total.tJunctions == 0);

  // The same cameras see size jumps that crack without the clamp (so the sweep did cross the ring borders).
  Scene none = loadExample("rings_small.toml", {"lod.adjacency_clamp=none"});
  std::vector<Camera> some(cams.begin(), cams.begin() + 100);
  SweepResult rn = sweep(prepared(none), some, {}, so);
  CHECK(rn.total.cracks > 0);
}

// lod::nvidiaTile's edge_vector reconstruction with raised (displaced) corners: the larger side keeps its displaced
// edge, the smaller side rebuilds it with the height of the corner it moved from, so the two measure different
// spheres and can round to different powers of two (the seed's own warning: the vector math is not guaranteed to
// rebuild the same vertex). resampled (the default scene's) re-acquires the rebuilt corner's height as the vertex
// shader samples it; far_corner passes the larger patch's own corner. Recorded so that a change in lod/ shows here.
TEST_CASE("pow2 regression: with displaced corners the EdgeVector rebuild mismatches factors", "[verify][pow2]") {
  Scene bad = loadExample("terrain.toml", {"lod.displaced_corners=true", "lod.reconstruction=edge_vector"});
  Report r = checkScene(prepared(bad), bad.camera);
  CHECK(r.stats.cracks > 0);
  for (const Finding& f : r.findings) {
    CHECK(f.a.processedFactor != 2 * f.b.processedFactor);
    // The LOD's own record: both sides went through the pow2 clamp; the small side rebuilt the big edge by the
    // edge vector.
    CHECK((f.a.lod.why.fixes & fftess::lod::FixPow2Clamp) != 0);
    CHECK((f.b.lod.why.fixes & fftess::lod::FixPow2Clamp) != 0);
    CHECK((f.b.lod.why.fixes & fftess::lod::FixLargerNeighbour) != 0);
    CHECK(f.b.lod.neighbourSize == 2.0f);
    CHECK(f.b.lod.reconstruction == fftess::lod::Reconstruction::EdgeVector);
  }
  Scene good = loadExample("terrain.toml", {"lod.displaced_corners=true", "lod.reconstruction=far_corner"});
  CHECK(checkScene(prepared(good), good.camera).stats.cracks == 0);
  // The default scene: displaced corners, resampled.
  Scene def = loadExample("terrain.toml");
  CHECK(def.lod.displacedCorners);
  CHECK(def.lod.screenSphere.reconstruction == fftess::lod::Reconstruction::Resampled);
  const Report rd = checkScene(prepared(def), def.camera);
  CHECK(rd.stats.cracks == 0);
  CHECK(rd.stats.tJunctions == 0);
  // Over more cameras: edge_vector cracks somewhere, resampled nowhere (the same cameras).
  const Terrain tb = prepared(bad), td = prepared(def);
  const std::vector<Camera> cams = orbitCameras(td, 12, 80.0f, 25.0f);
  SweepOptions so;
  so.threads = 2;
  CHECK(sweep(tb, cams, {}, so).total.cracks > 0);
  const SweepResult sd = sweep(td, cams, {}, so);
  CHECK(sd.total.cracks == 0);
  CHECK(sd.total.tJunctions == 0);
}
