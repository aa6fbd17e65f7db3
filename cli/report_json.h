// JSON reports of check and sweep (schema: docs/cli.md, "JSON reports"). Pure functions of the reports: no I/O.
#pragma once

#include "commands.h"

#include "verify/verify.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

using json = nlohmann::ordered_json;

// "version" of the check and sweep JSON reports; bumped on any change of their schema (docs/cli.md).
// 2: the classification and cause keys spell T-junctions "t_junction" (version 1 wrote "t-junction").
// 3: per side "factor_bits" and "lod" (the LOD's own record), and "work" (the command's work counters).
// 4: holes, verdicts nothing_checked / unchecked, invalid cameras.
// 5: sweep: "cameras" streamed before the summary (written as each camera finishes, in index order), "shard" (with
//    --shard), "terrain_work" (the terrain build's part of "work", so shards merge); work counters
//    full_tessellations, shared_edge_points, visibility_evaluations.
// 8: the sweep shortcuts: "visible_first" and "result_cache" in the sweep summary, "patches_off_screen" and
//    "edges_off_screen" in every "stats", work counters cache_hits, seam_hits, cache_misses, seam_proofs, box_tests.
// 9: --gpu-float: "gpu_float_mode" ("off" | "conformant") in the header, "gpu_float_pairs" and "gpu_float_findings" in
//    every "stats", check: "gpu_float" (the GPU float findings), sweep: "first_gpu_float" per camera and
//    "cameras_gpu_float" in the summary; verdict "gpu_float".
// 10: the envelope of every report kind (docs/schema): "cameras_source" is a key (scene_path | flyover | orbit |
//    random | file) and its words moved to "cameras_source_text"; result_cache.off_reason is a key (option |
//    camera_dependent_effect | keep_matches, "mixed" when merged shards differ) and its words moved to
//    "off_reason_text"; "cause_id" (the cause as a key of a fixed set, cli/causes.h) next to every "cause" (findings,
//    holes, undecided patches, GPU float findings, sweep's causes). prove's report (kind "prove") shares this version.
constexpr int kReportVersion = 10;

json vec3Json(const glm::vec3& v);
json gpuFloatJson(const vf::GpuFloatFinding& g); // one GPU float finding (--gpu-float conformant)
json findingJson(const vf::Finding& f);
json holeJson(const vf::Hole& h);
json denormalJson(const vf::DenormalFactor& d); // a denormal hull factor: patch, factor, value, bits, flushed
json lodJson(const vf::EdgeLod& l);   // one side's LOD record (docs/cli.md)
json workJson(const vf::WorkStats& w);
json statsJson(const vf::Stats& s);
// A sweep's result cache (vf::SweepResult, its work counters): {"on", "off_reason" (a key, null when on),
// "off_reason_text" (its words, null when on), "hits",
// "seam_hits", "misses", "seam_proofs", "items", "bytes", "dropped"}.
json resultCacheJson(const vf::SweepResult& res);
// The summary line of the sweep shortcuts ("  shortcuts      visible first (...); result cache on (...)\n") from the
// summary's "visible_first" and "result_cache" (a sweep's, or merged: true, false or "mixed") and its stats.
// fullCheckWhy: why visible first did not run, when the cli knows ("--offscreen", "--no-visible-first"; "" else).
std::string shortcutsText(const json& visibleFirst, const json& resultCache, const vf::Stats& total,
                          const std::string& fullCheckWhy);
json cameraJson(const vf::Camera& c);
json sceneJson(const SceneArgs& a, const vf::Scene& s);

// One entry of a sweep's cause table (sweep.cpp tallies them).
struct CauseRow {
  std::string cause;
  int64_t findings = 0;
  size_t cameras = 0;
  size_t firstCamera = 0;
  std::string example;
  std::string fix; // the first finding's Cause::fix
  std::string id;  // Cause::id (JSON "cause_id")
};

// The whole report of `fftess check` (mesh: null unless --mesh ran).
json checkJson(const SceneArgs& a, const vf::Terrain& terrain, const vf::Camera& cam, const vf::Report& r,
               const vf::MeshReport* mesh);
// The sweep report, written in three parts so that its cameras stream to the file as they finish (memory does not
// grow with the camera count), and so that `fftess merge` writes exactly the text one run writes:
//   sweepJsonBegin(header)   "{" and the header members, then the opening of "cameras";
//   sweepJsonCamera(entry)   one camera (first: whether it is the first one written);
//   sweepJsonEnd(summary)    the end of "cameras" and the summary members, "}" and a newline.
// The concatenation equals ordered_json{header..., "cameras": [entries...], summary...}.dump(2) + "\n".
// camerasSource: the key (scene_path, flyover, orbit, random, file); camerasSourceText: the same in words.
json sweepHeaderJson(const SceneArgs& a, const vf::Scene& scene, const std::string& camerasSource,
                     const std::string& camerasSourceText);
json sweepCameraJson(size_t globalIndex, const vf::Camera& cam, const vf::CameraResult& c);
// The summary: cameras_total .. work (requested: cameras asked for, more than checked if interrupted; countOffScreen:
// --offscreen, the verdict counts findings outside the view frustum).
json sweepSummaryJson(size_t requested, const vf::SweepResult& res, const std::vector<CauseRow>& causes,
                      const vf::WorkStats& terrainWork, bool countOffScreen);
std::string sweepJsonBegin(const json& header);
std::string sweepJsonCamera(const json& entry, bool first);
std::string sweepJsonEnd(const json& summary, bool anyCamera);

} // namespace fftess::cli
