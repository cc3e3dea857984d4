#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Drops every rule with a cell whose predicates no density passes. Such a rule is never
// among the matched rules, so rule choice (and its random draws) is unchanged.
IrModule removeNeverMatchingRules(IrModule module);

} // namespace voxc::ir
