// phong: the SIMD backend of the batch path (the lowest layer of ext/simd and ext/batch): xsimd
// when available (not std::experimental::simd: libstdc++ 12 loops exp and log1p per lane,
// docs/batch.md), else a scalar loop over the same kernel (simd_batch<T> = T; PHONG_NO_XSIMD forces it).
// SPDX-License-Identifier: MIT
#pragma once

#include "../../core/config.hpp"
#include "../../core/math.hpp"

#include <cstddef>
#include <limits>
#include <type_traits>

// g++ 12 reports _mm512_undefined_* inside its AVX-512 intrinsics as (maybe) uninitialized once
// inlined, deciding by each function's source position in the inlining chain: so xsimd is included
// inside the region, and every ext/simd and ext/batch header wraps its code in it
// (diagnostics_push.hpp; docs/batch.md). Include phong/batch.hpp before <xsimd/xsimd.hpp>.
#if !defined(PHONG_NO_XSIMD) && !defined(__CUDACC__) && __has_include(<xsimd/xsimd.hpp>)
#  if defined(__aarch64__)
// xsimd 8.1's NEON float division and sqrt are estimates with Newton steps (a few ulp; sqrt(inf)
// NaN); phong's bounds count IEEE ones, so neon64 float batches take vdivq_f32 / vsqrtq_f32. Its
// bitwise_cast and its integer shifts by a count pick the instruction from a table of function
// pointers or a recursion over every count, which g++ 12 resolves only after inlining: calls in
// the lanes' power kernels; here they are a reinterpretation and a shift by a register.
// These overloads take neon64 where xsimd's take neon (or are more specialized), so xsimd's
// qualified calls choose them: declared before <xsimd/xsimd.hpp>.
#    if defined(XSIMD_HPP)
#      error "phong: on aarch64 include phong/batch.hpp (or a phong lane header) before <xsimd/xsimd.hpp>: phong's NEON overloads must be declared first"
#    endif
#    include <arm_neon.h>
#    include <bit>
#    include <cstdint>
namespace xsimd {
template <class T, class A> class batch;
struct neon64;
namespace kernel {
// Defined here: every use depends on A, so batch<T, A> need not be complete yet.
template <class A> inline batch<float, A> div(batch<float, A> const& a, batch<float, A> const& b, neon64 const&) noexcept
{
    return vdivq_f32(a, b);
}
template <class A> inline batch<float, A> sqrt(batch<float, A> const& x, neon64 const&) noexcept
{
    return vsqrtq_f32(x);
}
#    define PHONG_DETAIL_NEON_CAST(From, To) \
        template <class A> inline batch<To, A> bitwise_cast(batch<From, A> const& x, batch<To, A> const&, neon64 const&) noexcept \
        { \
            return std::bit_cast<typename batch<To, A>::register_type>(typename batch<From, A>::register_type(x)); \
        }
PHONG_DETAIL_NEON_CAST(float, std::int32_t)
PHONG_DETAIL_NEON_CAST(std::int32_t, float)
PHONG_DETAIL_NEON_CAST(float, std::uint32_t)
PHONG_DETAIL_NEON_CAST(std::uint32_t, float)
PHONG_DETAIL_NEON_CAST(double, std::int64_t)
PHONG_DETAIL_NEON_CAST(std::int64_t, double)
PHONG_DETAIL_NEON_CAST(double, std::uint64_t)
PHONG_DETAIL_NEON_CAST(std::uint64_t, double)
#    undef PHONG_DETAIL_NEON_CAST
// vshlq by -n: an arithmetic right shift on signed lanes, a logical one on unsigned lanes (as xsimd's).
#    define PHONG_DETAIL_NEON_SHIFTS(T, suffix, count) \
        template <class A> inline batch<T, A> bitwise_lshift(batch<T, A> const& x, int n, neon64 const&) noexcept \
        { \
            return vshlq_##suffix(x, vdupq_n_##count(n)); \
        } \
        template <class A> inline batch<T, A> bitwise_rshift(batch<T, A> const& x, int n, neon64 const&) noexcept \
        { \
            return vshlq_##suffix(x, vdupq_n_##count(-n)); \
        }
PHONG_DETAIL_NEON_SHIFTS(std::int32_t, s32, s32)
PHONG_DETAIL_NEON_SHIFTS(std::uint32_t, u32, s32)
PHONG_DETAIL_NEON_SHIFTS(std::int64_t, s64, s64)
PHONG_DETAIL_NEON_SHIFTS(std::uint64_t, u64, s64)
#    undef PHONG_DETAIL_NEON_SHIFTS
} // namespace kernel
} // namespace xsimd
#  endif
#  include "diagnostics_push.hpp"
#  include <xsimd/xsimd.hpp>
#  include "diagnostics_pop.hpp"
#  if defined(XSIMD_NO_SUPPORTED_ARCHITECTURE) // xsimd 8.1 has no lanes there (RISC-V, POWER, s390x)
#    define PHONG_HAS_XSIMD 0
#  else
#    define PHONG_HAS_XSIMD 1
#  endif
#else
#  define PHONG_HAS_XSIMD 0
#endif

/// The lane kernels are small and hot: inline them into the shading loop.
#if defined(__GNUC__)
#  define PHONG_LANES_INLINE inline __attribute__((always_inline))
#else
#  define PHONG_LANES_INLINE inline
#endif

#include "diagnostics_push.hpp"

namespace phong {

#if PHONG_HAS_XSIMD
namespace detail::simd {

/// a * b + c rounded once on xsimd lanes: the fused instructions (x86 FMA3, AVX-512, AArch64's
/// vfmaq) called directly, as xsimd 8.1's fma is unfused on AVX-512 and without FMA; without FMA
/// hardware, Dekker's split (split_fma).
template <class V> PHONG_LANES_INLINE V split_fma(const V& a, const V& b, const V& c);

template <class V> PHONG_LANES_INLINE V fma(const V& a, const V& b, const V& c)
{
    [[maybe_unused]] constexpr bool float_lanes = std::is_same_v<typename V::value_type, float>;
#  if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        if constexpr (float_lanes) return V(_mm512_fmadd_ps(a, b, c));
        else return V(_mm512_fmadd_pd(a, b, c));
    }
#  endif
#  if defined(__FMA__)
    if constexpr (sizeof(V) == 32) {
        if constexpr (float_lanes) return V(_mm256_fmadd_ps(a, b, c));
        else return V(_mm256_fmadd_pd(a, b, c));
    } else if constexpr (sizeof(V) == 16) {
        if constexpr (float_lanes) return V(_mm_fmadd_ps(a, b, c));
        else return V(_mm_fmadd_pd(a, b, c));
    }
#  endif
#  if defined(__aarch64__)
    if constexpr (sizeof(V) == 16) {
        if constexpr (float_lanes) return V(vfmaq_f32(c, a, b));
        else return V(vfmaq_f64(c, a, b));
    }
#  endif
    return split_fma(a, b, c);
}

/// Dekker's product a * b = p + e exactly (dekker_product_error), then (p + c) + e: exact where
/// c = -fl(a * b) (the stable mode's error-free products), else within 1 ulp. Veltkamp's split
/// overflows above max / 2^(h + 1) (h = 12 float, 27 double; 8.3e34 in float), so such a and b are
/// scaled by 2^-(h+1) for e and back: exact, e being far from the subnormal range.
template <class V> PHONG_LANES_INLINE V split_fma(const V& a, const V& b, const V& c)
{
    using T = typename V::value_type;
    constexpr int h = (std::numeric_limits<T>::digits + 1) / 2;
    const V limit(std::numeric_limits<T>::max() / T(1ull << (h + 1)));
    const V down(T(1) / T(1ull << (h + 1))), up(T(1ull << (h + 1))), one(T(1));
    const auto big_a = xsimd::abs(a) > limit, big_b = xsimd::abs(b) > limit;
    const V as = xsimd::select(big_a, a * down, a), bs = xsimd::select(big_b, b * down, b);
    const V scale = xsimd::select(big_a, up, one) * xsimd::select(big_b, up, one);
    // fl(fl(a b) + c): the product unfused (ieee::barrier), else a contracting compiler makes it one
    // fused multiply-add, and adding e would count the product's error twice.
    return detail::ieee::opaque(detail::ieee::barrier(a * b) + c) +
           detail::dekker_product_error<V, T>(as, bs, detail::ieee::barrier(as * bs)) * scale;
}

} // namespace detail::simd

#  if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE__) && XSIMD_WITH_AVX512BW
/// g++ 12 at -O0 cannot compile xsimd 8.1's AVX-512BW integer select (used inside xsimd::log):
/// unoptimized builds use AVX-512DQ, the same 512-bit float arithmetic.
using simd_arch = xsimd::avx512dq;
#  else
/// The instruction set of shade_batch's lanes: xsimd's widest for the compile flags.
using simd_arch = xsimd::default_arch;
#  endif
/// The SIMD batch used by shade_batch for T: xsimd's widest for the compile flags.
template <class T> using simd_batch = xsimd::batch<T, simd_arch>;
#else
/// The SIMD batch used by shade_batch for T: T itself without xsimd (a scalar loop).
template <class T> using simd_batch = T;
#endif

/// Lanes per step of shade_batch for T.
template <class T> inline constexpr std::size_t batch_width = sizeof(simd_batch<T>) / sizeof(T);

/// 1 where simd_batch's lanes would have no fused multiply-add (x86 without FMA): Dekker's split
/// makes the kernels' fmas slowly (docs/batch.md), so shade_batch shades point by point with
/// shade<F>'s route (the same bits). PHONG_SIMD_WITHOUT_FMA keeps the lanes anyway.
#if PHONG_HAS_XSIMD && (defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86)) && \
    !defined(__FMA__) && !defined(__AVX512F__) && !defined(PHONG_SIMD_WITHOUT_FMA)
#  define PHONG_LANES_WITHOUT_FMA 1
#else
#  define PHONG_LANES_WITHOUT_FMA 0
#endif

} // namespace phong

#include "diagnostics_pop.hpp"
