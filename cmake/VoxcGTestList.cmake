# Writes OUTPUT: the ctest tests of BINARY, one per gtest suite (see VoxcGTest.cmake).
# Inputs: BINARY, OUTPUT, PREFIX, WORKING_DIRECTORY, SPLIT (SUITE;N;SUITE;N...).
execute_process(COMMAND ${BINARY} --gtest_list_tests
                WORKING_DIRECTORY ${WORKING_DIRECTORY}
                OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${BINARY} --gtest_list_tests failed (${status}): ${errors}")
endif()

set(parts_of)
list(LENGTH SPLIT split_length)
if(split_length GREATER 0)
  math(EXPR last "${split_length} - 1")
  foreach(i RANGE 0 ${last} 2)
    math(EXPR j "${i} + 1")
    list(GET SPLIT ${i} suite)
    list(GET SPLIT ${j} parts)
    set(parts_of_${suite} ${parts})
  endforeach()
endif()

# Suites start in column 0 ("Suite." or "Prefix/Suite.  # TypeParam = ..."); tests are indented.
string(REPLACE "\n" ";" lines "${listing}")
set(suites "")
foreach(line IN LISTS lines)
  if(line MATCHES "^([^ #][^ ]*)\\.")
    set(suite ${CMAKE_MATCH_1})
    list(APPEND suites ${suite})
    set(cases_of_${suite} 0)
  elseif(line MATCHES "^  [^ ]")
    math(EXPR cases_of_${suite} "${cases_of_${suite}} + 1")
  endif()
endforeach()

set(script "")
foreach(suite IN LISTS suites)
  set(parts 1)
  if(DEFINED parts_of_${suite})
    set(parts ${parts_of_${suite}})
  endif()
  math(EXPR last_part "${parts} - 1")
  foreach(part RANGE 0 ${last_part})
    set(name "${PREFIX}${suite}")
    set(properties "WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==] TIMEOUT 900")
    # gtest prints SKIPPED for a case that skipped and never for one that failed, so a suite of
    # one case can say it was skipped (a test that needs a real GPU, on a machine without one).
    if(cases_of_${suite} EQUAL 1 AND parts EQUAL 1)
      string(APPEND properties " SKIP_REGULAR_EXPRESSION [==[\\[  SKIPPED \\] 1 test]==]")
    endif()
    if(parts GREATER 1)
      math(EXPR shown "${part} + 1")
      string(APPEND name "_${shown}of${parts}")
      string(APPEND properties " ENVIRONMENT [==[GTEST_TOTAL_SHARDS=${parts};GTEST_SHARD_INDEX=${part}]==]")
    endif()
    string(APPEND script
      "add_test([==[${name}]==] [==[${BINARY}]==] [==[--gtest_filter=${suite}.*]==])\n"
      "set_tests_properties([==[${name}]==] PROPERTIES ${properties})\n")
  endforeach()
endforeach()
file(WRITE ${OUTPUT} "${script}")
