#pragma once
// How far back into the grid a grammar's result at a voxel reaches (its dependency cone), from
// the execution order of Semantics.h alone: the grammar stage's dependency radius.
#include "voxc/program/Program.h"

#include <string>

namespace voxc::stages {

// Per axis, the largest distance from a voxel to a voxel of the grid before the grammar that its
// value after the grammar can depend on, over every position of the voxel, capped at `cap`.
//
// Backwards from the last phase: a voxel's value after a phase depends on the window of that
// phase that holds it (if any) and on every window whose stamps reach it (the window grown by
// the sweep's largest stamp reach). So per axis the cone [lo, hi] of a voxel grows, phase by phase
// from the last, to the start of the window holding lo and the end of the one holding hi. The
// anchor lattice is taken without its bounds (fewer windows only shrink a cone), so the map is
// periodic in the position with period stride * lcm(phase counts), which bounds the positions
// tried. A box of per-axis cones holds the true (window-shaped) cone, so the radius is safe; it is
// exact along an axis whenever a rule can carry a value across a whole window along it.
glm::ivec3 grammarConeRadius(const Grammar& grammar, glm::ivec3 cap);

// The grammar's sweeps as --explain-halo prints them: "sweeps [3, 3, 1] in 9 phases, [2, 1, 1] in 2
// phases" and a sweep's stamp reach ("stamps reaching [2, 8, 2]").
std::string describeSweeps(const Grammar& grammar);

} // namespace voxc::stages
