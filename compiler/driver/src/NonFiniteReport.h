#pragma once
// The warnings `voxc run` and `voxc interp` print for the non-finite densities the stages
// replaced by 0 (docs/language.md, "Non-finite values"; voxc/grid/NonFinite.h).
#include "voxc/grid/NonFinite.h"
#include "voxc/program/Program.h"

#include <span>
#include <string>

namespace voxc::driver {

// One line per stage with a replacement, `counts[i]` belonging to the pipeline entry written at
// `stageLocs[i]`, e.g. "a.vox:9:23: warning: stage `union pole`: 3840 non-finite densities replaced
// by 0; the first at voxel (0, 0, 0), world (-3, 2, 5)". Empty when nothing was replaced.
std::string formatNonFiniteWarnings(const Program& program, const std::string& path,
                                    std::span<const SourceLoc> stageLocs, std::span<const NonFiniteCount> counts);

} // namespace voxc::driver
