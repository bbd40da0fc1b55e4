// phong: x^m on float SIMD lanes for x in [0, 1], m >= 0: the power of shade_batch's exact mode
// (math_traits<xsimd::batch<float>>::pow_unit). log2 and exp2 polynomials on the exponent bits, no
// division, no table: relative error (3.5 |y| + 2.5) u, y = m log2 x; results below the power
// floor 2^-100 are 0 (no subnormal made or read). Derivation: docs/accuracy.md#float-lanes-power
// Edges: x = 0 gives 0 (1 for m = 0); 0 < x < 2^-126 is taken as 2^-126; x = 1 gives 1; any finite
// m gives a finite result. Outside the domain: unspecified, never a trap or undefined behaviour.
// SPDX-License-Identifier: MIT
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

/// x = 2^e (1 + t), 1 + t in [sqrt(1/2), sqrt(2)), for a positive normal x, exactly (integer
/// arithmetic on the bits; t = (1 + t) - 1 is exact by Sterbenz).
template <class V> PHONG_LANES_INLINE V split_exponent(const V& x, V& e)
{
    using IV = xsimd::batch<std::int32_t, typename V::arch_type>;
    const IV bits = xsimd::bitwise_cast<IV>(x);
    const IV ei = (bits - IV(0x3f3504f3)) >> 23;
    e = xsimd::to_float(ei);
    return ieee::opaque(xsimd::bitwise_cast<V>(bits - (ei << 23)) - V(1.0f)); // -ffast-math: kept as one value
}

/// e + log2(1 + t) = e + t P(t), P of degree 8 by Horner (finer than fast::detail::log2_estrin's).
template <class V> PHONG_LANES_INLINE V log2_of_split(const V& t, const V& e)
{
    V p(log2_coefficients[0]);
    for (int k = 1; k < 9; ++k) p = fused(p, t, V(log2_coefficients[k]));
    return fused(t, p, e);
}

/// 2^y on the lanes of `kept` (y >= about -100.01: a normal result), 0 on the others: 2^r = 1 + r R(r)
/// by Horner, times 2^k. Clamp: y clamped at -101 first (NaN too), so no lane makes a subnormal;
/// without it (y finite) AVX-512's masked scalef computes nothing in the other lanes. Apart from
/// power::exp2_tabulated and fast::detail::exp2_estrin: other coefficients (merging changes bits).
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
    // The compiler may reassociate: y rounded by the shift (ieee.hpp), |y| <= 150 < 2^22 (xsimd's
    // nearbyint without a rounding instruction has a barrier clang -ffast-math sees through).
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

/// 2^y for y <= 0; 0 below the power floor -100 and for NaN (no subnormal result, nor from the
/// product by the light's coefficients). Finite: y known finite (no clamp under AVX-512).
template <class V, bool Finite = false> PHONG_LANES_INLINE V exp2_horner(const V& y)
{
    return exp2_kept<V, !Finite>(y, y >= V(float(ieee::power_floor_log2<float>))); // false for NaN
}

/// 2^(m log2 x) for x in [0, 1] (0 and subnormals taken as 2^-126), m >= 0 finite; Finite: m <= 2^100.
template <class V, bool Finite = false> PHONG_LANES_INLINE V power_of_log2(const V& x, const V& m)
{
    V e;
    const V t = split_exponent(xsimd::max(x, V(std::numeric_limits<float>::min())), e); // 0, subnormals: 2^-126
    return exp2_horner<V, Finite>(m * log2_of_split(t, e));
}

/// x^m lane-wise for x in [0, 1], m >= 0 finite, with m_is_zero = (m == 0) given (computed once per
/// call by shade_batch). Edges: x <= 0 and NaN give 0^m (0, or 1 for m = 0).
template <class V> PHONG_LANES_INLINE V pow_unit(const V& x, const V& m, const typename V::batch_bool_type& m_is_zero)
{
    const V power = power_of_log2(x, m);
    // 0^m in the same select: pow(0, m > 0) = 0 (2^(-126 m) is not 0 for m < 1); pow(0, 0) = 1 from y = 0.
    return xsimd::select(x > V(0.0f) || m_is_zero, power, V(0.0f));
}

/// pow_unit without the select: x^m for x in (0, 1], 0 <= m <= 2^100 (y finite: no clamp), and for
/// m = 0 any x; lanes with x <= 0 and m > 0 get a nonzero value for the caller to select away. The
/// same bits and bound as pow_unit where not selected away.
template <class V> PHONG_LANES_INLINE V pow_unit_positive(const V& x, const V& m) { return power_of_log2<V, true>(x, m); }

/// pow_unit_positive on the lanes of `kept` only (x > least_base(m), or m = 0), 0 on the others: the
/// same bits but for powers in [2^-101, 2^-100), kept here; no subnormal made or read. shade_batch
/// folds the lit mask and the floor test into `kept` (AVX-512: the masked scalef, no compare).
template <class V> PHONG_LANES_INLINE V pow_unit_kept(const V& x, const V& m, const typename V::batch_bool_type& kept)
{
    V e;
    const V t = split_exponent(xsimd::max(x, V(std::numeric_limits<float>::min())), e);
    return exp2_kept<V, false>(m * log2_of_split(t, e), kept);
}

/// least_base's lanes with m > 2^20 (float's 2^(-100 / m) too coarse): in double, rounded down (rare).
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

/// A base below which x^m is under the power floor, m > 0: every x >= 2^(-100 / m) has
/// x > least_base(m), and every x > least_base(m) has x^m >= 2^-101 (derivation: docs/accuracy.md).
/// 0 for m < 1 (every positive base: bases below 2^-126 count as 2^-126).
template <class V> PHONG_LANES_INLINE V least_base(const V& m)
{
    const V y = V(float(ieee::power_floor_log2<float>)) / m;
    const V least = exp2_horner(y) * (V(1.0f) - (V(4.0f) + V(101.0f) / xsimd::max(m, V(1.0f))) * V(0x1p-24f));
    if (xsimd::any(m > V(0x1p20f))) [[unlikely]] return least_base_wide(m, least);
    return least;
}

/// x^m lane-wise for x in [0, 1], m >= 0 finite.
template <class V> PHONG_LANES_INLINE V pow_unit(const V& x, const V& m) { return pow_unit(x, m, m == V(0.0f)); }

/// The relative error bound of pow_one_minus, y = m log2(1 - x): pow_unit's plus the rounding of 1 - x.
constexpr double pow_one_minus_lanes_error(double y)
{
    return (6.5 * (y < 0 ? -y : y) + 2.5) * 0x1p-24;
}

/// c^m = (1 - x)^m from both forms of a cosine c in [0, 1] (x = 1 - c and c, each a float: the
/// stable lanes' r.v or n.h), m >= 0 finite. Where c >= sqrt(1/2) the polynomial takes t = -x itself
/// (no rounding of 1 - x: a tiny x keeps its relative accuracy); below, c is split as pow_unit's base.
/// Error: pow_one_minus_lanes_error(m log2 c). Edges: x = 0 gives 1; c <= 0 gives 0 (1 for m = 0).
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

/// (1 - x)^m for x in [0, 1], m >= 0 finite: the stable lanes' pow_one_minus (specular.hpp), c = 1 - x.
/// Error: pow_one_minus_lanes_error. Edges: x = 0 gives 1; x >= 1 gives 0 (1 for m = 0).
template <class V> PHONG_LANES_INLINE V pow_one_minus(const V& x, const V& m)
{
    return pow_cosine(x, V(1.0f) - x, m);
}

} // namespace phong::detail::lanes

#include "diagnostics_pop.hpp"
#endif // PHONG_HAS_XSIMD
