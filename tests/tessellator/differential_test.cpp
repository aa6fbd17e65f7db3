// Differential test: the table kernels (issue 11) against the path they replaced, which was bit-exact with
// Microsoft's reference on all golden data. That path is kept as data: data/differential.hashes holds, for each chunk
// of differential_cases.h, the hash of its outputs (OutputHash), produced once from the old kernels before they were
// deleted. Many seeded random patches of every domain, partitioning, topology and stage, with special values (NaN,
// +-Inf, +-0, denormals, negatives, > 64, one 16.16 step around integers), through one reused Tessellator (buffers
// grow and shrink between patches).
#include <catch2/catch.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "differential_cases.h"
#include "tessellator/simd.h"
#include "tessellator/tessellator.h"

using namespace fftess;

namespace {

// NAME -> HASH of data/differential.hashes ('#' lines are comments).
std::map<std::string, uint64_t> readHashes() {
  const std::string path = std::string(FFTESS_TESSELLATOR_TEST_DATA) + "/differential.hashes";
  std::ifstream in(path);
  INFO("data file " << path);
  REQUIRE(in.good());
  std::map<std::string, uint64_t> hashes;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream words(line);
    std::string name, hex;
    INFO(path << ":" << n << ": " << line);
    REQUIRE(bool(words >> name >> hex));
    REQUIRE(hex.size() == 16);
    hashes[name] = std::stoull(hex, nullptr, 16);
  }
  return hashes;
}

// Every chunk's outputs hash to the file's value for its name; at most five differing chunks are named.
void checkChunks(const std::vector<testing::DifferentialChunk>& chunks) {
  static const std::map<std::string, uint64_t> expected = readHashes();
  Tessellator t;
  int mismatches = 0;
  for (const testing::DifferentialChunk& chunk : chunks) {
    const auto want = expected.find(chunk.name);
    INFO("chunk " << chunk.name << " (" << chunk.cases.size() << " patches)");
    REQUIRE(want != expected.end());
    testing::OutputHash hash;
    for (const testing::DifferentialCase& c : chunk.cases) {
      const int n = t.tessellate(c.patch, c.options);
      hash.patch(n, t.points(), t.indices());
    }
    if (hash.h != want->second && ++mismatches <= 5) FAIL_CHECK("differs from the old path");
  }
  CHECK(mismatches == 0);
}

} // namespace

TEST_CASE("table kernels equal the old path on random patches with special values", "[tessellator][differential]") {
  checkChunks(testing::specialValueChunks());
}

TEST_CASE("table kernels equal the old path on random plain factors", "[tessellator][differential]") {
  checkChunks(testing::plainFactorChunks());
}

TEST_CASE("table kernels equal the old path on every equal-factor quad and tri", "[tessellator][differential]") {
  checkChunks(testing::equalFactorChunks());
}

TEST_CASE("portable loops equal the old path too (the AVX2 kernels are chosen at run time)",
          "[tessellator][differential]") {
  fftess::simd::forcePortable(true);
  checkChunks(testing::portableChunks());
  fftess::simd::forcePortable(false);
}
