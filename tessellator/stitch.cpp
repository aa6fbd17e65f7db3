#include "stitch.h"

#include <cstring>

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

// kBelow[n]: bit k (0..32) set when the k-th inserted point of the ruler order lands below n, i.e. is one of the
// first n points of a half row. A half row's moves are the set bits in order (first half) or reverse order (second).
struct RulerMasks {
  uint64_t below[34];
  constexpr RulerMasks() : below{} {
    for (int n = 0; n <= 33; ++n)
      for (int k = 0; k <= 32; ++k)
        if (kRuler.position[k] < n) below[n] |= uint64_t(1) << k;
  }
};
constexpr RulerMasks kMasks{};

struct Cursor {
  MeshWriter& out;
  const Row& in;
  const Row& outRow;
  int i = 0, o = 0; // positions on the inside and outside rows

  void advanceOutside() { // triangle with its base on the outside row
    out.triangle(outRow.at(o), outRow.at(o + 1), in.at(i));
    ++o;
  }
  void advanceInside() { // triangle with its base on the inside row
    out.triangle(in.at(i), outRow.at(o), in.at(i + 1));
    ++i;
  }
};

// One corner of a quad between the rows: on the outside row (else inside) at offset d from the quad's position.
struct Corner {
  bool outside;
  int d;
};
using QuadShape = Corner[6]; // two triangles, clockwise

// Quad p (0-based within the row pair) has its inside corner at position p and its outside corner at p + shift
// (shift 1 after a trapezoid's first triangle).
constexpr QuadShape kFromOutside = {{true, 0}, {false, 1}, {false, 0}, {true, 0}, {true, 1}, {false, 1}};
constexpr QuadShape kFromInside = {{false, 0}, {true, 0}, {true, 1}, {false, 0}, {true, 1}, {false, 1}};
constexpr QuadShape kOutsideForward = {{true, 0}, {true, 1}, {false, 0}, {false, 0}, {true, 1}, {false, 1}};

using v8i = int32_t __attribute__((vector_size(32)));

// Writes quads [begin, end) of one shape. Quads whose corners may be redirected (the row's first and last) go
// through Row::at; the others are affine in p (index = a + b * p) and are written 4 quads (24 indices) per step.
void quadRun(MeshWriter& out, const Row& in, const Row& outRow, int shift, const QuadShape& shape, int begin, int end,
             int quads) {
  int p = begin;
  auto scalarQuad = [&](int q) {
    int v[6];
    for (int j = 0; j < 6; ++j)
      v[j] = shape[j].outside ? outRow.at(q + shift + shape[j].d) : in.at(q + shape[j].d);
    out.triangle(v[0], v[1], v[2]);
    out.triangle(v[3], v[4], v[5]);
  };
  if (p < end && p == 0) scalarQuad(p++);
  const int affineEnd = end < quads - 1 ? end : quads - 1;
  if (p < affineEnd) {
    int32_t a[6], b[6];
    for (int j = 0; j < 6; ++j) {
      const int jj = out.ccw && (j % 3) ? (j % 3 == 1 ? j + 1 : j - 1) : j; // ccw: 2nd and 3rd swapped
      const Corner c = shape[jj];
      a[j] = c.outside ? outRow.first + (shift + c.d) * outRow.step : in.first + c.d * in.step;
      b[j] = c.outside ? outRow.step : in.step;
    }
    int32_t* dst = out.indices + out.numIndices;
    const int count = affineEnd - p;
    int q = 0;
    if (count >= 4) {
      int32_t base[24], step[24];
      for (int t = 0; t < 24; ++t) {
        base[t] = a[t % 6] + b[t % 6] * (p + t / 6);
        step[t] = 4 * b[t % 6];
      }
      v8i v0, v1, v2, d0, d1, d2;
      std::memcpy(&v0, base, 32), std::memcpy(&v1, base + 8, 32), std::memcpy(&v2, base + 16, 32);
      std::memcpy(&d0, step, 32), std::memcpy(&d1, step + 8, 32), std::memcpy(&d2, step + 16, 32);
      for (; q + 4 <= count; q += 4, dst += 24) {
        std::memcpy(dst, &v0, 32), std::memcpy(dst + 8, &v1, 32), std::memcpy(dst + 16, &v2, 32);
        v0 += d0, v1 += d1, v2 += d2;
      }
    }
    for (; q < count; ++q, dst += 6)
      for (int j = 0; j < 6; ++j) dst[j] = a[j] + b[j] * (p + q);
    out.numIndices += 6 * count;
    p = affineEnd;
  }
  for (; p < end; ++p) scalarQuad(p);
}

} // namespace

void stitchTransition(MeshWriter& out, const Row& inside, int insideNumHalf, bool insideOdd, const Row& outside,
                      int outsideNumHalf, bool outsideOdd) {
  // Odd factors have a middle segment, not a middle point: count the half without it.
  const int nIn = insideOdd ? insideNumHalf - 1 : insideNumHalf;
  const int nOut = outsideOdd ? outsideNumHalf - 1 : outsideNumHalf;
  const uint64_t bIn = kMasks.below[nIn], bOut = kMasks.below[nOut];
  Cursor c{out, inside, outside};

  // First half, outwards from the start (ruler order 0, 1, ..., 32): inside before outside at each step.
  if (bOut & 1) c.advanceOutside();
  for (uint64_t m = (bIn | bOut) & ~uint64_t(1); m; m &= m - 1) {
    const int k = __builtin_ctzll(m);
    if ((bIn >> k) & 1) c.advanceInside();
    if ((bOut >> k) & 1) c.advanceOutside();
  }
  // Middle.
  if (insideOdd != outsideOdd || insideOdd) {
    if (insideOdd == outsideOdd) { // both odd: a quad
      out.triangle(inside.at(c.i), outside.at(c.o), inside.at(c.i + 1));
      out.triangle(inside.at(c.i + 1), outside.at(c.o), outside.at(c.o + 1));
      ++c.i;
      ++c.o;
    } else if (!insideOdd) { // the outside has the middle segment
      out.triangle(inside.at(c.i), outside.at(c.o), outside.at(c.o + 1));
      ++c.o;
    } else { // the inside has it
      out.triangle(inside.at(c.i), outside.at(c.o), inside.at(c.i + 1));
      ++c.i;
    }
  }
  // Second half, mirrored (ruler order 32 down to 1, then 0): outside before inside at each step.
  for (uint64_t m = (bIn | bOut) & ~uint64_t(1); m;) {
    const int k = 63 - __builtin_clzll(m);
    m &= ~(uint64_t(1) << k);
    if ((bOut >> k) & 1) c.advanceOutside();
    if ((bIn >> k) & 1) c.advanceInside();
  }
  if (bOut & 1) c.advanceOutside();
}

void stitchRegular(MeshWriter& out, bool trapezoid, Diagonals diagonals, int numInsidePoints, const Row& inside,
                   const Row& outside) {
  const int shift = trapezoid ? 1 : 0;
  const int quads = numInsidePoints - 1;
  if (trapezoid) out.triangle(outside.at(0), outside.at(1), inside.at(0));
  switch (diagonals) {
  case Diagonals::InsideToOutside:
    quadRun(out, inside, outside, shift, kFromInside, 0, quads, quads);
    break;
  case Diagonals::InsideToOutsideExceptMiddle: {
    // (odd strips only) the middle quad takes the other diagonal.
    const int before = numInsidePoints / 2 - 1;
    quadRun(out, inside, outside, shift, kOutsideForward, 0, before, quads);
    quadRun(out, inside, outside, shift, kFromOutside, before, before + 1, quads);
    quadRun(out, inside, outside, shift, kOutsideForward, before + 1, quads, quads);
    break;
  }
  case Diagonals::Mirrored: {
    const int half = numInsidePoints / 2 < quads ? numInsidePoints / 2 : (quads > 0 ? quads : 0);
    quadRun(out, inside, outside, shift, kFromOutside, 0, half, quads);
    quadRun(out, inside, outside, shift, kFromInside, half, quads, quads);
    break;
  }
  }
  const int i = quads > 0 ? quads : 0;
  if (trapezoid) out.triangle(outside.at(i + 1), outside.at(i + 2), inside.at(i));
}

} // namespace fftess
