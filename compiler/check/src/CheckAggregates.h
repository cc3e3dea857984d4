#pragma once
// A rule's `where` blocks (aggregate tests, voxc/program/Aggregates.h):
//   where { solid_fraction = [0.4, 1]; mean = [0.2, 0.8]; }
//   where floor { box = [[0, 0, 0], [5, 1, 1]]; min = [0.5, 1]; material_fraction = [rock, 0.5, 1]; }
#include "Context.h"

#include "voxc/program/Program.h"
#include "voxc/syntax/Ast.h"

#include <vector>

namespace voxc::check {

// The tests of one `where` block of a rule whose window is `windowSize`, in key order (mean,
// min, max, solid_fraction, material_fraction); reports its errors and returns what checked.
std::vector<AggregateTest> checkWhereBlock(Context& context, const ast::Block& block, glm::ivec3 windowSize,
                                           const std::string& rule);

} // namespace voxc::check
