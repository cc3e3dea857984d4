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

namespace {

// Tile `index` of the world's tiles (x fastest): its place and its box in the grid.
struct TilePlace {
    glm::ivec3 tile;
    stages::GridBox box;
};

glm::ivec3 tileCounts(const Program& program, int32_t edge) { return (program.world.size + edge - 1) / edge; }

TilePlace tilePlace(const Program& program, int32_t edge, int64_t index) {
    const glm::ivec3 counts = tileCounts(program, edge);
    const glm::ivec3 tile(int32_t(index % counts.x), int32_t(index / counts.x % counts.y),
                          int32_t(index / (int64_t(counts.x) * counts.y)));
    return {tile, {tile * edge, glm::min((tile + 1) * edge, program.world.size)}};
}

uint64_t volume(glm::ivec3 size) { return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z); }

} // namespace

std::string writeTile(const Program& program, const WorldOptions& options, int64_t index) {
    const TilePlace place = tilePlace(program, options.tile, index);
    const glm::ivec3 halo = stages::pipelineHalo(program).radius;
    const stages::GridBox computed = stages::haloBox(program, place.box, halo);
    const DenseGrid grid = options.run(stages::regionProgram(program, computed));
    const DenseGrid voxels =
        stages::cropGrid(grid, {place.box.min - computed.min, place.box.max - computed.min});
    const std::string bytes = tileVdbBytes(voxels, program.world.origin + place.box.min);
    writeFileAtomically((fs::path(options.directory) / tileFileName(place.tile)).string(), bytes);
    return sha256Hex(bytes);
}

WorldSummary writeWorld(const Program& program, const WorldOptions& options, const TileScheduler& scheduler) {
    const auto start = std::chrono::steady_clock::now();
    const fs::path directory(options.directory);
    if (fs::exists(directory) && !fs::is_directory(directory))
        throw UserError(fmt::format("-o '{}' is not a directory", options.directory));
    fs::create_directories(directory);
    removeStaleTempFiles(directory);
    const Json world = identity(program, options);
    const fs::path indexPath = directory / "index.json";
    const std::map<std::string, std::string> listed = listedTiles(indexPath, world);

    const glm::ivec3 tiles = tileCounts(program, options.tile);
    const glm::ivec3 halo = stages::pipelineHalo(program).radius;
    WorldSummary summary;
    TileProgress progress;
    progress.total = int64_t(tiles.x) * tiles.y * tiles.z;
    std::map<int64_t, Json> entries; // finished tiles by index: the index lists them in tile order
    const auto finish = [&](int64_t tile, const std::string& digest) {
        const TilePlace place = tilePlace(program, options.tile, tile);
        summary.voxelsWritten += volume(place.box.size());
        entries[tile] = Json{{"tile", vec(place.tile)},
                              {"min", vec(program.world.origin + place.box.min)},
                              {"max", vec(program.world.origin + place.box.max)},
                              {"file", tileFileName(place.tile)},
                              {"sha256", digest}};
        // The index lists every tile finished so far, so a run stopped after this one keeps it.
        Json list = Json::array();
        for (const auto& [i, entry] : entries) list.push_back(entry);
        const Json index{{"format", kIndexFormat}, {"world", world}, {"halo", vec(halo)},
                         {"tile_count", vec(tiles)}, {"tiles", list}};
        writeFileAtomically(indexPath.string(), index.dump(2) + "\n");
        ++progress.done;
        progress.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (options.progress) options.progress(progress);
    };

    std::vector<int64_t> pending;
    for (int64_t index = 0; index < progress.total; ++index) {
        const TilePlace place = tilePlace(program, options.tile, index);
        const fs::path path = directory / tileFileName(place.tile);
        const auto it = listed.find(tileFileName(place.tile));
        if (it != listed.end() && fs::exists(path) && sha256Hex(readBytes(path)) == it->second) {
            ++progress.kept;
            summary.voxelsKept += volume(place.box.size());
            finish(index, it->second);
            continue;
        }
        pending.push_back(index);
        summary.voxelsComputed += volume(stages::haloBox(program, place.box, halo).size());
    }
    const ComputeTile compute = [&](int64_t index) { return writeTile(program, options, index); };
    if (scheduler) {
        scheduler(pending, compute, finish);
    } else {
        for (int64_t index : pending) finish(index, compute(index));
    }
    summary.tiles = progress.total;
    summary.kept = progress.kept;
    return summary;
}

} // namespace voxc::world
