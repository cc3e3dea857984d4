#pragma once
// Program -> IR -> generated GLSL kernels -> validated SPIR-V, plus the dispatch plan.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/codegen/PackageWriter.h"
#include "voxc/ir/Ir.h"

#include <functional>
#include <string_view>

namespace voxc::codegen {

struct CompileOptions {
    // Called after lowering and after every IR pass with the pass's name and its result
    // (`voxc compile --dump-ir`); see voxc/ir/Lower.h.
    std::function<void(std::string_view passName, const ir::IrModule& module)> afterPass;
};

// One "start" kernel, one kernel per (field, mode) the pipeline runs, named "<field>_<mode>"
// (e.g. "ground_set"), and one kernel per (grammar, sweep), named "<grammar>_sweep<i>".
// The result is the same, byte for byte, on every run.
KernelPackage compileProgram(const Program& program, const CompileOptions& options = {});

} // namespace voxc::codegen
