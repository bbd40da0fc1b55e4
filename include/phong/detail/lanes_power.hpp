// phong: x^m on float SIMD lanes for the lighting model's domain (x in [0, 1], m >= 0): the power
// of shade_batch's exact mode (math_traits<xsimd::batch<float>>::pow_unit, batch.hpp). Included by
// batch.hpp after xsimd.
// SPDX-License-Identifier: MIT
//
// Why not exp(m log x) with xsimd's kernels (what double lanes use): their log divides (vdivps: one
// per 6 cycles on Zen 4), both handle special values the model never passes, and together they
// were a third of the lit pair's instructions. This is straight-line code, no division, no table:
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

#if __has_include(<xsimd/xsimd.hpp>) && !defined(__CUDACC__)
#include <xsimd/xsimd.hpp>

#include "../math.hpp"

#include <cstdint>
#include <limits>

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

/// x^m lane-wise for x in [0, 1], m >= 0 finite (see the header comment for the method and bound).
template <class V>
#if defined(__GNUC__)
__attribute__((always_inline))
#endif
inline V pow_unit(const V& x, const V& m)
{
    using IV = xsimd::batch<std::int32_t, typename V::arch_type>;
    const auto fma = [](const V& a, const V& b, const V& c) { return math_traits<V>::fma(a, b, c); }; // fused (xsimd 8.1's is not on AVX-512)
    const V one(1.0f);
    // x = 2^e f with f in [sqrt(1/2), sqrt(2)): subtracting the bits of sqrt(1/2) and shifting
    // gives e (arithmetic shift: e < 0 for x < sqrt(1/2)); removing e from the exponent field, f.
    const V xn = xsimd::max(x, V(std::numeric_limits<float>::min())); // 0, subnormals: 2^-126
    const IV bits = xsimd::bitwise_cast<IV>(xn);
    const IV e = (bits - IV(0x3f3504f3)) >> 23;
    const V t = xsimd::bitwise_cast<V>(bits - (e << 23)) - one;
    V p(log2_coefficients[0]);
    for (int k = 1; k < 9; ++k) p = fma(p, t, V(log2_coefficients[k]));
    const V log2x = fma(t, p, xsimd::to_float(e));
    // y <= 0; clamped where 2^y is 0 in float anyway (and for a NaN y: max returns the bound).
#if defined(__AVX512F__)
    constexpr bool scalef = sizeof(V) == 64;
#else
    constexpr bool scalef = false;
#endif
    // scalef takes any k; else the exponent field k + 127 stays >= 0 (field 0: the value 0).
    constexpr float y_min = scalef ? -150.0f : -127.0f;
    const V y = xsimd::max(m * log2x, V(y_min));
    const V k = xsimd::nearbyint(y);
    const V r = y - k;
    V q(exp2_coefficients[0]);
    for (int j = 1; j < 6; ++j) q = fma(q, r, V(exp2_coefficients[j]));
    const V mantissa = fma(r, q, one);
    V power;
#if defined(__AVX512F__)
    if constexpr (scalef) {
        power = V(_mm512_scalef_ps(mantissa, k));
    } else
#endif
    {
        const IV field = (xsimd::to_int(k) + IV(127)) << 23;
        power = mantissa * xsimd::bitwise_cast<V>(field);
    }
    // pow(0, m > 0) = 0 (2^(-126 m) above is not 0 for m < 1); pow(0, 0) = 1 comes out of y = 0.
    return xsimd::select(x > V(0.0f) || m == V(0.0f), power, V(0.0f));
}

} // namespace phong::detail::lanes
#endif // xsimd
