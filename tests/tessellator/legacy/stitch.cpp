#include "stitch.h"

namespace fftess::legacy {
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

} // namespace

void stitchTransition(MeshWriter& out, const Row& inside, int insideNumHalf, bool insideOdd, const Row& outside,
                      int outsideNumHalf, bool outsideOdd) {
  // Odd factors have a middle segment, not a middle point: count the half without it.
  const int nIn = insideOdd ? insideNumHalf - 1 : insideNumHalf;
  const int nOut = outsideOdd ? outsideNumHalf - 1 : outsideNumHalf;
  Cursor c{out, inside, outside};

  // First half, outwards from the start: inside before outside at each step.
  if (kRuler.position[0] < nOut) c.advanceOutside();
  for (int k = 1; k <= 32; ++k) {
    if (kRuler.position[k] < nIn) c.advanceInside();
    if (kRuler.position[k] < nOut) c.advanceOutside();
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
  // Second half, mirrored: outside before inside at each step.
  for (int k = 32; k >= 1; --k) {
    if (kRuler.position[k] < nOut) c.advanceOutside();
    if (kRuler.position[k] < nIn) c.advanceInside();
  }
  if (kRuler.position[0] < nOut) c.advanceOutside();
}

void stitchRegular(MeshWriter& out, bool trapezoid, Diagonals diagonals, int numInsidePoints, const Row& inside,
                   const Row& outside) {
  Cursor c{out, inside, outside};
  auto diagonalFromInside = [&] { // quad split by the diagonal inside(i) - outside(o+1)
    out.triangle(inside.at(c.i), outside.at(c.o), outside.at(c.o + 1));
    out.triangle(inside.at(c.i), outside.at(c.o + 1), inside.at(c.i + 1));
    ++c.i;
    ++c.o;
  };
  auto diagonalFromOutside = [&] { // quad split by the diagonal outside(o) - inside(i+1)
    out.triangle(outside.at(c.o), inside.at(c.i + 1), inside.at(c.i));
    out.triangle(outside.at(c.o), outside.at(c.o + 1), inside.at(c.i + 1));
    ++c.i;
    ++c.o;
  };
  auto diagonalOutsideForward = [&] { // quad split by the diagonal inside(i) - outside(o+1), outside triangle first
    out.triangle(outside.at(c.o), outside.at(c.o + 1), inside.at(c.i));
    out.triangle(inside.at(c.i), outside.at(c.o + 1), inside.at(c.i + 1));
    ++c.i;
    ++c.o;
  };

  if (trapezoid) c.advanceOutside();
  const int quads = numInsidePoints - 1;
  switch (diagonals) {
  case Diagonals::InsideToOutside:
    for (int p = 0; p < quads; ++p) diagonalFromInside();
    break;
  case Diagonals::InsideToOutsideExceptMiddle: {
    // (odd strips only) the middle quad takes the other diagonal.
    const int before = numInsidePoints / 2 - 1;
    int p = 0;
    for (; p < before; ++p) diagonalOutsideForward();
    diagonalFromOutside();
    for (p += 2; p < numInsidePoints; ++p) diagonalOutsideForward();
    break;
  }
  case Diagonals::Mirrored: {
    int p = 0;
    for (; p < numInsidePoints / 2; ++p) diagonalFromOutside();
    for (; p < quads; ++p) diagonalFromInside();
    break;
  }
  }
  if (trapezoid) c.advanceOutside();
}

} // namespace fftess
