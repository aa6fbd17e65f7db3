// A headless Vulkan device for the capture (vk_capture.h): instance, the chosen physical device, one graphics queue,
// host-visible buffers, GLSL compiled to SPIR-V with glslang. No surface, no window system.
#pragma once

#include "vk_functions.h"

#include <cstdint>
#include <string>
#include <vector>

namespace fftess {
namespace oracle {
namespace vk {

// A Vulkan structure with its sType, every other member zero.
template <class T>
T structure(VkStructureType type) {
  T t{};
  t.sType = type;
  return t;
}

// A buffer in host-visible, host-coherent memory, mapped for its whole life.
struct Buffer {
  VkBuffer buffer = VK_NULL_HANDLE;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  void* mapped = nullptr;
  VkDeviceSize size = 0;
};

// What the capture needs of a physical device; why a device was passed over is said in create()'s error.
struct Requirements {
  VkDeviceSize captureBytes = 0; // the transform feedback buffer's size (maxTransformFeedbackBufferSize)
};

class Device {
public:
  Device() = default;
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;
  ~Device();

  // Opens the loader, creates a Vulkan 1.1 instance and a device with tessellation and VK_EXT_transform_feedback
  // (transform feedback queries too). Device order: the CPU devices first (lavapipe, the reference), or with
  // hardwareFirst the others first (a GPU); the first that has everything is taken. False and 'error' (the Vulkan
  // call and its VkResult, or each device and what it lacks) when none.
  bool create(bool hardwareFirst, const Requirements& req, std::string& error);

  // VkPhysicalDeviceProperties::deviceName, and "Vulkan A.B.C, DRIVER INFO" (driver name and info where the device
  // gives them, VK_KHR_driver_properties / Vulkan 1.2, else the raw driverVersion).
  const std::string& name() const { return name_; }
  const std::string& version() const { return version_; }
  bool isCpu() const { return cpu_; } // VK_PHYSICAL_DEVICE_TYPE_CPU (lavapipe)

  bool createBuffer(VkDeviceSize size, VkBufferUsageFlags usage, Buffer& out, std::string& error);
  void destroyBuffer(Buffer& b);
  // A shader module from GLSL (Vulkan dialect) compiled with glslang; 'stage' 0 vertex, 1 tessellation control,
  // 2 tessellation evaluation. The error names the stage and carries glslang's log.
  bool shaderModule(const std::string& glsl, int stage, VkShaderModule& out, std::string& error);
  // Submits one command buffer and waits for it (a bounded wait: a hung device is an error, not a hang).
  bool submitAndWait(VkCommandBuffer cmd, std::string& error);

  Functions f;
  VkInstance instance = VK_NULL_HANDLE;
  VkPhysicalDevice physical = VK_NULL_HANDLE;
  VkDevice device = VK_NULL_HANDLE;
  VkQueue queue = VK_NULL_HANDLE;
  uint32_t queueFamily = 0;
  VkCommandPool commandPool = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;

private:
  bool createInstance(std::string& error);
  bool createLogicalDevice(bool portabilitySubset, std::string& error);
  uint32_t memoryType(uint32_t typeBits) const; // host-visible and coherent, cached preferred; ~0u if none
  std::string name_, version_;
  bool cpu_ = false;
};

// GLSL (#version 450, Vulkan rules) to SPIR-V 1.3 for Vulkan 1.1 with glslang; 'stage' as in Device::shaderModule.
bool compileGlsl(const std::string& glsl, int stage, std::vector<uint32_t>& spirv, std::string& error);

} // namespace vk
} // namespace oracle
} // namespace fftess
