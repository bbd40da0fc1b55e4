# The two halves of the NaN / bad-input policy that a doctest binary cannot check (see
# tests/nan_policy.test.cpp): a compile error for invalid parameters in constant evaluation, and a
# debug assertion at run time. Included from tests/CMakeLists.txt.

# 1. Constant evaluation: the compiler itself is the test. Case 0 is a valid control that must
#    compile; cases 1-7 must fail, naming phong::detail::precondition_failed_see_phong_validate.
set(phong_reject_includes -I${PROJECT_SOURCE_DIR}/include)
get_target_property(phong_glm_includes glm::glm INTERFACE_INCLUDE_DIRECTORIES)
foreach(dir IN LISTS phong_glm_includes)
  if(dir AND NOT dir IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES) # -I/usr/include breaks #include_next
    list(APPEND phong_reject_includes -I${dir})
  endif()
endforeach()
set(phong_reject_source ${CMAKE_CURRENT_LIST_DIR}/constexpr_reject.cpp)
foreach(case RANGE 0 7)
  add_test(NAME nan_policy_constexpr_reject_${case}
           COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror
                   ${phong_reject_includes} -DPHONG_REJECT_CASE=${case} ${phong_reject_source})
  if(NOT case EQUAL 0)
    set_tests_properties(nan_policy_constexpr_reject_${case} PROPERTIES
      PASS_REGULAR_EXPRESSION "precondition_failed_see_phong_validate")
  endif()
endforeach()

# 2. Run time, debug builds only (NDEBUG removes the assertion by design): the invalid call aborts.
add_executable(phong_assert_invalid ${CMAKE_CURRENT_LIST_DIR}/assert_invalid.cpp)
target_link_libraries(phong_assert_invalid PRIVATE phong::phong)
add_test(NAME nan_policy_assert_valid COMMAND phong_assert_invalid valid)
if(NOT CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo|MinSizeRel)$")
  add_test(NAME nan_policy_assert_invalid
           COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:phong_assert_invalid> -DARG=invalid
                   -P ${CMAKE_CURRENT_LIST_DIR}/expect_abort.cmake)
endif()

# 3. shade_batch with view_model::given without per-point views: a compile error with a message
#    that names the fix (case 0: the valid call with views must compile).
foreach(case RANGE 0 1)
  add_test(NAME batch_given_reject_${case}
           COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror
                   ${phong_reject_includes} -DPHONG_REJECT_CASE=${case} ${CMAKE_CURRENT_LIST_DIR}/batch_given_reject.cpp)
  if(case EQUAL 1)
    set_tests_properties(batch_given_reject_${case} PROPERTIES
      PASS_REGULAR_EXPRESSION "view_model::given needs a view vector per point")
  endif()
endforeach()
