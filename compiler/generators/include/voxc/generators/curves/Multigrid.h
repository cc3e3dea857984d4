#pragma once
// The linear solves (spec A3.4 laplace, A3.5, schedule A5): sum over in-box face neighbours of
// (u_j - u_i) = 0 off the Dirichlet mask, homogeneous Neumann at the box faces, by geometric
// multigrid in float32 with the fixed operation order of docs/curves.md.
#include "voxc/core/Stopped.h"
#include "voxc/generators/curves/Grid.h"
#include "voxc/generators/curves/Limits.h"
#include "voxc/program/SolveTable.h"

#include <functional>
#include <string>

namespace voxc::curves {

struct SolveReport {
    std::string name;
    int32_t levels = 0;
    std::vector<float> residuals; // max residual after FMG (index 0) and after each V-cycle
    std::vector<LevelResidual> fullMultigrid; // SolveSummary::fullMultigrid (host solves only)
    int32_t cycles() const { return int32_t(residuals.size()) - 1; }
};

// The schedule's constants: V(3,3) cycles, 50 red-black sweeps on the coarsest level.
inline constexpr int32_t kPreSmooth = 3, kPostSmooth = 3, kCoarsestSweeps = 50;
// The smoother's over-relaxation: a relaxed cell takes u + omega * (gauss_seidel - u).
inline constexpr float kOverRelaxation = 1.5f;

// One level of the hierarchy, finest first: its size, the axes the next (coarser) level halves
// (none on the coarsest) and its stencil weight per axis (1 / cell width^2 in finest cells, exact).
struct MultigridLevel {
    glm::ivec3 size{1};
    glm::ivec3 halved{0};
    glm::vec3 weight{1.0f};
};
std::vector<MultigridLevel> multigridLevels(glm::ivec3 size);
// Every level's Dirichlet mask: a coarse cell is fixed iff any child is.
std::vector<std::vector<uint8_t>> multigridMasks(const std::vector<MultigridLevel>& levels,
                                                 const std::vector<uint8_t>& fixed);

// Solves the components together: one schedule, one cycle count, stopped when the largest
// residual of any component is <= tolerance (so a uniform constraint direction stays exact).
// Cells with fixed[i] != 0 keep their values bitwise. Throws ConvergenceError past the cap (the
// free cells then hold the last iterate).
SolveReport solveLaplace(const std::string& name, const std::vector<uint8_t>& fixed, std::vector<Field3*> components,
                         float tolerance, const Limits& limits);
// solveLaplace that throws voxc::Stopped before its next V-cycle once `stop` is requested.
SolveReport solveLaplaceUntilStopped(const std::string& name, const std::vector<uint8_t>& fixed,
                                     std::vector<Field3*> components, float tolerance, const Limits& limits,
                                     const std::stop_token& stop);

// How a curves solve runs its linear solves: solveLaplace on the host, or the same schedule on a
// Vulkan device (voxc/vulkan/GpuMultigrid.h), bit for bit on lavapipe.
using LinearSolver = std::function<SolveReport(const std::string& name, const std::vector<uint8_t>& fixed,
                                               std::vector<Field3*> components, float tolerance, const Limits& limits)>;

// max over free cells of |sum_j (u_j - u_i)|, the quantity the schedule stops on.
float maxResidual(const std::vector<uint8_t>& fixed, const Field3& u);

} // namespace voxc::curves
