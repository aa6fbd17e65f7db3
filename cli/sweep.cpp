// fftess sweep SCENE: check a scene from many cameras (the scene's path, an orbit, a flyover, random), with
// progress and Ctrl-C, tally the findings by cause, print the summary, write the JSON / SVG reports atomically.
#include "camera_file.h"
#include "causes.h"
#include "ci_scene.h"
#include "commands.h"
#include "common.h"
#include "options.h"
#include "base/threads.h"
#include "gpu_lod.h"
#include "progress.h"
#include "report_gltf.h"
#include "report_json.h"
#include "report_svg.h"
#include "scene_options.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <stdexcept>
#include <cstdint>
#include <memory>

namespace fftess::cli {
namespace {

// Causes over a sweep: every finding of every camera names a cause (classification + findingCause key). Per cause: the
// findings, the cameras where it appeared, and the first camera where it appeared (lowest camera index; within that
// camera the first finding in layout order, whose explanation is the example). Fed by SweepOptions::onReport, which
// sweep serialises, in whatever order the cameras finish: the result does not depend on that order.
struct CauseInfo {
  std::string detail;     // explanation of the first finding with this cause
  std::string fix;        // its fix (Cause::fix)
  std::string id;         // Cause::id
  int64_t findings = 0;   // findings with this cause, over all cameras
  size_t cameras = 0;     // cameras with at least one finding with this cause
  size_t first = 0;       // first camera (index) where it appeared
  size_t firstFinding = 0; // index of that finding in the first camera's report
};

struct CauseTally {
  std::map<std::string, CauseInfo> causes;
  bool countOffScreen = false; // --offscreen: off-screen findings are tallied with the others

  void add(size_t camera, const vf::Report& r) {
    std::set<std::string> here;
    for (size_t k = 0; k < r.findings.size(); ++k) {
      const vf::Finding& f = r.findings[k];
      if (f.classification == vf::Classification::Match) continue;
      const Cause cause = findingCause(f);
      // Off-screen findings apart (not counted): their own keys, "crack (off screen): ...".
      const char* off = f.onScreen || countOffScreen ? "" : " (off screen)";
      addKey(std::string(vf::toString(f.classification)) + off + ": " + cause.key, cause, camera, k, here);
    }
    for (size_t k = 0; k < r.holes.size(); ++k) {
      const Cause cause = holeCause(r.holes[k]);
      // Holes after the findings of the same camera (index offset keeps the order stable).
      addKey("hole: " + cause.key, cause, camera, r.findings.size() + k, here);
    }
    for (size_t k = 0; k < r.undecided.size(); ++k) { // the key starts with "undecided: "
      const Cause cause = holeCause(r.undecided[k]);
      addKey(cause.key, cause, camera, r.findings.size() + r.holes.size() + k, here);
    }
    const size_t gpuFirst = r.findings.size() + r.holes.size() + r.undecided.size();
    for (size_t k = 0; k < r.gpuFloat.size(); ++k) { // --gpu-float: the key starts with "may crack on some GPUs: "
      Cause cause = gpuFloatCause(r.gpuFloat[k]);
      cause.detail = gpuFloatLine(r.gpuFloat[k]); // the example names the sides
      addKey(cause.key, cause, camera, gpuFirst + k, here);
    }
  }

  void addKey(const std::string& key, const Cause& cause, size_t camera, size_t k, std::set<std::string>& here) {
    {
      auto [it, added] = causes.try_emplace(key);
      CauseInfo& c = it->second;
      ++c.findings;
      if (here.insert(key).second) ++c.cameras;
      if (added || camera < c.first || (camera == c.first && k < c.firstFinding)) {
        c.first = camera;
        c.firstFinding = k;
        c.detail = cause.detail;
        c.fix = cause.fix;
        c.id = cause.id;
      }
    }
  }

  // Cause keys in the order they first appeared (by first camera, then first finding).
  std::vector<std::string> order() const {
    std::vector<std::string> keys;
    for (const auto& kv : causes) keys.push_back(kv.first);
    std::stable_sort(keys.begin(), keys.end(), [&](const std::string& x, const std::string& y) {
      const CauseInfo &a = causes.at(x), &b = causes.at(y);
      return a.first != b.first ? a.first < b.first : a.firstFinding < b.firstFinding;
    });
    return keys;
  }
};


} // namespace

// ---- sweep -------------------------------------------------------------------------------------------------------
// Cameras when the scene has no [[camera_path]] and no camera option is given (cameraSet, and the help says so).
constexpr int kDefaultFlyover = 200;

CLI::App* addSweep(CLI::App& app, SweepArgs& a) {
  CLI::App* sub = app.add_subcommand("sweep", "Check a scene from many cameras (a path, an orbit, a flyover, random)");
  sub->footer("Examples:\n"
              "  fftess sweep docs/examples/terrain.toml\n"
              "  fftess sweep docs/examples/terrain.toml --set lod.adjacency_clamp=none --random 500 --seed 3 "
              "--json sweep.json --svg sweep.svg\n"
              "Cameras (the first that applies): --cameras FILE, or --orbit N, --flyover N or --random N (only one of "
              "these four); else the scene's [[camera_path]]; else a flyover of " + std::to_string(kDefaultFlyover) +
              " cameras across the terrain (never the scene's [camera] alone: fftess check checks that one).\n"
              "Ctrl-C stops early and still prints the summary and writes the reports (exit 130 if no crack was found).\n"
              "Exit status: 0 watertight, 1 cracks or holes found, nothing checked or a camera that could not be checked, "
              "2 bad usage or scene, 3 internal error.");
  addSceneOptions(sub, a);
  // The *Given flags: a count given as -1 is refused like any other count below 1, never taken for "not given".
  sub->add_option_function<int>("--orbit", [&a](const int& n) { a.orbit = n, a.orbitGiven = true; },
                                "N cameras on a circle around the terrain, looking at its centre");
  sub->add_option_function<int>("--flyover", [&a](const int& n) { a.flyover = n, a.flyoverGiven = true; },
                                "N cameras on a straight flight across the terrain");
  sub->add_option_function<int>("--random", [&a](const int& n) { a.random = n, a.randomGiven = true; },
                                "N cameras at random positions and directions (see --seed)");
  addSeedOption(sub, a.seed, "Seed of --random's cameras");
  addShowOption(sub, a.show, "Causes listed in the cause table, each with its example and fix (all are in --json)");
  addThreadsOption(sub, a.threads, "Worker threads");
  sub->add_option("--label", a.label, "Name for this run in the summary (default: the scene's name)");
  sub->add_option("--shard", a.shard,
                  "K/N: check only the cameras i with i % N == K - 1 (1 <= K <= N; indices stay global, so the "
                  "shards' --json reports merge with 'fftess merge' into the report of one run: exactly, with "
                  "--no-result-cache)");
  sub->add_flag("--no-visible-first", a.noVisibleFirst,
                "Check every patch and shared edge of each camera, also those proven off screen (default: visible "
                "first, which skips them: the on-screen findings and the verdict are the same; --offscreen implies "
                "this)");
  sub->add_flag("--no-result-cache", a.noResultCache,
                "Prove every shared edge on every camera again (default: a camera reuses what earlier cameras proved "
                "about an edge; off by itself for camera-dependent effects, e.g. displacement.mip)");
  return sub;
}

// The cameras of a sweep by index (vf::CameraSet): the generator option given, else the scene's camera path, else a
// flyover of kDefaultFlyover.
static vf::CameraSet cameraSet(const SweepArgs& a, const vf::Terrain& terrain, uint64_t seed, CameraFile* file) {
  if (file) return vf::CameraSet::list(terrain, std::move(file->cameras)); // moved: held once
  if (a.orbit > 0) return vf::CameraSet::orbit(terrain, size_t(a.orbit));
  if (a.flyover > 0) return vf::CameraSet::flyover(terrain, size_t(a.flyover));
  if (a.random > 0) return vf::CameraSet::random(terrain, size_t(a.random), seed);
  if (!terrain.scene().cameraPath.empty()) return vf::CameraSet::path(terrain);
  return vf::CameraSet::flyover(terrain, kDefaultFlyover);
}

static std::string cameraWords(const SweepArgs& a, const vf::Terrain& terrain, uint64_t seed, const CameraFile* file) {
  if (file) return "cameras file " + file->path + ", " + std::to_string(file->lines.size()) + " cameras";
  if (a.orbit > 0) return "orbit of " + std::to_string(a.orbit);
  if (a.flyover > 0) return "flyover of " + std::to_string(a.flyover);
  if (a.random > 0) return std::to_string(a.random) + " random, seed " + std::to_string(seed);
  if (!terrain.scene().cameraPath.empty()) return "the scene's camera path";
  return "flyover of " + std::to_string(kDefaultFlyover) + ", the scene has no camera path";
}

// The same as a key (report_json.h, "cameras_source").
static const char* cameraSourceKey(const SweepArgs& a, const vf::Terrain& terrain, const CameraFile* file) {
  if (file) return "file";
  if (a.orbit > 0) return "orbit";
  if (a.flyover > 0) return "flyover";
  if (a.random > 0) return "random";
  return terrain.scene().cameraPath.empty() ? "flyover" : "scene_path";
}

// The sweep picture draws the cameras of the run (the path joined in order, the map's extent) up to `end` (all of
// them; an interrupted run's up to the last one checked), so --svg, and only --svg, holds them in memory.
static std::vector<vf::Camera> svgCameras(const vf::CameraSet& cams, size_t end) {
  std::vector<vf::Camera> out;
  out.reserve(std::min(end, cams.size()));
  for (size_t i = 0; i < end && i < cams.size(); ++i) out.push_back(cams.at(i));
  return out;
}

// --shard K/N: 1 <= K <= N, both whole numbers.
static void parseShard(const std::string& text, size_t& k, size_t& n) {
  k = 0, n = 1;
  if (text.empty()) return;
  const size_t slash = text.find('/');
  auto number = [&](const std::string& t, size_t& out) {
    if (t.empty() || t.size() > 9) return false;
    out = 0;
    for (char c : t) {
      if (c < '0' || c > '9') return false;
      out = out * 10 + static_cast<size_t>(c - '0');
    }
    return true;
  };
  size_t kk = 0, nn = 0;
  if (slash == std::string::npos || !number(text.substr(0, slash), kk) || !number(text.substr(slash + 1), nn) ||
      kk < 1 || nn < 1 || kk > nn)
    throw UsageError("--shard " + quoteToken(text) + ": expected K/N with 1 <= K <= N (e.g. 2/8)");
  k = kk - 1, n = nn;
}

// The options of a sweep, checked before any work (in this order: generators, counts, threads, seed, shard).
struct SweepPlan {
  uint64_t seed = 1;
  size_t shardK = 0, shardN = 1; // this run's share: global index g = shardK + local * shardN
  bool sharded = false;
  size_t global(size_t local) const { return shardK + local * shardN; }
  size_t shareOf(size_t total) const { return total > shardK ? (total - shardK + shardN - 1) / shardN : 0; }
};

static SweepPlan sweepPlan(const SweepArgs& a) {
  const int generators = a.orbitGiven + a.flyoverGiven + a.randomGiven;
  if (generators > 1) throw UsageError("sweep: give only one of --orbit, --flyover, --random");
  if (generators > 0 && !a.cameras.empty())
    throw UsageError("sweep: --cameras FILE is a camera source like --orbit, --flyover and --random: give only one");
  if (a.orbitGiven && a.orbit < 1) throw UsageError("--orbit " + std::to_string(a.orbit) + ": must be >= 1");
  if (a.flyoverGiven && a.flyover < 1) throw UsageError("--flyover " + std::to_string(a.flyover) + ": must be >= 1");
  if (a.randomGiven && a.random < 1) throw UsageError("--random " + std::to_string(a.random) + ": must be >= 1");
  // --threads: checked while parsing (addThreadsOption); again here for the Python module, which sets it directly.
  if (a.threads < 0 || a.threads > kMaxThreads)
    throw UsageError("--threads " + std::to_string(a.threads) + ": must be 0 (all cores) to " + std::to_string(kMaxThreads));
  if (a.show < 0) throw UsageError("--show " + std::to_string(a.show) + ": must be >= 0");
  SweepPlan p;
  p.seed = parseSeed(a.seed);
  parseShard(a.shard, p.shardK, p.shardN);
  p.sharded = !a.shard.empty();
  return p;
}

namespace {

// One sweep from the loaded scene to its reports: the cameras, the JSON report streamed as the cameras finish, and
// what the summary, the picture and the cause table keep of each camera. onReport and onCamera are called by
// verify's sweep, serialised, in whatever order the cameras finish.
class SweepRun {
public:
  SweepRun(const SweepArgs& a, const SweepPlan& plan, const vf::Terrain& terrain, const vf::CheckOptions& opt,
           AtomicFile* jsonFile, AtomicFile* svgFile, CameraFile* file)
      : a_(a), plan_(plan), terrain_(terrain), opt_(opt), cams_(cameraSet(a, terrain, plan.seed, file)),
        how_(cameraWords(a, terrain, plan.seed, file)), howKey_(cameraSourceKey(a, terrain, file)),
        requested_(plan.shareOf(cams_.size())), jsonFile_(jsonFile),
        svgFile_(svgFile) {
    if (file) camerasFile_ = {{"path", file->path}, {"hash", file->hashText()}, {"cameras", file->lines.size()}};
    tally_.countOffScreen = a.offscreen;
  }
  void beginJson();
  vf::SweepResult run(const std::atomic<bool>* cancel, bool talk, const std::string& label);
  std::string summaryText(const vf::SweepResult& res, const std::string& label, vf::Verdict verdict) const;
  void finishReports(const vf::SweepResult& res);
  // --gltf: the worst camera checked again, in 3D (false: no camera was checked, nothing to show).
  bool worstGltf(ReportFiles& reports, const vf::SweepResult& res) const;
  std::string worstWhy() const; // why worst_ is the camera --gltf shows
  void setCi(SweepCi* ci) { ci_ = ci; } // --sarif / --junit: fed every camera's report and result
  size_t requested() const { return requested_; }
  std::string eyeWords(size_t g) const { // camera g's eye and target, for --junit's test case names
    const vf::Camera c = cams_.at(g);
    char buf[160];
    std::snprintf(buf, sizeof buf, "eye (%g, %g, %g) target (%g, %g, %g)", double(c.eye.x), double(c.eye.y),
                  double(c.eye.z), double(c.target.x), double(c.target.y), double(c.target.z));
    return buf;
  }

private:
  void emitJson(const std::string& text);
  void flushPending(bool all);
  void onCamera(const vf::CameraResult& c);
  std::string causesText() const;

  const SweepArgs& a_;
  const SweepPlan& plan_;
  const vf::Terrain& terrain_;
  const vf::CheckOptions& opt_;
  // Every camera of the run (global indices, also when sharded), computed from its index when needed: memory does not
  // depend on the camera count, and there is no setup to wait for.
  const vf::CameraSet cams_;
  const std::string how_;
  const std::string howKey_; // how_ as a key (cameras_source)
  const size_t requested_; // this run's share of the cameras
  AtomicFile* jsonFile_;   // null without --json
  AtomicFile* svgFile_;    // null without --svg
  double elapsed_ = 0;
  // The JSON report streams: header now, each camera as it finishes (in camera order, through a small reorder
  // buffer), the summary at the end. The SVG keeps only what it draws.
  std::string jsonError_; // an I/O error while streaming (raised again when the report is finished)
  std::map<size_t, json> pending_; // local index -> camera text, waiting for the cameras before it
  size_t nextLocal_ = 0;
  bool anyCamera_ = false;
  std::vector<SvgCamera> dots_;
  std::vector<SvgHole> holes_;
  size_t crackCameras_ = 0, tjCameras_ = 0, holeCameras_ = 0;
  size_t firstInvalid_ = SIZE_MAX;
  size_t endChecked_ = 0; // 1 + the highest global index checked
  std::string firstInvalidError_;
  CauseTally tally_;
  // --gltf: the worst camera so far: rank 4 cracks that count (the largest counted gap: on screen, or all with
  // --offscreen), 3 a hole, 2 undecided patches, 1 T-junctions that count, 0 checked; the lowest index among equals.
  struct Worst {
    size_t camera = SIZE_MAX;
    int rank = -1;
    double gap = 0;
  } worst_;
  void noteWorst(size_t g, const vf::CameraResult& c);
  FactorDiffTally gpuDiffs_; // lod.evaluate = "gpu" / lod.shader: GPU vs C++ factors (cli/gpu_lod.h)
  json camerasFile_;         // --cameras: the file, its hash (shards must agree), its camera count; null otherwise
  SweepCi* ci_ = nullptr;    // --sarif / --junit
};

// Into the temporary file (or stdout) now; a FIFO or device is opened only when the report is complete (it would
// block on its reader), so for those the text waits in the buffer.
void SweepRun::emitJson(const std::string& text) {
  if (jsonFile_->streamsNow()) jsonFile_->stream(text);
  else jsonFile_->buffer() += text;
}

void SweepRun::beginJson() {
  if (!jsonFile_) return;
  json header = sweepHeaderJson(a_, terrain_.scene(), howKey_, how_);
  if (!camerasFile_.is_null()) header["cameras_file"] = camerasFile_;
  if (plan_.sharded) header["shard"] = {{"index", plan_.shardK + 1}, {"count", plan_.shardN}};
  header["denormals_flushed"] = vf::denormalRule(terrain_.scene(), opt_).flush; // the rule every camera ran with
  emitJson(sweepJsonBegin(header));
}

// Writes the pending cameras that are next in order (all of them at the end: cameras skipped by Ctrl-C leave gaps).
// Never throws (called on worker threads): an I/O error is kept in jsonError_.
void SweepRun::flushPending(bool all) {
  try {
    for (auto it = pending_.begin(); it != pending_.end() && (all || it->first == nextLocal_); it = pending_.erase(it)) {
      nextLocal_ = it->first + 1;
      if (jsonError_.empty()) emitJson(sweepJsonCamera(it->second, !anyCamera_));
      anyCamera_ = true;
    }
  } catch (const std::exception& e) {
    jsonError_ = e.what();
  }
}

// A camera's first hole for the picture; a camera-dependent layout's patch index is into that camera's layout.
static SvgHole svgHoleOf(const vf::Terrain& terrain, const vf::Camera& cam, const vf::Hole& h, std::string title) {
  SvgHole out{h.patch.index, std::move(title)};
  if (!terrain.cameraDependent()) return out;
  const vf::Terrain view = vf::layoutFor(terrain, cam);
  if (h.patch.index < 0 || h.patch.index >= view.patchCount()) return out;
  out.hasCorners = true;
  for (int k = 0; k < 4; ++k) out.corners[k] = view.patches()[size_t(h.patch.index)].corners[k];
  return out;
}

void SweepRun::noteWorst(size_t g, const vf::CameraResult& c) {
  const bool all = a_.offscreen;
  const int rank = (all ? c.stats.cracks : c.stats.cracksOnScreen()) > 0 ? 4
                   : c.stats.holes > 0                                     ? 3
                   : c.stats.undecided > 0                                 ? 2
                   : (all ? c.stats.tJunctions : c.stats.tJunctionsOnScreen()) > 0 ? 1
                                                                            : 0;
  const double gap = rank == 4 ? (all ? c.worst.gapWorld : c.worst.onScreenGapWorld) : 0;
  const bool better =
      rank > worst_.rank || (rank == worst_.rank && (gap > worst_.gap || (gap == worst_.gap && g < worst_.camera)));
  if (better) worst_ = {g, rank, gap};
}

void SweepRun::onCamera(const vf::CameraResult& c) {
  const size_t g = plan_.global(c.cameraIndex);
  endChecked_ = std::max(endChecked_, g + 1);
  if (!c.error.empty() && g < firstInvalid_) firstInvalid_ = g, firstInvalidError_ = c.error;
  if (ci_) ci_->addCamera(g, c);
  if (c.done && !a_.gltf.empty()) noteWorst(g, c);
  if (c.done) {
    if (c.stats.holes > 0) ++holeCameras_;
    const bool all = a_.offscreen; // the findings that count: on screen, or all with --offscreen
    if ((all ? c.stats.cracks : c.stats.cracksOnScreen()) > 0) ++crackCameras_;
    else if ((all ? c.stats.tJunctions : c.stats.tJunctionsOnScreen()) > 0) ++tjCameras_;
    if (!a_.svg.empty()) {
      dots_.push_back(svgCamera(g, cams_.at(g), c, all));
      if (c.hasHole) holes_.push_back(svgHoleOf(terrain_, cams_.at(g), c.firstHole, "camera " + std::to_string(g) + ": " + holeCause(c.firstHole).detail));
    }
  }
  if (!jsonFile_) return;
  pending_.emplace(c.cameraIndex, sweepCameraJson(g, cams_.at(g), c));
  flushPending(false);
}

// Runs the cameras with progress on stderr: a bar on a terminal, a plain line every few seconds otherwise, nothing
// with --quiet (talk false).
vf::SweepResult SweepRun::run(const std::atomic<bool>* cancel, bool talk, const std::string& label) {
  Progress progress("cameras");
  vf::SweepOptions so;
  so.threads = a_.threads;
  so.cancel = cancel;
  so.keepCameras = false; // per camera: the tallies and the streamed JSON entry, nothing else
  so.resultCache = !a_.noResultCache;
  if (talk) so.progress = [&progress](size_t done, size_t total) { progress.report(done, total); };
  so.onReport = [this](size_t local, const vf::Report& r) {
    tally_.add(plan_.global(local), r);
    gpuDiffs_.add(plan_.global(local), r);
    if (ci_) ci_->addReport(plan_.global(local), r);
  };
  so.onCamera = [this](const vf::CameraResult& c) { onCamera(c); };
  if (talk)
    std::fprintf(stderr, "fftess sweep %s: %s, %zu cameras (%s)%s\n", a_.scene.c_str(), label.c_str(), requested_,
                 how_.c_str(), plan_.sharded ? (", shard " + a_.shard).c_str() : "");
  vf::SweepResult res;
  if (!cancel->load())
    res = vf::sweep(terrain_, requested_, [&](size_t local) { return cams_.at(plan_.global(local)); }, opt_, so);
  res.cancelled = res.cancelled || (cancel->load() && res.camerasDone + res.camerasInvalid < requested_);
  if (a_.noResultCache && !res.resultCache) // the reason the user gave
    res.resultCacheOff = "--no-result-cache", res.resultCacheOffKey = "option";
  progress.finish();
  elapsed_ = progress.elapsed();
  return res;
}

// The cause table: per cause the findings, the cameras where it appeared and the first one, with an example.
std::string SweepRun::causesText() const {
  std::string text = "  causes (findings of each cause, cameras where it appeared, the first camera where it appeared):\n";
  char buf[256];
  const std::vector<std::string> order = tally_.order();
  for (size_t i = 0; i < order.size() && i < static_cast<size_t>(a_.show); ++i) {
    const std::string& k = order[i];
    const CauseInfo& c = tally_.causes.at(k);
    const vf::Camera cam = cams_.at(c.first);
    std::snprintf(buf, sizeof buf, "    %-75s %7lld findings on %5zu cameras, first #%zu eye (%.1f, %.1f, %.1f)\n",
                  k.c_str(), static_cast<long long>(c.findings), c.cameras, c.first, static_cast<double>(cam.eye.x),
                  static_cast<double>(cam.eye.y), static_cast<double>(cam.eye.z));
    text += buf;
    text += "      e.g. " + c.detail + "\n";
    text += "      fix: " + c.fix + "\n";
  }
  if (order.size() > static_cast<size_t>(a_.show)) // --show N: the first N causes
    text += "    ... " + std::to_string(order.size() - static_cast<size_t>(a_.show)) +
            " more causes (--show N, or --json FILE)\n";
  return text;
}

std::string SweepRun::summaryText(const vf::SweepResult& res, const std::string& label, vf::Verdict verdict) const {
  const vf::Scene& scene = terrain_.scene();
  std::string text;
  char buf[256];
  const std::string rule = neighbourRuleWords(scene);
  text += "\n== " + label + ": " + rule + " ==\n";
  for (const std::string& s : overridesOf(a_)) text += "  --set " + s + "\n";
  std::snprintf(buf, sizeof buf, "  cameras        %zu of %zu%s (%s%s, %.1f s, %s threads)\n", res.camerasDone,
                requested_, res.cancelled ? " (interrupted)" : "", how_.c_str(),
                plan_.sharded ? (", shard " + a_.shard).c_str() : "", elapsed_,
                a_.threads > 0 ? std::to_string(a_.threads).c_str() : "all");
  text += buf;
  text += "  adjacency      " + (shaderReadsClamp(scene) ? std::string(vf::toString(scene.lod.screenSphere.clamp)) + " clamp"
                                                            : std::string("the shader's own neighbour rule")) +
          ", " + toString(scene.partitioning) + " partitioning\n";
  text += shortcutsText(res.visibleFirst, resultCacheJson(res), res.total,
                        a_.offscreen ? "--offscreen" : a_.noVisibleFirst ? "--no-visible-first"
                        : a_.gpuFloat != "off" ? "--gpu-float " + a_.gpuFloat + ": its findings count off screen too" : "");
  text += statsText(res.total, a_.offscreen);
  text += gpuDiffs_.text(scene, opt_, res.total);
  std::snprintf(buf, sizeof buf, "  cameras with cracks %zu, with T-junctions only %zu, with holes %zu\n", crackCameras_,
                tjCameras_, holeCameras_);
  text += buf;
  if (res.camerasUndecided > 0) {
    std::snprintf(buf, sizeof buf, "  cameras with undecided patches (not clean): %zu\n", res.camerasUndecided);
    text += buf;
  }
  if (res.camerasGpuFloat > 0) {
    std::snprintf(buf, sizeof buf, "  cameras with edges that may crack on some GPUs (--gpu-float): %zu\n",
                  res.camerasGpuFloat);
    text += buf;
  }
  if (res.camerasNothingChecked > 0) {
    std::snprintf(buf, sizeof buf, "  cameras that classified no shared edge (all culled or out of view): %zu\n",
                  res.camerasNothingChecked);
    text += buf;
  }
  if (res.camerasInvalid > 0) {
    std::snprintf(buf, sizeof buf, "  cameras NOT CHECKED (invalid): %zu, first #%zu: ", res.camerasInvalid, firstInvalid_);
    text += buf + printable(firstInvalidError_) + "\n";
  }
  if (!tally_.causes.empty()) text += causesText();
  if (!a_.gltf.empty() && worst_.rank >= 0)
    text += "  3D view        camera " + std::to_string(worst_.camera) + " (" + worstWhy() + "): " + quotePath(a_.gltf) +
            "\n";
  return text + "verdict: " + verdictWords(verdict, res, crackCameras_, holeCameras_, requested_, a_.offscreen) + "\n";
}

// The end of the JSON report (the last cameras, the summary) and the picture, into their files' buffers.
void SweepRun::finishReports(const vf::SweepResult& res) {
  const std::vector<std::string> order = tally_.order();
  if (jsonFile_) {
    flushPending(true);
    if (!jsonError_.empty()) throw std::runtime_error(jsonError_);
    std::vector<CauseRow> rows;
    for (const std::string& k : order) {
      const CauseInfo& c = tally_.causes.at(k);
      rows.push_back({k, c.findings, c.cameras, c.first, c.detail, c.fix, c.id});
    }
    vf::WorkStats terrainWork = terrain_.stats();
    terrainWork.terrainBuilds = vf::terrainBuildCount(); // every build in this process
    jsonFile_->buffer() += sweepJsonEnd(sweepSummaryJson(requested_, res, rows, terrainWork, a_.offscreen), anyCamera_);
  }
  if (svgFile_) {
    std::vector<size_t> firsts;
    for (const std::string& k : order) firsts.push_back(tally_.causes.at(k).first);
    std::sort(dots_.begin(), dots_.end(), [](const SvgCamera& x, const SvgCamera& y) { return x.index < y.index; });
    svgFile_->buffer() = sweepSvg(terrain_, svgCameras(cams_, res.cancelled ? endChecked_ : cams_.size()), dots_, holes_,
                                  firsts, a_.random > 0, "fftess sweep " + a_.scene, a_.offscreen);
  }
}

std::string SweepRun::worstWhy() const {
  static const char* const kWhy[] = {"no findings, the first camera checked", "the first with T-junctions",
                                     "the first with undecided patches", "the first with a hole"};
  if (worst_.rank < 0) return "no camera checked";
  return worst_.rank == 4 ? "the worst: crack gap " + fmtWorld(worst_.gap) + " world units" : kWhy[worst_.rank];
}

bool SweepRun::worstGltf(ReportFiles& reports, const vf::SweepResult& res) const {
  if (!reports.gltf()) return true;
  if (worst_.rank < 0) return false;
  const vf::Camera cam = cams_.at(worst_.camera);
  vf::CheckOptions opt = opt_;
  opt.maxFindings = vf::CheckOptions{}.maxFindings; // what `check` keeps
  opt.visibleFirst = false;                         // and how it checks: the full check
  const vf::Report r = vf::checkScene(terrain_, cam, opt);
  if (!r.error.empty()) throw std::runtime_error("--gltf: camera " + std::to_string(worst_.camera) + ": " + r.error);
  std::string which = "camera " + std::to_string(worst_.camera) + " of the sweep (" + how_ + "), " + worstWhy();
  if (res.cancelled) which += ", of the cameras checked before the interrupt";
  reports.setGltf(checkGltf(terrain_, cam, opt, r,
                            {"fftess sweep " + a_.scene, vf::toString(vf::verdictOf(r.stats, a_.offscreen)), which},
                            gltfTextPath(a_.gltf)));
  return true;
}

} // namespace

int runSweep(const SweepArgs& a) {
  const SweepPlan plan = sweepPlan(a);
  // Output paths are checked before the work; the JSON streams into reports.json() as the cameras finish.
  ReportFiles reports(a);
  const vf::Terrain terrain = load(a); // the one terrain build of this command
  vf::CheckOptions opt = checkOptions(a, terrain);
  opt.maxFindings = static_cast<size_t>(-1); // every finding reaches onReport, so the cause counts are complete
  // Visible first unless --offscreen (every finding counts: the full check) or --no-visible-first; `check` keeps the
  // full check (it lists the off-screen findings apart).
  opt.visibleFirst = !a.offscreen && !a.noVisibleFirst;
  // Ctrl-C from here on (the sweep, the reports) stops the work; the summary and reports of what was done are still
  // written. A second Ctrl-C kills the process (temporary files removed). Once the work is done, a first Ctrl-C while a
  // report waits for a FIFO's reader ends that wait (AtomicFile: Interrupted, exit 130).
  InterruptGuard interrupts;
  // --cameras FILE: read whole (each camera validated; a bad file is a usage error before any work).
  std::unique_ptr<CameraFile> file;
  if (!a.cameras.empty()) file = std::make_unique<CameraFile>(readCameraFile(a.cameras, terrain.scene().camera));
  SweepRun sweep(a, plan, terrain, opt, reports.json(), reports.svg(), file.get());
  file.reset(); // its cameras were moved into the sweep's CameraSet
  std::unique_ptr<SweepCi> ci; // --sarif / --junit
  if (reports.ci()) sweep.setCi((ci = std::make_unique<SweepCi>(SceneCiContext(a, terrain.scene()))).get());
  const bool talk = !a.quiet && a.json != "-";
  const std::string& sceneName = terrain.scene().name;
  const std::string label = a.label.empty() ? (sceneName.empty() ? a.scene : sceneName) : a.label;
  sweep.beginJson();
  const vf::SweepResult res = sweep.run(InterruptGuard::flag(), talk, label);
  const vf::Verdict verdict = vf::verdictOf(res, a.offscreen);
  const int status = sweepStatus(res, verdict, a.failOnTJunctions);
  const std::string text = talk ? sweep.summaryText(res, label, verdict) : "";
  if (ci) setCiReports(reports, ci->finish(res, verdict, sweep.requested(), status, [&](size_t g) { return sweep.eyeWords(g); }));
  sweep.finishReports(res);
  if (!sweep.worstGltf(reports, res)) { // no camera checked: nothing to show in 3D
    reports.dropGltf();
    std::fprintf(stderr, "fftess sweep: --gltf %s not written: no camera was checked\n", quotePath(a.gltf).c_str());
  }
  reports.commit(); // all or nothing
  writeStdout(text);
  flushStdout();
  return status;
}

} // namespace fftess::cli
