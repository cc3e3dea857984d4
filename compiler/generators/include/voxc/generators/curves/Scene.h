#pragma once
// A `curves` block's whole solve, from curves to the table a pipeline stage combines with the
// grid (docs/curves.md, "The stage"): runCurves, then the noise displacement and the density
// of spec A3.7, and the material where the density is solid.
#include "voxc/generators/curves/Curves.h"
#include "voxc/program/SolveTable.h"

namespace voxc::curves {

struct Scene {
    std::vector<FeatureCurve> curves;
    Box box;                        // grid-local voxels
    Options options;
    float noiseFrequency = 0.0625f; // f0, per voxel
    uint32_t noiseSeed = 0;         // the displacement's warped_fbm seed
};

// density(S' - D, 2) = clamp(0.5 - (S' - D) / 2, 0, 1) per cell (0 where S' is +infinity: no
// seed reaches the cell), D = alpha * warped_fbm(f0 * p, beta, 0, 0, seed) at the cell's
// grid-local voxel p (0 where alpha is 0), all in float32 in that order; the material is the
// propagated one where the density is >= 0.5, else 0, and is left empty when no constraint
// point names a material. Throws ParameterError, LimitError and ConvergenceError. The linear
// solves run through `solver` (empty: the host's solveLaplace).
SolveTable solveScene(const Scene& scene, const Limits& limits, const LinearSolver& solver = {});

} // namespace voxc::curves
