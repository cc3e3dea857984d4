#pragma once
#include "voxc/ir/Ir.h"

namespace voxc::ir {

// Replaces each field call whose operands are all constants, and each component of a constant
// vector, by a constant computed with the record's interpreter `eval`. Only records with
// tolerance 0 fold (their CPU and GPU results are bit-identical), and only when every float
// involved is finite and not subnormal (a device may flush subnormals), so the kernels compute
// what the interpreter computes from the unfolded DAG. Unused nodes stay until CSE drops them.
IrModule foldConstants(IrModule module);

} // namespace voxc::ir
