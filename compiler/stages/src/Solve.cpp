#include "voxc/stages/Solve.h"

#include "voxc/core/Errors.h"
#include "voxc/generators/curves/Scene.h"
#include "voxc/stages/Region.h"

#include <algorithm>
#include <fmt/format.h>
#include <glm/vector_relational.hpp>

namespace voxc::stages {

void solveBlocks(Program& program, const SolveOptions& options) {
    const curves::Limits limits;
    const GridBox grid{program.world.localBase, program.world.localBase + program.world.size};
    for (CurvesBlock& block : program.curves) {
        if (block.table || !block.scene) continue;
        try {
            SolveTable table = curves::solveScene(*block.scene, limits, options.solvers, options.keepChannels);
            const bool inside = glm::all(glm::lessThanEqual(grid.min, table.min)) &&
                                glm::all(glm::lessThanEqual(table.min + table.size, grid.max));
            if (inside) {
                table.min -= grid.min;
                block.table = std::make_shared<const SolveTable>(std::move(table));
            } else {
                block.table = regionTable(table, grid);
            }
        } catch (const curves::ConvergenceError& e) {
            throw UserError(fmt::format("{}:{}:{}: curves '{}' did not solve: {}", program.sourcePath, block.loc.line,
                                        block.loc.column, block.name, e.what()));
        }
    }
}

const Program& solvedProgram(const Program& program, std::optional<Program>& scratch) {
    const auto unsolved = [](const CurvesBlock& block) { return !block.table && block.scene; };
    if (std::none_of(program.curves.begin(), program.curves.end(), unsolved)) return program;
    solveBlocks(scratch.emplace(program));
    return *scratch;
}

} // namespace voxc::stages
