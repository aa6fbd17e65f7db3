// The scene options of check and sweep: SCENE, --set and its shorthands, --kernel, --flush-denormals, --offscreen,
// --gpu-hardware, the --json / --svg reports and the verdict's exit status. Registration (addSceneOptions), loading
// the scene once per command (load), the checker's options (checkOptions), and the report files written all or nothing.
#pragma once

#include "commands.h"
#include "common.h"

#include "verify/verify.h"

#include <memory>
#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

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
// kExitFindings on cracks, holes, nothing checked, unchecked cameras (and T-junctions with failOnTJunctions: --fail-on-
// tjunctions); else kExitClean.
int verdictStatus(vf::Verdict v, bool failOnTJunctions);
// The same for a sweep (and merged shards): 130 when it was interrupted (Ctrl-C) before finding cracks or holes.
int sweepStatus(const vf::SweepResult& res, vf::Verdict v, bool failOnTJunctions);

// --json, --svg, --gltf and --view as refuseSameFiles outputs; the inputs of a scene: SCENE, and with the loaded scene the
// files it reads (lod.shader, displacement.file, layout.file). load() refuses reports that are one of those.
std::vector<FileArg> reportArgs(const SceneArgs& a);
std::vector<FileArg> sceneInputs(const SceneArgs& a, const vf::Scene* scene);

// The --json, --svg and --gltf reports (and check's --view) of one command: every path is checked when this is
// built (before the work: UsageError naming the path; --gltf's also names the option and refuses stdout), and
// commit() writes them all or nothing (AtomicFile, commitAll).
class ReportFiles {
public:
  explicit ReportFiles(const SceneArgs& a);
  void setJson(std::string text) { if (json_) json_->buffer() = std::move(text); }
  void setSvg(std::string text) { if (svg_) svg_->buffer() = std::move(text); }
  void setGltf(std::string bytes) { if (gltf_) gltf_->buffer() = std::move(bytes); }
  bool gltf() const { return gltf_ != nullptr; } // --gltf was given
  void dropGltf() { gltf_.reset(); } // the --gltf file is not written (its temporary file removed)
  void setView(std::string text) { if (view_) view_->buffer() = std::move(text); } // check --view
  AtomicFile* json() const { return json_.get(); } // null without --json (sweep streams into it)
  AtomicFile* svg() const { return svg_.get(); }   // null without --svg
  void setSarif(std::string text) { if (sarif_) sarif_->buffer() = std::move(text); } // --sarif (ci_scene.h)
  void setJunit(std::string text) { if (junit_) junit_->buffer() = std::move(text); } // --junit
  bool ci() const { return sarif_ || junit_; } // --sarif or --junit was given
  void commit();

private:
  std::unique_ptr<AtomicFile> json_, svg_;
  std::unique_ptr<AtomicFile> gltf_; // --gltf
  std::unique_ptr<AtomicFile> view_; // check --view
  std::unique_ptr<AtomicFile> sarif_, junit_; // --sarif, --junit
};

} // namespace fftess::cli
