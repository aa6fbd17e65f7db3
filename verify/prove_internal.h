// Internal header of fftess prove (verify/prove.h): the pieces proveScene is made of. Not installed.
//   prove_bridge.cpp   the scene's LOD settings -> lod/lod_bound.h calls (patchLodBound, as lod_bridge.cpp's patchLod),
//                      the region's cameras as Bounds, the exact frustum planes over a region (RegionFrustum) and the
//                      culling argument;
//   prove_region.cpp   one region's evaluation: every patch pair decided by trace, by value or off screen;
//   prove.cpp          proveScene: branch and bound over regions on threads, sampled counterexamples, the verdict.
#pragma once

#include "lod/lod_bound.h"
#include "verify/internal.h"
#include "verify/prove.h"

#include <string>
#include <vector>

namespace fftess::verify::detail {

// ---------------------------------------------------------------------------------------------------------------
// prove_bridge.cpp

// lod_bridge.cpp's patchLod with Bounds: the scene's built-in scheme (not geomorph, not lod.shader) for patch p, the
// tile-ring *TileBound variants where patches of different sizes meet (t.adjacency). Call inside forEachPath.
lod::BoundPatchLod patchLodBound(const TerrainData& t, const TerrainPatch& p, const lod::BoundCamera& camera);

// The cameras of a region: the LOD's camera (toLodCamera's convention) and the verifier's GL view camera (viewCamera),
// as Bounds (lod::boundCameraRegion). Needs an active BoundContext.
struct RegionCameras {
  lod::BoundCamera lod;
  lod::BoundCamera view;
};
RegionCameras regionCameras(const Camera& sceneCamera, const CameraRegion& r);

// A closed interval of reals, in double, rounded outward by a relative 2^-40 after every operation (far below every
// margin it is compared with; double products of floats are exact, sums of a few terms nearly so).
struct Interval {
  double lo = 0, hi = 0;
};

// The frustum of every camera of a region, exactly (the real values of the float view matrices the region's cameras
// have, times the float projection), as intervals: for a world point q and plane k (FrustumTest's order: w + x,
// w - x, w + y, w - y, w + z, w - z, GL clip space), the plane's value at q over every camera, its clip w, and the
// magnitude bound FrustumTest::boxOffScreen scales its margin with (an upper bound of it for every camera).
class RegionFrustum {
public:
  explicit RegionFrustum(const lod::BoundCamera& view);
  Interval plane(int k, const glm::dvec3& q) const;
  Interval clipW(const glm::dvec3& q) const;
  double scale(int k, const glm::dvec3& q) const; // >= sum over c of (|m[3][c]| + |m[row][c]|) |q_c|, q_3 = 1
  // For every camera of the region, the box [lo, hi] lies outside one plane (the same plane for all) by more than
  // boxOffScreen's margin (2^-16 of scale): FrustumTest::boxOffScreen holds for every camera (and so boxOutside).
  bool boxOffScreen(const glm::dvec3& lo, const glm::dvec3& hi) const;
  // The culling argument (docs/verify.md, "Proofs"): a patch whose lod/ frustum test culls it at some camera of the
  // region loses no pixel centre. lodLo / lodHi: lod/'s culling box; lo / hi: the patch's box (patchBox).
  // True when (a) the near and far planes cannot reject the lod box at any camera of the region (some corner lies
  // inside by more than the test's rounding bound) and (b) every corner of the patch's box is in front of every camera
  // (w > 0) and each side plane's rounding bound (of lod/'s test and of the vertex transform) plus the patch box's
  // excess over the lod box along the plane stays below half of the half-pixel margin w / W at every corner.
  // Otherwise why says which condition failed.
  bool cullHarmless(const glm::dvec3& lodLo, const glm::dvec3& lodHi, const glm::dvec3& lo, const glm::dvec3& hi,
                    std::string& why) const;

private:
  Interval v_[4][4];    // view[c][l] (column c, row l), the float sets of the region's cameras
  double p_[4][4] = {}; // projection[c][r]
  double viewport_[2] = {1, 1};
};

// lod/'s culling box of a patch (common.glsl patchOutsideFrustum): the corners' box, y widened by the height bounds.
void lodBox(const TerrainPatch& p, glm::dvec3& lo, glm::dvec3& hi);

// ---------------------------------------------------------------------------------------------------------------
// prove_region.cpp

// What one region's evaluation found.
enum class RegionOutcome : uint8_t {
  Decided,   // every camera of the region: watertight, no hole (what PROVED assumes)
  Undecided, // some pair or patch could not be decided (why); split
  Suspect,   // some pair's factors give a mismatch, or a patch may be discarded on screen: sample cameras (why)
};
struct RegionResult {
  RegionOutcome outcome = RegionOutcome::Decided;
  std::string why;
  int64_t pairsByTrace = 0, pairsByValue = 0, pairsOffScreen = 0, patchesOffScreen = 0, lodPaths = 0;
  bool onScreen = false; // some patch may be on screen for some camera of the region (false: nothing to check)
};

// Per-thread state of the region evaluations (BoundContext, edge points cache, scratch).
struct ProveScratch {
  ProveScratch(const TerrainData& t, int maxPaths);
  lod::BoundContext context;
  EdgeCache edges;
  std::vector<glm::vec3> pa, pb;
  std::vector<DomainPoint> da;
  std::vector<char> offScreen, cullChecked, cullOk;
  std::vector<std::string> cullWhy;
  std::vector<char> evaluated;
};

// Decides one region: every shared edge pair (forEachEdgePair order) whose joint box is not off screen for every
// camera of the region, by a joint evaluation of both patches over every path (docs/verify.md, "Proofs").
// seams: per pair number, the seam proof (SeamProof as a byte, 0 = not asked yet), filled as pairs need it.
RegionResult evaluateRegion(const TerrainData& t, const CameraRegion& region, ProveScratch& scratch,
                            std::vector<uint8_t>& seams);

// The pair (ia, e, ib) classified for concrete factors fa (patch ia's edge e) and fb (ib's opposite edge), as the
// check classifies it with no camera-dependent domain state: edge points, the shared part, bits, then classifyExact.
Classification classifyPairFactors(const TerrainData& t, size_t ia, int e, size_t ib, float fa, float fb,
                                   ProveScratch& s, Kernel kernel);

} // namespace fftess::verify::detail
