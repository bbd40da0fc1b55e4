// phong: the specular factor, reflection-based (Phong) and halfway-based (Blinn-Phong).
// SPDX-License-Identifier: MIT
#pragma once

#include "vector.hpp"

#include <limits>

namespace phong {

/// (1 - x)^m for x in [0, 1], m >= 0, without the rounding amplification of pow(1 - x, m):
///   exp(m * log1p(-x)), with m = 0 giving exactly 1 (pow(0, 0) = 1; m * log1p(-1) is never
///   formed as 0 * -inf, and no finite product overflows, so it is a constant expression too).
/// For unit vectors a, b: 1 - a.b = |a - b|^2 / 2, so with x = |a - b|^2 / 2 the relative error
/// of the result is about (|m log1p(-x)| + 2) eps plus m times the absolute error of x (x from
/// twofold unit vectors, as shade's stable mode does, makes that last term about m x eps).
/// Edge: x >= 1 gives 0 for m > 0 and 1 for m = 0 (pow(0, 0) = 1); x = 0 gives 1.
template <class T>
PHONG_HD constexpr T pow_one_minus(T x, T m)
{
    if constexpr (requires { math_traits<T>::pow_one_minus(x, m); }) return math_traits<T>::pow_one_minus(x, m); // SIMD kernels
    const T lg = phong::log1p(-phong::min(x, T(1))); // -inf at x = 1
    const mask_t<T> positive = m > T(0);
    return phong::exp(phong::select(positive, phong::select(positive, m, T(1)) * lg, T(0)));
}

/// Phong's reflection-based specular factor (seed 000, seed 003):
///   r = reflect(-l, n) = 2 (n.l) n - l,   s = [n.l > 0] max(r.v, 0)^m   (base clamped to [0, 1])
/// (TeX: s = [\hat n\cdot\hat l > 0]\,\max(\hat r\cdot\hat v, 0)^m)
/// Pre: n, l, v unit length (or 0); m >= 0. Edge: 0 when n.l <= 0 (the gate of seed 003);
/// m = 0 gives 1 where lit (pow(0, 0) = 1); l = 0 or v = 0 give 0 (m > 0).
/// Accuracy: straightforward formula, pow amplifies the rounding of r.v by m
/// (see specular_reflection_stable and phong/accuracy.hpp).
template <class T, glm::qualifier Q>
PHONG_HD constexpr T specular_reflection(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                         const glm::vec<3, T, Q>& v, T m)
{
    const T nl = phong::dot(n, l);
    const glm::vec<3, T, Q> r = phong::reflect(-l, n);
    const T s = phong::pow_unit(phong::clamp(phong::dot(r, v), T(0), T(1)), m);
    return phong::select(nl > T(0), s, T(0));
}

/// Blinn-Phong's halfway-based specular factor (seed 001):
///   h = normalize(l + v),   s = [n.l > 0] max(n.h, 0)^m   (base clamped to [0, 1])
/// Pre: n, l, v unit length (or 0); m >= 0. Edge: l = -v (no halfway vector) takes n.h = 0:
/// s = 0 for m > 0 and 1 for m = 0 (never NaN); 0 when n.l <= 0.
template <class T, glm::qualifier Q>
PHONG_HD constexpr T specular_halfway(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                      const glm::vec<3, T, Q>& v, T m)
{
    const T nl = phong::dot(n, l);
    const glm::vec<3, T, Q> h = phong::normalize_unscaled(l + v);
    const T s = phong::pow_unit(phong::clamp(phong::dot(n, h), T(0), T(1)), m);
    return phong::select(nl > T(0), s, T(0));
}

/// The reflection-based factor, evaluated stably for high m near the highlight:
///   s = [n.l > 0] (1 - x)^m,  x = min(|r - v|^2 / 2, 1) = 1 - r.v for unit r, v.
/// Same domain and edges as specular_reflection; the rounding of r.v is no longer amplified by m.
template <class T, glm::qualifier Q>
PHONG_HD constexpr T specular_reflection_stable(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                                const glm::vec<3, T, Q>& v, T m)
{
    const T nl = phong::dot(n, l);
    const glm::vec<3, T, Q> chord = n * (T(2) * nl) - l - v; // r - v
    const T x = phong::select(phong::dot(v, v) > T(0), phong::dot(chord, chord) * T(0.5), T(1));
    return phong::select(nl > T(0), phong::pow_one_minus(x, m), T(0));
}

/// The halfway-based factor, evaluated stably: s = [n.l > 0] (1 - x)^m, x = min(|n - h|^2 / 2, 1).
/// Same domain and edges as specular_halfway (l = -v gives x = 1).
template <class T, glm::qualifier Q>
PHONG_HD constexpr T specular_halfway_stable(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                             const glm::vec<3, T, Q>& v, T m)
{
    const T nl = phong::dot(n, l);
    const glm::vec<3, T, Q> sum = l + v;
    const T hh = phong::dot(sum, sum);
    const glm::vec<3, T, Q> chord = n - sum * phong::select(hh > T(0), phong::rsqrt(hh), T(0));
    const T x = phong::select(hh > T(0), phong::dot(chord, chord) * T(0.5), T(1));
    return phong::select(nl > T(0), phong::pow_one_minus(x, m), T(0));
}

} // namespace phong
