#pragma once
// The whole pipeline, stage by stage through the kinds' records: compiled into a kernel package,
// or run by the interpreter.
#include "voxc/codegen/KernelPackage.h"
#include "voxc/grid/Grid.h"
#include "voxc/interp/Interpreter.h"
#include "voxc/ir/Ir.h"
#include "voxc/program/Program.h"

#include <functional>
#include <string_view>

namespace voxc {

struct CompileOptions {
    // Called after lowering and after every IR pass with the pass's name and its result
    // (`voxc compile --dump-ir`); see voxc/ir/Lower.h.
    std::function<void(std::string_view passName, const ir::IrModule& module)> afterPass;
};

// Program -> IR -> generated GLSL kernels -> validated SPIR-V, plus the plan of every stage. Each
// kind names its kernels (e.g. "start", "ground_set", "overhang_sweep0"). The result is the same,
// byte for byte, on every run. Curves blocks with no table yet are solved on the host first
// (stages::solvedProgram).
KernelPackage compileProgram(const Program& program, const CompileOptions& options = {});

// Runs program.pipeline in order, starting from an all-air grid of the world's size (curves blocks
// with no table yet solved on the host first, as compileProgram).
DenseGrid interpret(const Program& program, const InterpOptions& options = {});

} // namespace voxc
