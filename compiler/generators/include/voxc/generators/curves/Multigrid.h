#pragma once
// The linear solves (spec A3.4 laplace, A3.5, schedule A5): sum over in-box face neighbours of
// (u_j - u_i) = 0 off the Dirichlet mask, homogeneous Neumann at the box faces, by geometric
// multigrid in float32 with the fixed operation order of docs/curves.md.
#include "voxc/generators/curves/Grid.h"
#include "voxc/generators/curves/Limits.h"

#include <string>

namespace voxc::curves {

struct SolveReport {
    std::string name;
    int32_t levels = 0;
    std::vector<float> residuals; // max residual after FMG (index 0) and after each V-cycle
    int32_t cycles() const { return int32_t(residuals.size()) - 1; }
};

// Solves the components together: one schedule, one cycle count, stopped when the largest
// residual of any component is <= tolerance (so a uniform constraint direction stays exact).
// Cells with fixed[i] != 0 keep their values bitwise. Throws ConvergenceError past the cap.
SolveReport solveLaplace(const std::string& name, const std::vector<uint8_t>& fixed, std::vector<Field3*> components,
                         float tolerance, const Limits& limits);

// max over free cells of |sum_j (u_j - u_i)|, the quantity the schedule stops on.
float maxResidual(const std::vector<uint8_t>& fixed, const Field3& u);

} // namespace voxc::curves
