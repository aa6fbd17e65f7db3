// corpus/ (the reference corpus in the repository, corpus/README.md) on its own, as a porter's clone has it: every
// .hashes file is what `fftess tessellate --format hashes` writes for its batch lines, byte for byte (the identity
// with shared/golden and the .in files' full outputs: corpus_test.cmake).
#include "run.h"

#include <catch2/catch.hpp>

#include <sstream>
#include <string>

using clitest::run;

TEST_CASE("corpus: every .hashes file is what fftess tessellate --format hashes writes for its batch lines", "[cli][slow]") {
  for (const char* stem : {"quad-hw", "quad-hlsl", "quad-sweep", "tri-hw", "tri-hlsl", "isoline-hw", "isoline-hlsl"}) {
    const std::string path = clitest::source("corpus/" + std::string(stem) + ".hashes");
    INFO(path);
    const std::string text = clitest::readFile(path);
    REQUIRE(!text.empty());
    std::istringstream in(text);
    std::string batch, line;
    int lines = 0;
    while (std::getline(in, line)) {
      batch += line.substr(0, line.find_last_of(' ')) + "\n";
      ++lines;
    }
    CHECK(lines >= 3396);
    const auto r = run({"tessellate", "--format", "hashes"}, batch);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out.size() == text.size());
    CHECK((r.out == text)); // not printed: 10,000 lines
  }
}
