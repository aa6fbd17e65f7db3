// The Vulkan entry points the capture uses, loaded at run time from the system's Vulkan loader (libvulkan.so.1,
// dlopen): fftess has no load-time dependency on Vulkan, a machine without the loader still runs every other
// command, and `driver-check --api vulkan` says the loader is missing. The loader itself finds the drivers (ICDs) in
// its standard places and honours VK_ICD_FILENAMES / VK_DRIVER_FILES; nothing here names a driver's path.
#pragma once

#ifndef VK_NO_PROTOTYPES
#define VK_NO_PROTOTYPES
#endif
#include <vulkan/vulkan.h>

#include <string>

namespace fftess {
namespace oracle {
namespace vk {

// Loader-level entry points (vkGetInstanceProcAddr with a null instance).
#define FFTESS_VK_GLOBAL_FUNCTIONS(X)                                                                                  \
  X(vkCreateInstance)                                                                                                  \
  X(vkEnumerateInstanceExtensionProperties)

// Instance-level (vkGetInstanceProcAddr with the instance). Vulkan 1.1 core: the *2 queries.
#define FFTESS_VK_INSTANCE_FUNCTIONS(X)                                                                                \
  X(vkDestroyInstance)                                                                                                 \
  X(vkEnumeratePhysicalDevices)                                                                                        \
  X(vkGetPhysicalDeviceProperties)                                                                                     \
  X(vkGetPhysicalDeviceProperties2)                                                                                    \
  X(vkGetPhysicalDeviceFeatures2)                                                                                      \
  X(vkGetPhysicalDeviceQueueFamilyProperties)                                                                          \
  X(vkGetPhysicalDeviceMemoryProperties)                                                                               \
  X(vkEnumerateDeviceExtensionProperties)                                                                              \
  X(vkCreateDevice)                                                                                                    \
  X(vkGetDeviceProcAddr)

// Device-level (vkGetDeviceProcAddr), VK_EXT_transform_feedback's commands included.
#define FFTESS_VK_DEVICE_FUNCTIONS(X)                                                                                  \
  X(vkDestroyDevice)                                                                                                   \
  X(vkGetDeviceQueue)                                                                                                  \
  X(vkDeviceWaitIdle)                                                                                                  \
  X(vkCreateBuffer)                                                                                                    \
  X(vkDestroyBuffer)                                                                                                   \
  X(vkGetBufferMemoryRequirements)                                                                                     \
  X(vkAllocateMemory)                                                                                                  \
  X(vkFreeMemory)                                                                                                      \
  X(vkBindBufferMemory)                                                                                                \
  X(vkMapMemory)                                                                                                       \
  X(vkInvalidateMappedMemoryRanges)                                                                                    \
  X(vkCreateShaderModule)                                                                                              \
  X(vkDestroyShaderModule)                                                                                             \
  X(vkCreateDescriptorSetLayout)                                                                                       \
  X(vkDestroyDescriptorSetLayout)                                                                                      \
  X(vkCreateDescriptorPool)                                                                                            \
  X(vkDestroyDescriptorPool)                                                                                           \
  X(vkAllocateDescriptorSets)                                                                                          \
  X(vkUpdateDescriptorSets)                                                                                            \
  X(vkCreatePipelineLayout)                                                                                            \
  X(vkDestroyPipelineLayout)                                                                                           \
  X(vkCreateRenderPass)                                                                                                \
  X(vkDestroyRenderPass)                                                                                               \
  X(vkCreateFramebuffer)                                                                                               \
  X(vkDestroyFramebuffer)                                                                                              \
  X(vkCreateGraphicsPipelines)                                                                                         \
  X(vkDestroyPipeline)                                                                                                 \
  X(vkCreateCommandPool)                                                                                               \
  X(vkDestroyCommandPool)                                                                                              \
  X(vkAllocateCommandBuffers)                                                                                          \
  X(vkBeginCommandBuffer)                                                                                              \
  X(vkEndCommandBuffer)                                                                                                \
  X(vkResetCommandBuffer)                                                                                              \
  X(vkCreateFence)                                                                                                     \
  X(vkDestroyFence)                                                                                                    \
  X(vkResetFences)                                                                                                     \
  X(vkWaitForFences)                                                                                                   \
  X(vkQueueSubmit)                                                                                                     \
  X(vkCreateQueryPool)                                                                                                 \
  X(vkDestroyQueryPool)                                                                                                \
  X(vkGetQueryPoolResults)                                                                                             \
  X(vkCmdResetQueryPool)                                                                                               \
  X(vkCmdBeginQuery)                                                                                                   \
  X(vkCmdEndQuery)                                                                                                     \
  X(vkCmdBeginRenderPass)                                                                                              \
  X(vkCmdEndRenderPass)                                                                                                \
  X(vkCmdBindPipeline)                                                                                                 \
  X(vkCmdBindDescriptorSets)                                                                                           \
  X(vkCmdDraw)                                                                                                         \
  X(vkCmdPipelineBarrier)                                                                                              \
  X(vkCmdBindTransformFeedbackBuffersEXT)                                                                              \
  X(vkCmdBeginTransformFeedbackEXT)                                                                                    \
  X(vkCmdEndTransformFeedbackEXT)

struct Functions {
  void* library = nullptr; // the dlopen handle of the loader
  std::string libraryName; // what was opened ("libvulkan.so.1", or the copy beside the executable)
  PFN_vkGetInstanceProcAddr vkGetInstanceProcAddr = nullptr;
  PFN_vkEnumerateInstanceVersion vkEnumerateInstanceVersion = nullptr; // null on a Vulkan 1.0 loader
#define FFTESS_VK_DECLARE(name) PFN_##name name = nullptr;
  FFTESS_VK_GLOBAL_FUNCTIONS(FFTESS_VK_DECLARE)
  FFTESS_VK_INSTANCE_FUNCTIONS(FFTESS_VK_DECLARE)
  FFTESS_VK_DEVICE_FUNCTIONS(FFTESS_VK_DECLARE)
#undef FFTESS_VK_DECLARE

  Functions() = default;
  Functions(const Functions&) = delete;
  Functions& operator=(const Functions&) = delete;
  ~Functions(); // closes the loader
};

// Opens the loader: "libvulkan.so.1" as the dynamic linker finds it (LD_LIBRARY_PATH, the system), else the copy
// beside the fftess executable (a prebuilt binary shipped with its loader). Loads the global entry points.
bool loadLoader(Functions& f, std::string& error);
// The instance-level and device-level entry points; false and 'error' naming the first missing one.
bool loadInstanceFunctions(Functions& f, VkInstance instance, std::string& error);
bool loadDeviceFunctions(Functions& f, VkDevice device, std::string& error);

// "VK_ERROR_DEVICE_LOST" etc. (the number for a code this build does not name).
std::string resultName(VkResult r);
// True for VK_SUCCESS; otherwise sets 'error' to "CALL failed: VK_ERROR_... (N)" and returns false.
bool succeeded(VkResult r, const char* call, std::string& error);

} // namespace vk
} // namespace oracle
} // namespace fftess
