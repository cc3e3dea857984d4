#pragma once
// A `curves` block's whole solve, from curves to the table a pipeline stage combines with the
// grid (docs/curves.md, "The stage"): solveCurves (runCurves without the scene's constraints),
// then the noise displacement and the density
// of spec A3.7, and the material where the density is solid.
#include "voxc/generators/curves/Curves.h"
#include "voxc/program/SolveTable.h"

#include <memory>

namespace voxc::curves {

struct Scene {
    std::vector<FeatureCurve> curves;
    Box box;                        // grid-local voxels
    Options options;
    float noiseFrequency = 0.0625f; // f0, per voxel
    uint32_t noiseSeed = 0;         // the displacement's warped_fbm seed
    // Heightmaps and meshes voxelised after the curves, with the dead zone (Voxelize.h).
    std::vector<std::shared_ptr<const InputSurface>> inputs;
    InputOptions inputOptions;
    // The curves and inputs voxelised into the box (gatherConstraints with options.seedValue) by
    // whoever made the scene and reported its errors (the checker); null: solveScene voxelises them.
    std::shared_ptr<const GatheredConstraints> gathered;
};

// density(S' - D, 2) = clamp(0.5 - (S' - D) / 2, 0, 1) per cell (0 where S' is +infinity: no
// seed reaches the cell), D = alpha * warped_fbm(f0 * p, beta, 0, 0, seed) at the cell's
// grid-local voxel p (0 where alpha is 0), all in float32 in that order; the material is the
// propagated one where the density is >= 0.5, else 0, and is left empty when no constraint
// point names a material. Throws ParameterError, LimitError and ConvergenceError. The global
// passes run through `solvers` (empty members: the host's loops).
// With keepChannels, the table also holds the solve's channels (SolveTable::channels):
// normal_x, normal_y, normal_z (normalised), amplitude, roughness, material (the propagated id,
// every cell), confidence, distance (raw S, +infinity where no seed reaches), smoothed (S') and
// displacement (D). The noise displacement is then evaluated at every cell; otherwise only where
// it can change the density (a band around S' = 0 bounded by warped_fbm's range), with the same
// densities bit for bit.
SolveTable solveScene(const Scene& scene, const Limits& limits, const Solvers& solvers = {},
                      bool keepChannels = false);

} // namespace voxc::curves
