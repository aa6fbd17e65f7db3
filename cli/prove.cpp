// fftess prove SCENE: proves a scene watertight for every camera of a region (verify/prove.h, proveScene), or gives a
// counterexample camera that `fftess check` confirms, or says which regions stayed undecided. Text, JSON, exit status:
// 0 PROVED, 1 COUNTEREXAMPLE or UNDECIDED, 2 bad usage or scene, 3 internal error (docs/cli.md, "prove").
#include "causes.h"
#include "commands.h"
#include "common.h"
#include "options.h"
#include "base/threads.h"
#include "progress.h"
#include "report_json.h"
#include "scene_options.h"

#include "verify/prove.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace fftess::cli {

CLI::App* addProve(CLI::App& app, ProveArgs& a) {
  CLI::App* sub = app.add_subcommand(
      "prove", "Prove a scene watertight for every camera in a region (or find a counterexample camera)");
  sub->footer("Examples:\n"
              "  fftess prove docs/examples/rings_small.toml\n"
              "  fftess prove docs/examples/rings_small.toml --eye-box 0,20,-80,20,30,-60 --target-box 0,0,0,0,0,0\n"
              "  fftess prove docs/examples/rings_small.toml --set lod.adjacency_clamp=none\n"
              "A box is X0,Y0,Z0,X1,Y1,Z1 (a point when both corners are equal); without --eye-box / --target-box the "
              "default region: the scene camera's eye and target, each moved by up to 2^-12 of the terrain's larger side "
              "(stated in the output). fov, viewport, near and far are the "
              "scene camera's. What PROVED assumes: docs/verify.md, \"Proofs\".\n"
              "Exit status: 0 PROVED, 1 COUNTEREXAMPLE or UNDECIDED, 2 bad usage or scene, 3 internal error.");
  sub->add_option("scene", a.scene.scene, "Scene file (TOML, docs/verify.md)")->required();
  sub->add_option("--set", a.scene.overrides, "Override a scene key: KEY=VALUE (repeatable), validated like the file")
      ->type_name("KEY=VALUE");
  sub->add_option("--eye-box", a.eyeBox, "Eyes in the box X0,Y0,Z0,X1,Y1,Z1 (default: the scene eye +-2^-12 of the terrain's side)")
      ->type_name("X0,Y0,Z0,X1,Y1,Z1");
  sub->add_option("--target-box", a.targetBox, "Targets in the box X0,Y0,Z0,X1,Y1,Z1 (default: the scene target +-2^-12 of the terrain's side)")
      ->type_name("X0,Y0,Z0,X1,Y1,Z1");
  sub->add_option("--max-depth", a.maxDepth, "Splits of a region on the way from the root (each halves one coordinate)")
      ->capture_default_str();
  sub->add_option("--max-regions", a.maxRegions, "Regions evaluated in all before the proof stops (what is open is "
                                                  "undecided)")
      ->capture_default_str();
  addThreadsOption(sub, a.threads, "Worker threads");
  addShowOption(sub, a.show, "Lines of the counterexample's findings and of the undecided regions to print");
  sub->add_option("--json", a.scene.json, "Write the proof's report as JSON to FILE ('-': stdout, no text then)");
  sub->add_flag("-q,--quiet", a.scene.quiet, "Print nothing but errors; the exit status tells the verdict");
  return sub;
}

namespace {

// "X0,Y0,Z0,X1,Y1,Z1" -> the two corners; a UsageError naming the option and the position of the bad number.
void parseBox(const char* option, const std::string& text, glm::vec3& lo, glm::vec3& hi) {
  float v[6];
  size_t at = 0;
  for (int i = 0; i < 6; ++i) {
    const size_t comma = text.find(',', at);
    const std::string item = text.substr(at, comma == std::string::npos ? std::string::npos : comma - at);
    char* end = nullptr;
    const float f = item.empty() ? 0.0f : std::strtof(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(f))
      throw UsageError(std::string(option) + " " + quoteToken(text) + ": number " + std::to_string(i + 1) + " (" +
                       quoteToken(item) + ") is not a finite number (expected X0,Y0,Z0,X1,Y1,Z1)");
    v[i] = f;
    if (comma == std::string::npos) {
      if (i != 5)
        throw UsageError(std::string(option) + " " + quoteToken(text) + ": " + std::to_string(i + 1) +
                         " numbers, expected 6 (X0,Y0,Z0,X1,Y1,Z1)");
      at = std::string::npos;
      break;
    }
    at = comma + 1;
  }
  if (at != std::string::npos)
    throw UsageError(std::string(option) + " " + quoteToken(text) + ": more than 6 numbers (expected X0,Y0,Z0,X1,Y1,Z1)");
  static const char* const names[3] = {"X", "Y", "Z"};
  for (int k = 0; k < 3; ++k)
    if (v[k] > v[k + 3])
      throw UsageError(std::string(option) + " " + quoteToken(text) + ": number " + std::to_string(k + 4) + " (" +
                       names[k] + "1 = " + formatFloat(v[k + 3]) + ") is below number " + std::to_string(k + 1) +
                       " (" + names[k] + "0 = " + formatFloat(v[k]) + "); each corner's coordinate must be <= the "
                       "other's");
  lo = glm::vec3(v[0], v[1], v[2]);
  hi = glm::vec3(v[3], v[4], v[5]);
}

void checkProveArgs(const ProveArgs& a) {
  if (a.maxDepth < 0) throw UsageError("--max-depth " + std::to_string(a.maxDepth) + ": must be >= 0");
  if (a.maxRegions < 1) throw UsageError("--max-regions " + std::to_string(a.maxRegions) + ": must be >= 1");
  // --threads: checked while parsing (addThreadsOption); again here for the Python module, which sets it directly.
  if (a.threads < 0 || a.threads > kMaxThreads)
    throw UsageError("--threads " + std::to_string(a.threads) + ": must be 0 (all cores) to " + std::to_string(kMaxThreads));
  if (a.show < 0) throw UsageError("--show " + std::to_string(a.show) + ": must be >= 0");
}

// A float as %.9g: the value `check --eye/--target` reads back to the same float.
std::string exact(float f) {
  char b[32];
  std::snprintf(b, sizeof b, "%.9g", static_cast<double>(f));
  return b;
}
std::string point(const glm::vec3& v) { return "(" + exact(v.x) + ", " + exact(v.y) + ", " + exact(v.z) + ")"; }
std::string commaList(const glm::vec3& v) { return exact(v.x) + "," + exact(v.y) + "," + exact(v.z); }

std::string boxText(const glm::vec3& lo, const glm::vec3& hi) {
  return lo == hi ? point(lo) : point(lo) + ".." + point(hi);
}
std::string regionText(const vf::CameraRegion& r) {
  return "eye " + boxText(r.eyeLo, r.eyeHi) + " target " + boxText(r.targetLo, r.targetHi);
}

json boxJson(const glm::vec3& lo, const glm::vec3& hi) { return {{"lo", vec3Json(lo)}, {"hi", vec3Json(hi)}}; }
json regionJson(const vf::CameraRegion& r) {
  return {{"eye", boxJson(r.eyeLo, r.eyeHi)}, {"target", boxJson(r.targetLo, r.targetHi)}};
}

std::string statsLine(const vf::ProveStats& s, bool volumes) {
  char b[512];
  std::snprintf(b, sizeof b,
                "  stats          regions %lld (%lld proved, %lld undecided), depth %d, pairs by trace %lld / by value "
                "%lld / off screen %lld, patches off screen %lld, lod paths %lld, cameras checked %lld, %.2f s\n",
                static_cast<long long>(s.regions), static_cast<long long>(s.regionsProved),
                static_cast<long long>(s.regionsUndecided), s.maxDepthReached, static_cast<long long>(s.pairsByTrace),
                static_cast<long long>(s.pairsByValue), static_cast<long long>(s.pairsOffScreen),
                static_cast<long long>(s.patchesOffScreen), static_cast<long long>(s.lodPaths),
                static_cast<long long>(s.camerasChecked), s.seconds);
  std::string text = b;
  if (volumes && (s.regionsInvalid > 0 || s.regionsNothingOnScreen > 0 || s.volumeProved < 1)) {
    std::snprintf(b, sizeof b,
                  "  volume         %.6g %% proved, %.6g %% nothing on screen, %.6g %% invalid cameras (%lld regions), "
                  "%.6g %% undecided\n",
                  100 * s.volumeProved, 100 * s.volumeNothingOnScreen, 100 * s.volumeInvalid,
                  static_cast<long long>(s.regionsInvalid), 100 * s.volumeUndecided);
    text += b;
  }
  return text;
}

std::string invalidText(const ProveArgs& a, const vf::ProveReport& r) {
  std::string text = "INVALID_CAMERAS: " + std::to_string(r.stats.regionsInvalid) +
                     " regions may hold cameras check refuses; they are not proved (every other camera of the region "
                     "is: watertight, no patch lost on screen). ";
  const size_t listed = std::min(r.invalid.size(), static_cast<size_t>(a.show));
  text += listed < static_cast<size_t>(r.stats.regionsInvalid) ? "The first " + std::to_string(listed) + ":\n"
                                                                : "Each of them:\n";
  for (size_t i = 0; i < listed; ++i) {
    const vf::UndecidedRegion& u = r.invalid[i];
    text += "  " + regionText(u.region) + " (depth " + std::to_string(u.depth) + "): " + u.why + "\n";
  }
  return text;
}

// The counterexample: the camera (values check reads back exactly), the command that confirms it, its findings as
// check prints them (holes, then on-screen cracks and T-junctions).
std::string counterexampleText(const ProveArgs& a, const vf::ProveReport& r) {
  const vf::Camera& c = r.counterexample;
  std::string text = "COUNTEREXAMPLE: eye " + point(c.eye) + " target " + point(c.target) + "\n";
  std::string cmd = "fftess check " + a.scene.scene;
  for (const std::string& s : a.scene.overrides) cmd += " --set " + s;
  text += "  confirm with   " + cmd + " --eye " + commaList(c.eye) + " --target " + commaList(c.target) + "\n";
  const vf::Report& rep = r.counterexampleReport;
  int shown = 0;
  for (const vf::Hole& h : rep.holes)
    if (shown++ < a.show) text += holeLine(h) + "\n";
  for (const vf::Finding& f : rep.findings)
    if (f.classification != vf::Classification::Match && f.onScreen && shown++ < a.show)
      text += findingLine(f) + "\n";
  if (shown > a.show) text += "  ... " + std::to_string(shown - a.show) + " more (--show N, or --json FILE)\n";
  return text;
}

std::string undecidedText(const ProveArgs& a, const vf::ProveReport& r) {
  std::string text = "UNDECIDED: " + std::to_string(r.stats.regionsUndecided) +
                     " regions left open (never PROVED while any remain); ";
  const size_t listed = std::min(r.undecided.size(), static_cast<size_t>(a.show));
  text += listed < static_cast<size_t>(r.stats.regionsUndecided) ? "the first " + std::to_string(listed) + ":\n"
                                                                    : "each of them:\n";
  for (size_t i = 0; i < listed; ++i) {
    const vf::UndecidedRegion& u = r.undecided[i];
    text += "  " + regionText(u.region) + " (depth " + std::to_string(u.depth) + "): " + u.why + "\n";
  }
  return text;
}

std::string proveText(const ProveArgs& a, const vf::Scene& scene, const vf::ProveReport& r) {
  std::string text = "fftess prove " + a.scene.scene + (scene.name.empty() ? "" : " (" + scene.name + ")") + "\n";
  for (const std::string& s : a.scene.overrides) text += "  --set " + s + "\n";
  text += "  region         " + regionText(r.region) +
          (r.regionDefault ? " (the default region: the scene camera's eye and target, each +-2^-12 of the terrain's side)" : "") + "\n";
  text += "  lod            " + std::string(vf::toString(scene.lod.scheme)) + ", " +
          vf::toString(scene.lod.screenSphere.clamp) + " clamp, " + toString(scene.partitioning) +
          " partitioning; the scene camera's fov, viewport, near and far\n";
  text += statsLine(r.stats, r.verdict != vf::ProveVerdict::Counterexample);
  switch (r.verdict) {
  case vf::ProveVerdict::Proved:
    text += "PROVED: every camera of the region sees every shared edge match vertex for vertex and no patch culled "
            "or discarded while on screen (what that assumes: docs/verify.md, \"Proofs\")\n";
    break;
  case vf::ProveVerdict::Counterexample: text += counterexampleText(a, r); break;
  case vf::ProveVerdict::Undecided: text += undecidedText(a, r); break;
  case vf::ProveVerdict::InvalidCameras: text += invalidText(a, r); break;
  case vf::ProveVerdict::NothingOnScreen:
    text += "NOTHING_ON_SCREEN: no camera of the region sees a shared edge on screen (every patch is off screen for "
            "every camera): nothing was checked, not a clean verdict\n";
    break;
  }
  if (r.verdict == vf::ProveVerdict::Proved && r.stats.regionsNothingOnScreen > 0)
    text += "  of which       " + std::to_string(r.stats.regionsNothingOnScreen) +
            " regions see no shared edge on screen (nothing checked there; the volume line says how much)\n";
  return text;
}

json proveJson(const ProveArgs& a, const vf::Terrain& terrain, const vf::ProveReport& r) {
  json j;
  j["version"] = kReportVersion;
  j["kind"] = "prove";
  j["fftess_version"] = FFTESS_VERSION;
  j["scene"] = sceneJson(a.scene, terrain.scene());
  j["region"] = regionJson(r.region);
  j["region_default"] = r.regionDefault;
  j["verdict"] = vf::toString(r.verdict);
  const vf::ProveStats& s = r.stats;
  j["stats"] = {{"regions", s.regions},         {"regions_proved", s.regionsProved},
                {"regions_undecided", s.regionsUndecided}, {"max_depth_reached", s.maxDepthReached},
                {"pairs_by_trace", s.pairsByTrace}, {"pairs_by_value", s.pairsByValue},
                {"pairs_off_screen", s.pairsOffScreen}, {"patches_off_screen", s.patchesOffScreen},
                {"lod_paths", s.lodPaths},       {"cameras_checked", s.camerasChecked},
                {"regions_invalid", s.regionsInvalid}, {"regions_nothing_on_screen", s.regionsNothingOnScreen},
                {"volume_proved", s.volumeProved}, {"volume_undecided", s.volumeUndecided},
                {"volume_invalid", s.volumeInvalid}, {"volume_nothing_on_screen", s.volumeNothingOnScreen},
                {"seconds", s.seconds}};
  if (r.verdict == vf::ProveVerdict::Counterexample) {
    json c = cameraJson(r.counterexample);
    json fs = json::array();
    for (const vf::Finding& f : r.counterexampleReport.findings)
      if (f.classification != vf::Classification::Match) fs.push_back(findingJson(f));
    json hs = json::array();
    for (const vf::Hole& h : r.counterexampleReport.holes) hs.push_back(holeJson(h));
    c["stats"] = statsJson(r.counterexampleReport.stats);
    c["findings"] = fs;
    c["holes"] = hs;
    j["counterexample"] = c;
  } else {
    j["counterexample"] = nullptr;
  }
  json us = json::array();
  for (const vf::UndecidedRegion& u : r.undecided)
    us.push_back({{"region", regionJson(u.region)}, {"depth", u.depth}, {"why", u.why}});
  j["undecided"] = us;
  json inv = json::array();
  for (const vf::UndecidedRegion& u : r.invalid)
    inv.push_back({{"region", regionJson(u.region)}, {"depth", u.depth}, {"why", u.why}});
  j["invalid"] = inv;
  return j;
}

} // namespace

int runProve(const ProveArgs& a) {
  checkProveArgs(a);
  vf::ProveOptions opt;
  glm::vec3 eyeLo, eyeHi, targetLo, targetHi;
  if (!a.eyeBox.empty()) parseBox("--eye-box", a.eyeBox, eyeLo, eyeHi);
  if (!a.targetBox.empty()) parseBox("--target-box", a.targetBox, targetLo, targetHi);
  std::unique_ptr<AtomicFile> jsonFile; // checked before the work
  refuseSameFiles({{"--json", a.scene.json}}, sceneInputs(a.scene, nullptr));
  if (!a.scene.json.empty()) jsonFile = std::make_unique<AtomicFile>(a.scene.json);
  const vf::Terrain terrain = load(a.scene);
  if (!a.eyeBox.empty() || !a.targetBox.empty()) { // a box not given: the default region's
    const vf::CameraRegion d = vf::defaultRegion(terrain);
    opt.region = d;
    if (!a.eyeBox.empty()) opt.region.eyeLo = eyeLo, opt.region.eyeHi = eyeHi;
    if (!a.targetBox.empty()) opt.region.targetLo = targetLo, opt.region.targetHi = targetHi;
    opt.regionGiven = true;
  }
  opt.maxDepth = a.maxDepth;
  opt.maxRegions = a.maxRegions;
  opt.threads = a.threads;
  opt.maxUndecidedListed = static_cast<size_t>(a.show);
  InterruptGuard interrupts; // Ctrl-C stops the proof; what is open is reported undecided
  opt.cancel = InterruptGuard::flag();
  const vf::ProveReport r = vf::proveScene(terrain, opt);
  if (!r.error.empty()) throw UsageError(loaderMessage(a.scene.scene, a.scene.scene + ": " + r.error));
  const bool talk = !a.scene.quiet && a.scene.json != "-";
  if (jsonFile) {
    jsonFile->buffer() = proveJson(a, terrain, r).dump(2) + "\n";
    AtomicFile* files[1] = {jsonFile.get()};
    commitAll(files, 1);
  }
  if (talk) writeStdout(proveText(a, terrain.scene(), r));
  flushStdout();
  return r.verdict == vf::ProveVerdict::Proved ? kExitClean : kExitFindings;
}

} // namespace fftess::cli
