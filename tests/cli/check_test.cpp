// fftess check / sweep end to end on the bundled scenes: exit statuses, JSON shape (docs/cli.md), SVG well-formed,
// bad scene files and overrides, no partial report files.
#include "run.h"
#include "usage_error.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>

using clitest::run;
using nlohmann::json;

namespace {

const std::string kScene = clitest::source("docs/examples/terrain.toml");

void checkStatsShape(const json& s) {
  for (const char* k : {"patches", "culled_patches", "edges_checked", "skipped_culled", "matches", "t_junctions", "cracks"})
    CHECK(s.at(k).is_number_integer());
  CHECK(s.at("worst_gap_world").is_number());
  CHECK(s.at("worst_gap_pixels").is_number());
  CHECK(s.at("edges_checked").get<int64_t>() ==
        s.at("matches").get<int64_t>() + s.at("t_junctions").get<int64_t>() + s.at("cracks").get<int64_t>());
  // On screen or not (docs/cli.md): the off-screen part of the counts, the on-screen worst gaps.
  CHECK(s.at("cracks_off_screen").get<int64_t>() <= s.at("cracks").get<int64_t>());
  CHECK(s.at("t_junctions_off_screen").get<int64_t>() <= s.at("t_junctions").get<int64_t>());
  CHECK(s.at("worst_gap_world_on_screen").is_number());
  CHECK(s.at("worst_gap_pixels_on_screen").is_number());
}

void checkFindingShape(const json& f) {
  const std::string c = f.at("classification");
  CHECK((c == "match" || c == "t_junction" || c == "crack"));
  CHECK(f.at("cause").is_string());
  CHECK(f.at("partitioning").is_string());
  for (const char* side : {"a", "b"}) {
    const json& s = f.at(side);
    CHECK(s.at("patch").at("index").is_number_integer());
    CHECK(s.at("patch").at("level").is_number_integer());
    const std::string e = s.at("edge");
    CHECK((e == "Ueq0" || e == "Veq0" || e == "Ueq1" || e == "Veq1"));
    CHECK(s.at("processed_factor").is_number());
    CHECK(s.at("param_range").size() == 2);
    CHECK(s.at("factor_bits").get<std::string>().rfind("0x", 0) == 0);
    const json& l = s.at("lod"); // the LOD's own record of this edge (docs/cli.md)
    CHECK(l.at("scheme").is_string());
    CHECK(l.at("fixes").is_array());
    CHECK(l.at("metric").is_number());
    CHECK(l.at("unclamped").is_number());
    CHECK(l.at("culled").is_boolean());
    CHECK(l.at("neighbour_size").is_number());
    CHECK(l.at("clamp").is_string());
  }
  CHECK(f.at("gap_world").is_number());
  CHECK(f.at("gap_vertex").size() == 3);
  CHECK(f.at("on_screen").is_boolean());
  CHECK(f.at("on_screen_gap_world").is_number());
  CHECK(f.at("on_screen_gap_vertex").size() == 3);
}

// A finding's cause key in a sweep's cause table: findings off screen are tallied apart ("crack (off screen): ...")
// unless the sweep counted them (--offscreen, the report's "offscreen").
std::string causeKey(const json& f, bool offscreenCounted) {
  const bool apart = !offscreenCounted && !f.at("on_screen").get<bool>();
  return f.at("classification").get<std::string>() + (apart ? " (off screen)" : "") + ": " + f.at("cause").get<std::string>();
}

// A sweep's causes against its cameras: findings add up to the total cracks + T-junctions, a cause's cameras are
// cameras with findings, the first camera has findings, causes are listed by first camera, and the cause of every
// camera's worst finding is listed with a first camera no later than that camera.
void checkCauses(const json& j) {
  const json& cams = j.at("cameras");
  int64_t findings = 0;
  size_t withFindings = 0, previousFirst = 0;
  for (const json& c : cams)
    withFindings += c.at("stats").at("cracks").get<int64_t>() + c.at("stats").at("t_junctions").get<int64_t>() > 0;
  std::map<std::string, size_t> firstOf;
  for (const json& c : j.at("causes")) {
    INFO(c.dump());
    const std::string cause = c.at("cause");
    CHECK((cause.rfind("crack: ", 0) == 0 || cause.rfind("t_junction: ", 0) == 0 ||
           cause.rfind("crack (off screen): ", 0) == 0 || cause.rfind("t_junction (off screen): ", 0) == 0));
    CHECK(c.at("example").is_string());
    const int64_t n = c.at("findings").get<int64_t>();
    const size_t cameras = c.at("cameras").get<size_t>(), first = c.at("first_camera").get<size_t>();
    CHECK(n >= 1);
    CHECK(cameras >= 1);
    CHECK(cameras <= withFindings);
    CHECK(static_cast<int64_t>(cameras) <= n);
    REQUIRE(first < cams.size());
    const json& s = cams.at(first).at("stats");
    CHECK(s.at("cracks").get<int64_t>() + s.at("t_junctions").get<int64_t>() > 0);
    CHECK(first >= previousFirst); // listed in the order the causes first appeared
    previousFirst = first;
    CHECK(firstOf.emplace(cause, first).second); // each cause once
    findings += n;
  }
  CHECK(findings == j.at("stats").at("cracks").get<int64_t>() + j.at("stats").at("t_junctions").get<int64_t>());
  for (const json& c : cams) {
    if (c.at("worst").is_null()) continue;
    const json& w = c.at("worst");
    const std::string cause = causeKey(w, j.at("offscreen").get<bool>());
    INFO(cause);
    REQUIRE(firstOf.count(cause) == 1);
    CHECK(firstOf[cause] <= c.at("index").get<size_t>());
  }
}

std::string svgOk(const std::string& path) {
  std::string why, root;
  const std::string text = clitest::readFile(path);
  CHECK(clitest::wellFormedXml(text, why, &root));
  INFO(why);
  CHECK(root == "svg");
  return text;
}

} // namespace

TEST_CASE("check: the bundled scene is watertight with the pow2 workaround, cracks without it", "[cli][check]") {
  const std::string js = clitest::tmpDir() + "/check.json", svg = clitest::tmpDir() + "/check.svg";
  auto r = run({"check", kScene, "--json", js, "--svg", svg});
  CHECK(r.status == 0);
  CHECK(r.out.find("verdict: watertight") != std::string::npos);
  json j = json::parse(clitest::readFile(js));
  CHECK(j.at("version") == 10);
  CHECK(j.at("kind") == "check");
  checkStatsShape(j.at("stats"));
  CHECK(j.at("stats").at("cracks") == 0);
  CHECK(j.at("scene").at("adjacency_clamp") == "pow2");
  svgOk(svg);

  r = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--json", js, "--svg", svg});
  CHECK(r.status == 1);
  CHECK(r.out.find("crack ") != std::string::npos);
  j = json::parse(clitest::readFile(js));
  checkStatsShape(j.at("stats"));
  CHECK(j.at("stats").at("cracks").get<int64_t>() > 0);
  CHECK(j.at("verdict") == "cracks");
  REQUIRE_FALSE(j.at("findings").empty());
  for (const json& f : j.at("findings")) checkFindingShape(f);
  CHECK(svgOk(svg).find("id=\"inset\"") != std::string::npos);

  // The integer clamp alone still cracks from this camera, and only where the 16.16 model says it must: at 2x jumps
  // whose factors nest as integers (big = 2 * small, big >= 4: the sample's recipe, so never "2 beside 2 x 1") but
  // whose big factor is not a power of two (tests/verify/adjacency_test.cpp checks every jump against the model).
  r = run({"check", kScene, "--set", "lod.adjacency_clamp=integer", "--json", js, "-q"});
  CHECK(r.status == 1);
  CHECK(r.out.empty());
  j = json::parse(clitest::readFile(js));
  CHECK(j.at("stats").at("cracks").get<int64_t>() > 0);
  CHECK_FALSE(j.at("truncated").get<bool>());
  for (const json& f : j.at("findings")) {
    INFO(f.dump());
    CHECK(f.at("classification") == "crack");
    const json& a = f.at("a");
    const json& b = f.at("b");
    const bool aBig = a.at("patch").at("level").get<int>() > b.at("patch").at("level").get<int>();
    const double big = (aBig ? a : b).at("processed_factor").get<double>();
    const double small = (aBig ? b : a).at("processed_factor").get<double>();
    REQUIRE(a.at("patch").at("level").get<int>() != b.at("patch").at("level").get<int>());
    CHECK(big == 2 * small);
    CHECK(big >= 4);
    CHECK(big == std::floor(big));
    const auto n = static_cast<uint64_t>(big);
    CHECK((n & (n - 1)) != 0); // not a power of two
    // The LOD's own record says what it did: the integer clamp on both sides, the small side rebuilt the big edge.
    const json& bigSide = aBig ? a : b;
    const json& smallSide = aBig ? b : a;
    for (const json* side : {&bigSide, &smallSide}) {
      const json& fixes = side->at("lod").at("fixes");
      CHECK(std::find(fixes.begin(), fixes.end(), "integer_clamp") != fixes.end());
      CHECK(side->at("lod").at("clamp") == "integer");
    }
    CHECK(smallSide.at("lod").at("neighbour_size") == 2.0);
    CHECK(bigSide.at("lod").at("neighbour_size") == 0.5);
    CHECK(f.at("cause").get<std::string>().find("(lod integer clamp, rebuilt resampled)") != std::string::npos);
  }
}

// One terrain build per command: the JSON reports count the builds of the whole process.
TEST_CASE("check, check --mesh and sweep build the terrain once", "[cli][check][sweep][slow]") {
  const std::string js = clitest::tmpDir() + "/builds.json";
  const std::string svg = clitest::tmpDir() + "/builds.svg";
  auto r = run({"check", kScene, "--json", js, "--svg", svg});
  CHECK(r.status == 0);
  CHECK(json::parse(clitest::readFile(js)).at("work").at("terrain_builds") == 1);
  r = run({"check", kScene, "--mesh", "--json", js, "--svg", svg});
  CHECK(r.status == 0);
  json j = json::parse(clitest::readFile(js));
  CHECK(j.at("work").at("terrain_builds") == 1);
  CHECK(j.at("work").at("lod_evaluations") == 2 * j.at("stats").at("patches").get<int64_t>()); // edge + mesh check
  r = run({"sweep", kScene, "--orbit", "3", "--json", js, "--svg", svg});
  CHECK(r.status == 0);
  j = json::parse(clitest::readFile(js));
  CHECK(j.at("work").at("terrain_builds") == 1);
  // stats sum the patches per camera; the LOD runs once for each, but not for those visible first proved off screen
  const int64_t lodEvals = j.at("work").at("lod_evaluations"), patches = j.at("stats").at("patches");
  CHECK(lodEvals <= patches);
  CHECK(lodEvals + j.at("stats").at("patches_off_screen").get<int64_t>() >= patches);
}

// check --mesh on a cracked camera where a big edge has two half-size neighbours and one of them is culled (random
// camera 6 of seed 1 on rings_small.toml with the clamp off): both checks skip the culled half and classify the
// drawn one, so they agree; the verdict is the cracks (exit 1), never an internal error (exit 3). The JSON says
// whether they agree, and lists what only one of them flags (nothing here).
TEST_CASE("check --mesh beside a half-culled edge agrees with the edge check and exits 1 for the cracks",
          "[cli][check][mesh][slow]") {
  const std::string js = clitest::tmpDir() + "/mesh_half_culled.json";
  const auto r = run({"check", clitest::source("docs/examples/rings_small.toml"), "--set", "lod.adjacency_clamp=none",
                      "--eye", "25.050155639648438,38.58116912841797,22.16835594177246", "--target",
                      "13.59434700012207,35.22592544555664,26.78861427307129", "--mesh", "--json", js});
  INFO(r.out << r.err);
  CHECK(r.status == 1);
  CHECK(r.err.empty());
  CHECK(r.out.find("agrees with the edge check") != std::string::npos);
  // The whole-mesh check compares every finding; the verdict counts the on-screen ones (3 of the cracks are off
  // screen: docs/verify.md, On screen).
  CHECK(r.out.find("verdict: CRACKS (3 cracks off screen, not counted)\n") != std::string::npos);
  const json j = json::parse(clitest::readFile(js));
  CHECK(j.at("verdict") == "cracks");
  CHECK(j.at("stats").at("cracks_off_screen") == 3);
  CHECK(j.at("mesh").at("agrees") == true);
  CHECK(j.at("mesh").at("mesh_only").empty());
  CHECK(j.at("mesh").at("edge_check_only").empty());
}

TEST_CASE("check: a scene with T-junctions reports them as t_junction (text, JSON) and exits 0", "[cli][check]") {
  const std::string js = clitest::tmpDir() + "/tj.json";
  auto r = run({"check", clitest::source("docs/examples/t_junction.toml"), "--json", js, "--show", "1"});
  CHECK(r.status == 0);
  CHECK(r.out.find("\n  t_junction: 2x jump: ") != std::string::npos); // the cause's header, then its edges
  CHECK(r.out.find("\n      ring ") != std::string::npos);
  CHECK(r.out.find("verdict: watertight now (T-junctions)") != std::string::npos);
  const json j = json::parse(clitest::readFile(js));
  checkStatsShape(j.at("stats"));
  CHECK(j.at("stats").at("t_junctions").get<int64_t>() > 0);
  CHECK(j.at("stats").at("cracks") == 0);
  REQUIRE_FALSE(j.at("findings").empty());
  for (const json& f : j.at("findings")) {
    checkFindingShape(f);
    CHECK(f.at("classification") == "t_junction");
  }
  // --fail-on-tjunctions turns them into exit 1; displacing the same scene turns them into cracks.
  CHECK(run({"check", clitest::source("docs/examples/t_junction.toml"), "--fail-on-tjunctions", "-q"}).status == 1);
  r = run({"check", clitest::source("docs/examples/t_junction.toml"), "--set", "displacement.kind=fbm", "--json", js,
           "-q"});
  CHECK(r.status == 1);
  CHECK(json::parse(clitest::readFile(js)).at("stats").at("cracks").get<int64_t>() > 0);
}

TEST_CASE("check: --json - prints only JSON, --quiet prints nothing", "[cli][check]") {
  auto r = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--json", "-"});
  CHECK(r.status == 1);
  CHECK(json::parse(r.out).at("kind") == "check");
  r = run({"check", kScene, "-q"});
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(r.err.empty());
}

TEST_CASE("check/sweep: bad scenes and overrides exit 2 with one line naming the key or file", "[cli][check]") {
  const std::string bad = clitest::tmpDir() + "/bad.toml";
  clitest::writeFile(bad, "[layout]\nkind = \"tile_rings\"\nrings = \"three\"\n");
  const std::string report = clitest::tmpDir() + "/never.json";
  struct Case {
    std::vector<std::string> args;
    const char* mention;
  } cases[] = {
      {{"check", "no/such/scene.toml"}, "no/such/scene.toml"},
      {{"check", bad, "--json", report}, "rings"},
      {{"check", kScene, "--set", "lod.adjacency_clamp=sometimes", "--json", report}, "adjacency_clamp"},
      {{"check", kScene, "--set", "lod.no_such_key=1"}, "no_such_key"},
      // A neighbour-rule key where no size jump exists: refused, naming the key and the file position.
      {{"check", clitest::source("docs/examples/grid.toml"), "--set", "lod.adjacency_clamp=pow2"},
       "--set lod.adjacency_clamp: cannot apply"},
      {{"sweep", kScene, "--set", "layout.rings=1"}, "terrain.toml:26:19: lod.adjacency_clamp: cannot apply"},
      {{"check", kScene, "--set", "novalue"}, "novalue"},
      {{"check", kScene, "--kernel", "exactish"}, "--kernel"},
      {{"check", kScene, "--path-camera", "3"}, "--path-camera"},
      {{"sweep", kScene, "--orbit", "3", "--random", "3"}, "--random"},
      {{"sweep", bad, "--svg", report}, "rings"},
      {{"check"}, "scene"},
  };
  for (const Case& c : cases) {
    clitest::checkUsageError(c.args, c.mention);
    CHECK_FALSE(clitest::fileExists(report));
  }
  // A report that cannot be written: exit 2, naming the file, nothing left behind.
  const auto r = run({"check", kScene, "-q", "--json", clitest::tmpDir() + "/missing-dir/r.json"});
  CHECK(r.status == 2);
  CHECK(r.err.find("missing-dir/r.json") != std::string::npos);
  for (const std::string& f : clitest::listDir(clitest::tmpDir())) CHECK(f.find(".tmp.") == std::string::npos);
}

TEST_CASE("sweep: workaround on is clean, off cracks, summary names causes, JSON and SVG", "[cli][sweep]") {
  const std::string js = clitest::tmpDir() + "/sweep.json", svg = clitest::tmpDir() + "/sweep.svg";
  auto r = run({"sweep", kScene, "--orbit", "12", "--threads", "2"});
  CHECK(r.status == 0);
  CHECK(r.out.find("WATERTIGHT from all 12 cameras") != std::string::npos);
  CHECK(r.err.find("12/12 cameras") != std::string::npos); // not a terminal: plain progress lines

  r = run({"sweep", kScene, "--random", "16", "--seed", "5", "--set", "lod.adjacency_clamp=integer", "--json", js,
           "--svg", svg});
  CHECK(r.status == 1);
  CHECK(r.out.find("causes") != std::string::npos);
  CHECK(r.out.find("not a power of two") != std::string::npos);
  const json j = json::parse(clitest::readFile(js));
  CHECK(j.at("version") == 10);
  CHECK(j.at("kind") == "sweep");
  CHECK(j.at("cameras_total") == 16);
  CHECK(j.at("cameras_done") == 16);
  CHECK(j.at("cancelled") == false);
  checkStatsShape(j.at("stats"));
  REQUIRE(j.at("cameras").size() == 16);
  int64_t cracks = 0;
  for (const json& c : j.at("cameras")) {
    checkStatsShape(c.at("stats"));
    cracks += c.at("stats").at("cracks").get<int64_t>();
    if (!c.at("worst").is_null()) checkFindingShape(c.at("worst"));
  }
  CHECK(cracks == j.at("stats").at("cracks").get<int64_t>());
  REQUIRE_FALSE(j.at("causes").empty());
  checkCauses(j);
  svgOk(svg);

  // The same sweep on one thread: the same causes, counts and first cameras (they do not depend on thread timing).
  const std::string js1 = clitest::tmpDir() + "/sweep1.json";
  r = run({"sweep", kScene, "--random", "16", "--seed", "5", "--set", "lod.adjacency_clamp=integer", "--threads",
           "1", "--json", js1, "-q"});
  CHECK(r.status == 1);
  CHECK(json::parse(clitest::readFile(js1)).at("causes") == j.at("causes"));

  r = run({"sweep", kScene, "--flyover", "4", "-q"});
  CHECK(r.status == 0);
  CHECK(r.out.empty());
  CHECK(r.err.empty());
}

TEST_CASE("sweep: causes count every finding, so a cause that is no camera's worst is listed too", "[cli][sweep]") {
  // terrain.toml without the clamp, 24 random cameras: besides the fractional nesting cracks, one camera has cracks
  // where the small side's factor is not half the big side's (the minimum factor clamp), never its worst finding.
  // --no-visible-first: each camera below is compared with `fftess check`, the full check (off-screen findings too).
  const std::string js = clitest::tmpDir() + "/sweep-causes.json";
  auto r = run({"sweep", kScene, "--random", "24", "--seed", "5", "--set", "lod.adjacency_clamp=none", "--threads",
                "2", "--json", js, "--no-visible-first"});
  CHECK(r.status == 1);
  const json j = json::parse(clitest::readFile(js));
  checkCauses(j);
  // The default sweep (visible first) lists the same causes on screen, with the same counts and first cameras.
  {
    const std::string vf = clitest::tmpDir() + "/sweep-causes-vf.json";
    CHECK(run({"sweep", kScene, "--random", "24", "--seed", "5", "--set", "lod.adjacency_clamp=none", "--threads", "2",
               "--json", vf, "-q"}).status == 1);
    const json k = json::parse(clitest::readFile(vf));
    checkCauses(k);
    auto onScreen = [](const json& causes) {
      json out = json::array();
      for (const json& c : causes)
        if (c.at("cause").get<std::string>().find("(off screen)") == std::string::npos) out.push_back(c);
      return out;
    };
    CHECK(onScreen(k.at("causes")) == onScreen(j.at("causes")));
  }
  const json& causes = j.at("causes");
  REQUIRE(causes.size() >= 2);
  bool notHalf = false;
  for (const json& c : causes) {
    const std::string cause = c.at("cause");
    INFO(cause);
    CHECK(r.out.find(cause) != std::string::npos); // in the text summary too
    notHalf = notHalf || cause.find("not half the big side's") != std::string::npos;
    // An independent look at the cameras up to the first one: `fftess check` of each camera's eye and target finds
    // this cause in the first camera's findings, with the same explanation as the example, and in none before it.
    const size_t first = c.at("first_camera").get<size_t>();
    int64_t inFirst = 0;
    for (size_t i = 0; i <= first; ++i) {
      const json& cam = j.at("cameras").at(i);
      auto xyz = [](const json& v) {
        return v.at(0).dump() + "," + v.at(1).dump() + "," + v.at(2).dump();
      };
      const auto one = run({"check", kScene, "--set", "lod.adjacency_clamp=none", "--eye", xyz(cam.at("eye")),
                            "--target", xyz(cam.at("target")), "--json", "-"});
      REQUIRE((one.status == 0 || one.status == 1));
      const json cj = json::parse(one.out);
      CHECK(cj.at("stats") == cam.at("stats"));
      int64_t n = 0;
      std::string example;
      for (const json& f : cj.at("findings"))
        if (causeKey(f, false) == cause) {
          if (n++ == 0) example = f.at("explanation");
        }
      if (i < first) CHECK(n == 0);
      else {
        inFirst = n;
        CHECK(example == c.at("example"));
      }
    }
    CHECK(inFirst > 0);
  }
  CHECK(notHalf);
}

TEST_CASE("check: an eye on a shared edge's midpoint plane gives holes, exit 1 (was a false watertight)",
          "[cli][check][holes]") {
  const std::string grid = clitest::source("docs/examples/grid.toml");
  const std::string json = clitest::tmpDir() + "/holes.json";
  const auto r = run({"check", grid, "--set", "displacement.kind=none", "--set", "lod.scheme=screen_sphere", "--set",
                      "tessellation.partitioning=fractional_even", "--set", "lod.frustum_cull=false", "--eye", "0,0,2",
                      "--target", "0,0,100", "--json", json, "--svg", json + ".svg"});
  CHECK(r.status == 1);
  CHECK(r.out.find("verdict: HOLES") != std::string::npos);
  const std::string svg = clitest::readFile(json + ".svg");
  std::string why;
  CHECK(clitest::wellFormedXml(svg, why));
  CHECK(svg.find("<path class=\"hole\"") != std::string::npos); // the holes are filled on the map
  CHECK(r.out.find("w = 0 in the projection") != std::string::npos);
  const nlohmann::json j = nlohmann::json::parse(clitest::readFile(json));
  CHECK(j.at("version") == 10);
  CHECK(j.at("verdict") == "holes");
  CHECK(j.at("stats").at("holes").get<int64_t>() >= 2);
  REQUIRE(j.at("holes").size() >= 2);
  for (const nlohmann::json& h : j.at("holes")) {
    CHECK(h.at("kind") == "discarded");
    CHECK(h.at("visibility") == "visible");
    const std::string f = h.at("hull_factor");
    CHECK((f == "nan" || f == "-nan"));
    const std::string bits = h.at("factor_bits");
    CHECK((bits == "0x7FC00000" || bits == "0xFFC00000"));
    const std::string w = h.at("midpoint_w");
    CHECK((w == "0" || w == "-0"));
  }
}

TEST_CASE("check: a camera that sees no shared edge is not clean", "[cli][check][holes]") {
  // Looking straight up from above the terrain: the LOD culls every patch, nothing is classified.
  const auto r = run({"check", kScene, "--eye", "0,200,0", "--target", "0,400,1"});
  CHECK(r.status == 1);
  CHECK(r.out.find("verdict: NOTHING CHECKED") != std::string::npos);
}
