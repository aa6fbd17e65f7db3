// fftess sweep --shard K/N and fftess merge: the merged shards' report is the unsharded run's, byte for byte; and
// fftess bench's table: its rows exist and its work counters prove the skipped work.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <string>

using clitest::run;
using json = nlohmann::ordered_json;

namespace {

const std::string kRings = clitest::source("docs/examples/rings_small.toml");

} // namespace

TEST_CASE("merging N = 1, 2, 7 shards of a sweep gives exactly the single run's report", "[cli][merge]") {
  const std::string dir = clitest::tmpDir();
  // Cracks (clamp none) so that causes, worst gaps and first cameras all take part. Without the result cache: with it
  // each shard's cache learns from its own cameras (and with threads from their timing), so the work counters and
  // "result_cache" are the shards' own (merged below without it, compared apart).
  const std::vector<std::string> base{"sweep", kRings, "--set", "lod.adjacency_clamp=none", "--random", "15",
                                      "--seed", "4", "-q", "--no-result-cache"};
  auto args = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  const std::string one = dir + "/one.json";
  clitest::Result r = run(args({"--json", one}));
  REQUIRE(r.status == 1);
  const std::string single = clitest::readFile(one);
  const json j = json::parse(single);
  REQUIRE(j.at("stats").at("cracks").get<int64_t>() > 0);
  REQUIRE(j.at("causes").size() >= 1);
  for (int n : {1, 2, 7}) {
    INFO("N = " << n);
    std::vector<std::string> merge{"merge"};
    for (int k = n; k >= 1; --k) { // given in reverse: the order of the inputs does not matter
      const std::string part = dir + "/s" + std::to_string(k) + "_" + std::to_string(n) + ".json";
      r = run(args({"--shard", std::to_string(k) + "/" + std::to_string(n), "--threads", std::to_string(1 + k % 2),
                    "--json", part}));
      REQUIRE(r.status <= 1);
      const json s = json::parse(clitest::readFile(part));
      CHECK(s.at("shard").at("index") == k);
      for (const json& c : s.at("cameras")) CHECK(c.at("index").get<int>() % n == k - 1); // global indices
      merge.push_back(part);
    }
    const std::string merged = dir + "/merged_" + std::to_string(n) + ".json";
    merge.insert(merge.end(), {"--json", merged});
    r = run(merge);
    CHECK(r.status == 1);
    CHECK(r.out.find("CRACKS") != std::string::npos);
    CHECK(clitest::readFile(merged) == single);
  }
  // With the result cache (the default): everything but the work and the cache's counters is the single run's.
  {
    auto withCache = [&](std::vector<std::string> extra) {
      std::vector<std::string> a = args(extra);
      a.erase(std::find(a.begin(), a.end(), "--no-result-cache"));
      return a;
    };
    auto cacheFree = [](json j) {
      j.erase("work");
      j.erase("result_cache");
      return j;
    };
    const std::string cachedOne = dir + "/cached_one.json", merged = dir + "/cached_merged.json";
    REQUIRE(run(withCache({"--json", cachedOne})).status == 1);
    std::vector<std::string> merge{"merge"};
    for (int k = 1; k <= 2; ++k) {
      const std::string part = dir + "/cached_s" + std::to_string(k) + ".json";
      REQUIRE(run(withCache({"--shard", std::to_string(k) + "/2", "--json", part})).status <= 1);
      merge.push_back(part);
    }
    merge.insert(merge.end(), {"--json", merged});
    CHECK(run(merge).status == 1);
    const json a = json::parse(clitest::readFile(cachedOne)), b = json::parse(clitest::readFile(merged));
    CHECK(cacheFree(a) == cacheFree(b));
    CHECK(cacheFree(a) == cacheFree(j)); // and the run without the cache's, but for the work
    CHECK(a.at("result_cache").at("on") == b.at("result_cache").at("on"));
  }
  // A shard missing or given twice, or shards of different sweeps: refused.
  r = run(args({"--shard", "1/2", "--json", dir + "/x1.json"}));
  CHECK(run({"merge", dir + "/x1.json"}).status == 2);
  CHECK(run({"merge", dir + "/x1.json", dir + "/x1.json"}).status == 2);
  r = run({"sweep", kRings, "--random", "15", "--seed", "5", "-q", "--shard", "2/2", "--json", dir + "/x2.json"});
  CHECK(run({"merge", dir + "/x1.json", dir + "/x2.json"}).status == 2);
  CHECK(run({"sweep", kRings, "--shard", "3/2"}).status == 2);
  CHECK(run({"sweep", kRings, "--shard", "0/2"}).status == 2);
}

TEST_CASE("fftess bench prints the accuracy table and its work counters prove the skipped work", "[cli][bench][slow]") {
  const std::string js = clitest::tmpDir() + "/bench.json", md = clitest::tmpDir() + "/bench.md",
                    svg = clitest::tmpDir() + "/bench.svg";
  const clitest::Result r = run({"bench", "--scene", kRings, "--cameras", "2", "--mesh-cameras", "1", "--json", js,
                                 "--markdown", md, "--svg", svg});
  REQUIRE(r.status == 0);
  const json j = json::parse(clitest::readFile(js));
  std::map<std::string, json> rows;
  for (const json& x : j.at("rows")) rows[x.at("group").get<std::string>() + "/" + x.at("row").get<std::string>()] = x;
  for (const char* name : {"checker/float", "checker/epick", "checker/epeck", "domain formula/nvidia",
                           "domain formula/lerp_fma", "domain formula/blend", "domain formula/blend_fma",
                           "heights/8-bit subtexel", "heights/float bilinear", "heights/r16_float", "heights/flat",
                           "mip/bonaventura, no mip", "mip/bonaventura, per_patch", "mip/bonaventura, per_vertex",
                           "lod precision/float", "lod precision/double", "tessellator/denormals kept", "tessellator/denormals flushed", "scope/edges",
                           "scope/whole mesh", "sweep shortcuts/full check", "sweep shortcuts/visible first",
                           "sweep shortcuts/result cache", "sweep shortcuts/both"}) {
    INFO(name);
    REQUIRE(rows.count(name));
    CHECK_FALSE(rows[name].contains("error"));
    CHECK(r.out.find(rows[name].at("row").get<std::string>()) != std::string::npos);
  }
  auto work = [&](const char* row, const char* key) { return rows[row].at("work").at(key).get<int64_t>(); };
  // The sweep shortcuts lose no finding on screen, on the same cameras; the full check evaluates every patch's LOD.
  for (const char* name : {"sweep shortcuts/visible first", "sweep shortcuts/result cache", "sweep shortcuts/both"}) {
    INFO(name);
    CHECK(rows[name].at("gained") == 0);
    CHECK(rows[name].at("lost") == 0);
    CHECK(rows[name].at("cameras") == 2);
    CHECK(rows[name].at("sweep").at("cache_hit_rate").is_number());
    CHECK(work(name, "lod_evaluations") <= 2 * j.at("patches").get<int64_t>());
    CHECK(work(name, "lod_evaluations") + rows[name].at("stats").at("patches_off_screen").get<int64_t>() >=
          2 * j.at("patches").get<int64_t>());
  }
  CHECK(work("sweep shortcuts/full check", "lod_evaluations") == 2 * j.at("patches").get<int64_t>());
  CHECK(rows["sweep shortcuts/full check"].at("sweep").at("result_cache") == false);
  CHECK(rows["sweep shortcuts/full check"].at("sweep").at("visible_first") == false);
  // A flat scene samples no height; the displaced ones sample one per domain evaluation.
  CHECK(work("heights/flat", "height_samples") == 0);
  CHECK(work("heights/flat", "domain_evaluations") > 0);
  CHECK(work("heights/8-bit subtexel", "height_samples") == work("heights/8-bit subtexel", "domain_evaluations"));
  // The edge check never tessellates a whole patch; the whole-mesh check tessellates every patch once per camera.
  CHECK(work("scope/edges", "full_tessellations") == 0);
  CHECK(work("scope/whole mesh", "full_tessellations") == rows["scope/whole mesh"].at("cameras").get<int64_t>() *
                                                            j.at("patches").get<int64_t>());
  // Culled patches run no domain emulation: what is evaluated besides the hole check's grid is the drawn edges'
  // points, at most one per point of the edges checked (shared points are taken from the first side).
  const json& e = rows["scope/edges"];
  CHECK(e.at("stats").at("culled_patches").get<int64_t>() > 0);
  CHECK(work("scope/edges", "edge_queries") > 0);
  CHECK(work("scope/edges", "shared_edge_points") > 0);
  // The double LOD row says how many factors differ and that it did not re-check.
  CHECK(rows["lod precision/double"].at("verdict") == "factors_compared");
  CHECK(rows["lod precision/double"].at("verdict_text").get<std::string>().find("factors differ") != std::string::npos);
  CHECK(work("lod precision/double", "lod_evaluations") == 2 * j.at("patches").get<int64_t>());
  // The exact-construction kernel is the checker group's reference; the float checker is the cheapest checker.
  CHECK(rows["checker/epeck"].at("reference") == true);
  CHECK(clitest::readFile(md).find("| checker | epeck (reference)") != std::string::npos);
  std::string why;
  CHECK(clitest::wellFormedXml(clitest::readFile(svg), why));
}
