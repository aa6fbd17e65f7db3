// The sweep shortcuts lose nothing (docs/verify.md, "Sweep shortcuts"; issue 22): every example scene that runs
// without a GPU, and variants with findings on screen (cracks, holes, a quadtree without balance, findings off
// screen beside them), swept over seeded random cameras plus the scene's own cameras four ways: no shortcut, visible
// first only (CheckOptions::visibleFirst), the result cache only (SweepOptions::resultCache), both. Camera by camera
// the four must show the same: every on-screen finding (both sides' patches, edges, factor bits, points, the gaps'
// bits), every hole and undecided patch, Report::error, the on-screen counts and worst on-screen gap; and the sweeps
// the same verdict. Also: --offscreen's countOffScreen runs the full check whatever visibleFirst asks; a scene with a
// camera-dependent effect gets no result cache; an injected fault is still found with both shortcuts on.
//
// The cases named "Shortcuts run: ..." require that the shortcuts actually ran where they should (visible first
// skipped patches, the cache answered pairs); the others hold for any sweep that loses nothing, shortcuts or not.
#include "verify_test_util.h"

#include "verify/internal.h" // TerrainData::tree (the number of shared edge pairs)
#include "verify/testing.h" // Fault, CheckOptions::fault

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

using namespace fftess;
using namespace fftess::verify;
using namespace fftess::verify::test;

namespace {

struct Way {
  const char* name;
  bool visibleFirst, resultCache;
};
constexpr Way kWays[4] = {
    {"no shortcut", false, false}, {"visible first", true, false}, {"result cache", false, true}, {"both", true, true}};

// Bits, so that "equal" means equal to the last bit (NaN included).
template <typename T> std::string hexOf(T v) {
  uint64_t b = 0;
  std::memcpy(&b, &v, sizeof v);
  char buf[24];
  std::snprintf(buf, sizeof buf, "%" PRIx64, b);
  return buf;
}
std::string hexOf(const glm::vec3& v) { return hexOf(v.x) + "," + hexOf(v.y) + "," + hexOf(v.z); }

std::string refText(const PatchRef& p) {
  return std::to_string(p.index) + "/" + std::to_string(p.ring) + "/" + std::to_string(p.tile) + "/" +
         std::to_string(p.patch) + "/" + std::to_string(p.level);
}

std::string sideText(const EdgeSide& s) {
  return refText(s.patch) + " e" + std::to_string(s.edge) + " f" + hexOf(s.hullFactorBits) + " p" +
         hexOf(s.processedFactor) + (s.culled ? " culled" : "") + " [" + hexOf(s.paramLo) + "," + hexOf(s.paramHi) +
         "] n" + std::to_string(s.pointCount) + " m" + std::to_string(s.firstMismatch);
}

std::string findingText(const Finding& f) {
  return std::string(toString(f.classification)) + " a " + sideText(f.a) + " b " + sideText(f.b) + " gap " +
         hexOf(f.gapWorld) + " " + hexOf(f.gapPixels) + " at " + hexOf(f.gapVertex) + " s" +
         std::to_string(f.gapSide) + (f.onScreen ? " on" : " off") + " screen gap " + hexOf(f.onScreenGapWorld) +
         " " + hexOf(f.onScreenGapPixels) + " at " + hexOf(f.onScreenGapVertex) + " s" +
         std::to_string(f.onScreenGapSide);
}

std::string holeText(const Hole& h) {
  return std::string(toString(h.kind)) + " " + refText(h.patch) + " v" + std::to_string(int(h.visibility)) + " " +
         hexOf(h.visiblePoint) + " e" + std::to_string(h.edge) + " f" + hexOf(h.hullFactorBits) + " w" +
         hexOf(h.midpointW) + " d" + hexOf(h.domainPoint.u) + "," + hexOf(h.domainPoint.v) + " side " +
         hexOf(h.undecidedSide) + (h.budgetExhausted ? " budget" : "");
}

// What one camera shows, line by line: its error, its findings that count (on screen, or all with countOffScreen;
// never matches), holes and undecided patches in layout order, then the counts that count and the worst gap.
std::vector<std::string> seenOf(const Report& r, bool countOffScreen) {
  std::vector<std::string> out;
  if (!r.error.empty()) out.push_back("error " + r.error);
  for (const Finding& f : r.findings)
    if (f.classification != Classification::Match && (f.onScreen || countOffScreen)) out.push_back(findingText(f));
  for (const Hole& h : r.holes) out.push_back("hole " + holeText(h));
  for (const Hole& h : r.undecided) out.push_back("undecided " + holeText(h));
  for (const GpuFloatFinding& g : r.gpuFloat) // --gpu-float conformant: counted wherever the pair lies
    out.push_back("gpu float " + refText(g.a) + " e" + std::to_string(g.edgeA) + " | " + refText(g.b) + " e" +
                  std::to_string(g.edgeB) + " " + hexOf(g.factorA) + " " + hexOf(g.factorB) + " " + hexOf(g.loA) + ".." +
                  hexOf(g.hiA) + " " + hexOf(g.loB) + ".." + hexOf(g.hiB) + " " + g.operationA + " | " + g.operationB +
                  " " + g.why);
  const Stats& s = r.stats;
  out.push_back("cracks " + std::to_string(countOffScreen ? s.cracks : s.cracksOnScreen()) + " t-junctions " +
                std::to_string(countOffScreen ? s.tJunctions : s.tJunctionsOnScreen()) + " holes " +
                std::to_string(s.holes) + " undecided " + std::to_string(s.undecided) + " worst gap " +
                hexOf(countOffScreen ? s.worstGapWorld : s.worstGapWorldOnScreen) + " gpu float " +
                std::to_string(s.gpuFloatFindings));
  return out;
}

// One sweep, one way: per camera what it shows (by cameraIndex) and what the shortcuts did.
struct WayRun {
  std::vector<std::vector<std::string>> seen; // per camera, seenOf
  std::vector<char> reported;                 // onReport saw the camera
  SweepResult res;
  Verdict verdict = Verdict::Watertight;
  int64_t findings = 0;            // lines of findings, holes and undecided patches (all cameras)
  int64_t offScreenFindings = 0;   // findings off screen (not in seen unless countOffScreen)
  size_t camerasVisibleFirst = 0;  // cameras whose report says Report::visibleFirst
  int64_t maxPatchesOffScreen = 0; // the most patches one camera proved off screen
};

WayRun runWay(const Terrain& terrain, const std::vector<Camera>& cams, const Way& way, CheckOptions o) {
  o.maxFindings = static_cast<size_t>(-1); // every finding: a truncated list would depend on what was skipped
  o.visibleFirst = way.visibleFirst;
  SweepOptions so;
  so.threads = 2; // the cache is shared by the threads
  so.resultCache = way.resultCache;
  so.keepCameras = false;
  WayRun out;
  out.seen.resize(cams.size());
  out.reported.assign(cams.size(), 0);
  // Serialised by sweep; no Catch2 assertions here (worker threads).
  so.onReport = [&](size_t i, const Report& r) {
    out.seen[i] = seenOf(r, o.countOffScreen);
    out.reported[i] = 1;
    out.findings += static_cast<int64_t>(out.seen[i].size()) - 1 - (r.error.empty() ? 0 : 1);
    for (const Finding& f : r.findings) out.offScreenFindings += !f.onScreen;
    out.camerasVisibleFirst += r.visibleFirst;
    out.maxPatchesOffScreen = std::max(out.maxPatchesOffScreen, r.stats.patchesOffScreen);
  };
  out.res = sweep(terrain, cams, o, so);
  out.verdict = verdictOf(out.res, o.countOffScreen);
  return out;
}

// Camera by camera the same as the reference; the first camera that differs is named with its first differing line.
void requireSameSeen(const WayRun& ref, const WayRun& got, const std::string& what) {
  INFO(what);
  REQUIRE(got.seen.size() == ref.seen.size());
  size_t differing = 0, first = 0;
  for (size_t c = 0; c < ref.seen.size(); ++c)
    if (got.seen[c] != ref.seen[c] || got.reported[c] != ref.reported[c]) first = differing++ ? first : c;
  if (differing > 0) {
    const std::vector<std::string>&a = ref.seen[first], &b = got.seen[first];
    size_t k = 0;
    while (k < a.size() && k < b.size() && a[k] == b[k]) ++k;
    INFO(differing << " cameras differ, the first is camera " << first << ": line " << k << "\n  reference: "
                   << (k < a.size() ? a[k] : "(none)") << "\n  this way:  " << (k < b.size() ? b[k] : "(none)"));
    CHECK(differing == 0);
  }
  CHECK(got.verdict == ref.verdict);
  CHECK(got.res.camerasDone == ref.res.camerasDone);
  CHECK(got.res.camerasInvalid == ref.res.camerasInvalid);
  CHECK(got.res.camerasUndecided == ref.res.camerasUndecided);
}

// The scene's cameras for the comparison: `random` seeded random ones, then its camera path (or its [camera]).
std::vector<Camera> camerasOf(const Terrain& terrain, int random, uint64_t seed) {
  std::vector<Camera> cams = randomCameras(terrain, random, seed);
  for (const Camera& c : pathCameras(terrain)) cams.push_back(c);
  return cams;
}

struct Compared {
  WayRun reference;
  std::vector<WayRun> ways; // kWays[1..3]
};

// The four ways on one scene; every way camera by camera equal to the one without shortcuts.
Compared compareWays(const std::string& what, const Terrain& terrain, const std::vector<Camera>& cams,
                     const CheckOptions& o = {}) {
  Compared c;
  c.reference = runWay(terrain, cams, kWays[0], o);
  for (size_t w = 1; w < 4; ++w) {
    c.ways.push_back(runWay(terrain, cams, kWays[w], o));
    requireSameSeen(c.reference, c.ways.back(), what + ", " + kWays[w].name + " vs " + kWays[0].name);
  }
  return c;
}

bool needsGpu(const Scene& s) { return !s.lod.shader.empty() || s.lod.evaluate == LodEvaluate::Gpu; }

// grid.toml flat, screen_sphere without frustum culling: with the eye on the terrain in the plane z = 2 + 4k (edge
// midpoints) and looking along +z, the edges whose midpoints lie in the image plane get NaN factors and the patches
// beside them in view are holes (tests/verify/hard_geometry_test.cpp). Those cameras, then random ones.
struct HoleScene {
  Terrain terrain;
  std::vector<Camera> cams;
};
HoleScene holeScene(int random) {
  const Scene s = loadExample("grid.toml", {"displacement.kind=none", "lod.scheme=screen_sphere",
                                            "tessellation.partitioning=fractional_even", "lod.frustum_cull=false"});
  HoleScene h{prepared(s), {}};
  for (const glm::vec3& eye : {glm::vec3(0, 0, 2), glm::vec3(0, 0, 0), glm::vec3(1, 0, 2), glm::vec3(-13, 0, -10)}) {
    Camera c = s.camera;
    c.eye = eye;
    c.target = eye + glm::vec3(0, 0, 100);
    h.cams.push_back(c);
  }
  for (const Camera& c : camerasOf(h.terrain, random, 5)) h.cams.push_back(c);
  return h;
}

// The variants with findings on screen: the comparison must not be vacuous there.
void requireFindings(const Compared& c, const char* what) {
  INFO(what);
  CHECK(c.reference.findings > 0);
}

void compareFindingVariants(int random, Kernel kernel) {
  CheckOptions o;
  o.kernel = kernel;
  const std::string k = std::string(" (") + toString(kernel) + ")";
  {
    const Terrain t = prepared(loadExample("rings_small.toml", {"lod.adjacency_clamp=none"}));
    requireFindings(compareWays("rings_small.toml, clamp none" + k, t, camerasOf(t, random, 3), o), "rings none");
  }
  {
    const HoleScene h = holeScene(random);
    const Compared c = compareWays("grid.toml flat, eye on edge midpoints (holes)" + k, h.terrain, h.cams, o);
    CHECK(c.reference.res.total.holes > 0);
  }
  {
    const Terrain t = prepared(loadExample("heightmap_offscreen.toml"));
    const Compared c = compareWays("heightmap_offscreen.toml" + k, t, camerasOf(t, random, 7), o);
    requireFindings(c, "heightmap_offscreen");
    CHECK(c.reference.offScreenFindings > 0); // findings off screen beside those on screen
  }
  {
    // Without balance (jumps of more than one level) the pow2 clamp is still watertight here; without the clamp too
    // the jumps crack. The layout is each camera's own (layoutFor).
    const Terrain t = prepared(loadExample("quadtree_cdlod.toml", {"layout.balance=none", "lod.adjacency_clamp=none"}));
    requireFindings(compareWays("quadtree_cdlod.toml, balance none, clamp none" + k, t, camerasOf(t, random, 9), o),
                    "quadtree");
  }
}

// The README's unbalanced CDLOD quadtree (layout.lod_distance_ratio = 1: jumps beyond 2x) cracks with the pow2 clamp
// on: one of the 10 random cameras of seed 9 sees them.
void compareJumps(int random) {
  const Terrain t = prepared(loadExample("quadtree_cdlod.toml", {"layout.balance=none", "layout.lod_distance_ratio=1"}));
  requireFindings(compareWays("quadtree_cdlod.toml, balance none, lod_distance_ratio 1", t, camerasOf(t, random, 9)),
                  "quadtree jumps beyond 2x");
}

} // namespace

TEST_CASE("sweep shortcuts: scenes with findings on screen show the same findings camera by camera with and without "
          "each shortcut",
          "[verify][sweep][shortcuts]") {
  compareFindingVariants(10, Kernel::Epick);
  compareFindingVariants(4, Kernel::Epeck);
  compareJumps(10);
}

TEST_CASE("sweep shortcuts: every example scene and the variants with findings show the same findings on 40 random "
          "cameras and the scene's own with and without each shortcut",
          "[verify][sweep][shortcuts][slow]") {
  std::vector<std::string> files;
  for (const auto& e : std::filesystem::directory_iterator(FFTESS_EXAMPLES_DIR))
    if (e.path().extension() == ".toml") files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 10);
  size_t compared = 0;
  for (const std::string& f : files) {
    const Scene s = loadExample(f);
    if (needsGpu(s)) continue; // lod.shader / lod.evaluate = "gpu": no GPU here
    const Terrain t = prepared(s);
    compareWays(f, t, camerasOf(t, 40, 11));
    ++compared;
  }
  CHECK(compared >= 10);
  const Terrain none = prepared(loadExample("terrain.toml", {"lod.adjacency_clamp=none"}));
  const std::vector<Camera> cams = camerasOf(none, 40, 11);
  requireFindings(compareWays("terrain.toml, clamp none", none, cams), "terrain none");
  CheckOptions epeck;
  epeck.kernel = Kernel::Epeck;
  compareWays("terrain.toml, clamp none (epeck)", none, std::vector<Camera>(cams.begin(), cams.begin() + 12), epeck);
  const Terrain unbalanced = prepared(loadExample("quadtree_cdlod.toml", {"layout.balance=none"}));
  compareWays("quadtree_cdlod.toml, balance none", unbalanced, camerasOf(unbalanced, 40, 11));
  compareJumps(40);
  compareFindingVariants(40, Kernel::Epick);
}

TEST_CASE("sweep shortcuts: with countOffScreen the visible-first request is ignored and every finding is that of the "
          "full check",
          "[verify][sweep][shortcuts][onscreen]") {
  const Terrain t = prepared(loadExample("heightmap_offscreen.toml"));
  const std::vector<Camera> cams = camerasOf(t, 6, 7);
  CheckOptions o;
  o.countOffScreen = true;
  const Compared c = compareWays("heightmap_offscreen.toml, countOffScreen", t, cams, o);
  CHECK(c.reference.offScreenFindings > 0); // the full check's findings off screen take part
  for (const WayRun& w : c.ways) {
    CHECK(w.camerasVisibleFirst == 0);
    CHECK(w.res.total.patchesOffScreen == 0);
    CHECK(w.res.total.edgesOffScreen == 0);
    CHECK(w.res.total.cracks == c.reference.res.total.cracks); // all of them, off screen too
    CHECK(w.res.total.tJunctions == c.reference.res.total.tJunctions);
    CHECK(w.offScreenFindings == c.reference.offScreenFindings);
    CHECK_FALSE(w.res.visibleFirst);
  }
}

namespace {

// Issue 42: with --gpu-float conformant visible first dropped the findings of matching pairs off screen (510 of 535
// on gpu_float_control.toml, seed 2). It now turns itself off there; the result cache stays on and must lose nothing.
void compareGpuFloat(int random) {
  CheckOptions o;
  o.gpuFloat = GpuFloat::Conformant;
  for (const char* f : {"gpu_float_control.toml", "rings_small.toml"}) {
    const Terrain t = prepared(loadExample(f));
    const Compared c = compareWays(std::string(f) + ", --gpu-float conformant", t, camerasOf(t, random, 2), o);
    for (const WayRun& w : c.ways) {
      CHECK(w.camerasVisibleFirst == 0); // turned off, whatever the way asked
      CHECK(w.res.total.gpuFloatFindings == c.reference.res.total.gpuFloatFindings);
      CHECK(w.res.total.gpuFloatPairs == c.reference.res.total.gpuFloatPairs);
    }
    if (std::string(f) == "gpu_float_control.toml") CHECK(c.reference.res.total.gpuFloatFindings > 0);
  }
}

} // namespace

TEST_CASE("sweep shortcuts: with --gpu-float conformant every way finds the same GPU float findings camera by camera "
          "(visible first turns itself off)",
          "[verify][sweep][shortcuts][gpufloat]") {
  compareGpuFloat(60);
}

TEST_CASE("sweep shortcuts: with --gpu-float conformant every way finds the same GPU float findings on 400 random "
          "cameras",
          "[verify][sweep][shortcuts][gpufloat][slow]") {
  compareGpuFloat(400);
}

namespace {

// geomorph.toml (vertices morph by the camera's distance) and bonaventura_mip.toml (heights at the camera's mip level).
const char* const kCameraDependent[] = {"geomorph.toml", "bonaventura_mip.toml"};

} // namespace

TEST_CASE("sweep shortcuts: a scene with a camera-dependent effect gets no result cache hit",
          "[verify][sweep][shortcuts]") {
  for (const char* f : kCameraDependent) {
    INFO(f);
    const Scene s = loadExample(f);
    CHECK_FALSE(cameraDependentEffects(s).empty());
    const Terrain t = prepared(s);
    const Compared c = compareWays(f, t, camerasOf(t, 6, 13));
    for (const WayRun& w : c.ways) {
      CHECK_FALSE(w.res.resultCache);
      CHECK(w.res.work.cacheHits == 0);
      CHECK(w.res.work.seamHits == 0);
    }
  }
  // Without the effect the scene declares nothing camera-dependent.
  CHECK(cameraDependentEffects(loadExample("bonaventura_mip.toml", {"displacement.mip=none"})).empty());
  CHECK(cameraDependentEffects(loadExample("terrain.toml")).empty());
}

namespace {

// A same-size shared edge pair of rings_small.toml that its scene camera draws and sees (its middle in view), with
// the same factor on both sides and interior points: the pair a seam proof or a cached match would decide without
// evaluating its points.
Finding seamPairInView(const Terrain& t, const Camera& cam) {
  CheckOptions o;
  o.keepMatches = true;
  o.maxFindings = static_cast<size_t>(-1);
  const Report r = checkScene(t, cam, o);
  REQUIRE(r.error.empty());
  const lod::Camera lc = lodCameraOf(cam);
  for (const Finding& f : r.findings)
    if (f.classification == Classification::Match && f.a.patch.level == f.b.patch.level &&
        f.a.hullFactorBits == f.b.hullFactorBits && f.a.pointCount >= 4 && f.a.paramLo == 0 && f.a.paramHi == 1 &&
        inView(lc, (f.edgeStart + f.edgeEnd) * 0.5f))
      return f;
  FAIL("no same-size pair in view");
  return {};
}

} // namespace

TEST_CASE("sweep shortcuts: fault injection still finds its injected crack with the result cache and visible first on",
          "[verify][sweep][shortcuts][fault]") {
  const Scene s = loadExample("rings_small.toml");
  const Terrain t = prepared(s);
  const Finding pair = seamPairInView(t, s.camera);
  // One ulp up in y on the pair's second interior point of side a: the two sides no longer meet there.
  Fault fault;
  fault.kind = Fault::Kind::PointUlp;
  fault.patch = pair.a.patch.index;
  fault.edge = pair.a.edge;
  fault.point = 2;
  fault.axis = 1;
  fault.direction = 1;
  CheckOptions o;
  o.fault = std::make_shared<const Fault>(fault);
  // The scene camera three times (a cache would know the pair from the first), between random cameras.
  std::vector<Camera> cams = randomCameras(t, 4, 17);
  cams.insert(cams.begin() + 1, s.camera);
  cams.insert(cams.begin() + 3, s.camera);
  cams.push_back(s.camera);
  // The ground truth: the full check of the scene camera finds it, on screen.
  const Report truth = checkScene(t, s.camera, o);
  bool found = false;
  for (const Finding& f : truth.findings)
    found = found || (f.classification != Classification::Match && f.onScreen &&
                      ((f.a.patch.index == fault.patch && f.a.edge == fault.edge) ||
                       (f.b.patch.index == fault.patch && f.b.edge == fault.edge)));
  REQUIRE(found);
  const Compared c = compareWays("rings_small.toml with a point fault", t, cams, o);
  // Every copy of the scene camera shows it with both shortcuts on (and compareWays: as without them).
  const WayRun& both = c.ways[2];
  for (size_t i : {size_t(1), size_t(3), cams.size() - 1}) {
    INFO("camera " << i);
    bool here = false;
    for (const std::string& line : both.seen[i])
      here = here || line.find(" a " + refText(pair.a.patch) + " e" + std::to_string(pair.a.edge) + " ") !=
                         std::string::npos;
    CHECK(here);
  }
  CHECK(both.verdict != Verdict::Watertight);
}

// ---- The shortcuts ran where they should (these fail until verify's check and sweep implement them) --------------

TEST_CASE("Shortcuts run: visible first skips the patches and edge pairs proven off screen on terrain.toml",
          "[verify][sweep][shortcuts]") {
  const Terrain t = prepared(loadExample("terrain.toml"));
  const std::vector<Camera> cams = randomCameras(t, 8, 21);
  const WayRun full = runWay(t, cams, kWays[0], {});
  const WayRun vf = runWay(t, cams, kWays[1], {});
  requireSameSeen(full, vf, "terrain.toml, visible first");
  CHECK(vf.res.visibleFirst);
  CHECK(vf.camerasVisibleFirst == cams.size());
  CHECK(vf.maxPatchesOffScreen > 0);
  CHECK(vf.res.total.patchesOffScreen > 0);
  CHECK(vf.res.total.edgesOffScreen > 0);
  CHECK(vf.res.work.boxTests > 0);
  // What was skipped is work not done: fewer LOD evaluations than one per patch and camera.
  CHECK(vf.res.work.lodEvaluations + vf.res.total.patchesOffScreen >= full.res.work.lodEvaluations);
  CHECK(vf.res.work.lodEvaluations < full.res.work.lodEvaluations);
  CHECK(full.camerasVisibleFirst == 0);
  CHECK(full.res.total.patchesOffScreen == 0);
}

TEST_CASE("Shortcuts run: the result cache decides repeated pairs without evaluating them on terrain.toml",
          "[verify][sweep][shortcuts]") {
  const Terrain t = prepared(loadExample("terrain.toml"));
  const std::vector<Camera> cams = randomCameras(t, 8, 21);
  const WayRun full = runWay(t, cams, kWays[0], {});
  const WayRun cached = runWay(t, cams, kWays[2], {});
  requireSameSeen(full, cached, "terrain.toml, result cache");
  CHECK(cached.res.resultCache);
  CHECK(cached.res.resultCacheOff.empty());
  CHECK(cached.res.work.cacheHits + cached.res.work.seamHits > 0);
  CHECK(cached.res.work.seamProofs > 0);
  CHECK(cached.res.resultCacheItems > 0);
  // The stated bound: 16 bytes per cache slot plus one byte per shared edge pair (the seam proofs).
  CHECK(cached.res.resultCacheBytes == 16 * SweepOptions{}.resultCacheSlots + t.data().tree->allPairs.size());
  CHECK(cached.res.work.domainEvaluations < full.res.work.domainEvaluations);
  CHECK_FALSE(full.res.resultCache);
  CHECK(full.res.work.cacheHits + full.res.work.seamHits == 0);
}

TEST_CASE("Shortcuts run: a camera-dependent effect turns the result cache off and says why, the same scene without "
          "it gets hits",
          "[verify][sweep][shortcuts]") {
  for (const char* f : kCameraDependent) {
    INFO(f);
    const Terrain t = prepared(loadExample(f));
    const WayRun w = runWay(t, camerasOf(t, 4, 13), kWays[3], {});
    CHECK_FALSE(w.res.resultCache);
    CHECK_FALSE(w.res.resultCacheOff.empty());
    const std::string effect = cameraDependentEffects(t.scene()).front();
    CHECK(w.res.resultCacheOff.find(effect.substr(0, effect.find(' '))) != std::string::npos); // names the key
  }
  const Terrain t = prepared(loadExample("bonaventura_mip.toml", {"displacement.mip=none"}));
  const WayRun w = runWay(t, camerasOf(t, 4, 13), kWays[3], {});
  CHECK(w.res.resultCache);
  CHECK(w.res.work.cacheHits + w.res.work.seamHits > 0);
}
