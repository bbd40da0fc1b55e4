// phong: configuration macros shared by every header, and the precondition handler.
// SPDX-License-Identifier: MIT
#pragma once

#include <cassert>
#include <type_traits>

#if !defined(__CUDA_ARCH__)
#  include <cstdio>
#  include <cstdlib>
#  if !defined(__GNUC__) && !defined(__clang__)
#    include <atomic>
#  endif
#endif

/// PHONG_DETAIL_CONSTANT_EVALUATED(): std::is_constant_evaluated(), spelled as the compiler's
/// builtin where it has one (the library's own definition of std::is_constant_evaluated): g++ then
/// drops a constant-evaluation-only branch when it parses the function, instead of compiling the
/// branch's callees until the call to std::is_constant_evaluated is inlined.
#if defined(__has_builtin)
#  if __has_builtin(__builtin_is_constant_evaluated)
#    define PHONG_DETAIL_CONSTANT_EVALUATED() __builtin_is_constant_evaluated()
#  endif
#endif
#if !defined(PHONG_DETAIL_CONSTANT_EVALUATED)
#  define PHONG_DETAIL_CONSTANT_EVALUATED() std::is_constant_evaluated()
#endif

/// PHONG_HD marks every function so the headers compile in CUDA device code.
/// Empty unless compiled by nvcc (or clang in CUDA mode).
#if defined(__CUDACC__)
#  define PHONG_HD __host__ __device__
#else
#  define PHONG_HD
#endif

/// PHONG_INLINE marks every function on shade<F>'s per-point and per-light path, so a shading loop
/// is one function whatever the inliner's heuristics (includes PHONG_HD). g++/clang++ when
/// optimizing: always_inline (plain inline at -O0 and under AddressSanitizer; docs/compilers.md,
/// "Inlining"); MSVC: __forceinline; CUDA: __forceinline__. PHONG_NO_FORCE_INLINE gives plain
/// `inline` (smaller code, a call per point; g++: also noclone); or define PHONG_INLINE yourself
/// before any phong header.
#if defined(__SANITIZE_ADDRESS__) // g++
#  define PHONG_DETAIL_ASAN 1
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer) // clang++
#    define PHONG_DETAIL_ASAN 1
#  endif
#endif
#if !defined(PHONG_INLINE)
#  if (defined(PHONG_NO_FORCE_INLINE) || defined(PHONG_DETAIL_ASAN)) && defined(__GNUC__) && !defined(__clang__) && \
      !defined(__CUDACC__)
// noclone: g++'s IPA-SRA would otherwise give every file that calls shade<F> a local copy of it
// with a rewritten signature, where the linker keeps one copy of an inline function.
#    define PHONG_INLINE inline __attribute__((noclone))
#  elif defined(PHONG_NO_FORCE_INLINE) || defined(PHONG_DETAIL_ASAN)
#    define PHONG_INLINE PHONG_HD inline
#  elif defined(__CUDACC__)
#    define PHONG_INLINE __host__ __device__ __forceinline__
#  elif defined(_MSC_VER) && !defined(__clang__)
#    define PHONG_INLINE __forceinline
#  elif (defined(__GNUC__) || defined(__clang__)) && defined(__OPTIMIZE__)
#    define PHONG_INLINE inline __attribute__((always_inline))
#  else
#    define PHONG_INLINE inline
#  endif
#endif

/// PHONG_DETAIL_OUT_OF_LINE marks the run-time body of a debug-build check (validate() of the
/// material, the environment, each light): one out-of-line copy per type instead of a copy at every
/// call, in builds without NDEBUG (inlined, the checks' messages and branches are most of a
/// shade<F> call's code there). Constant evaluation runs it as any constexpr function.
#if defined(__CUDACC__)
#  define PHONG_DETAIL_OUT_OF_LINE PHONG_HD inline
#elif defined(_MSC_VER) && !defined(__clang__)
#  define PHONG_DETAIL_OUT_OF_LINE inline __declspec(noinline)
#elif defined(__GNUC__) || defined(__clang__)
#  define PHONG_DETAIL_OUT_OF_LINE inline __attribute__((noinline))
#else
#  define PHONG_DETAIL_OUT_OF_LINE inline
#endif

/// PHONG_DETAIL_LAMBDA_INLINE: PHONG_INLINE's decision for a lambda (after its parameter list).
#if !defined(PHONG_NO_FORCE_INLINE) && !defined(PHONG_DETAIL_ASAN) && !defined(__CUDACC__) && (defined(__GNUC__) || defined(__clang__)) && \
    defined(__OPTIMIZE__)
#  define PHONG_DETAIL_LAMBDA_INLINE __attribute__((always_inline))
#else
#  define PHONG_DETAIL_LAMBDA_INLINE
#endif

namespace phong {

/// A precondition handler: called with the failed check's message (e.g. "material.kd: negative,
/// NaN or inf"), file and line. See set_precondition_handler.
using precondition_handler = void (*)(const char* message, const char* file, int line);

#if !defined(__CUDA_ARCH__)
namespace detail {

/// The default handler: prints "phong: precondition failed: <message> (<file>:<line>)" to stderr
/// and calls std::abort().
[[noreturn]] inline void default_precondition_handler(const char* message, const char* file, int line) noexcept
{
    std::fprintf(stderr, "phong: precondition failed: %s (%s:%d)\n", message, file, line);
    std::fflush(stderr);
    std::abort();
}

// The installed handler, atomic: g++/clang++ __atomic builtins (no <atomic> in every translation unit).
// Default visibility: one handler for the executable and the shared libraries it links, also when
// they are built with -fvisibility=hidden (else each shared object would keep its own).
#if defined(__GNUC__) || defined(__clang__)
__attribute__((visibility("default"))) inline precondition_handler current_precondition_handler = &default_precondition_handler;
inline precondition_handler exchange_handler(precondition_handler h) noexcept
{
    return __atomic_exchange_n(&current_precondition_handler, h, __ATOMIC_SEQ_CST);
}
inline precondition_handler load_handler() noexcept { return __atomic_load_n(&current_precondition_handler, __ATOMIC_SEQ_CST); }
#else
inline std::atomic<precondition_handler> current_precondition_handler{&default_precondition_handler};
inline precondition_handler exchange_handler(precondition_handler h) noexcept { return current_precondition_handler.exchange(h); }
inline precondition_handler load_handler() noexcept { return current_precondition_handler.load(); }
#endif

} // namespace detail

/// Installs the handler failed precondition checks call (debug builds: validate() of every
/// parameter; every build: shade_batch's span checks) and returns the previous one; nullptr restores
/// the default. Thread-safe, process-wide: shared by the executable and the shared libraries it links
/// (g++, clang++: whatever their -fvisibility); a library opened with dlopen shares it only if the
/// executable exports its symbols (-rdynamic), else it has its own. A handler may return (throwing
/// terminates: noexcept callers): the call goes on as under NDEBUG, result unspecified but no
/// undefined behaviour.
/// Not consulted in constant evaluation (a compile error) nor in CUDA device code (assert).
inline precondition_handler set_precondition_handler(precondition_handler handler) noexcept
{
    return detail::exchange_handler(handler ? handler : &detail::default_precondition_handler);
}

/// The handler set_precondition_handler installed (the default one if none).
inline precondition_handler get_precondition_handler() noexcept
{
    return detail::load_handler();
}

namespace detail {
/// What a failed PHONG_ASSERT calls at run time on the host: the installed handler.
inline void precondition_failed(const char* message, const char* file, int line) noexcept
{
    load_handler()(message, file, line);
}
} // namespace detail
#endif

} // namespace phong

/// PHONG_ASSERT(cond, msg): a debug-build precondition check (nothing evaluated under NDEBUG); a
/// false cond calls the precondition handler with msg, __FILE__, __LINE__ (CUDA device code: assert).
/// Define it yourself before any phong header to replace it.
#if defined(PHONG_ASSERT)
#  define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) PHONG_ASSERT(cond, msg)
#else
#  if defined(NDEBUG)
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) ((void)0)
#  elif defined(__CUDA_ARCH__)
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) assert((cond) && (msg))
#  else
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) \
        ((cond) ? void(0) : ::phong::detail::precondition_failed((msg), (file), (line)))
#  endif
#  define PHONG_ASSERT(cond, msg) PHONG_DETAIL_ASSERT_AT(cond, msg, __FILE__, __LINE__)
#endif

/// The caller's file and line, as default arguments, for detail::require.
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__)
#  define PHONG_DETAIL_CALLER_FILE __builtin_FILE()
#  define PHONG_DETAIL_CALLER_LINE __builtin_LINE()
#else
#  define PHONG_DETAIL_CALLER_FILE __FILE__
#  define PHONG_DETAIL_CALLER_LINE __LINE__
#endif

namespace phong::detail {

/// Called only when a precondition fails in constant evaluation: ordering the message's address
/// against a local's is not a core constant expression ([expr.const]), so the compiler rejects it
/// and prints the message literal. A null message would be constant: require never passes one.
PHONG_INLINE constexpr void precondition_failed_see_phong_validate(const char* message) noexcept
{
    const char unrelated = 0;
    if (message != nullptr && message < &unrelated) return;
}

/// Checks `ok`: a compile error in constant evaluation, PHONG_ASSERT at run time.
PHONG_INLINE constexpr void require(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                                int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
    if (PHONG_DETAIL_CONSTANT_EVALUATED()) {
        if (!ok) precondition_failed_see_phong_validate(message);
    } else {
#if !defined(__CUDA_ARCH__)
        PHONG_DETAIL_ASSERT_AT(ok, message, file, line);
#endif
        (void)ok;
        (void)message;
        (void)file;
        (void)line;
    }
}

/// Whether the debug-only value checks run: always in constant evaluation, at run time only
/// without NDEBUG. Every debug-only parameter check is written `if (value_checks_on()) { ... }`.
PHONG_INLINE constexpr bool value_checks_on() noexcept
{
#if defined(NDEBUG)
    return PHONG_DETAIL_CONSTANT_EVALUATED();
#else
    return true;
#endif
}

/// ok, reported where false as require() does, for a bound the caller keeps in every build.
PHONG_INLINE constexpr bool within_bounds(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                                      int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
    if (!ok) require(false, message, file, line);
    return ok;
}

} // namespace phong::detail
