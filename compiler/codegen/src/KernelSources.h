#pragma once
// Generated GLSL for each kind of kernel, built from the templates in compiler/shaders.
#include "voxc/ir/Ir.h"

#include <string>
#include <string_view>

namespace voxc::codegen {

// `sourceName` is how comments name the .vox file (its file name, so output does not
// depend on the directory it was compiled from).
std::string startKernelSource(const ir::IrModule& module, std::string_view sourceName);

std::string sweepKernelSource(const ir::IrGrammar& grammar, const ir::IrSweep& sweep, std::string_view kernelName,
                              std::string_view sourceName);

} // namespace voxc::codegen
