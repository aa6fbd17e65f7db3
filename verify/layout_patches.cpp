// layout.kind = "patches" (verify/internal.h): the squares of layout.file on their exact integer lattice, checked to
// tile their bounding rectangle (no overlap, no gap, nesting edges) and linked. docs/verify.md, "Patches".
//
// The lattice: every coordinate is a float, so its difference from the terrain's lowest x (z) is a dyadic rational,
// exact in double (checked: exactDifference). The base unit is the largest power of two dividing all of them; each
// patch's lower corner and side are then integers (ux, uz, size) in that unit, and everything the layout decides
// (overlaps, gaps, neighbours) is decided on those integers. The corners the checker and the domain shader use are
// the file's floats, unchanged.
#include "verify/internal.h"

#include <algorithm>
#include <cfloat>
#include <cstdio>
#include <map>

namespace fftess::verify::detail {

bool exactDifference(float a, float b, double& d) {
  const double x = a, y = -static_cast<double>(b);
  d = x + y; // TwoSum (Knuth): the rounding error of x + y is exactly (x - xv) + (y - yv)
  const double yv = d - x, xv = d - yv;
  return (x - xv) + (y - yv) == 0;
}

namespace {

constexpr double kMaxUnits = 0x1p40; // lattice steps across the terrain (int64 sums and products stay exact)
constexpr int64_t kMaxSize = int64_t(1) << 29; // a side in lattice steps (check.cpp decides shared parts exactly below)

const char* const kEdgeNames[4] = {"-x", "-z", "+x", "+z"}; // FactorIndex order: Ueq0 Veq0 Ueq1 Veq1

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// The exponent of the lowest set bit of d > 0 (d = odd * 2^result).
int lowestBit(double d) {
  int e;
  const double m = std::frexp(d, &e); // d = m * 2^e, m in [0.5, 1)
  const uint64_t mant = static_cast<uint64_t>(std::ldexp(m, 53)); // exact: a double has 53 bits
  return e - 53 + __builtin_ctzll(mant);
}

struct Lattice {
  const Layout& L;
  const std::vector<LayoutPatch>& list;
  TerrainData& t;
  std::string& error;
  float minX = 0, minZ = 0, maxX = 0, maxZ = 0;

  std::string at(size_t i) const { return L.file + ":" + std::to_string(list[i].line); }
  std::string square(size_t i) const {
    const LayoutPatch& p = list[i];
    return "x " + num(p.corners[0].x) + " .. " + num(p.corners[1].x) + ", z " + num(p.corners[0].y) + " .. " +
           num(p.corners[2].y);
  }
  bool fail(size_t i, const std::string& msg) {
    error = at(i) + ": " + msg;
    return false;
  }

  bool step(double& unit);
  bool place(double unit);
  bool limits(const Scene& s, double unit);
  bool noOverlap();
  bool noGap();
};

// The base unit (a power of two): the largest dividing every coordinate's difference from the lowest one.
bool Lattice::step(double& unit) {
  int exp = INT32_MAX;
  size_t finest = 0;
  for (size_t i = 0; i < list.size(); ++i)
    for (int c = 0; c < 4; ++c) {
      double dx, dz;
      if (!exactDifference(list[i].corners[c].x, minX, dx) || !exactDifference(list[i].corners[c].y, minZ, dz))
        return fail(i, "no exact lattice: the patch's coordinates (" + square(i) + ") and the terrain's lowest (x " +
                           num(minX) + ", z " + num(minZ) + ") differ in magnitude by more than 2^28");
      for (double d : {dx, dz})
        if (d > 0 && lowestBit(d) < exp) {
          exp = lowestBit(d);
          finest = i;
        }
    }
  unit = std::ldexp(1.0, exp);
  const double steps = std::max(double(maxX) - double(minX), double(maxZ) - double(minZ)) / unit;
  if (!(steps <= kMaxUnits))
    return fail(finest, "the lattice is too fine: this patch (" + square(finest) + ") needs a step of 2^" +
                            std::to_string(exp) + " world units, and the terrain spans " + num(steps) +
                            " steps (at most 2^40)");
  return true;
}

// Each patch's lower corner and side in base units; its corners and texture coordinates as the other layouts
// compute them (tex = (x - extent.minX) * invSizeX, in float).
bool Lattice::place(double unit) {
  int64_t smallest = INT64_MAX;
  t.patches.resize(list.size());
  for (size_t i = 0; i < list.size(); ++i) {
    const LayoutPatch& lp = list[i];
    TerrainPatch& p = t.patches[i];
    double x0, z0, dx, dz;
    exactDifference(lp.corners[0].x, minX, x0); // exact: step() checked every corner
    exactDifference(lp.corners[0].y, minZ, z0);
    if (!exactDifference(lp.corners[1].x, lp.corners[0].x, dx) || !exactDifference(lp.corners[2].y, lp.corners[0].y, dz) ||
        dx != dz || lp.corners[3].x != lp.corners[1].x || lp.corners[3].y != lp.corners[2].y ||
        lp.corners[2].x != lp.corners[0].x || lp.corners[1].y != lp.corners[0].y || !(dx > 0))
      return fail(i, "not an axis-aligned square (" + square(i) + ")");
    if (!(dx / unit < double(kMaxSize)))
      return fail(i, "the patch's side is 2^29 or more lattice steps (" + square(i) +
                         "): patch sizes and positions must share a step at most 2^29 times finer than every side");
    p.ref.index = static_cast<int>(i);
    p.ref.patch = static_cast<int>(i);
    p.ux = static_cast<int64_t>(x0 / unit);
    p.uz = static_cast<int64_t>(z0 / unit);
    p.size = static_cast<int64_t>(dx / unit);
    smallest = std::min(smallest, p.size);
    for (int c = 0; c < 4; ++c) {
      const float x = lp.corners[c].x, z = lp.corners[c].y;
      p.corners[c] = glm::vec3(x, 0.0f, z);
      p.tex[c][0] = (x - t.extent.minX) * t.invSizeX;
      p.tex[c][1] = (z - t.extent.minZ) * t.invSizeZ;
    }
  }
  for (TerrainPatch& p : t.patches) {
    while ((smallest << (p.ref.level + 1)) <= p.size) ++p.ref.level; // floor(log2(size / smallest))
    t.adjacency = t.adjacency || p.size != smallest;
  }
  return true;
}

// Finite and resolvable in float, as every layout (layout.cpp, geometryFits): coordinates below 2^60 (squared
// distances stay finite), the smallest patch at least 2^-63 (its squared side a normal float) and 2^-20 of the
// largest coordinate.
bool Lattice::limits(const Scene& s, double unit) {
  if (s.displacement.kind != DisplacementKind::None && !(std::fabs(s.displacement.heightScale) < 0x1p60)) {
    error = "displacement.height_scale: " + num(s.displacement.heightScale) +
            " overflows float in the LOD's squared distances (must be below 2^60)";
    return false;
  }
  const double maxAbs = std::max({std::fabs(minX), std::fabs(maxX), std::fabs(minZ), std::fabs(maxZ)});
  size_t small = 0;
  for (size_t i = 1; i < t.patches.size(); ++i)
    if (t.patches[i].size < t.patches[small].size) small = i;
  const double side = double(t.patches[small].size) * unit;
  if (!(maxAbs < 0x1p60))
    return fail(small, "the terrain reaches |x|, |z| = " + num(maxAbs) +
                           ": coordinates must stay below 2^60 so that squared distances stay finite in float");
  if (!(side >= 0x1p-63) || !(side >= maxAbs * 0x1p-20))
    return fail(small, "the patch (" + square(small) + ") vanishes in float at the terrain's coordinates (|x|, |z| up to " +
                           num(maxAbs) + "): a side must be at least 2^-20 of that and at least 2^-63");
  return true;
}

std::string overlapWords(const Lattice& g, size_t a, size_t b) {
  const TerrainPatch& A = g.t.patches[a];
  const TerrainPatch& B = g.t.patches[b];
  const bool bInA = B.ux >= A.ux && B.uz >= A.uz && B.ux + B.size <= A.ux + A.size && B.uz + B.size <= A.uz + A.size;
  const bool aInB = A.ux >= B.ux && A.uz >= B.uz && A.ux + A.size <= B.ux + B.size && A.uz + A.size <= B.uz + B.size;
  const std::string how = aInB && bInA ? "the same square twice"
                          : bInA       ? "the second lies inside the first"
                          : aInB       ? "the first lies inside the second"
                                       : "they overlap";
  return g.at(a) + " and line " + std::to_string(g.list[b].line) + ": patches overlap (" + g.square(a) + "; " +
         g.square(b) + "): " + how;
}

// No two patches share interior: a sweep over x (removals before insertions at the same x, so touching is fine)
// with the z intervals of the patches the sweep line crosses, kept disjoint, so a new one is compared with the
// intervals next to it only.
bool Lattice::noOverlap() {
  struct Event {
    int64_t x;
    int insert; // 0: the patch ends at x, 1: it starts
    int32_t i;
    bool operator<(const Event& o) const { return x != o.x ? x < o.x : insert != o.insert ? insert < o.insert : i < o.i; }
  };
  std::vector<Event> events;
  events.reserve(2 * t.patches.size());
  for (const TerrainPatch& p : t.patches) {
    events.push_back({p.ux, 1, p.ref.index});
    events.push_back({p.ux + p.size, 0, p.ref.index});
  }
  std::sort(events.begin(), events.end());
  std::map<int64_t, std::pair<int64_t, int32_t>> active; // z lo -> (z hi, patch)
  for (const Event& e : events) {
    const TerrainPatch& p = t.patches[static_cast<size_t>(e.i)];
    if (!e.insert) {
      active.erase(p.uz);
      continue;
    }
    auto it = active.lower_bound(p.uz);
    int32_t other = -1;
    if (it != active.end() && it->first < p.uz + p.size) other = it->second.second;
    if (other < 0 && it != active.begin() && std::prev(it)->second.first > p.uz) other = std::prev(it)->second.second;
    if (other >= 0) {
      error = overlapWords(*this, std::min<size_t>(size_t(other), size_t(e.i)), std::max<size_t>(size_t(other), size_t(e.i)));
      return false;
    }
    active.emplace(p.uz, std::make_pair(p.uz + p.size, e.i));
  }
  return true;
}

// No gap (with no overlap, the squares tile their bounding rectangle exactly when every edge inside the rectangle is
// covered by the patches across it): the first uncovered stretch of an inner edge, then the area as a last proof.
bool Lattice::noGap() {
  for (const TerrainPatch& p : t.patches)
    for (int e = 0; e < 4; ++e) {
      const bool alongX = e == Veq0 || e == Veq1;
      const int64_t line = e == Ueq0 ? p.ux : e == Ueq1 ? p.ux + p.size : e == Veq0 ? p.uz : p.uz + p.size;
      if (line == 0 || line == (alongX ? t.unitsZ : t.unitsX)) continue; // on the terrain's border
      const int64_t lo = alongX ? p.ux : p.uz, hi = lo + p.size;
      int64_t pos = lo, gapEnd = -1;
      for (const int32_t* q = t.neighboursBegin(p, e); q != t.neighboursEnd(p, e) && gapEnd < 0; ++q) {
        const TerrainPatch& Q = t.patches[static_cast<size_t>(*q)];
        const int64_t qlo = std::max(lo, alongX ? Q.ux : Q.uz), qhi = std::min(hi, (alongX ? Q.ux : Q.uz) + Q.size);
        if (qlo > pos) gapEnd = qlo;
        else pos = qhi;
      }
      if (gapEnd < 0 && pos < hi) gapEnd = hi;
      if (gapEnd < 0) continue;
      const double base = alongX ? minX : minZ, across = (alongX ? minZ : minX) + double(line) * t.unit;
      return fail(static_cast<size_t>(p.ref.index),
                  std::string("a gap: nothing lies across the patch's ") + kEdgeNames[e] + " edge (" + square(size_t(p.ref.index)) +
                      ") at " + (alongX ? "z " : "x ") + num(across) + ", " + (alongX ? "x " : "z ") +
                      num(base + double(pos) * t.unit) + " .. " + num(base + double(gapEnd) * t.unit) +
                      " (the patches must tile their bounding rectangle)");
    }
  __extension__ typedef __int128 Area; // up to 2^80: 4 million patches of 2^58, 2^40 x 2^40 steps
  Area area = 0;
  for (const TerrainPatch& p : t.patches) area += static_cast<Area>(p.size) * p.size;
  if (area != static_cast<Area>(t.unitsX) * t.unitsZ) {
    error = L.file + ": the patches do not tile their bounding rectangle (their areas do not add up to it)";
    return false;
  }
  return true;
}

} // namespace

bool buildPatchesLayout(const Scene& s, TerrainData& t, std::string& error) {
  const Layout& L = s.layout;
  if (!L.patchList || L.patchList->empty()) {
    error = "layout.file: no patches (a scene is read with loadScene / parseScene, which reads layout.file)";
    return false;
  }
  Lattice g{L, *L.patchList, t, error};
  g.minX = g.maxX = g.list[0].corners[0].x;
  g.minZ = g.maxZ = g.list[0].corners[0].y;
  for (const LayoutPatch& p : g.list)
    for (const glm::vec2& c : p.corners) {
      g.minX = std::min(g.minX, c.x);
      g.maxX = std::max(g.maxX, c.x);
      g.minZ = std::min(g.minZ, c.y);
      g.maxZ = std::max(g.maxZ, c.y);
    }
  double unit = 1;
  if (!g.step(unit)) return false;
  t.unit = unit;
  t.unitsX = static_cast<int64_t>((double(g.maxX) - double(g.minX)) / unit);
  t.unitsZ = static_cast<int64_t>((double(g.maxZ) - double(g.minZ)) / unit);
  t.extent = Extent{g.minX, g.minZ, g.maxX, g.maxZ};
  t.invSizeX = 1.0f / (t.extent.maxX - t.extent.minX);
  t.invSizeZ = 1.0f / (t.extent.maxZ - t.extent.minZ);
  t.adjacency = false;
  if (!g.place(unit) || !g.limits(s, unit) || !g.noOverlap()) return false;
  if (!linkLattice(t, error)) return false; // non-nesting edges (the message names the file's lines)
  return g.noGap();
}

} // namespace fftess::verify::detail
