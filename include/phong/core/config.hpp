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

/// PHONG_HD marks every function so the headers compile in CUDA device code.
/// Empty unless compiled by nvcc (or clang in CUDA mode).
#if defined(__CUDACC__)
#  define PHONG_HD __host__ __device__
#else
#  define PHONG_HD
#endif

/// PHONG_INLINE marks every function on shade<F>'s per-point and per-light path (and the small
/// public term functions): the compiler is told to inline it into the caller, so that a user's
/// shading loop is one function at every optimization level, rather than leaving the decision to
/// the inliner's size heuristics (which differ between compilers and between -O2 and -O3).
/// It includes PHONG_HD. g++ and clang++: inline __attribute__((always_inline)) when optimizing
/// (-O1 and up: __OPTIMIZE__; at -O0, where nothing is fast anyway, plain inline, so that debug
/// builds compile as quickly as without it; and under AddressSanitizer, whose checks multiply
/// with every inlined copy of the shading loop: measurements in docs/compilers.md, "Inlining");
/// MSVC: __forceinline; CUDA: __host__ __device__ __forceinline__. Define PHONG_NO_FORCE_INLINE to get
/// plain `inline` (e.g. to step through phong in a debugger), or define PHONG_INLINE yourself
/// before including any phong header. always_inline and constexpr combine: constant evaluation
/// is unaffected. A renderer's light_traits functions may use it too.
#if defined(__SANITIZE_ADDRESS__) // g++
#  define PHONG_DETAIL_ASAN 1
#elif defined(__has_feature)
#  if __has_feature(address_sanitizer) // clang++
#    define PHONG_DETAIL_ASAN 1
#  endif
#endif
#if !defined(PHONG_INLINE)
#  if defined(PHONG_NO_FORCE_INLINE) || defined(PHONG_DETAIL_ASAN)
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

/// PHONG_DETAIL_LAMBDA_INLINE: PHONG_INLINE's decision for a lambda (after its parameter list),
/// so that a light loop's body passed as a lambda (detail::each_listed_light) is inlined as the
/// loop's own steps are. g++ and clang++ when optimizing (not under AddressSanitizer, nor with
/// PHONG_NO_FORCE_INLINE); empty elsewhere.
#if !defined(PHONG_NO_FORCE_INLINE) && !defined(PHONG_DETAIL_ASAN) && !defined(__CUDACC__) && (defined(__GNUC__) || defined(__clang__)) && \
    defined(__OPTIMIZE__)
#  define PHONG_DETAIL_LAMBDA_INLINE __attribute__((always_inline))
#else
#  define PHONG_DETAIL_LAMBDA_INLINE
#endif

namespace phong {

/// A precondition handler: called with the failed check's message (validate's, naming the field
/// and the reason, e.g. "material.kd: negative, NaN or inf"; or shade_batch's), and the file and
/// line of the check. See set_precondition_handler.
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

// The installed handler, read and written atomically. g++ and clang++: their __atomic builtins on a
// plain pointer (what std::atomic<T*> runs, without <atomic> in every translation unit, which
// costs a header of GLM's size); other compilers: std::atomic.
#if defined(__GNUC__) || defined(__clang__)
inline precondition_handler current_precondition_handler = &default_precondition_handler;
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

/// Installs the handler that precondition checks (PHONG_ASSERT in debug builds: shade's validate()
/// of every parameter; in every build: shade_batch's span-length and overlap checks, which keep
/// memory safe) call when they fail, and returns the previous
/// one; nullptr restores the default (print "phong: precondition failed: <message> (file:line)" to
/// stderr, then std::abort()). Thread-safe (an atomic pointer); process-wide.
/// A handler may return (e.g. a test recording the message; throwing terminates, the checks are in
/// noexcept functions): the call then goes on as an NDEBUG
/// build would, with the result unspecified but no undefined behaviour (shade on out-of-domain
/// parameters gives some value, possibly NaN; shade_batch with spans of wrong lengths writes
/// nothing). Not consulted in constant evaluation (a compile error instead) nor in CUDA device
/// code (plain assert there), nor under NDEBUG for the value checks (shade_batch's memory checks
/// call it in every build).
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

/// PHONG_ASSERT(cond, msg): a debug-build check of a precondition. Under NDEBUG nothing is
/// evaluated. Otherwise a false cond calls the precondition handler with msg (a const char*, may
/// be computed at run time, e.g. validate(x).message()) and __FILE__, __LINE__; see
/// phong::set_precondition_handler (default: print "phong: precondition failed: <msg> (file:line)"
/// and abort). In CUDA device code it is the plain assert((cond) && (msg)). Define PHONG_ASSERT
/// yourself before including any phong header to replace it altogether (detail::require then
/// uses it too).
#if defined(PHONG_ASSERT)
#  define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) PHONG_ASSERT(cond, msg)
#else
#  if defined(NDEBUG)
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) ((void)0)
#  elif defined(__CUDA_ARCH__)
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) assert((cond) && (msg))
#  else
#    define PHONG_DETAIL_ASSERT_AT(cond, msg, file, line) \
        (static_cast<bool>(cond) ? void(0) : ::phong::detail::precondition_failed((msg), (file), (line)))
#  endif
#  define PHONG_ASSERT(cond, msg) PHONG_DETAIL_ASSERT_AT(cond, msg, __FILE__, __LINE__)
#endif

/// The file and line of the caller, as default arguments (g++ and clang builtins; std::source_location
/// needs clang 15): detail::require reports its caller's location, not its own.
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDACC__)
#  define PHONG_DETAIL_CALLER_FILE __builtin_FILE()
#  define PHONG_DETAIL_CALLER_LINE __builtin_LINE()
#else
#  define PHONG_DETAIL_CALLER_FILE __FILE__
#  define PHONG_DETAIL_CALLER_LINE __LINE__
#endif

namespace phong::detail {

/// Called only when a precondition fails during constant evaluation, and never a constant
/// expression then: it orders the message's address against a local's, a comparison whose result
/// is unspecified ([expr.const]: not a core constant expression). So the evaluation is rejected,
/// the compiler names this function, and both g++ 12 and clang 14 print the message literal (g++
/// in the failed comparison, clang in the call), which names the field (checked by
/// tests/nan_policy/checks.cmake). A null message would be a constant expression: require never
/// passes one.
PHONG_INLINE constexpr void precondition_failed_see_phong_validate(const char* message) noexcept
{
    const char unrelated = 0;
    if (message != nullptr && message < &unrelated) return;
}

/// Checks `ok`: a compile error in constant evaluation (naming the message), PHONG_ASSERT at run
/// time (the precondition handler in debug builds, with the caller's file and line; nothing under
/// NDEBUG or in CUDA device code).
PHONG_INLINE constexpr void require(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                                int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
    if (std::is_constant_evaluated()) {
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

/// Whether the debug-only value checks run here: always in constant evaluation (a failed check is
/// a compile error), at run time only without NDEBUG. Under NDEBUG at run time false, so a check
/// written `if (value_checks_on()) { ... }` is not even evaluated. Every debug-only check of a
/// parameter (validate() of the material, environment, lights and weights, unit_inputs' unit
/// vectors, an incident's direction) takes this one test.
PHONG_INLINE constexpr bool value_checks_on() noexcept
{
#if defined(NDEBUG)
    return std::is_constant_evaluated();
#else
    return true;
#endif
}

/// ok, reported where it is false as require() reports it (a compile error in constant
/// evaluation, the precondition handler in debug builds), for a bound the caller keeps in every
/// build: where ok is false it skips the read past a range. Release builds pay a compare there,
/// not the handler's call (shade_batch's span checks, once per call, use memory_safe instead).
PHONG_INLINE constexpr bool within_bounds(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                                      int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
    if (!ok) require(false, message, file, line);
    return ok;
}

} // namespace phong::detail
