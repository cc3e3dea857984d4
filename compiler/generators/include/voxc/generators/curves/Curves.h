#pragma once
// The feature-curve generator's CPU core (Becher et al., spec Part A, docs/curves.md): voxelise
// the curves into the solve box, diffuse normals, noise parameters and materials, propagate the
// signed surface and smooth it. The result is what a solve stage will hand to field kernels.
#include "voxc/generators/curves/Solvers.h"

#include <string>
#include <utility>

namespace voxc::curves {

enum class NormalMode { Laplace, PeronaMalik };

struct Options {
    NormalMode normals = NormalMode::Laplace;
    float k = 0.01f;              // Perona-Malik edge threshold, as the paper prints
    uint32_t sweeps = 0;          // Perona-Malik sweeps; 0 = the largest box axis
    PropagateRule propagate = PropagateRule::SmallestMagnitude;
    SeedValue seedValue = SeedValue::PlaneDistance;
    int32_t smoothPasses = 1;
};

struct Result {
    Field3 normalX, normalY, normalZ;   // normalised; 0 where no normal
    Field3 amplitude, roughness;
    MaterialField material;
    SurfaceField surface;               // raw S
    Field3 smoothed;                    // S after smoothPasses
    std::vector<SolveReport> solves;    // normals (laplace mode), parameters
    // Wall time of each part in order ("voxelize", "normals", then "fronts" (the host's material
    // and surface fronts, run side by side) or "material" and "surface" (either on a device),
    // "parameters", "smoothing"), for reports and benchmarks only: nothing computed depends on it.
    std::vector<std::pair<std::string, double>> phaseMs;
};

// Validates options (ParameterError, LimitError) and runs the stages on given constraints, each
// global pass through its member of `solvers` (empty: the host's loop).
Result solveCurves(const Constraints& constraints, const Options& options, const Limits& limits,
                   const Solvers& solvers = {});
// The same on constraints it may consume: N0, alpha0 and beta0 become the linear solves'
// unknowns (moved, not copied: five fields of fresh memory fewer).
Result solveCurves(Constraints&& constraints, const Options& options, const Limits& limits,
                   const Solvers& solvers = {});

// voxelize then solveCurves.
Result runCurves(const std::vector<FeatureCurve>& curves, const Box& box, const Options& options, const Limits& limits,
                 const Solvers& solvers = {});

} // namespace voxc::curves
