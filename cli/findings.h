// Findings in words, for check and sweep: edge and patch names, the cause of a finding, one-line finding text, the
// stats block, and the scene options shared by both commands (loading with --set overrides, kernel, exit status).
#pragma once

#include "check.h"
#include "common.h"

#include "verify/verify.h"

#include <memory>
#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

const char* edgeName(int e);                          // Ueq0 Veq0 Ueq1 Veq1, "?" out of range
std::string patchText(const vf::PatchRef& p);         // "ring R tile T patch P"
std::string fmtWorld(double v);                       // %.3g

// Why a finding happened, printed from its records (the LOD's per side, the tessellator's): a short, stable key (the
// grouping key of sweep summaries: the size jump, the tessellator fact and the rule the LOD applied) and a longer
// explanation with the numbers of this finding and each side's LOD record (vf::lodWords).
struct Cause {
  std::string key;
  std::string detail;
};
Cause findingCause(const vf::Finding& f);

// One line: classification, both sides, gap, cause. Off screen (Finding::onScreen false): "off screen" after the
// classification. A crack on screen whose farthest vertex is not its worst on-screen one: the on-screen gap, then the
// farthest vertex's.
std::string findingLine(const vf::Finding& f);
// A hole's cause from its records: a short key (sweep grouping) and the explanation (factor bits, lod's record,
// the projection's w at the edge's midpoint, where the patch was seen).
Cause holeCause(const vf::Hole& h);
std::string holeLine(const vf::Hole& h);              // one line: "hole", the patch, the cause
// The indented stats block of check and sweep. countOffScreen (--offscreen): off-screen findings are counted (and
// said so), the worst gap is over all cracks; else the worst gap is the on-screen one and the off-screen findings
// are named apart, not counted.
std::string statsText(const vf::Stats& s, bool countOffScreen);
// The off-screen findings in words: "" when there are none; else e.g. "100 cracks off screen, not counted", and with
// explain ": the factors that made them belong to their camera, so no other camera sees them either (--offscreen
// counts them)".
std::string offScreenWords(const vf::Stats& s, bool countOffScreen, bool explain = false);
// The worst gap that counts (on screen, or with countOffScreen over all cracks): world units and pixels.
double countedGapWorld(const vf::Stats& s, bool countOffScreen);
double countedGapPixels(const vf::Stats& s, bool countOffScreen);
// The verdict line's words of a sweep (and of merged shards): cameras = the cameras asked for.
std::string verdictWords(vf::Verdict verdict, const vf::SweepResult& res, size_t crackCameras, size_t holeCameras,
                         size_t cameras, bool countOffScreen);

// Scene options shared by check and sweep.
std::vector<std::string> overridesOf(const SceneArgs& a); // --eye/--target as overrides, then every --set
// The scene with its --set overrides, prepared once for the whole command (vf::prepareTerrain); throws UsageError
// with the loader's message.
vf::Terrain load(const SceneArgs& a);
// A scene loader's message: the scene path it starts with stays whole, the rest (keys and values from the file or
// from --set, of any length) is cut like any token (printable()).
std::string loaderMessage(const std::string& scene, const std::string& error);
vf::CheckOptions checkOptions(const SceneArgs& a);        // --kernel, --flush-denormals, --offscreen
// The same, plus the GPU LOD provider the scene asks for (lod.shader, lod.evaluate = "gpu"; cli/gpu_lod.h).
vf::CheckOptions checkOptions(const SceneArgs& a, const vf::Terrain& terrain);
void addSceneOptions(CLI::App* sub, SceneArgs& a);
// kExitFindings on cracks, holes, nothing checked, unchecked cameras (and T-junctions if asked); else kExitClean.
int verdictStatus(const SceneArgs& a, vf::Verdict v);

// --json and --svg as refuseSameFiles outputs; the inputs of a scene: SCENE, and with the loaded scene the files it
// reads (lod.shader, displacement.file). load() refuses reports that are one of those.
std::vector<FileArg> reportArgs(const SceneArgs& a);
std::vector<FileArg> sceneInputs(const SceneArgs& a, const vf::Scene* scene);

// The --json and --svg reports of one command: both paths are checked when this is built (before the work:
// UsageError naming the path), and commit() writes both all or nothing (AtomicFile, commitAll).
class ReportFiles {
public:
  explicit ReportFiles(const SceneArgs& a);
  void setJson(std::string text) { if (json_) json_->buffer() = std::move(text); }
  void setSvg(std::string text) { if (svg_) svg_->buffer() = std::move(text); }
  void commit();

private:
  std::unique_ptr<AtomicFile> json_, svg_;
};

} // namespace fftess::cli
