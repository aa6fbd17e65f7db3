// Internal (lod/bound.cpp, lod/bound_builtins.cpp): the set arithmetic behind Bound's operations, without the trace
// (lod/bound.h states the model; docs/lod.md, "Bounds").
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "lod/bound.h"
#include "lod/bound_internal.h"

namespace fftess::lod::bound {

using Impl = BoundContext::Impl;

constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr float kMinNormal = 0x1p-126f;

inline uint32_t bitsOf(float x) {
  uint32_t u;
  std::memcpy(&u, &x, sizeof u);
  return u;
}

inline Bound makeSet(float lo, float hi, bool nan) {
  Bound r{};
  r.lo = lo;
  r.hi = hi;
  r.nan = nan;
  return r;
}

inline Bound nanOnly() { return makeSet(kInf, -kInf, true); }

inline bool hasInf(const Bound& x) { return x.hasValues() && (x.lo == -kInf || x.hi == kInf); }
inline bool hasZero(const Bound& x) { return x.lo <= 0.0f && x.hi >= 0.0f; }

// std::nextafter(f, -Inf) / (f, +Inf) for f not NaN, by the bits.
inline float stepDown(float f) {
  if (f == -kInf) return f;
  if (f == 0.0f) return -0x1p-149f;
  uint32_t u = bitsOf(f);
  u = f > 0.0f ? u - 1 : u + 1;
  std::memcpy(&f, &u, sizeof f);
  return f;
}
inline float stepUp(float f) { return -stepDown(-f); }

// The largest float <= d, the smallest float >= d (d not NaN; beyond the float range: +-FLT_MAX or +-Inf).
inline float down(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) > d) f = stepDown(f);
  return f;
}
inline float up(double d) {
  float f = static_cast<float>(d);
  if (static_cast<double>(f) < d) f = stepUp(f);
  return f;
}

// The float ulp at magnitude |v| (v a double, possibly beyond the float range): 2^(e - 23) for |v| in the binade
// [2^e, 2^(e+1)), 2^-149 below 2^-126; Inf for Inf.
inline double ulpD(double v) {
  uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  const int e = static_cast<int>((bits >> 52) & 0x7ff) - 1023;
  if (e == 1024) return HUGE_VAL; // Inf (NaN: callers do not ask)
  if (e < -126) return 0x1p-149;
  const uint64_t u = static_cast<uint64_t>(e - 23 + 1023) << 52;
  double r;
  std::memcpy(&r, &u, sizeof r);
  return r;
}

// [vlo - k ulps, vhi + k ulps], rounded outward to float.
inline Bound widened(double vlo, double vhi, double k, bool nan) {
  const double l = vlo - k * ulpD(vlo);
  const double h = vhi + k * ulpD(vhi);
  return makeSet(std::isnan(l) ? -kInf : down(l), std::isnan(h) ? kInf : up(h), nan);
}

// Widens a float set by k ulps of each bound (the GPU's error beyond the correctly rounded result).
inline Bound widenUlps(const Bound& x, double k) {
  if (!x.hasValues()) return x;
  return widened(x.lo, x.hi, k, x.nan);
}

// min / max that order -0 before +0, so that a set holding both zeros is [-0, +0], never a point: a point claims
// one float, and the sign of a zero can matter (1 / x).
inline float lower(float a, float b) { return (b < a || (b == a && std::signbit(b))) ? b : a; }
inline float upper(float a, float b) { return (b > a || (b == a && !std::signbit(b))) ? b : a; }

inline Bound unite(const Bound& a, const Bound& b) {
  return makeSet(lower(a.lo, b.lo), upper(a.hi, b.hi), a.nan || b.nan);
}

// Conformant: a denormal may be read or written as 0 (of either sign).
inline void flushDenormals(Bound& x) {
  if (x.hasValues() && x.lo < kMinNormal && x.hi > -kMinNormal) {
    x.lo = std::min(x.lo, 0.0f);
    x.hi = std::max(x.hi, 0.0f);
  }
}

inline bool conformant(const Impl* c) { return c != nullptr && c->evalModel == FloatModel::Conformant; }
inline uint32_t modelBit(const Impl* c) { return conformant(c) ? bound::kConformantBit : 0u; }

// The result's node: a point is the constant of its bits; otherwise (op, operands), or a fresh node when an operand
// is untraced.
inline void finish(Impl* c, Bound& r, uint32_t op, uint32_t na, uint32_t nb, bool binary) {
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

// The result of `key` from an earlier evaluation in this trace (false when none, or an operand is untraced).
// Operations on points under Cpp are one float operation: cheaper to redo than to look up; they are not kept.
inline bool worthKeeping(const Impl* c, const Bound& a, const Bound& b) {
  return c != nullptr && (c->evalModel != FloatModel::Cpp || !a.point() || !b.point());
}
inline bool recalled(const Impl* c, const Node& key, bool binary, Bound& out) {
  if (c == nullptr || key.a == 0 || (binary && key.b == 0)) return false;
  const Bound* r = c->recall(key);
  if (r == nullptr) return false;
  out = *r;
  return true;
}
inline void keep(Impl* c, const Node& key, bool binary, const Bound& r) {
  if (c != nullptr && key.a != 0 && (!binary || key.b != 0)) c->remember(key, r);
}

// Sets (no trace): lod/bound.cpp.
Bound fromCandidates(const float* v, int n, bool nan);
Bound addSet(const Bound& a, const Bound& b);
Bound negSet(const Bound& a);
Bound mulSet(const Bound& a, const Bound& b);
Bound divSet(const Bound& a, const Bound& b);
Bound sqrtSet(const Bound& x);
Bound fusedSum(const Bound& p, const Bound& other);

} // namespace fftess::lod::bound
