// phong: opens the region that keeps g++'s false -W(maybe-)uninitialized in AVX-512 intrinsics out
// of the user's build (backend.hpp). Every ext/simd and ext/batch header; no include guard, on purpose.
// SPDX-License-Identifier: MIT
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
