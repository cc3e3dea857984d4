#include "voxc/world/VdbTile.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <mutex>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Prune.h>
#include <sstream>

namespace voxc::world {

namespace {

void initialiseOnce() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

} // namespace

std::string tileVdbBytes(const DenseGrid& grid, glm::ivec3 worldMin) {
    initialiseOnce();
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
    openvdb::Int32Grid::Ptr material = openvdb::Int32Grid::create(0);
    density->setName("density");
    material->setName("material");
    auto densities = density->getAccessor();
    auto materials = material->getAccessor();
    const glm::ivec3 size = grid.size();
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x) {
                const openvdb::Coord at(worldMin.x + x, worldMin.y + y, worldMin.z + z);
                const float d = grid.at({x, y, z});
                if (d != 0.0f) densities.setValue(at, d);
                if (const uint8_t m = grid.materialAt({x, y, z})) materials.setValue(at, int32_t(m));
            }
    openvdb::tools::prune(density->tree());
    openvdb::tools::prune(material->tree());
    openvdb::GridPtrVec grids{density, material};
    std::ostringstream out(std::ios::binary);
    openvdb::io::Stream(out).write(grids);
    return std::move(out).str();
}

DenseGrid readTileVdb(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size) {
    initialiseOnce();
    openvdb::io::File file(path);
    try {
        file.open();
    } catch (const openvdb::Exception& error) {
        throw UserError(fmt::format("cannot read '{}': {}", path, error.what()));
    }
    const auto density = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("density"));
    const auto material = openvdb::gridPtrCast<openvdb::Int32Grid>(file.readGrid("material"));
    if (!density || !material) throw UserError(fmt::format("'{}' is not a voxc tile (no density and material grids)", path));
    auto densities = density->getConstAccessor();
    auto materials = material->getConstAccessor();
    DenseGrid grid(size);
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x) {
                const openvdb::Coord at(worldMin.x + x, worldMin.y + y, worldMin.z + z);
                grid.at({x, y, z}) = densities.getValue(at);
                grid.materialAt({x, y, z}) = uint8_t(materials.getValue(at));
            }
    return grid;
}

} // namespace voxc::world
