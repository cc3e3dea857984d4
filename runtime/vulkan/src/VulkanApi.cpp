#include "VulkanApi.h"

#include "voxc/core/Errors.h"

#include <dlfcn.h>
#include <fmt/format.h>

#include <map>
#include <mutex>

namespace voxc::vulkan_detail {

namespace {

// One handle per library path for the whole process: closing the loader while drivers
// such as llvmpipe still hold global state is not worth the risk.
void* openLoader(const std::string& path) {
    static std::mutex mutex;
    static std::map<std::string, void*> opened;
    std::lock_guard<std::mutex> lock(mutex);
    auto it = opened.find(path);
    if (it != opened.end()) return it->second;
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
        const char* reason = dlerror();
        throw UserError(fmt::format("cannot load the Vulkan loader '{}' ({}); install a Vulkan driver, e.g. "
                                    "mesa-vulkan-drivers for the lavapipe CPU device",
                                    path, reason ? reason : "unknown reason"));
    }
    opened.emplace(path, handle);
    return handle;
}

template <typename Fn>
void resolve(Fn& slot, PFN_vkVoidFunction fn, const char* name) {
    if (!fn) throw UserError(fmt::format("the Vulkan loader does not provide {}", name));
    slot = reinterpret_cast<Fn>(fn);
}

} // namespace

VulkanApi loadGlobalApi(const std::string& loaderLibrary) {
    VulkanApi api;
    void* handle = openLoader(loaderLibrary);
    api.vkGetInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(handle, "vkGetInstanceProcAddr"));
    if (!api.vkGetInstanceProcAddr)
        throw UserError(fmt::format("'{}' is not a Vulkan loader (no vkGetInstanceProcAddr)", loaderLibrary));
#define VOXC_VK_LOAD(name) resolve(api.name, api.vkGetInstanceProcAddr(VK_NULL_HANDLE, #name), #name);
    VOXC_VK_GLOBAL_FUNCTIONS(VOXC_VK_LOAD)
#undef VOXC_VK_LOAD
    return api;
}

void loadInstanceApi(VulkanApi& api, VkInstance instance, bool debugUtils) {
#define VOXC_VK_LOAD(name) resolve(api.name, api.vkGetInstanceProcAddr(instance, #name), #name);
    VOXC_VK_INSTANCE_FUNCTIONS(VOXC_VK_LOAD)
    if (debugUtils) {
        VOXC_VK_DEBUG_FUNCTIONS(VOXC_VK_LOAD)
    }
#undef VOXC_VK_LOAD
}

void loadDeviceApi(VulkanApi& api, VkDevice device) {
#define VOXC_VK_LOAD(name) resolve(api.name, api.vkGetDeviceProcAddr(device, #name), #name);
    VOXC_VK_DEVICE_FUNCTIONS(VOXC_VK_LOAD)
#undef VOXC_VK_LOAD
}

const char* resultName(VkResult result) {
    switch (result) {
    case VK_SUCCESS: return "VK_SUCCESS";
    case VK_NOT_READY: return "VK_NOT_READY";
    case VK_TIMEOUT: return "VK_TIMEOUT";
    case VK_INCOMPLETE: return "VK_INCOMPLETE";
    case VK_ERROR_OUT_OF_HOST_MEMORY: return "VK_ERROR_OUT_OF_HOST_MEMORY";
    case VK_ERROR_OUT_OF_DEVICE_MEMORY: return "VK_ERROR_OUT_OF_DEVICE_MEMORY";
    case VK_ERROR_INITIALIZATION_FAILED: return "VK_ERROR_INITIALIZATION_FAILED";
    case VK_ERROR_DEVICE_LOST: return "VK_ERROR_DEVICE_LOST";
    case VK_ERROR_LAYER_NOT_PRESENT: return "VK_ERROR_LAYER_NOT_PRESENT";
    case VK_ERROR_EXTENSION_NOT_PRESENT: return "VK_ERROR_EXTENSION_NOT_PRESENT";
    case VK_ERROR_FEATURE_NOT_PRESENT: return "VK_ERROR_FEATURE_NOT_PRESENT";
    case VK_ERROR_INCOMPATIBLE_DRIVER: return "VK_ERROR_INCOMPATIBLE_DRIVER";
    case VK_ERROR_TOO_MANY_OBJECTS: return "VK_ERROR_TOO_MANY_OBJECTS";
    case VK_ERROR_OUT_OF_POOL_MEMORY: return "VK_ERROR_OUT_OF_POOL_MEMORY";
    case VK_ERROR_INVALID_SHADER_NV: return "VK_ERROR_INVALID_SHADER_NV";
    default: return "VkResult(other)";
    }
}

void check(VkResult result, const char* what) {
    if (result == VK_SUCCESS) return;
    const std::string text = fmt::format("{} failed: {} ({})", what, resultName(result), int(result));
    if (result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY)
        throw UserError(text + "; try a smaller grid");
    if (result == VK_ERROR_DEVICE_LOST) throw UserError(text + "; the Vulkan device stopped responding");
    throw InternalError(text);
}

} // namespace voxc::vulkan_detail
