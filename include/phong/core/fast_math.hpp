// phong: the approximations of the `fast` evaluation mode, each in phong::fast under the name of
// its exact twin, its bound as a constant beside it; one template for float, double and SIMD
// batches (bit access through fast::detail::lanes<V>, xsimd's in ext/simd/fast_lanes.hpp).
// SPDX-License-Identifier: MIT
// Derivations of the bounds: docs/accuracy.md#fast-mode.
#pragma once

#include "fast_sfu.hpp"
#include "math.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

// Float scalars on x86-64: rsqrtss by inline assembly (no <immintrin.h> in users' translation units).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE__) && !defined(__CUDA_ARCH__)
#  define PHONG_FAST_X86_RSQRT 1
#else
#  define PHONG_FAST_X86_RSQRT 0
#endif

#include "diagnostics_push.hpp"

namespace phong::fast {

namespace detail {
/// Lane-wise bit access for the fast kernels (scalars here; xsimd batches in ext/simd/fast_lanes.hpp).
template <class V, class Enable = void>
struct lanes {
    static_assert(std::is_same_v<V, float> || std::is_same_v<V, double>, "phong::fast: no lanes<V> for this type");
    using bits_t = std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>; ///< V's bits as an unsigned integer
    /// The bits of x.
    PHONG_INLINE static constexpr bits_t bits(V x) { return std::bit_cast<bits_t>(x); }
    /// The V whose bits are u.
    PHONG_INLINE static constexpr V from_bits(bits_t u) { return std::bit_cast<V>(u); }
    /// a * b + c (contracted to an fma where the compiler does).
    PHONG_INLINE static constexpr V madd(V a, V b, V c) { return a * b + c; }
};
} // namespace detail

namespace detail {

/// T's binary format. The coefficients below (Chebyshev-node interpolants, rounded to float, for
/// both T: the fast mode promises float's bound):
///   log2(1 + r) = r P(r), r in [sqrt(1/2) - 1, sqrt(2) - 1], degree 7: relative error 2.1e-7
///   2^t = E(t),           t in [-1/2, 1/2],                  degree 5: relative error 2.1e-7
template <class T>
struct format {
    static constexpr bool is_float = sizeof(T) == 4;
    static constexpr int mantissa_bits = is_float ? 23 : 52;
    static constexpr int bias = is_float ? 127 : 1023;
    using bits_t = std::conditional_t<is_float, std::uint32_t, std::uint64_t>;
    static constexpr bits_t one_bits = bits_t(bias) << mantissa_bits;                     // bits of 1.0
    static constexpr bits_t sqrt_half_bits = is_float ? 0x3f3504f3u : 0x3fe6a09e667f3bcdull; // bits of sqrt(1/2)
    static constexpr T shift = is_float ? T(0x1.8p23) : T(0x1.8p52); // ulp 1: y + shift rounds y to an integer
    static constexpr T min_normal = std::numeric_limits<T>::min();
    static constexpr T subnormal_scale = is_float ? T(0x1p24) : T(0x1p54); // lifts every subnormal to a normal number
    static constexpr T subnormal_log2 = is_float ? T(24) : T(54);
};

inline constexpr float log2_p[8] = {0x1.715476p+0f,  -0x1.71552cp-1f, 0x1.ec756ep-2f, -0x1.70dedep-2f,
                                    0x1.262f0ep-2f, -0x1.fe823ap-3f, 0x1.dc78f4p-3f, -0x1.245f38p-3f};
inline constexpr float exp2_e[6] = {0x1p+0f, 0x1.62e43p-1f, 0x1.ebf906p-3f, 0x1.c6af6cp-5f, 0x1.3d107p-7f, 0x1.5f089p-10f};

/// log2 x for x > 0 finite (subnormals included); other x give a finite value the callers select
/// away. x = 2^k f, f in [sqrt(1/2), sqrt(2)): k + r P(r), r = f - 1, Estrin's scheme. Kept apart
/// from power.hpp's tables and lanes::log2_of_split (ext/simd/lanes_power.hpp): those are for tighter bounds.
template <class V>
PHONG_INLINE constexpr V log2_estrin(V x)
{
    using S = phong::detail::scalar_t<V>;
    using fmt = format<S>;
    using L = lanes<V>;
    using U = typename L::bits_t;
    const auto subnormal = x < V(fmt::min_normal);
    const V xs = phong::detail::select(subnormal, x * V(fmt::subnormal_scale), x);
    const U u = L::bits(xs);
    // (u - bits(sqrt(1/2)) + bits(1)) >> mantissa_bits is k + bias, k the exponent of x / sqrt(1/2):
    // nonnegative for every positive normal x, so a logical shift (unsigned) does.
    const U biased = (u - U(fmt::sqrt_half_bits) + U(fmt::one_bits)) >> fmt::mantissa_bits;
    const V f = L::from_bits(u - (biased << fmt::mantissa_bits) + U(fmt::one_bits)); // x / 2^k in [sqrt(1/2), sqrt(2))
    // k as a V without an integer conversion: bits of shift + (k + bias), minus shift + bias. Both
    // opaque so -ffast-math neither rewrites the first nor reassociates r P into the second's rounding.
    const V k = phong::detail::ieee::opaque(phong::detail::ieee::opaque(L::from_bits(biased + L::bits(V(fmt::shift)))) -
                                            V(fmt::shift + S(fmt::bias)));
    const V r = phong::detail::ieee::opaque(f - V(S(1))); // the reduced argument, not re-expanded as f P - P
    // Estrin's scheme: three dependent multiply-adds instead of Horner's seven (latency).
    const auto c = [](int i) { return V(S(log2_p[i])); };
    const V r2 = r * r, r4 = r2 * r2;
    const V p01 = L::madd(c(1), r, c(0)), p23 = L::madd(c(3), r, c(2)), p45 = L::madd(c(5), r, c(4)), p67 = L::madd(c(7), r, c(6));
    const V p = L::madd(L::madd(p67, r2, p45), r4, L::madd(p23, r2, p01));
    return L::madd(r, p, k - phong::detail::select(subnormal, V(fmt::subnormal_log2), V(S(0))));
}

/// 2^y for y <= 0: 2^n from the exponent bits (n = round(y)) times E(t), t = y - n (2.1e-7).
/// y below the power floor (ieee::power_floor_log2), -inf or NaN gives 0 (no subnormal result);
/// y > 0 is outside the domain. Kept apart from power::exp2_tabulated (power.hpp) and
/// lanes::exp2_horner (ext/simd/lanes_power.hpp): those are for tighter bounds.
template <class V>
PHONG_INLINE constexpr V exp2_estrin(V y)
{
    using S = phong::detail::scalar_t<V>;
    using fmt = format<S>;
    using L = lanes<V>;
    using U = typename L::bits_t;
    constexpr S floor = S(phong::detail::ieee::power_floor_log2<S>);
    const V yc = phong::detail::max(y, V(floor - S(1))); // 2^n normal (a NaN y is selected away below)
    const auto [shifted, rounded] = phong::detail::ieee::round_by_shift(yc, V(fmt::shift)); // low bits: n = round(y)
    const V t = phong::detail::ieee::opaque(yc - rounded); // exact; not re-expanded as yc E - rounded E
    const U n_biased = L::bits(shifted) - L::bits(V(fmt::shift)) + U(U(fmt::bias));
    const V scale = L::from_bits(n_biased << fmt::mantissa_bits); // 2^n
    const auto c = [](int i) { return V(S(exp2_e[i])); };
    const V t2 = t * t;
    const V e = L::madd(L::madd(L::madd(c(5), t, c(4)), t2, L::madd(c(3), t, c(2))), t2, L::madd(c(1), t, c(0))); // Estrin
    return phong::detail::select(y >= V(floor), scale * e, V(S(0)));
}

/// Relative error bound of fast::pow_unit where the exact x^m >= 2^-24; below that its absolute
/// error is at most 2^-24 pow_unit_max_rel (derivation: docs/accuracy.md#fast-mode). Declared in
/// phong::fast by phong/accuracy.hpp.
inline constexpr double pow_unit_max_rel = 8e-6;

} // namespace detail

/// Fast x^m for x in [0, 1], m >= 0 finite: 2^(m log2 x), polynomials of degree 7 and 5.
/// Error: pow_unit_max_rel (see there). Edge: m = 0 gives 1 (pow(0, 0) = 1); x = 0 gives 0 for
/// m > 0; x = 1 gives 1; results below the power floor (2^-100 float, 2^-996 double) are 0. Never
/// NaN or inf (NaN x: 1 for m = 0, else 0; clamp x > 1). Exact twin: phong::detail::pow_unit.
/// Float in CUDA device code: the SFU's lg2/ex2, bound pow_unit_sfu_max_rel(m) (fast_sfu.hpp).
template <class V>
PHONG_INLINE constexpr V pow_unit(V x, V m)
{
    using S = phong::detail::scalar_t<V>;
#if defined(__CUDA_ARCH__)
    if constexpr (std::is_same_v<V, float>)
        if (!PHONG_DETAIL_CONSTANT_EVALUATED()) return detail::pow_unit_sfu(x, m);
#endif
    const V y = m * detail::log2_estrin(x);
    const V p = detail::exp2_estrin(phong::detail::min(y, V(S(0))));
    const auto positive = x > V(S(0));
    return phong::detail::select(positive, phong::detail::select(m == V(S(0)), V(S(1)), p), phong::detail::power_of_zero(m));
}

namespace detail {
/// Largest exponent fast::detail::pow_integer takes (its error grows like the exponent).
inline constexpr unsigned pow_integer_max_exponent = 64;

/// Relative error bound of fast::detail::pow_integer: (n - 1) u for n <= pow_integer_max_exponent,
/// 63 u = 3.8e-6 in float, within pow_unit_max_rel (derivation: docs/accuracy.md#fast-mode).
template <class T> inline constexpr double pow_integer_max_rel = double(pow_integer_max_exponent - 1) * double(std::numeric_limits<phong::detail::scalar_t<T>>::epsilon()) / 2;

/// pow_integer's schedule for one exponent n, made once where many powers share n.
struct pow_integer_plan {
    unsigned squarings = 0;  ///< floor(log2 n) (0 for n = 0 and 1)
    unsigned multiplies = 0; ///< n's bits below its top bit: bit i set, multiply by x after the squaring that leaves i to go
    unsigned chain = 0;      ///< 0: n = 0; 1 to 7: n = 2^(chain - 1); 8: any other n
};

/// The schedule of x^n for n in [0, pow_integer_max_exponent].
PHONG_INLINE constexpr pow_integer_plan plan_pow_integer(unsigned n)
{
    pow_integer_plan plan;
    if (n == 0) return plan;
    while ((n >> plan.squarings) > 1u) ++plan.squarings;
    plan.multiplies = n - (1u << plan.squarings);
    plan.chain = plan.multiplies == 0 && plan.squarings <= 6 ? plan.squarings + 1 : 8;
    return plan;
}

/// pow_integer(x, n) with n's schedule given; a power of two n is a chain of squarings entered at its length.
template <class V>
PHONG_INLINE constexpr V pow_integer(V x, const pow_integer_plan& plan)
{
    using S = phong::detail::scalar_t<V>;
    V power = x;
    switch (plan.chain) {
    case 0: return V(S(1)); // pow(0, 0) = 1
    case 7: power = power * power; [[fallthrough]];
    case 6: power = power * power; [[fallthrough]];
    case 5: power = power * power; [[fallthrough]];
    case 4: power = power * power; [[fallthrough]];
    case 3: power = power * power; [[fallthrough]];
    case 2: power = power * power; [[fallthrough]];
    case 1: return power;
    default: break;
    }
    for (unsigned i = plan.squarings; i-- > 0;) { // left to right: the bits below n's top one
        power = power * power;
        if ((plan.multiplies >> i) & 1u) power = power * x;
    }
    return power;
}

/// Fast x^n for x in [0, 1] and one integer n in [0, pow_integer_max_exponent] for every lane, by
/// left-to-right binary powering (floor(log2 n) squarings, popcount(n) - 1 products by x).
/// Error: relative pow_integer_max_rel<T> (larger n: (n - 1) u). Edge: n = 0 gives 1 (pow(0, 0) = 1);
/// x = 0 gives 0 for n > 0; x = 1 gives 1. Exact twin: phong::detail::pow_unit.
template <class V>
PHONG_INLINE constexpr V pow_integer(V x, unsigned n)
{
    return pow_integer(x, plan_pow_integer(n));
}

/// Relative error bound of fast::detail::reciprocal_normal for a positive normal x (float lanes: an
/// estimate plus one Newton step; elsewhere 1/x; derivation: docs/accuracy.md#fast-mode).
template <class T> inline constexpr double reciprocal_max_rel = sizeof(T) == 4 ? 2.5e-7 : 1.2e-16;

/// Fast 1/x for a positive normal x: r0 + r0 (1 - x r0), r0 the float lanes' hardware estimate;
/// elsewhere 1/x. Error: reciprocal_max_rel<T>. Edge: other x give an unspecified value, maybe NaN
/// (no guards). Exact twin: 1 / x.
template <class V>
PHONG_INLINE constexpr V reciprocal_normal(V x)
{
    if constexpr (requires { lanes<V>::reciprocal_normal(x); }) return lanes<V>::reciprocal_normal(x);
    else return V(phong::detail::scalar_t<V>(1)) / x;
}
} // namespace detail

namespace detail {

/// Relative error bound of fast::rsqrt for a positive normal x (derivation: docs/accuracy.md#fast-mode).
/// Declared in phong::fast by phong/accuracy.hpp.
template <class T> inline constexpr double rsqrt_max_rel = sizeof(T) == 4 ? 4e-7 : 4e-16;

/// One Newton step for 1/sqrt(x) in product form, r (3/2 - (x/2) r^2), half_x = x/2. Kept apart
/// from the exact lanes' correction form (ext/simd/math_traits.hpp): without a fused 1 - x r^2 that
/// form gains nothing, and the two round differently (swapping would change the fast mode's bits).
template <class V>
PHONG_INLINE constexpr V rsqrt_newton_product(V half_x, V r)
{
    return r * lanes<V>::madd(-half_x, r * r, V(phong::detail::scalar_t<V>(1.5)));
}

} // namespace detail

/// Fast 1/sqrt(x) for a positive normal x: r0 (3/2 - x/2 r0^2), r0 a hardware estimate (rsqrtss on
/// x86 float scalars; exact 1/sqrt(x) for double and elsewhere; CUDA float: rsqrtf, rsqrt_sfu_max_rel).
/// Error: rsqrt_max_rel<T>. Edge: x = 0 gives inf, inf gives 0; x < 0 or NaN: NaN; subnormal x:
/// inf with rsqrtss, else exact. Exact twin: phong::detail::rsqrt.
template <class V>
PHONG_INLINE constexpr V rsqrt(V x)
{
    if constexpr (requires { detail::lanes<V>::rsqrt(x); }) {
        return detail::lanes<V>::rsqrt(x); // SIMD batches
    } else {
#if defined(__CUDA_ARCH__)
        if constexpr (std::is_same_v<V, float>)
            if (!PHONG_DETAIL_CONSTANT_EVALUATED()) return rsqrtf(x);
#endif
#if PHONG_FAST_X86_RSQRT
        if constexpr (std::is_same_v<V, float>) {
            if (!PHONG_DETAIL_CONSTANT_EVALUATED()) {
                float r0;
#  if defined(__AVX__) // three operands: the upper lanes come from x itself, no false dependency
                __asm__("vrsqrtss %1, %1, %0" : "=x"(r0) : "x"(x));
#  else
                r0 = x;
                __asm__("rsqrtss %0, %0" : "+x"(r0));
#  endif
                const float r1 = detail::rsqrt_newton_product(0.5f * x, r0);
                return phong::detail::ieee::positive_finite(r0) ? r1 : r0;
            }
        }
#endif
        return phong::detail::rsqrt(x);
    }
}

} // namespace phong::fast
#include "diagnostics_pop.hpp"
