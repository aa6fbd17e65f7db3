// The headless Vulkan device of the capture (vk_device.h).
#include "vk_device.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace fftess {
namespace oracle {
namespace vk {

namespace {

constexpr uint64_t kFenceTimeoutNs = 120ull * 1000 * 1000 * 1000; // one draw; far above any real one

std::string versionText(uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

bool hasExtension(const std::vector<VkExtensionProperties>& list, const char* name) {
  return std::any_of(list.begin(), list.end(),
                     [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

const char* deviceTypeName(VkPhysicalDeviceType t) {
  switch (t) {
  case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return "integrated GPU";
  case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return "discrete GPU";
  case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return "virtual GPU";
  case VK_PHYSICAL_DEVICE_TYPE_CPU: return "CPU";
  default: return "other";
  }
}

// A physical device and what the capture would use of it.
struct Candidate {
  VkPhysicalDevice device = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties props{};
  uint32_t queueFamily = 0;
  bool portabilitySubset = false; // VK_KHR_portability_subset listed: it must be enabled (MoltenVK)
  std::string lacks;              // empty: usable
};

// What 'c' lacks for the capture ("" when nothing).
std::string lacksOf(const Functions& f, Candidate& c, const Requirements& req) {
  if (c.props.apiVersion < VK_API_VERSION_1_1) return "Vulkan " + versionText(c.props.apiVersion) + " (1.1 needed)";
  uint32_t n = 0;
  f.vkEnumerateDeviceExtensionProperties(c.device, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  if (n) f.vkEnumerateDeviceExtensionProperties(c.device, nullptr, &n, exts.data());
  exts.resize(n);
  if (!hasExtension(exts, VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME)) return "no VK_EXT_transform_feedback";
  c.portabilitySubset = hasExtension(exts, "VK_KHR_portability_subset");
  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{};
  xfb.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &xfb;
  f.vkGetPhysicalDeviceFeatures2(c.device, &features);
  if (!features.features.tessellationShader) return "no tessellationShader feature";
  if (!xfb.transformFeedback) return "no transformFeedback feature";
  VkPhysicalDeviceTransformFeedbackPropertiesEXT xfbProps{};
  xfbProps.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_PROPERTIES_EXT;
  VkPhysicalDeviceProperties2 props{};
  props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
  props.pNext = &xfbProps;
  f.vkGetPhysicalDeviceProperties2(c.device, &props);
  if (!xfbProps.transformFeedbackQueries) return "no transform feedback queries (transformFeedbackQueries)";
  if (xfbProps.maxTransformFeedbackBufferSize < req.captureBytes)
    return "maxTransformFeedbackBufferSize " + std::to_string(xfbProps.maxTransformFeedbackBufferSize) + " < " +
           std::to_string(req.captureBytes);
  uint32_t families = 0;
  f.vkGetPhysicalDeviceQueueFamilyProperties(c.device, &families, nullptr);
  std::vector<VkQueueFamilyProperties> fam(families);
  if (families) f.vkGetPhysicalDeviceQueueFamilyProperties(c.device, &families, fam.data());
  for (uint32_t i = 0; i < families; ++i)
    if (fam[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) {
      c.queueFamily = i;
      return "";
    }
  return "no graphics queue";
}

} // namespace

Device::~Device() {
  if (device && f.vkDeviceWaitIdle) { // the device's functions are loaded
    f.vkDeviceWaitIdle(device);
    if (fence) f.vkDestroyFence(device, fence, nullptr);
    if (commandPool) f.vkDestroyCommandPool(device, commandPool, nullptr);
  }
  if (device && f.vkDestroyDevice) f.vkDestroyDevice(device, nullptr);
  if (instance && f.vkDestroyInstance) f.vkDestroyInstance(instance, nullptr);
}

bool Device::createInstance(std::string& error) {
  if (!loadLoader(f, error)) return false;
  uint32_t loaderVersion = VK_API_VERSION_1_0;
  if (f.vkEnumerateInstanceVersion &&
      !succeeded(f.vkEnumerateInstanceVersion(&loaderVersion), "vkEnumerateInstanceVersion", error))
    return false;
  if (loaderVersion < VK_API_VERSION_1_1) {
    error = "the Vulkan loader " + f.libraryName + " is Vulkan " + versionText(loaderVersion) + "; 1.1 is needed";
    return false;
  }
  uint32_t n = 0;
  f.vkEnumerateInstanceExtensionProperties(nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  if (n) f.vkEnumerateInstanceExtensionProperties(nullptr, &n, exts.data());
  exts.resize(n);
  // Portability drivers (MoltenVK) are listed only when the application says it can take them.
  const bool portability = hasExtension(exts, "VK_KHR_portability_enumeration");
  const char* portabilityExt = "VK_KHR_portability_enumeration";
  VkApplicationInfo app{};
  app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
  app.pApplicationName = "fftess driver-check";
  app.apiVersion = VK_API_VERSION_1_1;
  VkInstanceCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
  ci.pApplicationInfo = &app;
  if (portability) {
    ci.flags = VK_INSTANCE_CREATE_ENUMERATE_PORTABILITY_BIT_KHR;
    ci.enabledExtensionCount = 1;
    ci.ppEnabledExtensionNames = &portabilityExt;
  }
  const VkResult r = f.vkCreateInstance(&ci, nullptr, &instance);
  if (!succeeded(r, "vkCreateInstance", error)) {
    if (r == VK_ERROR_INCOMPATIBLE_DRIVER)
      error += ": the loader found no Vulkan 1.1 driver (none installed, or VK_ICD_FILENAMES / VK_DRIVER_FILES name "
               "none that loads); install mesa-vulkan-drivers for lavapipe";
    return false;
  }
  return loadInstanceFunctions(f, instance, error);
}

bool Device::create(bool hardwareFirst, const Requirements& req, std::string& error) {
  if (!createInstance(error)) return false;
  uint32_t n = 0;
  if (!succeeded(f.vkEnumeratePhysicalDevices(instance, &n, nullptr), "vkEnumeratePhysicalDevices", error))
    return false;
  std::vector<VkPhysicalDevice> devices(n);
  if (n) { // VK_INCOMPLETE: a device went away between the calls; the n written are valid
    const VkResult r = f.vkEnumeratePhysicalDevices(instance, &n, devices.data());
    if (r != VK_INCOMPLETE && !succeeded(r, "vkEnumeratePhysicalDevices", error)) return false;
  }
  devices.resize(n);
  if (devices.empty()) {
    error = "the Vulkan loader found no device (no driver installed, or VK_ICD_FILENAMES / VK_DRIVER_FILES name none "
            "that loads); install mesa-vulkan-drivers for lavapipe";
    return false;
  }
  std::vector<Candidate> cands(devices.size());
  for (size_t i = 0; i < devices.size(); ++i) {
    cands[i].device = devices[i];
    f.vkGetPhysicalDeviceProperties(devices[i], &cands[i].props);
    cands[i].lacks = lacksOf(f, cands[i], req);
  }
  // The CPU devices (lavapipe) first by default; the others first with hardwareFirst. Stable: the loader's order.
  std::stable_sort(cands.begin(), cands.end(), [&](const Candidate& a, const Candidate& b) {
    const bool ca = a.props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU,
               cb = b.props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
    return hardwareFirst ? (!ca && cb) : (ca && !cb);
  });
  auto chosen = std::find_if(cands.begin(), cands.end(), [](const Candidate& c) { return c.lacks.empty(); });
  if (chosen == cands.end()) {
    error = "no Vulkan device can run the capture:";
    for (const Candidate& c : cands)
      error +=
          std::string(" '") + c.props.deviceName + "' (" + deviceTypeName(c.props.deviceType) + "): " + c.lacks + ";";
    error.pop_back();
    return false;
  }
  physical = chosen->device;
  queueFamily = chosen->queueFamily;
  cpu_ = chosen->props.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  name_ = chosen->props.deviceName;
  version_ = "Vulkan " + versionText(chosen->props.apiVersion);
  if (chosen->props.apiVersion >= VK_API_VERSION_1_2) {
    VkPhysicalDeviceDriverProperties driver{};
    driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
    VkPhysicalDeviceProperties2 props{};
    props.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
    props.pNext = &driver;
    f.vkGetPhysicalDeviceProperties2(physical, &props);
    version_ += std::string(", ") + driver.driverName + " " + driver.driverInfo;
  } else {
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%08x", chosen->props.driverVersion);
    version_ += std::string(", driver version ") + hex;
  }
  return createLogicalDevice(chosen->portabilitySubset, error);
}

bool Device::createLogicalDevice(bool portabilitySubset, std::string& error) {
  const float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{};
  qci.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
  qci.queueFamilyIndex = queueFamily;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkPhysicalDeviceTransformFeedbackFeaturesEXT xfb{};
  xfb.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_TRANSFORM_FEEDBACK_FEATURES_EXT;
  xfb.transformFeedback = VK_TRUE;
  VkPhysicalDeviceFeatures2 features{};
  features.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
  features.pNext = &xfb;
  features.features.tessellationShader = VK_TRUE;
  std::vector<const char*> exts = {VK_EXT_TRANSFORM_FEEDBACK_EXTENSION_NAME};
  if (portabilitySubset) exts.push_back("VK_KHR_portability_subset");
  VkDeviceCreateInfo dci{};
  dci.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
  dci.pNext = &features;
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = static_cast<uint32_t>(exts.size());
  dci.ppEnabledExtensionNames = exts.data();
  if (!succeeded(f.vkCreateDevice(physical, &dci, nullptr, &device), "vkCreateDevice", error)) return false;
  if (!loadDeviceFunctions(f, device, error)) return false;
  f.vkGetDeviceQueue(device, queueFamily, 0, &queue);
  VkCommandPoolCreateInfo pci{};
  pci.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = queueFamily;
  if (!succeeded(f.vkCreateCommandPool(device, &pci, nullptr, &commandPool), "vkCreateCommandPool", error))
    return false;
  VkFenceCreateInfo fci{};
  fci.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
  return succeeded(f.vkCreateFence(device, &fci, nullptr, &fence), "vkCreateFence", error);
}

uint32_t Device::memoryType(uint32_t typeBits) const {
  VkPhysicalDeviceMemoryProperties mem{};
  f.vkGetPhysicalDeviceMemoryProperties(physical, &mem);
  const VkMemoryPropertyFlags need = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  uint32_t found = ~0u;
  for (uint32_t i = 0; i < mem.memoryTypeCount; ++i) {
    const VkMemoryPropertyFlags flags = mem.memoryTypes[i].propertyFlags;
    if (!(typeBits & (1u << i)) || (flags & need) != need) continue;
    if (flags & VK_MEMORY_PROPERTY_HOST_CACHED_BIT) return i; // reads back fast
    if (found == ~0u) found = i;
  }
  return found;
}

bool Device::createBuffer(VkDeviceSize size, VkBufferUsageFlags usage, Buffer& out, std::string& error) {
  VkBufferCreateInfo bci{};
  bci.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  bci.size = size;
  bci.usage = usage;
  bci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (!succeeded(f.vkCreateBuffer(device, &bci, nullptr, &out.buffer), "vkCreateBuffer", error)) return false;
  VkMemoryRequirements req{};
  f.vkGetBufferMemoryRequirements(device, out.buffer, &req);
  VkMemoryAllocateInfo mai{};
  mai.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  mai.allocationSize = req.size;
  mai.memoryTypeIndex = memoryType(req.memoryTypeBits);
  if (mai.memoryTypeIndex == ~0u) {
    error = "vkGetBufferMemoryRequirements: no host-visible, host-coherent memory type for a buffer";
    return false;
  }
  if (!succeeded(f.vkAllocateMemory(device, &mai, nullptr, &out.memory), "vkAllocateMemory", error)) return false;
  if (!succeeded(f.vkBindBufferMemory(device, out.buffer, out.memory, 0), "vkBindBufferMemory", error)) return false;
  out.size = size;
  return succeeded(f.vkMapMemory(device, out.memory, 0, VK_WHOLE_SIZE, 0, &out.mapped), "vkMapMemory", error);
}

void Device::destroyBuffer(Buffer& b) {
  if (b.buffer) f.vkDestroyBuffer(device, b.buffer, nullptr);
  if (b.memory) f.vkFreeMemory(device, b.memory, nullptr); // unmaps
  b = Buffer{};
}

bool Device::shaderModule(const std::string& glsl, int stage, VkShaderModule& out, std::string& error) {
  std::vector<uint32_t> spirv;
  if (!compileGlsl(glsl, stage, spirv, error)) return false;
  VkShaderModuleCreateInfo ci{};
  ci.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  ci.codeSize = spirv.size() * sizeof(uint32_t);
  ci.pCode = spirv.data();
  return succeeded(f.vkCreateShaderModule(device, &ci, nullptr, &out), "vkCreateShaderModule", error);
}

bool Device::submitAndWait(VkCommandBuffer cmd, std::string& error) {
  VkSubmitInfo si{};
  si.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  si.commandBufferCount = 1;
  si.pCommandBuffers = &cmd;
  if (!succeeded(f.vkResetFences(device, 1, &fence), "vkResetFences", error)) return false;
  if (!succeeded(f.vkQueueSubmit(queue, 1, &si, fence), "vkQueueSubmit", error)) return false;
  const VkResult r = f.vkWaitForFences(device, 1, &fence, VK_TRUE, kFenceTimeoutNs);
  if (r == VK_TIMEOUT) {
    error = "vkWaitForFences: the device did not finish a draw within 120 s (VK_TIMEOUT)";
    return false;
  }
  return succeeded(r, "vkWaitForFences", error);
}

} // namespace vk
} // namespace oracle
} // namespace fftess
