// The differential test's cases (tests/tessellator/differential_test.cpp) and the hash of their outputs: the same
// seeded patches the test once ran through the kernels before issue 11 (tests/tessellator/legacy, now deleted), cut
// into chunks, one line of data/differential.hashes per chunk.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/bits.h"
#include "factor_samples.h"
#include "tessellator/names.h"
#include "tessellator/tessellator.h"

namespace fftess {
namespace testing {

// One patch of a chunk, with the options it is tessellated with.
struct DifferentialCase {
  Patch patch;
  Options options;
};

// A line of data/differential.hashes: its name (no spaces) and its patches, in order.
struct DifferentialChunk {
  std::string name;
  std::vector<DifferentialCase> cases;
};

// FNV-1a 64 over 32-bit words (h ^= word; h *= 0x100000001b3, mod 2^64; basis 0xcbf29ce484222325), one patch after
// the other: its point count as tessellate returned it, points().size(), indices().size(), then u and v bits of each
// point in order, then each index in order.
struct OutputHash {
  uint64_t h = 0xcbf29ce484222325ull;
  void word(uint32_t w) { h = (h ^ w) * 0x100000001b3ull; }
  void patch(int n, const std::vector<DomainPoint>& points, const std::vector<int32_t>& indices) {
    word(static_cast<uint32_t>(n));
    word(static_cast<uint32_t>(points.size()));
    word(static_cast<uint32_t>(indices.size()));
    for (const DomainPoint& p : points) word(bitsOf(p.u)), word(bitsOf(p.v));
    for (int32_t i : indices) word(static_cast<uint32_t>(i));
  }
};

constexpr int kDifferentialChunk = 500; // patches per line of random draws

// count seeded random patches (testing::FactorDraw(seed)) with special values, or with plain factors 0..66 in steps
// of 1/8 and arbitrary fractions (uniformFactors, from a second generator seeded seed ^ 0x9e3779b9), flushDenormals
// in 1 of 8; chunks named random-SEED-FIRST or plain-SEED-FIRST (FIRST = the chunk's first draw).
inline std::vector<DifferentialChunk> randomChunks(uint32_t seed, int count, bool uniformFactors) {
  FactorDraw draw(seed);
  FactorDraw uniform(seed ^ 0x9e3779b9u);
  std::vector<DifferentialChunk> chunks;
  for (int i = 0; i < count; ++i) {
    if (i % kDifferentialChunk == 0)
      chunks.push_back({std::string(uniformFactors ? "plain-" : "random-") + std::to_string(seed) + "-" +
                            std::to_string(i),
                        {}});
    DifferentialCase c;
    c.patch = draw.patch();
    if (uniformFactors)
      for (float& f : c.patch.factors)
        f = (uniform.rng.next() & 1) ? float(uniform.rng.next() % 529) / 8.0f : float(uniform.rng.next() % 66000000) / 1e6f;
    c.options.flushDenormals = (draw.rng.next() & 7) == 0;
    chunks.back().cases.push_back(c);
  }
  return chunks;
}

// Every equal-factor patch k/16, k = 0..66*16, of each domain, partitioning and topology (isoline: point and line);
// one chunk per domain, partitioning and topology, named equal-DOMAIN-PARTITIONING-TOPOLOGY.
inline std::vector<DifferentialChunk> equalFactorChunks() {
  std::vector<DifferentialChunk> chunks;
  for (Domain d : {Domain::Quad, Domain::Tri, Domain::Isoline})
    for (int part = 0; part < 4; ++part)
      for (int prim = 0; prim < 4; ++prim) {
        if (d == Domain::Isoline && prim > 1) continue;
        Patch p;
        p.domain = d;
        p.partitioning = Partitioning(part);
        p.primitive = OutputPrimitive(prim);
        DifferentialChunk chunk{std::string("equal-") + toString(d) + "-" + toString(p.partitioning) + "-" +
                                    toString(p.primitive),
                                {}};
        for (int k = 0; k <= 66 * 16; ++k) {
          for (float& f : p.factors) f = float(k) / 16.0f;
          chunk.cases.push_back({p, Options{}});
        }
        chunks.push_back(chunk);
      }
  return chunks;
}

// The four groups of the test, in file order: special values (seeds 1-4), plain factors (11-14), equal factors, and
// the portable loops' draws (seeds 5 and 15).
inline std::vector<DifferentialChunk> specialValueChunks() {
  std::vector<DifferentialChunk> all;
  for (uint32_t seed : {1u, 2u, 3u, 4u})
    for (DifferentialChunk& c : randomChunks(seed, 50000, false)) all.push_back(std::move(c));
  return all;
}
inline std::vector<DifferentialChunk> plainFactorChunks() {
  std::vector<DifferentialChunk> all;
  for (uint32_t seed : {11u, 12u, 13u, 14u})
    for (DifferentialChunk& c : randomChunks(seed, 50000, true)) all.push_back(std::move(c));
  return all;
}
inline std::vector<DifferentialChunk> portableChunks() {
  std::vector<DifferentialChunk> all = randomChunks(5u, 50000, false);
  for (DifferentialChunk& c : randomChunks(15u, 50000, true)) all.push_back(std::move(c));
  return all;
}

} // namespace testing
} // namespace fftess
