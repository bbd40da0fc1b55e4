// phong: the few primitives whose meaning rests on IEEE 754 arithmetic, written so that
// -ffast-math cannot change them: opaque() (an empty asm, no instruction) stops -fassociative-math
// from folding rounding steps and error-free transformations to 0; classification reads the bits,
// which -ffinite-math-only cannot fold (docs/compilers.md, "-ffast-math").
// SPDX-License-Identifier: MIT
#pragma once

#include "config.hpp"

#include <bit>
#include <cstdint>
#include <limits>
#include <type_traits>

// Every rounding step and error-free transformation below needs each float and double operation
// rounded to its own type (FLT_EVAL_METHOD 0). x87 arithmetic (32-bit x86 without -mfpmath=sse)
// keeps 64-bit significands in registers, so y + 1.5 2^23 - 1.5 2^23 is no longer y rounded to an
// integer, and the power kernels err by about 5e-3 in every mode.
#if defined(__FLT_EVAL_METHOD__) && __FLT_EVAL_METHOD__ > 0
#  error "phong: float and double arithmetic is evaluated in a wider precision here (__FLT_EVAL_METHOD__ > 0: x87, 32-bit x86 without SSE arithmetic), which phong's rounding steps cannot survive: build with -msse2 -mfpmath=sse"
#endif

// PHONG_FP_REASSOCIATION: 1 where the compiler is known to reassociate floating-point arithmetic;
// it refuses the twofold route and keeps xsimd's exp and log off the x86 lanes that lack a
// rounding instruction (their rounding tricks have no barrier). g++ 12 and later say
// -fassociative-math itself (__ASSOCIATIVE_MATH__). Older g++ says -ffast-math (__FAST_MATH__),
// and __GCC_IEC_559 = 0 for any flag that breaks IEEE arithmetic: with finite math still on
// (-ffast-math -fno-finite-math-only), that is read as reassociation. clang++ says only -ffast-math
// whole and drops __FAST_MATH__ when any of its flags is taken back, though the rest still
// reassociate: define PHONG_FP_REASSOCIATION=1 in such builds.
#if !defined(PHONG_FP_REASSOCIATION)
#  if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12 && defined(__ASSOCIATIVE_MATH__)
#    define PHONG_FP_REASSOCIATION 1
#  elif defined(__GNUC__) && !defined(__clang__) && __GNUC__ < 12 && \
      (defined(__FAST_MATH__) || (__GCC_IEC_559 == 0 && !__FINITE_MATH_ONLY__))
#    define PHONG_FP_REASSOCIATION 1
#  elif defined(__clang__) && defined(__FAST_MATH__)
#    define PHONG_FP_REASSOCIATION 1
#  else
#    define PHONG_FP_REASSOCIATION 0
#  endif
#endif
// PHONG_FP_BARRIER: 1 where opaque() below is a barrier: wherever the compiler may regroup, seen or
// not: g++ 12 and later with __ASSOCIATIVE_MATH__ or __RECIPROCAL_MATH__ (a / b into a * (1 / b)),
// older g++ with __GCC_IEC_559 = 0, clang++ always (its flags cannot be seen). A barrier is no
// instruction: an IEEE build gives the same bits with it as without.
#if !defined(PHONG_FP_BARRIER)
#  if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#    if defined(__ASSOCIATIVE_MATH__) || defined(__RECIPROCAL_MATH__)
#      define PHONG_FP_BARRIER 1
#    else
#      define PHONG_FP_BARRIER 0
#    endif
#  elif defined(__GNUC__) && !defined(__clang__) && __GCC_IEC_559 > 0
#    define PHONG_FP_BARRIER 0
#  else
#    define PHONG_FP_BARRIER 1
#  endif
#endif

namespace phong::detail::ieee {

/// x unchanged, opaque to the optimizer at run time in every build (identity in constant evaluation).
template <class V> PHONG_INLINE constexpr V barrier(V x)
{
#if (defined(__GNUC__) || defined(__clang__)) && !defined(__CUDA_ARCH__)
    if (!PHONG_DETAIL_CONSTANT_EVALUATED()) {
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

/// x unchanged, opaque to the optimizer where it may regroup (PHONG_FP_BARRIER). Scalars and SIMD
/// batches (a register_type).
template <class V> PHONG_INLINE constexpr V opaque(V x)
{
#if PHONG_FP_BARRIER
    return barrier(x);
#else
    return x;
#endif
}

/// 1 where the scalar power kernels (power.hpp) keep every product unfused, so run time gives
/// constant evaluation's bits: every target but x86, whose baselines (aarch64, RISC-V, POWER)
/// have a fused multiply-add that the compilers contract into by default (docs/compilers.md,
/// "aarch64"). x86: 0, where FMA needs -march; define PHONG_UNFUSED_KERNELS=1 there too if wanted.
#if !defined(PHONG_UNFUSED_KERNELS)
#  if defined(__x86_64__) || defined(__i386__) || defined(_M_X64) || defined(_M_IX86)
#    define PHONG_UNFUSED_KERNELS 0
#  else
#    define PHONG_UNFUSED_KERNELS 1
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

/// y rounded to a multiple of shift's ulp (|y| well below shift): sum = y + shift (its low bits
/// hold the rounded y as an integer) and value = sum - shift, both opaque so value is not folded to y.
template <class V> struct shift_rounded {
    V sum;
    V value;
};
template <class V> PHONG_INLINE constexpr shift_rounded<V> round_by_shift(V y, V shift)
{
    const V sum = opaque(y + shift);
    return {sum, opaque(sum - shift)};
}

/// lo with hi + lo = a + b exactly, hi = fl(a + b) (Knuth's TwoSum; every intermediate opaque).
template <class V> PHONG_INLINE constexpr V two_sum_error(const V& a, const V& b, const V& hi)
{
    const V h = opaque(hi);
    const V bb = opaque(h - a);
    const V aa = opaque(h - bb);
    return opaque(a - aa) + opaque(b - bb);
}

/// ((a + b) + c) + d in that order, each partial sum opaque (Dekker's product error).
template <class V> PHONG_INLINE constexpr V ordered_sum(const V& a, const V& b, const V& c, const V& d)
{
    return opaque(opaque(opaque(a) + b) + c) + d;
}

/// False where the compiler may reassociate sums (unless PHONG_ALLOW_REASSOCIATED_TWOFOLD): the
/// twofold route's accumulations need the written order, so it refuses such builds (docs/compilers.md).
template <class T>
inline constexpr bool twofold_allowed =
#if PHONG_FP_REASSOCIATION && !defined(PHONG_ALLOW_REASSOCIATED_TWOFOLD)
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

/// 0 < x < inf (not NaN) by bits (SIMD batches: their batch_bool): a refined estimate's guard.
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


/// The power floor: a specular or spot power below 2^power_floor_log2<S> (float 2^-100, double
/// 2^-996: S's smallest normal times 2^26) is 0, so neither it nor its product by ks Ls f is
/// subnormal (a microcode assist on x86). Why and its error: docs/accuracy.md#subnormal-numbers-the-power-floor.
template <class S> inline constexpr int power_floor_log2 = std::numeric_limits<S>::min_exponent - 1 + 26;

} // namespace phong::detail::ieee
