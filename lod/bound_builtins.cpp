// fftess lod: Bound's GLSL built-ins (lod/bound.h): sqrt, inversesqrt, exp2, log2, pow, acos, floor, ceil, abs,
// min, max under FloatModel::Cpp or ::Conformant, traced in the active BoundContext (docs/lod.md, "Bounds").
#include <algorithm>
#include <cmath>

#include "lod/bound.h"
#include "lod/bound_internal.h"
#include "lod/bound_sets.h"

namespace fftess::lod {

namespace {
using namespace bound;
} // namespace

// ---- built-ins ---------------------------------------------------------------------------------------------------

namespace {

// A unary built-in: the set function `f` under the active model, traced as (op, x).
template <class F>
Bound unary(uint32_t op, const Bound& x, F f) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  const Node key{op | modelBit(c), nodeOf(c, x), 0, 0};
  Bound r;
  if (recalled(c, key, false, r)) return r;
  Bound in = x;
  if (conf) flushDenormals(in);
  r = f(in, conf);
  if (conf) flushDenormals(r);
  r.product = 0;
  r.node = 0;
  if (c == nullptr) return r;
  finish(c, r, key.op, key.a, 0, false);
  keep(c, key, false, r);
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
Bound minMax(uint32_t op, const Bound& x, const Bound& y) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  const Node key{op | modelBit(c), nodeOf(c, x), nodeOf(c, y), 0};
  Bound recall;
  if (recalled(c, key, true, recall)) return recall;
  const bool isMin = op == bound::kMin;
  Bound a = x;
  Bound b = y;
  if (conf) {
    flushDenormals(a);
    flushDenormals(b);
  }
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
  if (c == nullptr) return r;
  finish(c, r, key.op, key.a, key.b, true);
  keep(c, key, true, r);
  return r;
}

} // namespace

Bound min(const Bound& a, const Bound& b) { return minMax(bound::kMin, a, b); }
Bound max(const Bound& a, const Bound& b) { return minMax(bound::kMax, a, b); }

Bound pow(const Bound& x, const Bound& y) {
  Impl* c = activeImpl();
  const bool conf = conformant(c);
  const Node key{bound::kPow | modelBit(c), nodeOf(c, x), nodeOf(c, y), 0};
  Bound recall;
  if (recalled(c, key, true, recall)) return recall;
  Bound bx = x;
  Bound by = y;
  if (conf) {
    flushDenormals(bx);
    flushDenormals(by);
  }
  Bound r = powSet(bx, by, conf);
  if (conf) flushDenormals(r);
  if (c == nullptr) return r;
  finish(c, r, key.op, key.a, key.b, true);
  keep(c, key, true, r);
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
  if (!conf && x.point() && y.point() && x.lo != 0.0f) { // the C++ build's own powf (a zero base: either sign)
    const float v = std::pow(x.lo, y.lo);
    return std::isnan(v) ? nanOnly() : makeSet(v, v, x.nan || y.nan);
  }
  Bound r = nanOnly();
  r.nan = x.nan || y.nan;
  if (x.lo <= 0.0f) { // pow(0, y): 0 for y > 0, 1 for y == 0, +Inf for y < 0 (Conformant: undefined for y <= 0)
    if (conf && y.lo <= 0.0f) return makeSet(-kInf, kInf, true);
    if (y.hi > 0.0f) r = unite(r, conf ? widened(0.0, 0.0, 3.5, false) : makeSet(0.0f, 0.0f, false));
    if (hasZero(y)) r = unite(r, makeSet(1.0f, 1.0f, false));
    if (y.lo < 0.0f) r = unite(r, makeSet(kInf, kInf, false));
    if (y.lo <= -1.0f) r = unite(r, makeSet(-kInf, -kInf, false)); // pow(-0, odd negative integer) = -Inf
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
