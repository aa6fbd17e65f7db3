// The CI reports (ci_report.h) of check and sweep: each finding, hole, undecided patch and GPU float finding as a
// result at its scene file and the line of the scene key its fix names (Scene::keyLines; a key --set replaced or
// that the file leaves at its default: no line, said so), with its patches and edges as logical locations; check's
// test cases are its cause groups, sweep's its cameras (docs/ci.md has the mapping). States that are not clean and
// have no finding (nothing checked, an invalid camera, an interrupted sweep, --mesh disagreeing) are results too
// (JUnit <error>), never a passing case.
#pragma once

#include "ci_report.h"
#include "commands.h"

#include "verify/verify.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

// The file, the scene's key lines and the options that decide what counts.
struct SceneCiContext {
  std::string file;                        // SCENE as given
  std::map<std::string, int> keyLines;     // vf::Scene::keyLines
  std::map<std::string, std::string> set;  // --set (and --eye / --target) KEY -> "KEY=VALUE"
  bool offscreen = false, failOnTJunctions = false;
  SceneCiContext(const SceneArgs& a, const vf::Scene& scene);
};

// The scene key a fix names (the first "section.key = " in it; "" for none).
std::string fixKey(const std::string& fix);
// Points a result at the key its fix names: file, line, lineWhy and a logical location for the key.
void locateKey(const SceneCiContext& ctx, CiResult& x);

class ReportFiles;
// Puts the report as SARIF and JUnit into the --sarif / --junit files' buffers (written by ReportFiles::commit).
void setCiReports(ReportFiles& files, const CiReport& r);

// fftess check: one case per cause group, and the case "verdict" (an <error> when nothing was checked or --mesh
// disagrees; else passing, with what was checked as system-out).
CiReport checkCi(const SceneCiContext& ctx, const vf::Camera& cam, const vf::Report& r, vf::Verdict verdict,
                 bool meshAgrees, int status);

// fftess sweep: fed per camera (serialised, as SweepOptions::onReport / onCamera are); one case per camera checked,
// a result per cause on that camera (with the number of its findings there and the first one's place).
class SweepCi {
public:
  explicit SweepCi(SceneCiContext ctx) : ctx_(std::move(ctx)) {}
  void addReport(size_t camera, const vf::Report& r);
  void addCamera(size_t camera, const vf::CameraResult& c);
  // requested: the cameras asked for; eyeOf: a camera's eye and target in words.
  CiReport finish(const vf::SweepResult& res, vf::Verdict verdict, size_t requested, int status,
                  const std::function<std::string(size_t)>& cameraWords) const;

private:
  struct Camera {
    std::vector<CiResult> results; // one per cause, in the order of the report
    std::vector<int64_t> counts;
    bool done = false, reported = false;
    std::string error;
    vf::Stats stats;
  };
  SceneCiContext ctx_;
  std::map<size_t, Camera> cameras_;
};

} // namespace fftess::cli
