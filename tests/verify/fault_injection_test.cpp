// Fault injection proves the checker: in an otherwise watertight scene, perturb one thing at a time (CheckOptions::
// fault) and require the verifier to report exactly what the perturbation changed, at the right place, as the right
// kind: a crack or T-junction on the perturbed shared edge, a hole at a dropped or NaN patch; and nothing where
// the geometry did not change (a factor ulp that rounds to the same 16.16 points, a mirrored edge that D3D's
// symmetric tessellation reproduces). The harness knows which is which from the emulator (fftess::edgePoints) and
// from its own visibility test, not from the verifier: both false negatives and false positives fail.
#include "verify_test_util.h"

#include "base/splitmix64.h"

#include "lod/lod.h"
#include "verify/internal.h" // the prepared patches' tile neighbours (NeighbourSize faults)
#include "verify/testing.h"  // Fault, CheckOptions::fault

#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <set>
#include <tuple>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

using Kind = Fault::Kind;

const char* kindName(Kind k) {
  switch (k) {
  case Kind::FactorUlp: return "factor +-1 ulp";
  case Kind::FactorStep: return "factor +-1 16.16 step";
  case Kind::PointUlp: return "edge point +-1 ulp in x, y or z";
  case Kind::DropPatch: return "dropped patch";
  case Kind::NanFactor: return "NaN factor";
  case Kind::MirrorEdge: return "mirrored edge";
  case Kind::NeighbourSize: return "wrong neighbour size";
  case Kind::CullPatch: return "culled while visible between grid points";
  case Kind::None: return "none";
  }
  return "?";
}

// One side of a baseline pair: which patch edge, its hull factor and the part of its edge that is compared.
struct PairKey {
  int pa, ea, pb, eb;
  bool operator<(const PairKey& o) const { return std::tie(pa, ea, pb, eb) < std::tie(o.pa, o.ea, o.pb, o.eb); }
  bool operator==(const PairKey& o) const { return std::tie(pa, ea, pb, eb) == std::tie(o.pa, o.ea, o.pb, o.eb); }
};

struct Tally {
  int injected = 0, changed = 0, detected = 0, unchanged = 0, quiet = 0, undecidable = 0;
};

// The points the tessellator puts on an edge for a factor, restricted to [lo, hi] (the compared part).
std::vector<float> paramsIn(float factor, const Scene& s, float lo, float hi, bool mirror = false) {
  const EdgePoints e = edgePoints(factor, s.partitioning, s.stage);
  std::vector<float> out;
  for (int j = 0; j < e.count; ++j) {
    const float p = mirror ? 1.0f - e.param[e.count - 1 - j] : e.param[j];
    if (p >= lo && p <= hi) out.push_back(p);
  }
  return out;
}

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(float)) != 0) return false;
  return true;
}

float perturbed(const Fault& f, float x) {
  if (f.kind == Kind::FactorStep) return x + static_cast<float>(f.direction) * 0x1p-16f;
  return std::nextafter(x, f.direction < 0 ? -INFINITY : INFINITY);
}

struct Harness {
  const char* name;
  Scene scene;
  Terrain terrain;
  Camera camera;
  bool flat;
  bool tileRings;             // screen_sphere on tile rings: NeighbourSize faults
  std::vector<Finding> pairs; // baseline: every shared edge pair, all matches
  std::map<Kind, Tally>& tally;

  // The factor lod/ gives edge f.edge of patch f.patch when told the neighbour there has size f.size (the scene's
  // scheme is screen_sphere on tile rings: lod::nvidiaTile).
  float wrongSizeFactor(const Fault& f) const {
    const detail::TerrainPatch& p = terrain.data().patches[static_cast<size_t>(f.patch)];
    lod::TileNeighbours wrong = p.tile;
    wrong.size[f.edge] = f.size;
    const lod::Camera cam =
        lod::makeCamera(camera.eye, camera.target, camera.up, camera.fovY * (3.14159265358979323846f / 180.0f),
                        camera.nearZ, camera.farZ,
                        glm::vec2(static_cast<float>(camera.width), static_cast<float>(camera.height)));
    return lod::nvidiaTile(p.lod, wrong, cam, scene.lod.screenSphere).factors[f.edge];
  }

  Report run(const Fault& f) const {
    CheckOptions o;
    o.maxFindings = 1u << 20;
    o.fault = std::make_shared<const Fault>(f);
    return checkScene(terrain, camera, o);
  }

  // The pairs (a patch edge on either side) the fault touches, with what the harness expects at each.
  void injectEdgeFault(const Fault& f, uint64_t& rngState) {
    Tally& t = tally[f.kind];
    ++t.injected;
    std::set<PairKey> expect;      // pairs whose compared points change
    std::map<PairKey, Classification> expectKind; // PointUlp on flat terrain: T-junction or crack
    for (const Finding& p : pairs) {
      for (int side = 0; side < 2; ++side) {
        const EdgeSide& s = side == 0 ? p.a : p.b;
        if (s.patch.index != f.patch || s.edge != f.edge) continue;
        const PairKey key{p.a.patch.index, p.a.edge, p.b.patch.index, p.b.edge};
        const float lo = s.paramLo, hi = s.paramHi;
        bool changes = false;
        if (f.kind == Kind::FactorUlp || f.kind == Kind::FactorStep)
          changes = !sameBits(paramsIn(s.hullFactor, scene, lo, hi), paramsIn(perturbed(f, s.hullFactor), scene, lo, hi));
        else if (f.kind == Kind::NeighbourSize)
          changes = !sameBits(paramsIn(s.hullFactor, scene, lo, hi), paramsIn(wrongSizeFactor(f), scene, lo, hi));
        else if (f.kind == Kind::MirrorEdge)
          changes = !sameBits(paramsIn(s.hullFactor, scene, lo, hi), paramsIn(s.hullFactor, scene, lo, hi, true));
        else if (f.kind == Kind::PointUlp) {
          const EdgePoints e = edgePoints(s.hullFactor, scene.partitioning, scene.stage);
          if (f.point < e.count) {
            const float param = e.param[f.point];
            changes = param >= lo && param <= hi;
            // Flat terrain: a vertex moved along its straight edge stays on the other side's line (T-junction)
            // unless it is an end of the compared part; any other move leaves it (crack).
            const bool alongEdge = (f.edge == Ueq0 || f.edge == Ueq1) ? f.axis == 2 : f.axis == 0;
            const bool endOfPart = param == lo || param == hi;
            if (changes)
              expectKind[key] = flat && alongEdge && !endOfPart ? Classification::TJunction : Classification::Crack;
          }
        }
        if (changes) expect.insert(key);
      }
    }
    (void)rngState;
    const Report r = run(f);
    INFO(name << ": " << kindName(f.kind) << " patch " << f.patch << " edge " << f.edge << " point " << f.point
              << " axis " << f.axis << " dir " << f.direction);
    REQUIRE(r.error.empty());
    CHECK(r.stats.holes == 0);
    std::set<PairKey> seen;
    for (const Finding& x : r.findings) {
      if (x.classification == Classification::Match) continue;
      const PairKey key{x.a.patch.index, x.a.edge, x.b.patch.index, x.b.edge};
      seen.insert(key);
      auto k = expectKind.find(key);
      if (k != expectKind.end()) CHECK(toString(x.classification) == std::string(toString(k->second)));
    }
    CHECK(seen == expect); // no false negative, no false positive
    if (expect.empty()) {
      ++t.unchanged;
      if (seen.empty()) ++t.quiet;
    } else {
      ++t.changed;
      if (seen == expect) ++t.detected;
    }
  }

  void injectPatchFault(const Fault& f) {
    Tally& t = tally[f.kind];
    ++t.injected;
    const bool visible = seenOnGrid(terrain, camera, f.patch);
    const Report r = run(f);
    INFO(name << ": " << kindName(f.kind) << " patch " << f.patch << " edge " << f.edge);
    REQUIRE(r.error.empty());
    CHECK(r.stats.cracks == 0);
    CHECK(r.stats.tJunctions == 0);
    CHECK(r.stats.holes <= 1);
    const bool hole = r.holes.size() == 1 && r.holes[0].patch.index == f.patch &&
                      r.holes[0].kind == HoleKind::Discarded &&
                      (f.kind == Kind::DropPatch || (r.holes[0].edge == f.edge && std::isnan(r.holes[0].hullFactor)));
    if (visible) {
      ++t.changed;
      CHECK(hole);
      if (hole) ++t.detected;
    } else {
      // Not seen on the harness's grid: invisible, or too close to the frustum's border for a grid to tell.
      ++t.undecidable;
      const bool undecided = r.undecided.size() == 1 && r.undecided[0].patch.index == f.patch;
      CHECK((r.stats.holes + r.stats.undecided == 0 || hole || undecided));
    }
  }

  // The LOD culls a patch (CullPatch) that a camera sees only between the points of the old 33 x 33 visibility grid:
  // a point P inside one of the grid's cells (at least a quarter cell from its sides), seen straight down from 1 unit
  // above, the far plane 1.5 units from the eye, and a field of view so narrow that the frustum is a column of
  // radius under 0.2 cells around P (0.13 cells at P). The harness confirms both: P in view, no point of the
  // 33 x 33 grid in view. Expected: exactly one hole, CulledWhileVisible, at that patch, seen at a point in view;
  // nothing else.
  void injectCulledBetweenGridPoints(fftess::SplitMix64& rng) {
    Tally& t = tally[Kind::CullPatch];
    ++t.injected;
    const std::vector<PatchGeometry> patches = terrain.patches();
    Fault f;
    f.kind = Kind::CullPatch;
    f.patch = static_cast<int>(rng.next() % patches.size());
    const PatchGeometry& g = patches[static_cast<size_t>(f.patch)];
    auto inCell = [&](uint64_t r) {
      const double jitter = (static_cast<double>(r % 1024) / 1023.0 - 0.5) * 0.5; // [-0.25, 0.25] of a cell
      return static_cast<float>((static_cast<double>((r >> 10) % 32) + 0.5 + jitter) / 32.0);
    };
    const float u = inCell(rng.next()), v = inCell(rng.next());
    const glm::vec3 p = domainPosition(terrain, f.patch, u, v);
    const double cell = std::fabs(static_cast<double>(g.corners[1].x) - g.corners[0].x) / 32.0;
    const double depth = 1.5; // the far plane
    const double aspect = static_cast<double>(camera.width) / camera.height;
    Camera c = camera;
    c.eye = p + glm::vec3(0, 1, 0);
    c.target = p;
    c.up = {0, 0, 1};
    c.nearZ = 0.1f;
    c.farZ = static_cast<float>(depth);
    c.fovY = static_cast<float>(2.0 * std::atan(0.2 * cell / (depth * std::sqrt(1 + aspect * aspect))) *
                                (180.0 / 3.14159265358979323846));
    INFO(name << ": " << kindName(f.kind) << " patch " << f.patch << " at u " << u << " v " << v << " fov_y "
              << c.fovY);
    const bool between = inView(lodCameraOf(c), p) && !seenOnGrid(terrain, c, f.patch, 33);
    CHECK(between); // the construction: visible, and only between the old grid's points
    CheckOptions o;
    o.maxFindings = 1u << 20;
    o.fault = std::make_shared<const Fault>(f);
    const Report r = checkScene(terrain, c, o);
    REQUIRE(r.error.empty());
    CHECK(r.stats.cracks == 0);
    CHECK(r.stats.tJunctions == 0);
    CHECK(r.stats.undecided == 0);
    CHECK(r.stats.holes == 1);
    const bool hole = r.holes.size() == 1 && r.holes[0].patch.index == f.patch &&
                      r.holes[0].kind == HoleKind::CulledWhileVisible &&
                      inView(lodCameraOf(c), r.holes[0].visiblePoint);
    CHECK(hole);
    if (!between) {
      ++t.undecidable;
      return;
    }
    ++t.changed;
    if (hole) ++t.detected;
  }
};

Harness makeHarness(const char* name, const char* example, const std::vector<std::string>& overrides, bool flat,
                    std::map<Kind, Tally>& tally) {
  Scene s = loadExample(example, overrides);
  Terrain t = prepared(s);
  Harness h{name, s, t, s.camera, flat, s.layout.kind == LayoutKind::TileRings && s.lod.scheme == LodScheme::ScreenSphere, {}, tally};
  CheckOptions o;
  o.keepMatches = true;
  o.maxFindings = 1u << 20;
  const Report base = checkScene(t, s.camera, o);
  INFO(name);
  REQUIRE(base.error.empty());
  REQUIRE(verdictOf(base.stats) == Verdict::Watertight); // the harness starts from a watertight scene
  REQUIRE(base.stats.edgesChecked > 100);
  h.pairs = base.findings;
  return h;
}

void runFaults(Harness& h, int count, uint64_t seed) {
  fftess::SplitMix64 cullRng{seed ^ 0x5eedc011u};
  for (int n = 0; n < count / 10; ++n) h.injectCulledBetweenGridPoints(cullRng);
  fftess::SplitMix64 rng{seed};
  for (int n = 0; n < count; ++n) {
    const Finding& pair = h.pairs[rng.next() % h.pairs.size()];
    const EdgeSide& side = (rng.next() & 1) ? pair.a : pair.b;
    Fault f;
    f.patch = side.patch.index;
    f.edge = side.edge;
    f.direction = (rng.next() & 1) ? 1 : -1;
    const uint64_t pick = rng.next() % 100;
    if (pick < 20) f.kind = Kind::FactorUlp;
    else if (pick < 40) f.kind = Kind::FactorStep;
    else if (pick < 70) {
      f.kind = Kind::PointUlp;
      const EdgePoints e = edgePoints(side.hullFactor, h.scene.partitioning, h.scene.stage);
      f.point = static_cast<int>(rng.next() % static_cast<uint64_t>(e.count));
      f.axis = static_cast<int>(rng.next() % 3);
    } else if (pick < 80) {
      f.kind = Kind::MirrorEdge;
      if (h.tileRings && (rng.next() & 1)) { // half of these on tile rings: a wrong neighbour size instead
        f.kind = Kind::NeighbourSize;
        const float now = h.terrain.data().patches[static_cast<size_t>(f.patch)].tile.size[f.edge];
        f.size = now != 1.0f ? 1.0f : ((rng.next() & 1) ? 2.0f : 0.5f);
      }
    }
    else if (pick < 90) f.kind = Kind::DropPatch;
    else f.kind = Kind::NanFactor;
    uint64_t state = rng.next();
    if (f.kind == Kind::DropPatch || f.kind == Kind::NanFactor) h.injectPatchFault(f);
    else h.injectEdgeFault(f, state);
  }
}

void printTally(const char* title, const std::map<Kind, Tally>& tally) {
  std::printf("%s\n  %-42s %8s %8s %8s %10s %8s %12s\n", title, "fault kind", "injected", "changed", "detected",
              "unchanged", "quiet", "undecidable");
  int injected = 0;
  for (const auto& [k, t] : tally) {
    std::printf("  %-42s %8d %8d %8d %10d %8d %12d\n", kindName(k), t.injected, t.changed, t.detected, t.unchanged,
                t.quiet, t.undecidable);
    injected += t.injected;
  }
  std::printf("  total injected: %d\n", injected);
}

} // namespace

TEST_CASE("fault injection: every fault is found and nothing else", "[verify][faults][slow]") {
  std::map<Kind, Tally> tally;
  Harness rings = makeHarness("rings_small (screen_sphere, pow2, fbm)", "rings_small.toml", {}, false, tally);
  Harness grid = makeHarness("grid (distance_pow2, fractional_odd, ridge)", "grid.toml", {}, false, tally);
  Harness flat = makeHarness("flat grid (constant 7, integer)", "grid.toml",
                             {"displacement.kind=none", "lod.scheme=constant", "lod.factor=7",
                              "tessellation.partitioning=integer"},
                             true, tally);
  Harness flatOdd = makeHarness("flat grid (distance_pow2, fractional_odd)", "grid.toml", {"displacement.kind=none"},
                                true, tally);
  runFaults(rings, 450, 1);
  runFaults(grid, 350, 2);
  runFaults(flat, 150, 3);
  runFaults(flatOdd, 250, 4);
  printTally("fault injection (4 scenes):", tally);
  int injected = 0;
  for (const auto& [k, t] : tally) {
    injected += t.injected;
    INFO(kindName(k));
    CHECK(t.detected == t.changed); // 100% of the faults that change the geometry are found
    CHECK(t.quiet == t.unchanged);  // and none of those that do not is reported
  }
  CHECK(injected >= 1000);
  // Each kind both changed the geometry somewhere and (for factor and mirror faults) left it alone somewhere.
  CHECK(tally[Kind::FactorUlp].changed > 0);
  CHECK(tally[Kind::FactorUlp].unchanged > 0);
  CHECK(tally[Kind::FactorStep].changed > 0);
  CHECK(tally[Kind::PointUlp].changed > 0);
  CHECK(tally[Kind::MirrorEdge].unchanged > 0);
  CHECK(tally[Kind::NeighbourSize].changed > 0);
  CHECK(tally[Kind::DropPatch].changed > 0);
  CHECK(tally[Kind::NanFactor].changed > 0);
  CHECK(tally[Kind::CullPatch].changed == tally[Kind::CullPatch].injected); // every one between the grid's points
}
