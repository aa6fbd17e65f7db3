// The GPU path of the LOD: hull factors evaluated by the local OpenGL driver, one compute dispatch per camera, for
// verify's FactorProvider (verify.h). Target fftess_gpu_lod (gpu_lod/CMakeLists.txt, built only with EGL); the
// cli links it. docs/gpu_lod.md documents the shader interface, the buffers and the costs.
//
// What runs: the scene's lod.shader (GLSL 4.50, or HLSL through glslangValidator's HLSL front end to SPIR-V and
// spirv-cross back to GLSL 4.50) or, for lod.evaluate = "gpu", the built-in scheme's own lod/shaders/*.glsl with the
// scene's parameters; inside a compute shader that reads every patch's LodInput from one buffer (uploaded once per
// terrain) and the camera from another, and writes each patch's six factors and record.
// Threads: one GL context, made current by whichever sweep thread evaluates, under one mutex: GPU evaluations are
// serialised (the C++ checking of other cameras goes on meanwhile).
#pragma once

#include "verify/verify.h"

#include <cstdint>
#include <memory>
#include <string>

namespace fftess::gpulod {

struct GpuLodOptions {
  bool hardware = false; // prefer a GPU's EGL device (DeviceOrder::HardwareFirst); default: Mesa's llvmpipe first
};

enum class GpuLodError : uint8_t {
  None,
  NoContext, // no OpenGL 4.5 context (no EGL device, no llvmpipe)
  Shader,    // the shader does not compile or link, lacks the entry point, or has the wrong signature
  Tools,     // HLSL: glslangValidator or spirv-cross not found / failed to run
  Gl,        // a GL error outside the shader
};

class GpuLodProvider;

// Whether a driver flushes denormal hull factors to zero in its tessellation stage, by its GL_RENDERER string, and
// why (one line). Measured: Mesa's llvmpipe flushes (a denormal outer factor culls the patch; docs/oracle.md,
// `fftess driver-check`); NVIDIA keeps them like the D3D11 reference (306,348 patches, docs/oracle.md). Any other
// renderer is not measured and is assumed to flush: then a denormal outer factor culls the patch and the check reports
// the hole where it is in view (--flush-denormals=off or lod.flush_denormals = false checks the other rule).
bool flushesDenormalsFor(const std::string& renderer, std::string* why = nullptr);

// Compiles the scene's GPU LOD for this terrain (patches.scene(): lod.shader or lod.scheme with lod.evaluate =
// "gpu"). Null with error and kind set on failure; error names the file and line for a shader error, as the
// driver's or glslang's log gives it.
std::shared_ptr<GpuLodProvider> createGpuLod(const verify::LodPatches& patches, const GpuLodOptions& options,
                                             std::string& error, GpuLodError& kind);

class GpuLodProvider : public verify::FactorProvider {
public:
  ~GpuLodProvider() override;
  bool evaluate(const verify::LodPatches& patches, const lod::Camera& camera, std::vector<lod::PatchLod>& out,
                std::string& error) override;

  void noteCpuSeconds(double seconds) override;
  // The driver's denormal rule, from GL_RENDERER (flushesDenormalsFor).
  bool flushesDenormals(std::string* why = nullptr) const override;
  // The C++ reference of the same cameras (verify's computeFactors, one thread each): cameras and seconds.
  int64_t cpuCameras() const;
  double cpuSeconds() const;

  const std::string& renderer() const;     // GL_RENDERER
  const std::string& version() const;      // GL_VERSION
  const std::string& description() const; // what runs: "lod.shader FILE (GLSL)", "built-in distance_pow2 (GLSL)"
  // Timing, all cameras so far: dispatches, seconds in the locked region per camera (camera upload, dispatch, wait,
  // read back, conversion), seconds of the one-time input upload, seconds to build the program.
  int64_t dispatches() const;
  double dispatchSeconds() const;
  double uploadSeconds() const;
  double compileSeconds() const;

  struct Impl;
  explicit GpuLodProvider(std::unique_ptr<Impl> impl);

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace fftess::gpulod
