// phong: opens the region in which g++ keeps its false positives inside xsimd's and its own
// AVX-512 intrinsics out of the user's build (see backend.hpp). Included at the top of the code of
// every header of detail/simd/ and detail/batch/, closed by diagnostics_pop.hpp at its end; no
// include guard, on purpose (one region per header).
// SPDX-License-Identifier: MIT
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
