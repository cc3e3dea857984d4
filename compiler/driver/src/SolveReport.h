#pragma once
// The lines `voxc run` and `voxc interp` print about the pipeline's global solves.
#include "voxc/program/Program.h"

#include <string>

namespace voxc::driver {

// Per curves stage of the pipeline: its box and, per solve, multigrid levels, V-cycles and the
// max residual after the full-multigrid start and at the end. Empty without curves stages.
std::string formatSolveReport(const Program& program);

} // namespace voxc::driver
