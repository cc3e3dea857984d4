#include "StageDebug.h"

#include "voxc/core/Errors.h"
#include "voxc/core/Suggest.h"
#include "voxc/interp/GridDiff.h"
#include "voxc/interp/Slice.h"

#include <charconv>
#include <fmt/format.h>
#include <vector>

namespace voxc::driver {

void addStageDebugFlags(CLI::App& command, StageDebugOptions& options) {
    command.add_option("--after", options.after,
                       "Run the pipeline up to this stage and no further, so every output is as it was after it: "
                       "the stage's position (0 is start), its entry as written ('subtract tunnel') or its "
                       "grammar, field or block name");
    command.add_option("--diff", options.diff,
                       "Like --after, and print what that stage changed: counts by kind (carved, filled, material "
                       "changed, density changed) and material, the box of the change and a slice marking it");
    command.add_option("--slice", options.slice, "Print one layer as text, e.g. y=12");
    command.add_option("--channel", options.channel, "What --slice shows: density (default) or material")
        ->check(CLI::IsMember({"density", "material"}));
}

SliceSpec parseSlice(const std::string& text, glm::ivec3 size) {
    const size_t equals = text.find('=');
    const std::string axisName = text.substr(0, equals);
    SliceSpec spec;
    if (equals == std::string::npos || axisName.size() != 1 || std::string("xyz").find(axisName[0]) == std::string::npos)
        throw UserError(fmt::format("--slice '{}': expected AXIS=INDEX, e.g. y=12", text));
    spec.axis = int(std::string("xyz").find(axisName[0]));
    try {
        size_t used = 0;
        spec.index = std::stoi(text.substr(equals + 1), &used);
        if (used != text.size() - equals - 1) throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
        throw UserError(fmt::format("--slice '{}': the index must be an integer", text));
    }
    if (spec.index < 0 || spec.index >= size[spec.axis])
        throw UserError(fmt::format("--slice '{}': index out of range 0..{}", text, size[spec.axis] - 1));
    return spec;
}

namespace {

// The name a stage's entry ends in: "tunnel" for "subtract tunnel", "erode" for "erode".
std::string_view stageName(const Stage& stage) {
    const std::string_view label = stage.label;
    const size_t space = label.rfind(' ');
    return space == std::string_view::npos ? label : label.substr(space + 1);
}

std::string listStages(const Program& program) {
    std::string list;
    for (size_t i = 0; i < program.pipeline.size(); ++i)
        list += fmt::format("{}{} {}", i == 0 ? "" : ", ", i, program.pipeline[i].label);
    return list;
}

size_t findStage(const Program& program, const std::string& name, const char* flag) {
    size_t index = 0;
    const auto [end, error] = std::from_chars(name.data(), name.data() + name.size(), index);
    if (!name.empty() && error == std::errc() && end == name.data() + name.size()) {
        if (index < program.pipeline.size()) return index;
        throw UserError(fmt::format("{} {}: the pipeline has {} stages, 0..{}: {}", flag, name, program.pipeline.size(),
                                    program.pipeline.size() - 1, listStages(program)));
    }
    std::vector<size_t> matches;
    for (size_t i = 0; i < program.pipeline.size(); ++i)
        if (program.pipeline[i].label == name) matches.push_back(i);
    if (matches.empty())
        for (size_t i = 0; i < program.pipeline.size(); ++i)
            if (stageName(program.pipeline[i]) == name) matches.push_back(i);
    if (matches.size() == 1) return matches[0];
    if (matches.size() > 1) {
        std::string positions;
        for (size_t i : matches) positions += fmt::format("{}{}", positions.empty() ? "" : ", ", i);
        throw UserError(fmt::format("{} '{}': the pipeline runs it {} times (stages {}); give the position instead",
                                    flag, name, matches.size(), positions));
    }
    std::vector<std::string_view> candidates;
    for (const Stage& stage : program.pipeline) {
        candidates.push_back(stage.label);
        if (stageName(stage) != stage.label) candidates.push_back(stageName(stage));
    }
    throw UserError(fmt::format("{} '{}': no such pipeline stage (the stages are: {}){}", flag, name,
                                listStages(program), didYouMean(name, candidates)));
}

} // namespace

std::optional<StageCut> selectStage(const Program& program, const StageDebugOptions& options) {
    if (!options.after.empty() && !options.diff.empty())
        throw UserError("--after and --diff both pick the stage to stop after; give one (--diff writes the outputs "
                        "as --after does)");
    if (!options.after.empty())
        return StageCut{findStage(program, options.after, "--after"), false, program.pipeline.size()};
    if (!options.diff.empty()) return StageCut{findStage(program, options.diff, "--diff"), true, program.pipeline.size()};
    return std::nullopt;
}

Program throughStage(Program program, size_t last) {
    VOXC_ASSERT(last < program.pipeline.size());
    program.pipeline.resize(last + 1);
    return program;
}

std::string describeCut(const Program& program, const StageCut& cut) {
    const Stage& stage = program.pipeline.at(cut.stage);
    return fmt::format("{} stage {} of {}, '{}' ({}:{}:{})\n", cut.diff ? "what changed in" : "the grid after",
                       cut.stage, cut.stages - 1, stage.label, program.sourcePath, stage.loc.line,
                       stage.loc.column);
}

std::string renderChosenSlice(const Program& program, const StageDebugOptions& options, const DenseGrid& grid,
                              float iso) {
    if (options.slice.empty()) return {};
    const SliceSpec slice = parseSlice(options.slice, grid.size());
    return options.channel == "material" ? renderMaterialSlice(program, grid, iso, slice.axis, slice.index)
                                         : renderSlice(grid, slice.axis, slice.index);
}

std::string reportStageDiff(const Program& program, const StageDebugOptions& options, const DenseGrid& before,
                            const DenseGrid& after, float iso) {
    const GridDiff diff = diffGrids(before, after, iso);
    std::string out = formatGridDiff(program, diff);
    if (!options.slice.empty()) {
        const SliceSpec slice = parseSlice(options.slice, after.size());
        out += renderDiffSlice(before, after, iso, slice.axis, slice.index);
    } else if (diff.changed > 0) {
        out += fmt::format("the y layer with the most changes (--slice AXIS=INDEX picks another):\n");
        out += renderDiffSlice(before, after, iso, 1, diff.busiestY);
    }
    return out;
}

} // namespace voxc::driver
