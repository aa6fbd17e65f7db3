// fftess prove (verify/prove.h): branch and bound over a region of cameras. Regions are evaluated on a pool of
// threads (each with its own BoundContext and edge cache) from a shared depth-first stack; a region that is not
// decided is split in two along its widest coordinate (relative to the root's width). The root, every suspect region
// (a pair's factors give a mismatch, a patch may be discarded on screen) and every undecided leaf are sampled: their
// centre camera and their simplest camera go through the full check (checkScene), and an on-screen finding or a hole
// there is the counterexample.
#include "verify/prove.h"
#include "verify/prove_internal.h"
#include "verify/sweep.h"
#include "base/threads.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

namespace fftess::verify {

const char* toString(ProveVerdict v) {
  switch (v) {
  case ProveVerdict::Proved: return "PROVED";
  case ProveVerdict::Counterexample: return "COUNTEREXAMPLE";
  case ProveVerdict::Undecided: return "UNDECIDED";
  case ProveVerdict::InvalidCameras: return "INVALID_CAMERAS";
  case ProveVerdict::NothingOnScreen: return "NOTHING_ON_SCREEN";
  }
  return "UNDECIDED";
}

CameraRegion defaultRegion(const Terrain& terrain) {
  const Extent& e = terrain.extent();
  const float side = std::max(e.maxX - e.minX, e.maxZ - e.minZ);
  const float r = std::ldexp(side, -12); // exact (a power-of-two scaling)
  const Camera& c = terrain.scene().camera;
  CameraRegion g;
  g.eyeLo = c.eye - glm::vec3(r);
  g.eyeHi = c.eye + glm::vec3(r);
  g.targetLo = c.target - glm::vec3(r);
  g.targetHi = c.target + glm::vec3(r);
  return g;
}

std::string regionInvalidCameras(const CameraRegion& r, const glm::vec3& up) {
  // The directions d = target - eye of the region: a box, each bound one double subtraction of two floats (exact
  // unless the exponents are far apart; the margin below covers that rounding many times over).
  glm::dvec3 lo, hi;
  double mag = 0;
  for (int i = 0; i < 3; ++i) {
    lo[i] = static_cast<double>(r.targetLo[i]) - static_cast<double>(r.eyeHi[i]);
    hi[i] = static_cast<double>(r.targetHi[i]) - static_cast<double>(r.eyeLo[i]);
    mag = std::max({mag, std::fabs(lo[i]), std::fabs(hi[i])});
  }
  // |d|^2 overflows float (validateCamera: not finite) somewhere in the box.
  if (mag * mag * 3.0 >= 0x1p127) return "a view direction |target - eye|^2 may overflow float";
  // The margin: 2^-30 of the largest direction (cameras within it of the degenerate set are refused by float's lookAt
  // or have no meaningful view), and 2^-60 absolutely (|target - eye|^2 below 2^-126 is refused).
  const double m = std::max(mag * 0x1p-30, 0x1p-60);
  lo -= glm::dvec3(m);
  hi += glm::dvec3(m);
  if (lo.x <= 0 && hi.x >= 0 && lo.y <= 0 && hi.y >= 0 && lo.z <= 0 && hi.z >= 0)
    return "eye == target (or |target - eye| too short for float)";
  // Some d = lambda * up, lambda != 0, in the box: the lambdas of each coordinate's slab, intersected.
  double l = -HUGE_VAL, h = HUGE_VAL;
  for (int i = 0; i < 3; ++i) {
    const double u = static_cast<double>(up[i]);
    if (u == 0) {
      if (!(lo[i] <= 0 && hi[i] >= 0)) return {};
      continue;
    }
    const double a = lo[i] / u, b = hi[i] / u;
    l = std::max(l, std::min(a, b));
    h = std::min(h, std::max(a, b));
  }
  if (l <= h && (l != 0 || h != 0)) return "the view direction parallel to up (looking straight down or up)";
  return {};
}

namespace {

using detail::RegionOutcome;

float& coord(CameraRegion& r, int d, bool hi) {
  glm::vec3& v = d < 3 ? (hi ? r.eyeHi : r.eyeLo) : (hi ? r.targetHi : r.targetLo);
  return v[d % 3];
}
float coord(const CameraRegion& r, int d, bool hi) { return coord(const_cast<CameraRegion&>(r), d, hi); }

// The float in [lo, hi] with the fewest significant bits: 0 when inside, else the coarsest multiple of a power of two.
float simplest(float lo, float hi) {
  if (lo <= 0 && hi >= 0) return 0.0f;
  const double a = lo, b = hi;
  for (int k = 128; k >= -149; --k) {
    const double step = std::ldexp(1.0, k);
    const double m = std::ceil(a / step) * step;
    if (m <= b) return static_cast<float>(m);
  }
  return lo;
}

float centre(float lo, float hi) { return static_cast<float>((static_cast<double>(lo) + hi) * 0.5); }

std::string validate(const Terrain& terrain, const CameraRegion& r) {
  const Scene& s = terrain.scene();
  if (!s.lod.shader.empty()) return "lod.shader: a user shader is not compiled with Bounds; prove covers the built-in schemes";
  if (s.lod.evaluate == LodEvaluate::Gpu) return "lod.evaluate = \"gpu\": prove evaluates lod/'s C++ build over Bounds; use \"cpu\"";
  if (s.lod.scheme == LodScheme::Geomorph) return "lod.scheme = \"geomorph\": not compiled with Bounds (its levels are integers)";
  if (s.layout.kind == LayoutKind::Quadtree || terrain.cameraDependent() || !terrain.data().tree)
    return "layout.kind = \"quadtree\": the layout depends on the camera; prove covers static layouts";
  const std::vector<std::string> effects = cameraDependentEffects(s);
  if (!effects.empty()) return "camera-dependent effect: " + effects.front();
  for (int d = 0; d < 6; ++d) {
    const float lo = coord(r, d, false), hi = coord(r, d, true);
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo <= hi)) return "the region: each coordinate needs finite lo <= hi";
  }
  return {};
}

bool isCounterexample(const Report& rep) {
  if (!rep.error.empty()) return false;
  if (rep.stats.holes > 0) return true;
  for (const Finding& f : rep.findings)
    if (f.classification != Classification::Match && f.onScreen) return true;
  return false;
}

struct Item {
  CameraRegion region;
  int depth = 0;
};

struct Prover {
  const Terrain& terrain;
  const ProveOptions& o;
  ProveReport& rep;
  Prover(const Terrain& t, const ProveOptions& opt, ProveReport& r) : terrain(t), o(opt), rep(r) {}
  float rootWidth[6] = {};
  std::mutex m;
  std::condition_variable cv;
  std::vector<Item> stack;
  int busy = 0;
  bool stop = false;

  // The dimension to split (-1: none can be split).
  int splitDimension(const CameraRegion& r) const {
    int best = -1;
    double bestWidth = 0;
    for (int d = 0; d < 6; ++d) {
      if (!(rootWidth[d] > 0)) continue;
      const float lo = coord(r, d, false), hi = coord(r, d, true), mid = centre(lo, hi);
      if (!(mid > lo && mid < hi)) continue;
      const double w = (static_cast<double>(hi) - lo) / rootWidth[d];
      if (w > bestWidth) best = d, bestWidth = w;
    }
    return best;
  }

  Camera cameraAt(const CameraRegion& r, bool simple) const {
    Camera c = terrain.scene().camera;
    for (int d = 0; d < 6; ++d) {
      const float lo = coord(r, d, false), hi = coord(r, d, true);
      (d < 3 ? c.eye : c.target)[d % 3] = simple ? simplest(lo, hi) : centre(lo, hi);
    }
    return c;
  }

  // The region's sampled cameras through the full check; true when one is a counterexample (recorded).
  bool sample(const CameraRegion& r) {
    const int count = std::min(2, std::max(0, o.samplesPerRegion)); // the centre, then the simplest camera
    CheckOptions co;
    co.kernel = o.kernel;
    for (int k = 0; k < count; ++k) {
      const Camera c = cameraAt(r, k == 1);
      Report cr = checkScene(terrain, c, co);
      std::lock_guard<std::mutex> lock(m);
      ++rep.stats.camerasChecked;
      if (isCounterexample(cr) && rep.verdict != ProveVerdict::Counterexample) {
        rep.verdict = ProveVerdict::Counterexample;
        rep.counterexample = c;
        rep.counterexampleReport = std::move(cr);
        stop = true;
        return true;
      }
    }
    return false;
  }

  // The fraction of the root's volume the region covers (its coordinates of non-zero root width).
  double volume(const CameraRegion& r) const {
    double v = 1;
    for (int d = 0; d < 6; ++d)
      if (rootWidth[d] > 0) v *= (static_cast<double>(coord(r, d, true)) - coord(r, d, false)) / rootWidth[d];
    return v;
  }

  void undecided(const Item& it, const std::string& reason) { // under m
    ++rep.stats.regionsUndecided;
    rep.stats.volumeUndecided += volume(it.region);
    if (rep.undecided.size() < o.maxUndecidedListed) rep.undecided.push_back({it.region, it.depth, reason});
  }

  void invalid(const Item& it, const std::string& reason) { // under m
    ++rep.stats.regionsInvalid;
    rep.stats.volumeInvalid += volume(it.region);
    if (rep.invalid.size() < o.maxUndecidedListed) rep.invalid.push_back({it.region, it.depth, reason});
  }

  // Splits the item in two along dimension d (under m).
  void split(const Item& it, int d) {
    Item a = it, b = it;
    const float mid = centre(coord(it.region, d, false), coord(it.region, d, true));
    coord(a.region, d, true) = mid;
    coord(b.region, d, false) = mid;
    a.depth = b.depth = it.depth + 1;
    stack.push_back(b);
    stack.push_back(a); // depth first: the lower half next
  }

  // A region that may hold invalid cameras is never evaluated (its bounds would reason about NaN cameras): split
  // until maxDepth, where it is listed as such.
  void finishInvalid(const Item& it, const std::string& reason) {
    std::lock_guard<std::mutex> lock(m);
    rep.stats.maxDepthReached = std::max(rep.stats.maxDepthReached, it.depth);
    const int d = it.depth < o.maxDepth ? splitDimension(it.region) : -1;
    if (d < 0) return invalid(it, reason);
    split(it, d);
  }

  void finish(const Item& it, const detail::RegionResult& r) {
    std::lock_guard<std::mutex> lock(m);
    ProveStats& s = rep.stats;
    s.pairsByTrace += r.pairsByTrace;
    s.pairsByValue += r.pairsByValue;
    s.pairsOffScreen += r.pairsOffScreen;
    s.patchesOffScreen += r.patchesOffScreen;
    s.lodPaths += r.lodPaths;
    s.maxDepthReached = std::max(s.maxDepthReached, it.depth);
    if (r.outcome == RegionOutcome::Decided) {
      ++s.regionsProved;
      if (r.onScreen) {
        s.volumeProved += volume(it.region);
      } else {
        ++s.regionsNothingOnScreen;
        s.volumeNothingOnScreen += volume(it.region);
      }
      return;
    }
    const int d = it.depth < o.maxDepth ? splitDimension(it.region) : -1;
    if (d < 0) {
      undecided(it, (it.depth >= o.maxDepth ? "maximum depth: " : "cannot split further: ") + r.why);
      return;
    }
    split(it, d);
  }

  void worker() {
    const detail::TerrainData& t = terrain.data();
    detail::ProveScratch scratch(t, o.maxPaths);
    std::vector<uint8_t> seams(t.tree->allPairs.size(), 0);
    for (;;) {
      Item it;
      {
        std::unique_lock<std::mutex> lock(m);
        cv.wait(lock, [&] { return stop || !stack.empty() || busy == 0; });
        if (o.cancel && o.cancel->load()) stop = true;
        if (rep.stats.regions >= o.maxRegions) stop = true;
        if (stop || stack.empty()) {
          cv.notify_all();
          return;
        }
        it = stack.back();
        stack.pop_back();
        ++busy;
        ++rep.stats.regions;
      }
      const std::string bad = regionInvalidCameras(it.region, terrain.scene().camera.up);
      if (!bad.empty()) {
        const bool leaf = it.depth >= o.maxDepth || splitDimension(it.region) < 0;
        if (it.depth == 0 || leaf) sample(it.region); // its valid cameras may still be counterexamples
        finishInvalid(it, bad);
        {
          std::lock_guard<std::mutex> lock(m);
          --busy;
        }
        cv.notify_all();
        continue;
      }
      const detail::RegionResult r = detail::evaluateRegion(t, it.region, scratch, seams);
      const bool leaf = r.outcome != RegionOutcome::Decided && (it.depth >= o.maxDepth || splitDimension(it.region) < 0);
      if (it.depth == 0 || r.outcome == RegionOutcome::Suspect || leaf) sample(it.region);
      finish(it, r);
      {
        std::lock_guard<std::mutex> lock(m);
        --busy;
      }
      cv.notify_all();
    }
  }
};

} // namespace

ProveReport proveScene(const Terrain& terrain, const ProveOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  ProveReport rep;
  rep.regionDefault = !options.regionGiven;
  rep.region = options.regionGiven ? options.region : defaultRegion(terrain);
  rep.error = validate(terrain, rep.region);
  if (!rep.error.empty()) return rep;
  Prover p(terrain, options, rep);
  for (int d = 0; d < 6; ++d) p.rootWidth[d] = coord(rep.region, d, true) - coord(rep.region, d, false);
  p.stack.push_back({rep.region, 0});
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  // A thread the system refuses stops the others and throws one message (base/threads.h).
  runOnThreads(threads, [&p](int) { p.worker(); }, [&p] {
    {
      std::lock_guard<std::mutex> lock(p.m);
      p.stop = true;
    }
    p.cv.notify_all();
  });
  if (rep.verdict != ProveVerdict::Counterexample) {
    for (const Item& it : p.stack)
      p.undecided(it, options.cancel && options.cancel->load() ? "cancelled" : "maximum regions reached");
    const ProveStats& s = rep.stats;
    rep.verdict = s.regionsUndecided > 0                        ? ProveVerdict::Undecided
                  : s.regionsInvalid > 0                        ? ProveVerdict::InvalidCameras
                  : s.regionsProved == s.regionsNothingOnScreen ? ProveVerdict::NothingOnScreen
                                                                : ProveVerdict::Proved;
  }
  rep.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return rep;
}

} // namespace fftess::verify
