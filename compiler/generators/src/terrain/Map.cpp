#include "voxc/generators/terrain/Map.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace voxc::terrain {

LimitError::LimitError(std::string quantity_, uint64_t value_, uint64_t limit_)
    : UserError(fmt::format("terrain: {} is {}, over the limit of {}", quantity_, value_, limit_)),
      quantity(std::move(quantity_)), value(value_), limit(limit_) {}

ParameterError::ParameterError(std::string parameter_, double value_, std::string requirement_)
    : UserError(fmt::format("terrain: {} = {} is invalid: {}", parameter_, value_, requirement_)),
      parameter(std::move(parameter_)), value(value_), requirement(std::move(requirement_)) {}

double Domain::cellSize(int32_t level) const { return size / std::ldexp(1.0, level); }

namespace {

void requireFinite(const char* name, double value) {
    if (!std::isfinite(value)) throw ParameterError(name, value, "must be finite");
}

void requireAtLeast(const char* name, double value, double minimum) {
    requireFinite(name, value);
    if (value < minimum) throw ParameterError(name, value, fmt::format("must be >= {}", minimum));
}

void validateMetaPoint(const MetaPoint& meta, uint32_t pieces) {
    requireFinite("u", meta.u);
    if (meta.u < 0.0 || meta.u > double(pieces)) throw ParameterError("u", meta.u, fmt::format("must lie in [0, {}]", pieces));
    requireAtLeast("radius", meta.radius, 0.0);
    requireAtLeast("left.width", meta.left.x, 0.0);
    requireFinite("left.height", meta.left.y);
    requireAtLeast("right.width", meta.right.x, 0.0);
    requireFinite("right.height", meta.right.y);
    requireAtLeast("hardness", meta.hardness, 0.0);
    if (meta.hardness > 1.0) throw ParameterError("hardness", meta.hardness, "must be <= 1 (alpha + beta <= 1)");
    for (auto [name, value] : {std::pair{"noise_amplitude", meta.noiseAmplitude}, {"noise_roughness", meta.noiseRoughness},
                               {"warp_low", meta.warpLow}, {"warp_high", meta.warpHigh}, {"rain", meta.rain},
                               {"capacity", meta.capacity}})
        requireFinite(name, value);
}

} // namespace

void validateMap(const TerrainMap& map, const Limits& limits) {
    const Domain& domain = map.domain;
    if (domain.minLevel < limits.minLevel || domain.maxLevel > limits.maxLevel || domain.minLevel > domain.maxLevel)
        throw ParameterError("levels", domain.maxLevel,
                             fmt::format("need {} <= min level ({}) <= max level <= {}", limits.minLevel, domain.minLevel, limits.maxLevel));
    requireFinite("origin.x", domain.origin.x);
    requireFinite("origin.z", domain.origin.y);
    requireFinite("size", domain.size);
    if (domain.size <= 0.0) throw ParameterError("size", domain.size, "must be > 0");
    requireFinite("max_height", domain.maxHeight);
    if (domain.maxHeight <= 0.0) throw ParameterError("max_height", domain.maxHeight, "must be > 0");
    requireAtLeast("noise.amplitude", map.noise.amplitude, 0.0);
    requireFinite("noise.scale", map.noise.scale);
    requireAtLeast("diffusion.multiplier", map.diffusion.multiplier, 0.0);
    if (map.splines.size() > limits.maxSplines) throw LimitError("the number of splines", map.splines.size(), limits.maxSplines);
    for (const Spline& spline : map.splines) {
        const size_t points = spline.controlPoints.size();
        if (points < 4 || (points - 1) % 3 != 0)
            throw ParameterError("control points", double(points), "a spline needs 3 * pieces + 1 control points (4, 7, 10, ...)");
        if (spline.pieces() > limits.maxCurvesPerSpline) throw LimitError("the Bezier pieces of a spline", spline.pieces(), limits.maxCurvesPerSpline);
        if (spline.metaPoints.size() > limits.maxMetaPointsPerSpline)
            throw LimitError("the meta points of a spline", spline.metaPoints.size(), limits.maxMetaPointsPerSpline);
        if (spline.samplings == 0 || spline.samplings > limits.maxSamplings)
            throw LimitError("samplings", spline.samplings, limits.maxSamplings);
        if (spline.minLevel > spline.maxLevel)
            throw ParameterError("spline levels", spline.minLevel, fmt::format("min level must be <= max level ({})", spline.maxLevel));
        for (const glm::dvec3& point : spline.controlPoints) {
            requireFinite("control point x", point.x);
            requireFinite("control point y", point.y);
            requireFinite("control point z", point.z);
        }
        double previousU = 0.0;
        for (const MetaPoint& meta : spline.metaPoints) {
            validateMetaPoint(meta, spline.pieces());
            if (meta.u < previousU) throw ParameterError("u", meta.u, "meta points must be sorted by u");
            previousU = meta.u;
        }
    }
    // Diffusion work: every level's terrain sweeps plus the 8 half-rate channels (2 normal + 6 parameter).
    uint64_t work = 0;
    for (int32_t level = domain.minLevel; level <= domain.maxLevel; ++level) {
        const uint64_t cells = uint64_t(1) << (2 * level);
        const uint32_t sweeps = terrainSweeps(map.diffusion, level);
        if (sweeps > limits.maxIterationsPerLevel) throw LimitError("diffusion sweeps on one level", sweeps, limits.maxIterationsPerLevel);
        work += cells * (uint64_t(sweeps) + 8 * uint64_t(fieldSweeps(map.diffusion, level)));
    }
    if (work > limits.maxDiffusionCellUpdates) throw LimitError("diffusion cell updates", work, limits.maxDiffusionCellUpdates);
}

uint32_t terrainSweeps(const DiffusionSettings& settings, int32_t level) {
    double base = double(level);
    if (settings.rule == IterationRule::Side) base = std::ldexp(1.0, level);
    if (settings.rule == IterationRule::SqrtSide) base = std::sqrt(std::ldexp(1.0, level));
    const double sweeps = std::floor(base * settings.multiplier + 0.5);
    // Clamped to 2^32 - 1 so an absurd multiplier reaches the LimitError, not an overflow.
    return uint32_t(std::clamp(sweeps, 1.0, 4294967295.0));
}

uint32_t fieldSweeps(const DiffusionSettings& settings, int32_t level) {
    return std::max<uint32_t>(1, terrainSweeps(settings, level) / 2);
}

} // namespace voxc::terrain
