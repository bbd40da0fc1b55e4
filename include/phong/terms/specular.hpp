// phong: the specular factor, reflection-based (Phong) and halfway-based (Blinn-Phong).
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/vector.hpp"

#include <limits>

namespace phong {

namespace detail {
/// (1 - x)^m = exp(m log1p(-x)) for x in [0, 1], m >= 0, without pow(1 - x, m)'s amplified
/// rounding: relative error about (|m log1p(-x)| + 2) eps plus m times x's absolute error.
/// Edge: m = 0 gives 1 (never 0 * -inf); x >= 1 gives 0 for m > 0; x = 0 gives 1; results below
/// the power floor are 0.
template <class T>
PHONG_INLINE constexpr T pow_one_minus(T x, T m)
{
    if constexpr (requires { math_traits<T>::pow_one_minus(x, m); }) return math_traits<T>::pow_one_minus(x, m); // SIMD kernels
    using S = scalar_t<T>;
    constexpr S least = S(detail::ieee::power_floor_log2<S>) * S(0.6931471805599453); // ln of the power floor
    const T lg = detail::log1p(-detail::min(x, T(1))); // -inf at x = 1
    const mask_t<T> positive = m > T(0);
    const T y = detail::select(positive, detail::select(positive, m, T(1)) * lg, T(0));
    const mask_t<T> below = y < T(least); // false for NaN, which exp keeps
    return detail::select(below, T(0), detail::exp(detail::select(below, T(least), y)));
}
} // namespace detail

namespace detail {

// The specular steps, shared by the public factors below and every route of shade<F>.

/// |d| (r.v) = 2 (n.d)(n.v) - d.v for l = d / |d|, r = reflect(-l, n): the sign before 1/|d|.
/// Pre: n, v unit (or 0). Edge: v = 0 gives 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T reflection_cosine_scaled(T nd, T nv, const glm::vec<3, T, Q>& d, const glm::vec<3, T, Q>& v)
{
    // nd (2 nv) and (2 nd) nv are the same bits; lanes hoist 2 nv per point, scalars do not.
    if constexpr (std::is_floating_point_v<T>) return T(2) * nd * nv - detail::dot(d, v);
    else return nd * (T(2) * nv) - detail::dot(d, v);
}

/// Blinn's 1/|l + v|, the scale of n.h = (n.l + n.v) / |l + v| (h = normalize(l + v)).
/// Edge: 0 when |l + v|^2 is not a normal number (l = -v: no halfway vector, n.h taken as 0).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T inverse_halfway_length(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& v)
{
    const glm::vec<3, T, Q> sum = l + v;
    return detail::exact_inverse_length(detail::dot(sum, sum));
}

/// min(max(c, 0), 1)^m for c = x * scale (x has c's sign), pow(0, 0) = 1. Pre: scale, m >= 0 finite.
template <class T>
PHONG_INLINE constexpr T cosine_power(T x, T scale, T m)
{
    if constexpr (std::is_floating_point_v<T>) {
        if (x > T(0)) return detail::pow_unit_at_most_one(detail::min(x * scale, T(1)), m);
        return detail::power_of_zero(m);
    } else {
        return detail::pow_unit(detail::clamp(x * scale, T(0), T(1)), m);
    }
}

/// 1 - r.v = |r - v|^2 / 2, chord r - v = 2 (n.l) n - l - v rounded once. Pre: n, l, v unit, nl = n.l.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T one_minus_reflection_cosine(const glm::vec<3, T, Q>& n, T nl, const glm::vec<3, T, Q>& l,
                                                 const glm::vec<3, T, Q>& v)
{
    const glm::vec<3, T, Q> chord = n * (T(2) * nl) - l - v;
    return detail::dot(chord, chord) * T(0.5);
}

/// 1 - n.h = |n - h|^2 / 2 for h = normalize(l + v) rounded once.
/// Pre: n, l, v unit. Edge: l = -v (no halfway vector) gives 1, i.e. n.h taken as 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T one_minus_halfway_cosine(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                              const glm::vec<3, T, Q>& v)
{
    const glm::vec<3, T, Q> sum = l + v;
    const T hh = detail::dot(sum, sum);
    const glm::vec<3, T, Q> chord = n - sum * detail::select(hh > T(0), detail::rsqrt(hh), T(0));
    return detail::select(hh > T(0), detail::dot(chord, chord) * T(0.5), T(1));
}

} // namespace detail

/// Phong's reflection-based specular factor (classic Phong, the GLSL ADS shader):
///   r = reflect(-l, n) = 2 (n.l) n - l,   s = [n.l > 0] max(r.v, 0)^m   (base clamped to [0, 1]).
/// Pre: n, l, v unit (or 0); m >= 0 finite. Edge: 0 when n.l <= 0; m = 0 gives 1 where lit; l = 0 or v = 0 give 0 (m > 0).
/// Accuracy: the exact mode's (phong/accuracy.hpp; m amplifies r.v's rounding).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T specular_reflection(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                         const glm::vec<3, T, Q>& v, T m)
{
    const T nl = detail::dot(n, l);
    const T s = detail::cosine_power(detail::reflection_cosine_scaled(nl, detail::dot(n, v), l, v), T(1), m);
    return detail::select(nl > T(0), s, T(0));
}

/// Blinn-Phong's halfway-based specular factor (ray tracer model):
///   h = normalize(l + v),   s = [n.l > 0] max(n.h, 0)^m   (base clamped to [0, 1])
/// with n.h = (n.l + n.v) / |l + v|. Pre: n, l, v unit length (or 0); m >= 0 finite. Edge: l = -v
/// (no halfway vector) takes n.h = 0: s = 0 for m > 0 and 1 for m = 0 (never NaN); 0 when n.l <= 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T specular_halfway(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                      const glm::vec<3, T, Q>& v, T m)
{
    const T nl = detail::dot(n, l);
    const T s = detail::cosine_power(nl + detail::dot(n, v), detail::inverse_halfway_length(l, v), m);
    return detail::select(nl > T(0), s, T(0));
}

namespace detail {
/// The reflection-based factor, evaluated stably for high m near the highlight:
///   s = [n.l > 0] (1 - x)^m,  x = min(|r - v|^2 / 2, 1) = 1 - r.v for unit r, v.
/// Same domain and edges as specular_reflection; the rounding of r.v is no longer amplified by m.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T specular_reflection_stable(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                                const glm::vec<3, T, Q>& v, T m)
{
    const T nl = detail::dot(n, l);
    const T x = detail::select(detail::dot(v, v) > T(0), detail::one_minus_reflection_cosine(n, nl, l, v), T(1));
    return detail::select(nl > T(0), detail::pow_one_minus(x, m), T(0));
}

/// The halfway-based factor, evaluated stably: s = [n.l > 0] (1 - x)^m, x = min(|n - h|^2 / 2, 1).
/// Same domain and edges as specular_halfway (l = -v gives x = 1).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T specular_halfway_stable(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& l,
                                             const glm::vec<3, T, Q>& v, T m)
{
    const T nl = detail::dot(n, l);
    return detail::select(nl > T(0), detail::pow_one_minus(detail::one_minus_halfway_cosine(n, l, v), m), T(0));
}
} // namespace detail

} // namespace phong
