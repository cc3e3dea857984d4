#include "Common.h"
#include "Console.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/syntax/Diagnostics.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <cstdlib>
#include <fmt/format.h>
#include <iostream>

namespace voxc::driver {

void addWorldOverrideFlags(CLI::App& command, WorldOverrides& overrides) {
    command.add_option("--seed", overrides.seed, "Override the world's seed");
    command.add_option("--chunk", overrides.chunk, "Override the chunk size (power of two, 8..64)");
    addMaxWorkFlag(command, overrides);
}

void addDeviceFlag(CLI::App& command, std::string& device) {
    command.add_option("--device", device, "auto (default: a GPU if present), lavapipe, gpu, or an index");
}

namespace {
constexpr double kMaxWorkBudget = 1e18;
} // namespace

void addMaxWorkFlag(CLI::App& command, WorldOverrides& overrides) {
    // A budget is a number of work units (Limits::maxWork, an int64): 1e400 or "inf" is not one,
    // and no budget is not an option (an unbounded run is what the budget is there to refuse).
    auto inRange = [](const std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        return end != text.c_str() && *end == '\0' && value >= 1.0 && value <= kMaxWorkBudget
                   ? std::string()
                   : fmt::format("expects a number from 1 to {:g}, such as 1e12", kMaxWorkBudget);
    };
    command
        .add_option("--max-work", overrides.maxWork,
                    fmt::format("Budget for the pipeline's estimated work (default {:.3g}; docs/language.md, Limits)",
                                double(Limits{}.maxWork)))
        ->check(CLI::Validator(inRange, "WORK"));
}

Program loadProgram(const std::string& path, const WorldOverrides& overrides, bool warningsAsErrors,
                    std::string* sourceText, std::vector<CheckedLsystem>* lsystems) {
    CheckOptions options;
    if (overrides.maxWork)
        options.limits.maxWork = int64_t(*overrides.maxWork);
    options.seed = overrides.seed;
    options.region = overrides.region;
    const auto start = std::chrono::steady_clock::now();
    CheckResult result = checkFile(path, options);
    const std::chrono::duration<double, std::milli> checkTime = std::chrono::steady_clock::now() - start;
    printDiagnostics(result.diagnostics, result.source);
    size_t errors = 0;
    size_t warnings = 0;
    for (const Diagnostic& diagnostic : result.diagnostics)
        (diagnostic.severity == Severity::Error ? errors : warnings)++;
    detail() << fmt::format("checked {} ({} bytes) in {:.1f} ms: {} error{}, {} warning{}\n", path,
                            result.source.text().size(), checkTime.count(), errors, errors == 1 ? "" : "s", warnings,
                            warnings == 1 ? "" : "s");
    for (const CheckedLsystem& lsystem : result.lsystems)
        if (!lsystem.rulesPath.empty())
            detail() << fmt::format("lsystem {} imports the rule file {}\n", lsystem.name, lsystem.rulesPath);
    if (result.program)
        for (const InputFile& input : result.program->inputs)
            detail() << fmt::format("{} {} reads {} ({} bytes){}\n", input.kind, input.block, input.path,
                                    input.bytes->size(),
                                    input.outside ? ", outside the .vox's folder" : "");
    failOnErrors(path, result.diagnostics, warningsAsErrors);
    VOXC_ASSERT(result.program); // a check without errors has a program
    Program program = std::move(*result.program);
    if (sourceText) *sourceText = result.source.text();
    if (lsystems) *lsystems = std::move(result.lsystems);
    if (overrides.chunk) {
        const int32_t c = *overrides.chunk;
        if (c < 8 || c > 64 || (c & (c - 1)) != 0)
            throw UserError(fmt::format("--chunk {}: the chunk size must be a power of two from 8 to 64", c));
        program.world.chunkSize = c;
    }
    return program;
}

std::string formatMaterialCounts(const Program& program, const DenseGrid& grid, float iso) {
    std::array<size_t, 256> counts{};
    for (size_t i = 0; i < grid.data().size(); ++i)
        if (grid.data()[i] > iso) ++counts[grid.materials()[i]];
    std::string line = "solid voxels by material:";
    for (size_t id = 0; id < counts.size(); ++id) {
        if (counts[id] == 0) continue;
        const Material* material = program.findMaterial(uint8_t(id));
        const std::string name = id == kMaterialNone ? "none" : material ? material->name : fmt::format("material{}", id);
        line += fmt::format("{} {} {}", line.back() == ':' ? "" : ",", name, counts[id]);
    }
    if (line.back() == ':') line += " (no solid voxels)";
    return line + "\n";
}

void requireExtension(const std::string& path, std::initializer_list<const char*> extensions, const char* what) {
    for (const char* extension : extensions) {
        const std::string e(extension);
        if (path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0) return;
    }
    std::string list;
    for (const char* extension : extensions) list += fmt::format("{}{}", list.empty() ? "" : ", ", extension);
    throw UserError(fmt::format("{} '{}' must end in {}", what, path, list));
}

void writeGridFiles(OutputFiles& outputs, const std::string& voxelsPath, const std::string& materialsPath,
                    const DenseGrid& grid) {
    if (!voxelsPath.empty()) writeNpy(outputs, voxelsPath, grid);
    if (!materialsPath.empty()) writeMaterialNpy(outputs, materialsPath, grid);
}

void reportWritten(std::initializer_list<std::string> paths) {
    for (const std::string& path : paths)
        if (!path.empty()) status() << "wrote " << path << "\n";
}

} // namespace voxc::driver
