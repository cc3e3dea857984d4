// libvoxc-openvdb.so: the only code of voxc that calls OpenVDB (ModuleApi.h says why it is apart).
#include "ModuleApi.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/Prune.h>

#include <exception>
#include <sstream>

namespace voxc::vdb {

namespace {

// Visits the box [min, min + size) x fastest, as every voxc grid lays out its voxels.
template <typename Visit>
void forEachVoxel(glm::ivec3 min, glm::ivec3 size, Visit visit) {
    size_t at = 0;
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x, ++at) visit(openvdb::Coord(min.x + x, min.y + y, min.z + z), at);
}

// Runs `work`, turning whatever OpenVDB throws into the table's error text.
template <typename Work>
bool guarded(std::string& error, Work work) {
    try {
        openvdb::initialize(); // idempotent, and cheap after the first call
        work();
        return true;
    } catch (const std::exception& failure) {
        error = failure.what();
    } catch (...) {
        error = "an exception OpenVDB did not describe";
    }
    return false;
}

bool writeTile(const float* density, const uint8_t* material, glm::ivec3 size, glm::ivec3 worldMin, std::string& bytes,
               std::string& error) {
    return guarded(error, [&] {
        // Densities are in [0, 1] with 0 (air) outside: a fog volume in OpenVDB's terms. Material
        // ids are floats (0..255 exactly) because float grids are what every reader opens:
        // pyopenvdb's readAll fails on an Int32 grid, and Houdini and Blender import float grids.
        openvdb::FloatGrid::Ptr densities = openvdb::FloatGrid::create(0.0f);
        openvdb::FloatGrid::Ptr materials = openvdb::FloatGrid::create(0.0f);
        densities->setName("density");
        densities->setGridClass(openvdb::GRID_FOG_VOLUME);
        materials->setName("material");
        auto densityAccessor = densities->getAccessor();
        auto materialAccessor = materials->getAccessor();
        forEachVoxel(worldMin, size, [&](const openvdb::Coord& at, size_t i) {
            if (density[i] != 0.0f) densityAccessor.setValue(at, density[i]);
            if (material[i] != 0) materialAccessor.setValue(at, float(material[i]));
        });
        openvdb::tools::prune(densities->tree());
        openvdb::tools::prune(materials->tree());
        openvdb::GridPtrVec grids{densities, materials};
        std::ostringstream out(std::ios::binary);
        openvdb::io::Stream(out).write(grids);
        bytes = std::move(out).str();
    });
}

bool readTile(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size, std::vector<float>& density,
              std::vector<float>& material, std::string& error) {
    return guarded(error, [&] {
        openvdb::io::File file(path);
        try {
            file.open();
        } catch (const openvdb::Exception& failure) {
            throw std::runtime_error("cannot read '" + path + "': " + failure.what());
        }
        const auto densities = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
        const auto materials = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("material"));
        if (!densities || !materials)
            throw std::runtime_error("'" + path + "' is not a voxc tile (no float density and material grids)");
        const auto densityAccessor = densities->getConstAccessor();
        const auto materialAccessor = materials->getConstAccessor();
        const size_t cells = size_t(size.x) * size_t(size.y) * size_t(size.z);
        density.assign(cells, 0.0f);
        material.assign(cells, 0.0f);
        forEachVoxel(worldMin, size, [&](const openvdb::Coord& at, size_t i) {
            density[i] = densityAccessor.getValue(at);
            material[i] = materialAccessor.getValue(at);
        });
    });
}

bool meshDistances(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles, float band,
                   glm::ivec3 min, glm::ivec3 size, std::vector<float>& values, std::string& error) {
    return guarded(error, [&] {
        std::vector<openvdb::Vec3s> vdbPoints;
        vdbPoints.reserve(points.size());
        for (const glm::vec3& p : points) vdbPoints.emplace_back(p.x, p.y, p.z);
        std::vector<openvdb::Vec3I> vdbTriangles;
        vdbTriangles.reserve(triangles.size());
        for (const glm::uvec3& t : triangles) vdbTriangles.emplace_back(t.x, t.y, t.z);
        // Index space = world voxels: voxel (i, j, k) of the VDB grid is world voxel (i, j, k).
        const openvdb::math::Transform::Ptr identity = openvdb::math::Transform::createLinearTransform(1.0);
        const openvdb::tools::QuadAndTriangleDataAdapter<openvdb::Vec3s, openvdb::Vec3I> adapter(vdbPoints, vdbTriangles);
        const openvdb::FloatGrid::Ptr grid = openvdb::tools::meshToVolume<openvdb::FloatGrid>(adapter, *identity, band, band);
        const openvdb::FloatGrid::ConstAccessor accessor = grid->getConstAccessor();
        values.assign(size_t(size.x) * size_t(size.y) * size_t(size.z), 0.0f);
        forEachVoxel(min, size, [&](const openvdb::Coord& at, size_t i) { values[i] = accessor.getValue(at); });
    });
}

constexpr ModuleApi kApi{kModuleAbi, writeTile, readTile, meshDistances};

} // namespace

} // namespace voxc::vdb

extern "C" __attribute__((visibility("default"))) const voxc::vdb::ModuleApi* voxcOpenVdbModule() {
    return &voxc::vdb::kApi;
}
