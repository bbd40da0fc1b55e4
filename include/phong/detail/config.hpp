// phong: configuration macros shared by every header.
// SPDX-License-Identifier: MIT
#pragma once

#include <cassert>
#include <type_traits>

/// PHONG_HD marks every function so the headers compile in CUDA device code.
/// Empty unless compiled by nvcc (or clang in CUDA mode).
#if defined(__CUDACC__)
#  define PHONG_HD __host__ __device__
#else
#  define PHONG_HD
#endif

/// PHONG_ASSERT(cond, msg): a debug-build check of a precondition. In constant evaluation a
/// failed check is a compile error (see detail::precondition_failed); at run time it is
/// `assert` (gone under NDEBUG). Define PHONG_ASSERT yourself before including to replace it.
#ifndef PHONG_ASSERT
#  define PHONG_ASSERT(cond, msg) assert((cond) && (msg))
#endif

namespace phong::detail {

/// Called only when a precondition fails during constant evaluation. It is deliberately not
/// constexpr, so the compiler rejects the constant expression and names this function.
PHONG_HD inline void precondition_failed_see_phong_validate(const char*) noexcept {}

/// Checks `ok`: a compile error in constant evaluation, an assertion at run time (debug builds).
PHONG_HD constexpr void require(bool ok, const char* message) noexcept
{
    if (std::is_constant_evaluated()) {
        if (!ok) precondition_failed_see_phong_validate(message);
    } else {
#if !defined(__CUDA_ARCH__)
        PHONG_ASSERT(ok, message);
#endif
        (void)ok;
        (void)message;
    }
}

} // namespace phong::detail
