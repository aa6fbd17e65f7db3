# After each link of a Catch2 test executable (fftess_discover_tests, tests/CMakeLists.txt): its cases tagged [slow],
# named as catch_discover_tests names them (TEST_PREFIX + case), written to OUTPUT as `set(TEST_LIST ...)` for the
# labels file. An executable without slow cases writes an empty list: Catch's exit status (the number of cases listed)
# is not an error here.
#   cmake -DTEST_EXECUTABLE=... -DTEST_PREFIX=module: -DTEST_LIST=name_slow_tests -DOUTPUT=file -P slow_tests.cmake
execute_process(COMMAND "${TEST_EXECUTABLE}" "[slow]" --list-test-names-only
                OUTPUT_VARIABLE output RESULT_VARIABLE result)
if(result LESS 0 OR NOT result MATCHES "^[0-9]+$")
  message(FATAL_ERROR "cannot list the [slow] cases of ${TEST_EXECUTABLE}: ${result}")
endif()
string(REPLACE "\n" ";" lines "${output}")
set(script "set(${TEST_LIST}")
set(count 0)
foreach(line IN LISTS lines)
  if(line STREQUAL "")
    continue()
  endif()
  string(APPEND script "\n  [==[${TEST_PREFIX}${line}]==]")
  math(EXPR count "${count} + 1")
endforeach()
if(NOT count EQUAL result)
  message(FATAL_ERROR "${TEST_EXECUTABLE}: ${result} [slow] cases, ${count} names listed")
endif()
file(WRITE "${OUTPUT}" "${script})\n")
