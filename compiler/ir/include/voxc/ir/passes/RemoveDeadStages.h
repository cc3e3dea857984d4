#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Drops the stages whose work cannot reach the result. A `set` writes every density without
// reading one, so the stages before the last set are dead, unless a stage writes materials:
// materials are written only where a stage wins, so a material-writing stage is kept, and with
// it every stage whose densities it reads (back to the set before it, recursively). (A dropped
// grammar's random draws have no side effect either: every draw is a pure hash of seed,
// iteration, sweep and anchor.) The dropped stages move to IrModule::deadStages, in order.
IrModule removeDeadStages(IrModule module);

} // namespace voxc::ir
