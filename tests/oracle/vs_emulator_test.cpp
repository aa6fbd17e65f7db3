// The independent oracle: a sweep of uniform factors 0..66 in steps of 1/8 for every domain and partitioning, then
// seeded random hardware-stage patches (every domain, partitioning and topology; factors
// rich in special values) tessellated by Mesa's llvmpipe (Microsoft's reference inside) and by fftess, compared
// bit for bit: point arrays, primitives as coordinates, index arrays (docs/oracle.md). fftess runs with
// flushDenormals = true, which is what llvmpipe does to denormal factors.
//
//   test_oracle_vs_emulator [PATCHES [SEED]]
//   environment: FFTESS_ORACLE_PATCHES, FFTESS_ORACLE_SEED override the defaults (30000 patches, seed 20261122).
//
// A failure lists each differing patch as a batch line, to reproduce with
//   echo 'LINE' | fftess_gl_oracle      and      echo 'LINE' | fftess tessellate --batch - --format hex
#include "random_patches.h"
#include "oracle_test_util.h"

#include "tessellator/tessellator.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

using namespace fftess::oracle;
using fftess::bitsOf;
using fftess::floatOf;

namespace {

fftess::Patch toEmulator(const Patch& p) {
  fftess::Patch e;
  e.domain = p.domain == Domain::Quad ? fftess::Domain::Quad
             : p.domain == Domain::Tri ? fftess::Domain::Tri
                                       : fftess::Domain::Isoline;
  switch (p.partitioning) {
  case Partitioning::Integer: e.partitioning = fftess::Partitioning::Integer; break;
  case Partitioning::Pow2: e.partitioning = fftess::Partitioning::Pow2; break;
  case Partitioning::FractionalOdd: e.partitioning = fftess::Partitioning::FractionalOdd; break;
  case Partitioning::FractionalEven: e.partitioning = fftess::Partitioning::FractionalEven; break;
  }
  switch (p.topology) {
  case Topology::Point: e.primitive = fftess::OutputPrimitive::Point; break;
  case Topology::Line: e.primitive = fftess::OutputPrimitive::Line; break;
  case Topology::TriangleCw: e.primitive = fftess::OutputPrimitive::TriangleCw; break;
  case Topology::TriangleCcw: e.primitive = fftess::OutputPrimitive::TriangleCcw; break;
  }
  e.stage = fftess::Stage{}; // hw
  for (int i = 0; i < 6; ++i) e.factors[i] = floatOf(p.factorBits[i]);
  return e;
}

long envOr(const char* name, long fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtol(v, nullptr, 0) : fallback;
}

} // namespace

int main(int argc, char** argv) {
  const char* name = "oracle_vs_emulator";
  const long total = argc > 1 ? std::strtol(argv[1], nullptr, 0) : envOr("FFTESS_ORACLE_PATCHES", 30000);
  const uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 0)
                                 : static_cast<uint64_t>(envOr("FFTESS_ORACLE_SEED", 20261122));
  auto oracle = createOracleOrExit(name);
  std::printf("%s: %ld patches, seed %llu\n", name, total, static_cast<unsigned long long>(seed));

  Rng rng{seed};
  fftess::Tessellator tess;
  fftess::Options options;
  options.flushDenormals = true; // llvmpipe flushes denormal factors to zero
  constexpr long kChunk = 500;   // patches per oracle run (bounds the memory of captured results)
  double glSeconds = 0, emuSeconds = 0;
  long compared = 0, agree = 0, culled = 0, withPrimitives = 0, duplicates = 0, denormal = 0, printed = 0;
  long long points = 0, primitives = 0;
  std::map<std::string, std::pair<long, long>> perMode; // "domain partitioning" -> (patches, failures)
  std::vector<Patch> patches;
  std::vector<Result> results;
  // First a systematic sweep: every domain and partitioning with all factors equal to k/8, k = 0..528 (0..66),
  // topologies taken in turn; then the random patches (random_patches.h, shared with nvidia/nvidia_compare.cpp).
  const std::vector<Patch> sweep = sweepPatches();
  const long sweepCount = static_cast<long>(sweep.size());
  for (long done = 0; done < sweepCount + total; done += kChunk) {
    patches.clear();
    for (long i = done; i < sweepCount + total && i < done + kChunk; ++i)
      patches.push_back(i < sweepCount ? sweep[static_cast<size_t>(i)] : randomPatch(rng));
    std::string error;
    const auto t0 = std::chrono::steady_clock::now();
    if (!oracle->run(patches, results, error)) {
      std::fprintf(stderr, "%s: the GL oracle failed: %s\n", name, error.c_str());
      return 1;
    }
    const auto t1 = std::chrono::steady_clock::now();
    glSeconds += std::chrono::duration<double>(t1 - t0).count();
    for (size_t i = 0; i < patches.size(); ++i) {
      const auto e0 = std::chrono::steady_clock::now();
      tess.tessellate(toEmulator(patches[i]), options);
      Expected want;
      want.points.reserve(tess.points().size() * 2);
      for (const fftess::DomainPoint& pt : tess.points()) {
        want.points.push_back(bitsOf(pt.u));
        want.points.push_back(bitsOf(pt.v));
      }
      want.indices = tess.indices();
      emuSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - e0).count();
      const Verdict v = compare(patches[i], results[i], want);
      ++compared;
      points += results[i].pointCount();
      primitives += static_cast<long long>(results[i].primitives.size() / 2 / static_cast<size_t>(results[i].verticesPerPrimitive));
      culled += results[i].pointCount() == 0;
      if (hasGlPrimitives(patches[i]) && results[i].pointCount() > 0) {
        ++withPrimitives;
        duplicates += hasDuplicatePoints(results[i]);
      }
      denormal += hasDenormalFactor(patches[i]);
      auto& mode = perMode[std::string(toString(patches[i].domain)) + " " + toString(patches[i].partitioning)];
      ++mode.first;
      if (v.all()) {
        ++agree;
        continue;
      }
      ++mode.second;
      if (printed++ < 20)
        std::printf("DIFFERS (%s %ld): %s\n  %s\n", done + static_cast<long>(i) < sweepCount ? "sweep" : "random",
                    done + static_cast<long>(i) - (done + static_cast<long>(i) < sweepCount ? 0 : sweepCount),
                    batchLine(patches[i]).c_str(),
                    v.firstDifference.c_str());
    }
  }
  std::printf("%-24s %8s %8s\n", "mode", "patches", "differ");
  for (const auto& kv : perMode) std::printf("%-24s %8ld %8ld\n", kv.first.c_str(), kv.second.first, kv.second.second);
  std::printf("%s: %ld patches compared (%ld sweep + %ld random; %ld culled, %ld with GL primitives of which %ld with duplicate points, %ld "
              "with a denormal factor), %lld points, %lld primitives; %ld agree bit for bit, %ld differ. "
              "llvmpipe %.2f s, fftess %.3f s\n",
              name, compared, sweepCount, total, culled, withPrimitives, duplicates, denormal, points, primitives, agree, compared - agree,
              glSeconds, emuSeconds);
  return agree == compared ? 0 : 1;
}
