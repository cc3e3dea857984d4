#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Narrows each window cell's access to what the live rules need: cells nobody reads or
// writes are skipped, cells only SET get an address but no load.
IrModule eliminateDeadCells(IrModule module);

} // namespace voxc::ir
