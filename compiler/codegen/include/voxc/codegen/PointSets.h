#pragma once
// The point sets a module's fields read (FieldNode::Kind::PointSet), in the order the package
// lists them (KernelPackage::pointSets) and generated kernels index them: fields in module
// order, nodes in order, each set once.
#include "voxc/ir/Ir.h"

#include <memory>
#include <vector>

namespace voxc::codegen {

std::vector<std::shared_ptr<const PointSet>> pointSetsOf(const ir::IrModule& module);

} // namespace voxc::codegen
