// phong: x^m for a base in [0, 1] and an exponent m >= 0, in double arithmetic, inline.
// SPDX-License-Identifier: MIT
//
// The specular and spot powers are the one transcendental every lit pair needs. Why not libm's
// pow: across a call every vector register is caller-saved, so a light loop must keep its sums
// and unit vectors in memory (docs/design.md). This kernel is straight-line code with two small
// tables (2 KiB + 512 B), usable in constant evaluation:
//   x = 2^k z, z in [0.6875, 1.375)  (offset so that x near 1 has k = 0: no cancellation with k)
//   log2 x = k + log2(c_i) + log2(1 + r),  r = z / c_i - 1,  |r| <= 2^-7,  c_i: 128 table points
//   2^y = 2^(n/64) 2^t,  n = round(64 y),  |t| <= 2^-7,  2^(j/64): 64 table entries
// with Taylor polynomials of degree 7 and 5 (truncation below 1e-17). The tables are computed at
// compile time by the long-double kernels of constexpr_math.hpp, so no magic constants are copied in.
//
// Accuracy (tests/power.test.cpp, against __float128): double relative error below
// 3 (|y| + m + 4) 2^-53 with y = m log2 x (measured worst 2.0 times (|y| + m + 4) 2^-53, near
// |y| = 512; the m term is the rounding of r = z / c_i - 1, which is not exact for x just below 1):
// 1e-14 for m <= 100, 1e-11 at m = 1e5. Float: 99.99 % correctly rounded, worst 0.5005 ulp.
// Constant evaluation and run time give the same bits unless the compiler contracts the
// polynomials' multiply-adds into FMA instructions (g++ and clang do on x86-64 with -march=native:
// then they differ by rounding, within the same bound). On aarch64, where FMA is always on and both
// compilers contract by default, every product is kept unfused (mul below, ieee::unfused_product):
// the same bits as constant evaluation, and as x86-64 without FMA.
#pragma once

#include "config.hpp"
#include "constexpr_math.hpp"
#include "ieee.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

#if defined(__NVCC__)
// The tables are built in long double on the host; nvcc warns (#20208) that device code would see
// double. Device code does not use them (math.hpp calls CUDA's pow there).
#  pragma nv_diagnostic push
#  pragma nv_diag_suppress 20208
#endif

namespace phong::detail {

/// 0^m for an exponent m >= 0: 1 for m = 0, 0 for m > 0. Every power of the lighting model (the
/// specular factor, the spot cone's exponent; pow_unit, fast::pow_unit, the SIMD lanes' powers)
/// takes this value at the base 0, the convention pow(0, 0) = 1 of IEEE pow: a shininess or spot
/// exponent of 0 gives the factor 1 wherever its term is on, the cosine's sign included (the limit
/// of x^0 as x -> 0). Scalars and SIMD lanes alike (lanes: their select, found by argument-dependent
/// lookup). The same test is written out in the scalar power kernels below (through the call g++
/// lays out the routes that inline them differently) and where the edge shares one select or
/// branch with the base's test: the lanes' kernels (x > 0 || m == 0, detail/simd/lanes_power.hpp),
/// the SFU power (fast_sfu.hpp) and the scalar add_specular (detail/exact.hpp).
template <class M>
PHONG_INLINE constexpr M power_of_zero(M m)
{
    if constexpr (std::is_arithmetic_v<M>) return m == M(0) ? M(1) : M(0);
    else return select(m == M(0), M(1), M(0));
}

} // namespace phong::detail

namespace phong::detail::power {

using u64 = std::uint64_t;

inline constexpr int log_table_bits = 7; // 128 points c_i
inline constexpr int exp_table_bits = 6; // 2^(j/64), j = 0..63
inline constexpr u64 log_offset = 0x3fe6000000000000ull; // bits of 0.6875

struct log2_point {
    double inv_c;  // 1 / c_i rounded to double (exactly 1 for the interval that holds 1)
    double log2_c; // log2(1 / inv_c) to within half an ulp: the identity holds for the rounded inv_c
};

inline constexpr long double wide_ln2 = ce::ln2;

PHONG_INLINE constexpr std::array<log2_point, (1 << log_table_bits)> make_log2_table()
{
    std::array<log2_point, (1 << log_table_bits)> t{};
    for (int i = 0; i < (1 << log_table_bits); ++i) {
        // The z that land on index i: bits log_offset + (i << 45) up to the next index.
        const double lo = std::bit_cast<double>(log_offset + (u64(i) << (52 - log_table_bits)));
        const double hi = std::bit_cast<double>(log_offset + (u64(i + 1) << (52 - log_table_bits)));
        const double inv_c = (lo <= 1.0 && 1.0 < hi) ? 1.0 : 2.0 / (lo + hi);
        t[i] = {inv_c, static_cast<double>(-ce::log(inv_c) / wide_ln2)};
    }
    return t;
}

// Entry j holds bits(2^(j/64)) - (j << 46): adding (round(64 y) << 46) then gives 2^(round(64 y)/64).
PHONG_INLINE constexpr std::array<u64, (1 << exp_table_bits)> make_exp2_table()
{
    std::array<u64, (1 << exp_table_bits)> t{};
    for (int j = 0; j < (1 << exp_table_bits); ++j) {
        const double v = static_cast<double>(ce::exp(static_cast<long double>(j) / (1 << exp_table_bits) * wide_ln2));
        t[j] = std::bit_cast<u64>(v) - (u64(j) << (52 - exp_table_bits));
    }
    return t;
}

#if !defined(__CUDA_ARCH__) // device code uses CUDA's pow (math.hpp); host tables are not visible there
inline constexpr std::array<log2_point, (1 << log_table_bits)> log2_table = make_log2_table();
inline constexpr std::array<u64, (1 << exp_table_bits)> exp2_table = make_exp2_table();

// Taylor coefficients: log2(1 + r) = sum_n (-1)^(n+1) r^n / (n ln 2);  2^t = sum_n (t ln 2)^n / n!.
inline constexpr long double inv_ln2 = 1 / wide_ln2;
inline constexpr double a1 = double(inv_ln2), a2 = double(-inv_ln2 / 2), a3 = double(inv_ln2 / 3),
                        a4 = double(-inv_ln2 / 4), a5 = double(inv_ln2 / 5), a6 = double(-inv_ln2 / 6),
                        a7 = double(inv_ln2 / 7);
inline constexpr double b1 = double(wide_ln2), b2 = double(wide_ln2 * wide_ln2 / 2),
                        b3 = double(wide_ln2 * wide_ln2 * wide_ln2 / 6),
                        b4 = double(wide_ln2 * wide_ln2 * wide_ln2 * wide_ln2 / 24),
                        b5 = double(wide_ln2 * wide_ln2 * wide_ln2 * wide_ln2 * wide_ln2 / 120);

/// a * b, never fused with a later addition (ieee::unfused_product): the kernels below round each
/// product on its own as constant evaluation does, so both give the same bits on every target.
PHONG_INLINE constexpr double mul(double a, double b) { return ieee::unfused_product(a, b); }

/// log2 x for a positive normal double x (absolute error about 2^-53 (|log2 c_i| + 1)). Short:
/// float's degree-5 polynomial (truncation below r^6/6 < 2^-50 absolute, which only matters times
/// m where m |log2 x| < 150, else the float result is 0) instead of degree 7.
template <bool Short = false>
PHONG_INLINE constexpr double log2_normal(double x)
{
    const u64 u = std::bit_cast<u64>(x);
    const u64 tmp = u - log_offset;
    const int i = static_cast<int>((tmp >> (52 - log_table_bits)) % (1u << log_table_bits));
    const double k = static_cast<double>(static_cast<std::int64_t>(tmp) >> 52); // arithmetic shift (C++20)
    const double z = std::bit_cast<double>(u - (tmp & (u64(0xfff) << 52)));
    const double r = ieee::opaque(mul(z, log2_table[i].inv_c) - 1.0); // exact for the interval holding 1 (inv_c = 1)
    const double r2 = r * r;
    double p;
    if constexpr (Short) p = mul(r, a1 + mul(r, a2)) + mul(r2 * r, (a3 + mul(r, a4)) + mul(r2, a5));
    else p = mul(r, a1 + mul(r, a2)) + mul(r2 * r, (a3 + mul(r, a4)) + mul(r2, (a5 + mul(r, a6)) + mul(r2, a7)));
    return (k + log2_table[i].log2_c) + p;
}

/// 2^y for y in [-1022, 0] (a normal result), from the 64-entry table and a short polynomial in
/// double. Short: float's degree-3 polynomial (truncation below 4e-11 relative) instead of degree 5.
/// One of three exp2 kernels, each for its own accuracy: this one is the scalar exact and stable
/// modes' (pow_unit, whose error the header states: float nearly always correctly rounded);
/// fast::detail::exp2_estrin (fast_math.hpp) is the fast mode's float-accurate polynomial at every
/// width; lanes::exp2_horner (detail/simd/lanes_power.hpp) is the exact mode's float SIMD lanes',
/// with no table (a table lookup per lane would be a gather).
template <bool Short = false>
PHONG_INLINE constexpr double exp2_tabulated(double y)
{
    constexpr double shift = 0x1.8p52 / (1 << exp_table_bits); // ulp 1/64 around it: y + shift rounds 64 y
    const auto [shifted, rounded] = ieee::round_by_shift(y, shift);
    const u64 n = std::bit_cast<u64>(shifted); // low bits: round(64 y), two's complement
    const double t = ieee::opaque(y - rounded); // |t| <= 1/128
    const double scale = std::bit_cast<double>(exp2_table[n % (1u << exp_table_bits)] + (n << (52 - exp_table_bits)));
    if constexpr (Short) {
        return scale + mul(scale, mul(t, b1 + mul(t, b2 + mul(t, b3))));
    } else {
        const double t2 = t * t;
        return scale + mul(scale, mul(t, b1) + mul(t2, (b2 + mul(t, b3)) + mul(t2, b4 + mul(t, b5))));
    }
}

/// The kernels' value outside their domain: IEEE pow's (Ieee: std::pow at run time, the
/// long-double kernel in constant evaluation), or NaN without any call to libm.
template <bool Ieee, class F>
PHONG_INLINE constexpr F outside_domain(F x, F m)
{
    if constexpr (!Ieee) {
        return std::numeric_limits<F>::quiet_NaN();
    } else {
        if (std::is_constant_evaluated()) return static_cast<F>(ce::pow(x, m));
        return std::pow(x, m);
    }
}

/// float's kernel: the same tables with the short polynomials, enough for a float result.
/// AtMostOne: x <= 1 is given (a clamped cosine), so y = m log2 x <= 0 is not tested (log2_normal
/// is <= 0 for every x <= 1: exactly 0 at 1, whose interval has c = 1 and r = x - 1 <= 0).
template <bool Ieee, bool AtMostOne = false>
PHONG_INLINE constexpr float pow_unit_kernel(float xf, float mf)
{
    const double x = xf, m = mf;
    if (x > 0.0) [[likely]] { // every positive float is a normal double
        const double y = m * log2_normal<true>(x);
        if (y >= -1022.0 && (AtMostOne || y <= 0.0)) [[likely]] return static_cast<float>(exp2_tabulated<true>(y));
        if (y < -1022.0) return 0.0f;
    } else if (x == 0.0 && m >= 0.0) {
        return m == 0.0 ? 1.0f : 0.0f; // 0^m: power_of_zero, written out
    }
    return outside_domain<Ieee>(xf, mf);
}

/// double's kernel; a subnormal x is scaled into the normal range. AtMostOne: as float's.
template <bool Ieee, bool AtMostOne = false>
PHONG_INLINE constexpr double pow_unit_kernel(double x, double m)
{
    if (x > 0.0) [[likely]] {
        const double y = x >= 0x1p-1022 ? m * log2_normal(x) : m * (log2_normal(x * 0x1p64) - 64.0);
        if (y >= -1022.0 && (AtMostOne || y <= 0.0)) [[likely]] return exp2_tabulated(y);
        if (y < -1022.0) return 0.0;
    } else if (x == 0.0 && m >= 0.0) {
        return m == 0.0 ? 1.0 : 0.0; // 0^m: power_of_zero, written out
    }
    return outside_domain<Ieee>(x, m);
}

/// x^m for x in [0, 1] and m >= 0 (the kernel of phong::pow_unit). Edges: pow_unit(0, 0) = 1,
/// pow_unit(+-0, m > 0) = +0, results below 2^-1022 are 0 (y = m log2 x < -1022). Outside the
/// domain: x > 1 with m < 0 (a result <= 1) runs the same kernel, with the same accuracy and flush;
/// everything else (x > 1 with m > 0, x < 0, NaN, inf) returns IEEE pow's value (std::pow at run
/// time, the long-double kernel in constant evaluation).
PHONG_INLINE constexpr float pow_unit(float x, float m) { return pow_unit_kernel<true>(x, m); }
PHONG_INLINE constexpr double pow_unit(double x, double m) { return pow_unit_kernel<true>(x, m); }

/// x^m for x in [0, 1] and a finite m >= 0 (a validated shininess): pow_unit's value there, with
/// no fallback to libm's pow outside that domain. NaN x, NaN m, x < 0, x > 1 with m > 0, or m < 0
/// with x < 1: NaN (x = 1 gives 1 for every finite m, the exact value). m = +inf: 0 for x < 1,
/// NaN for x = 1. Why a second entry point: the mere
/// presence of a call (all vector registers caller-saved) made g++ keep a light loop's sums in
/// memory in every iteration, and the shading loop never needs the fallback.
PHONG_INLINE constexpr float pow_unit_in_domain(float x, float m) { return pow_unit_kernel<false>(x, m); }
PHONG_INLINE constexpr double pow_unit_in_domain(double x, double m) { return pow_unit_kernel<false>(x, m); }

/// pow_unit_in_domain for a base that is at most 1 by construction (the specular cosine clamped
/// to 1: cosine_power): the same value for x in [0, 1], with one test fewer (y <= 0 holds there).
/// x > 1 is not tested: a meaningless value (finite or not), with every table read in bounds.
PHONG_INLINE constexpr float pow_unit_at_most_one(float x, float m) { return pow_unit_kernel<false, true>(x, m); }
PHONG_INLINE constexpr double pow_unit_at_most_one(double x, double m) { return pow_unit_kernel<false, true>(x, m); }
#endif

} // namespace phong::detail::power

#if defined(__NVCC__)
#  pragma nv_diagnostic pop
#endif
