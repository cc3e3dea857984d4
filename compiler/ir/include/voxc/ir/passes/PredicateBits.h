#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Numbers the distinct predicates of each window cell across a sweep's rules, so a kernel
// evaluates each predicate once into a per-cell bit mask and a rule is a few mask tests.
IrModule assignPredicateBits(IrModule module);

} // namespace voxc::ir
