// fftess verify, stage 5: the shared-edge check's result. For every pair of patches that share (part of) an edge,
// the points the tessellator puts on each side's edge (fftess::edgePoints), positioned by the domain-shader emulation,
// are compared exactly (CGAL predicates): a match, a T-junction or a crack, reported as a Finding with both sides'
// records. How the check runs is check.h (checkScene) and docs/architecture.md ("verify: the stages of a check").
#pragma once

#include "tessellator/tessellator.h"
#include "verify/lod_bridge.h"
#include "verify/terrain.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace fftess::verify {

// What one shared edge pair is, decided exactly (classifyExact, CGAL predicates on the float points).
enum class Classification : uint8_t {
  Match,      // every vertex on one side coincides exactly with a vertex on the other, in order, endpoints included
  TJunction,  // not a match, but every vertex of each side lies exactly on the other side's polyline
  Crack,      // some vertex lies off the other side's polyline: a visible gap
};

// One side of a shared edge.
struct EdgeSide {
  PatchRef patch;
  int edge = 0;                // FactorIndex of the edge in its patch: Ueq0 Veq0 Ueq1 Veq1
  float hullFactor = 0;        // factor the hull shader output (after the adjacency clamp)
  uint32_t hullFactorBits = 0; // its bits
  float processedFactor = 0;   // after the tessellator's processing (EdgePoints::processedFactor)
  bool culled = false;         // the patch is culled (by the LOD, or by the tessellator: some outer factor not > 0)
  EdgeLod lod;                 // where hullFactor came from
  float paramLo = 0, paramHi = 1; // the part of this edge that is shared, in its own edge parameter
  int pointCount = 0;          // edge points inside [paramLo, paramHi]
  int firstMismatch = -1;      // index (into those points) of the first vertex that differs, -1 if none
  DomainPoint mismatchDomain{};   // its (u, v)
  glm::vec3 mismatchWorld{};      // its world position
};

// One classified shared edge pair (Report::findings; matches only with CheckOptions::keepMatches).
struct Finding {
  Classification classification = Classification::Match;
  EdgeSide a;                  // the bigger (or, same size, lower-index) patch
  EdgeSide b;
  Partitioning partitioning = Partitioning::FractionalEven; // the tessellator's partitioning (both sides)
  glm::vec3 edgeStart{}, edgeEnd{}; // the shared edge's ends (flat corners, world)
  // Crack: the vertex farthest from the other side's polyline and that distance (exact with Epeck; converted to
  // double for printing), whether or not the camera sees it. T-junction / match: 0.
  double gapWorld = 0;
  // gapWorld in pixels at the vertex's view depth, with lod's projection (lod::makeCamera): gapWorld *
  // projection[1][1] * viewport.y / 2 / depth, depth = -(view * vertex).z (0 if at or behind the eye plane).
  double gapPixels = 0;
  glm::vec3 gapVertex{};
  int gapSide = 0;             // 0: the vertex is on side a, 1: on side b
  // On screen (docs/verify.md, "On screen"): false only when the finding is proven outside the view frustum (near
  // and far planes included): every triangle of a strip zipped between its two sides has its box outside one plane.
  // Occlusion by other terrain is not considered. Matches: true.
  bool onScreen = true;
  // Crack on screen: the widest the gap is where the camera may see it: the largest of (1) the distance of each
  // off-polyline vertex whose gap segment (to the nearest point of the other side) is not proven off screen (exact
  // as gapWorld) and (2) the width (double) where either side's edge crosses the frustum's boundary; when neither
  // exists (no part of either edge in view, but the strip may be), gapWorld at gapVertex. onScreenGapVertex: where it
  // was measured (a vertex, or a point where an edge leaves the view). Pixels there, but never nearer than the near
  // plane: onScreenGapWorld * projection[1][1] * viewport.y / 2 / max(depth, camera.near). Off screen, T-junction,
  // match: 0.
  double onScreenGapWorld = 0;
  double onScreenGapPixels = 0;
  glm::vec3 onScreenGapVertex{};
  int onScreenGapSide = 0;     // 0: measured on side a, 1: on side b
};

// The LOD's record of one side in words: the fix names (lod::fixName, in bit order), then the neighbour rule
// ("neighbour 2x: rebuilt edge_vector", "neighbour 0.5x") and "culled"; "" when lod/ did not run or changed
// nothing. For printing; cli prints from the record itself where it needs more.
std::string lodWords(const EdgeSide& side);

// "match", "t_junction", "crack".
const char* toString(Classification c);

} // namespace fftess::verify
