// phong: the constant-evaluation kernels (sqrt, exp, log, log1p, pow in long double) for math.hpp
// and power.hpp's tables: special values first, then range reduction, then a capped series.
// SPDX-License-Identifier: MIT
#pragma once

#include "config.hpp"

#include <limits>

#if defined(__NVCC__)
// nvcc warns (#20208) at long double in device code; double is enough here.
#  pragma nv_diagnostic push
#  pragma nv_diag_suppress 20208
#endif

#include "diagnostics_push.hpp"

namespace phong {
namespace detail::ce {

// Constant-evaluation kernels. All work in long double and round once at the end, so for float
// and double they are nearly correctly rounded. Loop counts are capped.
using wide = long double;

inline constexpr wide ln2 = 0.693147180559945309417232121458176568L;

template <class T> PHONG_INLINE constexpr bool is_nan(T x) { return x != x; }
template <class T> PHONG_INLINE constexpr T inf() { return std::numeric_limits<T>::infinity(); }
template <class T> PHONG_INLINE constexpr T qnan() { return std::numeric_limits<T>::quiet_NaN(); }

// x = m * 2^k with m in [sqrt(1/2), sqrt(2)); x finite and > 0.
PHONG_INLINE constexpr wide reduce_pow2(wide x, int& k)
{
    k = 0;
    constexpr wide two32 = 4294967296.0L;
    for (int i = 0; i < 600 && x >= two32; ++i) { x /= two32; k += 32; }
    for (int i = 0; i < 600 && x < 1 / two32; ++i) { x *= two32; k -= 32; }
    for (int i = 0; i < 64 && x >= 1.41421356237309504880L; ++i) { x /= 2; ++k; }
    for (int i = 0; i < 64 && x < 0.70710678118654752440L; ++i) { x *= 2; --k; }
    return x;
}

// 2^k as a long double, by repeated squaring.
PHONG_INLINE constexpr wide pow2(int k)
{
    wide base = k < 0 ? 0.5L : 2.0L;
    unsigned n = static_cast<unsigned>(k < 0 ? -k : k);
    wide r = 1;
    for (int i = 0; i < 32 && n != 0; ++i, n >>= 1) {
        if (n & 1u) r *= base;
        base *= base;
    }
    return r;
}

PHONG_INLINE constexpr wide sqrt(wide x)
{
    if (is_nan(x) || x == 0 || x == inf<wide>()) return x;
    if (x < 0) return qnan<wide>();
    int k = 0;
    wide m = reduce_pow2(x, k);
    if (k % 2 != 0) { m *= 2; --k; } // m in [0.7, 2.9), k even
    wide y = (1 + m) / 2;
    for (int i = 0; i < 16; ++i) {
        const wide next = (y + m / y) / 2;
        if (next == y) break;
        y = next;
    }
    return y * pow2(k / 2);
}

PHONG_INLINE constexpr wide exp(wide x)
{
    if (is_nan(x)) return x;
    if (x > 11357.3L) return inf<wide>();
    if (x < -11400.0L) return 0;
    const wide kf = x / ln2;
    const int k = static_cast<int>(kf < 0 ? kf - 0.5L : kf + 0.5L);
    const wide r = x - static_cast<wide>(k) * ln2; // |r| <= ln2 / 2
    wide term = 1, sum = 1;
    for (int i = 1; i < 40; ++i) {
        term *= r / static_cast<wide>(i);
        const wide next = sum + term;
        if (next == sum) break;
        sum = next;
    }
    // Split the scaling so intermediate powers of two stay finite near the ends of the range.
    return sum * pow2(k / 2) * pow2(k - k / 2);
}

// 2 atanh(t) = log((1 + t) / (1 - t)), |t| < 1/2.
PHONG_INLINE constexpr wide two_atanh(wide t)
{
    const wide t2 = t * t;
    wide power = t, sum = t;
    for (int i = 1; i < 200; ++i) {
        power *= t2;
        const wide next = sum + power / static_cast<wide>(2 * i + 1);
        if (next == sum) break;
        sum = next;
    }
    return 2 * sum;
}

PHONG_INLINE constexpr wide log(wide x)
{
    if (is_nan(x) || x == inf<wide>()) return x;
    if (x < 0) return qnan<wide>();
    if (x == 0) return -inf<wide>();
    int k = 0;
    const wide m = reduce_pow2(x, k);
    return two_atanh((m - 1) / (m + 1)) + static_cast<wide>(k) * ln2;
}

PHONG_INLINE constexpr wide log1p(wide x)
{
    if (is_nan(x) || x == inf<wide>()) return x;
    if (x < -1) return qnan<wide>();
    if (x == -1) return -inf<wide>();
    // log1p(x) = 2 atanh(x / (2 + x)) has no cancellation for small |x|.
    if (x > -0.25L && x < 0.5L) return two_atanh(x / (2 + x));
    return log(1 + x);
}

// e^x - 1 without cancellation for small |x|: the series itself for |x| < 1/2, else exp(x) - 1.
PHONG_INLINE constexpr wide expm1(wide x)
{
    if (is_nan(x) || x == inf<wide>()) return x;
    if (x == -inf<wide>()) return -1;
    if (x > -0.5L && x < 0.5L) {
        wide term = x, sum = x;
        for (int i = 2; i < 40; ++i) {
            term *= x / static_cast<wide>(i);
            const wide next = sum + term;
            if (next == sum) break;
            sum = next;
        }
        return sum;
    }
    return exp(x) - 1;
}

PHONG_INLINE constexpr wide pow(wide x, wide y)
{
    if (y == 0 || x == 1) return 1; // IEEE: pow(x, 0) = 1 even for NaN x; pow(1, y) = 1
    if (is_nan(x) || is_nan(y)) return qnan<wide>();
    if (x == 0) return y > 0 ? wide(0) : inf<wide>();
    if (x < 0) {
        // Integer exponents only (the lighting model never needs this; kept for completeness).
        const auto n = static_cast<long long>(y);
        if (static_cast<wide>(n) != y) return qnan<wide>();
        const wide r = exp(y * log(-x));
        return (n % 2 != 0) ? -r : r;
    }
    return exp(y * log(x));
}

} // namespace detail::ce
} // namespace phong
#include "diagnostics_pop.hpp"

#if defined(__NVCC__)
#  pragma nv_diagnostic pop
#endif
