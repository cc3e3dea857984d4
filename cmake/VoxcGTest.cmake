# voxc_add_gtest(TARGET [PREFIX P] [SPLIT SUITE N ...])
#
# Registers one ctest test per gtest test suite of TARGET, named after the suite (PREFIX first).
# A suite's tests run in one process, so they share what the process keeps: the Vulkan device
# (tests/support/Lavapipe.h), its pipelines and compiled kernels. One process per test made each
# Vulkan test start lavapipe and compile its kernels again; per suite, the 112 GPU-agreement tests
# run in 7 s instead of 185 s, while ctest still spreads the suites over the cores.
# SPLIT SUITE N runs a long suite as N ctest tests of every N-th test each (gtest's sharding).
# The suites are listed after each build of TARGET (`--gtest_list_tests`); each suite, or part of
# a split one, may take 900 s.
set(VOXC_GTEST_LIST_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/VoxcGTestList.cmake)

function(voxc_add_gtest target)
  cmake_parse_arguments(arg "" "PREFIX" "SPLIT" ${ARGN})
  set(listed ${CMAKE_CURRENT_BINARY_DIR}/${target}_suites.cmake)
  set(include ${CMAKE_CURRENT_BINARY_DIR}/${target}_include.cmake)
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND ${CMAKE_COMMAND} -D BINARY=$<TARGET_FILE:${target}> -D OUTPUT=${listed}
            -D PREFIX=${arg_PREFIX} "-D SPLIT=${arg_SPLIT}"
            -D WORKING_DIRECTORY=${CMAKE_CURRENT_BINARY_DIR} -P ${VOXC_GTEST_LIST_SCRIPT}
    BYPRODUCTS ${listed}
    VERBATIM)
  # A target that was never built shows as one failing test rather than as no tests.
  file(WRITE ${include}
    "if(EXISTS [[${listed}]])\n  include([[${listed}]])\nelse()\n"
    "  add_test([[${target}_NOT_BUILT]] [[${target}_NOT_BUILT]])\nendif()\n")
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES ${include})
endfunction()
