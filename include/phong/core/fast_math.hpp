// phong: the approximations of the `fast` evaluation mode (features::mode = evaluation::fast), each
// a named function in phong::fast under the name of its exact twin, its bound as a constant beside it.
// SPDX-License-Identifier: MIT
//
// For colours that end in 8-bit or half-float pixels: half an 8-bit level is 2e-3 of full scale,
// half a half-float ulp 2.4e-4 relative. The bounds below are a few 1e-7 to 1e-5, so the fast
// mode's error stays the exact mode's conditioning (phong/accuracy.hpp, bounds<evaluation::fast, T>).
// The same templates run on float, double and SIMD batches: the lane-wise bit operations come from
// `fast::detail::lanes<V>`, specialized for xsimd batches in detail/simd/fast_lanes.hpp (included by batch.hpp through detail/batch/kernel.hpp).
// The fast mode's route (detail/exact.hpp) keeps the exact mode's kernels on float SIMD lanes, which
// are of the same kind and cost there (detail/simd/lanes_power.hpp, rsqrt_normal) and within these bounds.
// tests/fast_math.test.cpp checks every bound on dense sweeps against long double; the benchmark
// rows kernel.fast_pow_unit.* and kernel.fast_rsqrt.* (benchmarks/kernels.bench.cpp) time each function
// beside its exact twin.
#pragma once

#include "fast_sfu.hpp"
#include "math.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

// Float scalars on x86-64 (g++, clang++): the rsqrtss instruction through inline assembly, as
// math.hpp takes sqrtss (no <immintrin.h> in every user's translation unit).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE__) && !defined(__CUDA_ARCH__)
#  define PHONG_FAST_X86_RSQRT 1
#else
#  define PHONG_FAST_X86_RSQRT 0
#endif

namespace phong::fast {

namespace detail {
/// Lane-wise bit access for the fast kernels: the unsigned integer type of V's bits, the casts,
/// and a multiply-add (contracted to an fma where the hardware has one). Scalars here; xsimd
/// batches in detail/simd/fast_lanes.hpp.
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

/// The kernels' constants for T (float or double): binary format and polynomial coefficients.
/// The coefficients interpolate at Chebyshev nodes (near-minimax), rounded to float, found by
/// tests/fast_math_coefficients.cpp (it prints them and their errors):
///   log2(1 + r) = r P(r), r in [sqrt(1/2) - 1, sqrt(2) - 1], degree 7: relative error 2.1e-7
///   2^t = E(t),           t in [-1/2, 1/2],                  degree 5: relative error 2.1e-7
/// Both T use float's coefficients: the bound is float's whatever T (double gains nothing but
/// the rounding of the arithmetic), which is what the fast mode promises.
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

/// log2 x for x > 0 finite (subnormal x included). Other x give a finite value (no NaN): the
/// callers select them away. x = 2^k f, f in [sqrt(1/2), sqrt(2)), log2 x = k + r P(r), r = f - 1,
/// P of degree 7 by Estrin's scheme. One template for every width: scalars and SIMD lanes differ
/// only in V (lanes<V>'s bit access). Beside it: power.hpp's tables (the exact scalar power) and
/// lanes::log2_of_split (detail/simd/lanes_power.hpp: the exact mode's float lanes, a degree-8 fit
/// for their tighter bound).
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
    // k as a V without an integer conversion: the bits of shift + (k + bias), minus shift + bias.
    // Both steps opaque: the first, or g++ -ffast-math rewrites it on SSE2 lanes into a wrong k;
    // the difference, or it reassociates r P + (that number - (shift + bias)) into
    // (r P + that number) - (shift + bias), where r P is lost in the rounding to shift's ulp 1.
    const V k = phong::detail::ieee::opaque(phong::detail::ieee::opaque(L::from_bits(biased + L::bits(V(fmt::shift)))) -
                                            V(fmt::shift + S(fmt::bias)));
    const V r = phong::detail::ieee::opaque(f - V(S(1))); // the reduced argument, not re-expanded as f P - P
    // Estrin's scheme: three dependent multiply-adds instead of Horner's seven (the power's latency
    // is what a light loop waits for; the same number of operations within two multiplications).
    const auto c = [](int i) { return V(S(log2_p[i])); };
    const V r2 = r * r, r4 = r2 * r2;
    const V p01 = L::madd(c(1), r, c(0)), p23 = L::madd(c(3), r, c(2)), p45 = L::madd(c(5), r, c(4)), p67 = L::madd(c(7), r, c(6));
    const V p = L::madd(L::madd(p67, r2, p45), r4, L::madd(p23, r2, p01));
    return L::madd(r, p, k - phong::detail::select(subnormal, V(fmt::subnormal_log2), V(S(0))));
}

/// 2^y for y <= 0: y rounded to an integer n plus t in [-1/2, 1/2], 2^n from the exponent bits,
/// 2^t = E(t) of degree 5 by Estrin's scheme (float's accuracy, 2.1e-7, whatever V).
/// y below the power floor (ieee::power_floor_log2: -100 float, -996 double), -inf or NaN gives 0
/// (flushed: no subnormal result, nor one from its product by a light's coefficients; y is clamped
/// at the floor - 1 first, so no step makes one either); y > 0 is outside the domain.
/// The fast mode's exp2 at every width (scalars and lanes: one template). Its two siblings are
/// for tighter bounds: power::exp2_tabulated (detail/power.hpp: the exact scalar power, tables in
/// double) and lanes::exp2_horner (detail/simd/lanes_power.hpp: the exact mode's float lanes,
/// degree 6, within 2.5 u).
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

/// Relative error bound of fast::pow_unit where the exact x^m >= 2^-24 (|m log2 x| <= 24); below
/// that its absolute error is at most 2^-24 pow_unit_max_rel. Derived: E's 2.1e-7 and the float
/// rounding of E, plus ln 2 |m log2 x| times the absolute error of m log2 x (P's 2.1e-7 relative,
/// float rounding of the product): 2.6e-7 + 24 ln 2 (2.5e-7 + 2^-23) = 6.5e-6; measured 5.1e-6 in
/// float, 3.3e-6 in double (tests/fast_math.test.cpp; SSE2, AVX2 and AVX-512 lanes alike), published
/// with a margin.
inline constexpr double pow_unit_max_rel = 8e-6;

} // namespace detail

/// Fast x^m for a base x in [0, 1] and an exponent m >= 0, finite (the specular power):
///   x^m = 2^(m log2 x), log2 by a degree-7 polynomial on the mantissa, 2^y by a degree-5 one.
/// Error: relative pow_unit_max_rel where x^m >= 2^-24; absolute 2^-24 pow_unit_max_rel below.
/// Edge: m = 0 gives 1 for every x (pow(0, 0) = 1); x = 0 gives 0 for m > 0; x = 1 gives exactly 1;
/// results below the power floor 2^-100 (float; double 2^-996: detail::ieee::power_floor_log2) are 0. Outside the domain: never NaN or
/// inf (NaN x gives 1 for m = 0, else 0; x > 1 is treated as 1 only up to P's accuracy, so clamp x).
/// Exact twin: phong::detail::pow_unit (math.hpp). Branch-free: scalars and SIMD lanes alike.
/// Float in CUDA device code: 2^min(m lg2(x), 0) on the GPU's special-function units instead,
/// relative error pow_unit_sfu_max_rel(m) (phong/core/fast_sfu.hpp; the same edges).
template <class V>
PHONG_INLINE constexpr V pow_unit(V x, V m)
{
    using S = phong::detail::scalar_t<V>;
#if defined(__CUDA_ARCH__) // float in CUDA device code: the SFU's lg2/ex2, bound pow_unit_sfu_max_rel(m) (fast_sfu.hpp)
    if constexpr (std::is_same_v<V, float>)
        if (!std::is_constant_evaluated()) return detail::pow_unit_sfu(x, m);
#endif
    const V y = m * detail::log2_estrin(x);
    const V p = detail::exp2_estrin(phong::detail::min(y, V(S(0))));
    const auto positive = x > V(S(0));
    return phong::detail::select(positive, phong::detail::select(m == V(S(0)), V(S(1)), p), phong::detail::power_of_zero(m));
}

namespace detail {
/// Largest exponent fast::detail::pow_integer takes (its error grows like the exponent).
inline constexpr unsigned pow_integer_max_exponent = 64;

/// Relative error bound of fast::detail::pow_integer in T's arithmetic (u = T's unit roundoff, 2^-24 for
/// float): x^n by left-to-right binary powering (the bits of n from the top: square, then
/// multiply by x where the bit is set). With e_k the relative error of the partial power x^k
/// (e_1 = 0), a squaring gives e_2k <= 2 e_k + u and a multiplication by the exact x gives
/// e_(k+1) <= e_k + u, so by induction e_k <= (k - 1) u, first order (n u < 4e-6).
/// For n <= pow_integer_max_exponent: 63 u = 3.8e-6 in float, within pow_unit_max_rel (so the fast
/// mode's bounds, phong/accuracy.hpp, hold unchanged). Results below T's smallest normal number
/// are subnormal or 0 (absolute error below 2^-126). tests/fast_math.test.cpp checks it against
/// long double pow for every n in [0, 64].
template <class T> inline constexpr double pow_integer_max_rel = double(pow_integer_max_exponent - 1) * std::numeric_limits<phong::detail::scalar_t<T>>::epsilon() / 2;

/// fast::detail::pow_integer's schedule for one exponent n, made once where n is the same for many
/// powers (shade_batch: once per call): the squarings and the multiplications by x that follow
/// them, from n's bits. chain: 0 for n = 0 (x^0 = 1), 1 + squarings where n is a power of two
/// (squarings only: pow_integer runs them without a test per step), else 8.
struct pow_integer_plan {
    unsigned squarings = 0;  ///< floor(log2 n) (0 for n = 0 and 1)
    unsigned multiplies = 0; ///< n's bits below its top bit: bit i set, multiply by x after the squaring that leaves i to go
    unsigned chain = 0;      ///< 0: n = 0; 1 to 7: n = 2^(chain - 1); 8: any other n
};

/// The schedule of x^n for n in [0, pow_integer_max_exponent] (larger n: squarings up to 31, see
/// pow_integer's precondition).
PHONG_INLINE constexpr pow_integer_plan plan_pow_integer(unsigned n)
{
    pow_integer_plan plan;
    if (n == 0) return plan;
    while ((n >> plan.squarings) > 1u) ++plan.squarings;
    plan.multiplies = n - (1u << plan.squarings);
    plan.chain = plan.multiplies == 0 && plan.squarings <= 6 ? plan.squarings + 1 : 8;
    return plan;
}

/// Fast x^n with n's schedule given (plan_pow_integer(n)): see pow_integer(x, n) below. A power
/// of two n <= 64 is a chain of squarings entered at its length (one jump, no test per squaring).
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

/// Fast x^n for a base x in [0, 1] and an integer exponent n in [0, pow_integer_max_exponent]:
///   x^n by left-to-right binary powering (floor(log2 n) squarings and popcount(n) - 1
///   multiplications by x; 5 squarings for n = 32, against the two polynomials of
///   fast::pow_unit). n is one value for every lane. The fast mode's SIMD lanes take it where the
///   shininess is such an integer (shade_batch with one material: Blinn-Phong exponents are
///   usually small integers), with the schedule made once per call (pow_integer_plan), else
///   fast::pow_unit's kernels.
/// Error: relative pow_integer_max_rel<T>. Edge: n = 0 gives 1 for every x (pow(0, 0) = 1); x = 0
/// gives 0 for n > 0; x = 1 gives exactly 1. Pre: n <= pow_integer_max_exponent (larger n: the
/// result is still x^n rounded, but the bound grows as (n - 1) u). Exact twin: phong::detail::pow_unit.
template <class V>
PHONG_INLINE constexpr V pow_integer(V x, unsigned n)
{
    return pow_integer(x, plan_pow_integer(n));
}

/// Relative error bound of fast::detail::reciprocal_normal for a positive normal x. Float SIMD lanes: a
/// hardware estimate r0 with relative error e0 refined by one Newton step in correction form,
/// r1 = r0 + r0 (1 - x r0): the step leaves e0^2 (AVX-512 rcp14: e0 < 2^-14, 2^-28; AVX rcp:
/// e0 <= 1.5 2^-12, 2.25 2^-24), 1 - x r0 is one fma (its rounding is u e0: negligible) and the
/// last fma rounds once more (u): 1.06 u (AVX-512), 3.3 u = 2.0e-7 (AVX); published 2.5e-7.
/// Elsewhere 1/x, correctly rounded (u). tests/fast_math.test.cpp measures it over dense sweeps.
template <class T> inline constexpr double reciprocal_max_rel = sizeof(T) == 4 ? 2.5e-7 : 1.2e-16;

/// Fast 1/x for a positive normal x (the caller has checked, or selects the other lanes away):
///   r1 = r0 + r0 (1 - x r0),   r0 the hardware estimate (float SIMD lanes; see detail/simd/fast_lanes.hpp),
/// relative error reciprocal_max_rel<T>; scalars and other lanes: 1/x. Edge: other x (0, inf,
/// subnormal, negative, NaN) give an unspecified value, maybe NaN (no guards: that is the point).
/// Exact twin: 1 / x.
template <class V>
PHONG_INLINE constexpr V reciprocal_normal(V x)
{
    if constexpr (requires { lanes<V>::reciprocal_normal(x); }) return lanes<V>::reciprocal_normal(x);
    else return V(phong::detail::scalar_t<V>(1)) / x;
}
} // namespace detail

namespace detail {

/// Relative error bound of fast::rsqrt for a positive normal x: an estimate with relative error
/// e0 <= 1.5 2^-12 (SSE rsqrtss/rsqrtps, the coarsest used) refined by one Newton step has
/// 1.5 e0^2 = 2.0e-7, plus the step's roundings (<= 2.5 2^-24 = 1.5e-7): 3.5e-7, published 4e-7.
/// Measured over every float in [1, 4) (tests/fast_math.test.cpp): 2.1e-7 (rsqrtss), 1.4e-7 (AVX-512 lanes).
/// Double: the exact 1/sqrt, or with AVX-512 lanes rsqrt14 (2^-14) refined by two Newton steps
/// (1.5 (1.5 2^-28)^2 plus the roundings, 2.5 2^-53): 3.3e-16, published 4e-16; measured 2.7e-16.
template <class T> inline constexpr double rsqrt_max_rel = sizeof(T) == 4 ? 4e-7 : 4e-16;

/// One Newton step for 1/sqrt(x) in product form, r (3/2 - (x/2) r^2), from an estimate r and
/// half_x = x/2: the fast mode's step at every width (float scalars after rsqrtss, double AVX-512
/// lanes twice after rsqrt14; lanes<V>::madd, contracted to an fma where the target has one).
/// It squares the estimate's relative error (1.5 e0^2) and adds about 2.5 u of roundings
/// (rsqrt_max_rel). Why not the correction form r + (r/2)(1 - x r^2) of the exact mode's float
/// lanes (math_traits<xsimd::batch>::rsqrt_newton_correction, detail/simd/math_traits.hpp), which
/// rounds less: without a fused 1 - x r^2 (baseline x86-64 scalars have no fma) the correction
/// form's residual loses what it gains, and this form is within the fast mode's bound everywhere;
/// the two round differently, so one in place of the other would change the fast mode's bits.
template <class V>
PHONG_INLINE constexpr V rsqrt_newton_product(V half_x, V r)
{
    return r * lanes<V>::madd(-half_x, r * r, V(phong::detail::scalar_t<V>(1.5)));
}

} // namespace detail

/// Fast 1/sqrt(x) for a positive normal x: a hardware estimate refined by one Newton step,
///   r1 = r0 (3/2 - x/2 r0^2),
/// relative error rsqrt_max_rel<T>. Float scalars on x86 (SSE): rsqrtss. Double scalars and other
/// targets: the exact 1/sqrt(x). Float in CUDA device code:
/// rsqrtf (rsqrt.approx.f32, rsqrt_sfu_max_rel; a subnormal x gives inf under -ftz). SIMD batches: see
/// detail/simd/fast_lanes.hpp. Edge: x = 0 gives inf, x = inf gives 0 (the estimate, unrefined);
/// x < 0 or NaN: NaN; a subnormal x gives inf with rsqrtss (it reads the input as 0), the exact
/// 1/sqrt(x) elsewhere (shade's fast mode never passes one: it drops such vectors first).
/// Exact twin: phong::detail::rsqrt (math.hpp).
template <class V>
PHONG_INLINE constexpr V rsqrt(V x)
{
    if constexpr (requires { detail::lanes<V>::rsqrt(x); }) {
        return detail::lanes<V>::rsqrt(x); // SIMD batches
    } else {
#if defined(__CUDA_ARCH__) // float in CUDA device code: rsqrtf, bound rsqrt_sfu_max_rel (fast_sfu.hpp)
        if constexpr (std::is_same_v<V, float>)
            if (!std::is_constant_evaluated()) return rsqrtf(x);
#endif
#if PHONG_FAST_X86_RSQRT
        if constexpr (std::is_same_v<V, float>) {
            if (!std::is_constant_evaluated()) {
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
