#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Lowering: every grammar's rules grouped into sweeps in execution order (voxc::orderSweeps),
// rule cells in cellIndex order, every cell loaded.
IrModule buildSweeps(const Program& program);

} // namespace voxc::ir
