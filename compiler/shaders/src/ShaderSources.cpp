#include "voxc/shaders/ShaderSources.h"

#include "EmbeddedShaders.h"
#include "voxc/core/Errors.h"

#include <string>

namespace voxc {

std::string_view shaderSource(std::string_view fileName) {
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; !s->name.empty(); ++s)
        if (s->name == fileName) return s->contents;
    throw InternalError("no embedded shader named '" + std::string(fileName) + "'");
}

std::vector<std::string_view> shaderFileNames() {
    std::vector<std::string_view> names;
    for (const detail::EmbeddedShader* s = detail::kEmbeddedShaders; !s->name.empty(); ++s)
        names.push_back(s->name);
    return names;
}

} // namespace voxc
