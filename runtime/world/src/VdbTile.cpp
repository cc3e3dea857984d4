#include "voxc/world/VdbTile.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"
#include "voxc/vdb/Vdb.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <utility>

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

} // namespace

std::string tileVdbBytes(const DenseGrid& grid, glm::ivec3 worldMin) {
    std::string bytes = vdb::tileFileBytes(grid.data().data(), grid.materials().data(), grid.size(), worldMin);
    setUuidFromContents(bytes);
    return bytes;
}

DenseGrid readTileVdb(const std::string& path, glm::ivec3 worldMin, glm::ivec3 size) {
    vdb::TileValues values = vdb::readTileFile(path, worldMin, size);
    DenseGrid grid(size);
    grid.data() = std::move(values.density);
    for (size_t i = 0; i < values.material.size(); ++i) {
        const float m = values.material[i];
        if (!(m >= 0.0f && m <= 255.0f && m == std::floor(m))) {
            const glm::ivec3 at = worldMin + glm::ivec3(int32_t(i % size_t(size.x)), int32_t(i / size_t(size.x) % size_t(size.y)),
                                                        int32_t(i / (size_t(size.x) * size_t(size.y))));
            throw UserError(fmt::format("'{}' holds material {} at ({}, {}, {}), not an id 0..255", path, m, at.x, at.y, at.z));
        }
        grid.materials()[i] = uint8_t(m);
    }
    return grid;
}

} // namespace voxc::world
