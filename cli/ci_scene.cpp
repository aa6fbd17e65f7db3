// The CI reports of check and sweep (ci_scene.h).
#include "ci_scene.h"
#include "causes.h"
#include "common.h"
#include "report_junit.h"
#include "report_sarif.h"
#include "scene_options.h"

#include <cstdio>

namespace fftess::cli {

namespace {

using ojson = nlohmann::ordered_json;

CiLogical patchLogical(const vf::PatchRef& p) {
  return {patchText(p), "patch[" + std::to_string(p.index) + "]", "object"};
}
CiLogical edgeLogical(const vf::PatchRef& p, int edge) {
  return {patchText(p) + " " + edgeName(edge), "patch[" + std::to_string(p.index) + "]." + edgeName(edge), "member"};
}
ojson patchJson(const vf::PatchRef& p, int edge) {
  ojson j{{"index", p.index}, {"ring", p.ring}, {"tile", p.tile}, {"patch", p.patch}, {"level", p.level}};
  if (edge >= 0) j["edge"] = edgeName(edge);
  return j;
}

CiResult findingResult(const SceneCiContext& ctx, const vf::Finding& f) {
  const Cause c = findingCause(f);
  const bool crack = f.classification == vf::Classification::Crack;
  const bool visible = f.onScreen || ctx.offscreen;
  const bool counted = visible && (crack || ctx.failOnTJunctions);
  CiResult x;
  x.kind = vf::toString(f.classification);
  x.rule = x.kind + (visible ? "" : " (off screen)") + ": " + c.key;
  x.level = counted ? "error" : crack || visible ? "warning" : "note";
  x.outcome = counted ? CiOutcome::Failure : CiOutcome::NotCounted;
  x.where = patchText(f.a.patch) + " " + edgeName(f.a.edge) + " | " + patchText(f.b.patch) + " " + edgeName(f.b.edge);
  x.message = c.detail;
  if (crack) x.message += "; gap " + fmtWorld(f.gapWorld) + " world units (" + fmtWorld(f.gapPixels) + " px)";
  if (!f.onScreen) x.message += ctx.offscreen ? "; off screen (counted: --offscreen)" : "; off screen, not counted";
  if (!crack && !ctx.failOnTJunctions) x.message += "; a T-junction, no gap now (--fail-on-tjunctions counts it)";
  x.fix = c.fix;
  x.logical = {edgeLogical(f.a.patch, f.a.edge), edgeLogical(f.b.patch, f.b.edge)};
  x.properties = {{"a", patchJson(f.a.patch, f.a.edge)}, {"b", patchJson(f.b.patch, f.b.edge)},
                  {"on_screen", f.onScreen}, {"gap_world", f.gapWorld}, {"gap_pixels", f.gapPixels}};
  locateKey(ctx, x);
  return x;
}

CiResult holeResult(const SceneCiContext& ctx, const vf::Hole& h) {
  const Cause c = holeCause(h);
  const bool undecided = h.visibility == vf::Visibility::Undecided;
  CiResult x;
  x.kind = undecided ? "undecided" : "hole";
  x.rule = undecided ? c.key : "hole: " + c.key; // undecided keys start with "undecided: "
  x.level = "error";
  x.outcome = undecided ? CiOutcome::Error : CiOutcome::Failure;
  x.where = patchText(h.patch) + (h.edge >= 0 ? std::string(" ") + edgeName(h.edge) : "");
  x.message = c.detail + (undecided ? "; visibility undecided: not a clean verdict" : "");
  x.fix = c.fix;
  x.logical = {h.edge >= 0 ? edgeLogical(h.patch, h.edge) : patchLogical(h.patch)};
  x.properties = {{"patch", patchJson(h.patch, h.edge)}};
  locateKey(ctx, x);
  return x;
}

CiResult gpuFloatResult(const SceneCiContext& ctx, const vf::GpuFloatFinding& g) {
  const Cause c = gpuFloatCause(g);
  CiResult x;
  x.kind = "gpu_float";
  x.rule = c.key;
  x.level = "error";
  x.where = patchText(g.a) + " " + edgeName(g.edgeA) + " | " + patchText(g.b) + " " + edgeName(g.edgeB);
  x.message = c.detail;
  x.fix = c.fix;
  x.logical = {edgeLogical(g.a, g.edgeA), edgeLogical(g.b, g.edgeB)};
  x.properties = {{"a", patchJson(g.a, g.edgeA)}, {"b", patchJson(g.b, g.edgeB)}};
  locateKey(ctx, x);
  return x;
}

// Every result of one camera's report, in the report's order (findings, holes, undecided, GPU float).
std::vector<CiResult> reportResults(const SceneCiContext& ctx, const vf::Report& r) {
  std::vector<CiResult> out;
  for (const vf::Finding& f : r.findings)
    if (f.classification != vf::Classification::Match) out.push_back(findingResult(ctx, f));
  for (const vf::Hole& h : r.holes) out.push_back(holeResult(ctx, h));
  for (const vf::Hole& h : r.undecided) out.push_back(holeResult(ctx, h));
  for (const vf::GpuFloatFinding& g : r.gpuFloat) out.push_back(gpuFloatResult(ctx, g));
  return out;
}

// A state that is not clean and has no finding: an <error> at the scene file.
CiResult stateResult(const SceneCiContext& ctx, const std::string& kind, const std::string& rule,
                     const std::string& message, const std::string& fix) {
  CiResult x;
  x.kind = kind, x.rule = rule, x.level = "error", x.outcome = CiOutcome::Error;
  x.message = message, x.fix = fix, x.file = ctx.file;
  return x;
}

const char* const kNothingCheckedFix =
    "aim the camera at the terrain (camera.eye, camera.target) so that shared patch edges are in view, or give the "
    "layout shared edges; a check that classified no edge says nothing about cracks";

// The case of a result: the case with that name, made when missing.
CiCase& caseNamed(std::vector<CiCase>& cases, const std::string& name) {
  for (CiCase& c : cases)
    if (c.name == name) return c;
  cases.push_back(CiCase{name, {}, "", ""});
  return cases.back();
}

ojson statsProps(const vf::Stats& s) {
  return {{"patches", s.patches},         {"culled_patches", s.culledPatches}, {"edges_checked", s.edgesChecked},
          {"matches", s.matches},         {"t_junctions", s.tJunctions},       {"cracks", s.cracks},
          {"holes", s.holes},             {"undecided", s.undecided},          {"gpu_float_findings", s.gpuFloatFindings},
          {"cracks_off_screen", s.cracksOffScreen}};
}

std::string checkedWords(const vf::Stats& s) {
  return std::to_string(s.edgesChecked) + " shared edges checked on " + std::to_string(s.patches) + " patches (" +
         std::to_string(s.culledPatches) + " culled): " + std::to_string(s.matches) + " matches, " +
         std::to_string(s.tJunctions) + " T-junctions, " + std::to_string(s.cracks) + " cracks, " +
         std::to_string(s.holes) + " holes, " + std::to_string(s.undecided) + " undecided";
}

} // namespace

void setCiReports(ReportFiles& files, const CiReport& r) {
  files.setSarif(sarifText(r));
  files.setJunit(junitText(r));
}

SceneCiContext::SceneCiContext(const SceneArgs& a, const vf::Scene& scene)
    : file(a.scene), keyLines(scene.keyLines), offscreen(a.offscreen), failOnTJunctions(a.failOnTJunctions) {
  for (const std::string& o : overridesOf(a)) {
    std::string key = o.substr(0, o.find('='));
    while (!key.empty() && key.back() == ' ') key.pop_back();
    set[key] = o;
  }
}

std::string fixKey(const std::string& fix) {
  for (size_t at = fix.find(" = "); at != std::string::npos; at = fix.find(" = ", at + 1)) {
    size_t b = at;
    auto keyChar = [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '.'; };
    while (b > 0 && keyChar(fix[b - 1])) --b;
    const std::string key = fix.substr(b, at - b);
    const size_t dot = key.find('.');
    if (dot != std::string::npos && dot > 0 && dot + 1 < key.size()) return key;
  }
  return "";
}

void locateKey(const SceneCiContext& ctx, CiResult& x) {
  x.file = ctx.file;
  const std::string key = fixKey(x.fix);
  if (key.empty()) return;
  x.logical.push_back({key.substr(key.rfind('.') + 1), key, "variable"});
  x.properties["scene_key"] = key;
  if (auto s = ctx.set.find(key); s != ctx.set.end()) {
    x.lineWhy = key + " given by --set " + s->second + " (not the file's line)";
    return;
  }
  if (auto k = ctx.keyLines.find(key); k != ctx.keyLines.end()) {
    x.line = k->second;
    x.lineWhy = "the line of " + key;
    return;
  }
  const std::string table = key.substr(0, key.find('.'));
  if (auto t = ctx.keyLines.find(table); t != ctx.keyLines.end()) {
    x.line = t->second;
    x.lineWhy = "the [" + table + "] table; " + key + " is not set there (its default)";
    return;
  }
  x.lineWhy = key + " is not set in the file (its default)";
}

CiReport checkCi(const SceneCiContext& ctx, const vf::Camera& cam, const vf::Report& r, vf::Verdict verdict,
                 bool meshAgrees, int status) {
  CiReport out;
  out.command = "check";
  out.suite = "fftess check " + ctx.file;
  out.exitStatus = status;
  out.results = reportResults(ctx, r);
  for (size_t i = 0; i < out.results.size(); ++i) {
    CiCase& c = caseNamed(out.cases, out.results[i].rule);
    c.results.push_back(i);
    if (out.results[i].outcome == CiOutcome::NotCounted)
      c.skipped = "not counted: " + std::string(out.results[i].kind == "crack"
                                                    ? "off screen (--offscreen counts it)"
                                                    : "T-junctions leave no gap now (--fail-on-tjunctions counts them)");
  }
  CiCase verdictCase{std::string("verdict: ") + vf::toString(verdict), {}, "", checkedWords(r.stats)};
  if (verdict == vf::Verdict::NothingChecked) {
    verdictCase.results.push_back(out.results.size());
    out.results.push_back(stateResult(ctx, "nothing_checked", "nothing checked: no shared edge was classified",
                                      "no shared edge was classified (every patch culled or out of view, or the "
                                      "layout has no shared edge): not a clean verdict", kNothingCheckedFix));
  }
  if (!meshAgrees) {
    verdictCase.results.push_back(out.results.size());
    out.results.push_back(stateResult(ctx, "mesh_disagrees", "the whole-mesh check disagrees with the edge check",
                                      "--mesh: the whole-mesh check and the edge check disagree (a verifier bug)",
                                      "report it with the scene and the command (fftess check --mesh --json)"));
  }
  out.cases.push_back(verdictCase);
  char eye[200];
  std::snprintf(eye, sizeof eye, "camera eye (%g, %g, %g) target (%g, %g, %g)", double(cam.eye.x), double(cam.eye.y),
                double(cam.eye.z), double(cam.target.x), double(cam.target.y), double(cam.target.z));
  out.notes.push_back({"note", std::string("checked ") + ctx.file + " from " + eye + ": " + checkedWords(r.stats) +
                                   "; verdict " + vf::toString(verdict)});
  if (r.truncated)
    out.notes.push_back({"warning", "the report keeps the first findings only (as --json does); the counts in "
                                    "properties are all of them"});
  out.properties = {{"verdict", vf::toString(verdict)}, {"scene", ctx.file}, {"camera", eye}, {"truncated", r.truncated}};
  out.properties["stats"] = statsProps(r.stats);
  return out;
}

// ---- sweep -------------------------------------------------------------------------------------------------------
void SweepCi::addReport(size_t camera, const vf::Report& r) {
  Camera& c = cameras_[camera];
  c.reported = true;
  for (CiResult& x : reportResults(ctx_, r)) {
    size_t k = 0;
    while (k < c.results.size() && c.results[k].rule != x.rule) ++k;
    if (k == c.results.size()) c.results.push_back(std::move(x)), c.counts.push_back(0);
    ++c.counts[k];
  }
}

void SweepCi::addCamera(size_t camera, const vf::CameraResult& r) {
  Camera& c = cameras_[camera];
  c.done = r.done;
  c.error = r.error;
  c.stats = r.stats;
}

CiReport SweepCi::finish(const vf::SweepResult& res, vf::Verdict verdict, size_t requested, int status,
                         const std::function<std::string(size_t)>& cameraWords) const {
  CiReport out;
  out.command = "sweep";
  out.suite = "fftess sweep " + ctx_.file;
  out.exitStatus = status;
  for (const auto& [index, cam] : cameras_) {
    const std::string name = "camera " + std::to_string(index);
    CiCase kase{name + " " + cameraWords(index), {}, "", ""};
    if (!cam.error.empty()) {
      kase.results.push_back(out.results.size());
      out.results.push_back(stateResult(ctx_, "camera_invalid", "camera not checked (invalid)",
                                        name + " could not be checked: " + cam.error,
                                        "give a valid camera (eye != target, finite, near < far)"));
    } else if (cam.done) {
      kase.out = checkedWords(cam.stats);
      for (size_t k = 0; k < cam.results.size(); ++k) {
        CiResult x = cam.results[k];
        x.message = name + ": " + std::to_string(cam.counts[k]) + " finding" + (cam.counts[k] == 1 ? "" : "s") +
                    " of this cause; the first: " + x.message;
        x.logical.insert(x.logical.begin(), {name, "camera[" + std::to_string(index) + "]", "object"});
        x.properties["camera"] = index;
        x.properties["findings_on_camera"] = cam.counts[k];
        if (x.outcome == CiOutcome::NotCounted) kase.skipped = "not counted: off screen or T-junctions only";
        kase.results.push_back(out.results.size());
        out.results.push_back(std::move(x));
      }
      if (cam.stats.edgesChecked == 0 && kase.results.empty())
        kase.skipped = "nothing checked: no shared edge was classified from this camera";
    } else {
      continue; // not checked (interrupted): counted in the case "interrupted" below
    }
    out.cases.push_back(std::move(kase));
  }
  CiCase verdictCase{std::string("verdict: ") + vf::toString(verdict), {}, "", checkedWords(res.total)};
  if (verdict == vf::Verdict::NothingChecked) {
    verdictCase.results.push_back(out.results.size());
    out.results.push_back(stateResult(ctx_, "nothing_checked", "nothing checked: no shared edge was classified",
                                      "no camera classified a shared edge: not a clean verdict", kNothingCheckedFix));
  }
  const size_t notChecked = requested - std::min(requested, res.camerasDone + res.camerasInvalid);
  if (notChecked > 0) {
    verdictCase.results.push_back(out.results.size());
    out.results.push_back(stateResult(ctx_, "interrupted", "cameras not checked (interrupted)",
                                      std::to_string(notChecked) + " of " + std::to_string(requested) +
                                          " cameras were not checked (interrupted): not a clean verdict",
                                      "run the sweep to the end"));
  }
  out.cases.push_back(verdictCase);
  std::string nothing; // cameras that classified no shared edge: skipped cases in JUnit, a warning here
  size_t nothingCount = 0;
  for (const auto& [index, cam] : cameras_)
    if (cam.done && cam.error.empty() && cam.stats.edgesChecked == 0 && nothingCount++ < 20)
      nothing += (nothing.empty() ? "" : ", ") + std::to_string(index);
  if (nothingCount > 0)
    out.notes.push_back({"warning", std::to_string(nothingCount) + " cameras classified no shared edge (nothing checked "
                                    "from them; every patch culled or out of view): " + nothing +
                                    (nothingCount > 20 ? ", ..." : "")});
  out.notes.push_back({"note", "swept " + ctx_.file + ": " + std::to_string(res.camerasDone) + " of " +
                                   std::to_string(requested) + " cameras checked, " +
                                   std::to_string(res.camerasInvalid) + " invalid; " + checkedWords(res.total) +
                                   "; verdict " + vf::toString(verdict)});
  out.properties = {{"verdict", vf::toString(verdict)},  {"scene", ctx_.file},
                    {"cameras_total", requested},         {"cameras_done", res.camerasDone},
                    {"cameras_invalid", res.camerasInvalid}, {"cameras_nothing_checked", res.camerasNothingChecked},
                    {"cameras_undecided", res.camerasUndecided}};
  out.properties["stats"] = statsProps(res.total);
  return out;
}

} // namespace fftess::cli
