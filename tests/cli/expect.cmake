# Runs one command and checks its exit code and that its output matches a pattern.
#   cmake -DEXPECT_EXIT=2 -DEXPECT_OUTPUT=regex -DCOMMAND=a;b;c -P expect.cmake
# -DFORBID_OUTPUT=regex: the output must also not match that pattern (none when empty).
# With WHITTED_SKIP_AS_ROOT in the environment, prints "SKIPPED: running as root" instead when run as root
# (root ignores file permissions).
if(DEFINED ENV{WHITTED_SKIP_AS_ROOT})
  execute_process(COMMAND id -u OUTPUT_VARIABLE uid OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(uid STREQUAL "0")
    message("SKIPPED: running as root")
    return()
  endif()
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE exit_code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 60)
set(all "${out}${err}")
# Windows writes text with CRLF line ends; the patterns are written with LF.
string(REPLACE "\r\n" "\n" all "${all}")
if(NOT exit_code STREQUAL EXPECT_EXIT)
  message(FATAL_ERROR "exit code ${exit_code}, expected ${EXPECT_EXIT}\noutput:\n${all}")
endif()
if(NOT all MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "output does not match '${EXPECT_OUTPUT}':\n${all}")
endif()
if(NOT "${FORBID_OUTPUT}" STREQUAL "" AND all MATCHES "${FORBID_OUTPUT}")
  message(FATAL_ERROR "output matches '${FORBID_OUTPUT}', which it must not:\n${all}")
endif()
if(DEFINED EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
  message(FATAL_ERROR "expected file ${EXPECT_FILE} was not written")
endif()
