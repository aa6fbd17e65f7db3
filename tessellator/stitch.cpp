#include "stitch.h"

#include "simd.h"

#include <cstring>
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace fftess {
namespace {

// Where the i-th inserted point lands on a half edge of 32 segments when points are inserted in ruler-function
// order (i = 1..32; entry 0 is the edge's start). With i - 1 = 2^s * q, q odd: position = (16 >> s) + (q - 1) / 2;
// i = 1 lands at the far end (32).
struct RulerOrder {
  int position[33];
  constexpr RulerOrder() : position{} {
    position[0] = 0;
    position[1] = 32;
    for (int i = 2; i <= 32; ++i) {
      int q = i - 1, s = 0;
      while ((q & 1) == 0) {
        q >>= 1;
        ++s;
      }
      position[i] = (16 >> s) + (q - 1) / 2;
    }
  }
};
constexpr RulerOrder kRuler{};
static_assert(kRuler.position[2] == 16 && kRuler.position[3] == 8 && kRuler.position[4] == 17, "ruler order");
static_assert(kRuler.position[9] == 2 && kRuler.position[17] == 1 && kRuler.position[32] == 31, "ruler order");

// The moves of the first half of a transition between rows of nIn and nOut half points (nIn, nOut <= 33), as bits
// in order, 1 = a triangle based on the inside row, 0 = on the outside row: ruler order 0 (outside only), then
// 1..32, inside before outside at each step. The second half is the same sequence reversed.
struct TransitionMoves {
  uint64_t seq[34][34];
  uint8_t len[34][34];
  uint8_t insideMoves[34][34];
  constexpr TransitionMoves() : seq{}, len{}, insideMoves{} {
    for (int nIn = 0; nIn <= 33; ++nIn)
      for (int nOut = 0; nOut <= 33; ++nOut) {
        uint64_t bits = 0;
        int n = 0;
        if (kRuler.position[0] < nOut) ++n;
        for (int k = 1; k <= 32; ++k) {
          if (kRuler.position[k] < nIn) bits |= uint64_t(1) << n++, ++insideMoves[nIn][nOut];
          if (kRuler.position[k] < nOut) ++n;
        }
        seq[nIn][nOut] = bits;
        len[nIn][nOut] = uint8_t(n);
      }
  }
};
constexpr TransitionMoves kMoves{};

template <bool Ccw>
inline void tri(int32_t* d, int a, int b, int c) {
  d[0] = a;
  d[1] = Ccw ? c : b;
  d[2] = Ccw ? b : c;
}

// One move of a transition: bit 1 = triangle (I(i), O(o), I(i+1)), bit 0 = triangle (O(o), O(o+1), I(i)).
// I and O are the rows' point indices, looked up (no per-move redirect test). transition() runs once per template
// (transitionTemplate below), on rows of corner codes.
template <bool Ccw>
inline void move(int32_t* d, uint32_t bit, const int32_t* I, const int32_t* O, int& i, int& o) {
  const int32_t m = -int32_t(bit);
  const int32_t ii = I[i], oo = O[o], i1 = I[i + 1], o1 = O[o + 1];
  tri<Ccw>(d, (ii & m) | (oo & ~m), (oo & m) | (o1 & ~m), (i1 & m) | (ii & ~m));
  i += int(bit);
  o += int(bit ^ 1);
}

constexpr int kMaxRow = 72; // > 2 * 33 + 2 positions

template <bool Ccw>
void transition(MeshWriter& w, const Row& in, int nIn, bool insideOdd, const Row& out, int nOut, bool outsideOdd) {
  const uint64_t seq = kMoves.seq[nIn][nOut];
  const int len = kMoves.len[nIn][nOut];
  const int insideMoves = kMoves.insideMoves[nIn][nOut];
  // Positions used on each row: every move and the middle advance one of them by one, plus the last corner.
  const int nI = 2 * insideMoves + (insideOdd ? 1 : 0) + 1, nO = 2 * (len - insideMoves) + (outsideOdd ? 1 : 0) + 1;
  int32_t I[kMaxRow], O[kMaxRow];
  for (int k = 0; k < nI; ++k) I[k] = in.first + in.step * k;
  for (int k = 0; k < nO; ++k) O[k] = out.first + out.step * k;
  if (in.redirectFrom >= 0 && in.redirectFrom < nI) I[in.redirectFrom] = in.redirectTo;
  if (out.redirectFrom >= 0 && out.redirectFrom < nO) O[out.redirectFrom] = out.redirectTo;
  int32_t* d = w.indices + w.numIndices;
  int i = 0, o = 0;
  for (int j = 0; j < len; ++j, d += 3) move<Ccw>(d, uint32_t(seq >> j) & 1u, I, O, i, o);
  // Middle.
  if (insideOdd && outsideOdd) { // a quad
    tri<Ccw>(d, I[i], O[o], I[i + 1]);
    tri<Ccw>(d + 3, I[i + 1], O[o], O[o + 1]);
    d += 6, ++i, ++o;
  } else if (outsideOdd) { // the outside has the middle segment
    tri<Ccw>(d, I[i], O[o], O[o + 1]);
    d += 3, ++o;
  } else if (insideOdd) { // the inside has it
    tri<Ccw>(d, I[i], O[o], I[i + 1]);
    d += 3, ++i;
  }
  for (int j = len - 1; j >= 0; --j, d += 3) move<Ccw>(d, uint32_t(seq >> j) & 1u, I, O, i, o);
  w.numIndices = int(d - w.indices);
}

// Quads between two rows. Quad p has inside corners I(p), I(p+1) and outside corners O(p+t), O(p+t+1).
enum QuadKind { FromOutside, FromInside, OutsideForward };

template <int K, bool Ccw>
inline void quad(int32_t* d, int i0, int i1, int o0, int o1) {
  if (K == FromOutside) { // diagonal outside(o) - inside(i+1)
    tri<Ccw>(d, o0, i1, i0);
    tri<Ccw>(d + 3, o0, o1, i1);
  } else if (K == FromInside) { // diagonal inside(i) - outside(o+1)
    tri<Ccw>(d, i0, o0, o1);
    tri<Ccw>(d + 3, i0, o1, i1);
  } else { // same diagonal, outside triangle first
    tri<Ccw>(d, o0, o1, i0);
    tri<Ccw>(d + 3, i0, o1, i1);
  }
}

// Rows as affine maps k -> first + step * k (redirects are patched afterwards).
struct Affine {
  int fi, si, fo, so, t;
};

using v8i = int32_t __attribute__((vector_size(32)));

// Quads [begin, end) of one kind, without redirects. Long runs: 4 quads (24 indices) per step, each index affine in p.
template <int K, bool Ccw>
int32_t* quadRun(int32_t* d, const Affine& r, int begin, int end) {
  int p = begin;
  if (end - begin >= 12) {
    int32_t base[24], next[24], step[24];
    for (int q = 0; q < 4; ++q) {
      const int pq = p + q;
      quad<K, Ccw>(base + 6 * q, r.fi + r.si * pq, r.fi + r.si * (pq + 1), r.fo + r.so * (pq + r.t),
                   r.fo + r.so * (pq + r.t + 1));
      quad<K, Ccw>(next + 6 * q, r.fi + r.si * (pq + 4), r.fi + r.si * (pq + 5), r.fo + r.so * (pq + 4 + r.t),
                   r.fo + r.so * (pq + 5 + r.t));
    }
    for (int j = 0; j < 24; ++j) step[j] = next[j] - base[j];
    v8i v0, v1, v2, d0, d1, d2;
    std::memcpy(&v0, base, 32), std::memcpy(&v1, base + 8, 32), std::memcpy(&v2, base + 16, 32);
    std::memcpy(&d0, step, 32), std::memcpy(&d1, step + 8, 32), std::memcpy(&d2, step + 16, 32);
    for (; p + 4 <= end; p += 4, d += 24) {
      std::memcpy(d, &v0, 32), std::memcpy(d + 8, &v1, 32), std::memcpy(d + 16, &v2, 32);
      v0 += d0, v1 += d1, v2 += d2;
    }
  }
  int i0 = r.fi + r.si * p, o0 = r.fo + r.so * (p + r.t);
  for (; p < end; ++p, d += 6, i0 += r.si, o0 += r.so) quad<K, Ccw>(d, i0, i0 + r.si, o0, o0 + r.so);
  return d;
}

template <bool Ccw>
void regular(MeshWriter& w, bool trapezoid, Diagonals diagonals, int numIn, const Row& in, const Row& out) {
  const int t = trapezoid ? 1 : 0;
  const int quads = numIn - 1 > 0 ? numIn - 1 : 0;
  const Affine r{in.first, in.step, out.first, out.step, t};
  int32_t* const start = w.indices + w.numIndices;
  int32_t* d = start;
  if (trapezoid) tri<Ccw>(d, r.fo, r.fo + r.so, r.fi), d += 3;
  const int before = numIn / 2 - 1; // InsideToOutsideExceptMiddle: quads before the middle one
  const int half = numIn / 2 < quads ? numIn / 2 : quads; // Mirrored: quads with the outside diagonal
  switch (diagonals) {
  case Diagonals::InsideToOutside: d = quadRun<FromInside, Ccw>(d, r, 0, quads); break;
  case Diagonals::InsideToOutsideExceptMiddle: // (odd strips only) the middle quad takes the other diagonal
    d = quadRun<OutsideForward, Ccw>(d, r, 0, before);
    d = quadRun<FromOutside, Ccw>(d, r, before, before + 1);
    d = quadRun<OutsideForward, Ccw>(d, r, before + 1, quads);
    break;
  case Diagonals::Mirrored:
    d = quadRun<FromOutside, Ccw>(d, r, 0, half);
    d = quadRun<FromInside, Ccw>(d, r, half, quads);
    break;
  }
  if (trapezoid) tri<Ccw>(d, r.fo + r.so * (quads + 1), r.fo + r.so * (quads + 2), r.fi + r.si * quads), d += 3;
  w.numIndices = int(d - w.indices);
  if (in.redirectFrom < 0 && out.redirectFrom < 0) return;
  // Redirects only ever move a row's first or last position: rewrite the opening triangle and first quad, the last
  // quad and the closing triangle through Row::at.
  auto rewriteQuad = [&](int p) {
    if (p < 0 || p >= quads) return;
    int32_t* q = start + 3 * t + 6 * p;
    const int i0 = in.at(p), i1 = in.at(p + 1), o0 = out.at(p + t), o1 = out.at(p + t + 1);
    const bool fromOutside = diagonals == Diagonals::Mirrored ? p < half
                                                              : diagonals == Diagonals::InsideToOutsideExceptMiddle &&
                                                                    p == before;
    if (fromOutside)
      quad<FromOutside, Ccw>(q, i0, i1, o0, o1);
    else if (diagonals == Diagonals::InsideToOutsideExceptMiddle)
      quad<OutsideForward, Ccw>(q, i0, i1, o0, o1);
    else
      quad<FromInside, Ccw>(q, i0, i1, o0, o1);
  };
  if (trapezoid) tri<Ccw>(start, out.at(0), out.at(1), in.at(0));
  rewriteQuad(0);
  rewriteQuad(quads - 1);
  if (trapezoid) tri<Ccw>(d - 3, out.at(quads + 1), out.at(quads + 2), in.at(quads));
}

// Transition templates: the triangles of one transition as corner codes (inside position k: k, outside position k:
// kRowCodes + k), in output order (the winding is part of the key). They depend only on the two half counts and
// parities, so each thread keeps the recent ones (direct-mapped). Rows are affine (first + step * position) except
// that a ring's last edge redirects the last position of its rows, so a transition is computed from the codes with
// no lookups (8 at a time with AVX2) and the few corners on a last position are patched afterwards.
constexpr int kRowCodes = kMaxRow;
constexpr int kMaxTransitionTriangles = 2 * 64 + 2;
constexpr int kMaxLastCorners = 16;
struct TransitionTemplate {
  uint32_t key = 0; // 0: empty
  int indices = 0;
  int insidePositions = 0, outsidePositions = 0; // positions used on each row
  int lastInside[kMaxLastCorners], lastOutside[kMaxLastCorners]; // corners on each row's last position
  int numLastInside = 0, numLastOutside = 0; // -1: more than kMaxLastCorners (redirects take Row::at)
  uint8_t corner[3 * kMaxTransitionTriangles + 8];
};
constexpr int kTransitionSlots = 256;

const TransitionTemplate& transitionTemplate(int nIn, bool insideOdd, int nOut, bool outsideOdd, bool ccw) {
  thread_local TransitionTemplate cache[kTransitionSlots];
  const uint32_t key = 1u | uint32_t(nIn) << 1 | uint32_t(nOut) << 7 | uint32_t(insideOdd) << 13 |
                       uint32_t(outsideOdd) << 14 | uint32_t(ccw) << 15;
  TransitionTemplate& slot = cache[(key * 0x9e3779b1u) >> 24];
  if (slot.key == key) return slot;
  int32_t codes[3 * kMaxTransitionTriangles];
  MeshWriter w;
  w.indices = codes;
  if (ccw)
    transition<true>(w, Row{0, 1}, nIn, insideOdd, Row{kRowCodes, 1}, nOut, outsideOdd);
  else
    transition<false>(w, Row{0, 1}, nIn, insideOdd, Row{kRowCodes, 1}, nOut, outsideOdd);
  slot.insidePositions = slot.outsidePositions = 0;
  for (int k = 0; k < w.numIndices; ++k) {
    slot.corner[k] = uint8_t(codes[k]);
    int& used = codes[k] < kRowCodes ? slot.insidePositions : slot.outsidePositions;
    const int position = codes[k] < kRowCodes ? codes[k] : codes[k] - kRowCodes;
    if (position + 1 > used) used = position + 1;
  }
  slot.numLastInside = slot.numLastOutside = 0;
  auto note = [](int* list, int& count, int k) {
    if (count >= 0 && count < kMaxLastCorners)
      list[count++] = k;
    else
      count = -1;
  };
  for (int k = 0; k < w.numIndices; ++k) {
    if (codes[k] == slot.insidePositions - 1) note(slot.lastInside, slot.numLastInside, k);
    if (codes[k] == kRowCodes + slot.outsidePositions - 1) note(slot.lastOutside, slot.numLastOutside, k);
  }
  slot.indices = w.numIndices;
  slot.key = key;
  return slot;
}

// Corner codes -> point indices for affine rows: d[k] = code < kRowCodes ? inFirst + inStep * code
//                                                                      : outFirst + outStep * (code - kRowCodes).
void affineCorners(int32_t* d, const uint8_t* c, int count, int inFirst, int inStep, int outFirst, int outStep) {
  const int outBase = outFirst - outStep * kRowCodes;
  for (int k = 0; k < count; ++k) {
    const int code = c[k];
    d[k] = code < kRowCodes ? inFirst + inStep * code : outBase + outStep * code;
  }
}

#if defined(__x86_64__)
// Rows step by +-1 (a degenerate inside row runs backwards): step * x = (x ^ sign) - sign.
__attribute__((target("avx2"))) void affineCornersAvx2(int32_t* d, const uint8_t* c, int count, int inFirst, int inStep,
                                                       int outFirst, int outStep) {
  const int outBase = outFirst - outStep * kRowCodes;
  int k = 0;
  if ((inStep == 1 || inStep == -1) && (outStep == 1 || outStep == -1)) {
    const __m256i limit = _mm256_set1_epi32(kRowCodes - 1);
    const __m256i inSign = _mm256_set1_epi32(inStep < 0 ? -1 : 0), outSign = _mm256_set1_epi32(outStep < 0 ? -1 : 0);
    const __m256i inBase = _mm256_set1_epi32(inFirst), outBase8 = _mm256_set1_epi32(outBase);
    for (; k + 8 <= count; k += 8) {
      const __m256i code = _mm256_cvtepu8_epi32(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(c + k)));
      const __m256i onOutside = _mm256_cmpgt_epi32(code, limit);
      const __m256i inValue = _mm256_add_epi32(inBase, _mm256_sub_epi32(_mm256_xor_si256(code, inSign), inSign));
      const __m256i outValue = _mm256_add_epi32(outBase8, _mm256_sub_epi32(_mm256_xor_si256(code, outSign), outSign));
      _mm256_storeu_si256(reinterpret_cast<__m256i*>(d + k), _mm256_blendv_epi8(inValue, outValue, onOutside));
    }
  }
  for (; k < count; ++k) {
    const int code = c[k];
    d[k] = code < kRowCodes ? inFirst + inStep * code : outBase + outStep * code;
  }
}
#endif

void emitTransition(MeshWriter& w, const TransitionTemplate& t, const Row& in, const Row& out) {
  int32_t* d = w.indices + w.numIndices;
#if defined(__x86_64__)
  if (simd::useAvx2())
    affineCornersAvx2(d, t.corner, t.indices, in.first, in.step, out.first, out.step);
  else
#endif
    affineCorners(d, t.corner, t.indices, in.first, in.step, out.first, out.step);
  // Redirects (only ever of a row's last position; anything else takes the lookups of at()).
  if (in.redirectFrom >= 0) {
    if (in.redirectFrom == t.insidePositions - 1 && t.numLastInside >= 0) {
      for (int k = 0; k < t.numLastInside; ++k) d[t.lastInside[k]] = in.redirectTo;
    } else {
      for (int k = 0; k < t.indices; ++k)
        if (t.corner[k] < kRowCodes) d[k] = in.at(t.corner[k]);
    }
  }
  if (out.redirectFrom >= 0) {
    if (out.redirectFrom == t.outsidePositions - 1 && t.numLastOutside >= 0) {
      for (int k = 0; k < t.numLastOutside; ++k) d[t.lastOutside[k]] = out.redirectTo;
    } else {
      for (int k = 0; k < t.indices; ++k)
        if (t.corner[k] >= kRowCodes) d[k] = out.at(t.corner[k] - kRowCodes);
    }
  }
  w.numIndices += t.indices;
}

} // namespace

void stitchTransition(MeshWriter& out, const Row& inside, int insideNumHalf, bool insideOdd, const Row& outside,
                      int outsideNumHalf, bool outsideOdd) {
  // Odd factors have a middle segment, not a middle point: count the half without it.
  const int nIn = insideOdd ? insideNumHalf - 1 : insideNumHalf;
  const int nOut = outsideOdd ? outsideNumHalf - 1 : outsideNumHalf;
  emitTransition(out, transitionTemplate(nIn, insideOdd, nOut, outsideOdd, out.ccw), inside, outside);
}

void stitchRegular(MeshWriter& out, bool trapezoid, Diagonals diagonals, int numInsidePoints, const Row& inside,
                   const Row& outside) {
  if (out.ccw)
    regular<true>(out, trapezoid, diagonals, numInsidePoints, inside, outside);
  else
    regular<false>(out, trapezoid, diagonals, numInsidePoints, inside, outside);
}

} // namespace fftess
