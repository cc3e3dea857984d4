#pragma once
// Firing counts per rule, for the summary `voxc interp --trace` prints after a run.
#include "voxc/program/Program.h"

#include <cstdint>
#include <string>
#include <vector>

namespace voxc {

struct FireStats {
    // Sized by the interpreter on first use: firings[grammar][rule], anchors[grammar].
    std::vector<std::vector<uint64_t>> firings;
    std::vector<uint64_t> anchors; // windows tested (per iteration, sweep and phase)
};

// One line per grammar ("grammar overhang: 4096 anchors tested, 37 firings") then one
// indented line per rule ("  erode_base 12"), in declaration order.
std::string formatFireStats(const Program& program, const FireStats& stats);

} // namespace voxc
