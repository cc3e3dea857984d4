#pragma once
// The maps a module's fields sample (FieldNode::Kind::Map), in the order generated kernels index
// them: fields in module order, nodes in order, each map once. They are the first solve tables
// of the package (KernelPackage::solveTables, binding 12), so map i is table i.
#include "voxc/ir/Ir.h"
#include "voxc/program/SolveTable.h"

#include <memory>
#include <vector>

namespace voxc::codegen {

std::vector<std::shared_ptr<const SampledMap>> mapsOf(const ir::IrModule& module);

// A map as a solve table: min 0, the map's size ((width, 1, depth) for a height map), its values
// as the table's densities.
std::shared_ptr<const SolveTable> mapTable(const SampledMap& map);

} // namespace voxc::codegen
