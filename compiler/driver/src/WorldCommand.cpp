#include "Commands.h"
#include "Console.h"
#include "Common.h"
#include "RegionOption.h"

#include "voxc/codegen/CompileCache.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Region.h"
#include "voxc/stages/Solve.h"
#include "voxc/vulkan/Context.h"
#include "voxc/vulkan/Executor.h"
#include "voxc/world/MpiTiles.h"
#include "voxc/world/Tiles.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <glm/common.hpp>
#include <iostream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace voxc::driver {

namespace {

struct WorldCommandOptions {
    std::string file;
    std::string directory;
    int32_t tile = 256;
    std::string region;
    std::string mesh = "glb";
    float iso = 0.5f;
    std::string device = "auto";
    bool interpreter = false;
    bool noCache = false;
    WorldOverrides overrides;
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return std::move(out).str();
}

// "[tile 12/64] 18% 1m20s left" on one terminal line, redrawn per tile.
void drawProgress(const world::TileProgress& progress) {
    const int64_t computed = progress.done - progress.kept;
    const double perTile = computed > 0 ? progress.seconds / double(computed) : 0.0;
    const int64_t left = int64_t(perTile * double(progress.total - progress.done) + 0.5);
    std::fprintf(stderr, "\r[tile %lld/%lld] %3lld%% %lldm%02llds left ", (long long)progress.done,
                 (long long)progress.total, (long long)(100 * progress.done / progress.total), (long long)(left / 60),
                 (long long)(left % 60));
    if (progress.done == progress.total) std::fputc('\n', stderr);
}

void writeWorldTiles(const WorldCommandOptions& options) {
    if (options.tile < 8 || options.tile > 512) throw UserError(fmt::format("--tile {}: the tile edge must be 8 to 512 voxels", options.tile));
    if (options.directory.empty()) throw UserError("world: -o DIR is required");
    if (options.mesh != "glb" && options.mesh != "ply" && options.mesh != "none")
        throw UserError(fmt::format("--mesh {}: the tiles' meshes are glb, ply or none", options.mesh));
    if (!std::isfinite(options.iso)) throw UserError(fmt::format("--iso {}: the surface level must be a finite number", options.iso));
    // The check bounds the grid of the largest tile: one in the middle of the area written, its
    // halo unclipped. The world's size comes from a first check for an empty box (no grid bounded yet).
    WorldOverrides overrides = options.overrides;
    overrides.region = std::pair(glm::ivec3(0), glm::ivec3(0));
    const Program declared = loadProgram(options.file, overrides);
    std::optional<stages::GridBox> region;
    if (!options.region.empty()) region = stages::parseRegion(options.region, declared.world);
    else if (declared.world.unbounded.x || declared.world.unbounded.z)
        throw UserError(fmt::format("world: {} declares an unbounded world; give the box to write with --region "
                                    "MINX,MINY,MINZ:MAXX,MAXY,MAXZ",
                                    options.file));
    const stages::GridBox area = region.value_or(stages::GridBox{glm::ivec3(0), declared.world.size});
    const glm::ivec3 edge = glm::min(glm::ivec3(options.tile), declared.world.size);
    const glm::ivec3 middle = declared.world.origin +
                              glm::clamp(area.min + (area.size() - edge) / 2, glm::ivec3(0), declared.world.size - edge);
    overrides.region = std::pair(middle, middle + edge);
    Program program = loadProgram(options.file, overrides);
    stages::solveBlocks(program); // once for every tile: a tile's program crops the tables

    // Tiles of one size compile to the same kernels (a tile's place is in the push constants): a
    // later tile takes their SPIR-V from the compile cache and their pipelines from the context, so
    // the Vulkan driver compiles each kernel once per run (per rank under mpirun); a rerun or
    // another rank also finds the SPIR-V in the compile cache.
    const std::optional<std::filesystem::path> cache = options.noCache ? std::nullopt : codegen::defaultCacheDirectory();
    codegen::setCompileCacheDirectory(cache);
    std::optional<VulkanContext> context;
    if (!options.interpreter)
        context.emplace(ContextOptions{.device = options.device,
                                       .pipelineCacheDirectory = cache ? cache->string() : "",
                                       .shareKernelPipelines = true});
    world::WorldOptions worldOptions;
    worldOptions.directory = options.directory;
    worldOptions.tile = options.tile;
    worldOptions.region = region;
    worldOptions.sourceText = readText(options.file);
    worldOptions.meshFormat = options.mesh == "none" ? "" : options.mesh;
    worldOptions.iso = options.iso;
    worldOptions.run = [&](const Program& region) {
        if (!context) return interpret(region);
        VulkanExecutor executor(*context, compileProgram(region, {}));
        return executor.run().grid.toDense();
    };
    if (isatty(STDERR_FILENO) && consoleOptions().verbosity != Verbosity::Quiet) worldOptions.progress = drawProgress;
    // Under mpirun, rank 0 hands the tiles to the other ranks (MpiTiles.h); they report nothing.
    const bool onRanks = world::startedByMpiWithRanks();
    const world::WorldSummary summary =
        onRanks ? world::writeWorldOnRanks(program, worldOptions) : world::writeWorld(program, worldOptions);
    if (onRanks && summary.tiles == 0) return;
    status() << fmt::format("wrote {} of {} tiles of {}^3 voxels to {} ({} up to date)", summary.tiles - summary.kept,
                             summary.tiles, options.tile, options.directory, summary.kept);
    if (summary.voxelsComputed > 0)
        status() << fmt::format("; computed {:.2f}x their voxels with the halos",
                                 double(summary.voxelsComputed) / double(summary.voxelsWritten - summary.voxelsKept));
    status() << "\n";
    if (context && !onRanks) { // under mpirun rank 0 compiles nothing: the kernels ran on the others
        const codegen::CompileCacheCounts kernels = codegen::compileCacheCounts();
        const KernelPipelineCounts pipelines = context->kernelPipelineCounts();
        status() << fmt::format("kernels: {} from the cache, {} compiled{}; pipelines: {} created, {} shared by tiles\n",
                                 kernels.hits, kernels.compiled, cache ? "" : " (--no-cache)", pipelines.created,
                                 pipelines.shared);
    }
}

} // namespace

void addWorldCommand(CLI::App& app) {
    auto options = std::make_shared<WorldCommandOptions>();
    CLI::App* command = app.add_subcommand(
        "world", "Generate the world tile by tile into DIR: an OpenVDB file per tile (density and material grids), "
                 "its mesh, and index.json; a stopped run resumes; under mpirun the tiles spread over the ranks");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("-o,--output", options->directory, "Directory of the tiles and index.json")->required();
    command->add_option("--tile", options->tile, "Tile edge in voxels (default 256)");
    command->add_option("--region", options->region,
                        "Write only the tiles that meet this box, MINX,MINY,MINZ:MAXX,MAXY,MAXZ in world voxels (max "
                        "excluded); needed for a world unbounded in x or z");
    command->add_option("--mesh", options->mesh,
                        "Each tile's share of the world's marching-cubes mesh beside its .vdb: glb (default), ply or none");
    command->add_option("--iso", options->iso, "Surface level for the meshes (default 0.5)");
    addDeviceFlag(*command, options->device);
    command->add_flag("--interpreter", options->interpreter,
                      "Compute the tiles with the CPU interpreter (the reference) instead of Vulkan");
    command->add_flag("--no-cache", options->noCache,
                      "Neither read nor write the compile cache (as voxc run --no-cache)");
    addWorldOverrideFlags(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] { writeWorldTiles(*options); });
}

} // namespace voxc::driver
