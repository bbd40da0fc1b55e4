# The two halves of the NaN / bad-input policy that a doctest binary cannot check (see
# tests/nan_policy.test.cpp): a compile error for invalid parameters in constant evaluation, and a
# debug assertion at run time. Included from tests/CMakeLists.txt.

# 1. Constant evaluation: the compiler itself is the test. Case 0 is a valid control that must
#    compile; cases 1-9 must fail, naming phong::detail::precondition_failed_see_phong_validate and
#    printing validate()'s message with the field (expect_compile_error.cmake).
set(phong_reject_includes -I${PROJECT_SOURCE_DIR}/include)
get_target_property(phong_glm_includes glm::glm INTERFACE_INCLUDE_DIRECTORIES)
foreach(dir IN LISTS phong_glm_includes)
  if(dir AND NOT dir IN_LIST CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES) # -I/usr/include breaks #include_next
    list(APPEND phong_reject_includes -I${dir})
  endif()
endforeach()
set(phong_reject_source ${CMAKE_CURRENT_LIST_DIR}/constexpr_reject.cpp)
set(phong_reject_command ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror ${phong_reject_includes})
add_test(NAME nan_policy_constexpr_reject_0 COMMAND ${phong_reject_command} -DPHONG_REJECT_CASE=0 ${phong_reject_source})
# The field each case spoils, as validate()'s message names it: the error must print it.
set(phong_reject_fields material.kd material.shininess material.alpha light.attenuation.constant light.spot.direction
                        light.position.w light.diffuse light.position.w environment.ambient)
set(case 0)
foreach(field IN LISTS phong_reject_fields)
  math(EXPR case "${case} + 1")
  add_test(NAME nan_policy_constexpr_reject_${case}
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${phong_reject_command}" -DCASE=${case} -DFIELD=${field}
                   -DSOURCE=${phong_reject_source} -P ${CMAKE_CURRENT_LIST_DIR}/expect_compile_error.cmake)
endforeach()

# 2. Run time, debug builds only (NDEBUG removes the checks by design): the default precondition
#    handler prints "phong: precondition failed: <message> (file:line)" and aborts; the message
#    must name the field (or shade_batch's aliasing rule).
add_executable(phong_assert_invalid ${CMAKE_CURRENT_LIST_DIR}/assert_invalid.cpp)
target_link_libraries(phong_assert_invalid PRIVATE phong::phong)
add_test(NAME nan_policy_assert_valid COMMAND phong_assert_invalid valid)
if(NOT CMAKE_BUILD_TYPE MATCHES "^(Release|RelWithDebInfo|MinSizeRel)$")
  foreach(mode_and_expect IN ITEMS "invalid|phong: precondition failed: material.kd: negative, NaN or inf [(].*shade.hpp:[0-9]+[)]"
                                   "light_w|phong: precondition failed: light.position.w: "
                                   "batch_overlap|phong: precondition failed: shade_batch: an output span overlaps an input span")
    string(REPLACE "|" ";" mode_and_expect "${mode_and_expect}")
    list(GET mode_and_expect 0 mode)
    list(GET mode_and_expect 1 expect)
    add_test(NAME nan_policy_assert_${mode}
             COMMAND ${CMAKE_COMMAND} -DEXE=$<TARGET_FILE:phong_assert_invalid> -DARG=${mode} "-DEXPECT=${expect}"
                     -P ${CMAKE_CURRENT_LIST_DIR}/expect_abort.cmake)
  endforeach()
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

# 4. A light type without a phong::light_traits specialization: one static_assert naming
#    light_traits (case 0, the same type with its specialization, must compile).
foreach(case RANGE 0 1)
  add_test(NAME light_traits_reject_${case}
           COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -Wall -Wextra -Wpedantic -Werror
                   ${phong_reject_includes} -DPHONG_REJECT_CASE=${case} ${CMAKE_CURRENT_LIST_DIR}/light_traits_reject.cpp)
  if(case EQUAL 1)
    set_tests_properties(light_traits_reject_${case} PROPERTIES
      PASS_REGULAR_EXPRESSION "phong::light_traits specialization")
  endif()
endforeach()

# 5. -ffast-math: the stable mode's twofold route (double; float with precision = twofold) is a
#    compile error naming the flag and the alternative (phong/core/ieee.hpp); the exact, fast and
#    float's wider stable mode compile (case 0).
foreach(case RANGE 0 2)
  add_test(NAME fast_math_reject_${case}
           COMMAND ${CMAKE_CXX_COMPILER} -std=c++20 -fsyntax-only -ffast-math -Wall -Wextra -Wpedantic -Werror
                   ${phong_reject_includes} -DPHONG_REJECT_CASE=${case} ${CMAKE_CURRENT_LIST_DIR}/fast_math_reject.cpp)
  if(NOT case EQUAL 0)
    set_tests_properties(fast_math_reject_${case} PROPERTIES
      PASS_REGULAR_EXPRESSION "-ffast-math \\(-fassociative-math\\) reorders them: build this translation unit with -fno-associative-math")
  endif()
endforeach()
