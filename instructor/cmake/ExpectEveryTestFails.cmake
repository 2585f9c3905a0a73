# cmake -DPROGRAM=lab_tests [-DWHAT=text] -P ExpectEveryTestFails.cmake
#
# Runs a GoogleTest program and passes only when every one of its tests ran and
# failed: the proof that a lab's tests give nothing to a lab file that answers
# everything with a constant (instructor/tests/constants/CMakeLists.txt). A
# test that passes, is skipped, or a program that ends before its summary (a
# crash: a test should fail an assertion, not crash, on a constant) is named.
if(NOT PROGRAM)
  message(FATAL_ERROR "ExpectEveryTestFails.cmake: PROGRAM is not set")
endif()
execute_process(COMMAND ${PROGRAM} --gtest_color=no RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
string(REGEX MATCHALL "\n\\[ +(OK|SKIPPED) +\\] [A-Za-z0-9_./]+" passed "\n${output}")
if(passed)
  string(REGEX REPLACE "\n\\[ +(OK|SKIPPED) +\\] " "\n  " passed "${passed}")
  list(JOIN passed "" passed)
  message(FATAL_ERROR "${WHAT}: these tests do not fail with every function of the lab returning a constant:${passed}\n"
                      "Each test of a function needs a case whose right answer no constant gives (a hit, true, a colour, ...).")
endif()
if(NOT output MATCHES "\n\\[==========\\] [0-9]+ tests? from [0-9]+ test suites? ran")
  string(REGEX MATCHALL "\\[ RUN      \\] [A-Za-z0-9_./]+" started "${output}")
  list(POP_BACK started last)
  message(FATAL_ERROR "${WHAT}: the tests ended before their summary (${result}); the last one started: ${last}")
endif()
if(result EQUAL 0)
  message(FATAL_ERROR "${WHAT}: the program passed (exit code 0)")
endif()
message(STATUS "${WHAT}: every test failed, as it must")
