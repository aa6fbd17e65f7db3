// fftess sweep SCENE: check a scene from many cameras (the scene's path, an orbit, a flyover, random), with
// progress and Ctrl-C, tally the findings by cause, print the summary, write the JSON / SVG reports atomically.
#include "check.h"
#include "common.h"
#include "findings.h"
#include "gpu_lod.h"
#include "progress.h"
#include "report_json.h"
#include "report_svg.h"

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
      addKey(std::string(vf::toString(f.classification)) + off + ": " + cause.key, cause.detail, camera, k, here);
    }
    for (size_t k = 0; k < r.holes.size(); ++k) {
      const Cause cause = holeCause(r.holes[k]);
      // Holes after the findings of the same camera (index offset keeps the order stable).
      addKey("hole: " + cause.key, cause.detail, camera, r.findings.size() + k, here);
    }
    for (size_t k = 0; k < r.undecided.size(); ++k) { // the key starts with "undecided: "
      const Cause cause = holeCause(r.undecided[k]);
      addKey(cause.key, cause.detail, camera, r.findings.size() + r.holes.size() + k, here);
    }
  }

  void addKey(const std::string& key, const std::string& detail, size_t camera, size_t k, std::set<std::string>& here) {
    {
      auto [it, added] = causes.try_emplace(key);
      CauseInfo& c = it->second;
      ++c.findings;
      if (here.insert(key).second) ++c.cameras;
      if (added || camera < c.first || (camera == c.first && k < c.firstFinding)) {
        c.first = camera;
        c.firstFinding = k;
        c.detail = detail;
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
CLI::App* addSweep(CLI::App& app, SweepArgs& a) {
  CLI::App* sub = app.add_subcommand("sweep", "Check a scene from many cameras (a path, an orbit, a flyover, random)");
  sub->footer("Examples:\n"
              "  fftess sweep docs/examples/terrain.toml\n"
              "  fftess sweep docs/examples/terrain.toml --set lod.adjacency_clamp=none --random 500 --seed 3 "
              "--json sweep.json --svg sweep.svg\n"
              "Cameras: the scene's [[camera_path]] (or its [camera]) unless --orbit, --flyover or --random is given.\n"
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
  sub->add_option("--seed", a.seed, "Seed for --random")->capture_default_str();
  sub->add_option("-j,--threads", a.threads, "Worker threads (default 0: all cores)")->capture_default_str();
  sub->add_option("--label", a.label, "Name for this run in the summary (default: the scene's name)");
  sub->add_option("--shard", a.shard,
                  "K/N: check only the cameras i with i % N == K - 1 (1 <= K <= N; indices stay global, so the "
                  "shards' --json reports merge with 'fftess merge' into exactly the report of one run)");
  return sub;
}

// Cameras when the scene has no [[camera_path]] and no generator option is given.
constexpr int kDefaultFlyover = 200;

// --seed: all decimal digits, 0 .. 2^64-1 (no sign, no wrap-around, no saturation).
static uint64_t parseSeed(const std::string& text) {
  uint64_t v = 0;
  bool ok = !text.empty() && text.size() <= 20;
  for (char c : text) {
    if (!ok) break;
    const unsigned d = static_cast<unsigned>(c - '0');
    ok = c >= '0' && c <= '9' && v <= (UINT64_MAX - d) / 10;
    v = v * 10 + d;
  }
  if (!ok) throw UsageError("--seed " + quoteToken(text) + ": expected a whole number from 0 to 18446744073709551615");
  return v;
}

// The verdict line without the off-screen findings.
static std::string verdictHeadline(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras,
                                   size_t holeCameras, size_t cameras, bool countOffScreen) {
  const std::string holesText = "HOLES seen from " + std::to_string(holeCameras) + " of " +
                                std::to_string(res.camerasDone) + " cameras (" + std::to_string(res.total.holes) +
                                " patches not drawn while in view)";
  const std::string undecidedText = res.total.undecided > 0 ? "; " + std::to_string(res.total.undecided) +
                                                                   " patches undecided on " +
                                                                   std::to_string(res.camerasUndecided) + " cameras"
                                                             : "";
  switch (verdict) {
  case vf::Verdict::Cracks:
    return "CRACKS seen from " + std::to_string(crackCameras) + " of " + std::to_string(res.camerasDone) +
           " cameras (worst gap" + (countOffScreen ? " " : " on screen ") + fmtWorld(countedGapWorld(res.total, countOffScreen)) +
           " world units, " + fmtWorld(countedGapPixels(res.total, countOffScreen)) + " px)" +
           (res.total.holes > 0 ? "; " + holesText : "") + undecidedText;
  case vf::Verdict::Holes: return holesText + undecidedText;
  case vf::Verdict::NothingChecked:
    return "NOTHING CHECKED: no camera classified a shared edge (" + std::to_string(res.camerasDone) +
           " cameras checked, " + std::to_string(res.camerasInvalid) + " invalid); not a clean verdict";
  case vf::Verdict::Unchecked:
    return "NOT CLEAN: " + std::to_string(res.camerasInvalid) + " of " + std::to_string(cameras) +
           " cameras could not be checked (the other " + std::to_string(res.camerasDone) + " found no crack or hole)";
  case vf::Verdict::Undecided:
    return "NOT WATERTIGHT: UNDECIDED from " + std::to_string(res.camerasUndecided) + " of " +
           std::to_string(res.camerasDone) + " cameras (" + std::to_string(res.total.undecided) +
           " patches not drawn, neither proven visible nor invisible)";
  case vf::Verdict::TJunctionsOnly: return res.cancelled ? "no cracks so far (interrupted)" : "no cracks (T-junctions only)";
  case vf::Verdict::Watertight:
    return res.cancelled ? "no cracks so far (interrupted)" : "WATERTIGHT from all " + std::to_string(res.camerasDone) + " cameras";
  }
  return "?";
}

// The verdict line's words (sweep and merge).
std::string verdictWords(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras, size_t holeCameras,
                         size_t cameras, bool countOffScreen) {
  const std::string off = offScreenWords(res.total, countOffScreen);
  return verdictHeadline(verdict, res, crackCameras, holeCameras, cameras, countOffScreen) +
         (off.empty() ? "" : " (" + off + ")");
}

// The cameras of a sweep by index (vf::CameraSet): the generator option given, else the scene's camera path, else a
// flyover of kDefaultFlyover.
static vf::CameraSet cameraSet(const SweepArgs& a, const vf::Terrain& terrain, uint64_t seed) {
  if (a.orbit > 0) return vf::CameraSet::orbit(terrain, size_t(a.orbit));
  if (a.flyover > 0) return vf::CameraSet::flyover(terrain, size_t(a.flyover));
  if (a.random > 0) return vf::CameraSet::random(terrain, size_t(a.random), seed);
  if (!terrain.scene().cameraPath.empty()) return vf::CameraSet::path(terrain);
  return vf::CameraSet::flyover(terrain, kDefaultFlyover);
}

static std::string cameraWords(const SweepArgs& a, const vf::Terrain& terrain, uint64_t seed) {
  if (a.orbit > 0) return "orbit of " + std::to_string(a.orbit);
  if (a.flyover > 0) return "flyover of " + std::to_string(a.flyover);
  if (a.random > 0) return std::to_string(a.random) + " random, seed " + std::to_string(seed);
  if (!terrain.scene().cameraPath.empty()) return "the scene's camera path";
  return "flyover of " + std::to_string(kDefaultFlyover) + ", the scene has no camera path";
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

int runSweep(const SweepArgs& a) {
  const int generators = a.orbitGiven + a.flyoverGiven + a.randomGiven;
  if (generators > 1) throw UsageError("sweep: give only one of --orbit, --flyover, --random");
  if (a.orbitGiven && a.orbit < 1) throw UsageError("--orbit " + std::to_string(a.orbit) + ": must be >= 1");
  if (a.flyoverGiven && a.flyover < 1) throw UsageError("--flyover " + std::to_string(a.flyover) + ": must be >= 1");
  if (a.randomGiven && a.random < 1) throw UsageError("--random " + std::to_string(a.random) + ": must be >= 1");
  if (a.threads < 0) throw UsageError("--threads " + std::to_string(a.threads) + ": must be >= 0");
  const uint64_t seed = parseSeed(a.seed);
  size_t shardK = 0, shardN = 1;
  parseShard(a.shard, shardK, shardN);
  const bool sharded = !a.shard.empty();
  // Output paths are checked before the work (as ReportFiles does; the JSON streams, so it is handled here).
  refuseSameFiles(reportArgs(a), sceneInputs(a, nullptr));
  std::unique_ptr<AtomicFile> jsonFile, svgFile;
  if (!a.json.empty()) jsonFile = std::make_unique<AtomicFile>(a.json);
  if (!a.svg.empty()) svgFile = std::make_unique<AtomicFile>(a.svg);
  const vf::Terrain terrain = load(a); // the one terrain build of this command
  const vf::Scene& scene = terrain.scene();
  vf::CheckOptions opt = checkOptions(a, terrain);
  opt.maxFindings = static_cast<size_t>(-1); // every finding reaches onReport, so the cause counts are complete
  // Ctrl-C from here on (the sweep, the reports) stops the work; the summary and reports of what was done are still
  // written. A second Ctrl-C kills the process (temporary files removed). Once the work is done, a first Ctrl-C while a
  // report waits for a FIFO's reader ends that wait (AtomicFile: Interrupted, exit 130).
  InterruptGuard interrupts;
  const std::atomic<bool>* cancel = InterruptGuard::flag();
  // Every camera of the run (global indices, also when sharded), computed from its index when needed: memory does not
  // depend on the camera count, and there is no setup to wait for.
  const vf::CameraSet cams = cameraSet(a, terrain, seed);
  const std::string how = cameraWords(a, terrain, seed);
  const size_t requestedAll = cams.size();
  // This run's share: global index g = shardK + local * shardN.
  auto shareOf = [&](size_t total) { return total > shardK ? (total - shardK + shardN - 1) / shardN : 0; };
  const size_t requested = shareOf(requestedAll);
  auto global = [&](size_t local) { return shardK + local * shardN; };
  const bool jsonToStdout = a.json == "-";
  const bool talk = !a.quiet && !jsonToStdout;
  const std::string label = a.label.empty() ? (scene.name.empty() ? a.scene : scene.name) : a.label;

  // The JSON report streams: header now, each camera as it finishes (in camera order, through a small reorder
  // buffer), the summary at the end. The SVG keeps only what it draws.
  std::string jsonError; // an I/O error while streaming (raised again when the report is finished)
  // Into the temporary file (or stdout) now; a FIFO or device is opened only when the report is complete (it would
  // block on its reader), so for those the text waits in the buffer.
  auto emitJson = [&](const std::string& text) {
    if (jsonFile->streamsNow()) jsonFile->stream(text);
    else jsonFile->buffer() += text;
  };
  if (jsonFile) {
    json header = sweepHeaderJson(a, scene, how);
    if (sharded) header["shard"] = {{"index", shardK + 1}, {"count", shardN}};
    header["denormals_flushed"] = vf::denormalRule(scene, opt).flush; // the rule every camera ran with
    emitJson(sweepJsonBegin(header));
  }
  std::map<size_t, json> pending; // local index -> camera text, waiting for the cameras before it
  size_t nextLocal = 0;
  bool anyCamera = false;
  std::vector<SvgCamera> dots;
  std::vector<SvgHole> holes;
  size_t crackCameras = 0, tjCameras = 0, holeCameras = 0;
  size_t firstInvalid = SIZE_MAX;
  size_t endChecked = 0; // 1 + the highest global index checked
  std::string firstInvalidError;

  // Progress on stderr: a bar on a terminal, a plain line every few seconds otherwise, nothing with --quiet.
  Progress progress("cameras");
  vf::SweepOptions so;
  so.threads = a.threads;
  so.cancel = cancel;
  so.keepCameras = false; // per camera: the tallies below and the streamed JSON entry, nothing else
  if (talk) so.progress = [&progress](size_t done, size_t total) { progress.report(done, total); };
  // Writes the pending cameras that are next in order (all of them at the end: cameras skipped by Ctrl-C leave gaps).
  // Never throws (called on worker threads): an I/O error is kept in jsonError.
  auto flushPending = [&](bool all) {
    try {
      for (auto it = pending.begin(); it != pending.end() && (all || it->first == nextLocal); it = pending.erase(it)) {
        nextLocal = it->first + 1;
        if (jsonError.empty()) emitJson(sweepJsonCamera(it->second, !anyCamera));
        anyCamera = true;
      }
    } catch (const std::exception& e) {
      jsonError = e.what();
    }
  };
  CauseTally tally;
  tally.countOffScreen = a.offscreen;
  FactorDiffTally gpuDiffs; // lod.evaluate = "gpu" / lod.shader: GPU vs C++ factors (cli/gpu_lod.h)
  so.onReport = [&](size_t local, const vf::Report& r) {
    tally.add(global(local), r);
    gpuDiffs.add(global(local), r);
  };
  so.onCamera = [&](const vf::CameraResult& c) {
    const size_t g = global(c.cameraIndex);
    endChecked = std::max(endChecked, g + 1);
    if (!c.error.empty() && g < firstInvalid) firstInvalid = g, firstInvalidError = c.error;
    if (c.done) {
      if (c.stats.holes > 0) ++holeCameras;
      const bool all = a.offscreen; // the findings that count: on screen, or all with --offscreen
      if ((all ? c.stats.cracks : c.stats.cracksOnScreen()) > 0) ++crackCameras;
      else if ((all ? c.stats.tJunctions : c.stats.tJunctionsOnScreen()) > 0) ++tjCameras;
      if (!a.svg.empty()) {
        dots.push_back(svgCamera(g, cams.at(g), c, all));
        if (c.hasHole) holes.push_back({c.firstHole.patch.index, "camera " + std::to_string(g) + ": " + holeCause(c.firstHole).detail});
      }
    }
    if (!jsonFile) return;
    pending.emplace(c.cameraIndex, sweepCameraJson(g, cams.at(g), c));
    flushPending(false);
  };
  if (talk)
    std::fprintf(stderr, "fftess sweep %s: %s, %zu cameras (%s)%s\n", a.scene.c_str(), label.c_str(), requested,
                 how.c_str(), sharded ? (", shard " + a.shard).c_str() : "");
  vf::SweepResult res;
  if (!cancel->load())
    res = vf::sweep(terrain, requested, [&](size_t local) { return cams.at(global(local)); }, opt, so);
  res.cancelled = res.cancelled || (cancel->load() && res.camerasDone + res.camerasInvalid < requested);
  progress.finish();
  const double elapsed = progress.elapsed();
  const std::vector<std::string> order = tally.order();
  const std::map<std::string, CauseInfo>& causes = tally.causes;
  const vf::Verdict verdict = vf::verdictOf(res, a.offscreen);
  const bool gaps = verdict == vf::Verdict::Cracks || verdict == vf::Verdict::Holes;
  const int status = res.cancelled && !gaps ? 130 : verdictStatus(a, verdict);

  std::string text;
  if (talk) {
    char buf[256];
    text += "\n== " + label + ": lod.adjacency_clamp = " + vf::toString(scene.lod.screenSphere.clamp) +
            (scene.lod.screenSphere.clamp == vf::AdjacencyClamp::Pow2 ? " (the power-of-two workaround on)" : "") + " ==\n";
    for (const std::string& s : overridesOf(a)) text += "  --set " + s + "\n";
    std::snprintf(buf, sizeof buf, "  cameras        %zu of %zu%s (%s%s, %.1f s, %s threads)\n", res.camerasDone,
                  requested, res.cancelled ? " (interrupted)" : "", how.c_str(),
                  sharded ? (", shard " + a.shard).c_str() : "", elapsed,
                  a.threads > 0 ? std::to_string(a.threads).c_str() : "all");
    text += buf;
    text += "  adjacency      " + std::string(vf::toString(scene.lod.screenSphere.clamp)) + " clamp, " +
            toString(scene.partitioning) + " partitioning\n";
    text += statsText(res.total, a.offscreen);
    text += gpuDiffs.text(scene, opt, res.total);
    std::snprintf(buf, sizeof buf, "  cameras with cracks %zu, with T-junctions only %zu, with holes %zu\n", crackCameras,
                  tjCameras, holeCameras);
    text += buf;
    if (res.camerasUndecided > 0) {
      std::snprintf(buf, sizeof buf, "  cameras with undecided patches (not clean): %zu\n", res.camerasUndecided);
      text += buf;
    }
    if (res.camerasNothingChecked > 0) {
      std::snprintf(buf, sizeof buf, "  cameras that classified no shared edge (all culled or out of view): %zu\n",
                    res.camerasNothingChecked);
      text += buf;
    }
    if (res.camerasInvalid > 0) {
      std::snprintf(buf, sizeof buf, "  cameras NOT CHECKED (invalid): %zu, first #%zu: ", res.camerasInvalid, firstInvalid);
      text += buf + printable(firstInvalidError) + "\n";
    }
    if (!order.empty()) {
      text += "  causes (findings of each cause, cameras where it appeared, the first camera where it appeared):\n";
      for (const std::string& k : order) {
        const CauseInfo& c = causes.at(k);
        const vf::Camera cam = cams.at(c.first);
        std::snprintf(buf, sizeof buf, "    %-75s %7lld findings on %5zu cameras, first #%zu eye (%.1f, %.1f, %.1f)\n",
                      k.c_str(), static_cast<long long>(c.findings), c.cameras, c.first, static_cast<double>(cam.eye.x),
                      static_cast<double>(cam.eye.y), static_cast<double>(cam.eye.z));
        text += buf;
        text += "      e.g. " + c.detail + "\n";
      }
    }
    text += "verdict: " + verdictWords(verdict, res, crackCameras, holeCameras, requested, a.offscreen) + "\n";
  }
  if (jsonFile) {
    flushPending(true);
    if (!jsonError.empty()) throw std::runtime_error(jsonError);
    std::vector<CauseRow> rows;
    for (const std::string& k : order) {
      const CauseInfo& c = causes.at(k);
      rows.push_back({k, c.findings, c.cameras, c.first, c.detail});
    }
    vf::WorkStats terrainWork = terrain.stats();
    terrainWork.terrainBuilds = vf::terrainBuildCount(); // every build in this process
    jsonFile->buffer() += sweepJsonEnd(sweepSummaryJson(requested, res, rows, terrainWork, a.offscreen), anyCamera);
  }
  if (svgFile) {
    std::vector<size_t> firsts;
    for (const std::string& k : order) firsts.push_back(causes.at(k).first);
    std::sort(dots.begin(), dots.end(), [](const SvgCamera& x, const SvgCamera& y) { return x.index < y.index; });
    svgFile->buffer() = sweepSvg(terrain, svgCameras(cams, res.cancelled ? endChecked : cams.size()), dots, holes,
                                 firsts, a.random > 0, "fftess sweep " + a.scene, a.offscreen);
  }
  AtomicFile* files[2];
  size_t nFiles = 0;
  if (jsonFile) files[nFiles++] = jsonFile.get();
  if (svgFile) files[nFiles++] = svgFile.get();
  commitAll(files, nFiles); // all or nothing
  writeStdout(text);
  flushStdout();
  return status;
}

} // namespace fftess::cli
