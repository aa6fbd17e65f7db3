// fftess explain: why an edge of factor BIG and two half-length edges of factor SMALL do (not) meet vertex for vertex,
// down to the 16.16 arithmetic step; and the --why-pow2 table over B = 2..64.
//
// Comparison (shared facts, "Where the power-of-two workaround comes from"): map both sides onto the big edge's
// parameter t: big t = v; first small edge t = v1/2; second small edge t = 1/2 + v2/2. All values are 16.16 fixed
// point, so t is an integer in units of 1/131072 of the big edge and the comparison is exact.
#include "commands.h"
#include "common.h"

#include "tessellator/batch.h"
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
__extension__ typedef __int128 i128;

// Exact rational (numerator/denominator, denominator > 0), enough for 16.16 values times segment counts <= 64.
struct Q {
  i128 n = 0;
  i128 d = 1;
  static i128 g(i128 a, i128 b) {
    if (a < 0) a = -a;
    while (b != 0) {
      i128 t = a % b;
      a = b;
      b = t;
    }
    return a == 0 ? 1 : a;
  }
  Q() = default;
  Q(i128 num, i128 den = 1) : n(num), d(den) {
    if (d < 0) { n = -n; d = -d; }
    i128 k = g(n, d);
    n /= k;
    d /= k;
  }
  friend Q operator+(Q a, Q b) { return Q(a.n * b.d + b.n * a.d, a.d * b.d); }
  friend Q operator-(Q a, Q b) { return Q(a.n * b.d - b.n * a.d, a.d * b.d); }
  friend Q operator*(Q a, Q b) { return Q(a.n * b.n, a.d * b.d); }
  friend bool operator==(Q a, Q b) { return a.n == b.n && a.d == b.d; }
  friend bool operator!=(Q a, Q b) { return !(a == b); }
  bool zero() const { return n == 0; }
  double value() const { return static_cast<double>(n) / static_cast<double>(d); }
};

std::string qText(Q q) {
  if (q.d == 1) return std::to_string(static_cast<long long>(q.n));
  return std::to_string(static_cast<long long>(q.n)) + "/" + std::to_string(static_cast<long long>(q.d));
}

// One point of one side, placed on the big edge.
struct Pt {
  int64_t t = 0;      // 1/131072 of the big edge
  int edge = 0;       // 0 = big, 1 = first small edge, 2 = second small edge
  int index = 0;      // index along its own edge
  uint32_t fixed = 0; // 16.16 on its own edge
};

// Error budget of one point relative to exact arithmetic, in 16.16 units of its own edge (signed as it acts on the
// final value, i.e. already negated for mirrored points).
struct PointBudget {
  bool midpoint = false;
  bool mirrored = false;
  Q ideal;            // exact-arithmetic position (exact reciprocals, unrounded lerp), 16.16 units
  Q reciprocalError;  // index * (table entry - 65536/segments), lerped
  Q lerpError;        // rounding of the 32.32 lerp back to 16.16
  bool consistent = true; // ideal + errors reproduces the tessellator's value (trace self-check)
};

struct Side {
  float factor = 0;
  EdgePoints e;
  EdgeTrace tr;
};

PointBudget budget(const EdgeTrace& tr, int index) {
  const EdgePointTrace& p = tr.points[index];
  PointBudget b;
  b.midpoint = p.midpoint;
  b.mirrored = p.mirrored;
  if (p.midpoint) {
    b.ideal = Q(32768);
    b.consistent = p.fixed == 0x8000u;
    return b;
  }
  const Q frac(tr.halfFraction, 65536);
  const Q oneMinus = Q(1) - frac;
  Q exactFloor = tr.floorSegments > 0 ? Q(static_cast<i128>(p.indexOnFloor) * 65536, tr.floorSegments) : Q(0);
  Q exactCeil = tr.ceilSegments > 0 ? Q(static_cast<i128>(p.indexOnCeil) * 65536, tr.ceilSegments) : Q(0);
  Q loc = exactFloor * oneMinus + exactCeil * frac;
  Q recip = (Q(static_cast<i128>(p.locationOnFloor)) - exactFloor) * oneMinus +
            (Q(static_cast<i128>(p.locationOnCeil)) - exactCeil) * frac;
  Q lerp = Q(static_cast<i128>(p.halfLocation)) - Q(static_cast<i128>(p.lerp), 65536);
  if (p.mirrored) {
    b.ideal = Q(65536) - loc;
    b.reciprocalError = Q(0) - recip;
    b.lerpError = Q(0) - lerp;
  } else {
    b.ideal = loc;
    b.reciprocalError = recip;
    b.lerpError = lerp;
  }
  b.consistent = b.ideal + b.reciprocalError + b.lerpError == Q(static_cast<i128>(p.fixed));
  return b;
}

// Scale from a side's own 16.16 units to 1/131072 of the big edge.
Q offsetOf(int edge) { return edge == 2 ? Q(65536) : Q(0); }

struct Row {
  // Positions in Comparison::bigPts / smallPts (-1: none), so a Comparison can be copied.
  int bi = -1;
  int si = -1;
  int64_t gap = 0; // 1/131072 units: small - big when paired, distance to the nearest other-side point otherwise
  bool match = true;
  std::vector<std::string> causes; // reciprocal_table, lerp_rounding, special_half, placement, point_count
  std::string why;
};

struct Comparison {
  Side big, small;
  bool culled = false;
  bool paired = false; // same number of points on both sides: rows pair points in order
  std::vector<Pt> bigPts, smallPts;
  std::vector<Row> rows;
  bool match = true;
  int64_t worstGap = 0; // 1/131072 units (Hausdorff distance of the two point sets along the edge)
  int64_t worstAt = 0;
  int mismatches = 0;
};

std::string recipText(const EdgeTrace& tr, bool ceil) {
  const int n = ceil ? tr.ceilSegments : tr.floorSegments;
  const uint32_t r = ceil ? tr.reciprocalCeil : tr.reciprocalFloor;
  std::string s = "r(" + std::to_string(n) + ") = " + std::to_string(r);
  if (n > 0 && 65536 % n != 0) s += " (65536/" + std::to_string(n) + " = " + formatNumber(65536.0 / n) + ")";
  return s;
}

std::string pointFormula(const Side& s, int index, const char* name) {
  const EdgePointTrace& p = s.tr.points[index];
  std::string out = std::string(name) + "#" + std::to_string(index) + " ";
  if (p.midpoint) return out + "= special-cased 0.5";
  std::string loc;
  if (s.tr.halfFraction == 0) {
    loc = std::to_string(p.indexOnFloor) + "*" + std::to_string(s.tr.reciprocalFloor);
  } else {
    loc = "lerp(" + std::to_string(p.indexOnFloor) + "*" + std::to_string(s.tr.reciprocalFloor) + ", " +
          std::to_string(p.indexOnCeil) + "*" + std::to_string(s.tr.reciprocalCeil) + ", " +
          std::to_string(s.tr.halfFraction) + "/65536) = " + std::to_string(p.halfLocation);
  }
  if (p.mirrored) return out + "= 65536 - " + loc;
  return out + "= " + loc;
}

void attribute(Comparison& c, Row& r) {
  const Pt* big = r.bi >= 0 ? &c.bigPts[static_cast<size_t>(r.bi)] : nullptr;
  const Pt* small = r.si >= 0 ? &c.smallPts[static_cast<size_t>(r.si)] : nullptr;
  if (big == nullptr || small == nullptr) {
    r.causes.push_back("point_count");
    r.why = std::string(big ? "big" : "small") + " edge has a point here and the other side has none (" +
            std::to_string(c.big.e.count) + " points vs 2 x " + std::to_string(c.small.e.count) + " - 1)";
    return;
  }
  const PointBudget bb = budget(c.big.tr, big->index);
  const PointBudget sb = budget(c.small.tr, small->index);
  if (!bb.consistent || !sb.consistent) {
    r.why = "(trace does not reproduce the point: no attribution)";
    return;
  }
  // Everything in 1/131072 of the big edge.
  const Q bigIdeal = bb.ideal * Q(2);
  const Q smallIdeal = sb.ideal + offsetOf(small->edge);
  if (bigIdeal != smallIdeal) {
    r.causes.push_back("placement");
    r.why = "exact arithmetic already puts them apart (" + qText(bigIdeal * Q(1, 2)) + " vs " +
            qText(smallIdeal * Q(1, 2)) + " /65536): the factors' segments do not nest";
    return;
  }
  std::vector<std::string> parts;
  const Q bR = bb.reciprocalError * Q(2), sR = sb.reciprocalError, bL = bb.lerpError * Q(2), sL = sb.lerpError;
  if (bb.midpoint != sb.midpoint) {
    r.causes.push_back("special_half");
    parts.push_back(std::string(bb.midpoint ? "big" : "small") + " point is the special-cased exact 0.5; the other is " +
                    "computed (" + pointFormula(bb.midpoint ? c.small : c.big,
                                                 bb.midpoint ? small->index : big->index,
                                                 bb.midpoint ? "small" : "big") + ")");
  }
  if (!bR.zero() || !sR.zero()) {
    r.causes.push_back("reciprocal_table");
    std::string s = "reciprocal table: ";
    if (!bR.zero() && !sR.zero())
      s += "big " + recipText(c.big.tr, false) + ", small " + recipText(c.small.tr, false) + ", 2*r(" +
           std::to_string(c.big.tr.floorSegments) + ") = " + std::to_string(2 * c.big.tr.reciprocalFloor);
    else if (!bR.zero())
      s += "big " + recipText(c.big.tr, false) + " is not exact";
    else
      s += "small " + recipText(c.small.tr, false) + " is not exact";
    if (bb.mirrored != sb.mirrored && !bb.midpoint && !sb.midpoint)
      s += std::string("; the ") + (bb.mirrored ? "big" : "small") +
           " point is mirrored (counted back from its edge's end), the other counted forward";
    s += " [error big " + qText(bR * Q(1, 2)) + ", small " + qText(sR * Q(1, 2)) + " (in 1/65536)]";
    parts.push_back(s);
  }
  if (!bL.zero() || !sL.zero()) {
    r.causes.push_back("lerp_rounding");
    parts.push_back("lerp rounded to 16.16 [error big " + qText(bL * Q(1, 2)) + ", small " + qText(sL * Q(1, 2)) +
                    " (in 1/65536)]");
  }
  for (size_t i = 0; i < parts.size(); ++i) r.why += (i ? "; " : "") + parts[i];
}

Comparison compare(float bigF, float smallF, Partitioning part, const Stage& stage) {
  Comparison c;
  c.big.factor = bigF;
  c.small.factor = smallF;
  c.big.e = edgePoints(bigF, part, stage);
  c.small.e = edgePoints(smallF, part, stage);
  c.big.tr = traceEdge(bigF, part, stage);
  c.small.tr = traceEdge(smallF, part, stage);
  if (c.big.e.culled || c.small.e.culled) {
    c.culled = true;
    c.match = false;
    return c;
  }
  for (int i = 0; i < c.big.e.count; ++i) c.bigPts.push_back({2 * static_cast<int64_t>(c.big.e.fixed[i]), 0, i, c.big.e.fixed[i]});
  for (int i = 0; i < c.small.e.count; ++i) c.smallPts.push_back({c.small.e.fixed[i], 1, i, c.small.e.fixed[i]});
  for (int i = 1; i < c.small.e.count; ++i)
    c.smallPts.push_back({65536 + static_cast<int64_t>(c.small.e.fixed[i]), 2, i, c.small.e.fixed[i]});

  auto nearest = [](const std::vector<Pt>& v, int64_t t) {
    int64_t best = INT64_MAX;
    for (const Pt& p : v) best = std::min(best, p.t > t ? p.t - t : t - p.t);
    return best;
  };
  for (const Pt& p : c.bigPts) {
    int64_t d = nearest(c.smallPts, p.t);
    if (d > c.worstGap) { c.worstGap = d; c.worstAt = p.t; }
  }
  for (const Pt& p : c.smallPts) {
    int64_t d = nearest(c.bigPts, p.t);
    if (d > c.worstGap) { c.worstGap = d; c.worstAt = p.t; }
  }
  c.match = c.worstGap == 0 && c.bigPts.size() == c.smallPts.size();
  c.paired = c.bigPts.size() == c.smallPts.size();
  if (c.paired) {
    for (size_t i = 0; i < c.bigPts.size(); ++i) {
      Row r;
      r.bi = static_cast<int>(i);
      r.si = static_cast<int>(i);
      r.gap = c.smallPts[i].t - c.bigPts[i].t;
      r.match = r.gap == 0;
      c.rows.push_back(r);
    }
  } else {
    size_t i = 0, j = 0;
    while (i < c.bigPts.size() || j < c.smallPts.size()) {
      Row r;
      if (j >= c.smallPts.size() || (i < c.bigPts.size() && c.bigPts[i].t < c.smallPts[j].t)) {
        r.bi = static_cast<int>(i);
        r.gap = nearest(c.smallPts, c.bigPts[i++].t);
      } else if (i >= c.bigPts.size() || c.smallPts[j].t < c.bigPts[i].t) {
        r.si = static_cast<int>(j);
        r.gap = nearest(c.bigPts, c.smallPts[j++].t);
      } else {
        r.bi = static_cast<int>(i++);
        r.si = static_cast<int>(j++);
      }
      r.match = r.bi >= 0 && r.si >= 0;
      c.rows.push_back(r);
    }
  }
  for (Row& r : c.rows) {
    if (r.match) continue;
    ++c.mismatches;
    attribute(c, r);
  }
  return c;
}

// Value in 1/131072 units -> JSON number in 1/65536 units (exact: .5 steps).
json units(int64_t u2) { return u2 % 2 == 0 ? json(u2 / 2) : json(static_cast<double>(u2) / 2.0); }
std::string unitsText(int64_t u2) {
  bool neg = u2 < 0;
  uint64_t a = static_cast<uint64_t>(neg ? -u2 : u2);
  return (neg ? "-" : "") + std::to_string(a / 2) + (a % 2 ? ".5" : "");
}

std::string edgeSummary(const Side& s) {
  const EdgeTrace& t = s.tr;
  std::string out = "factor " + formatFloat(s.factor);
  if (t.hlslFactor != t.input && !(std::isnan(t.hlslFactor) && std::isnan(t.input)))
    out += " -> HLSL " + formatFloat(t.hlslFactor);
  out += " -> " + formatFloat(s.e.processedFactor) + " (16.16 " + fixed16(s.e.fixedFactor) + ", " +
         (s.e.oddParity ? "odd" : "even") + " parity), " + std::to_string(s.e.count) + " points; " +
         recipText(t, false);
  if (t.ceilSegments != t.floorSegments) out += ", " + recipText(t, true) + ", half fraction " + std::to_string(t.halfFraction) + "/65536";
  return out;
}

json sideJson(const Side& s) {
  json j;
  j["factor"] = std::isfinite(s.factor) ? json(s.factor) : json(formatFloat(s.factor));
  j["factor_bits"] = hex8(floatBits(s.factor));
  j["culled"] = s.e.culled;
  j["processed_factor"] = s.e.processedFactor;
  j["fixed_factor"] = s.e.fixedFactor;
  j["odd_parity"] = s.e.oddParity;
  j["points"] = s.e.count;
  j["floor_segments"] = s.tr.floorSegments;
  j["ceil_segments"] = s.tr.ceilSegments;
  j["reciprocal_floor"] = s.tr.reciprocalFloor;
  j["reciprocal_ceil"] = s.tr.reciprocalCeil;
  j["half_fraction"] = s.tr.halfFraction;
  json fx = json::array();
  for (int i = 0; i < s.e.count; ++i) fx.push_back(s.e.fixed[i]);
  j["fixed"] = fx;
  return j;
}

json pointJson(const Pt* p) {
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
  Comparison c = compare(f[0], f[1], part, stage);
  if (a.json) {
    json j;
    j["version"] = 1;
    j["kind"] = "explain";
    j["partitioning"] = toString(part);
    j["stage"] = toString(stage);
    j["big"] = sideJson(c.big);
    j["small"] = sideJson(c.small);
    j["culled"] = c.culled;
    j["match"] = c.match;
    j["worst_gap"] = units(c.worstGap);
    j["mismatches"] = c.mismatches;
    json rows = json::array();
    for (const Row& r : c.rows) {
      json jr;
      jr["big"] = pointJson(r.bi >= 0 ? &c.bigPts[static_cast<size_t>(r.bi)] : nullptr);
      jr["small"] = pointJson(r.si >= 0 ? &c.smallPts[static_cast<size_t>(r.si)] : nullptr);
      jr["match"] = r.match;
      jr["gap"] = units(r.gap);
      jr["causes"] = r.causes;
      jr["why"] = r.why;
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
  for (const Row& row : c.rows) {
    const Row& r = row;
    const Pt* big = r.bi >= 0 ? &c.bigPts[static_cast<size_t>(r.bi)] : nullptr;
    const Pt* small = r.si >= 0 ? &c.smallPts[static_cast<size_t>(r.si)] : nullptr;
    std::string bIdx = big ? std::to_string(big->index) : "", bFx = big ? fixed16(big->fixed) : "",
                bT = big ? unitsText(big->t) : "";
    std::string sIdx = small ? std::string(small->edge == 1 ? "A" : "B") + std::to_string(small->index) : "",
                sFx = small ? fixed16(small->fixed) : "", sT = small ? unitsText(small->t) : "";
    std::string gap = r.match ? "" : (r.gap > 0 && big && small ? "+" : "") + unitsText(r.gap);
    std::snprintf(buf, sizeof buf, "  %-4s %-11s %-10s | %-5s %-11s %-10s | %-8s %s\n", bIdx.c_str(), bFx.c_str(),
                  bT.c_str(), sIdx.c_str(), sFx.c_str(), sT.c_str(), gap.c_str(), r.match ? "" : "MISMATCH");
    o += buf;
    if (!r.match && !r.why.empty()) o += "       why: " + r.why + "\n";
  }
  o += "\n";
  if (c.match) {
    o += "verdict: the sides meet vertex for vertex (" + std::to_string(c.big.e.count) + " points)\n";
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
    Comparison c;
  };
  std::vector<Entry> entries;
  for (int b = 2; b <= a.maxBig; ++b) {
    // S = B/2 exactly (a real number for odd B): the smaller patch takes half its neighbour's factor.
    const float s = static_cast<float>(b) / 2.0f;
    entries.push_back({b, s, compare(static_cast<float>(b), s, part, stage)});
  }
  if (a.json) {
    json j;
    j["version"] = 1;
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
    const EdgeTrace& tb = e.c.big.tr;
    const EdgeTrace& ts = e.c.small.tr;
    std::snprintf(buf, sizeof buf, "  %3d %5s  %6d %6d  %7u %7lld  %6u %6u  %-5s %s\n", e.big, formatFloat(e.small).c_str(),
                  e.c.big.e.count, e.c.small.e.count, tb.reciprocalFloor,
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
      ->check(CLI::IsMember(partitioningNames()))
      ->capture_default_str();
  sub->add_option("--stage", a.stage, "Stage the factors enter: hw, or an hlsl-* stage (edge preconditioning)")
      ->check(CLI::IsMember(stageNames()))
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
  return a.whyPow2 ? whyPow2(a, part, stage) : explainPair(a, part, stage);
}

} // namespace fftess::cli
