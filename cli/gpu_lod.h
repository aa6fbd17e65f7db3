// The GPU path of the LOD in the cli (lod.shader, lod.evaluate = "gpu"; docs/gpu_lod.md): building the provider
// (gpu_lod/gpu_lod.h, when fftess_gl is built) and the report section "factor differs from the GPU build".
#pragma once

#include "commands.h"

#include "verify/verify.h"

#include <string>
#include <vector>

namespace fftess::cli {

namespace vf = fftess::verify;

// Attaches the GPU factor provider the scene asks for to opt.factors (nothing when it asks for none). UsageError
// (exit 2) when the shader does not compile or link, lacks lodMain or has the wrong signature (the message names the
// file and line from the driver's or glslang's log), when no OpenGL 4.5 context exists, when HLSL tools are
// missing, or when fftess was built without EGL.
void attachGpuLod(const vf::Terrain& terrain, const SceneArgs& a, vf::CheckOptions& opt);

// Whether the scene's factors read lod.adjacency_clamp: a built-in scheme does; a lodMain shader when its text uses
// settings.clampMode; a hull shader as written never (it has its own rule; fftess does not state a clamp for it).
bool shaderReadsClamp(const vf::Scene& scene);
// The summary's headline of the neighbour rule: "lod.adjacency_clamp = pow2 (the power-of-two workaround on)", or
// for a shader that does not read it "lod.shader FILE (its own neighbour rule)".
std::string neighbourRuleWords(const vf::Scene& scene);

// The factor differences of a command, for the text report: counts from the summed stats, the first examples kept.
class FactorDiffTally {
public:
  void add(size_t camera, const vf::Report& r);
  // The denormal factors (any factor source: "denormal" lines with patch, factor and bits, and the rule that
  // decided whether they were flushed); then "" when the scene does not use the GPU path, else what ran, where, its
  // cost per camera, the driver's denormal rule, and (with a C++ reference) the section "factor differs from the GPU
  // build".
  std::string text(const vf::Scene& scene, const vf::CheckOptions& opt, const vf::Stats& total) const;

private:
  struct Example {
    size_t camera;
    vf::FactorDiff diff;
  };
  struct Denormal {
    size_t camera;
    vf::DenormalFactor factor;
  };
  std::vector<Example> examples_;
  std::vector<Example> tessellation_;
  std::vector<Denormal> denormals_; // the first few denormal factors (any factor source)
};

} // namespace fftess::cli
