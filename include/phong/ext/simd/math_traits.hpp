// phong: math_traits for xsimd batches: every kernel of math.hpp, lane-wise.
// SPDX-License-Identifier: MIT
#pragma once

#include "backend.hpp"
#include "lanes_power.hpp"
#include "../../core/math.hpp"

#include <limits>
#include <type_traits>

#if PHONG_HAS_XSIMD

#include "diagnostics_push.hpp"

#if PHONG_FP_REASSOCIATION && (defined(__x86_64__) || defined(__i386__)) && !defined(__SSE4_1__)
#  define PHONG_DETAIL_LANEWISE_EXP 1 // math_traits<batch>::exp below
#else
#  define PHONG_DETAIL_LANEWISE_EXP 0
#endif
#if PHONG_FP_REASSOCIATION && (defined(__x86_64__) || defined(__i386__)) && !defined(__AVX512DQ__)
#  define PHONG_DETAIL_LANEWISE_LOG 1 // math_traits<batch>::log and log1p below
#else
#  define PHONG_DETAIL_LANEWISE_LOG 0
#endif

namespace phong::detail {

/// math_traits for xsimd batches: every kernel of math.hpp, lane-wise. exp, log, log1p: xsimd's
/// (within a few ulp); float rsqrt: hardware estimate + one Newton step; fma fused. pow is
/// exp(y log x) for x >= 0 with pow(0, 0) = 1 (xsimd's own pow returns 0 there).
template <class T, class A>
struct math_traits<xsimd::batch<T, A>> {
    using V = xsimd::batch<T, A>;
    using scalar = T;
    using mask = xsimd::batch_bool<T, A>;
    static constexpr bool float_lanes = std::is_same_v<T, float>;

    PHONG_LANES_INLINE static V sqrt(const V& x) { return xsimd::sqrt(x); }
    /// 1/sqrt(x). Float lanes with AVX-512 or AVX: hardware estimate + one Newton step
    /// (< 2 ulp); elsewhere 1/sqrt(x). rsqrt(0) = inf, rsqrt(inf) = 0.
    PHONG_LANES_INLINE static V rsqrt(const V& x)
    {
        if constexpr (has_rsqrt_estimate) return newton_rsqrt(x, rsqrt_estimate(x));
        else return V(T(1)) / xsimd::sqrt(x);
    }
    /// 1/sqrt(x) for x a positive normal number (detail::rsqrt_normal): rsqrt without the guards
    /// for 0 and inf (other x: unspecified, maybe NaN).
    PHONG_LANES_INLINE static V rsqrt_normal(const V& x)
    {
        if constexpr (has_rsqrt_estimate) return rsqrt_newton_correction(x, rsqrt_estimate(x));
        else return V(T(1)) / xsimd::sqrt(x);
    }
    /// x is a positive normal number (AVX-512DQ: one vfpclass, not two compares).
    PHONG_LANES_INLINE static mask positive_normal(const V& x)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_knot_mask16(_mm512_fpclass_ps_mask(x, 0xff))));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_knot_mask8(_mm512_fpclass_pd_mask(x, 0xff))));
#endif
        return (x >= V(std::numeric_limits<T>::min())) && (x <= V(std::numeric_limits<T>::max()));
    }
    /// m && positive_normal(x) (AVX-512DQ: vfpclass and one kandn).
    PHONG_LANES_INLINE static mask both_positive_normal(const mask& m, const V& x)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_kandn_mask16(_mm512_fpclass_ps_mask(x, 0xff), m)));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_kandn_mask8(_mm512_fpclass_pd_mask(x, 0xff), m)));
#endif
        return m && positive_normal(x);
    }
    /// all(a && b) (AVX-512: one kortest of the complements).
    PHONG_LANES_INLINE static bool all_both(const mask& a, const mask& b)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return _kortestz_mask16_u8(_knot_mask16(a), _knot_mask16(b));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return _kortestz_mask8_u8(_knot_mask8(a), _knot_mask8(b));
#endif
        return xsimd::all(a && b);
    }
    /// e^x, lane-wise: xsimd::exp on x clamped to [minlog, maxlog] (xsimd's thresholds), NaN passed
    /// through. The clamp changes no result (xsimd's exp is exactly 0 / +inf beyond them) and keeps
    /// xsimd 8.1's scalar float-to-int conversion defined for huge |x| and NaN (double below
    /// AVX-512DQ), which the model reaches (exp(m log1p(-x)) with m = 1e30). -ffast-math on x86
    /// (PHONG_FP_REASSOCIATION): exp, log and log1p run std:: lane by lane, as xsimd's rounding
    /// tricks lack a barrier clang++ respects (docs/compilers.md).
    template <class F> PHONG_LANES_INLINE static V lanewise(const V& x, F f)
    {
        alignas(A::alignment()) T lanes[V::size];
        x.store_aligned(lanes);
        for (T& e : lanes) e = f(e);
        return V::load_aligned(lanes);
    }
    PHONG_LANES_INLINE static V exp(const V& x)
    {
        const V lo = xsimd::constants::minlog<V>(), hi = xsimd::constants::maxlog<V>();
        const V clamped = xsimd::select(x > lo, xsimd::select(x < hi, x, hi), lo); // NaN: lo
#if PHONG_DETAIL_LANEWISE_EXP
        return xsimd::select(x == x, lanewise(clamped, [](T e) { return std::exp(e); }), x);
#else
        return xsimd::select(x == x, xsimd::exp(clamped), x);
#endif
    }
    /// exp(y) for the powers: 0 where y is below the log of the power floor (ieee::power_floor_log2),
    /// so no subnormal is made, nor by the product with a light's coefficients. NaN: NaN.
    PHONG_LANES_INLINE static V power_exp(const V& y)
    {
        const V least(T(detail::ieee::power_floor_log2<T>) * T(0.6931471805599453));
        const auto below = y < least;
        return xsimd::select(below, V(T(0)), exp(xsimd::select(below, least, y)));
    }
    /// log and log1p: xsimd's (no integer conversion of the argument: defined for every input).
    PHONG_LANES_INLINE static V log(const V& x)
    {
#if PHONG_DETAIL_LANEWISE_LOG
        if constexpr (!float_lanes) return lanewise(x, [](T e) { return std::log(e); });
#endif
        return xsimd::log(x);
    }
    PHONG_LANES_INLINE static V log1p(const V& x)
    {
#if PHONG_DETAIL_LANEWISE_LOG
        if constexpr (!float_lanes) return lanewise(x, [](T e) { return std::log1p(e); });
#endif
        return xsimd::log1p(x);
    }
    /// x^y for x in [0, 1], y >= 0: exp(y log x) (power_exp: 0 below the power floor),
    /// pow(0, 0) = 1 (xsimd's own pow gives 0), pow(0, y > 0) = 0.
    PHONG_LANES_INLINE static V pow(const V& x, const V& y)
    {
        const V p = power_exp(y * log(xsimd::select(x > V(T(0)), x, V(T(1)))));
        return xsimd::select(x > V(T(0)), p, detail::power_of_zero(y));
    }
    /// x^m for x in [0, 1], m >= 0 (the exact mode's specular and spot powers). Float lanes:
    /// lanes_power.hpp, relative error <= pow_unit_lanes_error(m log2 x); double lanes: pow above.
    PHONG_LANES_INLINE static V pow_unit(const V& x, const V& m)
    {
        if constexpr (float_lanes) return detail::lanes::pow_unit(x, m);
        else return pow(x, m);
    }
    /// pow_unit with m_is_zero = (m == 0) given; x <= 0 and NaN give 0^m (0, or 1 for m = 0).
    PHONG_LANES_INLINE static V pow_unit(const V& x, const V& m, const mask& m_is_zero)
    {
        if constexpr (float_lanes) return detail::lanes::pow_unit(x, m, m_is_zero);
        else return pow(x, m);
    }
    /// Float lanes, x in [0, 1], 0 <= m <= 2^100: x^m where x > 0 or m = 0, else a finite value for
    /// the caller to select away (lanes_power.hpp's pow_unit_positive).
    template <class U = T, std::enable_if_t<std::is_same_v<U, float>, int> = 0>
    PHONG_LANES_INLINE static V pow_unit_positive(const V& x, const V& m) { return detail::lanes::pow_unit_positive(x, m); }
    /// Float lanes: lanes_power.hpp's pow_unit_kept (pow_unit_positive on the kept lanes, else 0).
    template <class U = T, std::enable_if_t<std::is_same_v<U, float>, int> = 0>
    PHONG_LANES_INLINE static V pow_unit_kept(const V& x, const V& m, const mask& kept) { return detail::lanes::pow_unit_kept(x, m, kept); }
    /// Float lanes: lanes_power.hpp's least_base (x^m >= 2^-101 above it; 0 for m < 1).
    template <class U = T, std::enable_if_t<std::is_same_v<U, float>, int> = 0>
    PHONG_LANES_INLINE static V least_base(const V& m) { return detail::lanes::least_base(m); }
    /// (1 - x)^m for x >= 0, m >= 0: exp(m log1p(-x)) (power_exp); x >= 1 gives 0 (1 for m = 0).
    /// Float lanes: lanes_power.hpp, relative error <= pow_one_minus_lanes_error(m log2(1 - x)).
    PHONG_LANES_INLINE static V pow_one_minus(const V& x, const V& m)
    {
        if constexpr (float_lanes) return detail::lanes::pow_one_minus(xsimd::max(x, V(T(0))), m);
        const V xc = xsimd::min(x, V(T(1)));
        const auto inside = xc < V(T(1));
        const V lg = log1p(-xsimd::select(inside, xc, V(T(0))));
        const V r = power_exp(m * lg);
        return xsimd::select(inside, r, detail::power_of_zero(m));
    }
    /// a * b + c rounded once (detail::simd::fma: the fused instruction, or Dekker's exact product).
    PHONG_LANES_INLINE static V fma(const V& a, const V& b, const V& c) { return detail::simd::fma(a, b, c); }
    /// a * b + c: the fused instruction where the target has one, else a multiply and an add (for
    /// sums of products, whose rounding is then the same in every loop that inlines them).
    PHONG_LANES_INLINE static V madd(const V& a, const V& b, const V& c)
    {
#  if defined(__FMA__) || defined(__AVX512F__) || defined(__aarch64__)
        return detail::simd::fma(a, b, c);
#  else
        return a * b + c;
#  endif
    }
    /// a * b + c by Dekker's split (detail::simd::split_fma), whatever the target.
    PHONG_LANES_INLINE static V split_fma(const V& a, const V& b, const V& c) { return detail::simd::split_fma(a, b, c); }
    static V select(const mask& m, const V& a, const V& b) { return xsimd::select(m, a, b); }
    static bool any(const mask& m) { return xsimd::any(m); }
    static bool all(const mask& m) { return xsimd::all(m); }
    static mask both(const mask& a, const mask& b) { return a && b; }
    static V abs(const V& x) { return xsimd::abs(x); }
    static V min(const V& a, const V& b) { return xsimd::min(a, b); }
    static V max(const V& a, const V& b) { return xsimd::max(a, b); }

    /// The power of two of inverse_pow2_scale, lane-wise: 2^(bias - e) by subtracting exponent fields
    /// (x above 2^bias: 2^(1 - bias)); no integer selects (xsimd 8.1, AVX-512BW, -O0 cannot compile them).
    static V inverse_pow2_scale(const V& x)
    {
        using I = xsimd::as_integer_t<T>;
        using IV = xsimd::batch<I, A>;
        constexpr int mant = std::numeric_limits<T>::digits - 1;
        constexpr I one = I(1) << mant;                                       // exponent field 1: 2^(1 - bias)
        constexpr I exponent_mask = ((I(1) << (sizeof(T) * 8 - 1 - mant)) - 1) << mant; // all exponent bits
        constexpr I two_bias = exponent_mask - one;                           // field 2 bias: 2^bias
        const IV scale_bits = IV(two_bias) - (xsimd::bitwise_cast<IV>(x) & IV(exponent_mask));
        const V two_pow_bias = xsimd::bitwise_cast<V>(IV(two_bias));
        return xsimd::select(x >= two_pow_bias, xsimd::bitwise_cast<V>(IV(one)), xsimd::bitwise_cast<V>(scale_bits));
    }

private:
    /// Float lanes with a hardware 1/sqrt estimate: AVX-512 (relative error 2^-14) or AVX (1.5 2^-12).
    static constexpr bool has_rsqrt_estimate =
        float_lanes && (std::is_base_of_v<xsimd::avx512f, A> || std::is_base_of_v<xsimd::avx, A>);
    /// That estimate (has_rsqrt_estimate only).
    PHONG_LANES_INLINE static V rsqrt_estimate(const V& x)
    {
        if constexpr (std::is_base_of_v<xsimd::avx512f, A>) return V(_mm512_rsqrt14_ps(x));
        else return V(_mm256_rsqrt_ps(x));
    }
    /// One Newton step for 1/sqrt(x) from an estimate: y0 + (y0 / 2)(1 - (x y0) y0) with fmas: 1.6 u
    /// from AVX-512's 2^-14, 4.9 u from AVX's 1.5 2^-12 (counted in accuracy.hpp's exact bounds).
    /// Apart from fast::detail::rsqrt_newton_product and the stable lanes' fourth-order correction
    /// on purpose: each rounds differently (merging would change a mode's bits or its bound).
    PHONG_LANES_INLINE static V rsqrt_newton_correction(const V& x, const V& estimate)
    {
        const V residual = fma(-(x * estimate), estimate, V(T(1))); // 1 - x y0^2
        return fma(estimate * V(T(0.5)), residual, estimate);
    }
    static V newton_rsqrt(const V& x, const V& estimate)
    {
        const V refined = rsqrt_newton_correction(x, estimate);
        const auto finite_nonzero = phong::detail::ieee::positive_finite(estimate);
        return xsimd::select(finite_nonzero, refined, estimate);
    }
};

} // namespace phong::detail

#include "diagnostics_pop.hpp"
#endif // PHONG_HAS_XSIMD
