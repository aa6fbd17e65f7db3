// fftess lod: Bound, a sound set of floats with a trace, for proofs over regions of cameras (verify/prove.h) and for
// the freedom a conformant GPU compiler has (--gpu-float conformant).
//
// A Bound stands for every float an operation can produce, in lod/'s C++ build or on any conformant GPU (FloatModel),
// for every input in its operands' sets: the closed interval [lo, hi] (lo <= hi; -0 and +0 are both in [-0, +0] and
// in any interval that contains 0), plus NaN when `nan` is set, plus -Inf / +Inf when lo / hi are infinite. Every
// operation rounds outward: +, -, *, /, sqrt, floor, ceil, abs, min and max are evaluated in float at the bounds of
// their operands (correctly rounded float arithmetic is monotone, so the float results at the bounds bound every
// float result exactly, and an operation on points gives the C++ build's float: a point); exp2, log2, pow and acos
// are evaluated in double at the bounds and widened by their error bound in float ulps plus one, the last step
// rounded outward to float (std::nextafter); and every result is
// widened by the model's error bound for that operation.
//
// The trace: every Bound carries `node`, the value number of the operation sequence that produced it, kept by the
// active BoundContext. A Bound whose set is one float (point(): lo and hi the same bits, not NaN) has the node of
// that constant (the same bits give the same node, however they were computed); any other result has the node of
// (operation, operand nodes), the same for the same operation on the same operands. Two Bounds with the same node
// hold the same float for every input and every model choice the context made consistently (a deterministic GPU runs
// the same operation sequence on the same inputs to the same bits): that is how a proof knows that both sides of a
// shared edge compute the same factor without knowing its value.
//
// Comparisons (<, <=, >, >=, ==, !=) return bool, as the shader source needs for its `if`s. When the sets decide the
// comparison (every pair of values gives the same answer, NaN's false included) that answer is returned. Otherwise
// the active BoundContext chooses: BoundContext::forEachPath runs the evaluation once per combination of choices,
// and the same comparison on the same nodes gets the same answer within one run (so the two sides of an edge that
// compare the same traced value against the same constant branch alike). No comparison narrows its operands.
//
// Within a run, an answer about a node compared with a constant also constrains that node for the rest of the run
// (after `x > 8` is answered true, `x > 4` is decided true), so infeasible combinations are not enumerated.
//
// The context remembers each operation's result by (operation, operand nodes): a repeated operation (the next run,
// the other patch of a pair) is one lookup. The trace and these results grow until clearTrace.
//
// lod/lod_bound.h compiles the shaders (lod/shaders/*.glsl) with Bound as their float: the same source as the float
// build, the same order of operations. Not thread-safe per context: one BoundContext per thread (it is made active
// for the calling thread by forEachPath or BoundContext::Scope). forEachPath is not reentrant (no forEachPath inside
// a run of the same context).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace fftess::lod {

// Which implementations of the shader's float operations a Bound covers (docs/verify.md, "Proofs").
enum class FloatModel : uint8_t {
  // lod/'s C++ build (-ffp-contract=off, SSE float): +, -, *, /, sqrt correctly rounded (IEEE binary32, round to
  // nearest even), no FMA, denormals kept; exp2, log2, pow, acos within 2 ulp (glibc's float functions are within 1);
  // inversesqrt as GLM's 1 / sqrt(x) (two correctly rounded operations).
  Cpp,
  // Any GLSL 4.50 implementation (GLSL 4.50, section 4.7.1): Cpp's results, and also: a * b + c (an add or subtract
  // whose operand is a product) contracted into one fused operation or not; division within 2.5 ulp; inversesqrt
  // within 2 ulp; sqrt as 1.0 / inversesqrt (so within 2.5 ulp of 2 ulp); exp2 within 3 + 2|x| ulp; log2 within 3
  // ulp outside [0.5, 2] and within 2^-21 absolute inside it; pow as exp2(y * log2(x)); acos as the spec leaves it
  // (inherited from atan: within 4096 ulp, stated in docs/verify.md); any denormal result flushed to 0 (of either
  // sign) or not; a denormal operand read as 0 or not.
  Conformant,
};

// Bound() leaves the members uninitialised, as float does (GLM's vectors keep their components in unions, which
// need a trivial default constructor); Bound{} is the point +0, untraced (node 0).
struct Bound {
  float lo;
  float hi;
  bool nan;
  uint32_t node; // the trace's value number (0: not traced: made outside a BoundContext)
  // FloatModel::Conformant only: when this Bound is the result of a multiplication (or its negation), the node of
  // that product (operation and operand nodes, even when the result is a point and `node` is a constant), so that
  // an add or subtract it feeds knows it may be contracted into an FMA; 0 otherwise.
  uint32_t product;

  Bound() = default;
  // A constant: the point {x} (NaN: the NaN-only set), traced as the constant of x's bits. Implicit: the shaders'
  // float literals and GLM's T(0), T(1) become constants.
  Bound(float x); // NOLINT(google-explicit-constructor)
  Bound(double x) = delete; // a double literal in the shader source is a bug: every float literal has an f suffix
  Bound(int x);   // NOLINT: GLM's static_cast<T>(0) / T(1)

  // An input in [lo, hi] (lo <= hi, not NaN), traced as input symbol `symbol` (a camera coordinate of a region: the
  // same symbol for the same quantity on both sides of an edge). A point input (lo == hi) is the constant instead.
  static Bound input(float lo, float hi, uint32_t symbol);
  // The set of every float (NaN included): what an operation the model cannot bound returns.
  static Bound anything();

  // One float, not NaN, with lo and hi the same bits.
  bool point() const;
  // Every value is finite (no NaN, no infinity).
  bool finite() const;
  bool contains(float x) const; // x in the set (NaN: nan; -0 and +0 alike)
  // The set holds at least one number (not only NaN). The NaN-only set is lo = +Inf, hi = -Inf, nan.
  bool hasValues() const { return lo <= hi; }
};

Bound operator+(const Bound& a, const Bound& b);
Bound operator-(const Bound& a, const Bound& b);
Bound operator*(const Bound& a, const Bound& b);
Bound operator/(const Bound& a, const Bound& b);
Bound operator-(const Bound& a);
Bound& operator+=(Bound& a, const Bound& b);
Bound& operator-=(Bound& a, const Bound& b);
Bound& operator*=(Bound& a, const Bound& b);
Bound& operator/=(Bound& a, const Bound& b);

bool operator<(const Bound& a, const Bound& b);
bool operator<=(const Bound& a, const Bound& b);
bool operator>(const Bound& a, const Bound& b);
bool operator>=(const Bound& a, const Bound& b);
bool operator==(const Bound& a, const Bound& b);
bool operator!=(const Bound& a, const Bound& b);

// The GLSL built-ins the shaders use, with GLSL's semantics (min/max: NaN behaviour as GLM's, i.e. std::min/max of
// the float build: min(a, b) = b < a ? b : a; floor/ceil exact; abs exact).
Bound sqrt(const Bound& x);
Bound inversesqrt(const Bound& x);
Bound exp2(const Bound& x);
Bound log2(const Bound& x);
Bound pow(const Bound& x, const Bound& y);
Bound acos(const Bound& x);
Bound floor(const Bound& x);
Bound ceil(const Bound& x);
Bound abs(const Bound& x);
Bound min(const Bound& a, const Bound& b);
Bound max(const Bound& a, const Bound& b);

// The evaluation state of one thread: the model, the trace and the choices of undecided comparisons.
class BoundContext {
public:
  // maxPaths: forEachPath gives up (returns false) after this many runs.
  explicit BoundContext(FloatModel model, int maxPaths = 256);
  ~BoundContext();
  BoundContext(const BoundContext&) = delete;
  BoundContext& operator=(const BoundContext&) = delete;

  FloatModel model() const;

  // Runs run() once per combination of answers to the comparisons its Bounds leave undecided (depth first: the
  // first run answers every undecided comparison true, the next flips the last such answer, ...), this context
  // active on the calling thread. Within one run, the same comparison (operator, operand nodes) gets the same answer.
  // Values computed in earlier runs stay valid (the trace is kept until clearTrace). True when every combination
  // ran; false when maxPaths was reached first (the runs made so far cover only part of the inputs).
  bool forEachPath(const std::function<void()>& run);
  // Undecided comparisons answered in the current run (0 when the run's Bounds decided every comparison).
  int choicesInRun() const;

  // Makes this context active on the calling thread for a scope (for evaluations outside forEachPath: an undecided
  // comparison there answers true and counts in undecidedOutsidePath()).
  class Scope {
  public:
    explicit Scope(BoundContext& c);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

  private:
    BoundContext* previous_;
  };
  int64_t undecidedOutsidePath() const;

  // The trace: the operation of a node in words, depth levels deep ("add(mul(input 3, 0x3f000000), ...)"; constants
  // as their float value and bits), for findings that say which operation two sides disagree on.
  std::string describe(uint32_t node, int depth = 3) const;
  // The first node, walking both traces from their roots in step, where a's and b's operations or operands differ
  // (0 when a == b): describe() it on each side to name the operation that differs.
  uint32_t firstDifference(uint32_t a, uint32_t b, uint32_t* otherSide) const;
  // Forgets every node (the next nodes number from 1 again); nodes kept from before are meaningless afterwards.
  void clearTrace();
  size_t traceSize() const;

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

// The context active on the calling thread (null when none).
BoundContext* activeBoundContext();

// The float ulp of x (the gap to the next float away from zero; 2^-149 for 0 and denormals; +Inf for infinities).
float ulpOf(float x);

} // namespace fftess::lod
