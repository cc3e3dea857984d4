# Writes OUTPUT, a C++ file defining voxc::detail::kEmbeddedShaders: one {file name, contents}
# entry per file in INPUTS, in the order given. Contents go in as raw string literals; a
# delimiter that no shader contains keeps them verbatim.
set(delimiter "voxc_glsl")
set(entries "")
foreach(input IN LISTS INPUTS)
  get_filename_component(name ${input} NAME)
  file(READ ${input} contents)
  string(FIND "${contents}" ")${delimiter}\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${input} contains the raw string delimiter ${delimiter}")
  endif()
  string(APPEND entries "    {\"${name}\", R\"${delimiter}(${contents})${delimiter}\"},\n")
endforeach()
set(text "// Generated from compiler/shaders/*.glsl by EmbedShaders.cmake; do not edit.
#include \"EmbeddedShaders.h\"

namespace voxc::detail {

const EmbeddedShader kEmbeddedShaders[] = {
${entries}    {\"\", \"\"},
};

} // namespace voxc::detail
")
# Rewriting an unchanged file would rebuild the library for nothing.
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} previous)
  if(previous STREQUAL text)
    return()
  endif()
endif()
file(WRITE ${OUTPUT} "${text}")
