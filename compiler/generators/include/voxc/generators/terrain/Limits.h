#pragma once
// Every size and amount of work of the heightfield terrain generator (docs/terrain.md), bounded in
// one place, and the two typed errors its checks throw. Both are UserErrors: the numbers come
// from the user's map, and the checker will locate them next session.
#include "voxc/generators/WorkErrors.h"

#include <utility>

#include <cstdint>
#include <string>

namespace voxc::terrain {

struct Limits {
    int32_t minLevel = 1;                       // 2x2 cells: the smallest grid a cascade may start on
    int32_t maxLevel = 12;                      // 4096x4096 cells (16.8 M cells per field)
    uint32_t maxSplines = 1024;
    uint32_t maxCurvesPerSpline = 1024;         // cubic Bezier pieces of one spline
    uint32_t maxMetaPointsPerSpline = 4096;
    uint32_t maxSamplings = 4096;               // samples per Bezier piece when rasterising
    uint64_t maxSplineSamples = 50'000'000;     // sum over splines and their levels of pieces * samplings
    uint64_t maxRasterCells = 400'000'000;      // cell-centre tests over all quads of all levels
    uint32_t maxIterationsPerLevel = 1'000'000; // diffusion sweeps or erosion steps on one level
    uint64_t maxDiffusionCellUpdates = 20'000'000'000; // terrain sweeps plus the five half-rate fields
    uint64_t maxErosionCellSteps = 20'000'000'000;     // sum over levels of 4^L * steps, drain included
};

// A size or an amount of work over its limit (generators::LimitError, naming "terrain").
struct LimitError : generators::LimitError {
    LimitError(std::string quantity, uint64_t value, uint64_t limit)
        : generators::LimitError("terrain", std::move(quantity), value, limit) {}
};

// A parameter outside its valid range, or a combination that makes the scheme unstable (e.g. "K_e*dt").
struct ParameterError : generators::ParameterError {
    ParameterError(std::string parameter, double value, std::string requirement)
        : generators::ParameterError("terrain", std::move(parameter), value, std::move(requirement)) {}
};

} // namespace voxc::terrain
