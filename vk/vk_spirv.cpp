// GLSL to SPIR-V for the capture's pipelines (vk_device.h compileGlsl), with glslang linked as a library (the same
// glslang the GPU LOD path links): the shaders are generated per (domain, spacing, capture) at run time, like the GL
// oracle's, so no build-time shader tool and no generated files.
#include "vk_device.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <mutex>

namespace fftess {
namespace oracle {
namespace vk {

bool compileGlsl(const std::string& glsl, int stage, std::vector<uint32_t>& spirv, std::string& error) {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
  const EShLanguage lang = stage == 0 ? EShLangVertex : stage == 1 ? EShLangTessControl : EShLangTessEvaluation;
  const char* stageName = stage == 0 ? "vertex" : stage == 1 ? "tessellation control" : "tessellation evaluation";
  glslang::TShader shader(lang);
  const char* text = glsl.c_str();
  shader.setStrings(&text, 1);
  shader.setEnvInput(glslang::EShSourceGlsl, lang, glslang::EShClientVulkan, 100);
  shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
  shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
  const EShMessages messages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);
  if (!shader.parse(GetDefaultResources(), 450, ECoreProfile, false, false, messages)) {
    error = std::string("glslang: the capture's ") + stageName +
            " shader does not compile (fftess's problem): " + shader.getInfoLog();
    return false;
  }
  glslang::TProgram program;
  program.addShader(&shader);
  if (!program.link(messages)) {
    error = std::string("glslang: the capture's ") + stageName + " shader does not link: " + program.getInfoLog();
    return false;
  }
  spirv.clear();
  glslang::GlslangToSpv(*program.getIntermediate(lang), spirv);
  return true;
}

} // namespace vk
} // namespace oracle
} // namespace fftess
