#pragma once
// The table EmbedShaders.cmake generates at build time.
#include <string_view>

namespace voxc::detail {

struct EmbeddedShader {
    std::string_view name;     // file name, e.g. "common.glsl"
    std::string_view contents; // empty name ends the table
};

extern const EmbeddedShader kEmbeddedShaders[];

} // namespace voxc::detail
