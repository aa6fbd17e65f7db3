// The scene options of check and sweep (scene_options.h): registration, loading with --set overrides, check options,
// report files, exit status.
#include "scene_options.h"
#include "common.h"
#include "options.h"
#include "gpu_lod.h"

#include <CLI/CLI.hpp>

#include <algorithm>

namespace fftess::cli {

// ---- scene loading -----------------------------------------------------------------------------------------------
std::vector<std::string> overridesOf(const SceneArgs& a) {
  std::vector<std::string> o;
  auto vec = [](const std::string& opt, const std::string& v) {
    std::string t = v;
    std::replace(t.begin(), t.end(), ';', ',');
    if (t.empty() || t.front() != '[') t = "[" + t + "]";
    (void)opt;
    return t;
  };
  if (!a.eye.empty()) o.push_back("camera.eye=" + vec("--eye", a.eye));
  if (!a.target.empty()) o.push_back("camera.target=" + vec("--target", a.target));
  o.insert(o.end(), a.overrides.begin(), a.overrides.end());
  for (const std::string& s : a.overrides)
    if (s.find('=') == std::string::npos || s.front() == '=')
      throw UsageError("--set " + quoteToken(s) + ": expected KEY=VALUE (e.g. --set lod.adjacency_clamp=none)");
  return o;
}

// The loader names --eye / --target as the overrides they become ("--set camera.eye: ..."): name the option given.
static std::string shorthandNamed(const SceneArgs& a, std::string error) {
  const std::pair<const char*, const std::string*> opts[] = {{"eye", &a.eye}, {"target", &a.target}};
  for (const auto& [key, value] : opts) {
    const std::string prefix = std::string("--set camera.") + key + ": ";
    bool viaSet = false;
    for (const std::string& o : a.overrides) viaSet = viaSet || o.rfind(std::string("camera.") + key + "=", 0) == 0;
    if (!value->empty() && !viaSet && error.rfind(prefix, 0) == 0)
      error = "--" + std::string(key) + " " + *value + ": " + error.substr(prefix.size());
  }
  return error;
}

std::string loaderMessage(const std::string& scene, const std::string& error) {
  if (error.compare(0, scene.size(), scene) == 0) return printable(scene, std::string::npos) + printable(error.substr(scene.size()));
  return printable(error);
}

vf::Terrain load(const SceneArgs& a) {
  vf::SceneResult r = vf::loadScene(a.scene, overridesOf(a));
  if (!r)
    throw UsageError(r.error.empty() ? "cannot load scene " + quotePath(a.scene)
                                     : loaderMessage(a.scene, shorthandNamed(a, r.error)));
  refuseSameFiles(reportArgs(a), sceneInputs(a, &r.scene)); // the files the scene reads are inputs too
  vf::TerrainResult t = vf::prepareTerrain(r.scene);
  if (!t) throw UsageError(loaderMessage(a.scene, a.scene + ": " + t.error));
  return t.terrain;
}

vf::CheckOptions checkOptions(const SceneArgs& a) {
  vf::CheckOptions o;
  if (!vf::parseKernel(a.kernel.c_str(), o.kernel))
    throw UsageError(choiceError("--kernel", a.kernel, {"epick", "epeck", "float"}));
  const std::string& fd = a.flushDenormals;
  if (fd == "on" || fd == "true") o.flushDenormals = vf::DenormalFlush::On;
  else if (fd == "off" || fd == "false") o.flushDenormals = vf::DenormalFlush::Off;
  else if (fd == "auto") o.flushDenormals = vf::DenormalFlush::Auto;
  else // the value goes after '=' (the bare flag is "on"): said as it is given
    throw UsageError("--flush-denormals=" + quoteToken(fd) + ": expected on|off|auto" + didYouMeanText(fd, {"on", "off", "auto"}));
  o.countOffScreen = a.offscreen;
  if (a.gpuFloat == "conformant") o.gpuFloat = vf::GpuFloat::Conformant;
  else if (a.gpuFloat != "off") throw UsageError(choiceError("--gpu-float", a.gpuFloat, {"off", "conformant"}));
  return o;
}

vf::CheckOptions checkOptions(const SceneArgs& a, const vf::Terrain& terrain) {
  vf::CheckOptions o = checkOptions(a);
  if (o.gpuFloat == vf::GpuFloat::Conformant) {
    const std::string why = vf::gpuFloatRefusal(terrain.scene());
    if (!why.empty()) throw UsageError(why);
  }
  attachGpuLod(terrain, a, o);
  return o;
}

// ---- shared plumbing ---------------------------------------------------------------------------------------------
std::vector<FileArg> reportArgs(const SceneArgs& a) {
  return {{"--json", a.json}, {"--svg", a.svg}, {"--gltf", a.gltf}, {"--view", a.view}, {"--sarif", a.sarif},
          {"--junit", a.junit}};
}

std::vector<FileArg> sceneInputs(const SceneArgs& a, const vf::Scene* scene) {
  std::vector<FileArg> in{{"SCENE", a.scene}, {"--cameras", a.cameras}};
  if (!scene) return in;
  in.push_back({"(the scene's lod.shader)", scene->lod.shader});
  const std::string& raw = scene->displacement.file; // relative to the scene file's folder
  if (!raw.empty()) {
    const size_t slash = a.scene.find_last_of('/');
    const std::string dir = slash == std::string::npos ? "." : a.scene.substr(0, slash + 1);
    in.push_back({"(the scene's displacement.file)", raw.front() == '/' ? raw : dir + "/" + raw});
  }
  if (scene->layout.kind == vf::LayoutKind::Patches) in.push_back({"(the scene's layout.file)", scene->layout.file});
  return in;
}

// --gltf's file: binary (or glTF JSON text, by the name), never stdout; a bad path names the option.
static std::unique_ptr<AtomicFile> gltfFile(const std::string& path) {
  if (path == "-") throw UsageError("--gltf -: a glTF file cannot go to stdout; give a file name (e.g. view.glb)");
  try {
    return std::make_unique<AtomicFile>(path);
  } catch (const UsageError& e) {
    throw UsageError(std::string("--gltf: ") + e.what());
  }
}

// --sarif / --junit: a file checked now (a bad path names the option); null when not given.
static std::unique_ptr<AtomicFile> ciFile(const char* option, const std::string& path) {
  if (path.empty()) return nullptr;
  if (path == "-") throw UsageError(std::string(option) + " -: stdout carries the text or --json report; give a file");
  try {
    return std::make_unique<AtomicFile>(path);
  } catch (const UsageError& e) {
    throw UsageError(std::string(option) + ": " + e.what());
  }
}

ReportFiles::ReportFiles(const SceneArgs& a) {
  refuseSameFiles(reportArgs(a), sceneInputs(a, nullptr));
  if (!a.json.empty()) json_ = std::make_unique<AtomicFile>(a.json);
  if (!a.svg.empty()) svg_ = std::make_unique<AtomicFile>(a.svg);
  if (!a.gltf.empty()) gltf_ = gltfFile(a.gltf);
  try {
    if (!a.view.empty()) view_ = std::make_unique<AtomicFile>(a.view);
  } catch (const UsageError& e) {
    throw UsageError(std::string("--view: ") + e.what());
  }
  sarif_ = ciFile("--sarif", a.sarif);
  junit_ = ciFile("--junit", a.junit);
}

void ReportFiles::commit() {
  AtomicFile* files[6];
  size_t n = 0;
  if (json_) files[n++] = json_.get();
  if (svg_) files[n++] = svg_.get();
  if (gltf_) files[n++] = gltf_.get();
  if (view_) files[n++] = view_.get();
  if (sarif_) files[n++] = sarif_.get();
  if (junit_) files[n++] = junit_.get();
  commitAll(files, n);
}

int verdictStatus(vf::Verdict v, bool failOnTJunctions) {
  switch (v) {
  case vf::Verdict::Watertight: return kExitClean;
  case vf::Verdict::TJunctionsOnly: return failOnTJunctions ? kExitFindings : kExitClean;
  default: return kExitFindings;
  }
}

int sweepStatus(const vf::SweepResult& res, vf::Verdict v, bool failOnTJunctions) {
  const bool gaps = v == vf::Verdict::Cracks || v == vf::Verdict::Holes;
  return res.cancelled && !gaps ? 130 : verdictStatus(v, failOnTJunctions);
}

void addSceneOptions(CLI::App* sub, SceneArgs& a) {
  sub->add_option("scene", a.scene, "Scene file (TOML, docs/verify.md)")->required();
  sub->add_option("--set", a.overrides, "Override a scene key: KEY=VALUE (repeatable), validated like the file")
      ->type_name("KEY=VALUE");
  sub->add_option("--eye", a.eye, "Camera eye X,Y,Z (shorthand for --set camera.eye=[X,Y,Z])");
  sub->add_option("--target", a.target, "Camera target X,Y,Z (shorthand for --set camera.target=[X,Y,Z])");
  sub->add_option("--kernel", a.kernel, "CGAL kernel: epick (exact predicates), epeck (exact gaps too), float (naive, wrong on purpose)")
      ->capture_default_str();
  sub->add_flag("--flush-denormals{on}", a.flushDenormals,
                "Denormal hull factors: =on flushed to zero (as llvmpipe; bare flag), =off kept (the D3D11 reference, "
                "NVIDIA), =auto (default) the scene's lod.flush_denormals, else the GPU driver's rule");
  sub->add_option("--json", a.json, "Write the full report as JSON to FILE ('-': stdout, no text then)");
  sub->add_option("--svg", a.svg, "Write an SVG picture to FILE");
  sub->add_option("--gltf", a.gltf,
                  "Write the checked camera's view in 3D to FILE (binary glTF; a name ending in .gltf: glTF JSON): the "
                  "terrain as tessellated, findings coloured, the camera; sweep: the worst camera's");
  sub->add_flag("-q,--quiet", a.quiet, "Print nothing but errors; the exit status tells the verdict");
  sub->add_flag("--fail-on-tjunctions", a.failOnTJunctions, "Exit 1 on T-junctions too (default: cracks only)");
  sub->add_flag("--offscreen", a.offscreen,
                "Count cracks and T-junctions outside the view frustum too (whole-mesh comparisons, strict CI); "
                "default: only what the camera sees counts");
  sub->add_option("--cameras", a.cameras,
                  "Cameras from FILE: CSV with a header (eye_x,eye_y,eye_z,target_x,target_y,target_z; optional up_x,"
                  "up_y,up_z,fov_y,near,far,width,height,convention) or, for FILE.json, a JSON array of objects with "
                  "those fields; what a camera leaves out comes from the scene's [camera] (docs/cli.md)")
      ->type_name("FILE");
  sub->add_option("--gpu-float", a.gpuFloat,
                  "off (default) | conformant: also evaluate each matching shared edge under every choice a "
                  "conformant GPU compiler may make (a*b+c fused or not, the spec's error bounds of /, sqrt, exp2, "
                  "log2, pow) and report edges whose match depends on it (\"may crack on some GPUs\"; exit 1); "
                  "built-in lod.scheme on the CPU path only (docs/verify.md, \"GPU float freedom\")")
      ->type_name("off|conformant");
  sub->add_option("--sarif", a.sarif,
                  "Write the findings as SARIF 2.1.0 to FILE (code scanning: each at the scene key its fix names, "
                  "patch and edge; docs/ci.md)")
      ->type_name("FILE");
  sub->add_option("--junit", a.junit,
                  "Write JUnit XML to FILE (check: a test case per cause; sweep: per camera; docs/ci.md)")
      ->type_name("FILE");
  sub->add_flag("--gpu-hardware", a.gpuHardware,
                "lod.shader / lod.evaluate = \"gpu\": use a GPU's EGL device (default: Mesa's llvmpipe first)");
}

} // namespace fftess::cli
