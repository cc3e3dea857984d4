#include "voxc/world/Tiles.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/core/Sha256.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/Region.h"
#include "voxc/world/VdbTile.h"

#include <chrono>
#include <tuple>
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
    Json identity{{"source_sha256", sha256Hex(options.sourceText)}, {"size", vec(world.size)},
                  {"origin", vec(world.origin)},                    {"seed", world.seed},
                  {"tile", options.tile}};
    if (!options.meshFormat.empty()) identity["mesh"] = Json{{"format", options.meshFormat}, {"iso", options.iso}};
    return identity;
}

// The listed tiles' entries by tile file name, from an index of the same identity; UserError
// for another's.
std::map<std::string, Json> listedTiles(const fs::path& indexPath, const Json& expected) {
    std::map<std::string, Json> listed;
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
    for (const Json& tile : index["tiles"]) listed[tile["file"].get<std::string>()] = tile;
    return listed;
}

bool hashesAsListed(const fs::path& path, const std::string& sha256) {
    return fs::exists(path) && sha256Hex(readBytes(path)) == sha256;
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

std::string tileMeshFileName(glm::ivec3 tile, const std::string& format) {
    return fmt::format("tile_{}_{}_{}.{}", tile.x, tile.y, tile.z, format);
}

namespace {

// Tile `index` of the world's tiles (x fastest): its place and its box in the grid.
struct TilePlace {
    glm::ivec3 tile;
    stages::GridBox box;
};

glm::ivec3 tileCounts(const Program& program, int32_t edge) { return (program.world.size + edge - 1) / edge; }

// The tiles this run writes: those meeting options.region, else all of them.
struct TileRange {
    glm::ivec3 first{0}, count{0};
    int64_t total() const { return int64_t(count.x) * count.y * count.z; }
    bool holds(glm::ivec3 tile) const {
        return glm::all(glm::greaterThanEqual(tile, first)) && glm::all(glm::lessThan(tile, first + count));
    }
};

TileRange tileRange(const Program& program, const WorldOptions& options) {
    if (!options.region) return {glm::ivec3(0), tileCounts(program, options.tile)};
    const glm::ivec3 first = options.region->min / options.tile;
    return {first, (options.region->max + options.tile - 1) / options.tile - first};
}

TilePlace tilePlace(const Program& program, const WorldOptions& options, int64_t index) {
    const TileRange range = tileRange(program, options);
    const glm::ivec3 tile = range.first + glm::ivec3(int32_t(index % range.count.x), int32_t(index / range.count.x % range.count.y),
                                                     int32_t(index / (int64_t(range.count.x) * range.count.y)));
    return {tile, {tile * options.tile, glm::min((tile + 1) * options.tile, program.world.size)}};
}

// The index lists tiles z slowest, then y, then x, whatever order they finished in.
using TileOrder = std::tuple<int32_t, int32_t, int32_t>;
TileOrder tileOrder(glm::ivec3 tile) { return {tile.z, tile.y, tile.x}; }

TileDigests listedDigests(const Json& entry) {
    return {entry["sha256"].get<std::string>(), entry.contains("mesh") ? entry["mesh"]["sha256"].get<std::string>() : ""};
}

uint64_t volume(glm::ivec3 size) { return uint64_t(size.x) * uint64_t(size.y) * uint64_t(size.z); }

// The voxels a tile's mesh reads (Tiles.h): one more below the tile, two more above, clipped to
// the world (outside it the mesher reads air, as it does around the whole world's grid).
stages::GridBox meshSampleBox(const Program& program, const stages::GridBox& tile) {
    return {glm::max(tile.min - 1, glm::ivec3(0)), glm::min(tile.max + 2, program.world.size)};
}

// The box a tile's region computes: its voxels, with its mesh's samples when it has a mesh.
stages::GridBox tileRegion(const Program& program, const WorldOptions& options, const stages::GridBox& tile) {
    const stages::GridBox needed = options.meshFormat.empty() ? tile : meshSampleBox(program, tile);
    return stages::haloBox(program, needed, stages::pipelineHalo(program).radius);
}

// The tile's share of the world's mesh from the computed grid (`computed` is its box).
Mesh tileMesh(const Program& program, const WorldOptions& options, const stages::GridBox& tile, const DenseGrid& grid,
              const stages::GridBox& computed) {
    const stages::GridBox samples = meshSampleBox(program, tile);
    const ChunkLayout layout =
        ChunkLayout::make(program.world.origin + samples.min, samples.size(), program.world.chunkSize);
    const ChunkedGrid sampled = ChunkedGrid::fromDense(
        stages::cropGrid(grid, {samples.min - computed.min, samples.max - computed.min}), layout);
    // The cells whose minimum corner is in the tile, grid-local to the samples; on the world's
    // low faces from -1, the outside cells the whole world's mesh closes itself with.
    CellBox cells{tile.min - samples.min, tile.max - samples.min};
    for (int axis = 0; axis < 3; ++axis)
        if (tile.min[axis] == 0) cells.begin[axis] = -1;
    const float margin = marching_cubes::crossingMargin(
        ChunkLayout::make(program.world.origin, program.world.size, program.world.chunkSize));
    return meshMarchingCubesCells(sampled, cells, margin, MeshOptions{.iso = options.iso});
}

} // namespace

TileDigests writeTile(const Program& program, const WorldOptions& options, int64_t index) {
    const TilePlace place = tilePlace(program, options, index);
    const stages::GridBox computed = tileRegion(program, options, place.box);
    const DenseGrid grid = options.run(stages::regionProgram(program, computed));
    TileDigests digests;
    const std::string bytes = tileVdbBytes(
        stages::cropGrid(grid, {place.box.min - computed.min, place.box.max - computed.min}),
        program.world.origin + place.box.min);
    writeFileAtomically((fs::path(options.directory) / tileFileName(place.tile)).string(), bytes);
    digests.voxels = sha256Hex(bytes);
    if (options.meshFormat.empty()) return digests;
    const Mesh mesh = tileMesh(program, options, place.box, grid, computed);
    if (mesh.triangles.empty()) return digests;
    const std::string path = (fs::path(options.directory) / tileMeshFileName(place.tile, options.meshFormat)).string();
    writeMesh(path, mesh, program.materials);
    digests.mesh = sha256Hex(readBytes(path));
    return digests;
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
    const std::map<std::string, Json> listed = listedTiles(indexPath, world);

    const glm::ivec3 tiles = tileCounts(program, options.tile);
    const TileRange range = tileRange(program, options);
    const glm::ivec3 halo = stages::pipelineHalo(program).radius;
    WorldSummary summary;
    TileProgress progress;
    progress.total = range.total();
    // Finished tiles, and those listed outside this run's range (an earlier run's region) kept as listed.
    std::map<TileOrder, Json> entries;
    for (const auto& [file, entry] : listed) {
        const glm::ivec3 tile(entry["tile"][0].get<int32_t>(), entry["tile"][1].get<int32_t>(), entry["tile"][2].get<int32_t>());
        if (!range.holds(tile)) entries[tileOrder(tile)] = entry;
    }
    const auto finish = [&](int64_t tile, const TileDigests& digests) {
        const TilePlace place = tilePlace(program, options, tile);
        summary.voxelsWritten += volume(place.box.size());
        Json& entry = entries[tileOrder(place.tile)] = Json{{"tile", vec(place.tile)},
                                           {"min", vec(program.world.origin + place.box.min)},
                                           {"max", vec(program.world.origin + place.box.max)},
                                           {"file", tileFileName(place.tile)},
                                           {"sha256", digests.voxels}};
        if (!digests.mesh.empty())
            entry["mesh"] = Json{{"file", tileMeshFileName(place.tile, options.meshFormat)}, {"sha256", digests.mesh}};
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
        const TilePlace place = tilePlace(program, options, index);
        if (const auto it = listed.find(tileFileName(place.tile)); it != listed.end()) {
            const TileDigests digests = listedDigests(it->second);
            if (hashesAsListed(directory / tileFileName(place.tile), digests.voxels) &&
                (digests.mesh.empty() ||
                 hashesAsListed(directory / tileMeshFileName(place.tile, options.meshFormat), digests.mesh))) {
                ++progress.kept;
                summary.voxelsKept += volume(place.box.size());
                finish(index, digests);
                continue;
            }
        }
        pending.push_back(index);
        summary.voxelsComputed += volume(tileRegion(program, options, place.box).size());
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
