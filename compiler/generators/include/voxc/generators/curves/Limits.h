#pragma once
// Every size and amount of work of the feature-curve generator (docs/curves.md), bounded in one
// place, and the typed errors its checks throw. All are UserErrors: the numbers come from the
// user's curves and box, and the checker will locate them once the generator has a syntax.
#include "voxc/generators/WorkErrors.h"

#include <utility>

#include <cstdint>
#include <string>

namespace voxc::curves {

struct Limits {
    uint64_t maxBoxCells = 16'777'216;          // 256x256x256 solve cells (about 46 B per cell)
    int32_t maxBoxAxis = 4096;
    double maxCoordinate = 1e6;                 // |control vertex|, |bitangent| and box bounds, voxels
    uint32_t maxCurves = 1024;
    uint32_t maxControlPoints = 4096;           // per curve
    uint32_t maxConstraintPoints = 4096;        // per curve
    uint32_t maxSegmentsPerCurve = 1u << 20;    // the chord-halving refinement stops here
    uint64_t maxSegments = 1u << 22;            // over all curves
    uint64_t maxCellTests = 400'000'000;        // triangle/cell overlap tests over all triangles
    uint64_t maxConstrainedCells = 4'000'000;   // cells hit by a triangle (each gathers sparsely)
    int32_t maxCycles = 30;                     // V-cycles per linear solve after FMG (spec A5)
    uint32_t maxSweeps = 100'000;               // Perona-Malik Jacobi sweeps
    uint64_t maxSweepCellUpdates = 1'000'000'000; // sweeps * cells, each six neighbours' g(): under a minute of one core
    int32_t maxSmoothPasses = 64;
};

// A size or an amount of work over its limit (generators::LimitError, naming "curves").
struct LimitError : generators::LimitError {
    LimitError(std::string quantity, uint64_t value, uint64_t limit)
        : generators::LimitError("curves", std::move(quantity), value, limit) {}
};

// A value outside its valid range, named as the user would write it (e.g. "curve 2 constraint 1 t").
struct ParameterError : generators::ParameterError {
    ParameterError(std::string parameter, double value, std::string requirement)
        : generators::ParameterError("curves", std::move(parameter), value, std::move(requirement)) {}
};

// A linear solve that did not reach its tolerance within Limits::maxCycles V-cycles.
struct ConvergenceError : UserError {
    ConvergenceError(std::string solve, int32_t cycles, double residual, double tolerance);
    std::string solve;
    int32_t cycles;
    double residual;
    double tolerance;
};

} // namespace voxc::curves
