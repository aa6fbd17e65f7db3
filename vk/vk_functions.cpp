// The Vulkan loader opened at run time (vk_functions.h).
#include "vk_functions.h"

#include <dlfcn.h>
#include <unistd.h>

#include <climits>
#include <type_traits>
#include <string>

namespace fftess {
namespace oracle {
namespace vk {

namespace {

// The folder of the running executable (/proc/self/exe), with a trailing '/'; empty if unknown.
std::string executableFolder() {
  char path[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 1);
  if (n <= 0) return {};
  const std::string s(path, static_cast<size_t>(n));
  const size_t slash = s.rfind('/');
  return slash == std::string::npos ? std::string() : s.substr(0, slash + 1);
}

// Loads the global (null instance), instance-level or device-level list, whichever 'handle' is for, with 'get'
// (vkGetInstanceProcAddr or vkGetDeviceProcAddr); 'owner' names the handle in the error.
template <class Get, class Handle>
bool loadFunctions(Functions& f, Get get, Handle handle, const std::string& owner, std::string& error) {
  constexpr bool device = std::is_same<Handle, VkDevice>::value;
  const bool global = !device && handle == VK_NULL_HANDLE;
#define FFTESS_VK_LOAD(fn)                                                                                             \
  f.fn = reinterpret_cast<PFN_##fn>(get(handle, #fn));                                                                 \
  if (!f.fn) {                                                                                                         \
    error = owner + " has no " #fn;                                                                                    \
    return false;                                                                                                      \
  }
  if (device) {
    FFTESS_VK_DEVICE_FUNCTIONS(FFTESS_VK_LOAD)
  } else if (global) {
    FFTESS_VK_GLOBAL_FUNCTIONS(FFTESS_VK_LOAD)
  } else {
    FFTESS_VK_INSTANCE_FUNCTIONS(FFTESS_VK_LOAD)
  }
#undef FFTESS_VK_LOAD
  return true;
}

} // namespace

Functions::~Functions() {
  if (library) dlclose(library);
}

bool loadLoader(Functions& f, std::string& error) {
  const char* name = "libvulkan.so.1";
  f.library = dlopen(name, RTLD_NOW | RTLD_LOCAL);
  f.libraryName = name;
  if (!f.library) {
    const char* why = dlerror();
    const std::string first = why ? why : "cannot open";
    const std::string beside = executableFolder() + name;
    f.library = dlopen(beside.c_str(), RTLD_NOW | RTLD_LOCAL);
    f.libraryName = beside;
    if (!f.library) {
      why = dlerror();
      error = "no Vulkan loader: dlopen(" + std::string(name) + "): " + first + "; dlopen(" + beside +
              "): " + (why ? why : "cannot open") +
              "; install libvulkan1 and a Vulkan driver, or put libvulkan.so.1 beside the fftess executable";
      return false;
    }
  }
  f.vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(f.library, "vkGetInstanceProcAddr"));
  if (!f.vkGetInstanceProcAddr) {
    error = f.libraryName + " has no vkGetInstanceProcAddr: not a Vulkan loader";
    return false;
  }
  f.vkEnumerateInstanceVersion =
      reinterpret_cast<PFN_vkEnumerateInstanceVersion>(f.vkGetInstanceProcAddr(nullptr, "vkEnumerateInstanceVersion"));
  return loadFunctions(f, f.vkGetInstanceProcAddr, VkInstance(VK_NULL_HANDLE), "the Vulkan loader " + f.libraryName,
                       error);
}

bool loadInstanceFunctions(Functions& f, VkInstance instance, std::string& error) {
  return loadFunctions(f, f.vkGetInstanceProcAddr, instance, "vkGetInstanceProcAddr: the Vulkan instance", error);
}

bool loadDeviceFunctions(Functions& f, VkDevice device, std::string& error) {
  return loadFunctions(f, f.vkGetDeviceProcAddr, device, "vkGetDeviceProcAddr: the Vulkan device", error);
}

std::string resultName(VkResult r) {
  switch (r) {
#define FFTESS_VK_NAME(code)                                                                                           \
  case code: return #code;
    FFTESS_VK_NAME(VK_SUCCESS)
    FFTESS_VK_NAME(VK_NOT_READY)
    FFTESS_VK_NAME(VK_TIMEOUT)
    FFTESS_VK_NAME(VK_EVENT_SET)
    FFTESS_VK_NAME(VK_EVENT_RESET)
    FFTESS_VK_NAME(VK_INCOMPLETE)
    FFTESS_VK_NAME(VK_ERROR_OUT_OF_HOST_MEMORY)
    FFTESS_VK_NAME(VK_ERROR_OUT_OF_DEVICE_MEMORY)
    FFTESS_VK_NAME(VK_ERROR_INITIALIZATION_FAILED)
    FFTESS_VK_NAME(VK_ERROR_DEVICE_LOST)
    FFTESS_VK_NAME(VK_ERROR_MEMORY_MAP_FAILED)
    FFTESS_VK_NAME(VK_ERROR_LAYER_NOT_PRESENT)
    FFTESS_VK_NAME(VK_ERROR_EXTENSION_NOT_PRESENT)
    FFTESS_VK_NAME(VK_ERROR_FEATURE_NOT_PRESENT)
    FFTESS_VK_NAME(VK_ERROR_INCOMPATIBLE_DRIVER)
    FFTESS_VK_NAME(VK_ERROR_TOO_MANY_OBJECTS)
    FFTESS_VK_NAME(VK_ERROR_FORMAT_NOT_SUPPORTED)
    FFTESS_VK_NAME(VK_ERROR_FRAGMENTED_POOL)
    FFTESS_VK_NAME(VK_ERROR_UNKNOWN)
    FFTESS_VK_NAME(VK_ERROR_OUT_OF_POOL_MEMORY)
    FFTESS_VK_NAME(VK_ERROR_INVALID_EXTERNAL_HANDLE)
    FFTESS_VK_NAME(VK_ERROR_FRAGMENTATION)
    FFTESS_VK_NAME(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
    FFTESS_VK_NAME(VK_ERROR_INVALID_SHADER_NV)
#undef FFTESS_VK_NAME
  default: return "VkResult " + std::to_string(static_cast<int>(r));
  }
}

bool succeeded(VkResult r, const char* call, std::string& error) {
  if (r == VK_SUCCESS) return true;
  error = std::string(call) + " failed: " + resultName(r) + " (" + std::to_string(static_cast<int>(r)) + ")";
  return false;
}

} // namespace vk
} // namespace oracle
} // namespace fftess
