#include "SolveReport.h"
#include "Common.h"

#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"

#include <algorithm>
#include <fmt/format.h>

namespace voxc::driver {

std::string formatSolveReport(const Program& program, bool perCycle, const std::string& passDevice) {
    std::string out;
    for (const Stage& stage : program.pipeline) {
        if (stage.kind != Stage::Kind::Curves) continue;
        const CurvesBlock& block = program.curves.at(stage.index);
        const SolveTable& table = block.solved();
        // A terrain's cascade runs on the host; where its erosion steps ran is a line of its own.
        const std::string where = table.source != "curves" || passDevice.empty() ? std::string("solved on the host")
                                                            : fmt::format("solved, its global passes on '{}'", passDevice);
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
            out += fmt::format("  {} full multigrid per level, coarsest first:", solve.name);
            if (solve.fullMultigrid.empty()) out += " not kept (the multigrid ran on the device)";
            for (size_t l = 0; l < solve.fullMultigrid.size(); ++l) {
                const LevelResidual& level = solve.fullMultigrid[l];
                out += fmt::format("{} {}x{}x{} {:.3e}", l == 0 ? "" : ",", level.size.x, level.size.y, level.size.z,
                                   level.residual);
            }
            out += "\n";
            out += fmt::format("  {} max residual: full multigrid {:.3e}", solve.name, solve.residuals.front());
            for (size_t c = 1; c < solve.residuals.size(); ++c)
                out += fmt::format(", V-cycle {} {:.3e}", c, solve.residuals[c]);
            out += "\n";
        }
    }
    return out;
}

namespace {

constexpr std::string_view kDumpChannels[] = {"density",  "normal_x",  "normal_y",   "normal_z",
                                              "amplitude", "roughness", "material",   "confidence",
                                              "distance",  "smoothed",  "displacement"};

} // namespace

std::span<const std::string_view> solveDumpChannels() { return kDumpChannels; }

void addDumpFlag(CLI::App& command, std::vector<std::string>& specs) {
    command.add_option("--dump", specs,
                       "Write a curves block's solved channel as a float32 .npy over its box: [BLOCK.]CHANNEL=FILE.npy, "
                       "CHANNEL one of density, normal_x, normal_y, normal_z, amplitude, roughness, material, "
                       "confidence, distance, smoothed, displacement (repeatable)");
}

std::vector<SolveDump> parseSolveDumps(const std::vector<std::string>& specs) {
    std::vector<SolveDump> dumps;
    for (const std::string& spec : specs) {
        const size_t equals = spec.find('=');
        if (equals == std::string::npos || equals + 1 == spec.size())
            throw UserError(fmt::format("--dump '{}': expected [BLOCK.]CHANNEL=FILE.npy", spec));
        const std::string name = spec.substr(0, equals);
        const size_t dot = name.rfind('.');
        SolveDump dump{dot == std::string::npos ? "" : name.substr(0, dot), name.substr(dot == std::string::npos ? 0 : dot + 1),
                       spec.substr(equals + 1)};
        if (std::find(std::begin(kDumpChannels), std::end(kDumpChannels), dump.channel) == std::end(kDumpChannels))
            throw UserError(fmt::format("--dump '{}': unknown channel '{}'; the channels are {}", spec, dump.channel,
                                        fmt::join(kDumpChannels, ", ")));
        requireExtension(dump.path, {".npy"}, "--dump file");
        dumps.push_back(std::move(dump));
    }
    return dumps;
}

std::vector<RolePath> dumpOutputs(std::span<const SolveDump> dumps) {
    std::vector<RolePath> outputs;
    for (const SolveDump& dump : dumps) outputs.push_back({"--dump " + dump.channel, dump.path});
    return outputs;
}

void writeSolveDumps(OutputFiles& outputs, const Program& program, std::span<const SolveDump> dumps) {
    for (const SolveDump& dump : dumps) {
        const CurvesBlock* block = nullptr;
        for (const CurvesBlock& candidate : program.curves)
            if (candidate.source == "curves" &&
                (candidate.name == dump.block || (dump.block.empty() && program.curves.size() == 1)))
                block = &candidate;
        if (!block)
            throw UserError(dump.block.empty()
                                ? fmt::format("--dump {}: name the curves block (BLOCK.{}): the file has {} solve blocks",
                                              dump.channel, dump.channel, program.curves.size())
                                : fmt::format("--dump {}.{}: the file has no curves block '{}'", dump.block, dump.channel,
                                              dump.block));
        const SolveTable& table = block->solved();
        if (dump.channel == "density") {
            writeFloatNpy(outputs, dump.path, table.size, table.density);
            continue;
        }
        const auto channel = std::find_if(table.channels.begin(), table.channels.end(),
                                          [&](const auto& c) { return c.first == dump.channel; });
        if (channel == table.channels.end())
            throw InternalError("--dump: the solve of '" + block->name + "' kept no channel " + dump.channel);
        writeFloatNpy(outputs, dump.path, table.size, channel->second);
    }
}

} // namespace voxc::driver
