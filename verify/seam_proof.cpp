// The seam proof (seam_proof.h; docs/verify.md, "Sweep shortcuts", "Seam proof"): value numbering of domain.cpp's
// float operations along one edge, on both of its sides.
//
// A value is a node of a small graph: a float constant (keyed by its bits), the edge parameter t (the only symbol,
// any float in [0, 1], -0 included), or an operation (add, sub, mul, fma) on earlier nodes. An operation on constants
// only is evaluated here in float, the same operation in the same order as domain.cpp (std::fma for fma; the
// project builds with -ffp-contract=off). Equal (operation, operands) are one node; add and mul (and fma's two
// factors) take their operands in a canonical order (IEEE addition and multiplication are commutative, bit for bit,
// for every operand that is not a NaN, and a NaN is never proven: see below). Simplifications, each exact for every
// value of its operands that the node's facts allow:
//   x - x = +0               x finite (inf - inf is NaN)
//   x * 1 = x                every x
//   x * (+-0) = a zero       x finite; its sign is sign(x) xor sign(0), so +0 or -0 where sign(x) is known,
//                            otherwise a "zero node" of unknown sign
//   z + x = x, x + z = x     z a zero, unless x may be -0 while z may be +0 (-0 + +0 = +0)
//   x - z = x                z a zero, unless x may be -0 while z may be -0 (-0 - -0 = +0)
//   fma(1, x, c) = c + x     the product is exact, so the one rounding is the sum's
//   fma(z, x, c) = z*x + c   z a zero, x finite: the product is an exact zero of sign sign(z) xor sign(x)
// Facts per node, conservative for every t: an interval [lo, hi] holding every value (double, widened by 2^-20
// relative and 2^-140 absolute for float rounding, underflow included), "finite" (every operand finite and the
// interval inside +-2^127: no overflow, hence no NaN either), and whether the value may be -0 or +0.
//
// Two sides are Identical when their x and z nodes (and, for domain.height_uv = "interpolated", the texture
// coordinates' nodes) are the same node and finite: the same function of t, never NaN, so sameBits holds for x and
// z (or both nodes are zeros of either sign: see sameCoordinate); y is then the same function of the same values (the height samples the same coordinates; the texels are finite,
// 0..1, as the loaders produce them), and it is not NaN because the texture coordinate stays far inside float range
// (|tx| < 2^100, checked from the interval) and height_scale is finite.
#include "verify/seam_proof.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

namespace fftess::verify::detail {

namespace {

enum class Op : uint8_t { Const, Sym, Add, Sub, Mul, Fma };

struct Node {
  Op op = Op::Const;
  int8_t a = -1, b = -1, c = -1; // operands
  uint32_t bits = 0;             // Const: the value's bits
  float k = 0;                   // Const: the value
  double lo = 0, hi = 0;         // every value lies in [lo, hi] (meaningless unless finite)
  bool finite = false;           // never inf, never NaN
  bool negZero = true, posZero = true; // may be -0, may be +0
};

constexpr int kMaxNodes = 64; // one coordinate of both sides needs at most ~30
constexpr double kHuge = FLT_MAX; // a float result whose bound stays within it is finite

uint32_t bitsOf(float f) {
  uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// Float rounding (round to nearest) keeps the sign of the exact value or gives a zero: a bound of 0 stays 0.
double widenLo(double v) { return v >= 0 ? std::max(0.0, v - v * 0x1p-20 - 0x1p-140) : v * (1 + 0x1p-20) - 0x1p-140; }
double widenHi(double v) { return v <= 0 ? std::min(0.0, v - v * 0x1p-20 + 0x1p-140) : v * (1 + 0x1p-20) + 0x1p-140; }

// The graph of one coordinate (x, z, tx or tz) on both sides of an edge. -1: no node (the graph is full).
class Graph {
public:
  int konst(float v) {
    const uint32_t bits = bitsOf(v);
    for (int i = 0; i < n_; ++i)
      if (nodes_[i].op == Op::Const && nodes_[i].bits == bits) return i;
    Node x;
    x.op = Op::Const;
    x.bits = bits;
    x.k = v;
    x.finite = std::isfinite(v);
    x.lo = x.hi = x.finite ? v : 0.0;
    x.negZero = v == 0.0f && std::signbit(v);
    x.posZero = v == 0.0f && !std::signbit(v);
    return push(x);
  }
  int symbol() { // t: any float in [0, 1], -0 included
    Node x;
    x.op = Op::Sym;
    x.lo = 0;
    x.hi = 1;
    x.finite = true;
    return push(x);
  }
  const Node& at(int i) const { return nodes_[i]; }
  // Every value of the node is +0 or -0.
  bool isZero(int i) const { return nodes_[i].finite && nodes_[i].lo == 0.0 && nodes_[i].hi == 0.0; }
  // A further bound on node i's values: [lo, hi] holds every value it takes.
  void tighten(int i, double lo, double hi) {
    Node& r = nodes_[i];
    if (r.op == Op::Const || !r.finite) return;
    r.lo = std::max(r.lo, lo);
    r.hi = std::min(r.hi, hi);
    if (r.lo > 0 || r.hi < 0) r.negZero = r.posZero = false;
  }

  int add(int x, int y) {
    if (x < 0 || y < 0) return -1;
    if (isConst(x) && isConst(y)) return konst(k(x) + k(y));
    if (isZero(y) && (!at(x).negZero || !at(y).posZero)) return x;
    if (isZero(x) && (!at(y).negZero || !at(x).posZero)) return y;
    if (y < x) std::swap(x, y);
    return intern(Op::Add, x, y, -1);
  }
  int sub(int x, int y) {
    if (x < 0 || y < 0) return -1;
    if (isConst(x) && isConst(y)) return konst(k(x) - k(y));
    if (x == y && at(x).finite) return konst(0.0f);
    if (isZero(y) && (!at(x).negZero || !at(y).negZero)) return x;
    if (isZero(x) && isConst(y) && at(y).finite && k(y) != 0.0f) return konst(-k(y)); // +-0 - c = -c exactly
    return intern(Op::Sub, x, y, -1);
  }
  int mul(int x, int y) {
    if (x < 0 || y < 0) return -1;
    if (isConst(x) && isConst(y)) return konst(k(x) * k(y));
    if (isConst(x) && k(x) == 1.0f) return y;
    if (isConst(y) && k(y) == 1.0f) return x;
    if (isZero(x) && at(y).finite) return zeroProduct(x, y);
    if (isZero(y) && at(x).finite) return zeroProduct(y, x);
    if (y < x) std::swap(x, y);
    return intern(Op::Mul, x, y, -1);
  }
  int fma(int x, int y, int z) { // x * y + z, rounded once
    if (x < 0 || y < 0 || z < 0) return -1;
    if (isConst(x) && isConst(y) && isConst(z)) return konst(std::fma(k(x), k(y), k(z)));
    if (isConst(x) && k(x) == 1.0f) return add(z, y);
    if (isConst(y) && k(y) == 1.0f) return add(z, x);
    if ((isZero(x) && at(y).finite) || (isZero(y) && at(x).finite)) return add(mul(x, y), z);
    if (y < x) std::swap(x, y);
    return intern(Op::Fma, x, y, z);
  }

private:
  bool isConst(int i) const { return nodes_[i].op == Op::Const; }
  float k(int i) const { return nodes_[i].k; }
  static bool mayBeNegative(const Node& x) { return !x.finite || x.lo < 0 || x.negZero; } // sign bit may be set
  static bool mayBePositive(const Node& x) { return !x.finite || x.hi > 0 || x.posZero; } // sign bit may be clear

  // z * x for a zero z and a finite x: an exact zero whose sign is sign(z) xor sign(x).
  int zeroProduct(int z, int x) {
    const Node& zn = at(z);
    const Node& xn = at(x);
    const bool neg = (zn.posZero && mayBeNegative(xn)) || (zn.negZero && mayBePositive(xn));
    const bool pos = (zn.posZero && mayBePositive(xn)) || (zn.negZero && mayBeNegative(xn));
    if (!neg) return konst(0.0f);
    if (!pos) return konst(-0.0f);
    const int i = intern(Op::Mul, std::min(z, x), std::max(z, x), -1);
    if (i >= 0) {
      Node& r = nodes_[i];
      r.lo = r.hi = 0;
      r.finite = true;
      r.negZero = r.posZero = true;
    }
    return i;
  }

  int intern(Op op, int x, int y, int z) {
    for (int i = 0; i < n_; ++i)
      if (nodes_[i].op == op && nodes_[i].a == x && nodes_[i].b == y && nodes_[i].c == z) return i;
    Node r;
    r.op = op;
    r.a = static_cast<int8_t>(x);
    r.b = static_cast<int8_t>(y);
    r.c = static_cast<int8_t>(z);
    facts(r);
    return push(r);
  }

  // The interval, finiteness and signed zeros of a new operation node (its operands are finite or it is not).
  void facts(Node& r) const {
    const Node& x = nodes_[r.a];
    const Node& y = nodes_[r.b];
    const Node* z = r.c >= 0 ? &nodes_[r.c] : nullptr;
    r.finite = x.finite && y.finite && (!z || z->finite);
    if (!r.finite) {
      r.lo = -HUGE_VAL;
      r.hi = HUGE_VAL;
      return;
    }
    double lo = 0, hi = 0;
    if (r.op == Op::Add) {
      lo = x.lo + y.lo;
      hi = x.hi + y.hi;
    } else if (r.op == Op::Sub) {
      lo = x.lo - y.hi;
      hi = x.hi - y.lo;
    } else {
      const double p[4] = {x.lo * y.lo, x.lo * y.hi, x.hi * y.lo, x.hi * y.hi};
      lo = *std::min_element(p, p + 4);
      hi = *std::max_element(p, p + 4);
      if (z) {
        lo += z->lo;
        hi += z->hi;
      }
    }
    r.lo = widenLo(lo);
    r.hi = widenHi(hi);
    r.finite = r.lo > -kHuge && r.hi < kHuge;
    const bool zero = r.lo <= 0 && r.hi >= 0;
    r.posZero = zero;
    if (r.op == Op::Add) r.negZero = zero && x.negZero && y.negZero;        // -0 only as -0 + -0
    else if (r.op == Op::Sub) r.negZero = zero && x.negZero && y.posZero;   // -0 only as -0 - +0
    else if (r.op == Op::Mul) {
      const bool sameSign = (!mayBeNegative(x) && !mayBeNegative(y)) || (!mayBePositive(x) && !mayBePositive(y));
      const bool oppositeSign = (!mayBeNegative(x) && !mayBePositive(y)) || (!mayBePositive(x) && !mayBeNegative(y));
      r.negZero = zero && !sameSign;
      r.posZero = zero && !oppositeSign;
    } else {
      r.negZero = zero; // fma: an exact tiny negative sum rounds to -0
    }
  }

  int push(const Node& x) {
    if (n_ == kMaxNodes) return -1;
    nodes_[n_] = x;
    return n_++;
  }

  Node nodes_[kMaxNodes];
  int n_ = 0;
};

// domain.cpp's lerpWith as nodes.
int lerpOps(Graph& g, LerpFormula f, int a, int b, int t) {
  switch (f) {
  case LerpFormula::Nvidia:
  case LerpFormula::Lerp: return g.add(a, g.mul(t, g.sub(b, a)));
  case LerpFormula::LerpFma: return g.fma(t, g.sub(b, a), a);
  case LerpFormula::Blend: return g.add(g.mul(a, g.sub(g.konst(1.0f), t)), g.mul(b, t));
  case LerpFormula::BlendFma: return g.fma(b, t, g.mul(a, g.sub(g.konst(1.0f), t)));
  }
  return -1;
}

// The same, and the bound every formula keeps for a weight t in [0, 1]: the exact lerp lies between a and b, and the
// formula's (at most four) roundings move it by less than 2^-20 of the larger magnitude (plus 2^-140 for underflow).
// The interval arithmetic of the single operations alone loses that a*(1 - t) + a*t stays near a.
int lerpNode(Graph& g, LerpFormula f, int a, int b, int t) {
  const int r = lerpOps(g, f, a, b, t);
  if (r < 0 || !g.at(a).finite || !g.at(b).finite) return r;
  const double lo = std::min(g.at(a).lo, g.at(b).lo), hi = std::max(g.at(a).hi, g.at(b).hi);
  const double slack = std::max(std::fabs(lo), std::fabs(hi)) * 0x1p-20 + 0x1p-140;
  g.tighten(r, lo >= 0 ? std::max(0.0, lo - slack) : lo - slack, hi <= 0 ? std::min(0.0, hi + slack) : hi + slack);
  return r;
}

// domain.cpp's bilerp of c[0..3] at (u, v) (nodes).
int bilerpNode(Graph& g, const DomainShader& ds, const float (&c)[4], int u, int v) {
  int n[4];
  for (int i = 0; i < 4; ++i) n[i] = g.konst(c[i]);
  if (ds.order == LerpOrder::UFirst) {
    const int bottom = lerpNode(g, ds.formula, n[0], n[1], u);
    const int top = lerpNode(g, ds.formula, n[2], n[3], u);
    return lerpNode(g, ds.formula, bottom, top, v);
  }
  const int left = lerpNode(g, ds.formula, n[0], n[2], v);
  const int right = lerpNode(g, ds.formula, n[1], n[3], v);
  return lerpNode(g, ds.formula, left, right, u);
}

// One coordinate (0: x, 1: z, 2: tx, 3: tz) of a patch's corners.
void cornerValues(const TerrainPatch& p, int coordinate, float (&c)[4]) {
  for (int i = 0; i < 4; ++i)
    c[i] = coordinate == 0 ? p.corners[i].x : coordinate == 1 ? p.corners[i].z : p.tex[i][coordinate - 2];
}

// The coordinate on edge e of a at t is the same node as on kOpposite[e] of b, or both are zeros (+0 or -0: equal
// under sameBits' ==, and the height cannot tell them apart either: the texture coordinate (x - minX) * invSizeX is
// then -minX * invSizeX or a zero, and the sampler's tx * width - 0.5 turns a zero of either sign into -0.5), and
// finite; bound: the largest magnitude it takes.
bool sameCoordinate(const DomainShader& ds, const TerrainPatch& a, int e, const TerrainPatch& b, int coordinate,
                    double& bound) {
  Graph g;
  const int t = g.symbol();
  int side[2];
  for (int s = 0; s < 2; ++s) {
    const int edge = s == 0 ? e : kOpposite[e];
    const int fixed = g.konst(edge == Ueq0 || edge == Veq0 ? 0.0f : 1.0f);
    const bool alongU = edge == Veq0 || edge == Veq1; // u = t
    float c[4];
    cornerValues(s == 0 ? a : b, coordinate, c);
    side[s] = bilerpNode(g, ds, c, alongU ? t : fixed, alongU ? fixed : t);
  }
  if (side[0] < 0 || side[1] < 0 || !g.at(side[0]).finite || !g.at(side[1]).finite) return false;
  if (side[0] != side[1] && !(g.isZero(side[0]) && g.isZero(side[1]))) return false;
  bound = std::max(std::fabs(g.at(side[0]).lo), std::fabs(g.at(side[0]).hi));
  return true;
}

} // namespace

SeamProof proveSeam(const TerrainData& t, const TerrainPatch& a, int e, const TerrainPatch& b) {
  if (e < 0 || e > 3 || a.size != b.size) return SeamProof::NotProven;
  const Scene& s = t.scene;
  const Displacement& d = s.displacement;
  const bool displaced = d.kind != DisplacementKind::None;
  // domainCamera's condition: the domain shader reads camera state.
  if (displaced && (s.lod.scheme == LodScheme::Geomorph || d.mip != MipMode::None)) return SeamProof::NotProven;
  if (displaced && (!d.texels || !std::isfinite(d.heightScale))) return SeamProof::NotProven;
  constexpr double kTexMax = 0x1p100; // |tx| below it: tx * width - 0.5 and its floor stay finite
  double bound[4] = {0, 0, 0, 0};
  for (int c = 0; c < 2; ++c)
    if (!sameCoordinate(s.domain, a, e, b, c, bound[c])) return SeamProof::NotProven;
  if (!displaced) return SeamProof::Identical;
  if (s.domain.heightUv == HeightUv::Interpolated) {
    for (int c = 2; c < 4; ++c)
      if (!sameCoordinate(s.domain, a, e, b, c, bound[c]) || !(bound[c] < kTexMax)) return SeamProof::NotProven;
    return SeamProof::Identical;
  }
  // "world": tx = (x - minX) * invSizeX, tz likewise (one rounding each: 2^-20 covers them).
  const double tx = (bound[0] + std::fabs(static_cast<double>(t.extent.minX))) *
                    std::fabs(static_cast<double>(t.invSizeX)) * (1 + 0x1p-20);
  const double tz = (bound[1] + std::fabs(static_cast<double>(t.extent.minZ))) *
                    std::fabs(static_cast<double>(t.invSizeZ)) * (1 + 0x1p-20);
  if (!(tx < kTexMax) || !(tz < kTexMax)) return SeamProof::NotProven;
  return SeamProof::Identical;
}

} // namespace fftess::verify::detail
