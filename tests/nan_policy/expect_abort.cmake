# cmake -DEXE=<program> -DARG=<argument> -P expect_abort.cmake: passes when the program does not
# exit normally with status 0 and its output contains an assertion message (ctest itself counts
# a child killed by SIGABRT as a failure, whatever PASS_REGULAR_EXPRESSION or WILL_FAIL say).
execute_process(COMMAND ${EXE} ${ARG} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit: ${result}\n${out}${err}")
if(result STREQUAL "0")
  message(FATAL_ERROR "expected an assertion failure, the program exited normally")
endif()
if(NOT "${out}${err}" MATCHES "Assertion .* failed")
  message(FATAL_ERROR "the program failed, but without an assertion message")
endif()
