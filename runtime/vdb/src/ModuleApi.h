#pragma once
// The table libvoxc-openvdb.so hands its loader (Load.cpp), through its one exported symbol
// voxcOpenVdbModule. Only standard and glm types cross it, and errors come back as text, never as
// exceptions: the module carries none of voxc's libraries, so no type needs to match on both sides.
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace voxc::vdb {

// Changed with every change to the table, so a stale module beside a newer voxc is refused.
inline constexpr uint32_t kModuleAbi = 1;

struct ModuleApi {
    uint32_t abi;
    // Each returns false with a message in `error` where OpenVDB failed; see Vdb.h for the rest.
    bool (*writeTile)(const float* density, const uint8_t* material, glm::ivec3 size, glm::ivec3 worldMin,
                      std::string& bytes, std::string& error);
    bool (*readTile)(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size, std::vector<float>& density,
                     std::vector<float>& material, std::string& error);
    bool (*meshDistances)(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles, float band,
                          glm::ivec3 min, glm::ivec3 size, std::vector<float>& values, std::string& error);
};

} // namespace voxc::vdb

extern "C" const voxc::vdb::ModuleApi* voxcOpenVdbModule();
