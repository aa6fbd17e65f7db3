// fftess tessellate, end to end through the built binary.
#include "run.h"

#include <catch2/catch.hpp>

#include <sstream>

using clitest::run;

namespace {

int countLinesStartingWith(const std::string& text, const std::string& prefix) {
  std::istringstream in(text);
  int n = 0;
  for (std::string l; std::getline(in, l);)
    if (l.compare(0, prefix.size(), prefix) == 0) ++n;
  return n;
}

void goldenCase(const std::string& stem) {
  INFO(stem);
  const auto r = run({"tessellate", "--format", "hex", clitest::golden(stem + ".in")});
  REQUIRE(r.status == 0);
  CHECK(r.err.empty());
  const std::string expected = clitest::readFile(clitest::golden(stem + ".out"));
  REQUIRE(r.out.size() == expected.size());
  CHECK(r.out == expected); // byte for byte
}

} // namespace

TEST_CASE("tessellate --format hex reproduces the golden outputs byte for byte", "[cli][tessellate][golden]") {
  for (const char* stem : {"quad-hw", "quad-hlsl", "tri-hw", "tri-hlsl", "isoline-hw", "isoline-hlsl"}) goldenCase(stem);
}

TEST_CASE("tessellate reads stdin, a file and -e lines alike", "[cli][tessellate]") {
  const std::string batch = "# comment line\n\nquad integer triangle_cw hw 4 4 4 4 4 4\n"
                            "  tri fractional_odd triangle_ccw hw 3.5 0x40200000 5 2 0 0   # trailing comment\n";
  const auto fromStdin = run({"tessellate", "--format", "hex"}, batch);
  REQUIRE(fromStdin.status == 0);
  const std::string path = clitest::tmpDir() + "/two.txt";
  clitest::writeFile(path, batch);
  const auto fromFile = run({"tessellate", "--format", "hex", path});
  REQUIRE(fromFile.status == 0);
  CHECK(fromFile.out == fromStdin.out);
  const auto fromArgs = run({"tessellate", "--format", "hex", "-e", "quad integer triangle_cw hw 4 4 4 4 4 4", "-e",
                             "tri fractional_odd triangle_ccw hw 3.5 0x40200000 5 2 0 0"});
  REQUIRE(fromArgs.status == 0);
  CHECK(fromArgs.out == fromStdin.out);
  // Integer 4x4 quad: 25 points, 32 triangles.
  CHECK(fromStdin.out.rfind("patch 0 points 25 indices 96\n", 0) == 0);
  CHECK(countLinesStartingWith(fromStdin.out, "patch ") == 2);
}

TEST_CASE("tessellate: a malformed line is an error naming line and token, nothing is printed", "[cli][tessellate]") {
  struct Case {
    const char* line;
    const char* mustMention;
  } cases[] = {
      {"quad integer triangle_cw hw 4 4 4 4 4 4\nquadd integer triangle_cw hw 4 4 4 4 4 4\n", ":2: token 1 'quadd'"},
      {"quad integr triangle_cw hw 4 4 4 4 4 4\n", ":1: token 2 'integr'"},
      {"quad integer tri hw 4 4 4 4 4 4\n", "token 3 'tri'"},
      {"quad integer triangle_cw hlsl 4 4 4 4 4 4\n", "token 4 'hlsl'"},
      {"quad integer triangle_cw hw 4 4 4 4 4\n", "expected 6 factors"},
      {"quad integer triangle_cw hw 4 4 4 4 4 4 4\n", "token 11 '4'"},
      {"quad integer triangle_cw hw 4 4 0x4080000 4 4 4\n", "token 7 '0x4080000'"},
      {"quad integer triangle_cw hw 4 4 0x408000000 4 4 4\n", "token 7 '0x408000000'"},
      {"quad integer triangle_cw hw 4 4 4 four 4 4\n", "token 8 'four'"},
      {"quad integer triangle_cw hw 4 4 4 4 4 4,\n", "token 10 '4,'"},
      {"isoline integer triangle_cw hw 4 4 0 0 0 0\n", "token 3 'triangle_cw'"},
      {"quad integer triangle_cw hw 4 4 -0x40800000 4 4 4\n", "token 7 '-0x40800000': factor Ueq1: not a decimal"},
      {"quad integer triangle_cw hw 4 4 0x1p3 4 4 4\n", "token 7 '0x1p3': factor Ueq1: hex factor needs"},
      {"tri integer triangle_cw hw 4 4 4 4..0 0 0\n", "token 8 '4..0': factor inside: not a number"},
      {"quad\n", ":1: missing partitioning after 'quad'"},
      {"quad integer\n", ":1: missing topology"},
      {"quad integer point\n", ":1: missing stage"},
  };
  for (const Case& c : cases) {
    INFO(c.line);
    const auto r = run({"tessellate", "--format", "hex"}, c.line);
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.find(c.mustMention) != std::string::npos);
    CHECK(r.err.find("<stdin>") != std::string::npos);
  }
}

TEST_CASE("tessellate --keep-going prints the good patches and still fails", "[cli][tessellate]") {
  const auto r = run({"tessellate", "--format", "hex", "--keep-going"},
                     "quad integer point hw 1 1 1 1 1 1\nquad integer point hw x 1 1 1 1 1\n"
                     "quad integer point hw 2 2 2 2 2 2\n");
  CHECK(r.status == 2);
  CHECK(r.err.find(":2: token 5 'x'") != std::string::npos);
  // Patch numbers count every patch line, so the malformed one leaves a gap.
  CHECK(r.out.find("patch 0 points 4 indices 4\n") == 0);
  CHECK(r.out.find("patch 1 ") == std::string::npos);
  CHECK(r.out.find("patch 2 points 9 indices 9\n") != std::string::npos);
}

TEST_CASE("tessellate -o writes the file whole, or not at all", "[cli][tessellate]") {
  const std::string dir = clitest::tmpDir() + "/outdir";
  const std::string ok = clitest::tmpDir() + "/ok.out";
  auto r = run({"tessellate", "--format", "hex", "-e", "quad integer point hw 1 1 1 1 1 1", "-o", ok});
  REQUIRE(r.status == 0);
  CHECK(r.out.empty());
  CHECK(clitest::readFile(ok).rfind("patch 0 points 4 indices 4\n", 0) == 0);
  const std::string bad = clitest::tmpDir() + "/bad.out";
  r = run({"tessellate", "--format", "hex", "-o", bad}, "quad integer point hw 1 1 1 1 1 1\nbad line\n");
  CHECK(r.status == 2);
  CHECK_FALSE(clitest::fileExists(bad));
  r = run({"tessellate", "-e", "quad integer point hw 1 1 1 1 1 1", "-o", dir + "/missing/x.svg"});
  CHECK(r.status == 2);
  CHECK(r.err.find("missing/x.svg") != std::string::npos);
  for (const std::string& f : clitest::listDir(clitest::tmpDir())) CHECK(f.find(".tmp.") == std::string::npos);
  r = run({"tessellate", "no/such/input.txt"});
  CHECK(r.status == 2);
  CHECK(r.err.find("no/such/input.txt") != std::string::npos);
}

TEST_CASE("tessellate --format table, obj and svg describe the same patch", "[cli][tessellate]") {
  const std::string line = "quad fractional_odd triangle_cw hw 3.5 2 5 4 3 3";
  const auto hex = run({"tessellate", "--format", "hex", "-e", line});
  REQUIRE(hex.status == 0);
  int points = 0, indices = 0;
  REQUIRE(std::sscanf(hex.out.c_str(), "patch 0 points %d indices %d", &points, &indices) == 2);
  REQUIRE(points > 0);

  const auto table = run({"tessellate", "--format", "table", "-e", line});
  REQUIRE(table.status == 0);
  CHECK(table.out.find(std::to_string(points) + " points, " + std::to_string(indices / 3) + " triangles") !=
        std::string::npos);

  const auto obj = run({"tessellate", "--format", "obj", "-e", line});
  REQUIRE(obj.status == 0);
  CHECK(countLinesStartingWith(obj.out, "v ") == points);
  CHECK(countLinesStartingWith(obj.out, "f ") == indices / 3);

  const auto svg = run({"tessellate", "--format", "svg", "-e", line, "-e", "tri integer line hw 3 3 3 3 0 0", "-e",
                        "isoline integer line hw 2 3 0 0 0 0", "-e", "quad integer point hw 0 1 1 1 1 1"});
  REQUIRE(svg.status == 0);
  std::string why, root;
  CHECK(clitest::wellFormedXml(svg.out, why, &root));
  INFO(why);
  CHECK(root == "svg");
  CHECK(svg.out.find("culled") != std::string::npos);
}

TEST_CASE("tessellate: NaN, infinities and denormals given as bits", "[cli][tessellate]") {
  // Reference behaviour (shared facts): a positive denormal outer factor is not culled; --flush-denormals culls it.
  const std::string denormal = "quad integer point hw 0x00000001 1 1 1 1 1";
  auto r = run({"tessellate", "--format", "hex", "-e", denormal});
  REQUIRE(r.status == 0);
  CHECK(r.out.rfind("patch 0 points 4 indices 4\n", 0) == 0);
  r = run({"tessellate", "--format", "hex", "--flush-denormals", "-e", denormal});
  REQUIRE(r.status == 0);
  CHECK(r.out == "patch 0 points 0 indices 0\n");
  r = run({"tessellate", "--format", "hex", "-e", "quad integer point hw nan 1 1 1 1 1", "-e",
           "quad integer point hw 0x7fc00000 1 1 1 1 1"});
  REQUIRE(r.status == 0);
  CHECK(r.out == "patch 0 points 0 indices 0\npatch 1 points 0 indices 0\n");
  r = run({"tessellate", "--format", "table", "-e", "quad integer point hw 0x7f800000 1 1 1 1 1"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("Ueq0=inf") != std::string::npos);
}

TEST_CASE("tessellate --threads N prints the same bytes as one thread", "[cli][tessellate][golden]") {
  for (const char* stem : {"quad-hw", "tri-hlsl", "isoline-hw"}) {
    INFO(stem);
    const std::string expected = clitest::readFile(clitest::golden(std::string(stem) + ".out"));
    for (const char* threads : {"2", "3", "0"}) {
      INFO("--threads " << threads);
      const auto r = run({"tessellate", "--format", "hex", "--threads", threads, clitest::golden(std::string(stem) + ".in")});
      REQUIRE(r.status == 0);
      CHECK(r.out == expected);
    }
  }
  const std::string batch = "quad integer triangle_cw hw 4 4 4 4 4 4\nbad line\ntri pow2 point hw 3 3 3 3 0 0\n";
  const auto one = run({"tessellate", "--format", "hashes", "--keep-going"}, batch);
  const auto two = run({"tessellate", "--format", "hashes", "--keep-going", "--threads", "2"}, batch);
  CHECK(one.status == 2);
  CHECK(two.status == 2);
  CHECK(one.out == two.out);
  CHECK(countLinesStartingWith(two.out, "quad ") == 1);
  CHECK(run({"tessellate", "--threads", "-1", "-e", "quad integer point hw 1 1 1 1 1 1"}).status == 2);
}
