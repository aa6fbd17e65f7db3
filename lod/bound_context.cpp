// fftess lod: BoundContext (lod/bound.h): the trace (hash-consed nodes), the choices of undecided comparisons
// (forEachPath), the active context of each thread.
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "lod/bound.h"
#include "lod/bound_internal.h"

namespace fftess::lod {

namespace {

thread_local BoundContext* tActive = nullptr;


float bitsFloat(uint32_t u) {
  float x;
  std::memcpy(&x, &u, sizeof x);
  return x;
}

// Operands of a node that are nodes themselves (constants, inputs and fresh nodes have none).
int operandCount(const bound::Node& n) {
  switch (n.op & bound::kOpMask) {
  case bound::kConst:
  case bound::kInput:
  case bound::kFresh:
    return 0;
  case bound::kAdd:
  case bound::kSub:
  case bound::kMul:
  case bound::kDiv:
  case bound::kPow:
  case bound::kMin:
  case bound::kMax:
    return 2;
  default:
    return 1;
  }
}

const char* opName(uint32_t op) {
  static const char* const kNames[] = {"?",   "const", "input", "fresh", "add",  "sub",   "mul",  "div", "neg", "sqrt",
                                       "inversesqrt", "exp2", "log2", "pow", "acos", "floor", "ceil", "abs", "min",
                                       "max"};
  const uint32_t o = op & bound::kOpMask;
  return o < sizeof(kNames) / sizeof(kNames[0]) ? kNames[o] : "?";
}

} // namespace

BoundContext::Impl::Impl() {
  nodes.resize(1);
  table.assign(1024, Slot{});
  results.assign(1024, Result{});
}

uint32_t BoundContext::Impl::insert(const bound::Node& n, size_t slot) {
  const uint32_t id = static_cast<uint32_t>(nodes.size());
  nodes.push_back(n);
  table[slot] = Slot{n, id};
  if (nodes.size() * 2 > table.size()) { // keep the load under one half
    table.assign(table.size() * 2, Slot{});
    const size_t mask = table.size() - 1;
    for (uint32_t k = 1; k < nodes.size(); ++k) {
      size_t j = hash(nodes[k]) & mask;
      while (table[j].id != 0) j = (j + 1) & mask;
      table[j] = Slot{nodes[k], k};
    }
  }
  return id;
}

void BoundContext::Impl::remember(const bound::Node& k, const Bound& v) {
  if ((resultCount + 1) * 2 > results.size()) { // keep the load under one half
    std::vector<Result> old(results.size() * 2, Result{});
    old.swap(results);
    const size_t mask = results.size() - 1;
    for (const Result& r : old) {
      if (r.key.op == 0) continue;
      size_t j = hash(r.key) & mask;
      while (results[j].key.op != 0) j = (j + 1) & mask;
      results[j] = r;
    }
  }
  const size_t mask = results.size() - 1;
  size_t i = hash(k) & mask;
  while (results[i].key.op != 0) {
    if (results[i].key.op == k.op && results[i].key.a == k.a && results[i].key.b == k.b && results[i].key.c == k.c) {
      return;
    }
    i = (i + 1) & mask;
  }
  results[i] = Result{k, v};
  ++resultCount;
}

uint32_t BoundContext::Impl::fresh() { return intern(bound::Node{bound::kFresh, ++freshSerial, 0, 0}); }

bool BoundContext::Impl::choose(uint32_t kind, uint32_t a, uint32_t b) {
  if (!inPath) {
    ++undecidedOutside;
    return true;
  }
  const bool traced = a != 0 && b != 0; // an untraced operand: a choice of its own every time
  if (traced) {
    for (const Choice& c : memo) {
      if (c.kind == kind && c.a == a && c.b == b) return c.answer;
    }
  }
  const size_t index = taken.size();
  const bool answer = index < prefix.size() ? prefix[index] != 0 : true;
  taken.push_back(answer ? 1 : 0);
  if (traced) memo.push_back(Choice{kind, a, b, answer});
  return answer;
}

namespace bound {

thread_local BoundContext::Impl* tActiveImpl = nullptr;

FloatModel activeModel() {
  BoundContext::Impl* c = activeImpl();
  return c ? c->evalModel : FloatModel::Cpp;
}

ModelOverride::ModelOverride(FloatModel m) : impl_(activeImpl()), previous_(FloatModel::Cpp) {
  if (impl_) {
    previous_ = impl_->evalModel;
    impl_->evalModel = m;
  }
}

ModelOverride::~ModelOverride() {
  if (impl_) impl_->evalModel = previous_;
}

void resolveNode(Bound& x) { x.node = nodeOf(activeImpl(), x); }

} // namespace bound

BoundContext::BoundContext(FloatModel model, int maxPaths) : impl_(std::make_unique<Impl>()) {
  impl_->model = model;
  impl_->evalModel = model;
  impl_->maxPaths = maxPaths;
}

BoundContext::~BoundContext() {
  if (tActive == this) {
    tActive = nullptr;
    bound::tActiveImpl = nullptr;
  }
}

FloatModel BoundContext::model() const { return impl_->model; }

bool BoundContext::forEachPath(const std::function<void()>& run) {
  Impl& s = *impl_;
  s.prefix.clear();
  for (int runs = 0;; ++runs) {
    if (runs >= s.maxPaths) return false;
    s.taken.clear();
    s.memo.clear();
    s.constraints.clear();
    {
      Scope scope(*this);
      s.inPath = true;
      struct Leave {
        Impl& s;
        ~Leave() { s.inPath = false; }
      } leave{s};
      run();
    }
    s.lastRunChoices = static_cast<int>(s.taken.size());
    // The next combination, depth first: drop the trailing false answers, flip the last true one.
    while (!s.taken.empty() && s.taken.back() == 0) s.taken.pop_back();
    if (s.taken.empty()) return true;
    s.taken.back() = 0;
    s.prefix = s.taken;
  }
}

int BoundContext::choicesInRun() const {
  return impl_->inPath ? static_cast<int>(impl_->taken.size()) : impl_->lastRunChoices;
}

BoundContext::Scope::Scope(BoundContext& c) : previous_(tActive) {
  tActive = &c;
  bound::tActiveImpl = c.impl_.get();
}
BoundContext::Scope::~Scope() {
  tActive = previous_;
  bound::tActiveImpl = previous_ ? previous_->impl_.get() : nullptr;
}

int64_t BoundContext::undecidedOutsidePath() const { return impl_->undecidedOutside; }

std::string BoundContext::describe(uint32_t node, int depth) const {
  const Impl& s = *impl_;
  if (node == 0 || node >= s.nodes.size()) return "untraced";
  const bound::Node& n = s.nodes[node];
  char buf[96];
  switch (n.op & bound::kOpMask) {
  case bound::kConst:
    std::snprintf(buf, sizeof buf, "%.9g (0x%08" PRIx32 ")", static_cast<double>(bitsFloat(n.a)), n.a);
    return buf;
  case bound::kInput:
    std::snprintf(buf, sizeof buf, "input %" PRIu32 " [%.9g, %.9g]", n.a, static_cast<double>(bitsFloat(n.b)),
                  static_cast<double>(bitsFloat(n.c)));
    return buf;
  case bound::kFresh:
    return "unknown #" + std::to_string(n.a);
  default:
    break;
  }
  std::string out = opName(n.op);
  if (n.op & bound::kConformantBit) out += (n.op & (bound::kFuseA | bound::kFuseB)) ? "~fma" : "~gpu";
  if (depth <= 0) return out + "(...)";
  out += "(";
  out += describe(n.a, depth - 1);
  if (operandCount(n) == 2) out += ", " + describe(n.b, depth - 1);
  return out + ")";
}

uint32_t BoundContext::firstDifference(uint32_t a, uint32_t b, uint32_t* otherSide) const {
  const Impl& s = *impl_;
  if (otherSide) *otherSide = 0;
  if (a == b) return 0;
  // Descend while both sides are the same operation and exactly one operand differs.
  while (a < s.nodes.size() && b < s.nodes.size() && a != 0 && b != 0) {
    const bound::Node& x = s.nodes[a];
    const bound::Node& y = s.nodes[b];
    if (x.op != y.op || operandCount(x) == 0) break;
    const bool firstDiffers = x.a != y.a;
    const bool secondDiffers = operandCount(x) == 2 && x.b != y.b;
    if (firstDiffers == secondDiffers) break;
    a = firstDiffers ? x.a : x.b;
    b = firstDiffers ? y.a : y.b;
  }
  if (otherSide) *otherSide = b;
  return a;
}

void BoundContext::clearTrace() {
  // Back to the first tables' size: clearing a large table costs more than growing a small one again.
  impl_->nodes.resize(1);
  impl_->table.assign(1024, Impl::Slot{});
  impl_->freshSerial = 0;
  impl_->results.assign(1024, Impl::Result{});
  impl_->resultCount = 0;
}

size_t BoundContext::traceSize() const { return impl_->nodes.size() - 1; }

BoundContext* activeBoundContext() { return tActive; }

} // namespace fftess::lod
