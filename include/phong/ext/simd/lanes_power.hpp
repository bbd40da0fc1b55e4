// phong: x^m on float SIMD lanes for the lighting model's domain (x in [0, 1], m >= 0): the power
// of shade_batch's exact mode (math_traits<xsimd::batch<float>>::pow_unit, math_traits.hpp).
// SPDX-License-Identifier: MIT
//
// Why not exp(m log x) with xsimd's kernels (what double lanes use): their log divides, and both
// handle special values the model never passes (their cost: docs/batch.md). This is straight-line
// code, no division, no table:
//   x = 2^e f, f in [sqrt(1/2), sqrt(2)), by integer arithmetic on the bits (exact);
//   log2 x = e + t P(t), t = f - 1 (exact), P of degree 8 (a Chebyshev fit of log2(1 + t) / t,
//     truncation 3.0e-8 = 0.5 u relative; u = 2^-24);
//   y = m log2 x, k = round(y), r = y - k in [-1/2, 1/2] (exact);
//   2^r = 1 + r R(r), R of degree 5 (a Chebyshev fit, truncation 5e-9 = 0.1 u), 2^k applied exactly.
// The coefficients are those of the hand-written baseline (benchmarks/support/hand_simd.hpp), fitted
// with mpmath and rounded to float.
//
// Error (derivation): the computed log2 x is log2 x (1 + dL), |dL| <= 4 u (Horner on |t| <= 0.415 with
// alternating coefficients: about 2.5 u, plus the fit; where e != 0, |t P| <= 1/2 <= |log2 x|). y is
// rounded once more: |y~ - m log2 x| <= 5 u |y| (first order). 2^r costs 2.5 u (Horner, fit, the
// final fma), and d(2^y) / 2^y = ln 2 dy. So, for results at least 2^-126 (normal floats):
//   |x^m~ / x^m - 1| <= pow_unit_lanes_error(y) = (3.5 |y| + 2.5) u,   y = m log2 x,
// 2.5 u at a highlight's peak, 38 u where x^m = 2^-10. Below 2^-126 the result is within 2^-126
// absolute (flushed to 0 under AVX2 and SSE, subnormal under AVX-512's scalef). tests/lanes_power.test.cpp
// checks the bound against long double pow on sweeps the derivation did not choose.
// Edges: x = 0 gives 0 for m > 0 and 1 for m = 0 (pow(0, 0) = 1); 0 < x < 2^-126 (a cosine lost to
// underflow) is taken as 2^-126, so the result lies between x^m and 2^(-126 m);
// x = 1 gives exactly 1; m up to the largest float gives a finite result (y is clamped below).
// Outside the domain (x < 0, x > 1, NaN, m < 0 or inf) the result is unspecified but never a trap
// and never undefined behaviour (NaN y is clamped like -inf).
#pragma once

#include "backend.hpp"

#include <cstdint>
#include <limits>

#if PHONG_HAS_XSIMD
#include "diagnostics_push.hpp"

namespace phong::detail::lanes {

/// log2(1 + t) = t P(t) on t in [sqrt(1/2) - 1, sqrt(2) - 1], highest degree first.
inline constexpr float log2_coefficients[9] = {0.1231096846719146f,  -0.20586188051276055f, 0.21607822552243777f,
                                               -0.2391698814010418f, 0.28790326092450147f,  -0.36069326813533614f,
                                               0.48091075345941253f, -0.7213474682495624f,  1.4426950035679822f};
/// 2^r = 1 + r R(r) on r in [-1/2, 1/2], highest degree first.
inline constexpr float exp2_coefficients[6] = {0.0001545316294512069f, 0.0013390863364671234f, 0.009618082557277852f,
                                               0.05550357114219078f,   0.24022650760568126f,   0.6931471880262288f};

/// The documented relative error bound of pow_unit below, for y = m log2 x (results >= 2^-126).
constexpr double pow_unit_lanes_error(double y)
{
    return (3.5 * (y < 0 ? -y : y) + 2.5) * 0x1p-24;
}

/// a b + c rounded once (detail::simd::fma: xsimd 8.1's fma is not fused on AVX-512).
template <class V> PHONG_LANES_INLINE V fused(const V& a, const V& b, const V& c) { return simd::fma(a, b, c); }

/// x = 2^e (1 + t) with 1 + t in [sqrt(1/2), sqrt(2)) for a positive normal x, exactly: subtracting
/// the bits of sqrt(1/2) and shifting gives e (arithmetic shift: e < 0 for x < sqrt(1/2));
/// removing e from the exponent field gives 1 + t, and t = (1 + t) - 1 is exact (Sterbenz).
template <class V> PHONG_LANES_INLINE V split_exponent(const V& x, V& e)
{
    using IV = xsimd::batch<std::int32_t, typename V::arch_type>;
    const IV bits = xsimd::bitwise_cast<IV>(x);
    const IV ei = (bits - IV(0x3f3504f3)) >> 23;
    e = xsimd::to_float(ei);
    return ieee::opaque(xsimd::bitwise_cast<V>(bits - (ei << 23)) - V(1.0f)); // -ffast-math: kept as one value
}

/// e + log2(1 + t) = e + t P(t) for t in [sqrt(1/2) - 1, sqrt(2) - 1], P of degree 8 by Horner's
/// scheme (fast::detail::log2_estrin, fast_math.hpp, is the fast mode's degree-7 fit: coarser).
template <class V> PHONG_LANES_INLINE V log2_of_split(const V& t, const V& e)
{
    V p(log2_coefficients[0]);
    for (int k = 1; k < 9; ++k) p = fused(p, t, V(log2_coefficients[k]));
    return fused(t, p, e);
}

/// 2^y for y <= 0: k = round(y), r = y - k, 2^r = 1 + r R(r) by Horner's scheme, times 2^k exactly
/// (y clamped below where 2^y is 0 in float anyway; a NaN y is clamped like -inf). Finite: y known
/// finite (not NaN), so AVX-512's scalef, which takes any k (2^r 2^k is 0 for k < -150 as for the
/// clamped k = -150), needs no clamp; exponent-field arithmetic keeps it.
/// Why a third exp2 beside power::exp2_tabulated (detail/power.hpp) and fast::detail::exp2_estrin
/// (fast_math.hpp): the tables would be a gather per lane, and the fast mode's degree-5 polynomial
/// is too coarse for the exact mode's bound (pow_unit_lanes_error); different coefficients, so
/// merging either would change the bits of one mode.
template <class V, bool Finite = false> PHONG_LANES_INLINE V exp2_horner(const V& y_in)
{
    using IV = xsimd::batch<std::int32_t, typename V::arch_type>;
#if defined(__AVX512F__)
    constexpr bool scalef = sizeof(V) == 64;
#else
    constexpr bool scalef = false;
#endif
    // scalef takes any k; else the exponent field k + 127 stays >= 0 (field 0: the value 0).
    constexpr float y_min = scalef ? -150.0f : -127.0f;
    V y = y_in;
    if constexpr (!(Finite && scalef)) y = xsimd::max(y_in, V(y_min));
#if PHONG_FP_BARRIER
    // Where the compiler may reassociate: y rounded by the shift (ieee.hpp), |y| <= 150 < 2^22.
    // xsimd's nearbyint without a rounding instruction (SSE2) is the same trick with a barrier
    // that clang -ffast-math sees through, which gave k = y.
    const V k = ieee::round_by_shift(y, V(0x1.8p23f)).value;
#else
    const V k = xsimd::nearbyint(y);
#endif
    const V r = ieee::opaque(y - k); // -ffast-math: not re-expanded as y R - k R
    V q(exp2_coefficients[0]);
    for (int j = 1; j < 6; ++j) q = fused(q, r, V(exp2_coefficients[j]));
    const V mantissa = fused(r, q, V(1.0f));
#if defined(__AVX512F__)
    if constexpr (scalef) return V(_mm512_scalef_ps(mantissa, k));
#endif
    const IV field = (xsimd::to_int(k) + IV(127)) << 23;
    return mantissa * xsimd::bitwise_cast<V>(field);
}

/// 2^(m log2 x) for x in [0, 1] (0 and subnormals taken as 2^-126), m >= 0 finite; Finite: m <= 2^100
/// (exp2_horner: y = m log2 x is then finite, |y| <= 126 2^100).
template <class V, bool Finite = false> PHONG_LANES_INLINE V power_of_log2(const V& x, const V& m)
{
    V e;
    const V t = split_exponent(xsimd::max(x, V(std::numeric_limits<float>::min())), e); // 0, subnormals: 2^-126
    return exp2_horner<V, Finite>(m * log2_of_split(t, e));
}

/// x^m lane-wise for x in [0, 1], m >= 0 finite (see the header comment for the method and bound),
/// with m_is_zero = (m == 0) given: a caller whose m is the same for many x (the light loop of
/// shade_batch) computes it once. Edges: x <= 0 and NaN give 0^m (0, or 1 for m = 0).
template <class V> PHONG_LANES_INLINE V pow_unit(const V& x, const V& m, const typename V::batch_bool_type& m_is_zero)
{
    const V power = power_of_log2(x, m);
    // 0^m (detail::power_of_zero) in the same select: pow(0, m > 0) = 0 (2^(-126 m) above is not 0
    // for m < 1); pow(0, 0) = 1 comes out of y = 0.
    return xsimd::select(x > V(0.0f) || m_is_zero, power, V(0.0f));
}

/// pow_unit without the select: x^m for x in (0, 1] and 0 <= m <= 2^100 (x below 2^-126 taken as
/// 2^-126), and for m = 0 any x; the lanes with x <= 0 and m > 0 get a finite value that is not 0,
/// for the caller to select away (shade_batch: with the mask of the lit lanes, one compare per pair).
/// With m <= 2^100, y = m log2 x is finite (|y| <= 126 2^100), so the exponential needs no clamp of
/// y under AVX-512. The same bits as pow_unit where it is not selected away; the same bound.
template <class V> PHONG_LANES_INLINE V pow_unit_positive(const V& x, const V& m) { return power_of_log2<V, true>(x, m); }

/// x^m lane-wise for x in [0, 1], m >= 0 finite.
template <class V> PHONG_LANES_INLINE V pow_unit(const V& x, const V& m) { return pow_unit(x, m, m == V(0.0f)); }

/// The documented relative error bound of pow_one_minus below, for y = m log2(1 - x) (results
/// >= 2^-126): pow_unit's, plus the rounding of 1 - x (relative u, at most 2.9 u relative to
/// log2(1 - x) where 1 - x < sqrt(1/2), i.e. |log2(1 - x)| >= 1/2) on the large-x side.
constexpr double pow_one_minus_lanes_error(double y)
{
    return (6.5 * (y < 0 ? -y : y) + 2.5) * 0x1p-24;
}

/// c^m = (1 - x)^m lane-wise from both forms of a cosine c in [0, 1]: its complement x = 1 - c and
/// c itself, each a float of its own (the stable mode's r.v or n.h, computed in double and rounded
/// twice: detail/simd/stable_lanes.hpp), m >= 0 finite. As 2^(m log2 c): where c >= sqrt(1/2) the
/// polynomial takes t = -x itself (log2(1 + t) = t P(t): no rounding of 1 - x, so a highlight's
/// tiny x keeps its relative accuracy, as log1p does); below, c is split like pow_unit's base, so
/// a small c keeps its relative accuracy too (1 - x rounded would leave it an absolute error of
/// u). Error: pow_one_minus_lanes_error(m log2 c), relative to the power of the floats given (for
/// the lanes where c >= sqrt(1/2), of 1 - x). Edges: x = 0 gives 1; c <= 0 gives 0 for m > 0 and
/// 1 for m = 0.
template <class V> PHONG_LANES_INLINE V pow_cosine(const V& x, const V& c, const V& m)
{
    V e;
    const V t_split = split_exponent(xsimd::max(c, V(std::numeric_limits<float>::min())), e);
    const auto near_one = c >= V(0.70710677f); // then e = 0 and t_split = c - 1
    const V log2_base = log2_of_split(xsimd::select(near_one, -x, t_split), xsimd::select(near_one, V(0.0f), e));
    const V power = exp2_horner(m * log2_base);
    return xsimd::select(c > V(0.0f) || m == V(0.0f), power, V(0.0f)); // 0^m as pow_unit's select
}

/// (1 - x)^m lane-wise for x in [0, 1], m >= 0 finite: the stable mode's power of 1 - r.v or
/// 1 - n.h (specular.hpp's pow_one_minus), pow_cosine with c = 1 - x (exact for x >= 1/2, one
/// rounding above). Error: pow_one_minus_lanes_error. Edges: x = 0 gives 1; x >= 1 gives 0 for
/// m > 0 and 1 for m = 0.
template <class V> PHONG_LANES_INLINE V pow_one_minus(const V& x, const V& m)
{
    return pow_cosine(x, V(1.0f) - x, m);
}

} // namespace phong::detail::lanes

#include "diagnostics_pop.hpp"
#endif // PHONG_HAS_XSIMD
