#include "RegionOption.h"

#include <fmt/format.h>

namespace voxc::driver {

std::string explainHalo(const Program& program, const std::string& file) {
    const stages::PipelineHalo halo = stages::pipelineHalo(program);
    std::string text = fmt::format("{}: dependency radius of each stage (voxels x y z a voxel's value can reach back "
                                   "into the grid before it):\n",
                                   file);
    for (size_t i = 0; i < program.pipeline.size(); ++i) {
        const Stage& stage = program.pipeline[i];
        const glm::ivec3 r = halo.stages[i].radius;
        // A pipeline left implicit has no place in the file.
        const std::string where = stage.loc.line ? fmt::format("{}:{}:{} ", file, stage.loc.line, stage.loc.column) : "";
        text += fmt::format("  {}{}: {} {} {}  ({})\n", where, stage.label, r.x, r.y, r.z, halo.stages[i].why);
    }
    const glm::ivec3 h = halo.radius;
    const glm::ivec3 world = program.world.size;
    text += fmt::format("halo: {} {} {} (their sum, at most the world's size - 1 per axis: {} {} {}); a --region box "
                        "is grown by it on every side, clipped to the world\n",
                        h.x, h.y, h.z, world.x - 1, world.y - 1, world.z - 1);
    return text;
}

void addRegionFlag(CLI::App& command, std::string& region) {
    command.add_option("--region", region,
                       "Compute only this box of the world, MINX,MINY,MINZ:MAXX,MAXY,MAXZ in world voxels (max "
                       "excluded); its voxels equal the whole world's there, bit for bit");
}

WorldOverrides withRegion(WorldOverrides overrides, const std::string& region) {
    if (!region.empty()) overrides.region = stages::parseWorldBox(region);
    return overrides;
}

RegionRun planRegionRun(Program program, const std::string& region) {
    RegionRun run{std::move(program), std::nullopt, {}};
    run.computed = {glm::ivec3(0), run.program.world.size};
    if (region.empty()) return run;
    run.region = stages::parseRegion(region, run.program.world);
    const stages::PipelineHalo halo = stages::pipelineHalo(run.program);
    run.computed = stages::haloBox(run.program, *run.region, halo.radius);
    run.program = stages::regionProgram(run.program, run.computed);
    return run;
}

DenseGrid RegionRun::crop(const DenseGrid& grid) const {
    if (!region) return grid;
    return stages::cropGrid(grid, {region->min - computed.min, region->max - computed.min});
}

ChunkedGrid RegionRun::crop(const ChunkedGrid& grid) const {
    const DenseGrid voxels = crop(grid.toDense());
    const ChunkLayout& layout = grid.layout();
    return ChunkedGrid::fromDense(
        voxels, ChunkLayout::make(layout.gridOrigin + region->min - computed.min, voxels.size(), layout.chunkSize));
}

std::string RegionRun::describe() const {
    if (!region) return "";
    const glm::ivec3 lo = program.world.origin - computed.min + region->min;
    const glm::ivec3 hi = lo + region->size();
    const glm::ivec3 size = computed.size();
    return fmt::format("region {},{},{}:{},{},{} of the world: a {}x{}x{} grid at world {},{},{} (the halo the "
                       "pipeline's dependency radii need, clipped to the world), cropped\n",
                       lo.x, lo.y, lo.z, hi.x, hi.y, hi.z, size.x, size.y, size.z, program.world.origin.x,
                       program.world.origin.y, program.world.origin.z);
}

} // namespace voxc::driver
