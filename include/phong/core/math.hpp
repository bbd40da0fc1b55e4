// phong: scalar kernels (sqrt, exp, expm1, log, log1p, pow, fma, min/max/clamp, select) that every
// formula calls instead of std::, so constant evaluation (constexpr_math.hpp) and SIMD batches
// (math_traits<V>, specialized by phong/batch.hpp) run the same templates.
// SPDX-License-Identifier: MIT
#pragma once

#include "config.hpp"
#include "constexpr_math.hpp"
#include "power.hpp"

// g++ and clang++ on x86-64 with SSE2: sqrt through the instruction (math_traits::sqrt).
#if defined(__GNUC__) && defined(__x86_64__) && defined(__SSE2__) && !defined(__CUDA_ARCH__) && !defined(PHONG_NO_X86_SQRT)
#  define PHONG_X86_SQRT 1
#else
#  define PHONG_X86_SQRT 0
#endif

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#if defined(__NVCC__)
// nvcc warns (#20208) at every long double in device code; here it serves only detail::ce and
// cos_degrees, for which double is enough.
#  pragma nv_diagnostic push
#  pragma nv_diag_suppress 20208
#endif

#include "diagnostics_push.hpp"

namespace phong {
namespace detail {

/// Largest distance, in ulp of T, between the constant-evaluation path and std:: for sqrt, exp,
/// log, log1p and pow on finite arguments whose result is a normal number.
inline constexpr int constexpr_tolerance_ulp = 2;



/// e with a * b = fl(a * b) + e exactly (Veltkamp split, Dekker's product), for |a|, |b| below
/// max / 2^((digits + 3) / 2) and e not subnormal. S is the lane type of V.
template <class V, class S = V>
PHONG_INLINE constexpr V dekker_product_error(const V& a, const V& b, const V& p)
{
    const V split = V(S((1ull << ((std::numeric_limits<S>::digits + 1) / 2)) + 1));
    // split * a rounded on its own (unfused_product): fused into ca - a it would not split a.
    const V ca = ieee::opaque(ieee::unfused_product(split, a)), ah = ieee::opaque(ca - ieee::opaque(ca - a)), al = a - ah;
    const V cb = ieee::opaque(ieee::unfused_product(split, b)), bh = ieee::opaque(cb - ieee::opaque(cb - b)), bl = b - bh;
    return ieee::ordered_sum(ah * bh - p, ah * bl, al * bh, al * bl);
}

/// a*b + c with the product exact: exact when c = -fl(a*b), else within 1 ulp (no FMA instruction).
template <class V, class S = V>
PHONG_INLINE constexpr V dekker_fma(const V& a, const V& b, const V& c)
{
    const V p = ieee::unfused_product(a, b); // fl(a b), not fused into p + c
    return ieee::opaque(p + c) + dekker_product_error<V, S>(a, b, p);
}

/// lo with hi + lo = a + b exactly, hi = fl(a + b) (Knuth's TwoSum; ieee::two_sum_error).
template <class T> PHONG_INLINE constexpr T two_sum_error(T a, T b, T hi)
{
    return ieee::two_sum_error(a, b, hi);
}


/// Customization point: phong's scalar kernels on V (float, double, long double here; SIMD in batch.hpp).
template <class V, class Enable = void>
struct math_traits {
    static_assert(std::is_floating_point_v<V>, "phong: no math_traits for this number type");
    using scalar = V; ///< the type of one lane (V itself)
    using mask = bool; ///< the result of a comparison of V

    /// The correctly rounded square root (IEEE); constant evaluation: detail::ce::sqrt.
    PHONG_INLINE static constexpr V sqrt(V x)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::sqrt(static_cast<detail::ce::wide>(x)));
#if PHONG_X86_SQRT
        // std::sqrt's value without its errno path (a libm call whose clobbers cost moves in the loop).
        if constexpr (std::is_same_v<V, float> || std::is_same_v<V, double>) {
            V r;
#  if defined(__AVX__) // three operands: the upper lanes come from x itself, no false dependency
            if constexpr (std::is_same_v<V, float>) __asm__("vsqrtss %1, %1, %0" : "=x"(r) : "x"(x));
            else __asm__("vsqrtsd %1, %1, %0" : "=x"(r) : "x"(x));
#  else // in place: no dependency on an unrelated register's upper lanes
            r = x;
            if constexpr (std::is_same_v<V, float>) __asm__("sqrtss %0, %0" : "+x"(r));
            else __asm__("sqrtsd %0, %0" : "+x"(r));
#  endif
            return r;
        }
#endif
        return std::sqrt(x);
    }
    /// 1/sqrt(x), correctly rounded twice (a division of a square root).
    PHONG_INLINE static constexpr V rsqrt(V x)
    {
        // 1/0 is not a constant expression: rsqrt(0) = inf explicitly.
        if (PHONG_DETAIL_CONSTANT_EVALUATED() && x == V(0)) return std::numeric_limits<V>::infinity();
        return V(1) / sqrt(x);
    }
    /// e^x (std::exp; constant evaluation: detail::ce::exp).
    PHONG_INLINE static constexpr V exp(V x)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::exp(static_cast<detail::ce::wide>(x)));
        return std::exp(x);
    }
    /// The natural logarithm (std::log; constant evaluation: detail::ce::log).
    PHONG_INLINE static constexpr V log(V x)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::log(static_cast<detail::ce::wide>(x)));
        return std::log(x);
    }
    /// log(1 + x), accurate for small x (std::log1p; constant evaluation: detail::ce::log1p).
    PHONG_INLINE static constexpr V log1p(V x)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::log1p(static_cast<detail::ce::wide>(x)));
        return std::log1p(x);
    }
    /// e^x - 1, accurate for small x (std::expm1; constant evaluation: detail::ce::expm1).
    PHONG_INLINE static constexpr V expm1(V x)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::expm1(static_cast<detail::ce::wide>(x)));
        return std::expm1(x);
    }
    /// x^y (std::pow; constant evaluation: detail::ce::pow).
    PHONG_INLINE static constexpr V pow(V x, V y)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) return static_cast<V>(detail::ce::pow(static_cast<detail::ce::wide>(x), static_cast<detail::ce::wide>(y)));
        return std::pow(x, y);
    }
    /// x^m for x in [0, 1], m >= 0: float and double by power.hpp; else (and CUDA) pow.
    PHONG_INLINE static constexpr V pow_unit(V x, V m)
    {
        if constexpr (std::is_same_v<V, float> || std::is_same_v<V, double>) {
#if defined(__CUDA_ARCH__)
            return (x == V(0) && m == V(0)) ? V(1) : ::pow(x, m);
#else
            return detail::power::pow_unit(x, m); // float: shorter polynomials; double: the full kernel
#endif
        } else {
            return pow(x, m);
        }
    }
    /// a * b + c with one rounding. Constant evaluation: exact through Dekker's product.
    PHONG_INLINE static constexpr V fma(V a, V b, V c)
    {
        if (PHONG_DETAIL_CONSTANT_EVALUATED()) {
            if constexpr (std::numeric_limits<V>::digits * 2 <= std::numeric_limits<detail::ce::wide>::digits) {
                using W = detail::ce::wide;
                return static_cast<V>(W(a) * W(b) + W(c)); // exact product
            } else {
                return detail::dekker_fma(a, b, c);
            }
        }
        return std::fma(a, b, c);
    }
    /// a where m, else b.
    PHONG_INLINE static constexpr V select(bool m, V a, V b) { return m ? a : b; }
    /// Whether any lane of m is set (one lane here).
    PHONG_INLINE static constexpr bool any(bool m) { return m; }
    /// a and b, lane-wise.
    PHONG_INLINE static constexpr bool both(bool a, bool b) { return a && b; }
    /// Whether every lane of m is set (one lane here).
    PHONG_INLINE static constexpr bool all(bool m) { return m; }
    /// |x|, with abs(-0) = +0.
    PHONG_INLINE static constexpr V abs(V x) { return x < 0 ? -x : (x == 0 ? V(0) : x); }
    /// The smaller of a and b (b where b < a: a NaN in a is returned, one in b is not).
    PHONG_INLINE static constexpr V min(V a, V b) { return b < a ? b : a; }
    /// The larger of a and b (b where a < b: a NaN in a is returned, one in b is not).
    PHONG_INLINE static constexpr V max(V a, V b) { return a < b ? b : a; }

    /// 2^-e with |x| 2^-e in [1, 2) for normal x (clamped to a normal number), x finite >= 0: an
    /// exact scale that keeps a vector's direction while its squares neither overflow nor underflow.
    PHONG_INLINE static constexpr V inverse_pow2_scale(V x)
    {
        using bits_t = std::conditional_t<sizeof(V) == 4, std::uint32_t, std::uint64_t>;
        if constexpr (std::is_same_v<V, float> || std::is_same_v<V, double>) {
            constexpr int mant = std::numeric_limits<V>::digits - 1;
            constexpr bits_t max_biased = (bits_t(1) << (sizeof(V) * 8 - 1 - mant)) - 2; // 254 / 2046
            const bits_t biased = (std::bit_cast<bits_t>(x) >> mant) & (max_biased + 1);
            bits_t scale_biased = max_biased - biased; // exponent -(e): 2*bias - biased
            if (biased == 0) scale_biased = max_biased; // subnormal: largest scale
            if (scale_biased < 1) scale_biased = 1;
            if (scale_biased > max_biased) scale_biased = max_biased;
            return std::bit_cast<V>(scale_biased << mant);
        } else {
            if (x == 0) return V(1);
            int k = 0;
            (void)detail::ce::reduce_pow2(static_cast<detail::ce::wide>(x), k);
            return static_cast<V>(detail::ce::pow2(-k));
        }
    }

};

/// Mask type of V: bool for scalars, a SIMD mask for batches.
template <class V> using mask_t = typename math_traits<V>::mask;
/// The scalar type of V: V itself for scalars, the lane type for batches.
template <class V> using scalar_t = typename math_traits<V>::scalar;
/// The largest finite value of V's scalar type, as a V (std::numeric_limits<batch> is not specialized).
template <class V> PHONG_INLINE constexpr V largest() { return V(std::numeric_limits<scalar_t<V>>::max()); }

/// sqrt(x), correctly rounded, x >= 0; sqrt(-0) = -0, x < 0 gives NaN (PHONG_NO_X86_SQRT: std::sqrt).
template <class V> PHONG_INLINE constexpr V sqrt(V x) { return math_traits<V>::sqrt(x); }
/// 1/sqrt(x), x >= 0: < 1 ulp (SIMD float lanes < 2); rsqrt(0) = inf, rsqrt(inf) = 0, x < 0 or NaN: NaN.
template <class V> PHONG_INLINE constexpr V rsqrt(V x) { return math_traits<V>::rsqrt(x); }
/// rsqrt for a positive normal x: SIMD float lanes skip the guards for 0 and inf.
template <class V> PHONG_INLINE constexpr V rsqrt_normal(V x)
{
    if constexpr (requires { math_traits<V>::rsqrt_normal(x); }) return math_traits<V>::rsqrt_normal(x);
    else return math_traits<V>::rsqrt(x);
}
/// e^x. Overflow gives inf, underflow 0.
template <class V> PHONG_INLINE constexpr V exp(V x) { return math_traits<V>::exp(x); }
/// ln x. log(0) = -inf, x < 0 gives NaN.
template <class V> PHONG_INLINE constexpr V log(V x) { return math_traits<V>::log(x); }
/// ln(1 + x), accurate for small |x|. log1p(-1) = -inf, x < -1 gives NaN.
template <class V> PHONG_INLINE constexpr V log1p(V x) { return math_traits<V>::log1p(x); }
/// e^x - 1, accurate for small |x|. expm1(-inf) = -1, expm1(+inf) = inf. Scalars only.
template <class V> PHONG_INLINE constexpr V expm1(V x) { return math_traits<V>::expm1(x); }
/// x^y (IEEE pow: pow(0, 0) = 1, pow(0, y > 0) = 0).
template <class V> PHONG_INLINE constexpr V pow(V x, V y) { return math_traits<V>::pow(x, y); }
/// x^m for x in [0, 1], m >= 0 (the specular and spot powers): power.hpp's kernel (bounds there).
/// pow_unit(0, 0) = 1, pow_unit(0, m > 0) = 0; other x or m: IEEE pow's value.
template <class V> PHONG_INLINE constexpr V pow_unit(V x, V m)
{
    if constexpr (requires { math_traits<V>::pow_unit(x, m); }) return math_traits<V>::pow_unit(x, m);
    else return math_traits<V>::pow(x, m);
}
/// pow_unit without its libm fallback, x in [0, 1], m >= 0 finite (else NaN but for 1^m = 1).
/// AtMostOne: x <= 1 by construction, so the test of m log2 x <= 0 is left out.
template <bool AtMostOne = false, class V> PHONG_INLINE constexpr V pow_unit_in_domain(V x, V m)
{
#if !defined(__CUDA_ARCH__)
    if constexpr (std::is_same_v<V, float> || std::is_same_v<V, double>) {
        if constexpr (AtMostOne) return power::pow_unit_at_most_one(x, m);
        else return power::pow_unit_in_domain(x, m);
    } else
#endif
        return detail::pow_unit(x, m);
}
/// pow_unit_in_domain<true>: the power of a base at most 1 by construction.
template <class V> PHONG_INLINE constexpr V pow_unit_at_most_one(V x, V m) { return pow_unit_in_domain<true>(x, m); }
/// a * b + c rounded once; constant evaluation: exact when c = -fl(a b), else within 1 ulp.
template <class V> PHONG_INLINE constexpr V fma(V a, V b, V c) { return math_traits<V>::fma(a, b, c); }
/// |x|.
template <class V> PHONG_INLINE constexpr V abs(V x) { return math_traits<V>::abs(x); }
/// min(a, b) = b < a ? b : a (std::min's NaN behaviour: a NaN `a` is returned).
template <class V> PHONG_INLINE constexpr V min(V a, V b) { return math_traits<V>::min(a, b); }
/// max(a, b) = a < b ? b : a (std::max's NaN behaviour: a NaN `a` is returned).
template <class V> PHONG_INLINE constexpr V max(V a, V b) { return math_traits<V>::max(a, b); }
/// clamp(x, lo, hi) = min(max(x, lo), hi); a NaN x is returned as NaN.
template <class V> PHONG_INLINE constexpr V clamp(V x, V lo, V hi) { return min(max(x, lo), hi); }
/// m ? a : b, lane-wise for SIMD (both sides are evaluated: keep them finite).
template <class V> PHONG_INLINE constexpr V select(mask_t<V> m, V a, V b) { return math_traits<V>::select(m, a, b); }

/// x^N for a compile-time N >= 0 by repeated squaring: relative error <= (N - 1) u. pow<0>(x) = 1.
template <unsigned N, class V> PHONG_INLINE constexpr V pow(V x)
{
    if constexpr (N == 0) {
        return V(1);
    } else if constexpr (N == 1) {
        return x;
    } else {
        const V half = pow<N / 2>(x);
        if constexpr (N % 2 == 0) return half * half;
        else return half * half * x;
    }
}

/// cos(deg pi / 180), exact at 0, 90 and 180; a Taylor series in long double, accurate for
/// |deg| <= 720 (beyond: reduce the angle first). NaN gives NaN.
template <class V> PHONG_INLINE constexpr V cos_degrees(V degrees)
{
    using W = detail::ce::wide;
    W d = static_cast<W>(degrees);
    if (d == 0) return V(1);
    if (d == 90) return V(0);
    if (d == 180) return V(-1);
    constexpr W pi = 3.14159265358979323846264338327950288L;
    const W x = d * pi / 180; // Taylor series; |x| <= pi converges in < 30 terms
    W term = 1, sum = 1;
    for (int i = 1; i < 40; ++i) {
        term *= -x * x / static_cast<W>((2 * i - 1) * (2 * i));
        const W next = sum + term;
        if (next == sum) break;
        sum = next;
    }
    return static_cast<V>(sum);
}

} // namespace detail

} // namespace phong
#include "diagnostics_pop.hpp"

#if defined(__NVCC__)
#  pragma nv_diagnostic pop
#endif
