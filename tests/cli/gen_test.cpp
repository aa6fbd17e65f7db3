// fftess gen: seeded random patches as a batch file: deterministic (a golden hash), every line a batch line that
// reads back as written, -o all or nothing, --sweep first.
#include "run.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>
#include <vector>

#include "tessellator/batch.h"

using clitest::run;

namespace {

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) lines.push_back(l);
  return lines;
}

} // namespace

TEST_CASE("gen: --random 1000 --seed 7 writes the same bytes on every platform (golden hash)", "[cli]") {
  const auto r = run({"gen", "--random", "1000", "--seed", "7"});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const std::vector<std::string> lines = linesOf(r.out);
  REQUIRE(lines.size() == 1001);
  CHECK(lines[0] == "# fftess gen --random 1000 --seed 7");
  // The generator of driver-check and the oracle tests (gl/random_patches.h, splitmix64): this hash changes only if
  // the generator or the batch format does, and then every kept random batch changes meaning.
  CHECK(r.out.size() == 94990);
  CHECK(fftess::fnv1a64(r.out) == 0x51ea596457e9c1a2ull);
  for (size_t i = 1; i < lines.size(); ++i) {
    fftess::Patch p;
    fftess::BatchError err;
    INFO("line " << i + 1 << ": " << lines[i]);
    REQUIRE(fftess::parseBatchLine(lines[i], p, err));
    REQUIRE(fftess::formatBatchLine(p) == lines[i]); // hex factors, hw stage: written as read
  }
  CHECK(run({"gen", "--random", "1000", "--seed", "8"}).out != r.out);
  CHECK(run({"gen", "--random", "1000", "--seed", "7"}).out == r.out);
}

TEST_CASE("gen: --sweep puts the 6348 uniform patches before the random ones", "[cli]") {
  const auto r = run({"gen", "--random", "5", "--seed", "3", "--sweep"});
  REQUIRE(r.status == 0);
  const std::vector<std::string> lines = linesOf(r.out);
  REQUIRE(lines.size() == 1 + 6348 + 5);
  CHECK(lines[0] == "# fftess gen --random 5 --seed 3 --sweep");
  CHECK(lines[1] == "quad integer point hw 0x00000000 0x00000000 0x00000000 0x00000000 0x00000000 0x00000000");
  CHECK(lines[6348] == "isoline fractional_even point hw 0x42840000 0x42840000 0x42840000 0x42840000 0x42840000 0x42840000");
  const auto plain = linesOf(run({"gen", "--random", "5", "--seed", "3"}).out);
  REQUIRE(plain.size() == 6);
  CHECK(std::vector<std::string>(lines.end() - 5, lines.end()) == std::vector<std::string>(plain.begin() + 1, plain.end()));
}

TEST_CASE("gen: -o writes what stdout gets, a bad -o or --random exits 2 and writes nothing", "[cli]") {
  const std::string path = clitest::tmpDir() + "/gen.batch";
  const auto r = run({"gen", "--random", "50", "--seed", "11", "-o", path});
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(clitest::readFile(path) == run({"gen", "--random", "50", "--seed", "11"}).out);
  const std::string bad = clitest::tmpDir() + "/no-such-dir/gen.batch";
  auto e = run({"gen", "--random", "50", "-o", bad});
  CHECK(e.status == 2);
  CHECK(e.out.empty());
  CHECK(e.err.find(bad) != std::string::npos);
  CHECK_FALSE(clitest::fileExists(bad));
  e = run({"gen", "--random", "-1"});
  CHECK(e.status == 2);
  CHECK(e.out.empty());
  CHECK(e.err.find("--random") != std::string::npos);
}
