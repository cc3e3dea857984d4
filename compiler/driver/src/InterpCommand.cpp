#include "Commands.h"
#include "Common.h"
#include "EditsFile.h"
#include "LsystemInputs.h"
#include "NonFiniteReport.h"
#include "OutputPaths.h"
#include "RegionOption.h"
#include "SolveReport.h"
#include "StageDebug.h"
#include "Console.h"

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
    StageDebugOptions stages; // --after, --diff, --slice, --channel
    std::string region;
    std::string editsPath;
    std::vector<std::string> dumps; // --dump [BLOCK.]CHANNEL=FILE.npy
    WorldOverrides overrides;
};

void interpretFile(const InterpOptions& options, std::span<const SolveDump> dumps) {
    std::vector<CheckedLsystem> lsystems;
    Program checked =
        loadProgram(options.file, withRegion(options.overrides, options.region), false, nullptr, &lsystems);
    stages::solveBlocks(checked, {.keepChannels = !dumps.empty()}); // on the host, for the report and --dump
    checkTraceFilter(checked, options.filter); // against the whole pipeline, whatever --after cuts
    const std::optional<StageCut> cut = selectStage(checked, options.stages);
    // --diff compares with the pipeline cut before the stage (all air and `none` before the first).
    std::optional<Program> before;
    if (cut && cut->diff && cut->stage > 0) before = throughStage(checked, cut->stage - 1);
    if (cut) checked = throughStage(std::move(checked), cut->stage);
    const RegionRun run = planRegionRun(std::move(checked), options.region);
    const Program& program = run.program;
    const std::vector<Brush> edits =
        options.editsPath.empty() ? std::vector<Brush>{} : loadEdits(options.editsPath, program);
    status() << formatSolveReport(program, options.trace);
    status() << run.describe();
    if (!options.stages.slice.empty()) // refused before the run rather than after it
        parseSlice(options.stages.slice, run.region ? run.region->size() : program.world.size);
    if (cut) std::cout << describeCut(program, *cut);

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
    if (!edits.empty()) status() << describeEdits(edits.size(), applyEdits(computed, program.world.origin, edits));
    const DenseGrid grid = run.crop(computed);
    std::vector<SourceLoc> stageLocs;
    for (const Stage& stage : program.pipeline) stageLocs.push_back(stage.loc);
    std::cerr << formatNonFiniteWarnings(program, options.file, stageLocs, nonFinite);
    if (traceFirings)
        std::cout << fmt::format("{} firings matched the trace filter ({} trace lines printed)\n", fired, printed);
    if (cut && cut->diff) {
        DenseGrid previous(grid.size());
        if (before) {
            const RegionRun beforeRun = planRegionRun(std::move(*before), options.region);
            previous = beforeRun.crop(interpret(beforeRun.program));
        }
        std::cout << reportStageDiff(program, options.stages, previous, grid, 0.5f);
    } else {
        std::cout << renderChosenSlice(program, options.stages, grid, 0.5f);
    }
    // Solid as the mesh of `voxc run` sees it at its default --iso.
    if (program.usesMaterials()) status() << formatMaterialCounts(program, grid, 0.5f);
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
    command->add_option("--trace-rule", options->filter.rule, "Trace only this rule, with every symmetry variant of it (NAME@VARIANT: that variant alone)");
    command->add_option("--trace-grammar", options->filter.grammar, "Trace only this grammar");
    command->add_option("--trace-iteration", options->filter.iteration, "Trace only this iteration (0-based)");
    command->add_option("--trace-limit", options->traceLimit, "Print at most this many trace lines");
    command->add_option("--trace-lsystem", options->traceLsystem,
                        "Trace only this lsystem's expansion: each choice of a production or macro substitute, and "
                        "the lengths (plain --trace traces every lsystem's)");
    addStageDebugFlags(*command, options->stages);
    addRegionFlag(*command, options->region);
    addEditsFlag(*command, options->editsPath);
    addWorldOverrideFlags(*command, options->overrides);
    addConsoleFlags(*command);
    command->callback([options] {
        if (!options->region.empty() && (options->trace || options->filter.rule || options->filter.grammar ||
                                         options->filter.iteration || options->traceLimit))
            throw UserError("interp: --region runs a grid of its own around the box; trace the whole world instead");
        if (!options->editsPath.empty() && (!options->stages.after.empty() || !options->stages.diff.empty()))
            throw UserError("interp: --edits are replayed on the finished grid; leave them out with --after or --diff");
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
