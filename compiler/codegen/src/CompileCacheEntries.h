#pragma once
// The cache's use by compileComputeShader (Spirv.cpp).
#include "voxc/codegen/CompileCache.h"

#include <functional>
#include <string>
#include <vector>

namespace voxc::codegen {

// The SPIR-V of kernel `kernelName` with source `glsl` from the SpirvMemo in scope, else from the
// cache, else from `compile` (then stored) when there is no valid entry.
std::vector<uint32_t> cachedCompile(std::string_view kernelName, const std::string& glsl,
                                    const std::function<std::vector<uint32_t>()>& compile);

} // namespace voxc::codegen
