// fftess explain: why an edge of factor BIG and two half-length edges of factor SMALL do (not) meet vertex for vertex,
// down to the 16.16 arithmetic step; and the --why-pow2 table over B = 2..64.
//
// The comparison and the causes come from tessellator/edge_analysis.h (compareHalfEdges); this file only prints them.
#include "commands.h"
#include "common.h"
#include "options.h"

#include <CLI/CLI.hpp>

#include "tessellator/batch.h"
#include "tessellator/edge_analysis.h"
#include "tessellator/names.h"
#include "tessellator/tessellator.h"
#include "tessellator/trace.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace fftess::cli {
namespace {

using json = nlohmann::ordered_json;

// num/den in lowest terms, den > 0.
Fraction lowest(int64_t num, int64_t den) {
  if (den < 0) num = -num, den = -den;
  const int64_t g = std::gcd(num, den);
  return Fraction{num / g, den / g};
}
Fraction halfOf(const Fraction& q, int64_t plus = 0) { return lowest(q.num + plus * q.den, 2 * q.den); }

std::string qText(const Fraction& q) {
  if (q.den == 1) return std::to_string(static_cast<long long>(q.num));
  return std::to_string(static_cast<long long>(q.num)) + "/" + std::to_string(static_cast<long long>(q.den));
}

std::string recipText(const EdgeTrace& tr, bool ceil) {
  const int n = ceil ? tr.ceilSegments : tr.floorSegments;
  const uint32_t r = ceil ? tr.reciprocalCeil : tr.reciprocalFloor;
  std::string s = "r(" + std::to_string(n) + ") = " + std::to_string(r);
  if (n > 0 && 65536 % n != 0) s += " (65536/" + std::to_string(n) + " = " + formatNumber(65536.0 / n) + ")";
  return s;
}

std::string pointFormula(const HalfEdgeSide& s, int index, const char* name) {
  const EdgePointTrace& p = s.trace.points[index];
  std::string out = std::string(name) + "#" + std::to_string(index) + " ";
  if (p.midpoint) return out + "= special-cased 0.5";
  std::string loc;
  if (s.trace.halfFraction == 0) {
    loc = std::to_string(p.indexOnFloor) + "*" + std::to_string(s.trace.reciprocalFloor);
  } else {
    loc = "lerp(" + std::to_string(p.indexOnFloor) + "*" + std::to_string(s.trace.reciprocalFloor) + ", " +
          std::to_string(p.indexOnCeil) + "*" + std::to_string(s.trace.reciprocalCeil) + ", " +
          std::to_string(s.trace.halfFraction) + "/65536) = " + std::to_string(p.halfLocation);
  }
  if (p.mirrored) return out + "= 65536 - " + loc;
  return out + "= " + loc;
}

bool has(const HalfEdgeRow& r, MismatchCause cause) {
  return std::find(r.causes.begin(), r.causes.end(), cause) != r.causes.end();
}

// The "why" of a mismatching row, from the causes and budgets compareHalfEdges found.
std::string whyText(const HalfEdgeComparison& c, const HalfEdgeRow& r) {
  if (r.match) return "";
  if (r.big < 0 || r.small < 0)
    return std::string(r.big >= 0 ? "big" : "small") + " edge has a point here and the other side has none (" +
           std::to_string(c.big.edge.count) + " points vs 2 x " + std::to_string(c.small.edge.count) + " - 1)";
  if (!r.attributed) return "(trace does not reproduce the point: no attribution)";
  const HalfEdgePoint& big = c.bigPoints[static_cast<size_t>(r.big)];
  const HalfEdgePoint& small = c.smallPoints[static_cast<size_t>(r.small)];
  const PointBudget& bb = r.bigBudget;
  const PointBudget& sb = r.smallBudget;
  if (has(r, MismatchCause::Placement))
    return "exact arithmetic already puts them apart (" + qText(bb.ideal) + " vs " +
           qText(halfOf(sb.ideal, small.edge == 2 ? 65536 : 0)) + " /65536): the factors' segments do not nest";
  std::vector<std::string> parts;
  if (has(r, MismatchCause::SpecialHalf))
    parts.push_back(std::string(bb.midpoint ? "big" : "small") +
                    " point is the special-cased exact 0.5; the other is " +
                    "computed (" + pointFormula(bb.midpoint ? c.small : c.big, bb.midpoint ? small.index : big.index,
                                                 bb.midpoint ? "small" : "big") + ")");
  if (has(r, MismatchCause::ReciprocalTable)) {
    const bool bR = !bb.reciprocalError.zero(), sR = !sb.reciprocalError.zero();
    std::string s = "reciprocal table: ";
    if (bR && sR)
      s += "big " + recipText(c.big.trace, false) + ", small " + recipText(c.small.trace, false) + ", 2*r(" +
           std::to_string(c.big.trace.floorSegments) + ") = " + std::to_string(2 * c.big.trace.reciprocalFloor);
    else if (bR)
      s += "big " + recipText(c.big.trace, false) + " is not exact";
    else
      s += "small " + recipText(c.small.trace, false) + " is not exact";
    if (bb.mirrored != sb.mirrored && !bb.midpoint && !sb.midpoint)
      s += std::string("; the ") + (bb.mirrored ? "big" : "small") +
           " point is mirrored (counted back from its edge's end), the other counted forward";
    s += " [error big " + qText(bb.reciprocalError) + ", small " + qText(halfOf(sb.reciprocalError)) + " (in 1/65536)]";
    parts.push_back(s);
  }
  if (has(r, MismatchCause::LerpRounding))
    parts.push_back("lerp rounded to 16.16 [error big " + qText(bb.lerpError) + ", small " +
                    qText(halfOf(sb.lerpError)) + " (in 1/65536)]");
  std::string why;
  for (size_t i = 0; i < parts.size(); ++i) why += (i ? "; " : "") + parts[i];
  return why;
}

// Value in 1/131072 units -> JSON number in 1/65536 units (exact: .5 steps).
// "version" of explain's JSON reports (kinds "explain" and "explain_why_pow2"; docs/schema); bumped on any change of
// their schema. 2: the envelope ("fftess_version"; --why-pow2's "kind" "explain_why_pow2").
constexpr int kExplainReportVersion = 2;

json units(int64_t u2) { return u2 % 2 == 0 ? json(u2 / 2) : json(static_cast<double>(u2) / 2.0); }
std::string unitsText(int64_t u2) {
  bool neg = u2 < 0;
  uint64_t a = static_cast<uint64_t>(neg ? -u2 : u2);
  return (neg ? "-" : "") + std::to_string(a / 2) + (a % 2 ? ".5" : "");
}

std::string edgeSummary(const HalfEdgeSide& s) {
  const EdgeTrace& t = s.trace;
  std::string out = "factor " + formatFloat(s.factor);
  if (t.hlslFactor != t.input && !(std::isnan(t.hlslFactor) && std::isnan(t.input)))
    out += " -> HLSL " + formatFloat(t.hlslFactor);
  out += " -> " + formatFloat(s.edge.processedFactor) + " (16.16 " + fixed16(s.edge.fixedFactor) + ", " +
         (s.edge.oddParity ? "odd" : "even") + " parity), " + std::to_string(s.edge.count) + " points; " +
         recipText(t, false);
  if (t.ceilSegments != t.floorSegments) out += ", " + recipText(t, true) + ", half fraction " + std::to_string(t.halfFraction) + "/65536";
  return out;
}

json sideJson(const HalfEdgeSide& s) {
  json j;
  j["factor"] = std::isfinite(s.factor) ? json(s.factor) : json(formatFloat(s.factor));
  j["factor_bits"] = hex8(bitsOf(s.factor));
  j["culled"] = s.edge.culled;
  j["processed_factor"] = s.edge.processedFactor;
  j["fixed_factor"] = s.edge.fixedFactor;
  j["odd_parity"] = s.edge.oddParity;
  j["points"] = s.edge.count;
  j["floor_segments"] = s.trace.floorSegments;
  j["ceil_segments"] = s.trace.ceilSegments;
  j["reciprocal_floor"] = s.trace.reciprocalFloor;
  j["reciprocal_ceil"] = s.trace.reciprocalCeil;
  j["half_fraction"] = s.trace.halfFraction;
  json fx = json::array();
  for (int i = 0; i < s.edge.count; ++i) fx.push_back(s.edge.fixed[i]);
  j["fixed"] = fx;
  return j;
}

json pointJson(const HalfEdgePoint* p) {
  if (!p) return nullptr;
  json j;
  j["edge"] = p->edge == 0 ? "big" : p->edge == 1 ? "small1" : "small2";
  j["index"] = p->index;
  j["fixed"] = p->fixed;
  j["t"] = units(p->t);
  return j;
}

int explainPair(const ExplainArgs& a, Partitioning part, const Stage& stage) {
  if (a.factors.size() != 2) throw UsageError("explain: give BIG and SMALL factors, or --why-pow2 (see fftess explain --help)");
  float f[2];
  for (int i = 0; i < 2; ++i) {
    std::string why;
    if (!fftess::parseFactor(a.factors[i], f[i], &why))
      throw UsageError(std::string("explain: ") + (i ? "SMALL" : "BIG") + " " + quoteToken(a.factors[i]) + ": " + why);
  }
  const HalfEdgeComparison c = compareHalfEdges(f[0], f[1], part, stage);
  if (a.json) {
    json j;
    j["version"] = kExplainReportVersion;
    j["kind"] = "explain";
    j["fftess_version"] = FFTESS_VERSION;
    j["partitioning"] = toString(part);
    j["stage"] = toString(stage);
    j["big"] = sideJson(c.big);
    j["small"] = sideJson(c.small);
    j["culled"] = c.culled;
    j["match"] = c.match;
    j["worst_gap"] = units(c.worstGap);
    j["mismatches"] = c.mismatches;
    json rows = json::array();
    for (const HalfEdgeRow& r : c.rows) {
      json jr;
      jr["big"] = pointJson(r.big >= 0 ? &c.bigPoints[static_cast<size_t>(r.big)] : nullptr);
      jr["small"] = pointJson(r.small >= 0 ? &c.smallPoints[static_cast<size_t>(r.small)] : nullptr);
      jr["match"] = r.match;
      jr["gap"] = units(r.gap);
      json causes = json::array();
      for (MismatchCause cause : r.causes) causes.push_back(toString(cause));
      jr["causes"] = causes;
      jr["why"] = whyText(c, r);
      rows.push_back(jr);
    }
    j["rows"] = rows;
    writeStdout(j.dump(2) + "\n");
    return kExitClean;
  }
  std::string o;
  o += "Edge of factor " + formatFloat(f[0]) + " beside two half-length edges of factor " + formatFloat(f[1]) + " (" +
       toString(part) + ", " + toString(stage) + " stage)\n";
  o += "  big:   " + edgeSummary(c.big) + "\n";
  o += "  small: " + edgeSummary(c.small) + "\n";
  if (c.culled) {
    o += "  culled: a factor that is not > 0 culls its patch; there is no edge to compare\n";
    writeStdout(o);
    return kExitClean;
  }
  o += "  t = position along the big edge in 1/65536 of it: big t = v, small t = v/2 (A) and 1/2 + v/2 (B)\n\n";
  char buf[256];
  std::snprintf(buf, sizeof buf, "  %-4s %-11s %-10s | %-5s %-11s %-10s | %-8s %s\n", "big", "16.16", "t", "small",
                "16.16", "t", "gap", "");
  o += buf;
  for (const HalfEdgeRow& row : c.rows) {
    const HalfEdgeRow& r = row;
    const HalfEdgePoint* big = r.big >= 0 ? &c.bigPoints[static_cast<size_t>(r.big)] : nullptr;
    const HalfEdgePoint* small = r.small >= 0 ? &c.smallPoints[static_cast<size_t>(r.small)] : nullptr;
    std::string bIdx = big ? std::to_string(big->index) : "", bFx = big ? fixed16(big->fixed) : "",
                bT = big ? unitsText(big->t) : "";
    std::string sIdx = small ? std::string(small->edge == 1 ? "A" : "B") + std::to_string(small->index) : "",
                sFx = small ? fixed16(small->fixed) : "", sT = small ? unitsText(small->t) : "";
    std::string gap = r.match ? "" : (r.gap > 0 && big && small ? "+" : "") + unitsText(r.gap);
    std::snprintf(buf, sizeof buf, "  %-4s %-11s %-10s | %-5s %-11s %-10s | %-8s %s\n", bIdx.c_str(), bFx.c_str(),
                  bT.c_str(), sIdx.c_str(), sFx.c_str(), sT.c_str(), gap.c_str(), r.match ? "" : "MISMATCH");
    o += buf;
    if (!r.match) {
      const std::string why = whyText(c, r);
      if (!why.empty()) o += "       why: " + why + "\n";
    }
  }
  o += "\n";
  if (c.match) {
    o += "verdict: the sides meet vertex for vertex (" + std::to_string(c.big.edge.count) + " points)\n";
  } else {
    o += "verdict: crack: " + std::to_string(c.mismatches) + " of " + std::to_string(c.rows.size()) +
         " rows mismatch; worst gap " + unitsText(c.worstGap) + "/65536 of the big edge (at t = " + unitsText(c.worstAt) +
         "/65536)\n";
  }
  writeStdout(o);
  return kExitClean;
}

int whyPow2(const ExplainArgs& a, Partitioning part, const Stage& stage) {
  if (!a.factors.empty()) throw UsageError("explain --why-pow2 takes no BIG SMALL arguments");
  struct Entry {
    int big;
    float small;
    HalfEdgeComparison c;
  };
  std::vector<Entry> entries;
  for (int b = 2; b <= a.maxBig; ++b) {
    // S = B/2 exactly (a real number for odd B): the smaller patch takes half its neighbour's factor.
    const float s = static_cast<float>(b) / 2.0f;
    entries.push_back({b, s, compareHalfEdges(static_cast<float>(b), s, part, stage)});
  }
  if (a.json) {
    json j;
    j["version"] = kExplainReportVersion;
    j["kind"] = "explain_why_pow2";
    j["fftess_version"] = FFTESS_VERSION;
    j["partitioning"] = toString(part);
    j["stage"] = toString(stage);
    json pairs = json::array();
    for (const Entry& e : entries) {
      json p;
      p["big"] = e.big;
      p["small"] = e.small;
      p["match"] = e.c.match;
      p["worst_gap"] = units(e.c.worstGap);
      pairs.push_back(p);
    }
    j["pairs"] = pairs;
    writeStdout(j.dump(2) + "\n");
    return kExitClean;
  }
  std::string o;
  o += "Edge of factor B beside two half-length edges of factor S = B/2 (" + std::string(toString(part)) + ", " +
       toString(stage) + " stage)\n";
  o += "gap = worst distance between the two sides' points, in 1/65536 of the big edge\n\n";
  char buf[200];
  std::snprintf(buf, sizeof buf, "  %3s %5s  %6s %6s  %7s %7s  %6s %6s  %-5s %s\n", "B", "S", "pts B", "pts S", "r(B)",
                "B*r(B)", "r(S)", "2r(B)", "meet", "gap");
  o += buf;
  std::vector<int> ok;
  for (const Entry& e : entries) {
    const EdgeTrace& tb = e.c.big.trace;
    const EdgeTrace& ts = e.c.small.trace;
    std::snprintf(buf, sizeof buf, "  %3d %5s  %6d %6d  %7u %7lld  %6u %6u  %-5s %s\n", e.big, formatFloat(e.small).c_str(),
                  e.c.big.edge.count, e.c.small.edge.count, tb.reciprocalFloor,
                  static_cast<long long>(tb.floorSegments) * tb.reciprocalFloor, ts.reciprocalFloor,
                  2 * tb.reciprocalFloor, e.c.match ? "yes" : "no", e.c.match ? "0" : unitsText(e.c.worstGap).c_str());
    o += buf;
    if (e.c.match) ok.push_back(e.big);
  }
  o += "\nmeet vertex for vertex: B =";
  for (size_t i = 0; i < ok.size(); ++i) o += (i ? ", " : " ") + std::to_string(ok[i]);
  if (ok.empty()) o += " none";
  o += " (" + std::to_string(ok.size()) + " of " + std::to_string(entries.size()) + ")\n";
  for (int parity = 0; parity < 2; ++parity) {
    int64_t w = 0;
    std::vector<int> at;
    for (const Entry& e : entries) {
      if (e.big % 2 != parity) continue;
      if (e.c.worstGap > w) { w = e.c.worstGap; at.clear(); }
      if (e.c.worstGap == w && w > 0) at.push_back(e.big);
    }
    o += std::string("worst gap, ") + (parity ? "odd B:  " : "even B: ") + unitsText(w) + "/65536";
    if (!at.empty()) o += " at B =";
    for (size_t i = 0; i < at.size(); ++i) o += (i ? ", " : " ") + std::to_string(at[i]);
    o += "\n";
  }
  o += "\n";
  o += "Why: the point i of an n-segment edge before its middle sits at i*r(n), r(n) = round(65536/n) (the reciprocal\n"
       "table); the second half is mirrored as 65536 - (n-i)*r(n); the exact middle is special-cased to 0.5.\n"
       "Two half edges of S meet an edge of 2S only if r(S) = 2*r(2S) (first quarter) and 2S*r(2S) = 65536 (the first\n"
       "small edge counts back from the big edge's middle). The second holds only if 2S divides 65536: a power of two.\n"
       "Odd B never meets: an odd number of segments has no point at 1/2, where the two small edges join.\n";
  if (part == Partitioning::FractionalEven || part == Partitioning::FractionalOdd)
    o += "Under " + std::string(toString(part)) + " the factor is clamped to its minimum (fractional_even: 2) and a\n"
         "factor of the wrong parity is fractional: it adds two short segments, so the point counts differ.\n";
  o += 
       "Details for one pair: fftess explain --partitioning " + std::string(toString(part)) + " 12 6\n";
  writeStdout(o);
  return kExitClean;
}

} // namespace

CLI::App* addExplain(CLI::App& app, ExplainArgs& a) {
  CLI::App* sub = app.add_subcommand(
      "explain", "Explain, down to the 16.16 arithmetic, why an edge of factor BIG and two half-length edges of "
                 "factor SMALL do or do not meet vertex for vertex");
  sub->footer("Examples:\n"
              "  fftess explain --partitioning integer 12 6\n"
              "  fftess explain --why-pow2\n"
              "  fftess explain --why-pow2 --partitioning fractional_even --json");
  sub->add_option("factors", a.factors, "BIG SMALL: the factors (decimal, or 0x + 8 hex digits)")->expected(0, 2);
  sub->add_option("-p,--partitioning", a.partitioning, "Partitioning")
      ->check(choiceOf(partitioningNames()))
      ->capture_default_str();
  sub->add_option("--stage", a.stage, "Stage the factors enter: hw, or an hlsl-* stage (edge preconditioning)")
      ->check(choiceOf(stageNames()))
      ->capture_default_str();
  sub->add_flag("--why-pow2", a.whyPow2, "Table of B = 2..64 against S = B/2: which pairs meet, worst gap");
  sub->add_flag("--json", a.json, "Machine-readable output on stdout (schema in docs/cli.md)");
  return sub;
}

int runExplain(const ExplainArgs& a) {
  Partitioning part;
  if (!parsePartitioning(a.partitioning.c_str(), part))
    throw UsageError("explain: --partitioning " + quoteToken(a.partitioning) + " is not a partitioning");
  Stage stage;
  if (!parseStage(a.stage.c_str(), stage)) throw UsageError("explain: --stage " + quoteToken(a.stage) + " is not a stage");
  const int status = a.whyPow2 ? whyPow2(a, part, stage) : explainPair(a, part, stage);
  flushStdout(); // a stdout that cannot be written is an error (exit 3), not a silent success
  return status;
}

} // namespace fftess::cli
