// phong: the SIMD backend of the batch path, the lowest layer of detail/simd/ and detail/batch/:
// xsimd (Debian libxsimd-dev, header-only) when it is available, else a plain scalar loop over
// the same kernel (simd_batch<T> = T). Every lane header includes this one first.
// SPDX-License-Identifier: MIT
//
// Why xsimd and not std::experimental::simd: the kernel needs vectorized exp and log1p (the
// specular power), and libstdc++ 12's <experimental/simd> computes those with a scalar loop per
// lane (docs/batch.md). Define PHONG_NO_XSIMD to force the scalar fallback.
//
// Defines PHONG_HAS_XSIMD (0 or 1), PHONG_LANES_INLINE, the fused multiply-add on lanes
// (detail::simd::fma), simd_arch, simd_batch<T>, batch_width<T> and PHONG_LANES_WITHOUT_FMA.
#pragma once

#include "../../core/config.hpp"
#include "../../core/math.hpp"

#include <cstddef>
#include <limits>
#include <type_traits>

// g++ 12 reports the _mm512_undefined_* placeholders inside its own AVX-512 intrinsics (which
// xsimd calls) as (maybe) uninitialized once they are inlined; they are not, by design. g++
// decides by the source position of each function in the inlining chain, innermost first, not
// by where a template is instantiated: so xsimd (and through it <immintrin.h>) is included inside
// the region, and every header of detail/simd/ and detail/batch/ wraps its code in the same
// region (diagnostics_push.hpp ... diagnostics_pop.hpp): every chain that runs through xsimd's
// code is covered, also from phong's templates instantiated in a user's file
// (tests/consumer/batch_user.cpp). Include phong/batch.hpp before <xsimd/xsimd.hpp> for this to
// hold.
#if !defined(PHONG_NO_XSIMD) && !defined(__CUDACC__) && __has_include(<xsimd/xsimd.hpp>)
#  if defined(__aarch64__)
// xsimd 8.1's float division and square root on NEON (its neon kernels, which neon64 inherits)
// are reciprocal estimates with two Newton steps, not correctly rounded (a few ulp off), and its
// sqrt is x * rsqrt(x), NaN at x = inf. phong's bounds count IEEE division and square root, so
// neon64 float batches take AArch64's instructions (vdivq_f32, vsqrtq_f32), as xsimd already does
// for double. These overloads take neon64 itself where xsimd's take its base neon, so xsimd's
// calls (kernel::div<A>(..., A{}), kernel::sqrt<A>(..., A{}), qualified: looked up where xsimd
// defines them) choose them; hence they are declared before <xsimd/xsimd.hpp>.
#    if defined(XSIMD_HPP)
#      error "phong: on aarch64 include phong/batch.hpp (or a phong lane header) before <xsimd/xsimd.hpp>: phong's NEON float division and square root must be declared first"
#    endif
#    include <arm_neon.h>
namespace xsimd {
template <class T, class A> class batch;
struct neon64;
namespace kernel {
template <class A> inline batch<float, A> div(batch<float, A> const& a, batch<float, A> const& b, neon64 const&) noexcept;
template <class A> inline batch<float, A> sqrt(batch<float, A> const& x, neon64 const&) noexcept;
} // namespace kernel
} // namespace xsimd
#  endif
#  include "diagnostics_push.hpp"
#  include <xsimd/xsimd.hpp>
#  include "diagnostics_pop.hpp"
#  if defined(__aarch64__)
namespace xsimd::kernel {
template <class A> inline batch<float, A> div(batch<float, A> const& a, batch<float, A> const& b, neon64 const&) noexcept
{
    return vdivq_f32(a, b);
}
template <class A> inline batch<float, A> sqrt(batch<float, A> const& x, neon64 const&) noexcept
{
    return vsqrtq_f32(x);
}
} // namespace xsimd::kernel
#  endif
#  define PHONG_HAS_XSIMD 1
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

/// a * b + c rounded once on xsimd lanes. xsimd 8.1's fma is a separate multiply and add on
/// AVX-512 and on targets without FMA (found by the stable mode's error-free products losing
/// their error term), so the fused instructions are called directly (x86 FMA3 and AVX-512;
/// AArch64's vfmaq, which every aarch64 target has), and without FMA hardware the exact product
/// comes from Dekker's split (split_fma below).
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

/// Dekker's product a * b = p + e exactly (detail::dekker_product_error, math.hpp), then
/// (p + c) + e: exact whenever c = -fl(a * b) (the error-free products of the stable mode), else
/// within 1 ulp. Veltkamp's split forms
/// (2^h + 1) x (h = 12 for float, 27 for double), which overflows for |x| above
/// max / 2^(h + 1) (8.3e34 in float, 1.1e300 in double): the error term would be inf - inf = NaN
/// (the stable mode would lose the view vector of a point at |Q| = 1e38 in float, where the
/// scalar path's std::fma is exact). So e is computed for a 2^-(h+1) (and b 2^-(h+1)) where
/// those are that large, and scaled back by the same powers of two: exact, since e of such a
/// product (|a b| >= 8.3e34 * 1.4e-45 in float) is far from the subnormal range.
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
/// The SIMD batch used by shade_batch for T: xsimd's widest for the compile flags (16 floats with
/// AVX-512, 8 with AVX2, 4 with SSE2); T itself without xsimd.
template <class T> using simd_batch = xsimd::batch<T, simd_arch>;
#else
/// The SIMD batch used by shade_batch for T: T itself without xsimd (a scalar loop).
template <class T> using simd_batch = T;
#endif

/// Lanes per step of shade_batch for T.
template <class T> inline constexpr std::size_t batch_width = sizeof(simd_batch<T>) / sizeof(T);

/// 1 where simd_batch's lanes would have no fused multiply-add: x86 compiled without FMA
/// instructions (the x86-64 baseline, no -march; any -m flags short of FMA). The lanes' exact and stable
/// kernels need multiply-adds rounded once (the power's polynomials, the Newton step of 1/|d|, the
/// error-free products), which detail::simd::fma then forms by Dekker's split, several operations
/// each (docs/batch.md, "Builds without FMA", has the measurement). There shade_batch shades point
/// by point with shade<F>'s own route (the same colours as shade<F>, bit for bit). Define
/// PHONG_SIMD_WITHOUT_FMA to keep the lanes anyway.
#if PHONG_HAS_XSIMD && (defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86)) && \
    !defined(__FMA__) && !defined(__AVX512F__) && !defined(PHONG_SIMD_WITHOUT_FMA)
#  define PHONG_LANES_WITHOUT_FMA 1
#else
#  define PHONG_LANES_WITHOUT_FMA 0
#endif

} // namespace phong

#include "diagnostics_pop.hpp"
