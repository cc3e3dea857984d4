#include "voxc/world/Tiles.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/core/InputFile.h"
#include "voxc/core/Sha256.h"
#include "voxc/mesh/Export.h"
#include "voxc/mesh/MarchingCubes.h"
#include "voxc/stages/Region.h"
#include "voxc/world/VdbTile.h"

#include <chrono>
#include <climits>
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

// Caps on what a resumed run reads back from the directory (which anyone may have changed): the
// index, and a tile's .vdb or mesh before hashing it. A tile holds at most 512^3 voxels of two
// grids, far below the tile cap.
constexpr uint64_t kMaxIndexBytes = uint64_t(256) << 20;
constexpr uint64_t kMaxTileBytes = uint64_t(4) << 30;

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return std::move(out).str();
}

bool isSha256Hex(const Json& value) {
    if (!value.is_string()) return false;
    const std::string& text = value.get_ref<const std::string&>();
    return text.size() == 64 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
}

// A tile entry as writeWorld writes it: "tile" three integers, "file" its tile's file name,
// "sha256" a digest, and an optional "mesh" with a "file" and a "sha256". Anything else (a
// damaged or edited index) is not trusted: the tile is computed again.
bool isTileEntry(const Json& entry) {
    if (!entry.is_object()) return false;
    const auto tile = entry.find("tile"), file = entry.find("file"), sha256 = entry.find("sha256");
    if (tile == entry.end() || file == entry.end() || sha256 == entry.end()) return false;
    if (!tile->is_array() || tile->size() != 3) return false;
    for (const Json& axis : *tile)
        if (!axis.is_number_integer() || axis.get<int64_t>() < 0 || axis.get<int64_t>() > INT32_MAX) return false;
    const glm::ivec3 place((*tile)[0].get<int32_t>(), (*tile)[1].get<int32_t>(), (*tile)[2].get<int32_t>());
    if (!file->is_string() || *file != tileFileName(place) || !isSha256Hex(*sha256)) return false;
    if (const auto mesh = entry.find("mesh"); mesh != entry.end()) {
        if (!mesh->is_object()) return false;
        const auto meshFile = mesh->find("file"), meshSha = mesh->find("sha256");
        if (meshFile == mesh->end() || meshSha == mesh->end() || !meshFile->is_string() || !isSha256Hex(*meshSha))
            return false;
    }
    return true;
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
    std::error_code ec;
    if (!fs::exists(fs::symlink_status(indexPath, ec))) return listed;
    const auto notAnIndex = [&](std::string_view why) {
        return UserError(fmt::format("'{}' is not a voxc world index ({}); remove it or use another directory",
                                     indexPath.string(), why));
    };
    // Only a regular file, read to a cap: a FIFO or a device left in its place must not block the run.
    InputFileRead read = readInputFile(indexPath.string(), kMaxIndexBytes);
    if (!read.bytes) throw UserError(read.message);
    Json index;
    try {
        index = Json::parse(*read.bytes);
    } catch (const Json::exception&) {
        throw notAnIndex("not JSON");
    }
    if (!index.is_object()) throw notAnIndex("not a JSON object");
    const auto format = index.find("format");
    const auto world = index.find("world");
    const auto tiles = index.find("tiles");
    if (format == index.end() || *format != kIndexFormat) throw notAnIndex("no \"format\": \"voxc-world\"");
    if (tiles == index.end() || !tiles->is_array()) throw notAnIndex("no \"tiles\" list");
    if (world == index.end() || *world != expected)
        throw UserError(fmt::format("'{}' holds the tiles of another file, world or tile size; remove the directory "
                                    "or use another one",
                                    indexPath.parent_path().string()));
    for (const Json& tile : *tiles)
        if (isTileEntry(tile)) listed[tile["file"].get<std::string>()] = tile;
    return listed;
}

// Whether the file is a regular file with the listed digest (anything else is written again).
bool hashesAsListed(const fs::path& path, const std::string& sha256) {
    const InputFileRead read = readInputFile(path.string(), kMaxTileBytes);
    return read.bytes && sha256Hex(*read.bytes) == sha256;
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
    OutputDirectory made(options.directory); // removed again if nothing gets written into it
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
    made.keep();
    summary.tiles = progress.total;
    summary.kept = progress.kept;
    return summary;
}

} // namespace voxc::world
