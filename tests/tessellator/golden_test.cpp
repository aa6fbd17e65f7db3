// Golden data: every patch of ../shared/golden (reference outputs of Microsoft's D3D11 tessellator), compared
// byte for byte (full outputs) or by FNV-1a 64 hash of the exact output block.
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tessellator/batch.h"
#include "tessellator/tessellator.h"
#include "invariants.h"

using namespace fftess;

namespace {

std::string goldenPath(const std::string& name) { return std::string(FFTESS_GOLDEN_DIR) + "/" + name; }

std::vector<std::string> readLines(const std::string& path) {
  std::ifstream in(path);
  INFO("golden file " << path);
  REQUIRE(in.good()); // a missing golden folder is a failure, in CI and everywhere
  std::vector<std::string> lines;
  std::string l;
  while (std::getline(in, l)) lines.push_back(l);
  return lines;
}

// Splits a .out file into blocks, one per patch, each with its trailing newline.
std::vector<std::string> readBlocks(const std::string& path) {
  std::vector<std::string> blocks;
  for (const std::string& l : readLines(path)) {
    if (l.rfind("patch ", 0) == 0) blocks.emplace_back();
    REQUIRE(!blocks.empty());
    blocks.back() += l + "\n";
  }
  return blocks;
}

std::string firstDifference(const std::string& a, const std::string& b) {
  std::istringstream sa(a), sb(b);
  std::string la, lb;
  for (int line = 1;; ++line) {
    const bool ga = bool(std::getline(sa, la)), gb = bool(std::getline(sb, lb));
    if (!ga && !gb) return "identical";
    if (la != lb || ga != gb)
      return "line " + std::to_string(line) + ": ours '" + (ga ? la : "<end>") + "' reference '" +
             (gb ? lb : "<end>") + "'";
  }
}

void compareFull(const std::string& stem) {
  const std::vector<std::string> in = readLines(goldenPath(stem + ".in"));
  const std::vector<std::string> expected = readBlocks(goldenPath(stem + ".out"));
  Tessellator t;
  int n = 0, mismatches = 0;
  for (const std::string& line : in) {
    if (isBatchSkippable(line)) continue;
    Patch p;
    BatchError err;
    INFO(stem << ".in patch " << n << ": " << line);
    REQUIRE(parseBatchLine(line, p, err));
    REQUIRE(size_t(n) < expected.size());
    t.tessellate(p);
    std::string ours;
    appendHexBlock(ours, n, p, t);
    if (ours != expected[size_t(n)]) {
      ++mismatches;
      if (mismatches <= 5) FAIL_CHECK(firstDifference(ours, expected[size_t(n)]));
    }
    ++n;
  }
  INFO(stem << ": " << n << " patches");
  CHECK(n > 0); // an empty .in/.out pair compares nothing
  CHECK(size_t(n) == expected.size());
  CHECK(mismatches == 0);
}

// The hash files' patches (63,396 of them): each output block's FNV-1a 64 is compared with the file's (golden/README.md,
// regenerated with the standard basis 0xcbf29ce484222325 on 2026-11-28), and every patch also goes through the output
// invariants.
void checkHashFileInvariants(const std::string& file) {
  const std::vector<std::string> lines = readLines(goldenPath(file));
  Tessellator t, tw;
  int n = 0, tessellated = 0;
  for (const std::string& line : lines) {
    if (isBatchSkippable(line)) continue;
    const std::string batch = line.substr(0, line.find_last_of(' '));
    Patch p;
    BatchError err;
    INFO(file << " patch " << n << ": " << batch);
    REQUIRE(parseBatchLine(batch, p, err));
    t.tessellate(p);
    if (testing::checkInvariants(p, Options{}, t, tw)) ++tessellated;
    ++n;
  }
  INFO(file);
  CHECK(n > 0);
  CHECK(tessellated > 0);
}

void compareHashes(const std::string& file) {
  const std::vector<std::string> lines = readLines(goldenPath(file));
  Tessellator t;
  int n = 0, mismatches = 0;
  std::string block;
  for (const std::string& line : lines) {
    if (isBatchSkippable(line)) continue;
    const size_t cut = line.find_last_of(' ');
    REQUIRE(cut != std::string::npos);
    const std::string batch = line.substr(0, cut);
    const uint64_t expected = std::stoull(line.substr(cut + 1), nullptr, 16);
    Patch p;
    BatchError err;
    INFO(file << " patch " << n << ": " << batch);
    REQUIRE(parseBatchLine(batch, p, err));
    t.tessellate(p);
    block.clear();
    appendHexBlock(block, n, p, t);
    if (fnv1a64(block) != expected) {
      ++mismatches;
      if (mismatches <= 5) FAIL_CHECK("hash mismatch");
    }
    ++n;
  }
  INFO(file << ": " << n << " patches");
  CHECK(n > 0);
  CHECK(mismatches == 0);
}

} // namespace

TEST_CASE("golden full outputs: quad hw", "[tessellator][golden]") { compareFull("quad-hw"); }
TEST_CASE("golden full outputs: quad hlsl", "[tessellator][golden]") { compareFull("quad-hlsl"); }
TEST_CASE("golden full outputs: tri hw", "[tessellator][golden]") { compareFull("tri-hw"); }
TEST_CASE("golden full outputs: tri hlsl", "[tessellator][golden]") { compareFull("tri-hlsl"); }
TEST_CASE("golden full outputs: isoline hw", "[tessellator][golden]") { compareFull("isoline-hw"); }
TEST_CASE("golden full outputs: isoline hlsl", "[tessellator][golden]") { compareFull("isoline-hlsl"); }

TEST_CASE("golden hash-file patches, invariants: quad hw",
          "[tessellator][golden][slow]") { checkHashFileInvariants("quad-hw.hashes"); }
TEST_CASE("golden hashes: quad hw", "[tessellator][golden][hashes]") { compareHashes("quad-hw.hashes"); }
TEST_CASE("golden hash-file patches, invariants: quad hlsl",
          "[tessellator][golden][slow]") { checkHashFileInvariants("quad-hlsl.hashes"); }
TEST_CASE("golden hashes: quad hlsl", "[tessellator][golden][hashes]") { compareHashes("quad-hlsl.hashes"); }
TEST_CASE("golden hash-file patches, invariants: quad sweep",
          "[tessellator][golden][slow]") { checkHashFileInvariants("quad-sweep.hashes"); }
TEST_CASE("golden hashes: quad sweep", "[tessellator][golden][hashes]") { compareHashes("quad-sweep.hashes"); }
TEST_CASE("golden hash-file patches, invariants: tri hw",
          "[tessellator][golden][slow]") { checkHashFileInvariants("tri-hw.hashes"); }
TEST_CASE("golden hashes: tri hw", "[tessellator][golden][hashes]") { compareHashes("tri-hw.hashes"); }
TEST_CASE("golden hash-file patches, invariants: tri hlsl",
          "[tessellator][golden][slow]") { checkHashFileInvariants("tri-hlsl.hashes"); }
TEST_CASE("golden hashes: tri hlsl", "[tessellator][golden][hashes]") { compareHashes("tri-hlsl.hashes"); }
TEST_CASE("golden hash-file patches, invariants: isoline hw",
          "[tessellator][golden][slow]") { checkHashFileInvariants("isoline-hw.hashes"); }
TEST_CASE("golden hashes: isoline hw", "[tessellator][golden][hashes]") { compareHashes("isoline-hw.hashes"); }
TEST_CASE("golden hash-file patches, invariants: isoline hlsl",
          "[tessellator][golden][slow]") { checkHashFileInvariants("isoline-hlsl.hashes"); }
TEST_CASE("golden hashes: isoline hlsl", "[tessellator][golden][hashes]") { compareHashes("isoline-hlsl.hashes"); }
