#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Merges field nodes that compute the same thing (same kind, type, payload and operands, after
// their operands were merged) and drops nodes the root does not use, keeping topological order.
// The checker already shares identical nodes; folding creates new equal constants.
IrModule eliminateCommonSubexpressions(IrModule module);

} // namespace voxc::ir
