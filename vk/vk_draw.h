// The draws of the Vulkan capture (vk_capture.h): one graphics pipeline per (domain, spacing, what is captured),
// a render pass without attachments, rasterizer discard, the tessellation evaluation shader's output captured with
// VK_EXT_transform_feedback, a transform feedback stream query to prove nothing was dropped. Internal to vk/.
#pragma once

#include "vk_device.h"

#include "gl/gl_capture.h" // oracle::Domain

#include <map>
#include <tuple>

namespace fftess {
namespace oracle {
namespace vk {

// What a pipeline captures. Triangle pipelines name the SPIR-V vertex order of their evaluation shader
// (VertexOrderCw / VertexOrderCcw), under the domain origin the pipelines use (vk_draw.cpp, kDomainOrigin).
enum class Capture : uint8_t { Points, TrianglesCw, TrianglesCcw, Lines };

int verticesPerRecord(Capture c); // 1 points, 2 lines, 3 triangles

struct PipelineKey {
  Domain domain = Domain::Quad;
  int spacing = 0; // glSpacing: 0 equal, 1 fractional_odd, 2 fractional_even
  Capture capture = Capture::Points;
  bool operator<(const PipelineKey& o) const {
    return std::tie(domain, spacing, capture) < std::tie(o.domain, o.spacing, o.capture);
  }
};

// Words per captured vertex: u bits, v bits, patch id within the draw (gl_PrimitiveID), 0.
constexpr int kRecordWords = 4;
// Factor words per patch in the storage buffer, GL/Vulkan slot order: outer[0..3], inner[0..1].
constexpr int kFactorWords = 6;

class Drawer {
public:
  explicit Drawer(Device& device) : dev_(device) {}
  Drawer(const Drawer&) = delete;
  Drawer& operator=(const Drawer&) = delete;
  ~Drawer();

  // The fixed objects: factor buffer for maxPatches patches, transform feedback buffer for captureVertices
  // vertices, render pass, descriptor set, command buffer, query pool, the vertex and control shaders.
  bool create(int maxPatches, int captureVertices, std::string& error);

  // One draw of 'count' patches (count <= maxPatches) whose factors are factors[0 .. count*kFactorWords), through the
  // pipeline of 'key', with room for roomVertices captured vertices (at most captureVertices: only that much of the
  // transform feedback buffer is bound; lavapipe's per-draw cost grows with the bound size). 'records' gets the
  // captured vertices (kRecordWords each, verticesPerRecord(key.capture) per primitive, in the driver's order).
  // Fails on any Vulkan error and on a transform feedback overflow (the stream query's primitives needed above
  // primitives written).
  bool draw(const PipelineKey& key, const uint32_t* factors, int count, int roomVertices,
            std::vector<uint32_t>& records, std::string& error);

  int drawCalls = 0;

private:
  bool createLayout(std::string& error);
  bool createRenderPass(std::string& error);
  VkPipeline pipeline(const PipelineKey& key, std::string& error);
  bool record(VkPipeline pipe, int count, VkDeviceSize captureBytes);

  Device& dev_;
  int maxPatches_ = 0, captureVertices_ = 0;
  Buffer factors_, capture_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  VkCommandBuffer cmd_ = VK_NULL_HANDLE;
  VkQueryPool query_ = VK_NULL_HANDLE;
  VkShaderModule vertex_ = VK_NULL_HANDLE, control_ = VK_NULL_HANDLE;
  std::map<PipelineKey, VkPipeline> pipelines_;
};

} // namespace vk
} // namespace oracle
} // namespace fftess
