#include "PipelineCache.h"

#include "voxc/core/AtomicWrite.h"

#include <cstring>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <iterator>

namespace voxc {

using vulkan_detail::check;

namespace {

// A file: this tag, the FNV-1a hash of the data (8 bytes, little-endian), then Vulkan's data.
constexpr char kTag[8] = {'v', 'o', 'x', 'c', 'p', 'c', '0', '1'};

uint64_t fnv1a(const char* data, size_t size) {
    uint64_t hash = 14695981039346656037ull;
    for (size_t i = 0; i < size; ++i) hash = (hash ^ uint8_t(data[i])) * 1099511628211ull;
    return hash;
}

std::string cacheFileName(const VkPhysicalDeviceProperties& p) {
    std::string uuid;
    for (uint8_t byte : p.pipelineCacheUUID) uuid += fmt::format("{:02x}", byte);
    return fmt::format("pipelines-{:04x}-{:04x}-{:08x}-{}.bin", p.vendorID, p.deviceID, p.driverVersion, uuid);
}

// Vulkan's own header (VkPipelineCacheHeaderVersionOne) names the device the data is for.
bool madeForThisDevice(const std::vector<char>& data, const VkPhysicalDeviceProperties& p) {
    VkPipelineCacheHeaderVersionOne header{};
    if (data.size() < sizeof(header)) return false;
    std::memcpy(&header, data.data(), sizeof(header));
    return header.headerSize >= sizeof(header) && header.headerSize <= data.size() &&
           header.headerVersion == VK_PIPELINE_CACHE_HEADER_VERSION_ONE && header.vendorID == p.vendorID &&
           header.deviceID == p.deviceID &&
           std::memcmp(header.pipelineCacheUUID, p.pipelineCacheUUID, VK_UUID_SIZE) == 0;
}

std::vector<char> readCacheData(const std::string& path, const VkPhysicalDeviceProperties& properties) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return {};
    const std::vector<char> file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    constexpr size_t kPrefix = sizeof(kTag) + sizeof(uint64_t);
    if (file.size() <= kPrefix || std::memcmp(file.data(), kTag, sizeof(kTag)) != 0) return {};
    uint64_t stored = 0;
    std::memcpy(&stored, file.data() + sizeof(kTag), sizeof(stored));
    std::vector<char> data(file.begin() + kPrefix, file.end());
    if (fnv1a(data.data(), data.size()) != stored || !madeForThisDevice(data, properties)) return {};
    return data;
}

} // namespace

void openPipelineCache(VulkanContext::Impl& ctx, const std::string& directory) {
    if (!directory.empty()) {
        ctx.pipelineCacheFile = (std::filesystem::path(directory) / cacheFileName(ctx.properties)).string();
        ctx.pipelineCacheLoaded = readCacheData(ctx.pipelineCacheFile, ctx.properties);
    }
    VkPipelineCacheCreateInfo info{VK_STRUCTURE_TYPE_PIPELINE_CACHE_CREATE_INFO};
    info.initialDataSize = ctx.pipelineCacheLoaded.size();
    info.pInitialData = ctx.pipelineCacheLoaded.empty() ? nullptr : ctx.pipelineCacheLoaded.data();
    check(ctx.api.vkCreatePipelineCache(ctx.device, &info, nullptr, &ctx.pipelineCache), "vkCreatePipelineCache");
}

void savePipelineCache(VulkanContext::Impl& ctx) noexcept {
    if (ctx.pipelineCacheFile.empty()) return;
    try {
        size_t size = 0;
        if (ctx.api.vkGetPipelineCacheData(ctx.device, ctx.pipelineCache, &size, nullptr) != VK_SUCCESS) return;
        std::vector<char> data(size);
        if (ctx.api.vkGetPipelineCacheData(ctx.device, ctx.pipelineCache, &size, data.data()) != VK_SUCCESS) return;
        data.resize(size);
        if (data == ctx.pipelineCacheLoaded || !madeForThisDevice(data, ctx.properties)) return;
        std::filesystem::create_directories(std::filesystem::path(ctx.pipelineCacheFile).parent_path());
        const uint64_t hash = fnv1a(data.data(), data.size());
        std::string file(kTag, sizeof(kTag));
        file.append(reinterpret_cast<const char*>(&hash), sizeof(hash));
        file.append(data.data(), data.size());
        writeFileAtomically(ctx.pipelineCacheFile, file);
    } catch (const std::exception&) {
    }
}

} // namespace voxc
