#pragma once
// The run-time half of the pipeline's global solves (docs/curves.md, "The stage"): the check keeps
// each curves block's voxelised scene (CurvesBlock::scene); a run solves it here, once, before the
// stage plan is built or interpreted, and every consumer of the table (the curves stage kind's plan
// and interpretation, the solve report, --dump, regions) reads it from the block afterwards.
#include "voxc/generators/curves/Solvers.h"
#include "voxc/program/Program.h"

#include <optional>

namespace voxc::stages {

struct SolveOptions {
    curves::Solvers solvers;   // where the global passes run: empty members, the host's loops
    bool keepChannels = false; // keep the solve's channels in the table (SolveTable::channels, --dump)
};

// Solves every curves block of `program` that has no table yet, in declaration order, over its
// whole declared box (curves::solveScene), and keeps the cells inside the program's grid (a region
// program's: World::localBase), so a region computes what the whole world computes there. A solve
// that fails (a multigrid past its cycle cap) is a UserError located at its block.
void solveBlocks(Program& program, const SolveOptions& options = {});

// `program` when every block has its table; otherwise `scratch`, a copy whose blocks are solved
// here on the host. compileProgram and interpret start with it, so a caller that has no solvers to
// pass need not call solveBlocks; one that reports or dumps the tables calls it first.
const Program& solvedProgram(const Program& program, std::optional<Program>& scratch);

} // namespace voxc::stages
