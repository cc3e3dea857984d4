#include "voxc/explore/Explore.h"

#include "voxc/check/Check.h"
#include "voxc/core/Errors.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/stages/Pipeline.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <glm/common.hpp>

namespace voxc::explore {

namespace {

void validate(const ExploreSettings& settings) {
    if (settings.parameter.empty()) throw UserError("--param: the name of a `const` of the file is required");
    if (settings.values.empty()) throw UserError("the sweep has no values");
    if (settings.runs < 1 || settings.runs > kMaxRuns)
        throw UserError(fmt::format("--runs {}: must be from 1 to {}", settings.runs, kMaxRuns));
    if (!std::isfinite(settings.iso)) throw UserError("--iso must be a finite number");
    if (settings.size) {
        const glm::ivec3 s = *settings.size;
        if (s.x < 1 || s.y < 1 || s.z < 1 || int64_t(s.x) * s.y * s.z > Limits{}.maxVoxels)
            throw UserError(fmt::format("--size {}x{}x{}: each axis must be >= 1 and the grid at most {} voxels",
                                        s.x, s.y, s.z, Limits{}.maxVoxels));
    }
}

// Each run checks the file again with its seed, so everything seeded while checking (features,
// carves, solves) varies with it as well as the grammars' choices.
ValueSummary exploreValue(const SourceFile& source, double value, const ExploreSettings& settings,
                          uint32_t fileSeed) {
    ValueSummary summary;
    summary.value = value;
    const uint32_t seedBase = settings.seedBase.value_or(fileSeed);
    std::vector<SolidSet> sets;
    std::vector<double> fractions, areas;
    for (uint32_t run = 0; run < settings.runs; ++run) {
        // The seed wraps modulo 2^32 like the seed itself.
        Program program = checkWithParameter(source, settings.parameter, value, nullptr, seedBase + run);
        if (settings.size) resizeWorld(program, *settings.size);
        if (settings.onRun) settings.onRun(value, run, program.world.seed);
        const DenseGrid grid = settings.generate ? settings.generate(program) : interpret(program);
        VOXC_ASSERT(grid.size() == program.world.size);
        const VolumeDescriptors descriptors = describeVolume(grid, settings.iso);
        summary.runs.push_back({run, program.world.seed, descriptors});
        fractions.push_back(descriptors.solidFraction);
        areas.push_back(descriptors.surfaceArea);
        sets.push_back(solidSet(grid, settings.iso));
    }
    summary.solidFraction = meanDeviation(fractions);
    summary.surfaceArea = meanDeviation(areas);
    summary.iou = pairwiseIou(sets);
    return summary;
}

} // namespace

Program checkWithParameter(const SourceFile& source, const std::string& parameter, double value,
                           std::string* warnings, std::optional<uint32_t> seed) {
    CheckOptions options;
    options.constOverrides[parameter] = value;
    options.seed = seed;
    CheckResult result = checkSource(source, options);
    if (result.hasErrors() || !result.program) {
        std::string rendered = result.rendered();
        while (!rendered.empty() && rendered.back() == '\n') rendered.pop_back();
        throw UserError(fmt::format("with {} = {}, {} does not check:\n{}", parameter, value, source.path(),
                                    rendered));
    }
    if (warnings) *warnings = result.rendered();
    return std::move(*result.program);
}

void resizeWorld(Program& program, glm::ivec3 size) {
    program.world.size = size;
    for (Grammar& grammar : program.grammars) {
        grammar.boundsMin = glm::min(grammar.boundsMin, size);
        grammar.boundsMax = glm::min(grammar.boundsMax, size);
    }
}

ExploreResult runExploration(const SourceFile& source, const ExploreSettings& settings) {
    validate(settings);
    ExploreResult result;
    result.parameter = settings.parameter;
    result.iso = settings.iso;
    for (size_t i = 0; i < settings.values.size(); ++i) {
        const double value = settings.values[i];
        Program program = checkWithParameter(source, settings.parameter, value, i == 0 ? &result.warnings : nullptr);
        if (settings.size) resizeWorld(program, *settings.size);
        result.size = program.world.size;
        result.values.push_back(exploreValue(source, value, settings, program.world.seed));
    }
    return result;
}

} // namespace voxc::explore
