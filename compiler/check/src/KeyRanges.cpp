#include "voxc/check/KeyRanges.h"

#include "voxc/generators/curves/Limits.h"
#include "voxc/generators/lsystem/Definition.h"
#include "voxc/generators/terrain/Map.h"

#include <algorithm>
#include <cstdint>
#include <limits>

namespace voxc {

std::optional<KeyRange> grammarKeyRange(std::string_view block, std::string_view key, const Limits& limits) {
    if (block == "grammar" && key == "iterations") return KeyRange{1.0, double(limits.maxIterations), true};
    if (block != "rule") return std::nullopt;
    if (key == "probability") return KeyRange{0.0, 1.0, false};
    if (key == "priority")
        return KeyRange{double(std::numeric_limits<int32_t>::min()), double(std::numeric_limits<int32_t>::max()), true};
    // One thousandth is the weight's unit; anything that rounds to 0 units is refused.
    if (key == "weight") return KeyRange{0.5 / kWeightUnitsPerOne, 1000.0, false};
    return std::nullopt;
}

namespace {

constexpr double kSeedMax = double(std::numeric_limits<uint32_t>::max());
// terrain::kMaxMetaFactor: the generator's own bound on a meta point's factors.
constexpr double kMeta = terrain::kMaxMetaFactor;
const curves::Limits kCurvesLimits{};
const lsystem::Limits kLsystemLimits{};

// Per kind, in docs/language.md's order. A meta point's keys default to its spline's, so they have
// no `absent` value. The lsystem's turtle ranges are those lsystem::checkDefinition holds them to.
const BlockKey kBlockKeys[] = {
    {"curves", "smoothing", {0, double(kCurvesLimits.maxSmoothPasses), true, 1}},
    {"curves", "noise_frequency", {0, 16, false, 0.0625}},
    {"curves", "noise_seed", {0, kSeedMax, true, 0}},
    {"curves", "dead_zone", {0, 64, true, 2}},
    {"curves", "input_amplitude", {0, 16, false, 0}},
    {"curves", "input_roughness", {0, 1, false, 0.5}},
    {"constraint", "amplitude", {0, 16, false, 0}},
    {"constraint", "roughness", {0, 1, false, 0.5}},
    {"terrain", "max_height", {1, 1e6, false}}, // from 1: the generator's own least height (terrain/Map.cpp)
    {"terrain", "ramp", {0.25, 64, false, 2}},
    {"terrain", "steps_scale", {0, 100, false, 1}},
    {"terrain", "deposit_threshold", {0, 1e6, false, 0.5}},
    {"noise", "amplitude", {0, 1e6, false, 0}},
    {"noise", "scale", {0, 1e6, false, 1}},
    {"noise", "seed", {0, kSeedMax, true, 0}},
    {"spline", "radius", {0, 1e6, false, 0}},
    {"spline", "hardness", {0, 1, false, 0}},
    {"spline", "noise_amplitude", {0, kMeta, false, 0}},
    {"spline", "roughness", {0, 1, false, 0.5}},
    {"spline", "warp_low", {0, kMeta, false, 0}},
    {"spline", "warp_high", {0, kMeta, false, 0}},
    {"spline", "rain", {0, kMeta, false, 1}},
    {"spline", "capacity", {0, kMeta, false, 1}},
    {"meta", "radius", {0, 1e6, false}},
    {"meta", "hardness", {0, 1, false}},
    {"meta", "noise_amplitude", {0, kMeta, false}},
    {"meta", "roughness", {0, 1, false}},
    {"meta", "warp_low", {0, kMeta, false}},
    {"meta", "warp_high", {0, kMeta, false}},
    {"meta", "rain", {0, kMeta, false}},
    {"meta", "capacity", {0, kMeta, false}},
    {"lsystem", "expansions", {0, double(kLsystemLimits.maxExpansions), true, 1}},
    {"lsystem", "seed", {0, kSeedMax, true, 0}},
    {"lsystem", "angle", {0, lsystem::kMaxTurtleAngle, false, 45}},
    {"lsystem", "step", {0, lsystem::kMaxTurtleStep, false, 4}},
    {"lsystem", "angle_delta", {0, lsystem::kMaxTurtleAngle, false, 5}},
    {"lsystem", "step_delta", {0, lsystem::kMaxTurtleStep, false, 1}},
    {"lsystem", "angle_deviation", {0, lsystem::kMaxTurtleAngle, false, 0}},
    {"lsystem", "pitch_limit", {0, lsystem::kMaxTurtlePitch, false, 0}},
};

} // namespace

std::span<const BlockKey> blockKeys(std::string_view block) {
    const BlockKey* first = std::find_if(std::begin(kBlockKeys), std::end(kBlockKeys),
                                         [&](const BlockKey& k) { return k.block == block; });
    const BlockKey* last = std::find_if(first, std::end(kBlockKeys), [&](const BlockKey& k) { return k.block != block; });
    return {first, last};
}

std::optional<KeyRange> blockKeyRange(std::string_view block, std::string_view key) {
    for (const BlockKey& k : blockKeys(block))
        if (k.key == key) return k.range;
    return std::nullopt;
}

} // namespace voxc
