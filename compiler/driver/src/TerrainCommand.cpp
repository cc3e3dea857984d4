// `voxc terrain FILE NAME [--heightmap H.png] [--height H.npy] [--water W.npy] [--sediment S.npy]
// [--difference D.npy]`:
// a terrain block's maps as a terrain artist takes them away (docs/terrain.md, "Outputs"), written
// as one set, with the generator's summary.
#include "Commands.h"
#include "Console.h"
#include "Common.h"
#include "OutputPaths.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/generators/terrain/Output.h"
#include "voxc/stages/Solve.h"

#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

struct TerrainOptions {
    std::string file;
    std::string name;
    std::string heightmapPath, heightPath, waterPath, sedimentPath, differencePath;
};

// Without erosion the water and sediment maps are zero, never missing.
terrain::Field2 field(int32_t side, const std::vector<float>& values) {
    VOXC_ASSERT(values.size() == size_t(side) * size_t(side));
    terrain::Field2 out(side, side);
    out.values = values;
    return out;
}

void runTerrain(const TerrainOptions& options) {
    if (!options.heightmapPath.empty()) requireExtension(options.heightmapPath, {".png"}, "the heightmap");
    for (const std::string* path : {&options.heightPath, &options.waterPath, &options.sedimentPath, &options.differencePath})
        if (!path->empty()) requireExtension(*path, {".npy"}, "a map");
    const RolePath inputs[] = {{"the input", options.file}};
    const RolePath outputs[] = {{"--heightmap", options.heightmapPath},
                                {"--height", options.heightPath},
                                {"--water", options.waterPath},
                                {"--sediment", options.sedimentPath},
                                {"--difference", options.differencePath}};
    refuseClashingPaths(inputs, outputs);

    Program program = loadProgram(options.file, WorldOverrides{});
    const CurvesBlock* block = nullptr;
    std::string names;
    for (const CurvesBlock& candidate : program.curves) {
        if (!candidate.terrain) continue;
        if (candidate.name == options.name) block = &candidate;
        names += fmt::format("{}{}", names.empty() ? "" : ", ", candidate.name);
    }
    if (!block)
        throw UserError(fmt::format("{}: no terrain named '{}' ({})", options.file, options.name,
                                    names.empty() ? "the file declares none" : "it declares: " + names));
    // Only the named block is generated: the others are left unsolved.
    Program named = program;
    std::erase_if(named.curves, [&](const CurvesBlock& other) { return other.name != block->name; });
    stages::solveBlocks(named);
    const SolveTable& table = named.curves.at(0).solved();
    std::cout << fmt::format("terrain '{}': {}\n", block->name, table.notes);
    const TerrainMaps& maps = *table.terrainMaps;
    OutputFiles files;
    if (!options.heightmapPath.empty())
        terrain::writeHeightPng(files, options.heightmapPath, field(maps.side, maps.height));
    if (!options.heightPath.empty())
        terrain::writeFieldNpy(files, options.heightPath, field(maps.side, maps.height));
    if (!options.waterPath.empty())
        terrain::writeFieldNpy(files, options.waterPath, field(maps.side, maps.water));
    if (!options.sedimentPath.empty())
        terrain::writeFieldNpy(files, options.sedimentPath, field(maps.side, maps.sediment));
    if (!options.differencePath.empty())
        terrain::writeFieldNpy(files, options.differencePath, field(maps.side, maps.difference));
    files.commit();
    reportWritten({options.heightmapPath, options.heightPath, options.waterPath, options.sedimentPath, options.differencePath});
}

} // namespace

void addTerrainCommand(CLI::App& app) {
    auto options = std::make_shared<TerrainOptions>();
    CLI::App* command = app.add_subcommand(
        "terrain", "Write a terrain block's maps: a 16-bit PNG heightmap and float32 .npy height, water and sediment");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("name", options->name, "The terrain block's name")->required();
    command->add_option("--heightmap", options->heightmapPath, "16-bit greyscale PNG: 0..65535 spans 0..max_height");
    command->add_option("--height", options->heightPath, "The height map as .npy (float32, units of max_height)");
    command->add_option("--water", options->waterPath, "The water depth left after the drain as .npy");
    command->add_option("--sediment", options->sedimentPath, "The suspended sediment as .npy");
    command->add_option("--difference", options->differencePath,
                        "The eroded height minus the uneroded one (S_h) as .npy: < 0 where water cut, > 0 where it deposited");
    addConsoleFlags(*command);
    command->callback([options] { runTerrain(*options); });
}

} // namespace voxc::driver
