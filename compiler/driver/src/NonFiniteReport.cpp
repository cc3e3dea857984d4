#include "NonFiniteReport.h"

#include "voxc/core/Errors.h"
#include "voxc/ir/Ir.h"

#include <fmt/format.h>

namespace voxc::driver {

namespace {

// The pipeline entry as written, e.g. "start", "overhang", "union pole".
std::string stageText(const Program& program, SourceLoc loc) {
    for (const Stage& stage : program.pipeline) {
        if (stage.loc.line != loc.line || stage.loc.column != loc.column) continue;
        return stage.label;
    }
    throw InternalError(fmt::format("no pipeline stage at {}:{}", loc.line, loc.column));
}

} // namespace

std::string formatNonFiniteWarnings(const Program& program, const std::string& path,
                                    std::span<const SourceLoc> stageLocs, std::span<const NonFiniteCount> counts) {
    VOXC_ASSERT(stageLocs.size() == counts.size());
    std::string out;
    for (size_t i = 0; i < counts.size(); ++i) {
        if (counts[i].count == 0) continue;
        const glm::ivec3 voxel = gridPosition(counts[i].firstIndex, program.world.size);
        const glm::ivec3 world = voxel + program.world.origin;
        out += fmt::format("{}:{}:{}: warning: stage `{}`: {} non-finite densit{} replaced by 0; the first at voxel "
                           "({}, {}, {}), world ({}, {}, {})\n",
                           path, stageLocs[i].line, stageLocs[i].column, stageText(program, stageLocs[i]),
                           counts[i].count, counts[i].count == 1 ? "y" : "ies", voxel.x, voxel.y, voxel.z, world.x,
                           world.y, world.z);
    }
    return out;
}

} // namespace voxc::driver
