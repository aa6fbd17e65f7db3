// fftess: version, help on every subcommand, bad usage, bench launcher.
#include "run.h"
#include "usage_error.h"

#include <catch2/catch.hpp>

#include <algorithm>

using clitest::run;

TEST_CASE("fftess --version", "[cli]") {
  const auto r = run({"--version"});
  CHECK(r.status == 0);
  CHECK(r.out.rfind("fftess ", 0) == 0);
}

TEST_CASE("--help on every subcommand shows an example line", "[cli]") {
  const std::vector<std::string> subs{"tessellate", "explain", "bench", "check", "sweep", "compare", "driver-check",
                                      "gen", "prove"};
  const auto top = run({"--help"});
  CHECK(top.status == 0);
  for (const std::string& s : subs) {
    INFO(s);
    CHECK(top.out.find(s) != std::string::npos);
    const auto r = run({s, "--help"});
    CHECK(r.status == 0);
    CHECK(r.out.find("Example") != std::string::npos);
    CHECK(r.out.find("fftess " + s) != std::string::npos);
  }
}

TEST_CASE("bad usage exits 2 with a one-line reason on stderr", "[cli]") {
  struct Case {
    std::vector<std::string> args;
    const char* mention;
  } cases[] = {
      {{}, "subcommand"},
      {{"frobnicate"}, "frobnicate"},
      {{"tessellate", "--format", "png"}, "--format"},
      {{"tessellate", "--no-such-option"}, "--no-such-option"},
      {{"explain", "--partitioning", "quadratic", "12", "6"}, "--partitioning"},
      {{"explain", "12"}, "BIG and SMALL"},
      {{"explain", "12", "six"}, "'six'"},
      {{"explain", "--why-pow2", "12", "6"}, "--why-pow2"},
      {{"explain", "--stage", "gpu", "12", "6"}, "--stage"},
  };
  for (const Case& c : cases) clitest::checkUsageError(c.args, c.mention);
}

#ifdef FFTESS_HAVE_BENCH
TEST_CASE("fftess bench runs the benchmark program (listing only, nothing timed)", "[cli][bench]") {
  const auto r = run({"bench", "--benchmark_list_tests=true"});
  CHECK(r.status == 0);
  CHECK(r.out.find("Tessellate") != std::string::npos);
  CHECK(r.out.find("EdgePoints") != std::string::npos);
}
#endif
