#include "Commands.h"
#include "Console.h"
#include "Common.h"
#include "OutputPaths.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/core/Errors.h"
#include "voxc/explore/Explore.h"
#include "voxc/explore/Plot.h"
#include "voxc/explore/Png.h"
#include "voxc/explore/Report.h"
#include "voxc/explore/Sweep.h"
#include "voxc/syntax/Diagnostics.h"

#include <filesystem>
#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

namespace {

struct ExploreOptions {
    std::string file;
    std::string parameter;
    std::string range;
    uint32_t runs = 4;
    std::optional<uint32_t> seed;
    float iso = 0.5f;
    std::string size;
    std::string runsCsv;
    std::string summaryCsv;
    std::string png;
};

// "X,Y,Z" or "XxYxZ".
glm::ivec3 parseSize(const std::string& text) {
    glm::ivec3 size{0};
    int axis = 0;
    size_t start = 0;
    while (axis < 3) {
        const size_t end = text.find_first_of(",x", start);
        const std::string part = text.substr(start, end == std::string::npos ? std::string::npos : end - start);
        try {
            size_t used = 0;
            size[axis] = std::stoi(part, &used);
            if (used != part.size()) throw std::invalid_argument("trailing");
        } catch (const std::exception&) {
            throw UserError(fmt::format("--size '{}': expected three integers X,Y,Z, e.g. 32,32,32", text));
        }
        ++axis;
        if (end == std::string::npos) break;
        start = end + 1;
    }
    if (axis != 3 || start > text.size() || text.find_first_of(",x", start) != std::string::npos)
        throw UserError(fmt::format("--size '{}': expected three integers X,Y,Z, e.g. 32,32,32", text));
    return size;
}

SourceFile loadSource(const std::string& path) {
    Diagnostics diagnostics;
    std::optional<SourceFile> source = loadSourceFile(path, diagnostics);
    if (!source) {
        for (const Diagnostic& diagnostic : diagnostics.all()) std::cerr << render(diagnostic, SourceFile(path, ""));
        throw UserError(fmt::format("{}: cannot read the file", path));
    }
    return *source;
}

void exploreFile(const ExploreOptions& options) {
    if (!options.runsCsv.empty()) requireExtension(options.runsCsv, {".csv"}, "--csv file");
    if (!options.summaryCsv.empty()) requireExtension(options.summaryCsv, {".csv"}, "--summary file");
    if (!options.png.empty()) requireExtension(options.png, {".png"}, "--png file");
    const RolePath inputs[] = {{"the input", options.file}};
    const RolePath outputs[] = {{"--csv", options.runsCsv}, {"--summary", options.summaryCsv}, {"--png", options.png}};
    refuseClashingPaths(inputs, outputs);

    explore::ExploreSettings settings;
    settings.parameter = options.parameter;
    const explore::SweepRange range = explore::parseSweepRange(options.range);
    settings.values = explore::sweepValues(range);
    settings.runs = options.runs;
    settings.seedBase = options.seed;
    settings.iso = options.iso;
    if (!options.size.empty()) settings.size = parseSize(options.size);
    settings.onRun = [&](double value, uint32_t run, uint32_t seed) {
        if (run == 0)
            status() << fmt::format("{} = {}: {} run{} from seed {}\n", options.parameter, value, options.runs,
                                     options.runs == 1 ? "" : "s", seed);
    };
    const SourceFile source = loadSource(options.file);
    const explore::ExploreResult result = explore::runExploration(source, settings);
    std::cerr << result.warnings;
    std::cout << explore::formatSummaryTable(result);

    OutputFiles files;
    if (!options.runsCsv.empty()) files.add(options.runsCsv, explore::formatRunsCsv(result));
    if (!options.summaryCsv.empty()) files.add(options.summaryCsv, explore::formatSummaryCsv(result));
    if (!options.png.empty()) {
        const std::string title =
            fmt::format("{}: {} FROM {} TO {} STEP {}", std::filesystem::path(options.file).filename().string(),
                        options.parameter, settings.values.front(), settings.values.back(), range.step);
        files.add(options.png, explore::encodePng(explore::plotExploration(result, title)));
    }
    files.commit();
    reportWritten({options.runsCsv, options.summaryCsv, options.png});
}

} // namespace

void addExploreCommand(CLI::App& app) {
    auto options = std::make_shared<ExploreOptions>();
    CLI::App* command = app.add_subcommand(
        "explore", "Sweep one const over a range with several seeds; report solid fraction, surface area, IoU");
    command->add_option("file", options->file, "The .vox file")->required();
    command->add_option("--param", options->parameter, "The const to sweep")->required();
    command->add_option("--range", options->range, "Values A:B:STEP (A, A+STEP, ... <= B), e.g. 0.3:0.7:0.1")
        ->required();
    command->add_option("--runs", options->runs, "Seeds per value (1..1000, default 4)");
    command->add_option("--seed", options->seed, "First seed (default: the file's); runs use SEED..SEED+RUNS-1");
    command->add_option("--iso", options->iso, "Density at or above which a voxel is solid (default 0.5)");
    command->add_option("--size", options->size, "Generate at this world size instead, e.g. 32,32,32");
    command->add_option("--csv", options->runsCsv, "Write one row per (value, run) to this .csv");
    command->add_option("--summary", options->summaryCsv, "Write one row per value (means, stddevs, IoU) to this .csv");
    command->add_option("--png", options->png, "Write the plot of descriptors against the parameter to this .png");
    addConsoleFlags(*command);
    command->callback([options] { exploreFile(*options); });
}

} // namespace voxc::driver
