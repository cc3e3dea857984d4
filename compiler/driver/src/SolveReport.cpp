#include "SolveReport.h"

#include <fmt/format.h>

namespace voxc::driver {

std::string formatSolveReport(const Program& program, bool perCycle, const std::string& multigridDevice) {
    std::string out;
    for (const Stage& stage : program.pipeline) {
        if (stage.kind != Stage::Kind::Curves) continue;
        const CurvesBlock& block = program.curves.at(stage.index);
        const SolveTable& table = *block.table;
        const std::string where = multigridDevice.empty() || table.source != "curves"
                                      ? std::string("solved on the host when checked")
                                      : fmt::format("solved when checked, the multigrid on '{}'", multigridDevice);
        out += fmt::format("{} '{}' ({}x{}x{} cells, {}):", table.source, block.name, table.size.x, table.size.y,
                           table.size.z, where);
        for (const SolveSummary& solve : table.solves)
            out += fmt::format("{} {} {} levels, {} V-cycles, max residual {:.2e} -> {:.2e}",
                               out.back() == ':' ? "" : ";", solve.name, solve.levels, solve.cycles(),
                               solve.residuals.front(), solve.residuals.back());
        if (!table.notes.empty()) out += fmt::format("{} {}", out.back() == ':' ? "" : ";", table.notes);
        out += "\n";
        if (!perCycle) continue;
        for (const SolveSummary& solve : table.solves) {
            out += fmt::format("  {} max residual: full multigrid {:.3e}", solve.name, solve.residuals.front());
            for (size_t c = 1; c < solve.residuals.size(); ++c)
                out += fmt::format(", V-cycle {} {:.3e}", c, solve.residuals[c]);
            out += "\n";
        }
    }
    return out;
}

} // namespace voxc::driver
