// fftess merge A.json B.json ...: the JSON reports of one sweep's shards (fftess sweep --shard K/N) merged into the
// report one unsharded run writes, byte for byte: cameras in global index order, stats summed (worst gaps the
// maxima), causes merged (the first camera by lowest global index, its example with it), the verdict recomputed with
// verify::verdictOf, the work summed with the terrain build counted once.
#include "causes.h"
#include "commands.h"
#include "common.h"
#include "report_json.h"
#include "scene_options.h"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace fftess::cli {

CLI::App* addMerge(CLI::App& app, MergeArgs& a) {
  CLI::App* sub = app.add_subcommand("merge", "Merge the JSON reports of a sweep's shards (sweep --shard K/N) into one");
  sub->footer("Examples:\n"
              "  fftess sweep docs/examples/terrain.toml --random 1000 --shard 1/2 --json s1.json\n"
              "  fftess sweep docs/examples/terrain.toml --random 1000 --shard 2/2 --json s2.json\n"
              "  fftess merge s1.json s2.json --json sweep.json\n"
              "Every shard 1..N of one sweep must be given once. The merged report equals the unsharded run's.\n"
              "Exit status: as sweep (0 watertight, 1 cracks, holes, nothing checked or unchecked cameras), 2 bad "
              "usage or input (not a sweep report of this version, shards of different sweeps or of different scene "
              "contents (scene_hash), a shard missing or given twice), 3 internal error.");
  sub->add_option("reports", a.inputs, "The shards' JSON reports")->required();
  sub->add_option("--json", a.json, "Write the merged report here ('-': stdout, and no text)");
  sub->add_flag("-q,--quiet", a.quiet, "No summary on stdout");
  sub->add_flag("--fail-on-tjunctions", a.failOnTJunctions, "Exit 1 on T-junctions too");
  return sub;
}

namespace {

json readReport(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UsageError("merge: cannot read " + quotePath(path));
  json j;
  try {
    j = json::parse(in);
  } catch (const std::exception& e) {
    throw UsageError("merge: " + quotePath(path) + ": not JSON (" + e.what() + ")");
  }
  if (!j.is_object() || j.value("kind", "") != "sweep")
    throw UsageError("merge: " + quotePath(path) + ": not a sweep report (\"kind\": \"sweep\")");
  if (j.value("version", 0) != kReportVersion)
    throw UsageError("merge: " + quotePath(path) + ": report version " + j.value("version", json(0)).dump() +
                     ", this fftess merges version " + std::to_string(kReportVersion));
  return j;
}

vf::Stats statsOf(const json& j) {
  vf::Stats s;
  s.patches = j.at("patches");
  s.culledPatches = j.at("culled_patches");
  s.edgesChecked = j.at("edges_checked");
  s.skippedCulled = j.at("skipped_culled");
  s.matches = j.at("matches");
  s.tJunctions = j.at("t_junctions");
  s.cracks = j.at("cracks");
  s.holes = j.at("holes");
  s.holesDiscarded = j.at("holes_discarded");
  s.holesCulledVisible = j.at("holes_culled_while_visible");
  s.culledUndecided = j.at("culled_undecided");
  s.visibilityTests = j.at("visibility_tests");
  s.denormalFactors = j.at("denormal_factors");
  s.worstGapWorld = j.at("worst_gap_world");
  s.worstGapPixels = j.at("worst_gap_pixels");
  s.cracksOffScreen = j.at("cracks_off_screen");
  s.tJunctionsOffScreen = j.at("t_junctions_off_screen");
  s.worstGapWorldOnScreen = j.at("worst_gap_world_on_screen");
  s.worstGapPixelsOnScreen = j.at("worst_gap_pixels_on_screen");
  s.undecided = j.at("undecided");
  s.patchesOffScreen = j.at("patches_off_screen");
  s.edgesOffScreen = j.at("edges_off_screen");
  s.gpuFloatPairs = j.value("gpu_float_pairs", int64_t(0));
  s.gpuFloatFindings = j.value("gpu_float_findings", int64_t(0));
  s.gpuModelFactors = j.value("gpu_model_factors", int64_t(0));
  s.gpuModelOutside = j.value("gpu_model_outside", int64_t(0));
  return s;
}

// The shards' common header: a shard's report without what differs between the shards of one sweep.
json mergeHeader(const json& shard) {
  json header = shard;
  for (const char* k : {"cameras", "shard", "cameras_total", "cameras_done", "cancelled", "cameras_not_done",
                        "cameras_invalid", "cameras_nothing_checked", "cameras_undecided", "cameras_gpu_float", "stats", "verdict",
                        "causes", "visible_first", "result_cache", "work", "terrain_work"})
    header.erase(k);
  return header;
}

// The scene's content first (Scene::contentHash: the file's bytes, the overrides, the files it names): the same
// path and overrides may have held another scene when a shard ran.
void checkSameScene(const MergeArgs& a, const std::vector<json>& shards) {
  const json hash0 = shards[0].value("scene_hash", json());
  for (size_t i = 1; i < shards.size(); ++i) {
    const json hash = shards[i].value("scene_hash", json());
    if (hash != hash0)
      throw UsageError("merge: " + quotePath(a.inputs[i]) + ": scene_hash " + hash.dump() + " differs from " +
                       quotePath(a.inputs[0]) + "'s " + hash0.dump() +
                       ": the shards ran on different contents of the scene (its file, --set overrides or the files it "
                       "names changed between the runs)");
  }
}

// One sweep: the same header (scene, overrides, cameras) in every report, shards 1..N each once (or one unsharded
// report).
void checkShardSet(const MergeArgs& a, const std::vector<json>& shards, const json& header) {
  size_t count = 0;
  std::vector<char> seen;
  for (size_t i = 0; i < shards.size(); ++i) {
    const json& h = shards[i];
    for (auto it = header.begin(); it != header.end(); ++it)
      if (h.value(it.key(), json()) != it.value())
        throw UsageError("merge: " + quotePath(a.inputs[i]) + ": \"" + it.key() + "\" differs from " +
                         quotePath(a.inputs[0]) + "'s: not a shard of the same sweep");
    const json shard = h.value("shard", json());
    if (shard.is_null()) {
      if (shards.size() != 1)
        throw UsageError("merge: " + quotePath(a.inputs[i]) + " is a whole sweep (no \"shard\"), not a shard");
      count = 1, seen.assign(1, 1);
      continue;
    }
    const size_t k = shard.at("index"), n = shard.at("count");
    if (i == 0) count = n, seen.assign(n, 0);
    if (n != count || k < 1 || k > n)
      throw UsageError("merge: " + quotePath(a.inputs[i]) + ": shard " + std::to_string(k) + "/" + std::to_string(n) +
                       " does not belong with " + std::to_string(count) + " shards");
    if (seen[k - 1]) throw UsageError("merge: shard " + std::to_string(k) + "/" + std::to_string(n) + " given twice");
    seen[k - 1] = 1;
  }
  for (size_t k = 0; k < count; ++k)
    if (!seen[k])
      throw UsageError("merge: shard " + std::to_string(k + 1) + "/" + std::to_string(count) + " missing");
}

// Cameras in global index order (each shard's list is already in order).
std::vector<const json*> mergedCameras(const std::vector<json>& shards) {
  std::vector<const json*> cams;
  for (const json& s : shards)
    for (const json& c : s.at("cameras")) cams.push_back(&c);
  std::stable_sort(cams.begin(), cams.end(),
                   [](const json* x, const json* y) { return x->at("index").get<size_t>() < y->at("index").get<size_t>(); });
  return cams;
}

// The summed result (total: the cameras asked for).
vf::SweepResult mergedResult(const std::vector<json>& shards, size_t& total) {
  vf::SweepResult res;
  total = 0;
  for (const json& s : shards) {
    total += s.at("cameras_total").get<size_t>();
    res.camerasDone += s.at("cameras_done").get<size_t>();
    res.camerasInvalid += s.at("cameras_invalid").get<size_t>();
    res.camerasNothingChecked += s.at("cameras_nothing_checked").get<size_t>();
    res.camerasUndecided += s.at("cameras_undecided").get<size_t>();
    res.camerasGpuFloat += s.value("cameras_gpu_float", size_t(0));
    res.cancelled = res.cancelled || s.at("cancelled").get<bool>();
    vf::accumulate(res.total, statsOf(s.at("stats")));
  }
  return res;
}

// Causes: per key the sums, the lowest first camera and its example; ordered by first camera, then by the order
// within the shard that holds it (the order of its first findings).
std::vector<CauseRow> mergedCauses(const std::vector<json>& shards) {
  struct MergedCause {
    CauseRow row;
    size_t position = 0;
  };
  std::map<std::string, MergedCause> causes;
  for (const json& s : shards) {
    size_t position = 0;
    for (const json& c : s.at("causes")) {
      const std::string key = c.at("cause");
      const size_t first = c.at("first_camera");
      auto [it, added] = causes.try_emplace(key);
      CauseRow& r = it->second.row;
      r.cause = key;
      r.findings += c.at("findings").get<int64_t>();
      r.cameras += c.at("cameras").get<size_t>();
      if (added || first < r.firstCamera) {
        r.firstCamera = first;
        r.example = c.at("example");
        r.fix = c.value("fix", std::string()); // reports written before "fix" existed have none
        r.id = c.at("cause_id");
        it->second.position = position;
      }
      ++position;
    }
  }
  std::vector<MergedCause> ordered;
  for (auto& kv : causes) ordered.push_back(kv.second);
  std::stable_sort(ordered.begin(), ordered.end(), [](const MergedCause& x, const MergedCause& y) {
    return x.row.firstCamera != y.row.firstCamera ? x.row.firstCamera < y.row.firstCamera : x.position < y.position;
  });
  std::vector<CauseRow> rows;
  for (const MergedCause& c : ordered) rows.push_back(c.row);
  return rows;
}

// Work: each shard's camera work (work - terrain_work), plus one terrain build's work.
json mergedWork(const std::vector<json>& shards) {
  json work = shards[0].at("terrain_work");
  for (const json& s : shards)
    for (auto it = work.begin(); it != work.end(); ++it)
      if (it.key() != "terrain_builds")
        it.value() = it.value().get<int64_t>() + s.at("work").at(it.key()).get<int64_t>() -
                     s.at("terrain_work").at(it.key()).get<int64_t>();
  return work;
}

// The shards' one value of a flag, or "mixed" when they differ (shards may run with and without a shortcut: the
// findings are the same).
json agreed(const std::vector<json>& values) {
  for (const json& v : values)
    if (v != values.front()) return "mixed";
  return values.front();
}

// The sweep shortcuts over the shards: visible_first, result_cache.on and off_reason as every shard says (else
// "mixed"), the cache's counters summed (each shard has its own cache: items, bytes and dropped add up too).
void mergeShortcuts(const std::vector<json>& shards, json& summary) {
  std::vector<json> visible, on, why, whyText;
  json rc = summary.at("result_cache"); // sweepSummaryJson's keys, in its order
  for (auto it = rc.begin(); it != rc.end(); ++it)
    if (it.value().is_number()) it.value() = 0;
  for (const json& s : shards) {
    visible.push_back(s.at("visible_first"));
    const json& c = s.at("result_cache");
    on.push_back(c.at("on"));
    why.push_back(c.at("off_reason"));
    whyText.push_back(c.at("off_reason_text"));
    for (auto it = rc.begin(); it != rc.end(); ++it)
      if (it.value().is_number()) it.value() = it.value().get<int64_t>() + c.at(it.key()).get<int64_t>();
  }
  rc["on"] = agreed(on);
  rc["off_reason"] = agreed(why);
  rc["off_reason_text"] = agreed(whyText);
  summary["visible_first"] = agreed(visible);
  summary["result_cache"] = rc;
}

// The text summary: what was merged, the stats block, the verdict line.
std::string mergeText(const std::vector<json>& shards, const json& header, const std::vector<const json*>& cams,
                      const vf::SweepResult& res, const json& summary, size_t total, vf::Verdict verdict,
                      bool countOffScreen) {
  size_t crackCameras = 0, holeCameras = 0;
  for (const json* c : cams) {
    if (!c->at("done").get<bool>()) continue;
    const json& st = c->at("stats");
    crackCameras += st.at("cracks").get<int64_t>() - (countOffScreen ? 0 : st.at("cracks_off_screen").get<int64_t>()) > 0;
    holeCameras += st.at("holes").get<int64_t>() > 0;
  }
  std::string text = "merged " + std::to_string(shards.size()) + " report(s) of " +
                     header.at("scene").at("file").get<std::string>() + " (" +
                     header.at("cameras_source_text").get<std::string>() + "): cameras " +
                     std::to_string(res.camerasDone) + " of " + std::to_string(total) +
                     (res.cancelled ? " (interrupted)" : "") + "\n";
  text += shortcutsText(summary.at("visible_first"), summary.at("result_cache"), res.total, "");
  text += statsText(res.total, countOffScreen);
  text += "verdict: " + verdictWords(verdict, res, crackCameras, holeCameras, total, countOffScreen) + "\n";
  return text;
}

} // namespace

int runMerge(const MergeArgs& a) {
  if (a.inputs.empty()) throw UsageError("merge: no reports");
  std::unique_ptr<AtomicFile> out;
  std::vector<FileArg> inputs;
  for (const std::string& p : a.inputs) inputs.push_back({"REPORT", p});
  refuseSameFiles({{"--json", a.json}}, inputs);
  if (!a.json.empty()) out = std::make_unique<AtomicFile>(a.json); // the path is checked before the work
  std::vector<json> shards;
  for (const std::string& p : a.inputs) shards.push_back(readReport(p));
  const json header = mergeHeader(shards[0]);
  checkSameScene(a, shards);
  checkShardSet(a, shards, header);
  const std::vector<const json*> cams = mergedCameras(shards);
  size_t total = 0;
  const vf::SweepResult res = mergedResult(shards, total);
  // --offscreen is part of the header (every shard the same): the merged verdict counts what the shards counted.
  const bool countOffScreen = header.value("offscreen", false);
  json summary = sweepSummaryJson(total, res, mergedCauses(shards), vf::WorkStats(), countOffScreen);
  summary["work"] = mergedWork(shards);
  summary["terrain_work"] = shards[0].at("terrain_work");
  mergeShortcuts(shards, summary);
  if (out) {
    out->stream(sweepJsonBegin(header));
    for (size_t i = 0; i < cams.size(); ++i) out->stream(sweepJsonCamera(*cams[i], i == 0));
    out->buffer() = sweepJsonEnd(summary, !cams.empty());
    out->commit();
  }
  const vf::Verdict verdict = vf::verdictOf(res, countOffScreen);
  if (!a.quiet && a.json != "-") {
    writeStdout(mergeText(shards, header, cams, res, summary, total, verdict, countOffScreen));
    flushStdout();
  }
  return sweepStatus(res, verdict, a.failOnTJunctions);
}

} // namespace fftess::cli
