// fftess bench (without --micro): what accuracy costs in time, as a table. Each row is one accuracy level or one
// simulated GPU effect, run on the same cameras of one scene: time per camera and per checked edge, cost relative
// to the cheapest row, the work done (WorkStats per camera), and what the level changes: findings gained or lost
// against its group's reference row on the same cameras. docs/accuracy.md holds the table for the default scene.
#include "accuracy.h"
#include "svg_text.h"
#include "common.h"
#include "report_json.h"
#include "scene_options.h"

#include "lod/lod_double.h"
#include "verify/internal.h" // the LOD's inputs per patch, for the float-vs-double row (bench only)

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <set>
#include <tuple>

namespace fftess::cli {
namespace {

using Clock = std::chrono::steady_clock;

// A finding's identity across rows: camera, the patch edge of each side, what it is. Holes: camera, patch, kind.
using Key = std::tuple<size_t, int, int, int, int, int>;

struct RowSpec {
  std::string group, name, what; // what: the setting, in scene keys / options
  std::vector<std::string> overrides;
  vf::Kernel kernel = vf::Kernel::Epick;
  bool flush = false;
  bool mesh = false;      // whole-mesh check instead of the edge check
  int lodPrecision = 0;   // 1: lod/ in float (the hull shader), 2: the same shaders in double (screen_sphere only)
  bool reference = false; // the group's reference row
  bool sweep = false;     // the sweep shortcuts group: vf::sweep on one thread, timed whole
  bool visibleFirst = false, resultCache = false; // its shortcuts
};

std::vector<RowSpec> rowSpecs() {
  std::vector<RowSpec> r;
  auto add = [&](const char* g, const char* n, const char* w, std::vector<std::string> o, bool ref = false) {
    RowSpec s;
    s.group = g, s.name = n, s.what = w, s.overrides = std::move(o), s.reference = ref;
    r.push_back(s);
    return &r.back();
  };
  add("checker", "float", "--kernel float (Simple_cartesian<float>)", {})->kernel = vf::Kernel::FloatNaive;
  add("checker", "epick", "--kernel epick (exact predicates)", {});
  add("checker", "epeck", "--kernel epeck (exact predicates and constructions)", {}, true)->kernel = vf::Kernel::Epeck;
  add("domain formula", "nvidia", "domain.formula=nvidia (HLSL lerp, the sample)", {"domain.formula=nvidia"}, true);
  add("domain formula", "lerp_fma", "domain.formula=lerp_fma", {"domain.formula=lerp_fma"});
  add("domain formula", "blend", "domain.formula=blend", {"domain.formula=blend"});
  add("domain formula", "blend_fma", "domain.formula=blend_fma", {"domain.formula=blend_fma"});
  add("heights", "8-bit subtexel", "displacement.subtexel_bits=8 (the GPU sampler)", {"displacement.subtexel_bits=8"}, true);
  add("heights", "float bilinear", "displacement.subtexel_bits=0", {"displacement.subtexel_bits=0"});
  add("heights", "r16_float", "displacement.format=r16_float (Luna)", {"displacement.format=r16_float"});
  add("heights", "flat", "displacement.kind=none (no height sampled)", {"displacement.kind=none"});
  add("mip", "bonaventura, no mip", "lod.scheme=bonaventura", {"lod.scheme=bonaventura"}, true);
  add("mip", "bonaventura, per_patch", "lod.scheme=bonaventura displacement.mip=per_patch",
      {"lod.scheme=bonaventura", "displacement.mip=per_patch"});
  add("mip", "bonaventura, per_vertex", "lod.scheme=bonaventura displacement.mip=per_vertex",
      {"lod.scheme=bonaventura", "displacement.mip=per_vertex"});
  add("lod precision", "float", "lod/ as the hull shader computes it (screen_sphere: nvidiaTile)", {}, true)->lodPrecision = 1;
  add("lod precision", "double", "the same .glsl compiled in double (lod_double.h), factors rounded to float", {})->lodPrecision = 2;
  add("tessellator", "denormals kept", "Options::flushDenormals=false (hardware)", {}, true);
  add("tessellator", "denormals flushed", "--flush-denormals (llvmpipe)", {})->flush = true;
  add("scope", "edges", "edge check: fftess::edgePoints per outer edge", {}, true);
  add("scope", "whole mesh", "--mesh: full tessellation, CGAL polygon soup, border edges", {})->mesh = true;
  auto sweepRow = [&](const char* n, const char* w, bool visibleFirst, bool cache) {
    RowSpec* x = add("sweep shortcuts", n, w, {}, !visibleFirst && !cache);
    x->sweep = true, x->visibleFirst = visibleFirst, x->resultCache = cache;
  };
  sweepRow("full check", "sweep --no-visible-first --no-result-cache", false, false);
  sweepRow("visible first", "sweep --no-result-cache (CheckOptions::visibleFirst)", true, false);
  sweepRow("result cache", "sweep --no-visible-first (SweepOptions::resultCache)", false, true);
  sweepRow("both", "sweep (the default)", true, true);
  return r;
}

} // namespace

std::vector<std::string> benchGroups() {
  std::vector<std::string> groups;
  for (const RowSpec& s : rowSpecs())
    if (std::find(groups.begin(), groups.end(), s.group) == groups.end()) groups.push_back(s.group);
  return groups;
}

namespace {

struct Row {
  RowSpec spec;
  std::string error;      // the variant does not apply to this scene (its loader's message)
  size_t cameras = 0;
  double seconds = 0;
  int64_t edges = 0;      // edges checked (edge rows) / patch edges flagged (mesh)
  vf::Stats stats;
  vf::WorkStats work;
  std::set<Key> findings;
  int64_t gained = 0, lost = 0;
  bool compared = false;
  std::string verdict;
  std::string verdictKey; // verdict as a key (the JSON's "verdict"; verdict is its "verdict_text")
  int64_t lodFactorsDiffer = 0, lodJumpFactorsDiffer = 0, lodCullsDiffer = 0;
  vf::SweepResult swept; // the sweep shortcuts group: the first run's result (its aggregates)
};

// The sweep shortcuts group: the row's cameras as one vf::sweep on one thread (the result cache lives for one sweep:
// a camera profits from the cameras before it), timed whole as the fastest of `repeats` runs, each with a fresh
// cache. Findings: those on screen (visible first skips only what no camera sees; the verdict counts on screen).
void runSweepRow(Row& row, const vf::Terrain& terrain, const std::vector<vf::Camera>& cams, int repeats) {
  vf::CheckOptions opt;
  opt.maxFindings = static_cast<size_t>(-1);
  opt.visibleFirst = row.spec.visibleFirst;
  vf::SweepOptions so;
  so.threads = 1;
  so.keepCameras = false;
  so.resultCache = row.spec.resultCache;
  so.onReport = [&row](size_t c, const vf::Report& r) {
    for (const vf::Finding& f : r.findings)
      if (f.onScreen)
        row.findings.insert({c, f.a.patch.index, f.a.edge, f.b.patch.index, f.b.edge, static_cast<int>(f.classification)});
    for (const vf::Hole& h : r.holes) row.findings.insert({c, h.patch.index, -1, -1, -1, 10 + static_cast<int>(h.kind)});
  };
  double best = 0;
  for (int k = 0; k < repeats; ++k) {
    const Clock::time_point t0 = Clock::now();
    vf::SweepResult res = vf::sweep(terrain, cams, opt, so);
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    best = k == 0 ? s : std::min(best, s);
    if (k == 0) row.swept = std::move(res), so.onReport = nullptr; // findings and counters: the first run's
  }
  if (!so.resultCache && row.swept.resultCacheOff.empty())
    row.swept.resultCacheOff = "--no-result-cache", row.swept.resultCacheOffKey = "option";
  row.seconds = best;
  row.cameras = cams.size();
  row.stats = row.swept.total;
  row.work = row.swept.work;
  row.edges = row.swept.total.edgesChecked;
  row.verdict = row.verdictKey = vf::toString(vf::verdictOf(row.swept, /*countOffScreen=*/false));
}

void runRow(Row& row, const BenchReportArgs& a, const std::vector<vf::Camera>& cams, size_t meshCameras) {
  std::vector<std::string> o = a.overrides;
  o.insert(o.end(), row.spec.overrides.begin(), row.spec.overrides.end());
  const vf::SceneResult sr = vf::loadScene(a.scene, o);
  if (!sr) {
    row.error = sr.error;
    return;
  }
  const vf::TerrainResult tr = vf::prepareTerrain(sr.scene);
  if (!tr) {
    row.error = tr.error;
    return;
  }
  if (row.spec.sweep) return runSweepRow(row, tr.terrain, cams, a.repeats);
  vf::CheckOptions opt;
  opt.kernel = row.spec.kernel;
  opt.tessellator.flushDenormals = row.spec.flush;
  opt.maxFindings = static_cast<size_t>(-1);
  const size_t n = row.spec.mesh ? std::min(meshCameras, cams.size()) : cams.size();
  vf::SweepResult sum;
  if (row.spec.lodPrecision) {
    // Only the LOD is run and timed. Both rows evaluate every patch; the double row also counts the outer factors of
    // patches float does not cull whose bits differ from the float evaluation, and the patches culled differently.
    const vf::detail::TerrainData& td = tr.terrain.data();
    const vf::Lod& L = td.scene.lod;
    if (L.scheme != vf::LodScheme::ScreenSphere) {
      row.error = "only lod.scheme = \"screen_sphere\" has a double build (lod/lod_double.h)";
      return;
    }
    for (size_t c = 0; c < n; ++c) {
      const lod::Camera cam = vf::detail::toLodCamera(cams[c]);
      std::vector<lod::PatchLod> f(td.patches.size());
      const Clock::time_point t0 = Clock::now();
      for (size_t i = 0; i < td.patches.size(); ++i) {
        const vf::detail::TerrainPatch& p = td.patches[i];
        f[i] = row.spec.lodPrecision == 1 ? vf::detail::patchLod(td, p, p.tile, cam)
               : td.adjacency             ? lod::nvidiaTileDouble(p.lod, p.tile, cam, L.screenSphere)
                                          : lod::screenSphereDouble(p.lod, cam, L.screenSphere.sphere);
      }
      row.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
      row.work.lodEvaluations += static_cast<int64_t>(td.patches.size());
      if (row.spec.lodPrecision == 1) continue;
      for (size_t i = 0; i < td.patches.size(); ++i) {
        const vf::detail::TerrainPatch& p = td.patches[i];
        const lod::PatchLod g = vf::detail::patchLod(td, p, p.tile, cam);
        if (g.why.culled != f[i].why.culled) ++row.lodCullsDiffer;
        if (g.why.culled) continue;
        for (int e = 0; e < 4; ++e) {
          if (bitsOf(g.factors[e]) == bitsOf(f[i].factors[e])) continue;
          ++row.lodFactorsDiffer;
          if (p.tile.size[e] != 1.0f) ++row.lodJumpFactorsDiffer;
        }
      }
    }
    row.cameras = n;
    row.verdictKey = row.spec.lodPrecision == 1 ? "reference" : "factors_compared";
    row.verdict = row.spec.lodPrecision == 1 ? "-" :
        std::to_string(row.lodFactorsDiffer) + " factors differ (" + std::to_string(row.lodJumpFactorsDiffer) +
        " at size jumps), " + std::to_string(row.lodCullsDiffer) + " culls differ; not re-checked";
    return;
  }
  for (size_t c = 0; c < n; ++c) {
    const Clock::time_point t0 = Clock::now();
    if (row.spec.mesh) {
      const vf::MeshReport m = vf::checkSceneMesh(tr.terrain, cams[c], opt);
      row.seconds += std::chrono::duration<double>(Clock::now() - t0).count();
      row.work += m.work;
      row.edges += static_cast<int64_t>(m.flagged.size());
      for (const vf::PatchEdgeRef& e : m.flagged) row.findings.insert({c, e.patch, e.edge, -1, -1, -1});
      continue;
    }
    // The edge check is timed as the fastest of a.repeats runs of the camera (the machine's other load and the first
    // run's page faults make single runs noisy); the findings are the first run's (every run gives the same).
    const vf::Report r = vf::checkScene(tr.terrain, cams[c], opt);
    double best = std::chrono::duration<double>(Clock::now() - t0).count();
    for (int k = 1; k < a.repeats; ++k) {
      const Clock::time_point t1 = Clock::now();
      (void)vf::checkScene(tr.terrain, cams[c], opt);
      best = std::min(best, std::chrono::duration<double>(Clock::now() - t1).count());
    }
    row.seconds += best;
    if (!r.error.empty()) {
      ++sum.camerasInvalid;
      continue;
    }
    ++sum.camerasDone;
    vf::accumulate(sum.total, r.stats);
    row.work += r.work;
    row.edges += r.stats.edgesChecked;
    for (const vf::Finding& f : r.findings)
      row.findings.insert({c, f.a.patch.index, f.a.edge, f.b.patch.index, f.b.edge, static_cast<int>(f.classification)});
    for (const vf::Hole& h : r.holes) row.findings.insert({c, h.patch.index, -1, -1, -1, 10 + static_cast<int>(h.kind)});
  }
  row.cameras = n;
  row.stats = sum.total;
  // Every finding counts, on screen or not: the rows compare checkers finding for finding (the mesh row has no view).
  row.verdict = row.spec.mesh ? (row.findings.empty() ? "no inner border" : "inner borders")
                              : vf::toString(vf::verdictOf(sum, /*countOffScreen=*/true));
  row.verdictKey = row.spec.mesh ? (row.findings.empty() ? "no_inner_border" : "inner_borders") : row.verdict;
}

// The mesh row's findings are patch edges: compare with the reference's findings as patch edges (both sides).
std::set<Key> asPatchEdges(const std::set<Key>& f, size_t cameras) {
  std::set<Key> out;
  for (const Key& k : f) {
    if (std::get<0>(k) >= cameras || std::get<5>(k) >= 10 || std::get<5>(k) == static_cast<int>(vf::Classification::Match))
      continue;
    out.insert({std::get<0>(k), std::get<1>(k), std::get<2>(k), -1, -1, -1});
    out.insert({std::get<0>(k), std::get<3>(k), std::get<4>(k), -1, -1, -1});
  }
  return out;
}

std::string fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

} // namespace

BenchTable runBenchTable(const BenchReportArgs& a) {
  BenchTable t;
  const vf::SceneResult base = vf::loadScene(a.scene, a.overrides);
  if (!base) throw UsageError(loaderMessage(a.scene, base.error));
  const vf::TerrainResult bt = vf::prepareTerrain(base.scene);
  if (!bt) throw UsageError(loaderMessage(a.scene, bt.error));
  t.scene = a.scene;
  t.patches = bt.terrain.patchCount();
  t.cameras = vf::randomCameras(bt.terrain, a.cameras, a.seed);
  t.repeats = a.repeats;
  t.meshCameras = std::min<size_t>(static_cast<size_t>(a.meshCameras), t.cameras.size());
  std::vector<Row> rows;
  for (const RowSpec& s : rowSpecs()) {
    if (!a.only.empty() && s.group != a.only) continue;
    Row r;
    r.spec = s;
    runRow(r, a, t.cameras, t.meshCameras);
    rows.push_back(std::move(r));
  }
  // Gained / lost against the group's reference (same cameras: the mesh row against the reference's first cameras).
  for (Row& r : rows) {
    const Row* ref = nullptr;
    for (const Row& q : rows)
      if (q.spec.group == r.spec.group && q.spec.reference && q.error.empty()) ref = &q;
    if (!ref || !r.error.empty()) continue;
    std::set<Key> mine = r.findings, theirs = ref->findings;
    if (r.spec.mesh) theirs = asPatchEdges(theirs, r.cameras);
    for (const Key& k : mine) r.gained += !theirs.count(k);
    for (const Key& k : theirs) r.lost += !mine.count(k);
    r.compared = true;
  }
  auto perCam = [](const Row& r) { return r.seconds / static_cast<double>(r.cameras); };
  double cheapest = 0;
  double lodFloat = 0; // the LOD rows time the LOD alone: their cost is relative to the float LOD
  double fullSweep = 0; // the sweep shortcuts rows time a sweep: their cost is relative to its full check
  for (const Row& r : rows) {
    if (!r.error.empty() || r.cameras == 0) continue;
    if (r.spec.lodPrecision == 1) lodFloat = perCam(r);
    if (r.spec.sweep && r.spec.reference) fullSweep = perCam(r);
    if (!r.spec.lodPrecision && !r.spec.sweep && (cheapest == 0 || perCam(r) < cheapest)) cheapest = perCam(r);
  }
  for (const Row& r : rows) {
    BenchRow b;
    b.group = r.spec.group, b.name = r.spec.name, b.what = r.spec.what, b.reference = r.spec.reference;
    b.error = r.error;
    b.cameras = r.cameras;
    if (r.error.empty() && r.cameras > 0) {
      b.msPerCamera = 1e3 * perCam(r);
      b.usPerEdge = r.spec.mesh || r.stats.edgesChecked == 0 ? 0 : 1e6 * r.seconds / static_cast<double>(r.stats.edgesChecked);
      const double unit = r.spec.lodPrecision ? lodFloat : r.spec.sweep ? fullSweep : cheapest;
      b.relative = unit > 0 ? perCam(r) / unit : 0;
    }
    b.findings = static_cast<int64_t>(r.findings.size());
    b.gained = r.gained, b.lost = r.lost, b.compared = r.compared;
    b.verdict = r.verdict, b.verdictKey = r.verdictKey;
    b.stats = r.stats;
    b.work = r.work;
    b.sweep = r.spec.sweep;
    b.visibleFirst = r.swept.visibleFirst, b.resultCache = r.swept.resultCache;
    b.resultCacheOff = r.swept.resultCacheOff, b.resultCacheOffKey = r.swept.resultCacheOffKey;
    b.resultCacheItems = r.swept.resultCacheItems, b.resultCacheBytes = r.swept.resultCacheBytes;
    t.rows.push_back(b);
  }
  return t;
}

static std::string perCamera(int64_t v, size_t cameras) {
  return cameras ? formatNumber(static_cast<double>(v) / static_cast<double>(cameras)) : "-";
}

// The share of the pairs classified (stats.edgesChecked) that `hits` decided without evaluating their points, in %;
// "-" where the row ran no result cache.
static std::string hitRate(const BenchRow& r, int64_t hits) {
  if (!r.resultCache || r.stats.edgesChecked == 0) return "-";
  return fmt("%.1f %%", 100.0 * static_cast<double>(hits) / static_cast<double>(r.stats.edgesChecked));
}

std::string benchMarkdown(const BenchTable& t) {
  std::string o;
  o += "Scene `" + t.scene + "` (" + std::to_string(t.patches) + " patches), " + std::to_string(t.cameras.size()) +
       " random cameras (the whole-mesh row: the first " + std::to_string(t.meshCameras) + "), one thread; each edge-check camera timed as the fastest of " + std::to_string(t.repeats) + " runs.\n\n";
  o += "| group | row | setting | ms / camera | µs / edge | cost | findings | vs reference (+gained / -lost) | verdict | "
       "lod evals | height samples | domain evals | shared points | edge queries | CGAL calls | full tessellations | "
       "box tests | cache hits | seam hits |\n";
  o += "|---|---|---|---:|---:|---:|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const BenchRow& r : t.rows) {
    if (!r.error.empty()) {
      o += "| " + r.group + " | " + r.name + " | " + r.what + " | - | - | - | - | not applicable: " + r.error +
           " | | | | | | | | | | | |\n";
      continue;
    }
    const size_t c = r.cameras;
    o += "| " + r.group + " | " + r.name + (r.reference ? " (reference)" : "") + " | " + r.what + " | " +
         fmt("%.2f", r.msPerCamera) + " | " + (r.usPerEdge > 0 ? fmt("%.3f", r.usPerEdge) : std::string("-")) + " | " +
         fmt("%.2fx", r.relative) + " | " + std::to_string(r.findings) + " | " +
         (r.reference ? std::string("reference") : r.compared ? "+" + std::to_string(r.gained) + " / -" + std::to_string(r.lost) : "-") +
         " | " + r.verdict + " | " + perCamera(r.work.lodEvaluations, c) + " | " + perCamera(r.work.heightSamples, c) +
         " | " + perCamera(r.work.domainEvaluations, c) + " | " + perCamera(r.work.sharedEdgePoints, c) + " | " +
         perCamera(r.work.edgeQueries, c) + " | " + perCamera(r.work.cgalCalls, c) + " | " +
         perCamera(r.work.fullTessellations, c) + " | " + perCamera(r.work.boxTests, c) + " | " +
         hitRate(r, r.work.cacheHits) + " | " + hitRate(r, r.work.seamHits) + " |\n";
  }
  o += "\nWork columns are per camera. Findings: cracks, T-junctions and holes over all cameras (whole mesh: patch "
       "edges holding an inner border edge). cost: time per camera over the cheapest row's; the lod precision rows "
       "time the LOD alone (every patch), their cost is relative to the float LOD. The sweep shortcuts rows time one "
       "sweep of all the cameras on one thread (the fastest of the runs, each with a fresh result cache), their cost "
       "relative to the group's full check, and count the findings on screen; cache hits and seam hits: the pairs classified that the result cache or a seam proof "
       "decided without evaluating their points.\n";
  return o;
}

// Under a sweep shortcuts row: the work per camera and what the shortcuts did.
static std::string sweepRowText(const BenchRow& r) {
  const size_t c = r.cameras;
  std::string o = "  " + std::string(41, ' ') + "per camera: lod evals " + perCamera(r.work.lodEvaluations, c) +
                  ", domain evals " + perCamera(r.work.domainEvaluations, c) + ", edge queries " +
                  perCamera(r.work.edgeQueries, c) + ", box tests " + perCamera(r.work.boxTests, c) + "; ";
  o += r.visibleFirst ? "visible first (" + perCamera(r.stats.patchesOffScreen, c) + " patches off screen)"
                      : std::string("full check");
  o += r.resultCache ? "; result cache hits " + hitRate(r, r.work.cacheHits) + ", seam hits " +
                           hitRate(r, r.work.seamHits) + " of the pairs classified"
                     : "; result cache off" + (r.resultCacheOff.empty() ? std::string() : ": " + r.resultCacheOff);
  return o + "\n";
}

std::string benchText(const BenchTable& t) {
  std::string o = "fftess bench: " + t.scene + ", " + std::to_string(t.patches) + " patches, " +
                  std::to_string(t.cameras.size()) + " random cameras (whole mesh: " + std::to_string(t.meshCameras) +
                  "), one thread\n";
  char buf[512];
  std::snprintf(buf, sizeof buf, "  %-15s %-24s %11s %9s %7s %8s %14s  %s\n", "group", "row", "ms/camera", "us/edge",
                "cost", "findings", "vs reference", "verdict");
  o += buf;
  for (const BenchRow& r : t.rows) {
    if (!r.error.empty()) {
      std::snprintf(buf, sizeof buf, "  %-15s %-24s not applicable: %s\n", r.group.c_str(), r.name.c_str(), r.error.c_str());
      o += buf;
      continue;
    }
    const std::string vs = r.reference ? "reference" : "+" + std::to_string(r.gained) + " -" + std::to_string(r.lost);
    std::snprintf(buf, sizeof buf, "  %-15s %-24s %11.2f %9s %6.2fx %8lld %14s  %s\n", r.group.c_str(), r.name.c_str(),
                  r.msPerCamera, r.usPerEdge > 0 ? fmt("%.3f", r.usPerEdge).c_str() : "-", r.relative,
                  static_cast<long long>(r.findings), vs.c_str(), r.verdict.c_str());
    o += buf;
    if (r.sweep) o += sweepRowText(r);
  }
  return o;
}

std::string benchJson(const BenchTable& t) {
  json j;
  j["version"] = kBenchReportVersion;
  j["kind"] = "bench";
  j["fftess_version"] = FFTESS_VERSION;
  j["scene"] = t.scene;
  j["patches"] = t.patches;
  j["cameras"] = t.cameras.size();
  j["mesh_cameras"] = t.meshCameras;
  json rows = json::array();
  for (const BenchRow& r : t.rows) {
    json x;
    x["group"] = r.group, x["row"] = r.name, x["setting"] = r.what, x["reference"] = r.reference;
    if (!r.error.empty()) {
      x["error"] = r.error;
      rows.push_back(x);
      continue;
    }
    x["cameras"] = r.cameras;
    x["ms_per_camera"] = r.msPerCamera;
    x["us_per_edge"] = r.usPerEdge;
    x["relative_cost"] = r.relative;
    x["findings"] = r.findings;
    x["gained"] = r.gained;
    x["lost"] = r.lost;
    x["verdict"] = r.verdictKey;
    x["verdict_text"] = r.verdict;
    x["stats"] = statsJson(r.stats);
    x["work"] = workJson(r.work);
    if (r.sweep) {
      const double pairs = static_cast<double>(std::max<int64_t>(1, r.stats.edgesChecked));
      x["sweep"] = {{"visible_first", r.visibleFirst},
                    {"result_cache", r.resultCache},
                    {"result_cache_off", r.resultCache ? json(nullptr) : json(r.resultCacheOffKey)},
                    {"result_cache_off_text", r.resultCache ? json(nullptr) : json(r.resultCacheOff)},
                    {"cache_hit_rate", static_cast<double>(r.work.cacheHits) / pairs},
                    {"seam_hit_rate", static_cast<double>(r.work.seamHits) / pairs},
                    {"result_cache_items", r.resultCacheItems},
                    {"result_cache_bytes", r.resultCacheBytes}};
    }
    rows.push_back(x);
  }
  j["rows"] = rows;
  return j.dump(2) + "\n";
}

// Bar labels ("1.23x, 4.56 ms (reference)") of one row.
static std::string barLabel(const BenchRow& r) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "%.2fx, %.2f ms", r.relative, r.msPerCamera);
  return buf + (r.reference ? std::string(" (reference)")
                            : r.gained + r.lost > 0 ? " +" + std::to_string(r.gained) + " -" + std::to_string(r.lost) : "");
}

// The page fits its texts (svg_text.h): the row names push the bars right, the bar labels widen the page, the title
// wraps.
std::string benchSvg(const BenchTable& t) {
  const double rowH = 22, width = 420;
  double left = 330, labelW = 0, maxRel = 1;
  for (const BenchRow& r : t.rows) {
    maxRel = std::max(maxRel, r.relative);
    left = std::max(left, 10 + svgTextWidth(r.group + ": " + r.name, 12, true) + 10);
    labelW = std::max(labelW, svgTextWidth(barLabel(r), 12, true));
  }
  const double pageW = std::max(900.0, left + 4 + width + 6 + labelW + 10);
  std::string o = "<style>.t{font:14px sans-serif}.s{font:12px monospace}.n{font:11px sans-serif}</style>\n"
                  "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const double top = svgTextLines(o, "t", "What accuracy costs: time per camera relative to the cheapest row (log scale), " +
                                            t.scene, 14, false, 10, 22, pageW - 20, 18) - 4;
  const double logMax = std::log2(std::max(2.0, maxRel));
  char buf[512];
  for (size_t i = 0; i < t.rows.size(); ++i) {
    const BenchRow& r = t.rows[i];
    const double y = top + rowH * static_cast<double>(i);
    std::snprintf(buf, sizeof buf, "<text class=\"s\" x=\"10\" y=\"%.1f\">", y + 15);
    o += buf + xmlEscape(r.group + ": " + r.name) + "</text>\n";
    if (!r.error.empty()) continue;
    const double w = 4 + width * std::log2(std::max(1.0, r.relative)) / logMax;
    const char* colour = r.gained + r.lost > 0 ? "#d01010" : r.reference ? "#2a5599" : "#7a9ac0";
    std::snprintf(buf, sizeof buf,
                  "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n<text class=\"s\" x=\"%.1f\" "
                  "y=\"%.1f\">%s</text>\n",
                  left, y + 4, w, rowH - 6, colour, left + w + 6, y + 15, xmlEscape(barLabel(r)).c_str());
    o += buf;
  }
  const double bottom = svgTextLines(o, "n", "red: the row changes findings against its group's reference (+gained -lost)", 11,
                                     false, 10, top + rowH * static_cast<double>(t.rows.size()) + 22, pageW - 20, 14);
  return svgHead(pageW, bottom, "fftess bench --scene " + t.scene) + o + "</svg>\n"; // the path whole in the title
}

} // namespace fftess::cli
