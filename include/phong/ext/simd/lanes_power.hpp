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
// 2.5 u at a highlight's peak, 38 u where x^m = 2^-10. Results below the power floor 2^-100
// (ieee::power_floor_log2<float>) are 0: absolute error below 2^-100, and no subnormal number is
// made or read (each would cost a microcode assist on x86 cores in the default floating-point
// environment). tests/lanes_power.test.cpp checks the bound against long double pow on sweeps the
// derivation did not choose.
// Edges: x = 0 gives 0 for m > 0 and 1 for m = 0 (pow(0, 0) = 1); 0 < x < 2^-126 (a cosine lost to
// underflow) is taken as 2^-126, so the result lies between x^m and 2^(-126 m);
// x = 1 gives exactly 1; m up to the largest float gives a finite result (y is clamped below).
// Outside the domain (x < 0, x > 1, NaN, m < 0 or inf) the result is unspecified but never a trap
// and never undefined behaviour (NaN y is clamped like -inf).
#pragma once

#include "backend.hpp"

#include <cmath>
#include <cstddef>
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

/// The documented relative error bound of pow_unit below, for y = m log2 x (results >= 2^-100; below: 0).
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

/// 2^y on the lanes of `kept`, 0 on the others: k = round(y), r = y - k, 2^r = 1 + r R(r) by
/// Horner's scheme, times 2^k exactly. The kept lanes must have y >= -100.01 or so (the power floor,
/// ieee::power_floor_log2<float>, less the rounding of y), so that their result is a normal number.
/// Clamp: y is first clamped at -101, so that no lane makes a subnormal number in the exponent-field
/// arithmetic (and a NaN y is clamped too); without it (y known finite) AVX-512's masked scalef
/// computes nothing in the other lanes (no result, no exception), and other ISAs clamp anyway.
/// Why a third exp2 beside power::exp2_tabulated (detail/power.hpp) and fast::detail::exp2_estrin
/// (fast_math.hpp): the tables would be a gather per lane, and the fast mode's degree-5 polynomial
/// is too coarse for the exact mode's bound (pow_unit_lanes_error); different coefficients, so
/// merging either would change the bits of one mode.
template <class V, bool Clamp> PHONG_LANES_INLINE V exp2_kept(const V& y_in, const typename V::batch_bool_type& kept)
{
    using IV = xsimd::batch<std::int32_t, typename V::arch_type>;
#if defined(__AVX512F__)
    constexpr bool scalef = sizeof(V) == 64;
#else
    constexpr bool scalef = false;
#endif
    constexpr float floor = float(ieee::power_floor_log2<float>);
    V y = y_in;
    if constexpr (Clamp || !scalef) y = xsimd::max(y_in, V(floor - 1.0f)); // NaN: -101
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
    if constexpr (scalef) return V(_mm512_maskz_scalef_ps(kept.data, mantissa, k));
#endif
    const IV field = (xsimd::to_int(k) + IV(127)) << 23;
    return xsimd::select(kept, mantissa * xsimd::bitwise_cast<V>(field), V(0.0f));
}

/// 2^y for y <= 0; 0 for y below the power floor -100 (ieee::power_floor_log2<float>: no subnormal
/// result, and none from its product by the light's coefficients) and for a NaN y (exp2_kept,
/// the lanes with y >= -100 kept). Finite: y known finite (not NaN): no clamp under AVX-512.
template <class V, bool Finite = false> PHONG_LANES_INLINE V exp2_horner(const V& y)
{
    return exp2_kept<V, !Finite>(y, y >= V(float(ieee::power_floor_log2<float>))); // false for NaN
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

/// pow_unit_positive on the lanes of `kept` only, 0 on the others, for a caller that knows which
/// powers are at least the power floor: kept lanes must have x > least_base(m) (or m = 0); there
/// the same bits as pow_unit_positive (but for powers in [2^-101, 2^-100), kept here, 0 there); no
/// lane makes or reads a subnormal number. shade_batch's
/// exact float lanes: `kept` is the mask of the lit lanes with c > least_base(m), so the select of
/// the power and the floor's test are both in the mask (AVX-512: the masked scalef, no compare).
template <class V> PHONG_LANES_INLINE V pow_unit_kept(const V& x, const V& m, const typename V::batch_bool_type& kept)
{
    V e;
    const V t = split_exponent(xsimd::max(x, V(std::numeric_limits<float>::min())), e);
    return exp2_kept<V, false>(m * log2_of_split(t, e), kept);
}

/// least_base's lanes with m > 2^20, where float's 2^(-100 / m) is too coarse (near 1, one ulp
/// of the base moves m log2 x by m 2^-24 / ln 2): 2^(-100 / m) in double, rounded down to float.
/// Out of line: a shininess above 2^20 is rare.
template <class V> V least_base_wide(const V& m, const V& least)
{
    alignas(64) float ms[V::size], out[V::size];
    m.store_aligned(ms);
    least.store_aligned(out);
    for (std::size_t i = 0; i < V::size; ++i) {
        if (!(ms[i] > 0x1p20f)) continue;
        const double t = std::exp2(double(ieee::power_floor_log2<float>) / double(ms[i]));
        float f = static_cast<float>(t);
        if (double(f) >= t) f = std::nextafter(f, 0.0f);
        out[i] = f;
    }
    return V::load_aligned(out);
}

/// A base below which x^m is under the power floor 2^-100, for m > 0 (finite): every x >= 2^(-100 / m)
/// has x > least_base(m), and every x > least_base(m) has x^m >= 2^-101, a normal number (the
/// lanes of pow_unit_kept). Up to m = 2^20: 2^(-100 / m) by exp2_horner, lowered by its error bound
/// ((2.5 + 69.3 / m) u relative: exp2_horner's 2.5 u and the quotient's rounding times ln 2 |y|)
/// and the product's rounding, i.e. by (4 + 101 / m) u; that moves m log2 x by at most
/// (10.8 m + 245) u <= 0.7. Above 2^20: least_base_wide. 0 for m < 1: every positive base (its
/// power is then at least 2^-126, bases below 2^-126 being taken as 2^-126).
template <class V> PHONG_LANES_INLINE V least_base(const V& m)
{
    const V y = V(float(ieee::power_floor_log2<float>)) / m;
    const V least = exp2_horner(y) * (V(1.0f) - (V(4.0f) + V(101.0f) / xsimd::max(m, V(1.0f))) * V(0x1p-24f));
    if (xsimd::any(m > V(0x1p20f))) [[unlikely]] return least_base_wide(m, least);
    return least;
}

/// x^m lane-wise for x in [0, 1], m >= 0 finite.
template <class V> PHONG_LANES_INLINE V pow_unit(const V& x, const V& m) { return pow_unit(x, m, m == V(0.0f)); }

/// The documented relative error bound of pow_one_minus below, for y = m log2(1 - x) (results
/// >= 2^-100; below: 0): pow_unit's, plus the rounding of 1 - x (relative u, at most 2.9 u relative to
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
    const V y = m * log2_base;
    // 0^m as pow_unit's select, and the power floor (exp2_horner's), in the one mask of exp2_kept
    const auto kept = (c > V(0.0f) || m == V(0.0f)) && y >= V(float(ieee::power_floor_log2<float>));
    return exp2_kept<V, true>(y, kept);
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
