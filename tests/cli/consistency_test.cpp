// One consistent CLI (issue 25): the options check and sweep share behave alike, the help says what the code does,
// --show and --seed follow one rule everywhere, parse errors are fftess's one line pointing at the subcommand's help,
// and misspelt subcommands, options, scene keys and values get a "did you mean".
#include "run.h"
#include "usage_error.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>
#include <vector>

using clitest::run;
using nlohmann::json;

namespace {

const std::string kScene = clitest::source("docs/examples/terrain.toml");
const std::string kRings = clitest::source("docs/examples/rings_small.toml");

size_t countOf(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The exact one-line error of args (exit 2, nothing on stdout).
void checkError(const std::vector<std::string>& args, const std::string& line) {
  std::string joined;
  for (const auto& a : args) joined += a + " ";
  INFO(joined);
  const auto r = run(args);
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(r.err == "fftess: error: " + line + "\n");
}

} // namespace

TEST_CASE("sweep takes --show like check: the cause rows printed", "[cli][sweep][consistency]") {
  const std::string js = clitest::tmpDir() + "/show-sweep.json";
  const std::vector<std::string> base{"sweep", kScene, "--set", "lod.adjacency_clamp=none", "--random", "24", "--seed",
                                      "5", "-j", "2"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return run(a);
  };
  const auto all = with({"--json", js});
  REQUIRE(all.status == 1);
  const size_t causes = json::parse(clitest::readFile(js)).at("causes").size();
  REQUIRE(causes >= 2);
  CHECK(countOf(all.out, "\n      e.g. ") == causes); // default 20: every cause of this run
  CHECK(all.out.find(" more causes") == std::string::npos);
  const auto one = with({"--show", "1"});
  CHECK(one.status == 1);
  CHECK(countOf(one.out, "\n      e.g. ") == 1);
  CHECK(one.out.find("... " + std::to_string(causes - 1) + " more causes (--show N, or --json FILE)") !=
        std::string::npos);
  const auto none = with({"--show", "0"});
  CHECK(none.status == 1);
  CHECK(countOf(none.out, "\n      e.g. ") == 0);
}

TEST_CASE("sweep --help says where the cameras come from, as the code picks them", "[cli][sweep][consistency]") {
  const auto h = run({"sweep", "--help"});
  REQUIRE(h.status == 0);
  CHECK(h.out.find("(or its [camera])") == std::string::npos);
  const size_t file = h.out.find("--cameras FILE"), gen = h.out.find("--orbit N, --flyover N or --random N"),
               path = h.out.find("the scene's [[camera_path]]"), fly = h.out.find("a flyover of 200 cameras");
  CHECK(file != std::string::npos);
  CHECK(gen != std::string::npos);
  CHECK(path != std::string::npos);
  REQUIRE(fly != std::string::npos);
  CHECK((file < path && gen < path && path < fly));
  CHECK(h.out.find("never the scene's [camera] alone") != std::string::npos);
  // What the help says: a scene without a camera path sweeps a flyover of 200 cameras.
  const std::string js = clitest::tmpDir() + "/help-flyover.json";
  REQUIRE(run({"sweep", kRings, "-q", "--json", js}).status == 0);
  const json j = json::parse(clitest::readFile(js));
  CHECK(j.at("cameras_total") == 200);
  CHECK(j.at("cameras_source") == "flyover");
  CHECK(j.at("cameras_source_text").get<std::string>().rfind("flyover of 200", 0) == 0);
}

TEST_CASE("bench --group: an unknown group is an error naming every group, and the help lists them all",
          "[cli][bench][consistency]") {
  const auto r = run({"bench", "--group", "lod"});
  CHECK(r.status == 2);
  CHECK(r.out.empty());
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.err.find("--group 'lod': expected ") != std::string::npos);
  CHECK(r.err.find("did you mean 'lod precision'?") != std::string::npos);
  CHECK(run({"bench", "--group", ""}).status == 2);
  const auto help = run({"bench", "--help"});
  for (const char* g : {"checker", "domain formula", "heights", "mip", "lod precision", "tessellator", "scope",
                        "sweep shortcuts"}) {
    INFO(g);
    CHECK(r.err.find(g) != std::string::npos);
    CHECK(help.out.find(g) != std::string::npos);
  }
}

TEST_CASE("a negative --show is refused by every subcommand that has it", "[cli][consistency]") {
  const std::string batch = clitest::source("docs/examples/compare_port.batch");
  const std::string capture = clitest::source("docs/examples/compare_port_bug.csv");
  const std::vector<std::vector<std::string>> cases{
      {"check", kScene, "--show", "-1"},           {"sweep", kScene, "--show", "-1"},
      {"compare", batch, capture, "--show", "-1"}, {"driver-check", "--random", "5", "--show", "-1"},
      {"prove", kScene, "--show", "-1"},           {"compare", batch, capture, "--show=-7"}};
  for (const auto& args : cases) {
    const std::string sub = args[0];
    const std::string value = args.back() == "--show=-7" ? "-7" : "-1";
    checkError(args, "--show " + value + ": must be >= 0 (see fftess " + sub + " --help)");
  }
}

// Issue [8/8]: `-j 100000` aborted in std::terminate (exit 134) with no fftess message.
TEST_CASE("threads: -j beyond 1024 or below 0 is refused by every subcommand that has it", "[cli][consistency]") {
  const std::vector<std::vector<std::string>> subs{{"sweep", kScene, "--random", "200000", "-q"},
                                                   {"prove", kScene},
                                                   {"tessellate", "-e", "quad integer point hw 1 1 1 1 1 1"}};
  for (const auto& sub : subs)
    for (const char* bad : {"100000", "1025", "-1", "2147483647"}) {
      std::vector<std::string> args = sub;
      args.insert(args.end(), {"-j", bad});
      checkError(args, "--threads " + std::string(bad) + ": must be 0 (all cores) to 1024 (see fftess " + sub[0] +
                           " --help)");
    }
  // The bound itself runs (prove stops at its first region; a sweep of 3 cameras starts 3 threads, not 1024).
  CHECK(run({"sweep", kScene, "--random", "3", "-q", "-j", "1024"}).status <= 1);
  CHECK(run({"prove", kScene, "--max-regions", "1", "-j", "1024", "-q"}).status <= 1);
}

TEST_CASE("seeds: one type and one rule for --seed in sweep, driver-check, gen and bench", "[cli][consistency]") {
  const std::vector<std::vector<std::string>> subs{
      {"sweep", kScene, "--random", "1"}, {"driver-check", "--random", "1"}, {"gen", "--random", "1"}, {"bench"}};
  for (const auto& sub : subs) {
    INFO(sub[0]);
    const auto help = run({sub[0], "--help"});
    CHECK(help.out.find("--seed SEED") != std::string::npos);
    CHECK(help.out.find(": a whole number from 0 to 18446744073709551615 (default 1)") != std::string::npos);
    for (const char* bad : {"-1", "x", "12x", "0x10", "+5", "18446744073709551616", "1e3", ""}) {
      std::vector<std::string> args = sub;
      args.insert(args.end(), {"--seed", bad});
      checkError(args, "--seed '" + std::string(bad) + "': expected a whole number from 0 to 18446744073709551615 "
                       "(see fftess " + sub[0] + " --help)");
    }
  }
  const auto max = run({"gen", "--random", "2", "--seed", "18446744073709551615"});
  CHECK(max.status == 0);
  CHECK(max.out.find("--seed 18446744073709551615") != std::string::npos);
  CHECK(run({"gen", "--random", "2", "--seed", "007"}).out == run({"gen", "--random", "2", "--seed", "7"}).out);
}

TEST_CASE("parse errors are one fftess line that points at the subcommand's help", "[cli][consistency]") {
  checkError({"sweep", kScene, "--sho", "5"}, "sweep: unknown option '--sho'; did you mean '--show'? (see fftess sweep --help)");
  checkError({"check", kScene, "--no-such-option"}, "check: unknown option '--no-such-option' (see fftess check --help)");
  checkError({"sweep", kScene, "--mesh"}, "sweep: unknown option '--mesh' (an option of fftess check) (see fftess sweep --help)");
  checkError({"check", kScene, "--jsno=x.json"}, "check: unknown option '--jsno'; did you mean '--json'? (see fftess check --help)");
  // A short stray argument: a long one is abbreviated in the message (quoted like every user text: cli/common.cpp), and
  // the scene's own path is as long as the checkout's (tests run from directories of 150+ characters).
  checkError({"check", kScene, "stray.toml"}, "check: unexpected argument 'stray.toml' (see fftess check --help)");
  checkError({"check"}, "check: missing SCENE (the scene file) (see fftess check --help)");
  checkError({}, "missing subcommand (expected tessellate|explain|check|sweep|merge|bench|compare|driver-check|layout|"
                 "gen|prove) (see fftess --help)");
  checkError({"check", kScene, "--show", "abc"}, "--show 'abc': expected a whole number (see fftess check --help)");
  checkError({"check", kScene, "--show"}, "--show: missing its value (N) (see fftess check --help)");
  checkError({"gen", "--random", "1e9"}, "--random '1e9': must be from 0 to 100000000 (see fftess gen --help)");
  checkError({"tessellate", "--format", "png"},
             "--format 'png': expected hex|table|obj|svg|hashes (see fftess tessellate --help)");
  checkError({"--frobnicate"}, "unknown option '--frobnicate' (see fftess --help)");
}

TEST_CASE("did you mean: subcommands, options, values and scene keys", "[cli][consistency]") {
  checkError({"chek", kScene}, "unknown subcommand 'chek'; did you mean 'check'? (expected tessellate|explain|check|"
                               "sweep|merge|bench|compare|driver-check|layout|gen|prove; see fftess --help)");
  checkError({"swep"}, "unknown subcommand 'swep'; did you mean 'sweep'? (expected tessellate|explain|check|sweep|merge|"
                       "bench|compare|driver-check|layout|gen|prove; see fftess --help)");
  checkError({"check", kScene, "--kernel", "epik"}, "--kernel 'epik': expected epick|epeck|float; did you mean 'epick'?");
  checkError({"sweep", kScene, "--gpu-float", "conformnt"},
             "--gpu-float 'conformnt': expected off|conformant; did you mean 'conformant'?");
  checkError({"check", kScene, "--flush-denormals=of"}, "--flush-denormals='of': expected on|off|auto; did you mean 'off'?");
  checkError({"tessellate", "--format", "tabel"},
             "--format 'tabel': expected hex|table|obj|svg|hashes; did you mean 'table'? (see fftess tessellate --help)");
  checkError({"driver-check", "--api", "vulkn"},
             "--api 'vulkn': expected gl|vulkan; did you mean 'vulkan'? (see fftess driver-check --help)");
  checkError({"check", kScene, "--set", "lod.adjacency_clmp=pow2"},
             "--set lod.adjacency_clmp: unknown key (did you mean \"lod.adjacency_clamp\"?)");
  const auto value = run({"check", kScene, "--set", "lod.scheme=screen_sphre"});
  CHECK(value.status == 2);
  CHECK(value.err.find("--set lod.scheme: unknown value \"screen_sphre\" (expected ") != std::string::npos);
  CHECK(value.err.find("; did you mean \"screen_sphere\"?)\n") != std::string::npos);
  // In a scene file: the file position, the key, the nearest key.
  const std::string scene = clitest::tmpDir() + "/clmp.toml";
  std::string text = clitest::readFile(kScene);
  const size_t at = text.find("adjacency_clamp");
  REQUIRE(at != std::string::npos);
  text.replace(at, 15, "adjacency_clmp");
  clitest::writeFile(scene, text);
  const auto file = run({"check", scene});
  CHECK(file.status == 2);
  CHECK(file.err.find(": lod.adjacency_clmp: unknown key (did you mean \"lod.adjacency_clamp\"?)\n") != std::string::npos);
}

TEST_CASE("check's text groups findings by cause: a header, the fix, an example and a few edges", "[cli][check][consistency]") {
  const std::string js = clitest::tmpDir() + "/grouped.json";
  const auto r = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--json", js});
  REQUIRE(r.status == 1);
  const json j = json::parse(clitest::readFile(js));
  // Every cause once, with the number of its findings in the report (off screen apart, keyed as sweep keys them).
  std::vector<std::pair<std::string, int>> causes; // "crack: KEY" or "crack (off screen): KEY", count
  auto keyOf = [](const json& f) {
    return f.at("classification").get<std::string>() + (f.at("on_screen").get<bool>() ? "" : " (off screen)") +
           ": " + f.at("cause").get<std::string>();
  };
  for (const json& f : j.at("findings")) {
    const std::string key = keyOf(f);
    auto it = std::find_if(causes.begin(), causes.end(), [&](const auto& c) { return c.first == key; });
    if (it == causes.end()) causes.emplace_back(key, 1);
    else ++it->second;
  }
  REQUIRE(!causes.empty());
  for (const auto& [key, n] : causes) {
    INFO(key);
    CHECK(countOf(r.out, "\n  " + key + ": " + std::to_string(n) + "\n    fix: ") == 1);
  }
  // Short lines: no line of the text is longer than 240 bytes, and the default shows 3 edges per cause.
  size_t longest = 0, edges = 0;
  for (size_t at = 0, end; at < r.out.size(); at = end + 1) {
    end = r.out.find('\n', at);
    const std::string line = r.out.substr(at, end - at);
    longest = std::max(longest, line.size());
    if (line.rfind("      ring ", 0) == 0) ++edges;
  }
  CHECK(longest <= 240);
  CHECK(edges <= 3 * causes.size());
  CHECK(edges >= 3);
  // The widest gap first: the first edge under the first cause is that cause's widest crack on screen.
  const auto onScreen = std::find_if(causes.begin(), causes.end(), [](const auto& c) {
    return c.first.find(" (off screen): ") == std::string::npos;
  });
  REQUIRE(onScreen != causes.end());
  const std::string first = onScreen->first;
  double widest = 0;
  for (const json& f : j.at("findings"))
    if (keyOf(f) == first) widest = std::max(widest, f.at("on_screen_gap_world").get<double>());
  char buf[64];
  std::snprintf(buf, sizeof buf, " %.3g world (", widest);
  const size_t header = r.out.find("\n  " + first + ": ");
  const size_t firstEdge = r.out.find("\n      ring ", header);
  REQUIRE(firstEdge != std::string::npos);
  CHECK(r.out.substr(firstEdge, r.out.find('\n', firstEdge + 1) - firstEdge).find(buf) != std::string::npos);
  // --show N: N edges per cause.
  const auto one = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--show", "1"});
  CHECK(countOf(one.out, "\n      ring ") == causes.size());
  const auto none = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--show", "0"});
  CHECK(countOf(none.out, "\n      ring ") == 0);
  CHECK(countOf(none.out, "\n    fix: ") == causes.size());
}

#ifdef FFTESS_HAVE_BENCH
TEST_CASE("bench --micro says how fftess was built, not the library's DEBUG warning", "[cli][bench][consistency]") {
  const auto r = run({"bench", "--micro", "--benchmark_filter=^BM_TraceEdge$", "--benchmark_min_time=0.001"});
  CHECK(r.status == 0);
  CHECK(r.out.find("BM_TraceEdge") != std::string::npos);
  CHECK(r.err.find("built as DEBUG") == std::string::npos);
  CHECK(r.err.find("fftess_bench: fftess built as ") != std::string::npos);
}
#endif
