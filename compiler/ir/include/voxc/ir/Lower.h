#pragma once
// The one place that decides which passes run, and in which order.
#include "voxc/ir/Ir.h"

#include <functional>
#include <string_view>

namespace voxc::ir {

struct LowerOptions {
    // Called after lowering and after every pass with the pass's name and the module it produced.
    std::function<void(std::string_view passName, const IrModule& module)> afterPass;
};

IrModule lowerProgram(const Program& program, const LowerOptions& options = {});

} // namespace voxc::ir
