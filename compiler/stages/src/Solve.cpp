#include "voxc/stages/Solve.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Stopped.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/generators/terrain/Block.h"
#include "voxc/codegen/CompileCache.h"
#include "voxc/stages/Region.h"
#include "voxc/stages/SolveCache.h"

#include <algorithm>
#include <fmt/format.h>
#include <glm/vector_relational.hpp>

namespace voxc::stages {

namespace {

UserError solveError(const Program& program, const CurvesBlock& block, const char* what, const std::string& why) {
    return UserError(fmt::format("{}:{}:{}: {} '{}' did not solve: {}", program.sourcePath, block.loc.line,
                                 block.loc.column, what, block.name, why));
}

// The erosion runner of `options`, run in batches of kStopErosionSteps with a look at the stop
// token before each when it can be asked to stop (the steps keep their numbers, so the same bits).
terrain::ErosionRunner stoppable(const SolveOptions& options) {
    if (!options.stop.stop_possible()) return options.erosionRunner;
    const terrain::ErosionRunner inner = options.erosionRunner ? options.erosionRunner : terrain::ErosionRunner(terrain::runErosionSteps);
    return [inner, stop = options.stop](terrain::ErosionGrid& grid, const terrain::ErosionParams& params, int32_t level,
                                        uint32_t firstStep, uint32_t steps, bool drain) {
        for (uint32_t done = 0; done < steps; done += kStopErosionSteps) {
            throwIfStopped(stop);
            inner(grid, params, level, firstStep + done, std::min(kStopErosionSteps, steps - done), drain);
        }
    };
}

// The block's table over its whole box: from the solve cache when it holds it, else solved (and
// kept there). Channels are never kept, so a run that asks for them solves.
SolveTable solveWhole(const Program& program, const CurvesBlock& block, const SolveOptions& options) {
    const std::optional<std::filesystem::path> directory =
        options.keepChannels ? std::nullopt : codegen::compileCacheDirectory();
    const curves::Solvers& s = options.solvers;
    const bool onDevice = s.linear || s.peronaMalik || s.smoothing || s.material || s.surface || s.displacement;
    const std::string key = directory ? solveKey(block, onDevice) : std::string();
    bool corrupted = false;
    if (directory)
        if (std::optional<SolveTable> kept = readSolve(*directory, key, corrupted)) {
            countSolve(true, false);
            return std::move(*kept);
        }
    SolveTable table;
    if (block.scene) {
        try {
            curves::Solvers solvers = options.solvers;
            solvers.stop = options.stop;
            table = curves::solveScene(*block.scene, curves::Limits{}, solvers, options.keepChannels);
        } catch (const curves::ConvergenceError& e) {
            throw solveError(program, block, "curves", e.what());
        }
    } else {
        try {
            table = terrain::solveTerrain(*block.terrain, stoppable(options)).table;
        } catch (const terrain::LimitError& e) {
            throw solveError(program, block, "terrain", e.what());
        }
    }
    countSolve(false, corrupted);
    if (directory) writeSolve(*directory, key, table);
    return table;
}

} // namespace

void replaceTerrainMap(Program& program, const std::string& name, const std::shared_ptr<const SampledMap>& map) {
    for (Field& field : program.fields)
        for (FieldNode& node : field.nodes)
            if (node.kind == FieldNode::Kind::Map && node.map->name == name && node.map->source == "terrain")
                node.map = map;
}

void keepTable(const World& world, CurvesBlock& block, SolveTable table) {
    const GridBox grid{world.localBase, world.localBase + world.size};
    const bool inside = glm::all(glm::lessThanEqual(grid.min, table.min)) &&
                        glm::all(glm::lessThanEqual(table.min + table.size, grid.max));
    if (inside) {
        table.min -= grid.min;
        block.table = std::make_shared<const SolveTable>(std::move(table));
    } else {
        block.table = regionTable(table, grid);
    }
}

void solveBlocks(Program& program, const SolveOptions& options) {
    for (CurvesBlock& block : program.curves) {
        if (block.table || (!block.scene && !block.terrain)) continue;
        SolveTable table = solveWhole(program, block, options);
        if (block.terrain) replaceTerrainMap(program, block.name, terrain::solvedMap(*block.terrain, *table.terrainMaps));
        keepTable(program.world, block, std::move(table));
    }
}

const Program& solvedProgram(const Program& program, std::optional<Program>& scratch) {
    const auto unsolved = [](const CurvesBlock& block) { return !block.table && (block.scene || block.terrain); };
    if (std::none_of(program.curves.begin(), program.curves.end(), unsolved)) return program;
    solveBlocks(scratch.emplace(program));
    return *scratch;
}

} // namespace voxc::stages
