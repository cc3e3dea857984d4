#include "voxc/world/Tiles.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"
#include "voxc/stages/Region.h"
#include "voxc/world/VdbTile.h"

#include <chrono>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <glm/common.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

namespace voxc::world {

namespace {

namespace fs = std::filesystem;
using Json = nlohmann::json;

constexpr const char* kIndexFormat = "voxc-world";

Json vec(glm::ivec3 v) { return Json::array({v.x, v.y, v.z}); }

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return std::move(out).str();
}

// What the tiles depend on besides their place: a directory's tiles are kept only for the same.
Json identity(const Program& program, const WorldOptions& options) {
    const World& world = program.world;
    return Json{{"source_sha256", sha256Hex(options.sourceText)}, {"size", vec(world.size)},
                {"origin", vec(world.origin)},                    {"seed", world.seed},
                {"tile", options.tile}};
}

// The listed files by tile name, from an index of the same identity; UserError for another's.
std::map<std::string, std::string> listedTiles(const fs::path& indexPath, const Json& expected) {
    std::map<std::string, std::string> listed;
    if (!fs::exists(indexPath)) return listed;
    Json index;
    try {
        index = Json::parse(readBytes(indexPath));
    } catch (const Json::exception&) {
        throw UserError(fmt::format("'{}' is not a voxc world index; remove it or use another directory", indexPath.string()));
    }
    if (index.value("format", "") != kIndexFormat || index.value("world", Json()) != expected)
        throw UserError(fmt::format("'{}' holds the tiles of another file, world or tile size; remove the directory "
                                    "or use another one",
                                    indexPath.parent_path().string()));
    for (const Json& tile : index["tiles"]) listed[tile["file"].get<std::string>()] = tile["sha256"].get<std::string>();
    return listed;
}

// Temp files of a run that was killed outright (OutputFiles names them "PATH.tmp-PID-N").
void removeStaleTempFiles(const fs::path& directory) {
    for (const fs::directory_entry& entry : fs::directory_iterator(directory)) {
        const std::string name = entry.path().filename().string();
        if ((name.starts_with("tile_") || name.starts_with("index.json")) && name.find(".tmp-") != std::string::npos)
            fs::remove(entry.path());
    }
}

} // namespace

std::string tileFileName(glm::ivec3 tile) { return fmt::format("tile_{}_{}_{}.vdb", tile.x, tile.y, tile.z); }

WorldSummary writeWorld(const Program& program, const WorldOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path directory(options.directory);
    if (fs::exists(directory) && !fs::is_directory(directory))
        throw UserError(fmt::format("-o '{}' is not a directory", options.directory));
    fs::create_directories(directory);
    removeStaleTempFiles(directory);
    const Json world = identity(program, options);
    const fs::path indexPath = directory / "index.json";
    const std::map<std::string, std::string> listed = listedTiles(indexPath, world);

    const glm::ivec3 size = program.world.size;
    const glm::ivec3 tiles = (size + options.tile - 1) / options.tile;
    const glm::ivec3 halo = stages::pipelineHalo(program).radius;
    WorldSummary summary;
    Json entries = Json::array();
    TileProgress progress;
    progress.total = int64_t(tiles.x) * tiles.y * tiles.z;
    for (int32_t k = 0; k < tiles.z; ++k)
        for (int32_t j = 0; j < tiles.y; ++j)
            for (int32_t i = 0; i < tiles.x; ++i) {
                const glm::ivec3 tile(i, j, k);
                const stages::GridBox box{tile * options.tile, glm::min((tile + 1) * options.tile, size)};
                const std::string name = tileFileName(tile);
                const fs::path path = directory / name;
                std::string digest;
                const auto it = listed.find(name);
                if (it != listed.end() && fs::exists(path) && sha256Hex(readBytes(path)) == it->second) {
                    digest = it->second;
                    ++progress.kept;
                    const glm::ivec3 b = box.size();
                    summary.voxelsKept += uint64_t(b.x) * uint64_t(b.y) * uint64_t(b.z);
                } else {
                    const stages::GridBox computed = stages::haloBox(program, box, halo);
                    const DenseGrid grid = options.run(stages::regionProgram(program, computed));
                    const DenseGrid voxels = stages::cropGrid(grid, {box.min - computed.min, box.max - computed.min});
                    const std::string bytes = tileVdbBytes(voxels, program.world.origin + box.min);
                    digest = sha256Hex(bytes);
                    writeFileAtomically(path.string(), bytes);
                    const glm::ivec3 c = computed.size();
                    summary.voxelsComputed += uint64_t(c.x) * uint64_t(c.y) * uint64_t(c.z);
                }
                const glm::ivec3 b = box.size();
                summary.voxelsWritten += uint64_t(b.x) * uint64_t(b.y) * uint64_t(b.z);
                entries.push_back(Json{{"tile", vec(tile)},
                                       {"min", vec(program.world.origin + box.min)},
                                       {"max", vec(program.world.origin + box.max)},
                                       {"file", name},
                                       {"sha256", digest}});
                // The index lists every tile written so far, so a run stopped after this one keeps it.
                const Json index{{"format", kIndexFormat}, {"world", world}, {"halo", vec(halo)},
                                 {"tile_count", vec(tiles)}, {"tiles", entries}};
                writeFileAtomically(indexPath.string(), index.dump(2) + "\n");
                ++progress.done;
                progress.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                if (options.progress) options.progress(progress);
            }
    summary.tiles = progress.total;
    summary.kept = progress.kept;
    return summary;
}

} // namespace voxc::world
