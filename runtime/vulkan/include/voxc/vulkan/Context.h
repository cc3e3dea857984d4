#pragma once
// A Vulkan instance, the chosen physical device, a logical device and one compute queue.
// The header is free of Vulkan types: the loader is opened at run time (see src/VulkanApi.h),
// so code that only includes this header needs neither Vulkan headers nor libvulkan.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace voxc {

enum class DeviceType : uint8_t { Discrete, Integrated, Virtual, Cpu, Other };

const char* deviceTypeName(DeviceType type); // "discrete", "integrated", "virtual", "cpu", "other"

struct DeviceInfo {
    uint32_t index = 0;       // position in the enumerated list (what `--device N` names)
    std::string name;         // e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
    DeviceType type = DeviceType::Other;
    uint32_t apiVersion = 0;  // VK_MAKE_API_VERSION encoding
    bool hasCompute = false;  // has a queue family with compute
};

std::string apiVersionText(uint32_t apiVersion); // "1.3.238"

// The device choice as the CLI spells it:
//   "auto"     a GPU (discrete, then integrated, then virtual) when present, else the CPU device
//   "lavapipe" the CPU device (lavapipe; "cpu" is accepted too); UserError when there is none
//   "gpu"      any non-CPU device, same preference as auto; UserError when there is none
//   "N"        index N of the enumerated list
// Devices without a compute queue are never chosen. Returns an index into `devices`.
// Throws UserError for an unknown choice, an out-of-range index or no usable device.
uint32_t selectDevice(const std::vector<DeviceInfo>& devices, const std::string& choice);

// One line per device: "0: llvmpipe (LLVM 15.0.6, 256 bits) [cpu, Vulkan 1.3.238]".
std::string formatDeviceList(const std::vector<DeviceInfo>& devices);

struct ContextOptions {
    std::string device = "auto";               // see selectDevice
    bool validation = false;                   // VK_LAYER_KHRONOS_validation + message capture
    std::string loaderLibrary = "libvulkan.so.1"; // the Vulkan loader to open
    // Where the device's VkPipelineCache is kept between runs (one file per device and driver
    // version); empty: pipelines are cached for the life of the context only.
    std::string pipelineCacheDirectory = {};
    // Keep every package kernel's pipeline until the context goes, and give it to every later
    // executor whose kernel has the same SPIR-V, instead of having the driver compile it again
    // (which lavapipe does even with the pipeline cache): what `voxc world` asks for, whose tiles
    // of one size share their kernels (docs/scale.md). Off by default, since a context that runs
    // many different packages (tests, the viewer's reloads) would hold all of their pipelines.
    bool shareKernelPipelines = false;
};

// The package kernels' pipelines a context made and shared (ContextOptions::shareKernelPipelines).
struct KernelPipelineCounts {
    uint64_t created = 0; // compiled by the driver
    uint64_t shared = 0;  // handed to an executor from an earlier one with the same SPIR-V
};

// A warning or error reported by the validation layer.
struct ValidationMessage {
    bool error = false; // false: warning
    std::string text;
};

class VulkanContext {
public:
    // Throws UserError when there is no loader, no driver, no device, no device matching the
    // choice, or validation was asked for and the layer is not installed.
    explicit VulkanContext(const ContextOptions& options = {});
    ~VulkanContext();
    VulkanContext(const VulkanContext&) = delete;
    VulkanContext& operator=(const VulkanContext&) = delete;

    // Enumerates devices with a throwaway instance (for `voxc run --list-devices`).
    static std::vector<DeviceInfo> listDevices(const std::string& loaderLibrary = "libvulkan.so.1");

    const DeviceInfo& device() const;
    bool validationEnabled() const;
    // Whether the device computes in double (shaderFloat64), which marching cubes on the device needs.
    bool hasShaderFloat64() const;
    // Messages captured so far (warnings and errors); empty unless validation is enabled.
    std::vector<ValidationMessage> validationMessages() const;
    void clearValidationMessages();
    KernelPipelineCounts kernelPipelineCounts() const;

    struct Impl; // Vulkan handles and entry points, defined in src/ContextImpl.h

private:
    friend class VulkanExecutor;
    friend class VulkanSolveRunner;
    friend class MeshRenderer; // voxc/render: a graphics pipeline on this device and queue
    std::unique_ptr<Impl> impl_;
};

} // namespace voxc
