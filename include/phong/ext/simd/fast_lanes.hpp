// phong: fast::detail::lanes for xsimd batches (the lane-wise bit access of phong/core/fast_math.hpp's kernels)
// and the batches' fast::rsqrt.
// SPDX-License-Identifier: MIT
#pragma once

#include "backend.hpp"
#include "math_traits.hpp"
#include "../../core/fast_math.hpp"

#include <cstdint>
#include <limits>
#include <type_traits>

#if PHONG_HAS_XSIMD
#include "diagnostics_push.hpp"

namespace phong::fast {

namespace detail {
template <class T, class A>
struct lanes<xsimd::batch<T, A>> {
    using V = xsimd::batch<T, A>;
    using bits_t = xsimd::batch<std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>, A>;
    static bits_t bits(const V& x) { return xsimd::bitwise_cast<bits_t>(x); }
    static V from_bits(const bits_t& u) { return xsimd::bitwise_cast<V>(u); }
    /// a * b + c: the fused instruction where the target has one, else a multiply and an add.
    static V madd(const V& a, const V& b, const V& c) { return phong::detail::math_traits<V>::madd(a, b, c); }
    /// 1/sqrt(x), relative error fast::rsqrt_max_rel<T>. Float: math_traits' estimate + one Newton
    /// step (AVX, AVX-512). Double with AVX-512: rsqrt14 + two rsqrt_newton_product steps. Elsewhere
    /// 1/sqrt. x = 0: inf, x = inf: 0.
    static V rsqrt(const V& x)
    {
#  if defined(__AVX512F__)
        if constexpr (std::is_same_v<T, double> && sizeof(V) == 64) {
            const V r0(_mm512_rsqrt14_pd(x));
            const V half_x = V(0.5) * x;
            const V r2 = detail::rsqrt_newton_product(half_x, detail::rsqrt_newton_product(half_x, r0));
            return xsimd::select(phong::detail::ieee::positive_finite(r0), r2, r0);
        }
#  endif
        return phong::detail::math_traits<V>::rsqrt(x);
    }
    /// 1/x for a positive normal x, relative error fast::detail::reciprocal_max_rel<T>: float lanes with
    /// AVX-512 (rcp14) or AVX with FMA (rcp), the estimate + one Newton step in correction form
    /// (two fused multiply-adds; unfused, x r0 rounded would add u); else 1/x.
    static V reciprocal_normal(const V& x)
    {
        if constexpr (std::is_same_v<T, float>) {
#  if defined(__AVX512F__)
            if constexpr (sizeof(V) == 64) return newton_reciprocal(x, V(_mm512_rcp14_ps(x)));
#  endif
#  if defined(__AVX__) && defined(__FMA__)
            if constexpr (sizeof(V) == 32) return newton_reciprocal(x, V(_mm256_rcp_ps(x)));
#  endif
        }
        return V(T(1)) / x;
    }

private:
    static V newton_reciprocal(const V& x, const V& r0)
    {
        // r0 + r0 (1 - x r0); -0 - x is -x exactly (xsimd's unary minus is 0 - x, which the
        // compiler may not fold into a negated fma)
        return phong::detail::math_traits<V>::fma(r0, phong::detail::math_traits<V>::fma(V(T(-0.0)) - x, r0, V(T(1))), r0);
    }
};
} // namespace detail

} // namespace phong::fast

#include "diagnostics_pop.hpp"
#endif // PHONG_HAS_XSIMD
