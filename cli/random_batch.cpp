// The patches of `fftess gen` and `driver-check --random` (random_batch.h).
#include "random_batch.h"

#include "tessellator/batch.h"
#include "gl/random_patches.h"

#include <cstring>

namespace fftess::cli {

Patch fromOracle(const oracle::Patch& g) {
  Patch p;
  p.domain = static_cast<Domain>(static_cast<uint8_t>(g.domain));
  p.partitioning = static_cast<Partitioning>(static_cast<uint8_t>(g.partitioning));
  p.primitive = static_cast<OutputPrimitive>(static_cast<uint8_t>(g.topology));
  std::memcpy(p.factors, g.factorBits, sizeof p.factors);
  return p;
}

oracle::Patch toOracle(const Patch& p) {
  oracle::Patch g;
  g.domain = static_cast<oracle::Domain>(static_cast<uint8_t>(p.domain));
  g.partitioning = static_cast<oracle::Partitioning>(static_cast<uint8_t>(p.partitioning));
  g.topology = static_cast<oracle::Topology>(static_cast<uint8_t>(p.primitive));
  std::memcpy(g.factorBits, p.factors, sizeof g.factorBits);
  return g;
}

std::string genCommand(const GenSpec& spec) {
  return "fftess gen --random " + std::to_string(spec.random) + " --seed " + std::to_string(spec.seed) +
         (spec.sweep ? " --sweep" : "");
}

std::string genHeader(const GenSpec& spec) { return "# " + genCommand(spec) + "\n"; }

int genLineOf(int64_t index) { return static_cast<int>(index + 2); }

void forEachGenPatch(const GenSpec& spec, const std::function<void(int64_t, const Patch&)>& emit) {
  int64_t index = 0;
  if (spec.sweep)
    for (const oracle::Patch& g : oracle::sweepPatches()) emit(index++, fromOracle(g));
  oracle::Rng rng{spec.seed};
  for (long i = 0; i < spec.random; ++i) emit(index++, fromOracle(oracle::randomPatch(rng)));
}

namespace {
constexpr size_t kFlushBytes = size_t(1) << 20;
} // namespace

void BatchFileWriter::text(const std::string& s) {
  pending_ += s;
  if (pending_.size() >= kFlushBytes) file_.stream(pending_), pending_.clear();
}

void BatchFileWriter::add(const Patch& p) { text(formatBatchLine(p) + '\n'); }

void BatchFileWriter::commit() {
  file_.stream(pending_);
  pending_.clear();
  file_.commit();
  if (file_.path() == "-") flushStdout();
}

} // namespace fftess::cli
