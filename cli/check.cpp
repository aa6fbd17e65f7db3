// fftess check SCENE: run verify/ on one camera, print a summary and one line per finding, write the JSON / SVG
// reports atomically, and turn the verdict into an exit status.
#include "camera_file.h"
#include "causes.h"
#include "ci_scene.h"
#include "commands.h"
#include "common.h"
#include "options.h"
#include "gpu_lod.h"
#include "report_gltf.h"
#include "report_json.h"
#include "report_svg.h"
#include "report_view.h"
#include "scene_options.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <stdexcept>

namespace fftess::cli {

namespace {

// The patch edges only one of the two checks flags (--mesh): both empty when they agree.
struct MeshDiff {
  std::vector<vf::PatchEdgeRef> meshOnly, edgeOnly;
  bool agree() const { return meshOnly.empty() && edgeOnly.empty(); }
};

MeshDiff meshDiff(const vf::Report& full, const vf::MeshReport& mesh) {
  const std::vector<vf::PatchEdgeRef> edge = vf::flaggedPatchEdges(full);
  MeshDiff d;
  std::set_difference(mesh.flagged.begin(), mesh.flagged.end(), edge.begin(), edge.end(), std::back_inserter(d.meshOnly));
  std::set_difference(edge.begin(), edge.end(), mesh.flagged.begin(), mesh.flagged.end(), std::back_inserter(d.edgeOnly));
  return d;
}

// A disagreement in words: each patch edge only the mesh check flags, and each finding of the edge check on a
// patch edge the mesh check does not flag (at most `show` lines of each).
std::string meshDiffText(const vf::Terrain& terrain, const vf::Report& full, const MeshDiff& d, int show) {
  const std::vector<vf::PatchGeometry> patches = terrain.patches();
  std::string out = "  the whole-mesh check and the edge check disagree (a verifier bug; both findings follow):\n";
  int n = 0;
  for (const vf::PatchEdgeRef& e : d.meshOnly)
    if (n++ < show)
      out += "  mesh only  " + patchText(patches[static_cast<size_t>(e.patch)].ref) + " " + edgeName(e.edge) +
             ": inner border edges of the whole mesh, no edge-check finding\n";
  n = 0;
  for (const vf::Finding& f : full.findings) {
    if (f.classification == vf::Classification::Match) continue;
    const vf::PatchEdgeRef a{f.a.patch.index, f.a.edge}, b{f.b.patch.index, f.b.edge};
    if (!std::binary_search(d.edgeOnly.begin(), d.edgeOnly.end(), a) &&
        !std::binary_search(d.edgeOnly.begin(), d.edgeOnly.end(), b))
      continue;
    if (n++ < show) out += "  edge only  " + findingLine(f) + " (the whole mesh has no border there)\n";
  }
  return out;
}

json meshDiffJson(const vf::Terrain& terrain, const MeshDiff& d) {
  const std::vector<vf::PatchGeometry> patches = terrain.patches();
  auto list = [&](const std::vector<vf::PatchEdgeRef>& v) {
    json a = json::array();
    for (const vf::PatchEdgeRef& e : v) {
      const vf::PatchRef& p = patches[static_cast<size_t>(e.patch)].ref;
      a.push_back({{"patch", {{"index", p.index}, {"ring", p.ring}, {"tile", p.tile}, {"patch", p.patch},
                              {"level", p.level}}},
                   {"edge", edgeName(e.edge)}});
    }
    return a;
  };
  return {{"agrees", d.agree()}, {"mesh_only", list(d.meshOnly)}, {"edge_check_only", list(d.edgeOnly)}};
}

} // namespace

CLI::App* addCheck(CLI::App& app, CheckArgs& a) {
  CLI::App* sub = app.add_subcommand("check", "Check every shared patch edge of a scene from one camera");
  sub->footer("Examples:\n"
              "  fftess check docs/examples/terrain.toml\n"
              "  fftess check docs/examples/terrain.toml --set lod.adjacency_clamp=integer --json report.json "
              "--svg report.svg\n"
              "Exit status: 0 watertight, 1 cracks or holes found, undecided visibility or nothing checked (or "
              "--mesh disagrees with the edge check), 2 bad usage or scene, 3 internal error.");
  addSceneOptions(sub, a);
  sub->add_option_function<int>(
      "--path-camera", [&a](const int& n) { a.pathCamera = n, a.pathCameraGiven = true; },
      "Use camera N of the scene's [[camera_path]] instead of [camera] (0 is the first)");
  sub->add_option_function<int>(
      "--camera-index", [&a](const int& n) { a.cameraIndex = n, a.cameraIndexGiven = true; },
      "With --cameras FILE: check camera N of the file (0 is the first); without it the file must hold one camera");
  addShowOption(sub, a.show, "Example edges printed under each cause, the widest gap first (all are in --json)");
  sub->add_flag("--mesh", a.mesh, "Also run the whole-mesh check (full tessellation) and compare the two verdicts");
  sub->add_option("--view", a.view,
                  "Write what the camera sees as SVG: drawn patches' outlines by size, holes, on-screen findings with "
                  "their pixel gaps, each cause's fix");
  return sub;
}

namespace {

// --show and --path-camera, checked before any work.
void checkCheckArgs(const CheckArgs& a) {
  if (a.show < 0) throw UsageError("--show " + std::to_string(a.show) + ": must be >= 0");
  if (a.pathCameraGiven && a.pathCamera < 0)
    throw UsageError("--path-camera " + std::to_string(a.pathCamera) + ": must be >= 0 (0 is the path's first camera)");
  if (a.cameraIndexGiven && a.cameras.empty())
    throw UsageError("--camera-index " + std::to_string(a.cameraIndex) + ": needs --cameras FILE");
  if (a.cameraIndexGiven && a.cameraIndex < 0)
    throw UsageError("--camera-index " + std::to_string(a.cameraIndex) + ": must be >= 0 (0 is the file's first camera)");
  if (a.pathCameraGiven && !a.cameras.empty())
    throw UsageError("--path-camera and --cameras: give only one camera source");
}

// --cameras FILE: its one camera, or camera --camera-index N. source: the report's "cameras_file".
vf::Camera fileCamera(const CheckArgs& a, const vf::Scene& scene, json& source) {
  const CameraFile f = readCameraFile(a.cameras, scene.camera);
  const size_t n = f.cameras.size();
  if (!a.cameraIndexGiven && n != 1)
    throw UsageError("--cameras " + quotePath(a.cameras) + ": holds " + std::to_string(n) +
                     " cameras; check takes one: pick it with --camera-index N (0 is the first), or run fftess sweep "
                     "--cameras");
  const size_t i = a.cameraIndexGiven ? static_cast<size_t>(a.cameraIndex) : 0;
  if (i >= n)
    throw UsageError("--camera-index " + std::to_string(a.cameraIndex) + ": " + quotePath(a.cameras) + " holds " +
                     std::to_string(n) + " cameras");
  source = {{"path", a.cameras}, {"hash", f.hashText()}, {"cameras", n}, {"index", i}, {"line", f.lines[i]}};
  return f.cameras[i];
}

// The scene's [camera], or with --path-camera N its camera path's camera N, or with --cameras FILE the file's.
vf::Camera checkCamera(const CheckArgs& a, const vf::Scene& scene, json& source) {
  if (!a.cameras.empty()) return fileCamera(a, scene, source);
  if (!a.pathCameraGiven) return scene.camera;
  if (static_cast<size_t>(a.pathCamera) >= scene.cameraPath.size())
    throw UsageError("--path-camera " + std::to_string(a.pathCamera) + ": the scene's camera path has " +
                     std::to_string(scene.cameraPath.size()) + " cameras");
  return scene.cameraPath[static_cast<size_t>(a.pathCamera)];
}

// What the report keeps (CheckOptions::maxFindings), the same as a check without --mesh.
vf::Report keptReport(const vf::Report& full, size_t keep) {
  vf::Report r = full;
  if (r.findings.size() > keep) {
    r.findings.resize(keep);
    r.truncated = true;
  }
  return r;
}

// The holes, undecided patches and findings grouped by cause, keyed as sweep's cause table keys them (off-screen
// findings apart, "crack (off screen): ...", unless --offscreen), in the order of the report: holes, undecided
// patches, findings on screen, GPU float findings, then those off screen. Each cause: a header with its count in the
// report, its fix, the explanation of its first example ("e.g."), then at most --show example edges, the widest gap
// first (then in layout order), each only where and how wide, and how many more there are.
struct CauseItem {
  double gap = 0; // the gap that orders the examples (a crack's counted gap; 0 for the rest)
  std::string where, detail;
};

struct CauseGroup {
  std::string key, fix;
  std::vector<CauseItem> items;
};

void addToGroup(std::vector<CauseGroup>& groups, const std::string& key, const std::string& fix, CauseItem item) {
  auto it = std::find_if(groups.begin(), groups.end(), [&](const CauseGroup& g) { return g.key == key; });
  if (it == groups.end()) it = groups.insert(groups.end(), CauseGroup{key, fix, {}});
  it->items.push_back(std::move(item));
}

std::string groupText(std::vector<CauseGroup> groups, int show) {
  std::string text;
  for (CauseGroup& g : groups) {
    std::stable_sort(g.items.begin(), g.items.end(), [](const CauseItem& x, const CauseItem& y) { return x.gap > y.gap; });
    text += "  " + g.key + ": " + std::to_string(g.items.size()) + "\n    fix: " + g.fix + "\n";
    text += "    e.g. " + g.items.front().detail + "\n";
    const size_t shown = std::min(g.items.size(), static_cast<size_t>(show));
    for (size_t i = 0; i < shown; ++i) text += "      " + g.items[i].where + "\n";
    if (shown < g.items.size())
      text += "      ... and " + std::to_string(g.items.size() - shown) + " more findings (--show N, or --json FILE)\n";
  }
  return text;
}

std::string findingLines(const CheckArgs& a, const vf::Report& r) {
  std::vector<CauseGroup> groups, gpu, off;
  for (const vf::Hole& h : r.holes) {
    const Cause c = holeCause(h);
    addToGroup(groups, "hole: " + c.key, c.fix, {0, patchText(h.patch), c.detail});
  }
  for (const vf::Hole& h : r.undecided) {
    const Cause c = holeCause(h); // the key starts with "undecided: "
    addToGroup(groups, c.key, c.fix, {0, patchText(h.patch), c.detail});
  }
  for (const vf::Finding& f : r.findings) {
    if (f.classification == vf::Classification::Match) continue;
    const Cause c = findingCause(f);
    const bool counted = f.onScreen || a.offscreen;
    const std::string key = std::string(vf::toString(f.classification)) + (counted ? "" : " (off screen)") + ": " + c.key;
    const double gap = f.onScreen ? f.onScreenGapWorld : f.gapWorld;
    addToGroup(counted ? groups : off, key, c.fix, {a.offscreen ? f.gapWorld : gap, findingWhere(f), c.detail});
  }
  for (const vf::GpuFloatFinding& g : r.gpuFloat) { // --gpu-float conformant: matching edges that may crack on some GPUs
    const Cause c = gpuFloatCause(g);
    addToGroup(gpu, c.key, c.fix, {0, gpuFloatWhere(g), c.detail});
  }
  std::string text = groupText(groups, a.show) + groupText(gpu, a.show) + groupText(off, a.show);
  if (r.truncated)
    text += "  the report keeps the first " + std::to_string(r.findings.size()) +
            " findings (the counts under each cause are of those; the stats above count all)\n";
  return text;
}

// The text report before the verdict: the scene, overrides and camera, the stats, the GPU factor section, the
// finding lines.
std::string checkText(const CheckArgs& a, const vf::Scene& scene, const vf::Camera& cam, const vf::CheckOptions& opt,
                      const vf::Report& full, const vf::Report& r) {
  std::string text = "fftess check " + a.scene + (scene.name.empty() ? "" : " (" + scene.name + ")") + "\n";
  for (const std::string& s : overridesOf(a)) text += "  --set " + s + "\n";
  char buf[200];
  std::snprintf(buf, sizeof buf, "  camera eye (%g, %g, %g) target (%g, %g, %g), %dx%d", static_cast<double>(cam.eye.x),
                static_cast<double>(cam.eye.y), static_cast<double>(cam.eye.z), static_cast<double>(cam.target.x),
                static_cast<double>(cam.target.y), static_cast<double>(cam.target.z), cam.width, cam.height);
  text += buf;
  if (cam.convention != vf::CameraConvention::Gl) text += std::string(", ") + vf::toString(cam.convention) + " convention";
  if (!a.cameras.empty())
    text += " (camera " + std::to_string(a.cameraIndexGiven ? a.cameraIndex : 0) + " of " + a.cameras + ")";
  text += "\n";
  text += statsText(r.stats, a.offscreen);
  FactorDiffTally gpuDiffs; // lod.evaluate = "gpu" / lod.shader (cli/gpu_lod.h)
  gpuDiffs.add(0, full);
  text += gpuDiffs.text(scene, opt, r.stats);
  return text + findingLines(a, r);
}

// --mesh: the whole-mesh check of the same camera and where it disagrees with the edge check.
struct MeshRun {
  vf::MeshReport mesh;
  MeshDiff diff;
};

MeshRun runMesh(const vf::Terrain& terrain, const vf::Camera& cam, const vf::CheckOptions& opt, const vf::Report& full) {
  MeshRun m;
  m.mesh = vf::checkSceneMesh(terrain, cam, opt);
  if (!m.mesh.error.empty()) throw UsageError(m.mesh.error);
  m.diff = meshDiff(full, m.mesh);
  return m;
}

std::string meshText(const vf::Terrain& terrain, const vf::Report& full, const MeshRun& m, int show) {
  std::string text = "whole-mesh check: " + std::to_string(m.mesh.triangles) + " triangles, " +
                     std::to_string(m.mesh.innerBorderEdges) + " inner border edges on " +
                     std::to_string(m.mesh.flagged.size()) + " patch edges: " +
                     (m.diff.agree() ? "agrees with the edge check" : "DISAGREES with the edge check") + "\n";
  if (!m.diff.agree()) text += meshDiffText(terrain, full, m.diff, show);
  return text;
}

// The verdict line of a check.
std::string checkVerdictLine(vf::Verdict verdict, const vf::Stats& stats, bool countOffScreen, bool meshAgrees) {
  std::string words;
  switch (verdict) {
  case vf::Verdict::Cracks: words = stats.holes > 0 ? "CRACKS and HOLES" : "CRACKS"; break;
  case vf::Verdict::Holes: words = "HOLES (patches not drawn while in view)"; break;
  case vf::Verdict::NothingChecked:
    words = "NOTHING CHECKED: no shared edge was classified (every patch culled or out of view, or the layout has "
            "no shared edge); not a clean verdict";
    break;
  case vf::Verdict::Undecided:
    words = "UNDECIDED: " + std::to_string(stats.undecided) +
            " patches not drawn could be neither proven visible nor invisible (listed above); not a clean verdict";
    break;
  case vf::Verdict::GpuFloat:
    words = "MAY CRACK ON SOME GPUS: " + std::to_string(stats.gpuFloatFindings) +
            " matching shared edges depend on a conformant GPU compiler's choices (listed above); no crack with "
            "lod/'s C++ build";
    break;
  case vf::Verdict::TJunctionsOnly: words = "watertight now (T-junctions)"; break;
  default: words = "watertight"; break;
  }
  if (stats.undecided > 0 && verdict != vf::Verdict::Undecided)
    words += " (and " + std::to_string(stats.undecided) + " patches of undecided visibility)";
  const std::string off = offScreenWords(stats, countOffScreen);
  if (!off.empty()) words += " (" + off + ")";
  if (!meshAgrees) words += "; the whole-mesh check DISAGREES with the edge check (exit 1)";
  return "verdict: " + words + "\n";
}

// The --json and --svg reports, written all or nothing.
void writeCheckReports(const CheckArgs& a, ReportFiles& reports, const vf::Terrain& terrain, const vf::Camera& cam,
                       const vf::Report& r, const MeshRun* mesh, const json& camerasFile) {
  if (!a.json.empty()) {
    json j = checkJson(a, terrain, cam, r, mesh ? &mesh->mesh : nullptr);
    if (!camerasFile.is_null()) j["cameras_file"] = camerasFile; // --cameras: the file, its hash, the camera's index
    if (mesh) {
      const json d = meshDiffJson(vf::layoutFor(terrain, cam), mesh->diff);
      for (auto it = d.begin(); it != d.end(); ++it) j["mesh"][it.key()] = it.value();
    }
    reports.setJson(j.dump(2) + "\n");
  }
  if (!a.svg.empty()) // the camera's own patches (a quadtree's differ per camera): the report's indices
    reports.setSvg(checkSvg(vf::layoutFor(terrain, cam), r, "fftess check " + a.scene, a.offscreen));
  if (!a.view.empty()) // the camera's own layout: the report's patch indices (a quadtree's leaves for this camera)
    reports.setView(viewSvg(vf::layoutFor(terrain, cam), cam, r, "fftess check " + a.scene + " --view", a.offscreen));
  reports.commit(); // all or nothing
}

// --gltf: the camera's view in 3D (report_gltf.h) from the report as kept, into its file's buffer.
void setCheckGltf(const CheckArgs& a, ReportFiles& reports, const vf::Terrain& terrain, const vf::Camera& cam,
                  const vf::CheckOptions& opt, const vf::Report& r, vf::Verdict verdict) {
  if (!reports.gltf()) return;
  const std::string which = a.pathCameraGiven ? "camera " + std::to_string(a.pathCamera) + " of the scene's camera path"
                                              : "the scene's camera";
  reports.setGltf(checkGltf(terrain, cam, opt, r, {"fftess check " + a.scene, vf::toString(verdict), which},
                            gltfTextPath(a.gltf)));
}

} // namespace

int runCheck(const CheckArgs& a) {
  checkCheckArgs(a);
  ReportFiles reports(a); // output paths are checked before the work
  const vf::Terrain terrain = load(a); // the one terrain build of this command
  const vf::Scene& scene = terrain.scene();
  json camerasFile; // null unless --cameras
  const vf::Camera cam = checkCamera(a, scene, camerasFile);
  vf::CheckOptions opt = checkOptions(a, terrain);
  const size_t keep = opt.maxFindings;
  if (a.mesh) opt.maxFindings = static_cast<size_t>(-1); // the mesh comparison needs every finding
  opt.keepDrawn = !a.view.empty();                        // --view draws the patches drawn
  const vf::Report full = vf::checkScene(terrain, cam, opt); // the one edge check of this camera
  if (!full.error.empty()) throw UsageError(full.error);
  const vf::Report r = keptReport(full, keep);
  const bool talk = !a.quiet && a.json != "-";
  std::string text = talk ? checkText(a, scene, cam, opt, full, r) : "";
  MeshRun mesh;
  if (a.mesh) {
    mesh = runMesh(terrain, cam, opt, full);
    if (talk) text += meshText(vf::layoutFor(terrain, cam), full, mesh, a.show);
  }
  const vf::Verdict verdict = vf::verdictOf(r.stats, a.offscreen);
  // A disagreement of the two checks is a finding (exit 1), reported with both sides, never a clean verdict.
  const int status = mesh.diff.agree() ? verdictStatus(verdict, a.failOnTJunctions) : kExitFindings;
  if (talk) text += checkVerdictLine(verdict, r.stats, a.offscreen, mesh.diff.agree());
  if (reports.ci()) // --sarif / --junit (docs/ci.md)
    setCiReports(reports, checkCi(SceneCiContext(a, scene), cam, r, verdict, mesh.diff.agree(), status));
  // Reports first (atomically), then the text: a failure writing a report leaves no partial file.
  setCheckGltf(a, reports, terrain, cam, opt, r, verdict);
  writeCheckReports(a, reports, terrain, cam, r, a.mesh ? &mesh : nullptr, camerasFile);
  writeStdout(text);
  flushStdout();
  return status;
}

} // namespace fftess::cli
