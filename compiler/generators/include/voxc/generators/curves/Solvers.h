#pragma once
// Where a curves solve runs its global passes (docs/curves.md, "What runs where"): each member
// has the host function's signature and contract, and an empty member runs the host's loop.
// voxc/vulkan/GpuCurves.h fills them with the same passes on a Vulkan device.
#include "voxc/generators/curves/Diffuse.h"
#include "voxc/generators/curves/Multigrid.h"
#include "voxc/generators/curves/Propagate.h"

#include <functional>
#include <stop_token>
#include <utility>

namespace voxc::curves {

// Perona-Malik (b): `sweeps` Jacobi sweeps on the filled field `normals` (host: peronaMalikSweeps).
using PeronaMalikSweeper = std::function<void(const Constraints& constraints, NormalField& normals, float k, uint32_t sweeps)>;
// smoothBinomial's contract.
using Smoother = std::function<Field3(const Field3& field, int32_t passes)>;
// propagateMaterial's contract.
using MaterialPropagator = std::function<MaterialField(const Constraints& constraints)>;
// propagateSurface's contract.
using SurfacePropagator = std::function<SurfaceField(const Constraints& constraints, const Field3& nx, const Field3& ny,
                                                     const Field3& nz, PropagateRule rule)>;
// The noise displacement of every cell of `smoothed.box`: alpha * warped_fbm(f0 * p, beta, 0, 0,
// seed) at the cell's grid-local voxel p, 0 where alpha is 0 (solveScene's D); or none (empty):
// then the host evaluates it, only where it can change the density.
using Displacer = std::function<std::vector<float>(const Field3& amplitude, const Field3& roughness, float frequency,
                                                   uint32_t seed)>;

struct Solvers {
    LinearSolver linear;
    PeronaMalikSweeper peronaMalik;
    Smoother smoothing;
    MaterialPropagator material;
    SurfacePropagator surface;
    Displacer displacement;
    // Asked to stop, the solve throws voxc::Stopped at its next boundary: before each pass, and
    // before each V-cycle of the host's linear solves (a device's run theirs whole).
    std::stop_token stop;

    Solvers() = default;
    // Only the linear solves replaced (the first device pass; callers that hand a LinearSolver).
    Solvers(LinearSolver linearSolver) : linear(std::move(linearSolver)) {}
};

} // namespace voxc::curves
