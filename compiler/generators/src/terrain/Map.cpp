#include "voxc/generators/terrain/Map.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <string>

namespace voxc::terrain {

double Domain::cellSize(int32_t level) const { return size / std::ldexp(1.0, level); }

namespace {

// Ranges keep every intermediate float32 value finite (docs/terrain.md, "Value ranges").
constexpr double kMaxCoordinate = 1e9; // world voxels: positions, sizes, widths, heights
constexpr double kMinSize = 1e-3;      // world voxels: the domain's edge
constexpr double kMinHeight = 1.0;     // world voxels: max_height, so normalised heights stay <= 1e9
constexpr double kMaxScale = 1e6;      // noise scale and diffusion multiplier

void requireRange(const std::string& name, double value, double minimum, double maximum) {
    if (!std::isfinite(value)) throw ParameterError(name, value, "must be finite");
    if (value < minimum || value > maximum) throw ParameterError(name, value, fmt::format("must lie in [{}, {}]", minimum, maximum));
}

void validateMetaPoint(const MetaPoint& meta, uint32_t pieces) {
    requireRange("u", meta.u, 0.0, double(pieces));
    requireRange("radius", meta.radius, 0.0, kMaxCoordinate);
    requireRange("left.width", meta.left.x, 0.0, kMaxCoordinate);
    requireRange("left.height", meta.left.y, -kMaxCoordinate, kMaxCoordinate);
    requireRange("right.width", meta.right.x, 0.0, kMaxCoordinate);
    requireRange("right.height", meta.right.y, -kMaxCoordinate, kMaxCoordinate);
    requireRange("hardness", meta.hardness, 0.0, 1.0); // alpha + beta <= 1
    requireRange("noise_amplitude", meta.noiseAmplitude, -kMaxMetaFactor, kMaxMetaFactor);
    requireRange("noise_roughness", meta.noiseRoughness, 0.0, 1.0);
    requireRange("warp_low", meta.warpLow, -kMaxMetaFactor, kMaxMetaFactor);
    requireRange("warp_high", meta.warpHigh, -kMaxMetaFactor, kMaxMetaFactor);
    requireRange("rain", meta.rain, 0.0, kMaxMetaFactor);
    requireRange("capacity", meta.capacity, 0.0, kMaxMetaFactor);
}

void validateSpline(const Spline& spline, const Limits& limits) {
    const size_t points = spline.controlPoints.size();
    if (points < 4 || (points - 1) % 3 != 0)
        throw ParameterError("control points", double(points), "a spline needs 3 * pieces + 1 control points (4, 7, 10, ...)");
    if (spline.pieces() > limits.maxCurvesPerSpline) throw LimitError("the Bezier pieces of a spline", spline.pieces(), limits.maxCurvesPerSpline);
    if (spline.metaPoints.size() > limits.maxMetaPointsPerSpline)
        throw LimitError("the meta points of a spline", spline.metaPoints.size(), limits.maxMetaPointsPerSpline);
    if (spline.samplings == 0) throw ParameterError("samplings", 0.0, "must be >= 1");
    if (spline.samplings > limits.maxSamplings) throw LimitError("samplings", spline.samplings, limits.maxSamplings);
    if (spline.minLevel > spline.maxLevel)
        throw ParameterError("spline levels", spline.minLevel, fmt::format("min level must be <= max level ({})", spline.maxLevel));
    for (const glm::dvec3& point : spline.controlPoints) {
        requireRange("control point x", point.x, -kMaxCoordinate, kMaxCoordinate);
        requireRange("control point y", point.y, -kMaxCoordinate, kMaxCoordinate);
        requireRange("control point z", point.z, -kMaxCoordinate, kMaxCoordinate);
    }
    double previousU = 0.0;
    for (const MetaPoint& meta : spline.metaPoints) {
        validateMetaPoint(meta, spline.pieces());
        if (meta.u < previousU) throw ParameterError("u", meta.u, "meta points must be sorted by u");
        previousU = meta.u;
    }
}

} // namespace

void validateMap(const TerrainMap& map, const Limits& limits) {
    const Domain& domain = map.domain;
    if (domain.minLevel < limits.minLevel || domain.maxLevel > limits.maxLevel || domain.minLevel > domain.maxLevel)
        throw ParameterError("levels", domain.maxLevel,
                             fmt::format("need {} <= min level ({}) <= max level <= {}", limits.minLevel, domain.minLevel, limits.maxLevel));
    requireRange("origin.x", domain.origin.x, -kMaxCoordinate, kMaxCoordinate);
    requireRange("origin.z", domain.origin.y, -kMaxCoordinate, kMaxCoordinate);
    requireRange("size", domain.size, kMinSize, kMaxCoordinate);
    requireRange("max_height", domain.maxHeight, kMinHeight, kMaxCoordinate);
    requireRange("noise.amplitude", map.noise.amplitude, 0.0, kMaxCoordinate);
    requireRange("noise.scale", map.noise.scale, -kMaxScale, kMaxScale);
    requireRange("diffusion.multiplier", map.diffusion.multiplier, 0.0, kMaxScale);
    if (map.splines.size() > limits.maxSplines) throw LimitError("the number of splines", map.splines.size(), limits.maxSplines);
    uint64_t samples = 0;
    for (const Spline& spline : map.splines) {
        validateSpline(spline, limits);
        const int32_t levels = std::min(spline.maxLevel, domain.maxLevel) - std::max(spline.minLevel, domain.minLevel) + 1;
        samples += uint64_t(std::max(levels, 0)) * spline.pieces() * spline.samplings;
    }
    if (samples > limits.maxSplineSamples) throw LimitError("spline samples over all levels", samples, limits.maxSplineSamples);
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
