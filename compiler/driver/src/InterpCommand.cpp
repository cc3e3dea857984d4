#include "Commands.h"
#include "Common.h"
#include "EditsFile.h"
#include "LsystemInputs.h"
#include "NonFiniteReport.h"
#include "OutputPaths.h"
#include "RegionOption.h"
#include "SolveReport.h"

#include "voxc/core/Errors.h"
#include "voxc/grid/Grid.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"
#include "voxc/stages/Solve.h"

#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

struct InterpOptions {
    std::string file;
    std::string voxelsPath;
    std::string materialsPath;
    bool trace = false;
    TraceFilter filter;
    std::optional<uint64_t> traceLimit;
    std::optional<std::string> traceLsystem;
    std::string slice;
    std::string region;
    std::string editsPath;
    std::vector<std::string> dumps; // --dump [BLOCK.]CHANNEL=FILE.npy
    WorldOverrides overrides;
};

struct SliceSpec {
    int axis = 1;
    int index = 0;
};

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

void interpretFile(const InterpOptions& options, std::span<const SolveDump> dumps) {
    std::vector<CheckedLsystem> lsystems;
    Program checked =
        loadProgram(options.file, withRegion(options.overrides, options.region), false, nullptr, &lsystems);
    stages::solveBlocks(checked, {.keepChannels = !dumps.empty()}); // on the host, for the report and --dump
    const RegionRun run = planRegionRun(std::move(checked), options.region);
    const Program& program = run.program;
    const std::vector<Brush> edits =
        options.editsPath.empty() ? std::vector<Brush>{} : loadEdits(options.editsPath, program.materials);
    std::cerr << formatSolveReport(program, options.trace);
    std::cerr << run.describe();
    std::optional<SliceSpec> slice;
    if (!options.slice.empty())
        slice = parseSlice(options.slice, run.region ? run.region->size() : program.world.size);

    voxc::InterpOptions interpOptions;
    uint64_t printed = 0;
    uint64_t fired = 0;
    // Any --trace-* filter asks for a trace too; --trace-lsystem alone traces only that expansion.
    const bool grammarFilter = options.filter.rule || options.filter.grammar || options.filter.iteration;
    const bool trace = options.trace || grammarFilter || options.traceLimit || options.traceLsystem;
    const bool traceFirings = options.trace || grammarFilter || (options.traceLimit && !options.traceLsystem);
    if (options.traceLsystem) findLsystem(lsystems, options.file, *options.traceLsystem);
    if (trace && (options.traceLsystem || !grammarFilter))
        for (const CheckedLsystem& lsystem : lsystems)
            if (!options.traceLsystem || lsystem.name == *options.traceLsystem)
                std::cout << expansionTrace(lsystem, options.traceLimit.value_or(UINT64_MAX), printed);
    if (traceFirings) {
        interpOptions.onFire = [&](const TraceEvent& event) {
            if (!traceFilterAccepts(program, options.filter, event)) return;
            ++fired;
            if (options.traceLimit && printed >= *options.traceLimit) return;
            ++printed;
            std::cout << formatTraceEvent(program, event) << "\n";
        };
    }
    std::vector<NonFiniteCount> nonFinite;
    interpOptions.nonFinite = &nonFinite;
    DenseGrid computed = interpret(program, interpOptions);
    // Before the crop: a brush is voxel by voxel, so edits then crop is crop then edits (`voxc run`).
    if (!edits.empty()) std::cerr << describeEdits(edits.size(), applyEdits(computed, program.world.origin, edits));
    const DenseGrid grid = run.crop(computed);
    std::vector<SourceLoc> stageLocs;
    for (const Stage& stage : program.pipeline) stageLocs.push_back(stage.loc);
    std::cerr << formatNonFiniteWarnings(program, options.file, stageLocs, nonFinite);
    if (traceFirings)
        std::cout << fmt::format("{} firings matched the trace filter ({} trace lines printed)\n", fired, printed);
    if (slice) std::cout << renderSlice(grid, slice->axis, slice->index);
    // Solid as the mesh of `voxc run` sees it at its default --iso.
    if (program.usesMaterials()) std::cerr << formatMaterialCounts(program, grid, 0.5f);
    OutputFiles files;
    writeSolveDumps(files, program, dumps);
    writeGridFiles(files, options.voxelsPath, options.materialsPath, grid);
    files.commit();
    reportWritten({options.voxelsPath, options.materialsPath});
    for (const SolveDump& dump : dumps) reportWritten({dump.path});
}

} // namespace

void addInterpCommand(CLI::App& app) {
    auto options = std::make_shared<InterpOptions>();
    CLI::App* command = app.add_subcommand(
        "interp", "Run a .vox file with the CPU interpreter (the reference), with tracing and slices");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("--voxels", options->voxelsPath, "Write the densities as a NumPy .npy file (float32)");
    command->add_option("--materials", options->materialsPath, "Write the material ids as a NumPy .npy file (uint8)");
    addDumpFlag(*command, options->dumps);
    command->add_flag("--trace", options->trace, "Print every rule firing (iteration, sweep, phase, anchor, rule)");
    command->add_option("--trace-rule", options->filter.rule, "Trace only this rule");
    command->add_option("--trace-grammar", options->filter.grammar, "Trace only this grammar");
    command->add_option("--trace-iteration", options->filter.iteration, "Trace only this iteration (0-based)");
    command->add_option("--trace-limit", options->traceLimit, "Print at most this many trace lines");
    command->add_option("--trace-lsystem", options->traceLsystem,
                        "Trace only this lsystem's expansion: each choice of a production or macro substitute, and "
                        "the lengths (plain --trace traces every lsystem's)");
    command->add_option("--slice", options->slice, "Print one layer as text, e.g. y=12");
    addRegionFlag(*command, options->region);
    addEditsFlag(*command, options->editsPath);
    addWorldOverrideFlags(*command, options->overrides);
    command->callback([options] {
        if (!options->region.empty() && (options->trace || options->filter.rule || options->filter.grammar ||
                                         options->filter.iteration || options->traceLimit))
            throw UserError("interp: --region runs a grid of its own around the box; trace the whole world instead");
        if (!options->voxelsPath.empty()) requireExtension(options->voxelsPath, {".npy"}, "voxel file");
        if (!options->materialsPath.empty()) requireExtension(options->materialsPath, {".npy"}, "material file");
        const RolePath inputs[] = {{"the input", options->file}, {"--edits", options->editsPath}};
        const std::vector<SolveDump> dumps = parseSolveDumps(options->dumps);
        if (!dumps.empty() && !options->region.empty())
            throw UserError("interp: --dump writes a curves block's whole box, which a --region run does not keep; leave "
                            "out --region");
        std::vector<RolePath> outputs = dumpOutputs(dumps);
        outputs.insert(outputs.begin(), {{"--voxels", options->voxelsPath}, {"--materials", options->materialsPath}});
        refuseClashingPaths(inputs, outputs);
        interpretFile(*options, dumps);
    });
}

} // namespace voxc::driver
