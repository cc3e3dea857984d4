#pragma once
// GLSL for a curves stage (compiler/shaders/curves.glsl): solve table `table` of
// KernelPackage::solveTables combined with the grid by `mode`.
#include "voxc/codegen/KernelSources.h"

namespace voxc::codegen {

DispatchShape curvesDispatchShape(const ir::IrModule& module);
// `writesMaterials`: the table has materials, written where the table wins and the result is solid.
std::string curvesKernelSource(const ir::IrModule& module, uint32_t table, FieldMode mode, bool writesMaterials,
                               std::string_view kernelName, std::string_view origin);

} // namespace voxc::codegen
