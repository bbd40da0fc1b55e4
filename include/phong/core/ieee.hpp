// phong: the few primitives whose meaning rests on IEEE 754 arithmetic, in one place, written so
// that -ffast-math (and its parts) cannot change them.
// SPDX-License-Identifier: MIT
//
// What -ffast-math allows the compiler, and what each primitive here does about it:
//  * -fassociative-math: (y + c) - c may be folded to y, and hi - a to b when hi = a + b. The
//    rounding tricks (2^y's range reduction t = y - ((y + shift) - shift)) and the error-free
//    transformations (TwoSum's (a - (hi - bb)) + (b - bb), the rounded product fma(a, b, 0)) then
//    return 0 instead of the rounding error. opaque(x) returns x through an empty inline asm the
//    optimizer cannot see through, so the value it returns has no known relation to the operands
//    it came from and nothing is folded; it costs no instruction (the value stays in its register).
//    It is active where the compiler says it may reassociate (g++: __ASSOCIATIVE_MATH__, which
//    follows -fassociative-math exactly; clang: __FAST_MATH__, dropped by -fno-associative-math, while
//    its lone -fassociative-math defines nothing: define PHONG_FP_BARRIER=1 there), or always with
//    PHONG_FP_BARRIER=1; identity in IEEE builds and in constant evaluation.
//  * -ffinite-math-only: x != x, x < inf and std::isnan are folded to constants. The tests here
//    read the bits instead (std::bit_cast), which no floating-point flag can change.
#pragma once

#include "config.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

#if !defined(PHONG_FP_BARRIER)
#  if (defined(__GNUC__) && !defined(__clang__)) ? defined(__ASSOCIATIVE_MATH__) : defined(__FAST_MATH__)
#    define PHONG_FP_BARRIER 1
#  else
#    define PHONG_FP_BARRIER 0
#  endif
#endif

namespace phong::detail::ieee {

/// x unchanged, opaque to the optimizer at run time in every build (identity in constant
/// evaluation): the empty asm of opaque() below, unconditionally. Scalars and SIMD batches.
template <class V> PHONG_INLINE constexpr V barrier(V x)
{
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDA_ARCH__)
    if (!std::is_constant_evaluated()) {
        if constexpr (std::is_floating_point_v<V>) {
#  if defined(__x86_64__) || defined(__i386__)
            __asm__("" : "+x"(x));
#  elif defined(__aarch64__)
            __asm__("" : "+w"(x));
#  else
            __asm__("" : "+m"(x));
#  endif
        } else if constexpr (requires { typename V::register_type; }) {
            typename V::register_type r = x;
#  if (defined(__x86_64__) || defined(__i386__)) && defined(__AVX512F__)
            __asm__("" : "+v"(r));
#  elif defined(__x86_64__) || defined(__i386__)
            __asm__("" : "+x"(r));
#  elif defined(__aarch64__)
            __asm__("" : "+w"(r));
#  else
            __asm__("" : "+m"(r));
#  endif
            x = V(r);
        }
    }
#endif
    return x;
}

/// x unchanged, but opaque to the optimizer where it may reassociate (see above): nothing computed
/// from the result is simplified using how x was computed. Scalars (float, double) and SIMD batches
/// (any type with a register_type, e.g. xsimd::batch).
template <class V> PHONG_INLINE constexpr V opaque(V x)
{
#if PHONG_FP_BARRIER
    return barrier(x);
#else
    return x;
#endif
}

/// 1 where the scalar power kernels (detail/power.hpp) keep every product rounded on its own:
/// aarch64, whose FMA instructions are always enabled and which g++ (-ffp-contract=fast, the
/// default outside ISO mode) and clang++ (-ffp-contract=on: within an expression) contract
/// a * b + c into by default. A contracted kernel rounds differently from its constant evaluation
/// (which never contracts), so "constant evaluation and run time give the same bits" would fail
/// (tests/power.test.cpp). Elsewhere 0 (x86-64 contracts only where -mfma or -march enables FMA
/// instructions, an opt-in documented in detail/power.hpp); define PHONG_UNFUSED_KERNELS=1 to keep
/// the products unfused there too.
#if !defined(PHONG_UNFUSED_KERNELS)
#  if defined(__aarch64__)
#    define PHONG_UNFUSED_KERNELS 1
#  else
#    define PHONG_UNFUSED_KERNELS 0
#  endif
#endif

/// a * b rounded on its own (PHONG_UNFUSED_KERNELS: behind barrier(), so no later addition is
/// fused with it), else a * b.
template <class V> PHONG_INLINE constexpr V unfused_product(V a, V b)
{
#if PHONG_UNFUSED_KERNELS
    return barrier(a * b);
#else
    return a * b;
#endif
}

/// y rounded to a multiple of shift's ulp by the sum y + shift (round to nearest; |y| well below
/// shift): sum = y + shift, whose low mantissa bits hold the rounded y as an integer, and value =
/// sum - shift, the rounded y itself. Both opaque: a reassociating compiler would otherwise fold
/// value to y (and y - value, the reduced argument, to 0).
template <class V> struct shift_rounded {
    V sum;
    V value;
};
template <class V> PHONG_INLINE constexpr shift_rounded<V> round_by_shift(V y, V shift)
{
    const V sum = opaque(y + shift);
    return {sum, opaque(sum - shift)};
}

/// The rounding error of hi = fl(a + b): hi + lo = a + b exactly (Knuth's TwoSum), lo returned.
/// Every intermediate passes through opaque, so a reassociating compiler can neither fold
/// (hi - a) back to b nor cancel terms across the sum (both would return 0).
template <class V> PHONG_INLINE constexpr V two_sum_error(const V& a, const V& b, const V& hi)
{
    const V h = opaque(hi);
    const V bb = opaque(h - a);
    const V aa = opaque(h - bb);
    return opaque(a - aa) + opaque(b - bb);
}

/// ((a + b) + c) + d in that order (Dekker's product error: each partial sum exact), each
/// partial sum opaque so that no compiler reorders it.
template <class V> PHONG_INLINE constexpr V ordered_sum(const V& a, const V& b, const V& c, const V& d)
{
    return opaque(opaque(opaque(a) + b) + c) + d;
}

/// False where the compiler may reassociate floating-point sums (PHONG_FP_BARRIER: -ffast-math,
/// -fassociative-math), unless PHONG_ALLOW_REASSOCIATED_TWOFOLD is defined. The stable mode's
/// twofold route (double, or features::precision = twofold) accumulates double-word sums over
/// many steps; opaque() keeps each TwoSum exact, but not the accumulations around them (measured
/// under g++ -O3 -ffast-math: 2.4e-13 relative at m = 1e5 against the published 3e-15), so that
/// route refuses such builds (a static_assert naming the flag, tests/nan_policy/checks.cmake).
template <class T>
inline constexpr bool twofold_allowed =
#if PHONG_FP_BARRIER && !defined(PHONG_ALLOW_REASSOCIATED_TWOFOLD)
    false;
#else
    true;
#endif

/// The unsigned integer of T's width.
template <class T> using bits_of = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
/// The bits of +inf in T (all exponent bits set, mantissa 0).
template <class T> inline constexpr bits_of<T> inf_bits = sizeof(T) == 4 ? bits_of<T>(0x7f800000u) : bits_of<T>(0x7ff0000000000000ull);
/// The sign bit.
template <class T> inline constexpr bits_of<T> sign_bit = bits_of<T>(1) << (8 * sizeof(T) - 1);

/// Classification by bits: the same answer under -ffinite-math-only as in IEEE builds.
template <class T> PHONG_INLINE constexpr bool is_nan(T x)
{
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
    return (std::bit_cast<bits_of<T>>(x) & ~sign_bit<T>) > inf_bits<T>;
}
template <class T> PHONG_INLINE constexpr bool is_inf(T x)
{
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
    return (std::bit_cast<bits_of<T>>(x) & ~sign_bit<T>) == inf_bits<T>;
}
template <class T> PHONG_INLINE constexpr bool is_finite(T x)
{
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
    return (std::bit_cast<bits_of<T>>(x) & ~sign_bit<T>) < inf_bits<T>;
}

/// 0 < x < inf (x not NaN) by bits: scalars give bool; SIMD batches (xsimd's batch<T, A>, found by
/// argument-dependent lookup) give their batch_bool. The guard of a refined hardware estimate
/// (keep the estimate itself where it is 0 or inf), which -ffinite-math-only would fold to x > 0.
template <class T> PHONG_INLINE constexpr bool positive_finite(T x)
{
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
    const bits_of<T> b = std::bit_cast<bits_of<T>>(x);
    return b != 0 && b < inf_bits<T>; // the sign bit set makes b >= inf_bits
}
template <template <class, class> class B, class T, class A>
    requires(std::is_floating_point_v<T>)
auto positive_finite(const B<T, A>& x)
{
    using I = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
    using IB = B<I, A>;
    const IB b = bitwise_cast<IB>(x); // xsimd::bitwise_cast by argument-dependent lookup
    return bool_cast(b > IB(I(0)) && b < IB(static_cast<I>(inf_bits<T>))); // signed: negative x < 0
}


/// The shading's power floor, as a power of two: a specular or spot power x^m whose value is below
/// 2^power_floor_log2<S> is returned as exactly 0 (S the arithmetic's scalar: float 2^-100, double
/// 2^-996, i.e. S's smallest normal number times 2^26). Why: such a power, or its product by the
/// coefficients that scale it (ks Ls times the attenuation and spot factors, at least 2^-26 = 1.5e-8
/// in any ordinary scene), would be a subnormal number, and x86 cores in the default floating-point
/// environment (no flush-to-zero, no denormals-are-zero: Intel's) take a microcode assist, about a
/// hundred cycles, for every subnormal result or operand. Absolute error of the flush: below 2^-100
/// (float) or 2^-996 (double) times ks Ls f, under half an ulp of every channel of at least 2^-76
/// (float) ks Ls f (docs/accuracy.md, "Subnormal numbers").
template <class S> inline constexpr int power_floor_log2 = std::numeric_limits<S>::min_exponent - 1 + 26;

} // namespace phong::detail::ieee
