#pragma once
// compileComputeShader's side of PackagedSpirvScope (voxc/codegen/PackageReader.h).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::codegen {

// Nothing when no PackagedSpirvScope lives on this thread; else the package's SPIR-V for the
// kernel, or UserError when the package has no kernel of that name and GLSL.
std::optional<std::vector<uint32_t>> packagedSpirv(std::string_view kernelName, const std::string& glsl);

} // namespace voxc::codegen
