#pragma once
// GLSL compute (and the renderer's graphics) shaders -> SPIR-V (glslang), and SPIR-V validation (SPIRV-Tools).
// Targets Vulkan 1.1 / SPIR-V 1.3.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace voxc::codegen {

// Compiles and validates one generated kernel. Any failure is a voxc bug: InternalError with
// the compiler's or validator's message and the source with line numbers. Inside a
// PackagedSpirvScope (PackageReader.h) the kernel's SPIR-V comes from the loaded package instead.
std::vector<uint32_t> compileComputeShader(std::string_view kernelName, const std::string& glsl);

// The renderer's vertex and fragment stages (voxc/render), compiled and validated the same way,
// uncached (two small files).
enum class GraphicsStage { Vertex, Fragment };
std::vector<uint32_t> compileGraphicsShader(std::string_view name, const std::string& glsl, GraphicsStage stage);

// The validator's messages, or nothing when `spirv` is valid for Vulkan 1.1.
std::optional<std::string> spirvValidationErrors(const std::vector<uint32_t>& spirv);

// The bindings of descriptor set 0 that a valid module's variables are decorated with,
// ascending: what the kernel declares, used or not. InternalError for another set.
std::vector<uint32_t> spirvDescriptorBindings(const std::vector<uint32_t>& spirv);

} // namespace voxc::codegen
