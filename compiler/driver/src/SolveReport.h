#pragma once
// The lines `voxc run` and `voxc interp` print about the pipeline's global solves.
#include "voxc/program/Program.h"

#include <string>

namespace voxc::driver {

// Per curves stage of the pipeline: its box and, per solve, multigrid levels, V-cycles and the
// max residual after the full-multigrid start and at the end; with `perCycle` (voxc interp
// --trace) also a line per solve listing the max residual after each cycle. Empty without
// curves stages. `multigridDevice`: the Vulkan device the curves' multigrid ran on (voxc run
// --solve-on), empty when it ran on the host.
std::string formatSolveReport(const Program& program, bool perCycle = false, const std::string& multigridDevice = "");

} // namespace voxc::driver
