#include "voxc/vdb/Vdb.h"

#include "ModuleApi.h"
#include "voxc/core/Errors.h"

#include <dlfcn.h>
#include <filesystem>
#include <fmt/format.h>
#include <mutex>

namespace voxc::vdb {

namespace {

constexpr const char* kModuleName = "libvoxc-openvdb.so";

// Where the module may lie, most specific first (Vdb.h).
std::vector<std::filesystem::path> candidatePaths() {
    std::vector<std::filesystem::path> paths;
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&candidatePaths), &info) != 0 && info.dli_fname) {
        const std::filesystem::path here = std::filesystem::absolute(info.dli_fname).parent_path();
        paths.push_back(here / kModuleName);
        paths.push_back(here / "voxc" / kModuleName);
        paths.push_back((here / ".." / VOXC_INSTALL_LIBDIR / "voxc" / kModuleName).lexically_normal());
    }
    paths.push_back(VOXC_OPENVDB_MODULE_BUILT);
    return paths;
}

// Loads the module once per process; later calls return the same table (or the same error).
const ModuleApi& module() {
    static std::once_flag once;
    static const ModuleApi* api = nullptr;
    static std::string failure;
    std::call_once(once, [] {
        std::string tried;
        for (const std::filesystem::path& path : candidatePaths()) {
            std::error_code missing;
            if (!std::filesystem::exists(path, missing)) {
                tried += fmt::format("\n  {}: no such file", path.string());
                continue;
            }
            // Never unloaded: OpenVDB registers its grid types process-wide.
            void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
            const auto entry = handle ? reinterpret_cast<const ModuleApi* (*)()>(dlsym(handle, "voxcOpenVdbModule")) : nullptr;
            const ModuleApi* found = entry ? entry() : nullptr;
            if (found && found->abi == kModuleAbi) {
                api = found;
                return;
            }
            tried += found ? fmt::format("\n  {}: from another build of voxc (interface {}, not {})", path.string(),
                                         found->abi, kModuleAbi)
                           : fmt::format("\n  {}: {}", path.string(), handle ? "not voxc's OpenVDB module" : dlerror());
        }
        failure = fmt::format("voxc's OpenVDB module ({}), which reads and writes .vdb files and meshes' signed "
                              "distances, could not be loaded; tried:{}",
                              kModuleName, tried);
    });
    if (!api) throw UserError(failure);
    return *api;
}

} // namespace

std::string tileFileBytes(const float* density, const uint8_t* material, glm::ivec3 size, glm::ivec3 worldMin) {
    std::string bytes, error;
    if (!module().writeTile(density, material, size, worldMin, bytes, error))
        throw InternalError("OpenVDB could not write a tile: " + error);
    return bytes;
}

TileValues readTileFile(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size) {
    TileValues values;
    std::string error;
    if (!module().readTile(path, worldMin, size, values.density, values.material, error)) throw UserError(error);
    return values;
}

std::vector<float> meshSignedDistances(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles,
                                       float band, glm::ivec3 min, glm::ivec3 size) {
    std::vector<float> values;
    std::string error;
    if (!module().meshDistances(points, triangles, band, min, size, values, error))
        throw InternalError("OpenVDB's meshToVolume failed: " + error);
    return values;
}

} // namespace voxc::vdb
