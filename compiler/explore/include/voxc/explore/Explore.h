#pragma once
// `voxc explore`: generate a file's volume over a sweep of one `const` and several seeds, and
// reduce every volume to descriptors (docs/explore.md).
#include "voxc/explore/Descriptors.h"
#include "voxc/grid/Grid.h"
#include "voxc/program/Program.h"
#include "voxc/syntax/SourceFile.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace voxc::explore {

constexpr uint32_t kMaxRuns = 1000;

struct ExploreSettings {
    std::string parameter;             // a `const` of the file
    std::vector<double> values;        // see sweepValues()
    uint32_t runs = 1;                 // seeds seedBase .. seedBase + runs - 1 (mod 2^32), 1..kMaxRuns
    std::optional<uint32_t> seedBase;  // default: the world seed the file gives for each value
    float iso = 0.5f;                  // solid: density >= iso
    // Replaces the world size after checking, to explore cheaply; grammar bounds are clipped to it.
    std::optional<glm::ivec3> size;
    // Generates one volume; default: the CPU interpreter (voxc::interpret).
    std::function<DenseGrid(const Program&)> generate;
    // Called before each run, e.g. to report progress.
    std::function<void(double value, uint32_t run, uint32_t seed)> onRun;
};

struct RunRecord {
    uint32_t run = 0;
    uint32_t seed = 0;
    VolumeDescriptors descriptors;
};

struct ValueSummary {
    double value = 0.0;
    std::vector<RunRecord> runs;
    MeanDeviation solidFraction;
    MeanDeviation surfaceArea;
    std::optional<MeanDeviation> iou; // over pairs of runs; none with a single run
};

struct ExploreResult {
    std::string parameter;
    float iso = 0.5f;
    glm::ivec3 size{0};            // the world size the volumes were generated at
    std::vector<ValueSummary> values;
    std::string warnings;          // the checker's warnings for the first value, rendered
};

// Checks `source` with `parameter` overridden to `value` (CheckOptions::constOverrides) and, when
// given, the world's seed replaced (CheckOptions::seed). Throws UserError carrying the rendered
// diagnostics when there are errors.
Program checkWithParameter(const SourceFile& source, const std::string& parameter, double value,
                           std::string* warnings = nullptr, std::optional<uint32_t> seed = std::nullopt);

// Applies ExploreSettings::size: the world size becomes `size` and grammar bounds are clipped.
void resizeWorld(Program& program, glm::ivec3 size);

// Validates the settings (UserError), then for every value checks the file, runs it `runs` times
// and summarises. Deterministic: the same settings give the same result.
ExploreResult runExploration(const SourceFile& source, const ExploreSettings& settings);

} // namespace voxc::explore
