// fftess sweep's shortcuts (docs/cli.md, "fftess sweep"; docs/verify.md, "Sweep shortcuts"): visible first and the
// result cache run unless --offscreen, --no-visible-first or --no-result-cache; the summary line and the JSON say
// what ran; the findings are the same either way; fftess merge sums the counters and says "mixed" where shards
// differ. The case named "Shortcuts run: ..." requires that they actually ran (it fails until verify implements them).
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <vector>

using clitest::run;
using json = nlohmann::ordered_json;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");

std::string lineOf(const std::string& text, const std::string& start) {
  const size_t at = text.find("\n" + start);
  if (at == std::string::npos) return "";
  const size_t end = text.find('\n', at + 1);
  return text.substr(at + 1, end == std::string::npos ? std::string::npos : end - at - 1);
}

struct Swept {
  clitest::Result r;
  json j;
};

// rings_small without the clamp (cracks on screen and off), 8 random cameras, on two threads.
Swept sweepWith(const std::vector<std::string>& extra, const std::string& name) {
  const std::string js = clitest::tmpDir() + "/" + name + ".json";
  std::vector<std::string> args{"sweep", kRings, "--set", "lod.adjacency_clamp=none", "--random", "8", "--seed", "6",
                                "-j", "2", "--json", js};
  args.insert(args.end(), extra.begin(), extra.end());
  Swept s{run(args), json()};
  INFO(s.r.err);
  REQUIRE(s.r.status == 1);
  s.j = json::parse(clitest::readFile(js));
  return s;
}

// What counts: the verdict, the on-screen counts and the cause table, per camera and in total.
json onScreenPart(const json& j) {
  json out;
  auto stats = [](const json& s) {
    return json{{"cracks", s.at("cracks").get<int64_t>() - s.at("cracks_off_screen").get<int64_t>()},
                {"t_junctions", s.at("t_junctions").get<int64_t>() - s.at("t_junctions_off_screen").get<int64_t>()},
                {"holes", s.at("holes")},
                {"undecided", s.at("undecided")},
                {"worst_gap_world_on_screen", s.at("worst_gap_world_on_screen")}};
  };
  out["verdict"] = j.at("verdict");
  out["stats"] = stats(j.at("stats"));
  json cams = json::array();
  for (const json& c : j.at("cameras"))
    cams.push_back({{"index", c.at("index")}, {"stats", stats(c.at("stats"))}, {"worst", c.at("worst")},
                    {"first_hole", c.at("first_hole")}});
  out["cameras"] = cams;
  json causes = json::array();
  for (const json& c : j.at("causes"))
    if (c.at("cause").get<std::string>().find("(off screen)") == std::string::npos) causes.push_back(c);
  out["causes"] = causes;
  return out;
}

} // namespace

TEST_CASE("sweep: the shortcuts run unless --offscreen, --no-visible-first or --no-result-cache, the summary and the "
          "JSON say what ran, and the findings that count are the same",
          "[cli][sweep][shortcuts]") {
  const Swept dflt = sweepWith({}, "shortcuts-default");
  const Swept noVf = sweepWith({"--no-visible-first"}, "shortcuts-no-vf");
  const Swept noCache = sweepWith({"--no-result-cache"}, "shortcuts-no-cache");
  const Swept none = sweepWith({"--no-visible-first", "--no-result-cache"}, "shortcuts-none");
  const Swept offscreen = sweepWith({"--offscreen"}, "shortcuts-offscreen");
  // The summary line.
  INFO(dflt.r.out);
  CHECK(lineOf(dflt.r.out, "  shortcuts").rfind("  shortcuts      ", 0) == 0);
  CHECK(lineOf(noVf.r.out, "  shortcuts").find("full check (--no-visible-first); ") != std::string::npos);
  CHECK(lineOf(offscreen.r.out, "  shortcuts").find("full check (--offscreen); ") != std::string::npos);
  CHECK(lineOf(noCache.r.out, "  shortcuts").find("; result cache off: --no-result-cache") != std::string::npos);
  CHECK(lineOf(none.r.out, "  shortcuts") ==
        "  shortcuts      full check (--no-visible-first); result cache off: --no-result-cache");
  // The JSON keys.
  for (const Swept* s : {&dflt, &noVf, &noCache, &none, &offscreen}) {
    const json& j = s->j;
    CHECK(j.at("version") == 10);
    CHECK(j.at("visible_first").is_boolean());
    const json& rc = j.at("result_cache");
    CHECK(rc.at("on").is_boolean());
    CHECK((rc.at("on").get<bool>() ? rc.at("off_reason").is_null() : rc.at("off_reason").is_string()));
    CHECK((rc.at("on").get<bool>() ? rc.at("off_reason_text").is_null() : rc.at("off_reason_text").is_string()));
    for (const char* k : {"hits", "seam_hits", "misses", "seam_proofs", "items", "bytes", "dropped"})
      CHECK(rc.at(k).is_number_integer());
    CHECK(rc.at("hits") == j.at("work").at("cache_hits"));
    CHECK(rc.at("seam_hits") == j.at("work").at("seam_hits"));
    CHECK(rc.at("misses") == j.at("work").at("cache_misses"));
    CHECK(rc.at("seam_proofs") == j.at("work").at("seam_proofs"));
    CHECK(j.at("work").at("box_tests").is_number_integer());
    CHECK(j.at("terrain_work").at("cache_hits") == 0);
    CHECK(j.at("stats").at("patches_off_screen").is_number_integer());
    CHECK(j.at("stats").at("edges_off_screen").is_number_integer());
    CHECK(j.at("cameras").at(0).at("stats").at("patches_off_screen").is_number_integer());
  }
  for (const Swept* s : {&noVf, &none, &offscreen}) {
    CHECK(s->j.at("visible_first") == false);
    CHECK(s->j.at("stats").at("patches_off_screen") == 0);
    CHECK(s->j.at("stats").at("edges_off_screen") == 0);
  }
  for (const Swept* s : {&noCache, &none}) {
    CHECK(s->j.at("result_cache").at("on") == false);
    CHECK(s->j.at("result_cache").at("off_reason") == "option");
    CHECK(s->j.at("result_cache").at("off_reason_text") == "--no-result-cache");
    CHECK(s->j.at("work").at("cache_hits") == 0);
    CHECK(s->j.at("work").at("seam_hits") == 0);
  }
  // Nothing that counts is lost: the same verdict, on-screen counts, worst findings and causes, camera by camera.
  const json ref = onScreenPart(none.j);
  CHECK(onScreenPart(dflt.j) == ref);
  CHECK(onScreenPart(noVf.j) == ref);
  CHECK(onScreenPart(noCache.j) == ref);
  CHECK(onScreenPart(offscreen.j).at("stats") == ref.at("stats"));
  // --offscreen is the full check: every finding, as without the shortcuts.
  CHECK(offscreen.j.at("stats").at("cracks") == none.j.at("stats").at("cracks"));
  CHECK(offscreen.j.at("stats").at("cracks_off_screen") == none.j.at("stats").at("cracks_off_screen"));
  // check keeps the full check (no such flags).
  CHECK(run({"check", kRings, "--no-visible-first"}).status == 2);
  CHECK(run({"check", kRings, "--no-result-cache"}).status == 2);
}

TEST_CASE("merge: the shards' shortcut counters are summed and a flag the shards do not agree on is mixed",
          "[cli][merge][shortcuts]") {
  const std::string dir = clitest::tmpDir();
  const std::string s1 = dir + "/mixed_s1.json", s2 = dir + "/mixed_s2.json", merged = dir + "/mixed.json";
  const std::vector<std::string> base{"sweep", kRings, "--random", "6", "--seed", "2", "-q"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  REQUIRE(run(with({"--shard", "1/2", "--json", s1})).status == 0);
  REQUIRE(run(with({"--shard", "2/2", "--no-visible-first", "--no-result-cache", "--json", s2})).status == 0);
  const clitest::Result m = run({"merge", s1, s2, "--json", merged});
  INFO(m.out << m.err);
  REQUIRE(m.status == 0);
  CHECK(lineOf(m.out, "  shortcuts").rfind("  shortcuts      ", 0) == 0);
  const json a = json::parse(clitest::readFile(s1)), b = json::parse(clitest::readFile(s2)),
             j = json::parse(clitest::readFile(merged));
  const json& ra = a.at("result_cache");
  const json& rb = b.at("result_cache");
  const json& rj = j.at("result_cache");
  // Shard 2 says why its cache was off; shard 1's reason (none when on) is another: mixed.
  CHECK(rj.at("off_reason") == "mixed");
  CHECK(rj.at("off_reason_text") == "mixed");
  CHECK(rj.at("on") == (ra.at("on") == rb.at("on") ? ra.at("on") : json("mixed")));
  CHECK(j.at("visible_first") == (a.at("visible_first") == b.at("visible_first") ? a.at("visible_first") : json("mixed")));
  for (const char* k : {"hits", "seam_hits", "misses", "seam_proofs", "items", "bytes", "dropped"})
    CHECK(rj.at(k).get<int64_t>() == ra.at(k).get<int64_t>() + rb.at(k).get<int64_t>());
  for (const char* k : {"cache_hits", "seam_hits", "box_tests", "lod_evaluations"})
    CHECK(j.at("work").at(k).get<int64_t>() ==
          a.at("work").at(k).get<int64_t>() + b.at("work").at(k).get<int64_t>() - a.at("terrain_work").at(k).get<int64_t>());
  for (const char* k : {"patches_off_screen", "edges_off_screen"})
    CHECK(j.at("stats").at(k).get<int64_t>() == a.at("stats").at(k).get<int64_t>() + b.at("stats").at(k).get<int64_t>());
  // Shards that agree keep their value.
  const std::string t1 = dir + "/agree_s1.json", t2 = dir + "/agree_s2.json";
  REQUIRE(run(with({"--shard", "1/2", "--no-result-cache", "--json", t1})).status == 0);
  REQUIRE(run(with({"--shard", "2/2", "--no-result-cache", "--json", t2})).status == 0);
  const clitest::Result m2 = run({"merge", t1, t2, "--json", merged});
  REQUIRE(m2.status == 0);
  const json k = json::parse(clitest::readFile(merged));
  CHECK(k.at("result_cache").at("on") == false);
  CHECK(k.at("result_cache").at("off_reason") == "option");
  CHECK(k.at("result_cache").at("off_reason_text") == "--no-result-cache");
  CHECK(k.at("visible_first") == json::parse(clitest::readFile(t1)).at("visible_first"));
  CHECK(lineOf(m2.out, "  shortcuts").find("result cache off: --no-result-cache") != std::string::npos);
}

TEST_CASE("Shortcuts run: fftess sweep runs visible first and answers pairs from the result cache by default",
          "[cli][sweep][shortcuts]") {
  const Swept dflt = sweepWith({}, "shortcuts-run");
  INFO(dflt.r.out);
  CHECK(dflt.j.at("visible_first") == true);
  CHECK(dflt.j.at("stats").at("patches_off_screen").get<int64_t>() > 0);
  CHECK(dflt.j.at("result_cache").at("on") == true);
  CHECK(dflt.j.at("result_cache").at("hits").get<int64_t>() + dflt.j.at("result_cache").at("seam_hits").get<int64_t>() > 0);
  CHECK(dflt.j.at("work").at("box_tests").get<int64_t>() > 0);
  const std::string line = lineOf(dflt.r.out, "  shortcuts");
  CHECK(line.rfind("  shortcuts      visible first (", 0) == 0);
  CHECK(line.find("; result cache on (") != std::string::npos);
  // fftess bench's sweep shortcuts rows: less work than the full check on the same cameras.
  const std::string js = clitest::tmpDir() + "/shortcuts-bench.json";
  REQUIRE(run({"bench", "--scene", kRings, "--group", "sweep shortcuts", "--cameras", "4", "--repeats", "1", "--json",
               js, "-q"}).status == 0);
  std::map<std::string, json> rows;
  const std::string benchJson = clitest::readFile(js);
  INFO(benchJson);
  const json bench = json::parse(benchJson); // kept: a range-for over a temporary's member would dangle
  for (const json& x : bench.at("rows")) rows[x.at("row").get<std::string>()] = x;
  auto work = [&](const char* row, const char* key) { return rows.at(row).at("work").at(key).get<int64_t>(); };
  CHECK(work("visible first", "lod_evaluations") < work("full check", "lod_evaluations"));
  CHECK(work("result cache", "domain_evaluations") < work("full check", "domain_evaluations"));
  CHECK(rows.at("both").at("sweep").at("cache_hit_rate").get<double>() +
            rows.at("both").at("sweep").at("seam_hit_rate").get<double>() > 0);
  CHECK(rows.at("both").at("sweep").at("visible_first") == true);
}
