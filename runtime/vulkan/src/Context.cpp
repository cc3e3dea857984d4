#include "ContextImpl.h"
#include "PipelineCache.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>

namespace voxc {

using vulkan_detail::check;
using vulkan_detail::VulkanApi;

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

DeviceType toDeviceType(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return DeviceType::Discrete;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return DeviceType::Integrated;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return DeviceType::Virtual;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return DeviceType::Cpu;
    default: return DeviceType::Other;
    }
}

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data, void* user) {
    auto* impl = static_cast<VulkanContext::Impl*>(user);
    ValidationMessage message;
    message.error = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0;
    message.text = data && data->pMessage ? data->pMessage : "(no message text)";
    std::lock_guard<std::mutex> lock(impl->messageMutex);
    impl->messages.push_back(std::move(message));
    return VK_FALSE; // never abort the call: the test that reads the messages decides
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(VulkanContext::Impl* impl) {
    VkDebugUtilsMessengerCreateInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onValidationMessage;
    info.pUserData = impl;
    return info;
}

bool hasLayer(const VulkanApi& api, const char* name) {
    uint32_t count = 0;
    check(api.vkEnumerateInstanceLayerProperties(&count, nullptr), "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(api.vkEnumerateInstanceLayerProperties(&count, layers.data()), "vkEnumerateInstanceLayerProperties");
    return std::any_of(layers.begin(), layers.begin() + count,
                       [&](const VkLayerProperties& l) { return std::strcmp(l.layerName, name) == 0; });
}

bool hasExtension(const VulkanApi& api, const char* layer, const char* name) {
    uint32_t count = 0;
    check(api.vkEnumerateInstanceExtensionProperties(layer, &count, nullptr), "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> extensions(count);
    check(api.vkEnumerateInstanceExtensionProperties(layer, &count, extensions.data()),
          "vkEnumerateInstanceExtensionProperties");
    return std::any_of(extensions.begin(), extensions.begin() + count,
                       [&](const VkExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

uint32_t instanceApiVersion(const VulkanApi& api) {
    auto enumerateVersion = reinterpret_cast<PFN_vkEnumerateInstanceVersion>(
        api.vkGetInstanceProcAddr(VK_NULL_HANDLE, "vkEnumerateInstanceVersion"));
    uint32_t version = VK_API_VERSION_1_0;
    if (enumerateVersion && enumerateVersion(&version) != VK_SUCCESS) version = VK_API_VERSION_1_0;
    return std::min(version, uint32_t(VK_API_VERSION_1_3));
}

// Creates the instance; with `impl` set, also the validation layer and its message capture
// (synchronization validation included where the layer offers it, to check our barriers).
VkInstance createInstance(VulkanApi& api, VulkanContext::Impl* validationSink) {
    VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "voxc";
    app.pEngineName = "voxc";
    app.apiVersion = instanceApiVersion(api);

    VkInstanceCreateInfo info{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    info.pApplicationInfo = &app;
    std::vector<const char*> layers, extensions;
    VkDebugUtilsMessengerCreateInfoEXT messenger{};
    VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
    const VkValidationFeatureEnableEXT syncValidation = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    if (validationSink) {
        if (!hasLayer(api, kValidationLayer))
            throw UserError(fmt::format("Vulkan validation was requested but the layer {} is not installed "
                                        "(Debian/Ubuntu: vulkan-validationlayers)",
                                        kValidationLayer));
        if (!hasExtension(api, kValidationLayer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME))
            throw UserError(fmt::format("the validation layer does not offer {}", VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        // Chained so messages from vkCreateInstance/vkDestroyInstance are captured too.
        messenger = messengerInfo(validationSink);
        info.pNext = &messenger;
        if (hasExtension(api, kValidationLayer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME)) {
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            features.enabledValidationFeatureCount = 1;
            features.pEnabledValidationFeatures = &syncValidation;
            messenger.pNext = &features;
        }
    }
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();

    VkInstance instance = VK_NULL_HANDLE;
    const VkResult result = api.vkCreateInstance(&info, nullptr, &instance);
    if (result == VK_ERROR_INCOMPATIBLE_DRIVER)
        throw UserError("no Vulkan driver found (the loader found no installable client driver); install one, "
                        "e.g. mesa-vulkan-drivers for the lavapipe CPU device");
    check(result, "vkCreateInstance");
    loadInstanceApi(api, instance, validationSink != nullptr);
    return instance;
}

std::vector<VkPhysicalDevice> physicalDevices(const VulkanApi& api, VkInstance instance) {
    uint32_t count = 0;
    check(api.vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    if (count) check(api.vkEnumeratePhysicalDevices(instance, &count, devices.data()), "vkEnumeratePhysicalDevices");
    devices.resize(count);
    return devices;
}

// The first queue family with compute, or -1.
int computeFamily(const VulkanApi& api, VkPhysicalDevice device) {
    uint32_t count = 0;
    api.vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    api.vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    for (uint32_t i = 0; i < count; ++i)
        if (families[i].queueFlags & VK_QUEUE_COMPUTE_BIT) return int(i);
    return -1;
}

DeviceInfo describe(const VulkanApi& api, VkPhysicalDevice device, uint32_t index) {
    VkPhysicalDeviceProperties properties;
    api.vkGetPhysicalDeviceProperties(device, &properties);
    DeviceInfo info;
    info.index = index;
    info.name = properties.deviceName;
    info.type = toDeviceType(properties.deviceType);
    info.apiVersion = properties.apiVersion;
    info.hasCompute = computeFamily(api, device) >= 0;
    return info;
}

std::vector<DeviceInfo> describeAll(const VulkanApi& api, const std::vector<VkPhysicalDevice>& devices) {
    std::vector<DeviceInfo> infos;
    for (uint32_t i = 0; i < devices.size(); ++i) infos.push_back(describe(api, devices[i], i));
    return infos;
}

std::string availableText(const std::vector<DeviceInfo>& devices) {
    if (devices.empty()) return "none";
    std::string text;
    for (const DeviceInfo& d : devices)
        text += fmt::format("{}{}: {} ({})", text.empty() ? "" : "; ", d.index, d.name, deviceTypeName(d.type));
    return text;
}

// Index of the best device with compute: GPUs first, the CPU device last (if allowed); -1 if none.
int bestDevice(const std::vector<DeviceInfo>& devices, bool allowCpu) {
    const DeviceType preference[] = {DeviceType::Discrete, DeviceType::Integrated, DeviceType::Virtual,
                                     DeviceType::Other, DeviceType::Cpu};
    for (DeviceType type : preference) {
        if (type == DeviceType::Cpu && !allowCpu) break;
        for (const DeviceInfo& d : devices)
            if (d.type == type && d.hasCompute) return int(d.index);
    }
    return -1;
}

} // namespace

const char* deviceTypeName(DeviceType type) {
    switch (type) {
    case DeviceType::Discrete: return "discrete";
    case DeviceType::Integrated: return "integrated";
    case DeviceType::Virtual: return "virtual";
    case DeviceType::Cpu: return "cpu";
    case DeviceType::Other: return "other";
    }
    return "other";
}

std::string apiVersionText(uint32_t v) {
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(v), VK_API_VERSION_MINOR(v), VK_API_VERSION_PATCH(v));
}

uint32_t selectDevice(const std::vector<DeviceInfo>& devices, const std::string& choice) {
    if (devices.empty()) throw UserError("no Vulkan device found (the driver reports zero physical devices)");
    const std::string available = availableText(devices);
    int chosen = -1;
    if (choice == "auto" || choice.empty()) {
        chosen = bestDevice(devices, true);
        if (chosen < 0) throw UserError("no Vulkan device with a compute queue; available: " + available);
    } else if (choice == "gpu") {
        chosen = bestDevice(devices, false);
        if (chosen < 0) throw UserError("no GPU Vulkan device found; available: " + available);
    } else if (choice == "lavapipe" || choice == "cpu") {
        for (const DeviceInfo& d : devices)
            if (chosen < 0 && d.type == DeviceType::Cpu && d.hasCompute) chosen = int(d.index);
        if (chosen < 0) throw UserError("no lavapipe (CPU) Vulkan device found; available: " + available);
    } else if (!choice.empty() && std::all_of(choice.begin(), choice.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        const unsigned long index = choice.size() > 9 ? devices.size() : std::stoul(choice);
        if (index >= devices.size())
            throw UserError(fmt::format("Vulkan device index {} is out of range; available: {}", choice, available));
        if (!devices[index].hasCompute)
            throw UserError(fmt::format("Vulkan device {} ({}) has no compute queue", index, devices[index].name));
        chosen = int(index);
    } else {
        throw UserError(fmt::format("unknown device '{}': expected auto, gpu, lavapipe or a device index", choice));
    }
    return uint32_t(chosen);
}

std::string formatDeviceList(const std::vector<DeviceInfo>& devices) {
    std::string text;
    for (const DeviceInfo& d : devices)
        text += fmt::format("{}: {} [{}, Vulkan {}]{}\n", d.index, d.name, deviceTypeName(d.type),
                            apiVersionText(d.apiVersion), d.hasCompute ? "" : " (no compute queue)");
    return text;
}

VulkanContext::Impl::~Impl() {
    if (device) {
        api.vkDeviceWaitIdle(device);
        for (const auto& [spirv, pipeline] : kernelPipelines) api.vkDestroyPipeline(device, pipeline, nullptr);
        if (kernelPipelineLayout) api.vkDestroyPipelineLayout(device, kernelPipelineLayout, nullptr);
        if (kernelSetLayout) api.vkDestroyDescriptorSetLayout(device, kernelSetLayout, nullptr);
        if (pipelineCache) {
            savePipelineCache(*this);
            api.vkDestroyPipelineCache(device, pipelineCache, nullptr);
        }
        api.vkDestroyDevice(device, nullptr);
    }
    if (messenger) api.vkDestroyDebugUtilsMessengerEXT(instance, messenger, nullptr);
    if (instance) api.vkDestroyInstance(instance, nullptr);
}

VulkanContext::VulkanContext(const ContextOptions& options) : impl_(std::make_unique<Impl>()) {
    Impl& s = *impl_;
    s.api = vulkan_detail::loadGlobalApi(options.loaderLibrary);
    s.validation = options.validation;
    s.instance = createInstance(s.api, options.validation ? &s : nullptr);
    if (options.validation) {
        const VkDebugUtilsMessengerCreateInfoEXT info = messengerInfo(&s);
        check(s.api.vkCreateDebugUtilsMessengerEXT(s.instance, &info, nullptr, &s.messenger),
              "vkCreateDebugUtilsMessengerEXT");
    }

    const std::vector<VkPhysicalDevice> devices = physicalDevices(s.api, s.instance);
    const std::vector<DeviceInfo> infos = describeAll(s.api, devices);
    const uint32_t chosen = selectDevice(infos, options.device);
    s.physicalDevice = devices[chosen];
    s.info = infos[chosen];
    s.api.vkGetPhysicalDeviceProperties(s.physicalDevice, &s.properties);
    s.api.vkGetPhysicalDeviceMemoryProperties(s.physicalDevice, &s.memory);
    s.queueFamily = uint32_t(computeFamily(s.api, s.physicalDevice));

    const float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    queueInfo.queueFamilyIndex = s.queueFamily;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;
    VkPhysicalDeviceFeatures supported{};
    s.api.vkGetPhysicalDeviceFeatures(s.physicalDevice, &supported);
    VkPhysicalDeviceFeatures enabled{};
    enabled.shaderFloat64 = supported.shaderFloat64;
    s.shaderFloat64 = supported.shaderFloat64 == VK_TRUE;
    VkDeviceCreateInfo deviceInfo{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.pEnabledFeatures = &enabled;
    check(s.api.vkCreateDevice(s.physicalDevice, &deviceInfo, nullptr, &s.device), "vkCreateDevice");
    vulkan_detail::loadDeviceApi(s.api, s.device);
    s.api.vkGetDeviceQueue(s.device, s.queueFamily, 0, &s.queue);
    openPipelineCache(s, options.pipelineCacheDirectory);
    s.shareKernelPipelines = options.shareKernelPipelines;
}

VulkanContext::~VulkanContext() = default;

std::vector<DeviceInfo> VulkanContext::listDevices(const std::string& loaderLibrary) {
    VulkanApi api = vulkan_detail::loadGlobalApi(loaderLibrary);
    VkInstance instance = createInstance(api, nullptr);
    std::vector<DeviceInfo> infos;
    try {
        infos = describeAll(api, physicalDevices(api, instance));
    } catch (...) {
        api.vkDestroyInstance(instance, nullptr);
        throw;
    }
    api.vkDestroyInstance(instance, nullptr);
    return infos;
}

const DeviceInfo& VulkanContext::device() const { return impl_->info; }

bool VulkanContext::validationEnabled() const { return impl_->validation; }

bool VulkanContext::hasShaderFloat64() const { return impl_->shaderFloat64; }

std::vector<ValidationMessage> VulkanContext::validationMessages() const {
    std::lock_guard<std::mutex> lock(impl_->messageMutex);
    return impl_->messages;
}

void VulkanContext::clearValidationMessages() {
    std::lock_guard<std::mutex> lock(impl_->messageMutex);
    impl_->messages.clear();
}

KernelPipelineCounts VulkanContext::kernelPipelineCounts() const {
    std::lock_guard<std::mutex> lock(impl_->kernelPipelineMutex);
    return impl_->kernelPipelineCounts;
}

} // namespace voxc
