# Runs a command and checks its exit code and output (ctest's WILL_FAIL cannot be combined with
# an output check). Used as:
#   cmake -DCMD="prog|arg1|arg2" -DEXPECT_EXIT=1 [-DSTDERR_REGEX=...] [-DSTDOUT_REGEX=...]
#         -P expect.cmake
# The arguments of CMD are separated by '|'. The test fails (FATAL_ERROR) on any mismatch
# and shows what the command printed.
if(NOT DEFINED CMD OR CMD STREQUAL "")
  message(FATAL_ERROR "expect.cmake: CMD is not set")
endif()
string(REPLACE "|" ";" command "${CMD}")

execute_process(COMMAND ${command}
  RESULT_VARIABLE rc
  OUTPUT_VARIABLE out
  ERROR_VARIABLE err
  TIMEOUT 100)

string(REPLACE ";" " " shown "${command}")
message("command: ${shown}\nexit status: ${rc}\n--- stdout ---\n${out}--- stderr ---\n${err}--------------")

set(failures "")
if(DEFINED EXPECT_EXIT AND NOT EXPECT_EXIT STREQUAL "")
  if(NOT rc STREQUAL EXPECT_EXIT)
    string(APPEND failures "  exit status ${rc}, expected ${EXPECT_EXIT}\n")
  endif()
endif()
if(DEFINED STDERR_REGEX AND NOT STDERR_REGEX STREQUAL "")
  if(NOT err MATCHES "${STDERR_REGEX}")
    string(APPEND failures "  stderr does not match: ${STDERR_REGEX}\n")
  endif()
endif()
if(DEFINED STDOUT_REGEX AND NOT STDOUT_REGEX STREQUAL "")
  if(NOT out MATCHES "${STDOUT_REGEX}")
    string(APPEND failures "  stdout does not match: ${STDOUT_REGEX}\n")
  endif()
endif()
if(failures)
  message(FATAL_ERROR "expect.cmake: FAILED\n${failures}")
endif()
message("expect.cmake: ok")
