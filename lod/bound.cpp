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
#include "lod/bound_sets.h"

namespace fftess::lod {

namespace bound {

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
    lo = lower(lo, v[i]);
    hi = upper(hi, v[i]);
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
  const float lo = std::isnan(l) ? -kInf : stepDown(down(l));
  const float hi = std::isnan(h) ? kInf : stepUp(up(h));
  return makeSet(lo, hi, p.nan || other.nan || std::isnan(l) || std::isnan(h));
}

} // namespace bound

namespace {

using namespace bound;

// ---- traced operations -------------------------------------------------------------------------------------------

// a + b (negateB: a - b) under the active model.
Bound addOrSub(const Bound& a, const Bound& b, bool negateB) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  uint32_t flags = 0;
  if (conf && a.product != 0) flags |= bound::kFuseA;
  if (conf && b.product != 0) flags |= bound::kFuseB;
  uint32_t na = flags & bound::kFuseA ? a.product : nodeOf(c, a);
  uint32_t nb = flags & bound::kFuseB ? b.product : nodeOf(c, b);
  if (!negateB && flags == 0 && na > nb) std::swap(na, nb); // a + b == b + a bit for bit (not once fused)
  const Node key{(negateB ? bound::kSub : bound::kAdd) | flags | modelBit(c), na, nb, 0};
  const bool memo = worthKeeping(c, a, b);
  Bound r;
  if (memo && recalled(c, key, true, r)) return r;
  Bound x = a;
  Bound y = negateB ? negSet(b) : b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  r = addSet(x, y);
  if (flags & bound::kFuseA) r = unite(r, fusedSum(x, y));
  if (flags & bound::kFuseB) r = unite(r, fusedSum(y, x));
  if (conf) flushDenormals(r);
  if (c == nullptr) return r;
  finish(c, r, key.op, na, nb, true);
  if (memo) keep(c, key, true, r);
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
  uint32_t na = nodeOf(c, a);
  uint32_t nb = nodeOf(c, b);
  if (na > nb) std::swap(na, nb); // x * y == y * x, fused or not
  const Node key{bound::kMul | modelBit(c), na, nb, 0};
  const bool memo = worthKeeping(c, a, b);
  Bound r;
  if (memo && recalled(c, key, true, r)) return r;
  Bound x = a;
  Bound y = b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  r = mulSet(x, y);
  if (conf) flushDenormals(r);
  if (c == nullptr) return r;
  finish(c, r, key.op, na, nb, true);
  if (conf) r.product = r.point() ? (na && nb ? c->intern(key) : c->fresh()) : r.node;
  if (memo) keep(c, key, true, r);
  return r;
}

Bound operator/(const Bound& a, const Bound& b) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  const Node key{bound::kDiv | modelBit(c), nodeOf(c, a), nodeOf(c, b), 0};
  const bool memo = worthKeeping(c, a, b);
  Bound r;
  if (memo && recalled(c, key, true, r)) return r;
  Bound x = a;
  Bound y = b;
  if (conf) {
    flushDenormals(x);
    flushDenormals(y);
  }
  r = divSet(x, y);
  if (conf && r.hasValues()) {
    // 2.5 ulp for |divisor| in [2^-126, 2^126]; beyond that range the spec leaves the result undefined.
    const bool inRange = y.hasValues() && std::max(std::fabs(y.lo), std::fabs(y.hi)) <= 0x1p126f &&
                         (y.lo >= kMinNormal || y.hi <= -kMinNormal);
    r = inRange ? widenUlps(r, 3.5) : makeSet(-kInf, kInf, true);
    flushDenormals(r);
  }
  finish(c, r, key.op, key.a, key.b, true);
  if (memo) keep(c, key, true, r);
  return r;
}

Bound operator-(const Bound& a) {
  Impl* c = activeImpl();
  const Node key{bound::kNeg | modelBit(c), nodeOf(c, a), a.product, 0}; // the product decides what -a may fuse into
  Bound r;
  if (recalled(c, key, false, r)) return r;
  r = negSet(a);
  if (conformant(c)) flushDenormals(r);
  if (c == nullptr) return r;
  finish(c, r, key.op, key.a, 0, false);
  if (a.product != 0) r.product = c->intern(bound::Node{key.op, a.product, 0, 0}); // -(x*y) + z fuses too
  keep(c, key, false, r);
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

} // namespace fftess::lod
