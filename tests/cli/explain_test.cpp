// fftess explain, end to end: the 16.16 facts of the power-of-two workaround (shared facts), JSON shapes as
// documented in docs/cli.md.
#include "run.h"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <set>

using clitest::run;
using nlohmann::json;

namespace {

// Checks the documented shape of `explain --why-pow2 --json`; returns the pairs.
json whyPow2(const std::string& partitioning) {
  const auto r = run({"explain", "--why-pow2", "--json", "--partitioning", partitioning});
  REQUIRE(r.status == 0);
  REQUIRE(r.err.empty());
  const json j = json::parse(r.out);
  REQUIRE(j.is_object());
  CHECK(j.at("version") == 2);
  CHECK(j.at("kind") == "explain_why_pow2");
  CHECK(j.at("partitioning") == partitioning);
  const json& pairs = j.at("pairs");
  REQUIRE(pairs.is_array());
  REQUIRE(pairs.size() == 63);
  int b = 2;
  for (const json& p : pairs) {
    INFO(p.dump());
    REQUIRE(p.is_object());
    CHECK(p.size() == 4);
    CHECK(p.at("big").is_number_integer());
    CHECK(p.at("big") == b);
    CHECK(p.at("small").is_number());
    CHECK(p.at("small").get<double>() == b / 2.0);
    CHECK(p.at("match").is_boolean());
    CHECK(p.at("worst_gap").is_number());
    CHECK(p.at("worst_gap").get<double>() >= 0);
    CHECK(p.at("match").get<bool>() == (p.at("worst_gap").get<double>() == 0));
    ++b;
  }
  return pairs;
}

double gapAt(const json& pairs, int big) { return pairs.at(static_cast<size_t>(big - 2)).at("worst_gap").get<double>(); }

// Checks the documented shape of `explain BIG SMALL --json`.
json explainJson(const std::vector<std::string>& args) {
  std::vector<std::string> all{"explain", "--json"};
  all.insert(all.end(), args.begin(), args.end());
  const auto r = run(all);
  REQUIRE(r.status == 0);
  const json j = json::parse(r.out);
  CHECK(j.at("version") == 2);
  CHECK(j.at("kind") == "explain");
  for (const char* side : {"big", "small"}) {
    const json& s = j.at(side);
    CHECK(s.at("points").is_number_integer());
    CHECK(s.at("fixed").is_array());
    CHECK(s.at("fixed").size() == s.at("points").get<size_t>());
    CHECK(s.at("fixed").front() == 0);
    CHECK(s.at("fixed").back() == 65536);
    CHECK(s.at("factor_bits").is_string());
  }
  CHECK(j.at("match").is_boolean());
  CHECK(j.at("worst_gap").is_number());
  CHECK(j.at("mismatches").is_number_integer());
  int mismatches = 0;
  for (const json& row : j.at("rows")) {
    CHECK((row.at("big").is_null() || row.at("big").at("edge") == "big"));
    CHECK((row.at("small").is_null() || row.at("small").at("edge") == "small1" ||
           row.at("small").at("edge") == "small2"));
    CHECK(row.at("causes").is_array());
    if (!row.at("match").get<bool>()) {
      ++mismatches;
      CHECK_FALSE(row.at("causes").empty());
    }
  }
  CHECK(mismatches == j.at("mismatches"));
  return j;
}

} // namespace

TEST_CASE("why-pow2, integer: only powers of two meet, 12 beside 6 misses by 1.5/65536", "[cli][explain]") {
  const json pairs = whyPow2("integer");
  std::set<int> meet;
  double worstEven = 0;
  std::set<int> worstAt;
  for (const json& p : pairs) {
    const int b = p.at("big");
    if (p.at("match").get<bool>()) meet.insert(b);
    if (b % 2 == 0) {
      const double g = p.at("worst_gap");
      if (g > worstEven) worstAt.clear(), worstEven = g;
      if (g == worstEven) worstAt.insert(b);
    }
  }
  CHECK(meet == std::set<int>{2, 4, 8, 16, 32, 64});
  CHECK(gapAt(pairs, 12) == 1.5);
  CHECK(gapAt(pairs, 14) == 1); // 14 * 4681 = 65534
  CHECK(worstEven == 9.5);
  CHECK(worstAt == std::set<int>{44, 54});
}

TEST_CASE("why-pow2, fractional_even: only 4, 8, 16, 32, 64 meet", "[cli][explain]") {
  const json pairs = whyPow2("fractional_even");
  std::set<int> meet;
  double worstOddS = 0;
  for (const json& p : pairs) {
    if (p.at("match").get<bool>()) meet.insert(p.at("big").get<int>());
    const int b = p.at("big");
    if (b % 4 == 2 && b > 2) worstOddS = std::max(worstOddS, p.at("worst_gap").get<double>());
  }
  CHECK(meet == std::set<int>{4, 8, 16, 32, 64});
  CHECK(gapAt(pairs, 2) == 16384); // S = 1 is clamped to 2: points at 1/4 and 3/4 the big edge lacks
  CHECK(worstOddS == 5461);         // odd S is fractional under even partitioning (shared facts: up to 5461/65536)
}

TEST_CASE("why-pow2 text table", "[cli][explain]") {
  const auto r = run({"explain", "--why-pow2"});
  REQUIRE(r.status == 0);
  CHECK(r.out.find("meet vertex for vertex: B = 2, 4, 8, 16, 32, 64 (6 of 63)") != std::string::npos);
  CHECK(r.out.find("9.5/65536 at B = 44, 54") != std::string::npos);
}

TEST_CASE("explain 12 6: every mismatch attributed to the 16.16 step that caused it", "[cli][explain]") {
  const json j = explainJson({"--partitioning", "integer", "12", "6"});
  CHECK_FALSE(j.at("match").get<bool>());
  CHECK(j.at("worst_gap") == 1.5);
  CHECK(j.at("big").at("points") == 13);
  CHECK(j.at("small").at("points") == 7);
  CHECK(j.at("big").at("reciprocal_floor") == 5461); // round(65536 / 12)
  CHECK(j.at("small").at("reciprocal_floor") == 10923);
  // Row 3: big 3*5461 = 16383 against the small edge's special-cased midpoint (t = 16384/65536).
  const json& row3 = j.at("rows").at(3);
  CHECK(row3.at("big").at("fixed") == 16383);
  CHECK(row3.at("small").at("fixed") == 32768);
  CHECK(row3.at("gap") == 1);
  std::set<std::string> causes(row3.at("causes").begin(), row3.at("causes").end());
  CHECK(causes.count("special_half") == 1);
  CHECK(causes.count("reciprocal_table") == 1);
  // Row 5: 5*5461 = 27305 against 65536 - 10923 = 54613 / 2 = 27306.5: the 1.5/65536 of the shared facts.
  const json& row5 = j.at("rows").at(5);
  CHECK(row5.at("big").at("fixed") == 27305);
  CHECK(row5.at("small").at("fixed") == 54613);
  CHECK(row5.at("gap") == 1.5);
  CHECK(row5.at("causes") == json::array({"reciprocal_table"}));
  // The middle and the ends meet.
  CHECK(j.at("rows").at(6).at("match") == true);
  CHECK(j.at("rows").at(0).at("match") == true);

  const auto text = run({"explain", "--partitioning", "integer", "12", "6"});
  REQUIRE(text.status == 0);
  CHECK(text.out.find("MISMATCH") != std::string::npos);
  CHECK(text.out.find("special-cased") != std::string::npos);
  CHECK(text.out.find("r(12) = 5461") != std::string::npos);
  CHECK(text.out.find("worst gap 1.5/65536") != std::string::npos);
}

TEST_CASE("explain 8 4 meets, fractional factors name placement or point counts", "[cli][explain]") {
  json j = explainJson({"8", "4"});
  CHECK(j.at("match") == true);
  CHECK(j.at("mismatches") == 0);
  CHECK(j.at("worst_gap") == 0);
  j = explainJson({"--partitioning", "fractional_even", "6", "3"});
  CHECK(j.at("match") == false);
  CHECK(j.at("worst_gap") == 5461);
  for (const json& row : j.at("rows"))
    if (!row.at("match").get<bool>()) CHECK(row.at("causes") == json::array({"point_count"}));
  j = explainJson({"--partitioning", "fractional_odd", "7.3", "3.65"});
  CHECK(j.at("match") == false);
  // Hex factors and hlsl stages are accepted too.
  j = explainJson({"--stage", "hlsl-avg", "--partitioning", "pow2", "0x41400000", "6"}); // pow2 rounds 12 up to 16
  CHECK(j.at("big").at("processed_factor") == 16);
  CHECK(j.at("small").at("processed_factor") == 8);
  CHECK(j.at("match") == true);
}
