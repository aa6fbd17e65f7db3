// The draws of the Vulkan capture (vk_draw.h).
#include "vk_draw.h"

#include <algorithm>
#include <cstring>

namespace fftess {
namespace oracle {
namespace vk {

namespace {

// The domain origin of every pipeline, chosen explicitly (VkPipelineTessellationDomainOriginStateCreateInfo): upper
// left, Vulkan's default and what DXVK and vkd3d-proton use, with which D3D11 triangle_cw is SPIR-V VertexOrderCw
// (established on lavapipe, which runs the reference tessellator: docs/oracle.md "Vulkan").
constexpr VkTessellationDomainOrigin kDomainOrigin = VK_TESSELLATION_DOMAIN_ORIGIN_UPPER_LEFT;

const char* kVertexShader = R"(#version 450
void main() { gl_Position = vec4(0.0); }
)";

// Factors arrive as raw bits so NaN payloads, denormals and exact values reach the fixed-function unit untouched.
// The draw's patches are the buffer's, in order: gl_PrimitiveID (the patch within the draw) indexes them.
const char* kControlShader = R"(#version 450
layout(vertices = 1) out;
layout(std430, set = 0, binding = 0) readonly buffer Factors { uint factorBits[]; };
void main() {
  uint b = uint(gl_PrimitiveID) * 6u;
  gl_TessLevelOuter[0] = uintBitsToFloat(factorBits[b + 0u]);
  gl_TessLevelOuter[1] = uintBitsToFloat(factorBits[b + 1u]);
  gl_TessLevelOuter[2] = uintBitsToFloat(factorBits[b + 2u]);
  gl_TessLevelOuter[3] = uintBitsToFloat(factorBits[b + 3u]);
  gl_TessLevelInner[0] = uintBitsToFloat(factorBits[b + 4u]);
  gl_TessLevelInner[1] = uintBitsToFloat(factorBits[b + 5u]);
  gl_out[gl_InvocationID].gl_Position = vec4(0.0);
}
)";

// Every evaluation shader invocation writes one record: the coordinate's bits and its patch within the draw.
std::string evaluationShader(const PipelineKey& k) {
  std::string layout = k.domain == Domain::Quad ? "quads" : k.domain == Domain::Tri ? "triangles" : "isolines";
  layout += k.spacing == 0   ? ", equal_spacing"
            : k.spacing == 1 ? ", fractional_odd_spacing"
                             : ", fractional_even_spacing";
  if (k.capture == Capture::TrianglesCw) layout += ", cw";
  if (k.capture == Capture::TrianglesCcw) layout += ", ccw";
  if (k.capture == Capture::Points) layout += ", point_mode";
  return "#version 450\nlayout(" + layout + ") in;\n" +
         "layout(location = 0, xfb_buffer = 0, xfb_offset = 0, xfb_stride = " + std::to_string(kRecordWords * 4) +
         ") out uvec4 cap;\n"
         "void main() {\n"
         "  cap = uvec4(floatBitsToUint(gl_TessCoord.xy), uint(gl_PrimitiveID), 0u);\n"
         "  gl_Position = vec4(0.0);\n"
         "}\n";
}

} // namespace

int verticesPerRecord(Capture c) { return c == Capture::Points ? 1 : c == Capture::Lines ? 2 : 3; }

Drawer::~Drawer() {
  if (!dev_.device) return;
  Functions& f = dev_.f;
  f.vkDeviceWaitIdle(dev_.device);
  for (auto& kv : pipelines_) f.vkDestroyPipeline(dev_.device, kv.second, nullptr);
  if (vertex_) f.vkDestroyShaderModule(dev_.device, vertex_, nullptr);
  if (control_) f.vkDestroyShaderModule(dev_.device, control_, nullptr);
  if (query_) f.vkDestroyQueryPool(dev_.device, query_, nullptr);
  if (framebuffer_) f.vkDestroyFramebuffer(dev_.device, framebuffer_, nullptr);
  if (renderPass_) f.vkDestroyRenderPass(dev_.device, renderPass_, nullptr);
  if (layout_) f.vkDestroyPipelineLayout(dev_.device, layout_, nullptr);
  if (pool_) f.vkDestroyDescriptorPool(dev_.device, pool_, nullptr);
  if (setLayout_) f.vkDestroyDescriptorSetLayout(dev_.device, setLayout_, nullptr);
  dev_.destroyBuffer(factors_);
  dev_.destroyBuffer(capture_);
}

bool Drawer::create(int maxPatches, int captureVertices, std::string& error) {
  maxPatches_ = maxPatches, captureVertices_ = captureVertices;
  Functions& f = dev_.f;
  if (!dev_.createBuffer(VkDeviceSize(maxPatches) * kFactorWords * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, factors_,
                         error) ||
      !dev_.createBuffer(VkDeviceSize(captureVertices) * kRecordWords * 4,
                         VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT, capture_, error))
    return false;
  if (!createLayout(error) || !createRenderPass(error)) return false;
  VkCommandBufferAllocateInfo cai{};
  cai.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
  cai.commandPool = dev_.commandPool;
  cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  cai.commandBufferCount = 1;
  if (!succeeded(f.vkAllocateCommandBuffers(dev_.device, &cai, &cmd_), "vkAllocateCommandBuffers", error)) return false;
  VkQueryPoolCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
  qci.queryType = VK_QUERY_TYPE_TRANSFORM_FEEDBACK_STREAM_EXT;
  qci.queryCount = 1;
  if (!succeeded(f.vkCreateQueryPool(dev_.device, &qci, nullptr, &query_), "vkCreateQueryPool", error)) return false;
  return dev_.shaderModule(kVertexShader, 0, vertex_, error) && dev_.shaderModule(kControlShader, 1, control_, error);
}

// The factor buffer as storage buffer 0 of set 0, seen by the tessellation control shader.
bool Drawer::createLayout(std::string& error) {
  Functions& f = dev_.f;
  VkDescriptorSetLayoutBinding binding{};
  binding.binding = 0;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  binding.descriptorCount = 1;
  binding.stageFlags = VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
  VkDescriptorSetLayoutCreateInfo lci{};
  lci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
  lci.bindingCount = 1;
  lci.pBindings = &binding;
  if (!succeeded(f.vkCreateDescriptorSetLayout(dev_.device, &lci, nullptr, &setLayout_), "vkCreateDescriptorSetLayout",
                 error))
    return false;
  VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1};
  VkDescriptorPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
  pci.maxSets = 1;
  pci.poolSizeCount = 1;
  pci.pPoolSizes = &size;
  if (!succeeded(f.vkCreateDescriptorPool(dev_.device, &pci, nullptr, &pool_), "vkCreateDescriptorPool", error))
    return false;
  VkDescriptorSetAllocateInfo sai{};
  sai.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
  sai.descriptorPool = pool_;
  sai.descriptorSetCount = 1;
  sai.pSetLayouts = &setLayout_;
  if (!succeeded(f.vkAllocateDescriptorSets(dev_.device, &sai, &set_), "vkAllocateDescriptorSets", error)) return false;
  VkDescriptorBufferInfo info{factors_.buffer, 0, VK_WHOLE_SIZE};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set_;
  write.dstBinding = 0;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = &info;
  f.vkUpdateDescriptorSets(dev_.device, 1, &write, 0, nullptr);
  VkPipelineLayoutCreateInfo plci{};
  plci.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
  plci.setLayoutCount = 1;
  plci.pSetLayouts = &setLayout_;
  return succeeded(f.vkCreatePipelineLayout(dev_.device, &plci, nullptr, &layout_), "vkCreatePipelineLayout", error);
}

// A render pass and framebuffer without attachments: the draws rasterize nothing (rasterizer discard).
bool Drawer::createRenderPass(std::string& error) {
  Functions& f = dev_.f;
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  VkRenderPassCreateInfo rci{};
  rci.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
  rci.subpassCount = 1;
  rci.pSubpasses = &subpass;
  if (!succeeded(f.vkCreateRenderPass(dev_.device, &rci, nullptr, &renderPass_), "vkCreateRenderPass", error))
    return false;
  VkFramebufferCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  fci.renderPass = renderPass_;
  fci.width = fci.height = fci.layers = 1;
  return succeeded(f.vkCreateFramebuffer(dev_.device, &fci, nullptr, &framebuffer_), "vkCreateFramebuffer", error);
}

VkPipeline Drawer::pipeline(const PipelineKey& key, std::string& error) {
  auto it = pipelines_.find(key);
  if (it != pipelines_.end()) return it->second;
  VkShaderModule evaluation = VK_NULL_HANDLE;
  if (!dev_.shaderModule(evaluationShader(key), 2, evaluation, error)) return VK_NULL_HANDLE;
  VkPipelineShaderStageCreateInfo stages[3]{};
  const VkShaderStageFlagBits bits[3] = {VK_SHADER_STAGE_VERTEX_BIT, VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT,
                                         VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT};
  const VkShaderModule modules[3] = {vertex_, control_, evaluation};
  for (int i = 0; i < 3; ++i) {
    stages[i].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[i].stage = bits[i];
    stages[i].module = modules[i];
    stages[i].pName = "main";
  }
  auto vertexInput =
      structure<VkPipelineVertexInputStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO);
  auto assembly =
      structure<VkPipelineInputAssemblyStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO);
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  auto origin = structure<VkPipelineTessellationDomainOriginStateCreateInfo>(
      VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_DOMAIN_ORIGIN_STATE_CREATE_INFO);
  origin.domainOrigin = kDomainOrigin;
  auto tess =
      structure<VkPipelineTessellationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO);
  tess.pNext = &origin;
  tess.patchControlPoints = 1;
  // Viewport and multisample state are ignored under rasterizer discard; given anyway, valid, for strict drivers.
  const VkViewport viewport{0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
  const VkRect2D scissor{{0, 0}, {1, 1}};
  auto viewportState =
      structure<VkPipelineViewportStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO);
  viewportState.viewportCount = viewportState.scissorCount = 1;
  viewportState.pViewports = &viewport;
  viewportState.pScissors = &scissor;
  auto raster =
      structure<VkPipelineRasterizationStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO);
  raster.rasterizerDiscardEnable = VK_TRUE;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;
  auto multisample =
      structure<VkPipelineMultisampleStateCreateInfo>(VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO);
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
  auto pci = structure<VkGraphicsPipelineCreateInfo>(VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO);
  pci.stageCount = 3;
  pci.pStages = stages;
  pci.pVertexInputState = &vertexInput;
  pci.pInputAssemblyState = &assembly;
  pci.pTessellationState = &tess;
  pci.pViewportState = &viewportState;
  pci.pRasterizationState = &raster;
  pci.pMultisampleState = &multisample;
  pci.layout = layout_;
  pci.renderPass = renderPass_;
  VkPipeline pipe = VK_NULL_HANDLE;
  const VkResult r = dev_.f.vkCreateGraphicsPipelines(dev_.device, VK_NULL_HANDLE, 1, &pci, nullptr, &pipe);
  dev_.f.vkDestroyShaderModule(dev_.device, evaluation, nullptr);
  if (!succeeded(r, "vkCreateGraphicsPipelines", error)) return VK_NULL_HANDLE;
  return pipelines_.emplace(key, pipe).first->second;
}

// The draw's commands: query reset, the draw under transform feedback and the stream query, then the captured
// vertices made visible to the host.
bool Drawer::record(VkPipeline pipe, int count, VkDeviceSize captureBytes) {
  Functions& f = dev_.f;
  auto begin = structure<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  if (f.vkResetCommandBuffer(cmd_, 0) != VK_SUCCESS || f.vkBeginCommandBuffer(cmd_, &begin) != VK_SUCCESS) return false;
  f.vkCmdResetQueryPool(cmd_, query_, 0, 1);
  auto rp = structure<VkRenderPassBeginInfo>(VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO);
  rp.renderPass = renderPass_;
  rp.framebuffer = framebuffer_;
  rp.renderArea = VkRect2D{{0, 0}, {1, 1}};
  f.vkCmdBeginRenderPass(cmd_, &rp, VK_SUBPASS_CONTENTS_INLINE);
  f.vkCmdBindPipeline(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipe);
  f.vkCmdBindDescriptorSets(cmd_, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_, 0, 1, &set_, 0, nullptr);
  const VkDeviceSize offset = 0, size = captureBytes;
  f.vkCmdBindTransformFeedbackBuffersEXT(cmd_, 0, 1, &capture_.buffer, &offset, &size);
  f.vkCmdBeginQuery(cmd_, query_, 0, 0); // stream 0
  f.vkCmdBeginTransformFeedbackEXT(cmd_, 0, 0, nullptr, nullptr);
  f.vkCmdDraw(cmd_, static_cast<uint32_t>(count), 1, 0, 0); // one control point per patch
  f.vkCmdEndTransformFeedbackEXT(cmd_, 0, 0, nullptr, nullptr);
  f.vkCmdEndQuery(cmd_, query_, 0);
  f.vkCmdEndRenderPass(cmd_);
  auto barrier = structure<VkMemoryBarrier>(VK_STRUCTURE_TYPE_MEMORY_BARRIER);
  barrier.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT;
  barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  f.vkCmdPipelineBarrier(cmd_, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier,
                         0, nullptr, 0, nullptr);
  return f.vkEndCommandBuffer(cmd_) == VK_SUCCESS;
}

bool Drawer::draw(const PipelineKey& key, const uint32_t* factors, int count, int roomVertices,
                  std::vector<uint32_t>& records, std::string& error) {
  records.clear();
  if (count <= 0) return true;
  roomVertices = std::max(1, std::min(roomVertices, captureVertices_));
  if (count > maxPatches_) {
    error = "internal: a draw of " + std::to_string(count) + " patches, above the " + std::to_string(maxPatches_) +
            " the factor buffer holds";
    return false;
  }
  const VkPipeline pipe = pipeline(key, error);
  if (!pipe) return false;
  std::memcpy(factors_.mapped, factors, size_t(count) * kFactorWords * 4);
  if (!record(pipe, count, VkDeviceSize(roomVertices) * kRecordWords * 4)) {
    error = "recording the draw's command buffer failed (vkBeginCommandBuffer / vkEndCommandBuffer)";
    return false;
  }
  if (!dev_.submitAndWait(cmd_, error)) return false;
  ++drawCalls;
  uint64_t counts[2] = {0, 0}; // primitives written, primitives needed
  if (!succeeded(dev_.f.vkGetQueryPoolResults(dev_.device, query_, 0, 1, sizeof counts, counts, sizeof counts,
                                              VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
                 "vkGetQueryPoolResults", error))
    return false;
  const uint64_t perPrim = static_cast<uint64_t>(verticesPerRecord(key.capture));
  if (counts[1] != counts[0] || counts[0] * perPrim > static_cast<uint64_t>(roomVertices)) {
    error = "transform feedback overflow: " + std::to_string(counts[1]) + " primitives needed, " +
            std::to_string(counts[0]) + " written (room for " + std::to_string(roomVertices / perPrim) + ")";
    return false;
  }
  const size_t words = static_cast<size_t>(counts[0] * perPrim) * kRecordWords;
  records.resize(words);
  if (words) std::memcpy(records.data(), capture_.mapped, words * 4);
  return true;
}

} // namespace vk
} // namespace oracle
} // namespace fftess
