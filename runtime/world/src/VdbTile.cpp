#include "voxc/world/VdbTile.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <mutex>
#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Prune.h>
#include <sstream>

namespace voxc::world {

namespace {

// OpenVDB's archive header: magic (8 bytes), file version, library major and minor (4 each), the
// grid-offsets flag (1), then the file's UUID as 36 characters, drawn at random on every write.
constexpr size_t kUuidOffset = 21;
constexpr size_t kUuidLength = 36;

// Replaces the random UUID by one made from the rest of the file (SHA-256, written as a UUID), so
// equal tiles are equal files: a second run, or a resumed one, writes the same bytes.
void setUuidFromContents(std::string& bytes) {
    const bool uuid = bytes.size() > kUuidOffset + kUuidLength && bytes[kUuidOffset + 8] == '-' &&
                      bytes[kUuidOffset + 13] == '-' && bytes[kUuidOffset + 18] == '-' && bytes[kUuidOffset + 23] == '-';
    if (!uuid) throw InternalError("OpenVDB wrote a header without a UUID where voxc expects it");
    std::fill_n(bytes.begin() + kUuidOffset, kUuidLength, '0');
    const std::string digest = sha256Hex(bytes);
    const std::string name = fmt::format("{}-{}-5{}-8{}-{}", digest.substr(0, 8), digest.substr(8, 4),
                                         digest.substr(12, 3), digest.substr(15, 3), digest.substr(18, 12));
    bytes.replace(kUuidOffset, kUuidLength, name);
}

void initialiseOnce() {
    static std::once_flag once;
    std::call_once(once, [] { openvdb::initialize(); });
}

} // namespace

std::string tileVdbBytes(const DenseGrid& grid, glm::ivec3 worldMin) {
    initialiseOnce();
    // Densities are in [0, 1] with 0 (air) outside: a fog volume in OpenVDB's terms. Material ids
    // are stored as floats (0..255 exactly) because float grids are what every reader opens:
    // pyopenvdb's readAll fails on an Int32 grid, and Houdini and Blender import float grids.
    openvdb::FloatGrid::Ptr density = openvdb::FloatGrid::create(0.0f);
    openvdb::FloatGrid::Ptr material = openvdb::FloatGrid::create(0.0f);
    density->setName("density");
    density->setGridClass(openvdb::GRID_FOG_VOLUME);
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
                if (const uint8_t m = grid.materialAt({x, y, z})) materials.setValue(at, float(m));
            }
    openvdb::tools::prune(density->tree());
    openvdb::tools::prune(material->tree());
    openvdb::GridPtrVec grids{density, material};
    std::ostringstream out(std::ios::binary);
    openvdb::io::Stream(out).write(grids);
    std::string bytes = std::move(out).str();
    setUuidFromContents(bytes);
    return bytes;
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
    const auto material = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("material"));
    if (!density || !material) throw UserError(fmt::format("'{}' is not a voxc tile (no float density and material grids)", path));
    auto densities = density->getConstAccessor();
    auto materials = material->getConstAccessor();
    DenseGrid grid(size);
    for (int32_t z = 0; z < size.z; ++z)
        for (int32_t y = 0; y < size.y; ++y)
            for (int32_t x = 0; x < size.x; ++x) {
                const openvdb::Coord at(worldMin.x + x, worldMin.y + y, worldMin.z + z);
                grid.at({x, y, z}) = densities.getValue(at);
                const float m = materials.getValue(at);
                if (!(m >= 0.0f && m <= 255.0f && m == std::floor(m)))
                    throw UserError(fmt::format("'{}' holds material {} at ({}, {}, {}), not an id 0..255", path, m, at.x(), at.y(), at.z()));
                grid.materialAt({x, y, z}) = uint8_t(m);
            }
    return grid;
}

} // namespace voxc::world
