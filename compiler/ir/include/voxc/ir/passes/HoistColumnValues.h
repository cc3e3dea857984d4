#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Marks the field nodes that do not depend, even through their operands, on y (LocalY or
// WorldY): a kernel that walks a column along y computes them once per (x, z) column
// (IrField::perColumn). Constants count as per-column values.
IrModule hoistColumnValues(IrModule module);

} // namespace voxc::ir
