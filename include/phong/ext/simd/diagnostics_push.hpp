// phong: opens the region of an ext/simd or ext/batch header that keeps g++'s false
// -W(maybe-)uninitialized in AVX-512 intrinsics out of the user's build (backend.hpp), and g++'s
// -Wsign-conversion in its own gather macros (unoptimized builds pass the mask as a signed type;
// clang still checks these lines), and -Wfloat-equal off as core/diagnostics_push.hpp does.
// No include guard, on purpose.
// SPDX-License-Identifier: MIT
#if defined(__GNUC__) || defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wfloat-equal"
#  if !defined(__clang__)
#    pragma GCC diagnostic ignored "-Wuninitialized"
#    pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#    pragma GCC diagnostic ignored "-Wsign-conversion"
#  endif
#endif
