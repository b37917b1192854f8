# CTest's list of the GoogleTest executable's tests, one CTest test per suite (cmake -P, after each
# link of thinlayer_tests). A suite runs in one process, as GoogleTest is made to: the executable's
# start (the dynamic loader binding gmsh and OpenCASCADE, about 0.2 s of CPU) is paid once per suite
# rather than once per test; a failure still names its test (`[  FAILED  ] Suite.Test` in the output
# CTest prints), and `ctest -R '^Suite$'` or `thinlayer_tests --gtest_filter=Suite.Test` runs one alone.
#   -D EXECUTABLE=path/to/thinlayer_tests -D OUTPUT=path/to/suites.cmake [-D COSTS=Suite:seconds,...]
# COSTS: the long suites' seconds, so that `ctest -j N` starts them first (CTest's COST property).
cmake_minimum_required(VERSION 3.22)
execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status}): ${errors}")
endif()
string(REPLACE "\n" ";" lines "${listing}")
set(script "")
set(suites "")
foreach(line IN LISTS lines)
  # A suite is a line that starts in column 0 and ends its name with a dot ("Suite." or
  # "Instance/Suite." for a parameterised one, perhaps followed by "  # TypeParam = ...").
  if(line MATCHES "^([A-Za-z_][A-Za-z0-9_/]*)\\.")
    set(suite "${CMAKE_MATCH_1}")
    string(APPEND script "add_test([=[${suite}]=] [=[${EXECUTABLE}]=] [=[--gtest_filter=${suite}.*]=])\n")
    list(APPEND suites "${suite}")
  elseif(NOT line MATCHES "^ " AND NOT line MATCHES "^Running main\\(\\) from " AND NOT line STREQUAL "")
    # Neither a test (indented), a suite, nor gtest_main's banner: a suite this script cannot name
    # would otherwise never run.
    message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests: a line that is no suite: '${line}'")
  endif()
endforeach()
string(REPLACE "," ";" costs "${COSTS}")
foreach(suite_cost IN LISTS costs)
  string(REPLACE ":" ";" suite_cost "${suite_cost}")
  list(GET suite_cost 0 suite)
  list(GET suite_cost 1 seconds)
  if(suite IN_LIST suites)
    string(APPEND script "set_tests_properties([=[${suite}]=] PROPERTIES COST ${seconds})\n")
  endif()
endforeach()
if(NOT suites)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests listed no suite")
endif()
file(WRITE "${OUTPUT}" "${script}")
