#pragma once
// What voxc asks of OpenVDB: tiles as .vdb files (voxc world) and signed distances of meshes
// (mesh inputs). OpenVDB is linked into a module of its own, libvoxc-openvdb.so, loaded the first
// time one of these functions runs: loading libopenvdb binds about 56,000 symbols, some 80 ms that
// every voxc process (a check, an LSP start, a test) would otherwise pay at start-up.
// The module is looked for beside the file holding this code (the voxc executable, libvoxc.so or
// the Python package), under ../<libdir>/voxc/ from it (an install), then where the build wrote it.
// A module that is missing or from another build of voxc is a UserError naming the paths tried.
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace voxc::vdb {

// A .vdb file of two float grids, "density" (class fog volume) and "material" (ids 0..255 as
// floats), both with background 0 and pruned to constant tiles; voxel (x, y, z) of the block,
// x fastest, at world coordinate worldMin + (x, y, z). OpenVDB draws the file's UUID at random.
std::string tileFileBytes(const float* density, const uint8_t* material, glm::ivec3 size, glm::ivec3 worldMin);

// The two grids of such a file over the box [worldMin, worldMin + size), x fastest. A file
// OpenVDB cannot open, or without float "density" and "material" grids, is a UserError.
struct TileValues {
    std::vector<float> density;
    std::vector<float> material;
};
TileValues readTileFile(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size);

// OpenVDB's meshToVolume narrow-band signed distances (band voxels each side, index space = world
// voxels) sampled over the box [min, min + size), x fastest; outside the band ±band.
std::vector<float> meshSignedDistances(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles,
                                       float band, glm::ivec3 min, glm::ivec3 size);

} // namespace voxc::vdb
