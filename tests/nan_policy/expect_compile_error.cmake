# cmake -DSOURCE=<file> -DCASE=<n> -DFIELD=<regex> "-DCOMMAND=<compiler;flags...>" -P expect_compile_error.cmake:
# compiles SOURCE with -DPHONG_REJECT_CASE=CASE and passes when the compilation fails, names
# phong::detail::precondition_failed_see_phong_validate and prints the validate() message of the
# field (FIELD), so the user sees which parameter is out of the domain.
execute_process(COMMAND ${COMMAND} -DPHONG_REJECT_CASE=${CASE} ${SOURCE}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(result STREQUAL "0")
  message(FATAL_ERROR "case ${CASE}: compiled, but validate() rejects its parameters")
endif()
if(NOT "${out}${err}" MATCHES "precondition_failed_see_phong_validate")
  message(FATAL_ERROR "case ${CASE}: the error does not name precondition_failed_see_phong_validate:\n${out}${err}")
endif()
if(NOT "${out}${err}" MATCHES "\"${FIELD}")
  message(FATAL_ERROR "case ${CASE}: the error does not print the message naming ${FIELD}:\n${out}${err}")
endif()
message(STATUS "case ${CASE}: rejected, the message names ${FIELD}")
