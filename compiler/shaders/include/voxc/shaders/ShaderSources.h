#pragma once
// The GLSL templates of compiler/shaders, embedded into the binary at build time.
#include <string_view>
#include <vector>

namespace voxc {

// Contents of one template by file name (e.g. "sweep.glsl"); InternalError if there is none.
std::string_view shaderSource(std::string_view fileName);

// Every embedded file name, sorted.
std::vector<std::string_view> shaderFileNames();

} // namespace voxc
