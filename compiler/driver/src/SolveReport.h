#pragma once
// The lines `voxc run` and `voxc interp` print about the pipeline's global solves.
#include "OutputPaths.h"

#include "voxc/core/AtomicWrite.h"
#include "voxc/program/Program.h"

#include <CLI/CLI.hpp>
#include <span>
#include <string>
#include <vector>

namespace voxc::driver {

// Per curves stage of the pipeline (its block solved: stages::solveBlocks): its box and, per solve, multigrid levels, V-cycles and the
// max residual after the full-multigrid start and at the end; with `perCycle` (voxc interp
// --trace) also a line per solve listing the max residual after each cycle. Empty without
// curves stages. `passDevice`: the Vulkan device the curves' global passes (multigrid,
// Perona-Malik sweeps, fronts, smoothing, displacement) ran on (voxc run --solve-on), empty when
// they ran on the host.
std::string formatSolveReport(const Program& program, bool perCycle = false, const std::string& passDevice = "");

// `--dump [BLOCK.]CHANNEL=FILE.npy` (run, interp): one channel of a curves block's solve as a
// float32 .npy over its box, shaped like --voxels (arr[x, y, z] is box cell (x, y, z)).
struct SolveDump {
    std::string block;   // empty: the file's only curves block
    std::string channel; // one of solveDumpChannels()
    std::string path;
};
// density and the channels curves::solveScene keeps (voxc/generators/curves/Scene.h).
std::span<const std::string_view> solveDumpChannels();
void addDumpFlag(CLI::App& command, std::vector<std::string>& specs);
// UserError for a spec without '=', an unknown channel or a path not ending in .npy.
std::vector<SolveDump> parseSolveDumps(const std::vector<std::string>& specs);
// The dumps' paths as outputs for refuseClashingPaths.
std::vector<RolePath> dumpOutputs(std::span<const SolveDump> dumps);
// Adds each dump's file to `outputs` (committed with the command's other files). UserError when
// the block does not exist, or is missing and the file has not exactly one curves block.
void writeSolveDumps(OutputFiles& outputs, const Program& program, std::span<const SolveDump> dumps);

} // namespace voxc::driver
