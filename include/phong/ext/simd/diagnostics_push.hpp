// phong: opens the region of an ext/simd or ext/batch header: core/diagnostics_push.hpp's (no
// -Wfloat-equal), and with g++ also no false -W(maybe-)uninitialized in AVX-512 intrinsics
// (backend.hpp) and no -Wsign-conversion in g++'s own gather macros (unoptimized builds pass the
// mask as a signed type; clang still checks these lines). No include guard, on purpose.
// SPDX-License-Identifier: MIT
#include "../../core/diagnostics_push.hpp"
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#  pragma GCC diagnostic ignored "-Wsign-conversion"
#endif
