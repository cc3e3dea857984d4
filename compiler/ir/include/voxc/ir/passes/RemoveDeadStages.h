#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Drops every stage before the last `set` field stage: a set writes every voxel without reading
// the density, so nothing earlier can reach the result. (A dropped grammar's random draws have no
// side effect either: every draw is a pure hash of seed, iteration, sweep and anchor.) The
// dropped stages move to IrModule::deadStages.
IrModule removeDeadStages(IrModule module);

} // namespace voxc::ir
