// Bound's operations (lod/bound.h) against exhaustive float evaluation on sampled inputs: for random small sets
// (points, a few ulps, sets touching 0, denormals, +-Inf ends, NaN, huge values, one 16.16 step around an integer),
// every float the C++ build's operation gives on floats sampled from the operands' sets lies in the result.
// Conformant also holds the fused a * b + c, a flushed denormal, and a few ulps around the correctly rounded result
// of the operations the spec lets err.
#include <catch2/catch.hpp>

#include <functional>
#include <random>
#include <vector>

#include "lod/bound.h"
#include "lod_test_util.h"

using namespace fftess::lod;
using fftess::bitsOf;
using lodtest::hex;

namespace {

using Rng = std::mt19937;
constexpr float kInf = INFINITY;

// Floats as integers in their order (-0 and +0 both 0).
int64_t ordered(float f) {
  const uint32_t b = bitsOf(f);
  return (b & 0x80000000u) ? -static_cast<int64_t>(b & 0x7fffffffu) : static_cast<int64_t>(b);
}
float fromOrdered(int64_t o) {
  const uint32_t b = o >= 0 ? static_cast<uint32_t>(o) : (static_cast<uint32_t>(-o) | 0x80000000u);
  float f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

float uniform(Rng& r, float lo, float hi) { return std::uniform_real_distribution<float>(lo, hi)(r); }
float randomSign(Rng& r, float x) { return (r() & 1) ? -x : x; }

float randomFloat(Rng& r) {
  switch (r() % 8) {
  case 0:
    return uniform(r, -100.0f, 100.0f);
  case 1:
    return randomSign(r, std::ldexp(uniform(r, 1.0f, 2.0f), static_cast<int>(r() % 60) - 30));
  case 2:
    return fromOrdered(randomSign(r, 1.0f) < 0 ? -static_cast<int64_t>(1 + r() % 0x7fffff) : 1 + r() % 0x7fffff);
  case 3:
    return randomSign(r, std::ldexp(uniform(r, 1.0f, 2.0f), 100 + static_cast<int>(r() % 28)));
  case 4:
    return static_cast<float>(static_cast<int>(r() % 129) - 64);
  case 5:
    return (r() & 1) ? -0.0f : 0.0f;
  case 6:
    return randomSign(r, std::ldexp(uniform(r, 1.0f, 2.0f), -126 - static_cast<int>(r() % 3)));
  default:
    return uniform(r, -1.0f, 1.0f);
  }
}

// A random set and floats sampled from it (its ends, their neighbours inside, 0 when inside, random members).
struct Operand {
  Bound b;
  std::vector<float> samples;
};

Operand randomOperand(Rng& r, uint32_t symbol) {
  float lo = randomFloat(r);
  float hi = lo;
  switch (r() % 8) {
  case 0: // a point
    break;
  case 1: // a few ulps
    hi = fromOrdered(std::min<int64_t>(ordered(lo) + 1 + r() % 1000, ordered(FLT_MAX)));
    break;
  case 2: // touching or containing 0
    lo = (r() % 3 == 0) ? 0.0f : -std::fabs(randomFloat(r));
    hi = (r() % 3 == 0) ? 0.0f : std::fabs(randomFloat(r));
    break;
  case 3: { // one 16.16 step around an integer
    const float n = static_cast<float>(static_cast<int>(r() % 2001) - 1000);
    lo = n - 0x1p-16f;
    hi = n + 0x1p-16f;
    break;
  }
  case 4: // an infinite end
    if (r() & 1) {
      hi = kInf;
    } else {
      lo = -kInf;
    }
    break;
  case 5: // denormals
    lo = fromOrdered(-static_cast<int64_t>(r() % 0x800000));
    hi = fromOrdered(static_cast<int64_t>(r() % 0x800000));
    break;
  default:
    hi = randomFloat(r);
    break;
  }
  if (hi < lo) std::swap(lo, hi);
  Operand o;
  o.b = lo == hi && bitsOf(lo) == bitsOf(hi) ? Bound(lo) : Bound::input(lo, hi, symbol);
  if (lo == hi) o.b = Bound(lo);
  if (r() % 8 == 0) { // NaN too (an untraced set)
    o.b.nan = true;
    o.b.node = 0;
    o.samples.push_back(NAN);
  }
  o.samples.push_back(lo);
  o.samples.push_back(hi);
  if (lo < hi) {
    o.samples.push_back(std::nextafter(lo, kInf));
    o.samples.push_back(std::nextafter(hi, -kInf));
  }
  if (lo <= 0.0f && hi >= 0.0f) {
    o.samples.push_back(0.0f);
    o.samples.push_back(-0.0f);
  }
  std::uniform_int_distribution<int64_t> pick(ordered(lo), ordered(hi));
  for (int i = 0; i < 12; ++i) o.samples.push_back(fromOrdered(pick(r)));
  if (std::isfinite(lo) && std::isfinite(hi) && hi - lo < FLT_MAX) {
    for (int i = 0; i < 4; ++i) o.samples.push_back(uniform(r, 0.0f, 1.0f) * (hi - lo) + lo);
  }
  return o;
}

bool denormal(float f) { return f != 0.0f && std::fabs(f) < 0x1p-126f; }

// The values a conformant GPU may also give for float result f: f itself, 0 for a denormal, and up to `steps`
// floats either side when the operation has an ulp bound of at least steps + 0.5 ulp (only floats in f's binade,
// and none when f is a power of two: there the exact result may lie in the binade below, whose ulp is half).
std::vector<float> conformantAlso(float f, int steps) {
  std::vector<float> v{f};
  if (denormal(f)) v.push_back(0.0f);
  int e = 0;
  if (!std::isfinite(f) || f == 0.0f || std::frexp(std::fabs(f), &e) == 0.5f) return v;
  float lo = f;
  float hi = f;
  for (int i = 0; i < steps; ++i) {
    lo = std::nextafter(lo, -kInf);
    hi = std::nextafter(hi, kInf);
    int el = 0;
    int eh = 0;
    std::frexp(lo, &el);
    std::frexp(hi, &eh);
    if (el == e && lo != 0.0f) v.push_back(lo);
    if (eh == e && hi != 0.0f) v.push_back(hi);
  }
  return v;
}

// Conformant reads a denormal operand as 0 or not.
std::vector<float> flushedToo(float x) {
  std::vector<float> v{x};
  if (denormal(x)) v.push_back(0.0f);
  return v;
}

struct Failure {
  int count = 0;
  std::string first;
};

void record(Failure& f, const std::string& what) {
  if (f.count++ == 0) f.first = what;
}

std::string setText(const Bound& b) {
  return "[" + hex(b.lo) + ", " + hex(b.hi) + "]" + (b.nan ? " + NaN" : "");
}

struct UnaryOp {
  const char* name;
  std::function<Bound(const Bound&)> bounded;
  std::function<float(float)> plain;
  int steps; // Conformant: floats either side of the correctly rounded result the spec allows
};

struct BinaryOp {
  const char* name;
  std::function<Bound(const Bound&, const Bound&)> bounded;
  std::function<float(float, float)> plain;
  int steps;
  bool divisorRange; // the steps only for a divisor with magnitude in [2^-126, 2^126]
};

std::vector<UnaryOp> unaryOps() {
  return {
      {"sqrt", [](const Bound& x) { return sqrt(x); }, [](float x) { return std::sqrt(x); }, 3},
      {"inversesqrt", [](const Bound& x) { return inversesqrt(x); }, [](float x) { return 1.0f / std::sqrt(x); }, 1},
      {"exp2", [](const Bound& x) { return exp2(x); }, [](float x) { return std::exp2(x); }, 2},
      {"log2", [](const Bound& x) { return log2(x); }, [](float x) { return std::log2(x); }, 2},
      {"acos", [](const Bound& x) { return acos(x); }, [](float x) { return std::acos(x); }, 3},
      {"floor", [](const Bound& x) { return floor(x); }, [](float x) { return std::floor(x); }, 0},
      {"ceil", [](const Bound& x) { return ceil(x); }, [](float x) { return std::ceil(x); }, 0},
      {"abs", [](const Bound& x) { return abs(x); }, [](float x) { return std::fabs(x); }, 0},
      {"negate", [](const Bound& x) { return -x; }, [](float x) { return -x; }, 0},
  };
}

std::vector<BinaryOp> binaryOps() {
  return {
      {"add", [](const Bound& a, const Bound& b) { return a + b; }, [](float a, float b) { return a + b; }, 0, false},
      {"sub", [](const Bound& a, const Bound& b) { return a - b; }, [](float a, float b) { return a - b; }, 0, false},
      {"mul", [](const Bound& a, const Bound& b) { return a * b; }, [](float a, float b) { return a * b; }, 0, false},
      {"div", [](const Bound& a, const Bound& b) { return a / b; }, [](float a, float b) { return a / b; }, 2, true},
      {"pow", [](const Bound& a, const Bound& b) { return pow(a, b); }, [](float a, float b) { return std::pow(a, b); },
       2, false},
      // GLM's min / max: b < a ? b : a, a < b ? b : a.
      {"min", [](const Bound& a, const Bound& b) { return min(a, b); }, [](float a, float b) { return b < a ? b : a; },
       0, false},
      {"max", [](const Bound& a, const Bound& b) { return max(a, b); }, [](float a, float b) { return a < b ? b : a; },
       0, false},
  };
}

const char* modelName(FloatModel m) { return m == FloatModel::Cpp ? "cpp" : "conformant"; }

// Every float result of `plain` on the operand samples (Conformant: and what conformantAlso allows) in `got`.
void checkUnary(const UnaryOp& op, FloatModel model, Rng& rng, Failure& fail) {
  BoundContext ctx(model);
  BoundContext::Scope scope(ctx);
  for (int iter = 0; iter < 1500; ++iter) {
    const Operand x = randomOperand(rng, 1);
    const Bound got = op.bounded(x.b);
    for (float s : x.samples) {
      for (float in : model == FloatModel::Cpp ? std::vector<float>{s} : flushedToo(s)) {
        const float f = op.plain(in);
        const int steps = model == FloatModel::Cpp ? 0 : op.steps;
        for (float want : conformantAlso(f, steps)) {
          if (model == FloatModel::Cpp && want != f) continue;
          if (!got.contains(want)) {
            record(fail, std::string(op.name) + " " + modelName(model) + " of " + hex(in) + " in " + setText(x.b) +
                             ": " + hex(want) + " not in " + setText(got));
          }
        }
      }
    }
  }
}

void checkBinary(const BinaryOp& op, FloatModel model, Rng& rng, Failure& fail) {
  BoundContext ctx(model);
  BoundContext::Scope scope(ctx);
  for (int iter = 0; iter < 1500; ++iter) {
    const Operand a = randomOperand(rng, 1);
    const Operand b = randomOperand(rng, 2);
    const Bound got = op.bounded(a.b, b.b);
    for (int k = 0; k < 48; ++k) {
      const float sa = a.samples[k < 16 ? k % 4 % a.samples.size() : rng() % a.samples.size()];
      const float sb = b.samples[k < 16 ? k / 4 % b.samples.size() : rng() % b.samples.size()];
      for (float ia : model == FloatModel::Cpp ? std::vector<float>{sa} : flushedToo(sa)) {
        for (float ib : model == FloatModel::Cpp ? std::vector<float>{sb} : flushedToo(sb)) {
          const float f = op.plain(ia, ib);
          const bool inRange = !op.divisorRange || (std::fabs(ib) >= 0x1p-126f && std::fabs(ib) <= 0x1p126f);
          const int steps = model == FloatModel::Cpp || !inRange ? 0 : op.steps;
          for (float want : model == FloatModel::Cpp ? std::vector<float>{f} : conformantAlso(f, steps)) {
            if (!got.contains(want)) {
              record(fail, std::string(op.name) + " " + modelName(model) + " of " + hex(ia) + ", " + hex(ib) +
                               " in " + setText(a.b) + ", " + setText(b.b) + ": " + hex(want) + " not in " +
                               setText(got));
            }
          }
        }
      }
    }
  }
}

} // namespace

TEST_CASE("Bound: every float result of each operation on sampled inputs lies in the result, C++ build and "
          "conformant GPUs",
          "[lod][bound]") {
  for (FloatModel model : {FloatModel::Cpp, FloatModel::Conformant}) {
    for (const UnaryOp& op : unaryOps()) {
      Rng rng(101);
      Failure fail;
      checkUnary(op, model, rng, fail);
      INFO(op.name << " " << modelName(model) << ": " << fail.count << " outside, first: " << fail.first);
      CHECK(fail.count == 0);
    }
    for (const BinaryOp& op : binaryOps()) {
      Rng rng(202);
      Failure fail;
      checkBinary(op, model, rng, fail);
      INFO(op.name << " " << modelName(model) << ": " << fail.count << " outside, first: " << fail.first);
      CHECK(fail.count == 0);
    }
  }
}

TEST_CASE("Bound: under Conformant a product fed to an add or subtract also holds the fused multiply-add",
          "[lod][bound]") {
  BoundContext ctx(FloatModel::Conformant);
  BoundContext::Scope scope(ctx);
  Rng rng(303);
  Failure fail;
  for (int iter = 0; iter < 3000; ++iter) {
    const Operand x = randomOperand(rng, 1);
    const Operand y = randomOperand(rng, 2);
    const Operand c = randomOperand(rng, 3);
    const Bound p = x.b * y.b;
    const Bound sums[5] = {p + c.b, c.b + p, p - c.b, c.b - p, -p + c.b};
    for (int k = 0; k < 40; ++k) {
      const float sx = x.samples[rng() % x.samples.size()];
      const float sy = y.samples[rng() % y.samples.size()];
      const float sc = c.samples[rng() % c.samples.size()];
      const float want[5][2] = {{std::fma(sx, sy, sc), sx * sy + sc},
                                {std::fma(sx, sy, sc), sc + sx * sy},
                                {std::fma(sx, sy, -sc), sx * sy - sc},
                                {std::fma(-sx, sy, sc), sc - sx * sy},
                                {std::fma(-sx, sy, sc), -(sx * sy) + sc}};
      for (int s = 0; s < 5; ++s) {
        for (float w : want[s]) {
          if (!sums[s].contains(w)) {
            record(fail, "form " + std::to_string(s) + " of " + hex(sx) + ", " + hex(sy) + ", " + hex(sc) + ": " +
                             hex(w) + " not in " + setText(sums[s]));
          }
        }
      }
    }
  }
  INFO(fail.count << " outside, first: " << fail.first);
  REQUIRE(fail.count == 0);
  // A product that rounds: the fused result differs from the unfused one, and both are in the set.
  const Bound third = Bound(1.0f) / Bound(3.0f);
  const Bound three(3.0f);
  const Bound q = three * third;
  const Bound r = q - Bound(1.0f);
  const float t = 1.0f / 3.0f;
  REQUIRE(std::fma(3.0f, t, -1.0f) != 3.0f * t - 1.0f);
  REQUIRE(r.contains(std::fma(3.0f, t, -1.0f)));
  REQUIRE(r.contains(3.0f * t - 1.0f));
}

TEST_CASE("Bound: a comparison the sets decide agrees with every sampled pair", "[lod][bound]") {
  BoundContext ctx(FloatModel::Cpp);
  BoundContext::Scope scope(ctx);
  Rng rng(404);
  Failure fail;
  int decided = 0;
  for (int iter = 0; iter < 3000; ++iter) {
    const Operand a = randomOperand(rng, 1);
    const Operand b = (iter % 4 == 0) ? a : randomOperand(rng, 2);
    const std::function<bool(float, float)> plain[4] = {[](float x, float y) { return x < y; },
                                                        [](float x, float y) { return x <= y; },
                                                        [](float x, float y) { return x == y; },
                                                        [](float x, float y) { return x != y; }};
    for (int op = 0; op < 4; ++op) {
      const int64_t before = ctx.undecidedOutsidePath();
      const bool answer = op == 0 ? a.b < b.b : op == 1 ? a.b <= b.b : op == 2 ? a.b == b.b : a.b != b.b;
      if (ctx.undecidedOutsidePath() != before) continue; // undecided: the context chose
      ++decided;
      for (float x : a.samples) {
        for (float y : b.samples) {
          if (plain[op](x, y) != answer) {
            record(fail, "comparison " + std::to_string(op) + " of " + hex(x) + ", " + hex(y) + " in " +
                             setText(a.b) + ", " + setText(b.b));
          }
        }
      }
    }
  }
  INFO(fail.count << " disagree, first: " << fail.first);
  REQUIRE(fail.count == 0);
  REQUIRE(decided > 1000);
}

TEST_CASE("Bound: a result that may be -0 or +0 is not a point, a zero of known sign is", "[lod][bound]") {
  BoundContext ctx(FloatModel::Cpp);
  BoundContext::Scope scope(ctx);
  const Bound x = Bound::input(-1.0f, 1.0f, 1);
  const Bound zero = x * Bound(0.0f); // -0 for x < 0, +0 for x > 0
  INFO(setText(zero));
  REQUIRE(!zero.point());
  REQUIRE(zero.contains(0.0f));
  REQUIRE(zero.node != Bound(0.0f).node);
  REQUIRE(zero.node != Bound(-0.0f).node);
  const Bound negative = Bound(-1.0f) * Bound(0.0f);
  REQUIRE(negative.point());
  REQUIRE(std::signbit(negative.lo));
}
