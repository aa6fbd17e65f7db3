// Internal header of fftess_verify (not installed): the seam proof, one of the sweep's shortcuts (docs/verify.md,
// "Sweep shortcuts"). It decides, once per shared edge and without evaluating a single point, that the domain-shader
// emulation (domain.cpp) computes the same point on both sides of the edge for EVERY edge parameter, so that any two
// equal tessellations of the edge match, whatever the camera: the check of such a pair with the same edge points on
// both sides is then a match without evaluating the points.
#pragma once

#include "verify/internal.h"

namespace fftess::verify::detail {

// What proveSeam decided.
enum class SeamProof : uint8_t {
  Unknown = 0,     // not asked yet (the value a cache slot starts with)
  Identical = 1,   // proven: for every finite float t in [0, 1], evalDomain(t, a, edgeDomain(e, t), nullptr) and
                   // evalDomain(t, b, edgeDomain(kOpposite[e], t), nullptr) are the same point (sameBits)
  NotProven = 2,   // no proof (the points may still agree for some or all t): check the pair point by point
};

// Decides whether the two sides of a shared edge are the same function of the edge parameter t, by value numbering
// the float operations of domain.cpp's flat position (bilerp of the corners' x and z in the scene's lerp formula and
// order) and, for domain.height_uv = "interpolated", of the texture coordinates: t is a symbol, every operation on
// constants only is evaluated in float exactly as domain.cpp evaluates it, equal operations on equal operands are
// one value, and only simplifications exact for every t in [0, 1] and every operand value are applied (x * 1 = x,
// x - x = +0 for a finite x, x + (-0) = x, ...). Identical when the two sides' x and z (and texture coordinates) are
// the same value (or both are zeros of either sign, which neither sameBits' == nor the height sampler tells apart)
// and finite; the height is then the same because it is a function of those alone (domain.height_uv "world":
// of x and z; "interpolated": of the texture coordinates) on a camera-independent domain.
// Preconditions: a and b have the same size and share edge e of a (b is across it); the scene's domain needs no
// camera state (domainCamera(t, ...) is empty: no geomorph on a displaced scene, displacement.mip = "none");
// otherwise NotProven. Cost: a few dozen operations on fixed-size arrays on the stack, no allocation (~0.9 us per
// call on the default scene, ~2 us with height_uv "interpolated", Release); called once per edge per sweep.
SeamProof proveSeam(const TerrainData& t, const TerrainPatch& a, int e, const TerrainPatch& b);

// sweep_memo.cpp: the sweep's memo (SweepMemo) for one pair.
// The pair's key, the same for every camera: its number + 1 (static layouts), else the two quadtree nodes' ids and
// the edge; 0: none (ids too large to pack).
uint64_t memoKey(const TerrainData& t, const EdgePair& p);
// The pair's seam proof: proveSeam by the first camera that asks (work.seamProofs), then read by every other, on any
// thread. key: memoKey's (quadtree pairs keep their proof in the result cache).
SeamProof seamOf(SweepMemo& memo, const TerrainData& t, const EdgePair& p, uint64_t key, WorkStats& work);
// The same edge points: the same count and the same parameter bits.
bool sameEdgePoints(const EdgePoints& a, const EdgePoints& b);

} // namespace fftess::verify::detail
