#pragma once
// The run-time half of the pipeline's global solves (docs/curves.md, "The stage"; docs/terrain.md):
// the check keeps each curves block's voxelised scene (CurvesBlock::scene) and each terrain
// block's checked settings (CurvesBlock::terrain); a run solves them here, once, before the stage
// plan is built or interpreted, and every consumer of the table (the curves stage kind's plan and
// interpretation, the solve report, --dump, regions, `voxc terrain`) and of a terrain's height map
// (fields that sample it) reads it from the program afterwards.
#include "voxc/generators/curves/Solvers.h"
#include "voxc/generators/terrain/Terrain.h"
#include "voxc/program/Program.h"

#include <optional>
#include <stop_token>

namespace voxc::stages {

struct SolveOptions {
    curves::Solvers solvers{}; // where the curves' global passes run: empty members, the host's loops
    bool keepChannels = false; // keep the solve's channels in the table (SolveTable::channels, --dump)
    terrain::ErosionRunner erosionRunner{}; // where terrain erosion steps run: empty, the host's loop
    // Asked to stop, the solve in progress throws voxc::Stopped at its next boundary (a curves
    // pass or V-cycle, a batch of kStopErosionSteps erosion steps) and nothing reaches the cache.
    std::stop_token stop{};
};

// How many erosion steps a stoppable terrain solve runs between two looks at SolveOptions::stop.
inline constexpr uint32_t kStopErosionSteps = 8;

// Solves every curves and terrain block of `program` that has no table yet, in declaration order,
// over its whole declared box (curves::solveScene; a terrain over the checked world,
// terrain::solveTerrain), and keeps the cells inside the program's grid (a region program's:
// World::localBase), so a region computes what the whole world computes there. A terrain's solved
// height map replaces its declared one in every field that samples it. A solve that fails (a
// multigrid past its cycle cap, a terrain past its work limits) is a UserError located at its block.
void solveBlocks(Program& program, const SolveOptions& options = {});

// Keeps `table`, solved over `block`'s whole box, as the block's table for `world`'s grid: its
// cells inside the grid (a region program's: World::localBase), in grid-local coordinates.
void keepTable(const World& world, CurvesBlock& block, SolveTable table);

// Every field node of `program` that samples the terrain `name` reads `map` from now on (solveBlocks
// gives them the solved map; the viewer's preview a coarse one).
void replaceTerrainMap(Program& program, const std::string& name, const std::shared_ptr<const SampledMap>& map);

// `program` when every block has its table; otherwise `scratch`, a copy whose blocks are solved
// here on the host. compileProgram and interpret start with it, so a caller that has no solvers to
// pass need not call solveBlocks; one that reports or dumps the tables calls it first.
const Program& solvedProgram(const Program& program, std::optional<Program>& scratch);

} // namespace voxc::stages
