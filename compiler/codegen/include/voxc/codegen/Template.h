#pragma once
// Instantiates a GLSL template of compiler/shaders: `#include "file.glsl"` lines paste that
// template (each file once per kernel), and a line `// <<NAME>>` is replaced by the generated
// section NAME, indented like the marker (an `#include` line in a section pastes that template
// too, still once per kernel). Every section must be used exactly once.
#include <map>
#include <string>
#include <string_view>

namespace voxc::codegen {

using TemplateSections = std::map<std::string, std::string, std::less<>>;

std::string instantiateTemplate(std::string_view templateFile, const TemplateSections& sections);

// Puts `prefix` before every line of `text` ("// " makes a comment block); empty lines get
// the prefix without its trailing spaces.
std::string prefixLines(std::string_view text, std::string_view prefix);

} // namespace voxc::codegen
