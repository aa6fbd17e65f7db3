// JSON reports of check and sweep (schema: docs/cli.md, "JSON reports"). Pure functions of the reports: no I/O.
#pragma once

#include "check.h"
#include "findings.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace fftess::cli {

using json = nlohmann::ordered_json;

// "version" of the check and sweep JSON reports; bumped on any change of their schema (docs/cli.md).
// 2: the classification and cause keys spell T-junctions "t_junction" (version 1 wrote "t-junction").
// 3: per side "factor_bits" and "lod" (the LOD's own record), and "work" (the command's work counters).
constexpr int kReportVersion = 4; // 4: holes, verdicts nothing_checked / unchecked, invalid cameras

json vec3Json(const glm::vec3& v);
json findingJson(const vf::Finding& f);
json holeJson(const vf::Hole& h);
json lodJson(const vf::EdgeLod& l);   // one side's LOD record (docs/cli.md)
json workJson(const vf::WorkStats& w);
json statsJson(const vf::Stats& s);
json cameraJson(const vf::Camera& c);
json sceneJson(const SceneArgs& a, const vf::Scene& s);

// One entry of a sweep's cause table (sweep.cpp tallies them).
struct CauseRow {
  std::string cause;
  int64_t findings = 0;
  size_t cameras = 0;
  size_t firstCamera = 0;
  std::string example;
};

// The whole report of `fftess check` (mesh: null unless --mesh ran).
json checkJson(const SceneArgs& a, const vf::Terrain& terrain, const vf::Camera& cam, const vf::Report& r,
               const vf::MeshReport* mesh);
// The whole report of `fftess sweep`.
json sweepJson(const SceneArgs& a, const vf::Terrain& terrain, const std::string& camerasSource,
               const std::vector<vf::Camera>& cams, size_t requested, const vf::SweepResult& res,
               const std::vector<CauseRow>& causes); // requested: cameras asked for (more than cams if interrupted)

} // namespace fftess::cli
