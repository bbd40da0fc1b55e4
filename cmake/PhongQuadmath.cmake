# phong_use_quadmath(<target>...): link libquadmath and define PHONG_HAVE_QUADMATH=1 where the
# compiler has __float128 and <quadmath.h> (g++; Debian's clang++ 14 does not find the header),
# so the tests' and benchmarks' reference model runs in 113-bit precision (else long double).
include_guard(GLOBAL)
include(CheckCXXSourceCompiles)
set(CMAKE_REQUIRED_LIBRARIES quadmath)
check_cxx_source_compiles("#include <quadmath.h>
int main() { __float128 x = 2; return (int)sqrtq(x); }" PHONG_HAVE_QUADMATH)
unset(CMAKE_REQUIRED_LIBRARIES)

function(phong_use_quadmath)
  if(PHONG_HAVE_QUADMATH)
    foreach(target IN LISTS ARGN)
      target_compile_definitions(${target} PRIVATE PHONG_HAVE_QUADMATH=1)
      target_link_libraries(${target} PRIVATE quadmath)
    endforeach()
  endif()
endfunction()
