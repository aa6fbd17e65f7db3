// fftess lod: Bound's operations (lod/bound.h): sound sets of floats under FloatModel::Cpp or ::Conformant, each
// result traced in the active BoundContext (lod/bound_context.cpp).
//
// The sets: + - * / sqrt floor ceil abs min max are evaluated in float at the operands' bounds (correctly rounded
// float arithmetic is monotone: the results at the bounds bound every float result, and points stay points);
// exp2 log2 pow acos in double at the bounds, widened by their error in float ulps (ulpD) and rounded outward to
// float (down / up: one std::nextafter step beyond the double). Conformant adds the GLSL 4.50 / Vulkan freedom
// (docs/lod.md, "Bounds: the schemes over sets of floats").
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "lod/bound.h"
#include "lod/bound_internal.h"

namespace fftess::lod {

namespace {

using bound::activeImpl;
using bound::nodeOf;
using Impl = BoundContext::Impl;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMinNormal = 0x1p-126f;

uint32_t bitsOf(float x) {
  uint32_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

Bound makeSet(float lo, float hi, bool nan) {
  Bound r{};
  r.lo = lo;
  r.hi = hi;
  r.nan = nan;
  return r;
}

Bound nanOnly() { return makeSet(kInf, -kInf, true); }

bool hasInf(const Bound& x) { return x.hasValues() && (x.lo == -kInf || x.hi == kInf); }
bool hasZero(const Bound& x) { return x.lo <= 0.0f && x.hi >= 0.0f; }

// The largest float <= d, the smallest float >= d (d not NaN; beyond the float range: +-FLT_MAX or +-Inf).
float down(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = std::nextafter(f, -kInf);
  return f;
}
float up(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) < d) f = std::nextafter(f, kInf);
  return f;
}

// The float ulp at magnitude |v| (v a double, possibly beyond the float range): 2^(e - 23) for |v| in the binade
// [2^e, 2^(e+1)), 2^-149 below 2^-126; Inf for Inf.
double ulpD(double v) {
  const double a = std::fabs(v);
  if (std::isinf(a)) return a;
  if (a < 0x1p-126) return 0x1p-149;
  return std::ldexp(1.0, std::ilogb(a) - 23);
}

// [vlo - k ulps, vhi + k ulps], rounded outward to float.
Bound widened(double vlo, double vhi, double k, bool nan) {
  const double l = vlo - k * ulpD(vlo);
  const double h = vhi + k * ulpD(vhi);
  return makeSet(std::isnan(l) ? -kInf : down(l), std::isnan(h) ? kInf : up(h), nan);
}

// Widens a float set by k ulps of each bound (the GPU's error beyond the correctly rounded result).
Bound widenUlps(const Bound& x, double k) {
  if (!x.hasValues()) return x;
  return widened(x.lo, x.hi, k, x.nan);
}

Bound unite(const Bound& a, const Bound& b) {
  return makeSet(std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.nan || b.nan);
}

// Conformant: a denormal may be read or written as 0 (of either sign).
void flushDenormals(Bound& x) {
  if (x.hasValues() && x.lo < kMinNormal && x.hi > -kMinNormal) {
    x.lo = std::min(x.lo, 0.0f);
    x.hi = std::max(x.hi, 0.0f);
  }
}

bool conformant(const Impl* c) { return c != nullptr && c->evalModel == FloatModel::Conformant; }
uint32_t modelBit(const Impl* c) { return conformant(c) ? bound::kConformantBit : 0u; }

// The result's node: a point is the constant of its bits; otherwise (op, operands), or a fresh node when an operand
// is untraced.
void finish(Impl* c, Bound& r, uint32_t op, uint32_t na, uint32_t nb, bool binary) {
  if (c == nullptr) {
    r.node = 0;
  } else if (r.point()) {
    r.node = c->constant(r.lo);
  } else if (na == 0 || (binary && nb == 0)) {
    r.node = c->fresh();
  } else {
    r.node = c->intern(bound::Node{op, na, nb, 0});
  }
}

// ---- sets (no trace) ---------------------------------------------------------------------------------------------

// Min and max of the non-NaN values among n candidates; NaN candidates set nan.
Bound fromCandidates(const float* v, int n, bool nan) {
  float lo = kInf;
  float hi = -kInf;
  for (int i = 0; i < n; ++i) {
    if (std::isnan(v[i])) {
      nan = true;
      continue;
    }
    lo = std::min(lo, v[i]);
    hi = std::max(hi, v[i]);
  }
  return makeSet(lo, hi, nan);
}

Bound addSet(const Bound& a, const Bound& b) {
  const bool nan = a.nan || b.nan;
  if (!a.hasValues() || !b.hasValues()) return nanOnly();
  if (a.point() && b.point()) {
    const float s = a.lo + b.lo;
    return std::isnan(s) ? nanOnly() : makeSet(s, s, nan);
  }
  const float v[4] = {a.lo + b.lo, a.lo + b.hi, a.hi + b.lo, a.hi + b.hi};
  return fromCandidates(v, 4, nan);
}

Bound negSet(const Bound& a) { return a.hasValues() ? makeSet(-a.hi, -a.lo, a.nan) : nanOnly(); }

Bound mulSet(const Bound& a, const Bound& b) {
  bool nan = a.nan || b.nan;
  if (!a.hasValues() || !b.hasValues()) return nanOnly();
  if (a.point() && b.point()) {
    const float p = a.lo * b.lo;
    return std::isnan(p) ? nanOnly() : makeSet(p, p, nan);
  }
  nan = nan || (hasZero(a) && hasInf(b)) || (hasInf(a) && hasZero(b));
  const float v[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return fromCandidates(v, 4, nan);
}

Bound divSet(const Bound& a, const Bound& b) {
  bool nan = a.nan || b.nan;
  if (!a.hasValues() || !b.hasValues()) return nanOnly();
  if (hasZero(b)) { // x / +-0 = +-Inf, 0 / 0 = NaN
    nan = nan || hasZero(a) || (hasInf(a) && hasInf(b));
    return makeSet(-kInf, kInf, nan);
  }
  if (a.point() && b.point()) {
    const float q = a.lo / b.lo;
    return std::isnan(q) ? nanOnly() : makeSet(q, q, nan);
  }
  nan = nan || (hasInf(a) && hasInf(b));
  const float v[4] = {a.lo / b.lo, a.lo / b.hi, a.hi / b.lo, a.hi / b.hi};
  return fromCandidates(v, 4, nan);
}

Bound sqrtSet(const Bound& x) {
  const bool nan = x.nan || (x.hasValues() && x.lo < 0.0f);
  if (!x.hasValues() || x.hi < 0.0f) return nanOnly();
  const float lo = x.lo < 0.0f ? 0.0f : std::sqrt(x.lo); // sqrt(-0) = -0: both zeros are in [0, ..]
  return makeSet(lo, std::sqrt(x.hi), nan);
}

// An add or subtract whose operand `p` may be contracted with its product into fma(x, y, other): the exact
// product lies within half an ulp of every float in p; the fused sum is computed in double and rounded outward
// (one more nextafter step: the double sum itself may be rounded).
Bound fusedSum(const Bound& p, const Bound& other) {
  if (!p.hasValues() || !other.hasValues()) return nanOnly();
  const double plo = static_cast<double>(p.lo) - 0.5 * ulpD(p.lo);
  const double phi = static_cast<double>(p.hi) + 0.5 * ulpD(p.hi);
  const double l = plo + static_cast<double>(other.lo);
  const double h = phi + static_cast<double>(other.hi);
  const float lo = std::isnan(l) ? -kInf : std::nextafter(down(l), -kInf);
  const float hi = std::isnan(h) ? kInf : std::nextafter(up(h), kInf);
  return makeSet(lo, hi, p.nan || other.nan || std::isnan(l) || std::isnan(h));
}

// ---- traced operations -------------------------------------------------------------------------------------------

// a + b (negateB: a - b) under the active model.
Bound addOrSub(const Bound& a, const Bound& b, bool negateB) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  Bound x = a;
  Bound y = negateB ? negSet(b) : b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  Bound r = addSet(x, y);
  uint32_t flags = 0;
  if (conf && a.product != 0) {
    r = unite(r, fusedSum(x, y));
    flags |= bound::kFuseA;
  }
  if (conf && b.product != 0) {
    r = unite(r, fusedSum(y, x));
    flags |= bound::kFuseB;
  }
  if (conf) flushDenormals(r);
  if (c == nullptr) return r;
  uint32_t na = flags & bound::kFuseA ? a.product : nodeOf(c, a);
  uint32_t nb = flags & bound::kFuseB ? b.product : nodeOf(c, b);
  if (!negateB && flags == 0 && na > nb) std::swap(na, nb); // a + b == b + a bit for bit (not once fused)
  finish(c, r, (negateB ? bound::kSub : bound::kAdd) | flags | modelBit(c), na, nb, true);
  return r;
}

} // namespace

Bound::Bound(float x) : lo(x), hi(x), nan(false), node(0), product(0) {
  if (std::isnan(x)) {
    *this = nanOnly();
  }
  Impl* c = activeImpl();
  node = c ? c->constant(x) : 0;
}

Bound::Bound(int x) : Bound(static_cast<float>(x)) {}

Bound Bound::input(float lo, float hi, uint32_t symbol) {
  if (bitsOf(lo) == bitsOf(hi)) return Bound(lo);
  Bound r = makeSet(lo, hi, false);
  Impl* c = activeImpl();
  r.node = c ? c->intern(bound::Node{bound::kInput, symbol, bitsOf(lo), bitsOf(hi)}) : 0;
  return r;
}

Bound Bound::anything() {
  Bound r = makeSet(-kInf, kInf, true);
  Impl* c = activeImpl();
  r.node = c ? c->fresh() : 0;
  return r;
}

bool Bound::point() const { return !nan && bitsOf(lo) == bitsOf(hi); }
bool Bound::finite() const { return !nan && std::isfinite(lo) && std::isfinite(hi); }
bool Bound::contains(float x) const { return std::isnan(x) ? nan : (lo <= x && x <= hi); }

float ulpOf(float x) {
  const float a = std::fabs(x);
  if (std::isinf(a) || std::isnan(a)) return kInf;
  if (a == std::numeric_limits<float>::max()) return 0x1p104f;
  return std::nextafter(a, kInf) - a;
}

Bound operator+(const Bound& a, const Bound& b) { return addOrSub(a, b, false); }
Bound operator-(const Bound& a, const Bound& b) { return addOrSub(a, b, true); }

Bound operator*(const Bound& a, const Bound& b) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  Bound x = a;
  Bound y = b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  Bound r = mulSet(x, y);
  if (conf) flushDenormals(r);
  if (c == nullptr) return r;
  uint32_t na = nodeOf(c, a);
  uint32_t nb = nodeOf(c, b);
  if (na > nb) std::swap(na, nb); // x * y == y * x, fused or not
  const uint32_t op = bound::kMul | modelBit(c);
  finish(c, r, op, na, nb, true);
  if (conf) r.product = r.point() ? (na && nb ? c->intern(bound::Node{op, na, nb, 0}) : c->fresh()) : r.node;
  return r;
}

Bound operator/(const Bound& a, const Bound& b) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  Bound x = a;
  Bound y = b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  Bound r = divSet(x, y);
  if (conf && r.hasValues()) {
    // 2.5 ulp for |divisor| in [2^-126, 2^126]; beyond that range the spec leaves the result undefined.
    const bool inRange = y.hasValues() && std::max(std::fabs(y.lo), std::fabs(y.hi)) <= 0x1p126f &&
                         (y.lo >= kMinNormal || y.hi <= -kMinNormal);
    r = inRange ? widenUlps(r, 3.5) : makeSet(-kInf, kInf, true);
    flushDenormals(r);
  }
  finish(c, r, bound::kDiv | modelBit(c), nodeOf(c, a), nodeOf(c, b), true);
  return r;
}

Bound operator-(const Bound& a) {
  Impl* c = activeImpl();
  Bound r = negSet(a);
  if (c == nullptr) return r;
  const uint32_t op = bound::kNeg | modelBit(c);
  finish(c, r, op, nodeOf(c, a), 0, false);
  if (a.product != 0) r.product = c->intern(bound::Node{op, a.product, 0, 0}); // -(x*y) + z fuses too
  return r;
}

Bound& operator+=(Bound& a, const Bound& b) { return a = a + b; }
Bound& operator-=(Bound& a, const Bound& b) { return a = a - b; }
Bound& operator*=(Bound& a, const Bound& b) { return a = a * b; }
Bound& operator/=(Bound& a, const Bound& b) { return a = a / b; }

// ---- comparisons -------------------------------------------------------------------------------------------------

namespace {

// x's set as far as this run's answers constrain its node.
Bound effective(const Impl* c, const Bound& x, uint32_t n) {
  if (c == nullptr || !c->inPath || n == 0 || x.point()) return x;
  for (const Impl::Constraint& k : c->constraints) {
    if (k.node != n) continue;
    Bound r = x;
    r.lo = std::max(x.lo, k.lo);
    r.hi = std::min(x.hi, k.hi);
    r.nan = x.nan && k.nan;
    if (!(r.lo <= r.hi)) {
      r.lo = kInf;
      r.hi = -kInf;
    }
    return r;
  }
  return x;
}

// Records that node n is in [lo, hi] (or NaN when nan) for the rest of the run.
void constrain(Impl* c, uint32_t n, float lo, float hi, bool nan) {
  if (n == 0) return;
  for (Impl::Constraint& k : c->constraints) {
    if (k.node == n) {
      k.lo = std::max(k.lo, lo);
      k.hi = std::min(k.hi, hi);
      k.nan = k.nan && nan;
      return;
    }
  }
  c->constraints.push_back(Impl::Constraint{n, lo, hi, nan});
}

// What `answer` to (a kind b) implies for the non-constant side when the other side is a constant v.
void recordAnswer(Impl* c, uint32_t kind, bool answer, const Bound& a, uint32_t na, const Bound& b, uint32_t nb) {
  const float lowest = -kInf;
  if (b.point() && !a.point()) {
    const float v = b.lo;
    if (kind == bound::kLess) answer ? constrain(c, na, lowest, std::nextafter(v, -kInf), false)
                                     : constrain(c, na, v, kInf, true);
    if (kind == bound::kLessEqual) answer ? constrain(c, na, lowest, v, false)
                                          : constrain(c, na, std::nextafter(v, kInf), kInf, true);
    if (kind == bound::kEqual && answer) constrain(c, na, v, v, false);
  } else if (a.point() && !b.point()) {
    const float v = a.lo;
    if (kind == bound::kLess) answer ? constrain(c, nb, std::nextafter(v, kInf), kInf, false)
                                     : constrain(c, nb, lowest, v, true);
    if (kind == bound::kLessEqual) answer ? constrain(c, nb, v, kInf, false)
                                          : constrain(c, nb, lowest, std::nextafter(v, -kInf), true);
    if (kind == bound::kEqual && answer) constrain(c, nb, v, v, false);
  }
}

bool both(const Bound& a, const Bound& b) { return a.hasValues() && b.hasValues(); }

// Whether (a kind b) can be true and can be false for some values of the sets (NaN compares false).
void outcomes(uint32_t kind, const Bound& a, const Bound& b, bool& canTrue, bool& canFalse) {
  const bool values = both(a, b);
  const bool nan = a.nan || b.nan;
  if (kind == bound::kLess) {
    canTrue = values && a.lo < b.hi;
    canFalse = nan || (values && a.hi >= b.lo);
  } else if (kind == bound::kLessEqual) {
    canTrue = values && a.lo <= b.hi;
    canFalse = nan || (values && a.hi > b.lo);
  } else {
    canTrue = values && a.lo <= b.hi && b.lo <= a.hi;
    canFalse = nan || !values || !(a.lo == a.hi && b.lo == b.hi && a.lo == b.lo);
  }
}

// (a kind b): decided by the sets (as constrained by this run's answers), else the context's choice.
bool compare(uint32_t kind, const Bound& a, const Bound& b) {
  Impl* c = activeImpl();
  const uint32_t na = nodeOf(c, a);
  const uint32_t nb = nodeOf(c, b);
  bool canTrue = false;
  bool canFalse = false;
  outcomes(kind, effective(c, a, na), effective(c, b, nb), canTrue, canFalse);
  if (!canFalse) return true;
  if (!canTrue) return false;
  if (c == nullptr) return true;
  const bool swap = kind == bound::kEqual && na > nb;
  const bool answer = c->choose(kind, swap ? nb : na, swap ? na : nb);
  if (c->inPath) recordAnswer(c, kind, answer, a, na, b, nb);
  return answer;
}

} // namespace

bool operator<(const Bound& a, const Bound& b) { return compare(bound::kLess, a, b); }
bool operator<=(const Bound& a, const Bound& b) { return compare(bound::kLessEqual, a, b); }
bool operator>(const Bound& a, const Bound& b) { return compare(bound::kLess, b, a); }
bool operator>=(const Bound& a, const Bound& b) { return compare(bound::kLessEqual, b, a); }
bool operator==(const Bound& a, const Bound& b) { return compare(bound::kEqual, a, b); }
bool operator!=(const Bound& a, const Bound& b) { return !compare(bound::kEqual, a, b); }

// ---- built-ins ---------------------------------------------------------------------------------------------------

namespace {

// A unary built-in: the set function `f` under the active model, traced as (op, x).
template <class F>
Bound unary(uint32_t op, const Bound& x, F f) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  Bound in = x;
  if (conf) flushDenormals(in);
  Bound r = f(in, conf);
  if (conf) flushDenormals(r);
  r.product = 0;
  r.node = 0;
  if (c != nullptr) finish(c, r, op | modelBit(c), nodeOf(c, x), 0, false);
  return r;
}

// Conformant inversesqrt: 2 ulp; undefined for x <= 0.
Bound inverseSqrtConformant(const Bound& x) {
  if (!x.hasValues() || x.lo <= 0.0f) return x.hasValues() ? makeSet(-kInf, kInf, true) : nanOnly();
  const double vlo = 1.0 / std::sqrt(static_cast<double>(x.hi));
  const double vhi = 1.0 / std::sqrt(static_cast<double>(x.lo));
  return widened(vlo, vhi, 2.5, x.nan);
}

Bound exp2Set(const Bound& x, bool conf) {
  if (!x.hasValues()) return x;
  if (!conf && x.point()) { // the C++ build's own exp2f
    const float v = std::exp2(x.lo);
    return makeSet(v, v, false);
  }
  // Cpp: glibc's exp2f within 1 ulp, modelled as 2 (+ 0.5 for the double evaluation). Conformant: 3 + 2|x|.
  const double k = conf ? 3.5 + 2.0 * std::max(std::fabs(static_cast<double>(x.lo)), std::fabs(static_cast<double>(x.hi)))
                        : 2.5;
  return widened(std::exp2(static_cast<double>(x.lo)), std::exp2(static_cast<double>(x.hi)), k, x.nan);
}

Bound log2Set(const Bound& x, bool conf) {
  if (!x.hasValues()) return x;
  if (conf) { // undefined for x <= 0; 3 ulp outside [0.5, 2], 2^-21 absolute inside
    if (x.lo <= 0.0f) return makeSet(-kInf, kInf, true);
    Bound r = widened(std::log2(static_cast<double>(x.lo)), std::log2(static_cast<double>(x.hi)), 3.5, x.nan);
    if (x.lo <= 2.0f && x.hi >= 0.5f) {
      r.lo = down(static_cast<double>(r.lo) - 0x1p-21);
      r.hi = up(static_cast<double>(r.hi) + 0x1p-21);
    }
    return r;
  }
  if (x.point()) {
    const float v = std::log2(x.lo);
    return std::isnan(v) ? nanOnly() : makeSet(v, v, false);
  }
  const bool nan = x.nan || x.lo < 0.0f;
  if (x.hi < 0.0f) return nanOnly();
  const double lo = x.lo <= 0.0f ? -HUGE_VAL : std::log2(static_cast<double>(x.lo));
  return widened(lo, std::log2(static_cast<double>(x.hi)), 2.5, nan);
}

Bound acosSet(const Bound& x, bool conf);
Bound powSet(const Bound& x, const Bound& y, bool conf);

} // namespace

Bound sqrt(const Bound& x) {
  return unary(bound::kSqrt, x, [](const Bound& in, bool conf) {
    Bound r = sqrtSet(in);
    // Conformant: 1 / inversesqrt(x): 2 ulp of inversesqrt (up to 4 ulp of the root, relatively) and 2.5 of the
    // division.
    return conf && r.hasValues() ? widenUlps(r, 7.5) : r;
  });
}

Bound inversesqrt(const Bound& x) {
  return unary(bound::kInverseSqrt, x, [](const Bound& in, bool conf) {
    return conf ? inverseSqrtConformant(in) : divSet(Bound(1.0f), sqrtSet(in)); // GLM: 1.0f / sqrt(x)
  });
}

Bound exp2(const Bound& x) { return unary(bound::kExp2, x, exp2Set); }
Bound log2(const Bound& x) { return unary(bound::kLog2, x, log2Set); }
Bound acos(const Bound& x) { return unary(bound::kAcos, x, acosSet); }

Bound floor(const Bound& x) {
  return unary(bound::kFloor, x, [](const Bound& in, bool) {
    return in.hasValues() ? makeSet(std::floor(in.lo), std::floor(in.hi), in.nan) : in;
  });
}

Bound ceil(const Bound& x) {
  return unary(bound::kCeil, x, [](const Bound& in, bool) {
    return in.hasValues() ? makeSet(std::ceil(in.lo), std::ceil(in.hi), in.nan) : in;
  });
}

Bound abs(const Bound& x) {
  return unary(bound::kAbs, x, [](const Bound& in, bool) {
    if (!in.hasValues()) return in;
    if (hasZero(in)) return makeSet(0.0f, std::max(-in.lo, in.hi), in.nan);
    return in.lo > 0.0f ? in : makeSet(-in.hi, -in.lo, in.nan);
  });
}

namespace {

// GLM's min(a, b) = b < a ? b : a and max(a, b) = a < b ? b : a: a NaN first operand is returned, a NaN second
// operand returns the first. Conformant (GLSL leaves NaN undefined): either operand, or NaN.
Bound minMax(uint32_t op, const Bound& a, const Bound& b) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  const bool isMin = op == bound::kMin;
  Bound r = nanOnly();
  r.nan = a.nan;
  if (a.hasValues() && b.hasValues()) {
    r.lo = isMin ? std::min(a.lo, b.lo) : std::max(a.lo, b.lo);
    r.hi = isMin ? std::min(a.hi, b.hi) : std::max(a.hi, b.hi);
  }
  if (b.nan && a.hasValues()) r = unite(r, makeSet(a.lo, a.hi, r.nan));
  if (conf && (a.nan || b.nan)) r = unite(unite(r, a), b);
  r.product = 0;
  r.node = 0;
  if (c != nullptr) finish(c, r, op | modelBit(c), nodeOf(c, a), nodeOf(c, b), true);
  return r;
}

} // namespace

Bound min(const Bound& a, const Bound& b) { return minMax(bound::kMin, a, b); }
Bound max(const Bound& a, const Bound& b) { return minMax(bound::kMax, a, b); }

Bound pow(const Bound& x, const Bound& y) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  Bound bx = x;
  Bound by = y;
  if (conf) {
    flushDenormals(bx);
    flushDenormals(by);
  }
  Bound r = powSet(bx, by, conf);
  if (conf) flushDenormals(r);
  if (c != nullptr) finish(c, r, bound::kPow | modelBit(c), nodeOf(c, x), nodeOf(c, y), true);
  return r;
}

namespace {

// acos: Cpp: glibc's acosf (within 1 ulp; modelled as 2), NaN outside [-1, 1]. Conformant: GLSL 4.50 leaves its
// precision undefined; Vulkan's: atan2(sqrt(1 - x*x), x) with atan2 within 4096 ulp, the rest as modelled here.
Bound acosSet(const Bound& x, bool conf) {
  if (!x.hasValues()) return x;
  if (conf) {
    if (x.lo < -1.0f || x.hi > 1.0f) return makeSet(-kInf, kInf, true);
    Bound sq = mulSet(x, x);
    Bound t = unite(addSet(Bound(1.0f), negSet(sq)), fusedSum(negSet(sq), Bound(1.0f)));
    flushDenormals(t);
    Bound s = sqrtSet(t);
    if (s.hasValues()) s = widenUlps(s, 7.5);
    if (!s.hasValues()) return makeSet(-kInf, kInf, true);
    const double slo = std::max(0.0, static_cast<double>(s.lo));
    const double shi = static_cast<double>(s.hi);
    if (slo == 0.0 && x.lo <= 0.0f && x.hi >= 0.0f) return widened(0.0, M_PI, 4097.0, true);
    const double v[4] = {std::atan2(slo, static_cast<double>(x.lo)), std::atan2(slo, static_cast<double>(x.hi)),
                         std::atan2(shi, static_cast<double>(x.lo)), std::atan2(shi, static_cast<double>(x.hi))};
    return widened(*std::min_element(v, v + 4), *std::max_element(v, v + 4), 4097.0, x.nan || s.nan);
  }
  if (x.point()) {
    const float v = std::acos(x.lo);
    return std::isnan(v) ? nanOnly() : makeSet(v, v, false);
  }
  const bool nan = x.nan || x.lo < -1.0f || x.hi > 1.0f;
  if (x.lo > 1.0f || x.hi < -1.0f) return nanOnly();
  const double lo = std::acos(std::min(static_cast<double>(x.hi), 1.0));
  const double hi = std::acos(std::max(static_cast<double>(x.lo), -1.0));
  return widened(lo, hi, 2.5, nan);
}

// pow over x > 0: the extremes of y * log2(x) (bilinear) are at the corners.
Bound powPositive(const Bound& x, const Bound& y, bool conf) {
  if (conf) { // exp2(y * log2(x)), each step as modelled
    Bound l = log2Set(x, true);
    Bound p = mulSet(y, l);
    flushDenormals(p);
    return exp2Set(p, true);
  }
  const double xs[2] = {static_cast<double>(x.lo), static_cast<double>(x.hi)};
  const double ys[2] = {static_cast<double>(y.lo), static_cast<double>(y.hi)};
  double lo = HUGE_VAL;
  double hi = -HUGE_VAL;
  bool nan = x.nan || y.nan;
  for (double xv : xs) {
    for (double yv : ys) {
      const double v = std::pow(xv, yv);
      if (std::isnan(v)) {
        nan = true;
        continue;
      }
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (lo > hi) return nanOnly();
  return widened(lo, hi, 2.5, nan);
}

Bound powSet(const Bound& x, const Bound& y, bool conf) {
  if (!x.hasValues() || !y.hasValues()) return nanOnly();
  if (x.lo < 0.0f) return makeSet(-kInf, kInf, true); // a negative base: NaN, +-values; not modelled closer
  if (!conf && x.point() && y.point()) {              // the C++ build's own powf
    const float v = std::pow(x.lo, y.lo);
    return std::isnan(v) ? nanOnly() : makeSet(v, v, x.nan || y.nan);
  }
  Bound r = nanOnly();
  r.nan = x.nan || y.nan;
  if (x.lo <= 0.0f) { // pow(0, y): 0 for y > 0, 1 for y == 0, +Inf for y < 0 (Conformant: undefined for y <= 0)
    if (conf && y.lo <= 0.0f) return makeSet(-kInf, kInf, true);
    if (y.hi > 0.0f) r = unite(r, makeSet(0.0f, 0.0f, false));
    if (hasZero(y)) r = unite(r, makeSet(1.0f, 1.0f, false));
    if (y.lo < 0.0f) r = unite(r, makeSet(kInf, kInf, false));
  }
  if (x.hi > 0.0f) {
    Bound positive = x;
    positive.lo = std::max(x.lo, 0x1p-149f);
    r = unite(r, powPositive(positive, y, conf));
  }
  return r;
}

} // namespace

} // namespace fftess::lod
