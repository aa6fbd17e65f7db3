// The GPU path of the LOD in the cli. See gpu_lod.h.
#include "gpu_lod.h"
#include "common.h"
#include "causes.h"

#ifdef FFTESS_HAVE_GL
#include "gpu_lod/gpu_lod.h"
#endif

#include <cstdio>
#include <fstream>
#include <iterator>
#include <regex>

namespace fftess::cli {

static bool usesGpu(const vf::Scene& s) { return !s.lod.shader.empty() || s.lod.evaluate == vf::LodEvaluate::Gpu; }

void attachGpuLod(const vf::Terrain& terrain, const SceneArgs& a, vf::CheckOptions& opt) {
  const vf::Scene& scene = terrain.scene();
  if (!usesGpu(scene)) return;
  setShaderBlame(scene);
#ifdef FFTESS_HAVE_GL
  gpulod::GpuLodOptions o;
  o.hardware = a.gpuHardware;
  std::string error;
  gpulod::GpuLodError kind = gpulod::GpuLodError::None;
  auto p = gpulod::createGpuLod(vf::LodPatches(terrain), o, error, kind);
  if (!p) {
    // The log's lines first, one diagnostic per line as the compiler names file, line and column (an editor reads
    // them), then "fftess: error: WHAT". createGpuLod's message is "WHAT:\nLOG".
    std::string head = error, log;
    const size_t nl = error.find('\n');
    if (nl != std::string::npos) head = error.substr(0, nl), log = error.substr(nl + 1);
    while (!head.empty() && head.back() == ':') head.pop_back();
    const char* what = kind == gpulod::GpuLodError::NoContext ? "no OpenGL context for the GPU LOD: " : "";
    throw UsageError(what + head, log);
  }
  opt.factors = p;
#else
  (void)opt;
  (void)a;
  throw UsageError(a.scene + ": " + (scene.lod.shader.empty() ? "lod.evaluate = \"gpu\"" : "lod.shader") +
                   " needs the GPU path, and this fftess was built without OpenGL (EGL or GL/glcorearb.h not found; "
                   "install libegl-dev libgl-dev and rebuild)");
#endif
}

bool shaderReadsClamp(const vf::Scene& scene) {
  if (scene.lod.shader.empty()) return true;
  std::ifstream f(scene.lod.shader, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  static const std::regex lodMain(R"(\blodMain\s*\()"), clampMode(R"(\bclampMode\b)");
  return std::regex_search(text, lodMain) && std::regex_search(text, clampMode);
}

std::string neighbourRuleWords(const vf::Scene& scene) {
  if (!shaderReadsClamp(scene)) {
    const std::string& f = scene.lod.shader;
    return "lod.shader " + f.substr(f.find_last_of('/') == std::string::npos ? 0 : f.find_last_of('/') + 1) +
           " (its own neighbour rule)";
  }
  return std::string("lod.adjacency_clamp = ") + vf::toString(scene.lod.screenSphere.clamp) +
         (scene.lod.screenSphere.clamp == vf::AdjacencyClamp::Pow2 ? " (the power-of-two workaround on)" : "");
}

static const char* const kFactorNames[6] = {"Ueq0", "Veq0", "Ueq1", "Veq1", "insideU", "insideV"};

void FactorDiffTally::add(size_t camera, const vf::Report& r) {
  for (const vf::DenormalFactor& d : r.denormalFactors) {
    if (denormals_.size() >= 5) break;
    denormals_.push_back({camera, d});
  }
  for (const vf::FactorDiff& d : r.factorDiffs) {
    if (examples_.size() < 3) examples_.push_back({camera, d});
    if (d.changesTessellation && tessellation_.size() < 3) tessellation_.push_back({camera, d});
    if (examples_.size() >= 3 && tessellation_.size() >= 3) break;
  }
}

std::string FactorDiffTally::text(const vf::Scene& scene, const vf::CheckOptions& opt, const vf::Stats& total) const {
  std::string out;
  char buf[400];
  const vf::DenormalRule rule = vf::denormalRule(scene, opt);
  if (total.denormalFactors > 0) {
    std::snprintf(buf, sizeof buf, "  denormals      %lld hull factors are denormal; %s: %s\n",
                  static_cast<long long>(total.denormalFactors), rule.flush ? "flushed to zero" : "kept", rule.why.c_str());
    out += buf;
    for (const Denormal& d : denormals_) {
      std::snprintf(buf, sizeof buf, "denormal   camera #%zu %s %s %s (0x%s): %s\n", d.camera,
                    patchText(d.factor.patch).c_str(), kFactorNames[d.factor.factor], formatFloat(d.factor.value).c_str(),
                    hex8(d.factor.bits).c_str(),
                    !d.factor.flushed ? "kept (the clamp makes an outer factor the minimum tessellation)"
                    : d.factor.factor < 4 ? "flushed to zero: the tessellator discards the patch"
                                          : "flushed to zero (an inside factor: the minimum either way)");
      out += buf;
    }
  }
  if (!usesGpu(scene)) return out;
#ifdef FFTESS_HAVE_GL
  if (auto* p = dynamic_cast<const gpulod::GpuLodProvider*>(opt.factors.get())) {
    out += "  GPU LOD        " + p->description() + " on " + p->renderer() + "\n";
    const double per = p->dispatches() > 0 ? p->dispatchSeconds() / static_cast<double>(p->dispatches()) : 0.0;
    if (p->description().rfind("hull shader", 0) == 0)
      std::snprintf(buf, sizeof buf,
                    "                 %lld cameras drawn through the TCS, %.3f ms per camera (program build and the "
                    "patches' upload once: %.1f ms)\n",
                    static_cast<long long>(p->dispatches()), per * 1e3, p->compileSeconds() * 1e3);
    else
      std::snprintf(buf, sizeof buf,
                    "                 %lld dispatches, %.3f ms per camera (upload of the patches %s: %.1f ms, "
                    "program build: %.1f ms)\n",
                    static_cast<long long>(p->dispatches()), per * 1e3,
                    scene.layout.kind == vf::LayoutKind::Quadtree ? "of each camera's layout, in all" : "once",
                    p->uploadSeconds() * 1e3, p->compileSeconds() * 1e3);
    out += buf;
    if (p->cpuCameras() > 0) {
      std::snprintf(buf, sizeof buf, "                 the C++ build of the same factors: %.3f ms per camera (one thread)\n",
                    p->cpuSeconds() / static_cast<double>(p->cpuCameras()) * 1e3);
      out += buf;
    }
    out += std::string("                 denormal factors ") + (rule.flush ? "flushed to zero" : "kept") + ": " +
           rule.why + "\n";
  }
#else
  (void)opt;
#endif
  if (scene.lod.scheme == vf::LodScheme::Shader) {
    out += "  factor differs from the GPU build: not compared (lod.scheme = \"shader\": no C++ reference; set "
           "lod.scheme to a built-in scheme to compare)\n";
    return out;
  }
  const double share = total.factorsCompared > 0
                           ? 100.0 * static_cast<double>(total.factorDiffs) / static_cast<double>(total.factorsCompared)
                           : 0.0;
  std::snprintf(buf, sizeof buf,
                "  factor differs from the GPU build (C++ %s): %lld of %lld factors (%.4g %%), %lld of them change "
                "the tessellation\n",
                vf::toString(scene.lod.scheme), static_cast<long long>(total.factorDiffs),
                static_cast<long long>(total.factorsCompared), share,
                static_cast<long long>(total.factorDiffsTessellation));
  out += buf;
  auto line = [&](const Example& e) {
    std::snprintf(buf, sizeof buf, "    camera #%zu %s %s: GPU %s (0x%s), C++ %s (0x%s)%s\n", e.camera,
                  patchText(e.diff.patch).c_str(), kFactorNames[e.diff.factor], formatFloat(e.diff.gpu).c_str(),
                  hex8(e.diff.gpuBits).c_str(), formatFloat(e.diff.cpu).c_str(), hex8(e.diff.cpuBits).c_str(),
                  e.diff.changesTessellation ? ", changes the tessellation" : "");
    out += buf;
  };
  for (const Example& e : examples_) line(e);
  for (const Example& e : tessellation_) {
    bool seen = false;
    for (const Example& x : examples_) seen = seen || (x.camera == e.camera && x.diff.patch.index == e.diff.patch.index &&
                                                       x.diff.factor == e.diff.factor);
    if (!seen) line(e);
  }
  return out;
}

} // namespace fftess::cli
