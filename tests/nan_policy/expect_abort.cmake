# cmake -DEXE=<program> -DARG=<argument> -DEXPECT=<regex> -P expect_abort.cmake: passes when the
# program does not exit normally with status 0 and its output matches EXPECT (default: the
# default precondition handler's "phong: precondition failed: "). ctest itself counts a child
# killed by SIGABRT as a failure, whatever PASS_REGULAR_EXPRESSION or WILL_FAIL say.
if(NOT DEFINED EXPECT)
  set(EXPECT "phong: precondition failed: ")
endif()
execute_process(COMMAND ${EXE} ${ARG} RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
message(STATUS "exit: ${result}\n${out}${err}")
if(result STREQUAL "0")
  message(FATAL_ERROR "expected a precondition failure, the program exited normally")
endif()
if(NOT "${out}${err}" MATCHES "${EXPECT}")
  message(FATAL_ERROR "the program failed, but its output does not match: ${EXPECT}")
endif()
