// JSON reports of check and sweep (report_json.h).
#include "report_json.h"
#include "causes.h"
#include "common.h"
#include "scene_options.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace fftess::cli {

json vec3Json(const glm::vec3& v) { return json::array({v.x, v.y, v.z}); }

json lodJson(const vf::EdgeLod& l) {
  json fixes = json::array();
  for (uint32_t bit = 1; bit <= lod::FixLiteralSource; bit <<= 1)
    if (l.why.fixes & bit) fixes.push_back(lod::fixName(static_cast<lod::Fix>(bit)));
  json j;
  j["scheme"] = vf::toString(l.scheme);
  j["fixes"] = fixes;
  j["metric"] = l.why.metric;
  j["unclamped"] = l.why.unclamped;
  j["exponent"] = l.why.exponent;
  j["culled"] = l.culled;
  j["neighbour_size"] = l.neighbourSize;
  j["clamp"] = vf::toString(l.clamp);
  j["reconstruction"] = vf::toString(l.reconstruction);
  return j;
}

json workJson(const vf::WorkStats& w) {
  return {{"terrain_builds", w.terrainBuilds},   {"height_samples", w.heightSamples},
          {"domain_evaluations", w.domainEvaluations}, {"lod_evaluations", w.lodEvaluations},
          {"edge_queries", w.edgeQueries},       {"cgal_calls", w.cgalCalls},
          {"full_tessellations", w.fullTessellations}, {"shared_edge_points", w.sharedEdgePoints},
          {"visibility_evaluations", w.visibilityEvaluations},
          {"layout_selections", w.layoutSelections},     {"layout_nodes", w.layoutNodes},
          {"cache_hits", w.cacheHits},           {"seam_hits", w.seamHits},
          {"cache_misses", w.cacheMisses},       {"seam_proofs", w.seamProofs},
          {"box_tests", w.boxTests}};
}

static json sideJson(const vf::EdgeSide& s) {
  json j;
  j["patch"] = {{"index", s.patch.index}, {"ring", s.patch.ring}, {"tile", s.patch.tile}, {"patch", s.patch.patch},
                {"level", s.patch.level}};
  j["edge"] = edgeName(s.edge);
  j["hull_factor"] = s.hullFactor;
  char bits[16];
  std::snprintf(bits, sizeof bits, "0x%08X", static_cast<unsigned>(s.hullFactorBits));
  j["factor_bits"] = bits;
  j["processed_factor"] = s.processedFactor;
  j["culled"] = s.culled;
  j["lod"] = lodJson(s.lod);
  j["param_range"] = json::array({s.paramLo, s.paramHi});
  j["point_count"] = s.pointCount;
  j["first_mismatch"] = s.firstMismatch;
  if (s.firstMismatch >= 0) {
    j["mismatch_domain"] = json::array({s.mismatchDomain.u, s.mismatchDomain.v});
    j["mismatch_world"] = vec3Json(s.mismatchWorld);
  } else {
    j["mismatch_domain"] = nullptr;
    j["mismatch_world"] = nullptr;
  }
  return j;
}

json findingJson(const vf::Finding& f) {
  json j;
  j["classification"] = vf::toString(f.classification);
  const Cause cause = findingCause(f);
  j["cause"] = cause.key;
  j["cause_id"] = cause.id;
  j["fix"] = cause.fix;
  j["explanation"] = cause.detail;
  j["partitioning"] = toString(f.partitioning);
  j["a"] = sideJson(f.a);
  j["b"] = sideJson(f.b);
  j["edge_start"] = vec3Json(f.edgeStart);
  j["edge_end"] = vec3Json(f.edgeEnd);
  j["gap_world"] = f.gapWorld;
  j["gap_pixels"] = f.gapPixels;
  j["gap_vertex"] = vec3Json(f.gapVertex);
  j["gap_side"] = f.gapSide == 0 ? "a" : "b";
  j["on_screen"] = f.onScreen;
  j["on_screen_gap_world"] = f.onScreenGapWorld;
  j["on_screen_gap_pixels"] = f.onScreenGapPixels;
  j["on_screen_gap_vertex"] = vec3Json(f.onScreenGapVertex);
  j["on_screen_gap_side"] = f.onScreenGapSide == 0 ? "a" : "b";
  return j;
}

json statsJson(const vf::Stats& s) {
  return {{"patches", s.patches},           {"culled_patches", s.culledPatches}, {"edges_checked", s.edgesChecked},
          {"skipped_culled", s.skippedCulled}, {"matches", s.matches},          {"t_junctions", s.tJunctions},
          {"cracks", s.cracks},             {"holes", s.holes},                  {"holes_discarded", s.holesDiscarded},
          {"holes_culled_while_visible", s.holesCulledVisible}, {"culled_undecided", s.culledUndecided},
          {"visibility_tests", s.visibilityTests}, {"denormal_factors", s.denormalFactors},
          {"worst_gap_world", s.worstGapWorld}, {"worst_gap_pixels", s.worstGapPixels},
          {"cracks_off_screen", s.cracksOffScreen}, {"t_junctions_off_screen", s.tJunctionsOffScreen},
          {"worst_gap_world_on_screen", s.worstGapWorldOnScreen},
          {"worst_gap_pixels_on_screen", s.worstGapPixelsOnScreen}, {"undecided", s.undecided},
          {"patches_off_screen", s.patchesOffScreen}, {"edges_off_screen", s.edgesOffScreen},
          {"gpu_float_pairs", s.gpuFloatPairs}, {"gpu_float_findings", s.gpuFloatFindings},
          {"gpu_model_factors", s.gpuModelFactors}, {"gpu_model_outside", s.gpuModelOutside}};
}

json gpuFloatJson(const vf::GpuFloatFinding& g) {
  auto side = [](const vf::PatchRef& p, int edge, float factor, float lo, float hi, const std::string& op) {
    return json{{"patch", {{"index", p.index}, {"ring", p.ring}, {"tile", p.tile}, {"patch", p.patch}, {"level", p.level}}},
                {"edge", edgeName(edge)},
                {"factor", formatFloat(factor)}, // strings: NaN and Inf are not JSON numbers
                {"conformant_lo", formatFloat(lo)},
                {"conformant_hi", formatFloat(hi)},
                {"operation", op.empty() ? json(nullptr) : json(op)}};
  };
  const Cause c = gpuFloatCause(g);
  return {{"cause", c.key}, {"cause_id", c.id}, {"why", g.why}, {"fix", g.fix}, {"explanation", c.detail},
          {"a", side(g.a, g.edgeA, g.factorA, g.loA, g.hiA, g.operationA)},
          {"b", side(g.b, g.edgeB, g.factorB, g.loB, g.hiB, g.operationB)}};
}

json holeJson(const vf::Hole& h) {
  json j;
  j["kind"] = vf::toString(h.kind);
  const Cause cause = holeCause(h);
  j["cause"] = cause.key;
  j["cause_id"] = cause.id;
  j["fix"] = cause.fix;
  j["explanation"] = cause.detail;
  j["patch"] = {{"index", h.patch.index}, {"ring", h.patch.ring}, {"tile", h.patch.tile}, {"patch", h.patch.patch},
                {"level", h.patch.level}};
  j["visibility"] = vf::toString(h.visibility);
  j["visible_point"] = h.visibility == vf::Visibility::Visible ? vec3Json(h.visiblePoint) : json(nullptr);
  j["edge"] = h.edge >= 0 ? json(edgeName(h.edge)) : json(nullptr);
  j["hull_factor"] = formatFloat(h.hullFactor); // a string: NaN and Inf are not JSON numbers
  char bits[16];
  std::snprintf(bits, sizeof bits, "0x%08X", static_cast<unsigned>(h.hullFactorBits));
  j["factor_bits"] = bits;
  json fs = json::array();
  for (float f : h.factors) fs.push_back(formatFloat(f));
  j["factors"] = fs;
  j["lod"] = lodJson(h.lod);
  j["midpoint_w"] = formatFloat(h.midpointW);
  j["lod_box_y"] = json::array({h.lodBoxMinY, h.lodBoxMaxY});
  j["on_screen"] = h.onScreen;
  j["domain_point"] = h.visibility == vf::Visibility::Invisible ? json(nullptr)
                                                                : json::array({h.domainPoint.u, h.domainPoint.v});
  if (h.visibility == vf::Visibility::Undecided) {
    j["undecided_side"] = h.undecidedSide;
    j["budget_exhausted"] = h.budgetExhausted;
  }
  return j;
}

json denormalJson(const vf::DenormalFactor& d) {
  static const char* const names[6] = {"Ueq0", "Veq0", "Ueq1", "Veq1", "insideU", "insideV"};
  char bits[16];
  std::snprintf(bits, sizeof bits, "0x%08X", static_cast<unsigned>(d.bits));
  return {{"patch", {{"index", d.patch.index}, {"ring", d.patch.ring}, {"tile", d.patch.tile}, {"patch", d.patch.patch},
                     {"level", d.patch.level}}},
          {"factor", d.factor >= 0 && d.factor < 6 ? names[d.factor] : "?"},
          {"value", formatFloat(d.value)},
          {"bits", bits},
          {"flushed", d.flushed}};
}

json cameraJson(const vf::Camera& c) {
  return {{"eye", vec3Json(c.eye)}, {"target", vec3Json(c.target)}, {"up", vec3Json(c.up)},       {"fov_y", c.fovY},
          {"near", c.nearZ},      {"far", c.farZ},            {"width", c.width},       {"height", c.height},
          {"convention", vf::toString(c.convention)}};
}

json sceneJson(const SceneArgs& a, const vf::Scene& s) {
  return {{"file", a.scene},
          {"name", s.name},
          {"overrides", overridesOf(a)},
          {"layout", vf::toString(s.layout.kind)},
          {"lod_scheme", vf::toString(s.lod.scheme)},
          {"adjacency_clamp", vf::toString(s.lod.screenSphere.clamp)},
          {"partitioning", toString(s.partitioning)},
          {"stage", toString(s.stage)},
          {"domain_formula", vf::toString(s.domain.formula)},
          {"kernel", a.kernel}};
}

// The fields every check and sweep report starts with.
static json reportHeader(const char* kind, const SceneArgs& a, const vf::Scene& scene) {
  json j;
  j["version"] = kReportVersion;
  j["kind"] = kind;
  j["fftess_version"] = FFTESS_VERSION;
  j["scene"] = sceneJson(a, scene);
  char hash[24];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(scene.contentHash));
  j["scene_hash"] = std::string("fnv1a64:") + hash; // vf::Scene::contentHash: the scene's bytes, overrides, files
  j["offscreen"] = a.offscreen; // --offscreen: findings outside the view frustum count in the verdict
  j["gpu_float_mode"] = a.gpuFloat; // --gpu-float: "off" or "conformant"
  return j;
}

json checkJson(const SceneArgs& a, const vf::Terrain& terrain, const vf::Camera& cam, const vf::Report& r,
               const vf::MeshReport* mesh) {
  json j = reportHeader("check", a, terrain.scene());
  j["camera"] = cameraJson(cam);
  j["stats"] = statsJson(r.stats);
  j["verdict"] = vf::toString(vf::verdictOf(r.stats, a.offscreen));
  j["truncated"] = r.truncated;
  json fs = json::array();
  for (const vf::Finding& f : r.findings) fs.push_back(findingJson(f));
  j["findings"] = fs;
  json hs = json::array();
  for (const vf::Hole& h : r.holes) hs.push_back(holeJson(h));
  j["holes"] = hs;
  json us = json::array();
  for (const vf::Hole& h : r.undecided) us.push_back(holeJson(h));
  j["undecided"] = us;
  j["denormals_flushed"] = r.denormalsFlushed;
  json ds = json::array();
  for (const vf::DenormalFactor& d : r.denormalFactors) ds.push_back(denormalJson(d));
  j["denormal_factors"] = ds;
  json gs = json::array();
  for (const vf::GpuFloatFinding& g : r.gpuFloat) gs.push_back(gpuFloatJson(g));
  j["gpu_float"] = gs;
  if (mesh)
    j["mesh"] = {{"triangles", mesh->triangles}, {"vertices", mesh->vertices}, {"border_edges", mesh->borderEdges},
                 {"inner_border_edges", mesh->innerBorderEdges}, {"flagged_patch_edges", mesh->flagged.size()}};
  vf::WorkStats work = terrain.stats();
  work += r.work;
  if (mesh) work += mesh->work;
  work.terrainBuilds = vf::terrainBuildCount(); // every build in this process, not just the one counted above
  j["work"] = workJson(work);
  return j;
}

json sweepHeaderJson(const SceneArgs& a, const vf::Scene& scene, const std::string& camerasSource,
                     const std::string& camerasSourceText) {
  json j = reportHeader("sweep", a, scene);
  j["cameras_source"] = camerasSource;
  j["cameras_source_text"] = camerasSourceText;
  return j;
}

json sweepCameraJson(size_t globalIndex, const vf::Camera& cam, const vf::CameraResult& c) {
  json jc;
  jc["index"] = globalIndex;
  jc["eye"] = vec3Json(cam.eye);
  jc["target"] = vec3Json(cam.target);
  jc["done"] = c.done;
  if (!c.error.empty()) {
    jc["error"] = c.error;
    return jc;
  }
  jc["first_hole"] = c.hasHole ? holeJson(c.firstHole) : json(nullptr);
  jc["first_undecided"] = c.hasUndecided ? holeJson(c.firstUndecided) : json(nullptr);
  jc["stats"] = statsJson(c.stats);
  jc["worst"] = c.hasFinding ? findingJson(c.worst) : json(nullptr);
  jc["first_gpu_float"] = c.hasGpuFloat ? gpuFloatJson(c.firstGpuFloat) : json(nullptr);
  return jc;
}

json sweepSummaryJson(size_t requested, const vf::SweepResult& res, const std::vector<CauseRow>& causes,
                      const vf::WorkStats& terrainWork, bool countOffScreen) {
  json j;
  j["cameras_total"] = requested;
  j["cameras_done"] = res.camerasDone;
  j["cancelled"] = res.cancelled;
  if (res.cancelled) j["cameras_not_done"] = requested - res.camerasDone; // not listed one by one
  j["cameras_invalid"] = res.camerasInvalid;
  j["cameras_nothing_checked"] = res.camerasNothingChecked;
  j["cameras_undecided"] = res.camerasUndecided;
  j["cameras_gpu_float"] = res.camerasGpuFloat;
  j["stats"] = statsJson(res.total);
  j["verdict"] = vf::toString(vf::verdictOf(res, countOffScreen));
  json cs = json::array();
  for (const CauseRow& c : causes)
    cs.push_back({{"cause", c.cause}, {"cause_id", c.id}, {"fix", c.fix}, {"findings", c.findings},
                  {"cameras", c.cameras}, {"first_camera", c.firstCamera},
                  {"example", c.example}});
  j["causes"] = cs;
  j["visible_first"] = res.visibleFirst;
  j["result_cache"] = resultCacheJson(res);
  vf::WorkStats work = terrainWork;
  work += res.work;
  work.terrainBuilds = terrainWork.terrainBuilds;
  j["work"] = workJson(work);
  j["terrain_work"] = workJson(terrainWork);
  return j;
}

json resultCacheJson(const vf::SweepResult& res) {
  const vf::WorkStats& w = res.work;
  return {{"on", res.resultCache},
          {"off_reason", res.resultCache ? json(nullptr) : json(res.resultCacheOffKey)},
          {"off_reason_text", res.resultCache ? json(nullptr) : json(res.resultCacheOff)},
          {"hits", w.cacheHits},
          {"seam_hits", w.seamHits},
          {"misses", w.cacheMisses},
          {"seam_proofs", w.seamProofs},
          {"items", res.resultCacheItems},
          {"bytes", res.resultCacheBytes},
          {"dropped", res.resultCacheDropped}};
}

// "visible first (...)", "visible first on some shards (...)" or "full check (why)".
static std::string visibleFirstWords(const json& on, const vf::Stats& s, const std::string& fullCheckWhy) {
  const std::string counts = " (" + std::to_string(s.patchesOffScreen) + " patches, " +
                             std::to_string(s.edgesOffScreen) + " edge pairs off screen, not evaluated)";
  if (on.is_boolean() && on.get<bool>()) return "visible first" + counts;
  if (on.is_string()) return "visible first on some shards" + counts; // merged: "mixed"
  return "full check" + (fullCheckWhy.empty() ? std::string() : " (" + fullCheckWhy + ")");
}

// "result cache on (...)", "result cache on some shards (...)" or "result cache off: why".
static std::string resultCacheWords(const json& rc, const vf::Stats& s) {
  const json& on = rc.at("on");
  const bool some = on.is_string();
  if (!some && !on.get<bool>()) {
    const json& why = rc.at("off_reason_text");
    const std::string text = why.is_string() ? why.get<std::string>() : std::string();
    return "result cache off" + (text.empty() ? std::string() : ": " + text);
  }
  const int64_t hits = rc.at("hits").get<int64_t>(), seam = rc.at("seam_hits").get<int64_t>();
  // Hit rate: the pairs decided without evaluating their points, over the pairs classified (stats.edges_checked).
  char rate[32] = "-";
  if (s.edgesChecked > 0)
    std::snprintf(rate, sizeof rate, "%.1f %%", 100.0 * static_cast<double>(hits + seam) / static_cast<double>(s.edgesChecked));
  char buf[256];
  std::snprintf(buf, sizeof buf, " (%lld hits, %lld seam hits, hit rate %s, %lld items, %lld KiB, %lld dropped)",
                static_cast<long long>(hits), static_cast<long long>(seam), rate,
                static_cast<long long>(rc.at("items").get<int64_t>()),
                static_cast<long long>(rc.at("bytes").get<int64_t>() / 1024),
                static_cast<long long>(rc.at("dropped").get<int64_t>()));
  return (some ? "result cache on some shards" : "result cache on") + std::string(buf);
}

std::string shortcutsText(const json& visibleFirst, const json& resultCache, const vf::Stats& total,
                          const std::string& fullCheckWhy) {
  return "  shortcuts      " + visibleFirstWords(visibleFirst, total, fullCheckWhy) + "; " +
         resultCacheWords(resultCache, total) + "\n";
}

// dump(2) of a value nested `depth` levels deep: its continuation lines indented by 2 * depth more.
static std::string nested(const json& v, int depth) {
  const std::string text = v.dump(2), pad(static_cast<size_t>(2 * depth), ' ');
  std::string out;
  out.reserve(text.size() + text.size() / 8);
  for (char c : text) {
    out += c;
    if (c == '\n') out += pad;
  }
  return out;
}

static std::string members(const json& obj) {
  std::string out;
  bool first = true;
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    out += first ? "" : ",\n";
    first = false;
    out += "  " + json(it.key()).dump() + ": " + nested(it.value(), 1);
  }
  return out;
}

std::string sweepJsonBegin(const json& header) { return "{\n" + members(header) + ",\n  \"cameras\": ["; }

std::string sweepJsonCamera(const json& entry, bool first) { return (first ? "\n    " : ",\n    ") + nested(entry, 2); }

std::string sweepJsonEnd(const json& summary, bool anyCamera) {
  return std::string(anyCamera ? "\n  ]" : "]") + ",\n" + members(summary) + "\n}\n";
}

} // namespace fftess::cli
