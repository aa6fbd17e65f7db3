// Internal (lod/bound.cpp, lod/bound_context.cpp, lod/lod_bound.cpp): the state behind BoundContext, shared by the
// operations (which hash-cons their result nodes and ask for the choices of undecided comparisons) and the context.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

#include "lod/bound.h"

namespace fftess::lod::bound {

// Operation codes of trace nodes. The low byte is the operation; kConformantBit marks an operation evaluated under
// FloatModel::Conformant (a different set of floats than the same operation under Cpp); kFuseA / kFuseB mark an add
// or subtract whose first / second operand is a product a compiler may contract (the operand is then the product's
// node, Bound::product).
enum Op : uint32_t {
  kConst = 1, // a = the float's bits
  kInput,     // a = symbol, b = lo bits, c = hi bits
  kFresh,     // a = a serial number: a set nothing else is known to equal (anything(), untraced operands)
  kAdd,
  kSub,
  kMul,
  kDiv,
  kNeg,
  kSqrt,
  kInverseSqrt,
  kExp2,
  kLog2,
  kPow,
  kAcos,
  kFloor,
  kCeil,
  kAbs,
  kMin,
  kMax,
};
constexpr uint32_t kOpMask = 0xffu;
constexpr uint32_t kConformantBit = 1u << 8;
constexpr uint32_t kFuseA = 1u << 9;
constexpr uint32_t kFuseB = 1u << 10;

// Comparison kinds of the per-run memo (a > b is b < a, a >= b is b <= a, a != b is !(a == b)).
enum Compare : uint32_t { kLess = 1, kLessEqual, kEqual };

struct Node {
  uint32_t op = 0;
  uint32_t a = 0;
  uint32_t b = 0;
  uint32_t c = 0;
};

} // namespace fftess::lod::bound

namespace fftess::lod {

struct BoundContext::Impl {
  FloatModel model = FloatModel::Cpp;
  FloatModel evalModel = FloatModel::Cpp; // the model operations use now (boundCameraRegion evaluates under Cpp)
  int maxPaths = 256;

  // The trace: nodes[id] for id >= 1 (nodes[0] unused); table: open addressing, each slot the node and its id
  // (id 0: empty), load under one half.
  struct Slot {
    bound::Node key;
    uint32_t id;
  };
  std::vector<bound::Node> nodes;
  std::vector<Slot> table;
  // Results by (operation, operand nodes): the same operation on the same nodes gives the same set, so a repeated
  // operation (the next run of forEachPath, the other patch of a pair, the camera's planes) is one lookup.
  struct Result {
    bound::Node key; // op 0: empty
    Bound value;
  };
  std::vector<Result> results;
  size_t resultCount = 0;
  uint32_t freshSerial = 0;

  // forEachPath: the forced prefix of answers, the answers of this run, the memo of this run.
  struct Choice {
    uint32_t kind;
    uint32_t a;
    uint32_t b;
    bool answer;
  };
  std::vector<uint8_t> prefix;
  std::vector<uint8_t> taken;
  std::vector<Choice> memo;
  // What this run's answers imply about a node compared with a constant (a run answers its comparisons
  // consistently: after `x > 8` is answered true, `x > 4` is decided): x is in [lo, hi], or NaN when nan.
  struct Constraint {
    uint32_t node;
    float lo;
    float hi;
    bool nan;
  };
  std::vector<Constraint> constraints;
  bool inPath = false;
  int lastRunChoices = 0;
  int64_t undecidedOutside = 0;

  Impl();
  uint32_t intern(const bound::Node& n) {
    const size_t mask = table.size() - 1;
    for (size_t i = hash(n) & mask;; i = (i + 1) & mask) {
      const Slot& s = table[i];
      if (s.id == 0) return insert(n, i);
      if (s.key.op == n.op && s.key.a == n.a && s.key.b == n.b && s.key.c == n.c) return s.id;
    }
  }
  uint32_t constant(float x) {
    uint32_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    return intern(bound::Node{bound::kConst, bits, 0, 0});
  }
  static size_t hash(const bound::Node& n) {
    uint64_t h = (static_cast<uint64_t>(n.op) << 32 | n.a) * 0x9e3779b97f4a7c15ull;
    h += (static_cast<uint64_t>(n.b) << 32 | n.c) * 0xc2b2ae3d27d4eb4full;
    return static_cast<size_t>(h ^ (h >> 31));
  }
  uint32_t insert(const bound::Node& n, size_t slot);
  const Bound* recall(const bound::Node& k) const {
    const size_t mask = results.size() - 1;
    for (size_t i = hash(k) & mask;; i = (i + 1) & mask) {
      const Result& r = results[i];
      if (r.key.op == 0) return nullptr;
      if (r.key.op == k.op && r.key.a == k.a && r.key.b == k.b && r.key.c == k.c) return &r.value;
    }
  }
  void remember(const bound::Node& k, const Bound& v);
  uint32_t fresh();
  bool choose(uint32_t kind, uint32_t a, uint32_t b);
};

namespace bound {

// The active context's state (null when none).
extern thread_local BoundContext::Impl* tActiveImpl; // lod/bound_context.cpp
inline BoundContext::Impl* activeImpl() { return tActiveImpl; }
// The model operations use now (Cpp when no context is active).
FloatModel activeModel();
// Evaluate under another model for a scope (boundCameraRegion: the camera is built on the CPU, FloatModel::Cpp).
class ModelOverride {
public:
  explicit ModelOverride(FloatModel m);
  ~ModelOverride();
  ModelOverride(const ModelOverride&) = delete;
  ModelOverride& operator=(const ModelOverride&) = delete;

private:
  BoundContext::Impl* impl_;
  FloatModel previous_;
};
// x's node: its own, else (a point made outside a context) the constant of its bits, else 0.
inline uint32_t nodeOf(BoundContext::Impl* c, const Bound& x) {
  if (x.node != 0 || c == nullptr) return x.node;
  return x.point() ? c->constant(x.lo) : 0;
}
// Gives x its node when it is a point made outside a context (for results handed to callers).
void resolveNode(Bound& x);

} // namespace bound
} // namespace fftess::lod
