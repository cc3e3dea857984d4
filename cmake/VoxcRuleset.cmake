# voxc_add_ruleset(TARGET name SOURCES a.vox [b.vox ...] OUTPUT_DIR dir [SEED s] [CHUNK n])
#
# Compiles each .vox file into the package directory OUTPUT_DIR/<file name without .vox>
# (manifest.json, kernels/, data/; docs/cli.md) as part of the target `name`, which the default
# build builds. A package is compiled again when its .vox file, a rule file the .vox imports or
# the voxc command changes, and only then: voxc writes a depfile listing its inputs (-MD), and a
# stamp file marks each compile, since an unchanged package keeps its old times. OUTPUT_DIR is
# relative to the current binary directory; SOURCES to the current source directory. The target's
# VOXC_PACKAGE_DIRS property lists the package directories. Needs CMake 3.20 (DEPFILE with
# either generator) and policy CMP0116 NEW (cmake_minimum_required(VERSION 3.20) or later).
function(voxc_add_ruleset)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "TARGET;OUTPUT_DIR;SEED;CHUNK" "SOURCES")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "voxc_add_ruleset: unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_TARGET OR NOT arg_SOURCES OR NOT arg_OUTPUT_DIR)
    message(FATAL_ERROR "voxc_add_ruleset: TARGET, SOURCES and OUTPUT_DIR are required")
  endif()
  set(options "")
  if(DEFINED arg_SEED)
    list(APPEND options --seed ${arg_SEED})
  endif()
  if(DEFINED arg_CHUNK)
    list(APPEND options --chunk ${arg_CHUNK})
  endif()

  get_filename_component(outputDir "${arg_OUTPUT_DIR}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_BINARY_DIR}")
  set(stampDir "${CMAKE_CURRENT_BINARY_DIR}/voxc_rulesets/${arg_TARGET}")
  set(stamps "")
  set(packages "")
  foreach(source IN LISTS arg_SOURCES)
    get_filename_component(sourcePath "${source}" ABSOLUTE BASE_DIR "${CMAKE_CURRENT_SOURCE_DIR}")
    get_filename_component(name "${source}" NAME_WE)
    set(package "${outputDir}/${name}")
    if(package IN_LIST packages)
      message(FATAL_ERROR "voxc_add_ruleset(${arg_TARGET}): two sources would both compile into ${package}")
    endif()
    set(stamp "${stampDir}/${name}.stamp")
    set(depfile "${stampDir}/${name}.d")
    add_custom_command(
      OUTPUT "${stamp}"
      COMMAND "${CMAKE_COMMAND}" -E make_directory "${outputDir}" "${stampDir}"
      COMMAND voxc::voxc compile "${sourcePath}" -o "${package}" ${options} -MD -MF "${depfile}" -MT "${stamp}" --quiet
      COMMAND "${CMAKE_COMMAND}" -E touch "${stamp}"
      DEPENDS "${sourcePath}" "$<TARGET_FILE:voxc::voxc>"
      DEPFILE "${depfile}"
      COMMENT "voxc: compiling ${source} into ${package}"
      VERBATIM)
    list(APPEND stamps "${stamp}")
    list(APPEND packages "${package}")
  endforeach()
  add_custom_target(${arg_TARGET} ALL DEPENDS ${stamps})
  set_target_properties(${arg_TARGET} PROPERTIES VOXC_PACKAGE_DIRS "${packages}")
endfunction()
