// phong: f_i(Q), the attenuation of light i at point Q: distance falloff and spot cones (their
// parameters, falloff and spot_cone, are a light's: inputs/light.hpp).
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/vector.hpp"

#include <limits>

namespace phong {

namespace detail {
/// Smallest denominator an attenuation divides by, sqrt(smallest normal T): f stays finite at d = 0.
template <class T>
inline constexpr T attenuation_denominator_min = T(1.0842021724855044e-19L); // 2^-63, float's sqrt(min)
template <>
inline constexpr double attenuation_denominator_min<double> = 1.4916681462400413e-154; // 2^-511
template <>
inline constexpr long double attenuation_denominator_min<long double> = 1.4916681462400413e-154L;
} // namespace detail

/// Polynomial attenuation (classic Phong's f_i(Q), OpenGL):
///   f = 1 / max(c0 + c1 d + c2 d^2, attenuation_denominator_min<Floor>)
/// evaluated as c0 + d (c1 + c2 d), so c2 = 0 with a huge d gives no 0 * inf.
/// Pre: c0, c1, c2 >= 0 finite, d >= 0. Edge: d = 0 with c0 = 0 gives the cap
/// 1 / attenuation_denominator_min<Floor>; d = inf is taken as T's largest (0 when c2 > 0); NaN
/// gives NaN. Floor: the type whose cap applies (float for float lights evaluated in double).
template <class T, class Floor = detail::scalar_t<T>>
PHONG_INLINE constexpr T attenuation_polynomial(T d, T c0, T c1, T c2)
{
    d = detail::min(d, detail::largest<T>()); // inf -> max: keeps c2 * d finite
    const T denominator = c0 + d * (c1 + c2 * d);
    return T(1) / detail::max(denominator, T(detail::scalar_t<T>(detail::attenuation_denominator_min<Floor>)));
}

/// Windowed inverse square (Filament, three.js "physically based" falloff):
///   f = clamp(1 - (d / range)^4, 0, 1)^2 / max(d^2, attenuation_denominator_min<Floor>)
/// Reaches exactly 0 at d >= range and stays finite at d = 0 (cap 1/attenuation_denominator_min).
/// Pre: range > 0 (inf: pure inverse square), d >= 0. Edge: d = inf gives 0. Floor: as
/// attenuation_polynomial's, applied to d^2 before the window multiplies.
template <class T, class Floor = detail::scalar_t<T>>
PHONG_INLINE constexpr T attenuation_windowed(T d, T range)
{
    d = detail::min(d, detail::largest<T>());
    const T ratio = detail::min(d / range, T(65536)); // ratio^4 stays finite; window is 0 anyway
    const T window = detail::clamp(T(1) - detail::pow<4>(ratio), T(0), T(1));
    return window * window / detail::max(d * d, T(detail::scalar_t<T>(detail::attenuation_denominator_min<Floor>)));
}

/// OpenGL spot factor for the unit light direction l (from Q toward the light) and unit axis s:
///   c = dot(-l, s);  spot = c >= cos_cutoff ? clamp(c, 0, 1)^e : 0;  cos_cutoff = -1 (180 deg) gives 1.
/// Pre: l, s unit; e >= 0. Edge: l = 0 gives c = 0 (inside only for a 90 degree cutoff: 0^e);
/// e = 0 gives a hard-edged cone of strength 1. The base is clamped at 1 (rounding can give c a
/// little above 1, and (1 + eps)^e overflows for large e). Below the power floor: 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T spot_opengl(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& s, T exponent, T cos_cutoff)
{
    const detail::mask_t<T> no_cone = cos_cutoff <= T(-1);
    if (detail::math_traits<T>::all(no_cone)) return T(1); // 180 degrees: skip the power (every lane of a batch)
    const T c = -detail::dot(l, s);
    const T inside = detail::select(c >= cos_cutoff, detail::pow_unit_in_domain(detail::clamp(c, T(0), T(1)), exponent), T(0));
    return detail::select(no_cone, T(1), inside);
}

/// Smooth spot factor: t = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1),
/// spot = t^2 (3 - 2 t) (smoothstep), c = dot(-l, s).
/// Pre: l, s unit; cos_outer <= cos_inner. Edge: cos_inner == cos_outer gives a hard edge
/// (1 where c >= cos_outer, else 0), no division by zero; cos_outer = -1 and cos_inner = -1 give 1.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T spot_smooth(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& s, T cos_inner, T cos_outer)
{
    const T c = -detail::dot(l, s);
    const T width = cos_inner - cos_outer;
    const T hard = detail::select(c >= cos_outer, T(1), T(0));
    const T t = detail::clamp((c - cos_outer) / detail::select(width > T(0), width, T(1)), T(0), T(1));
    return detail::select(width > T(0), t * t * (T(3) - T(2) * t), hard);
}

/// Linear spot factor (LearnOpenGL, Unity, Godot): a straight ramp in the cosine,
///   spot = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1),  c = dot(-l, s).
/// Pre: l, s unit; -1 <= cos_outer <= cos_inner <= 1. Edge: cos_inner == cos_outer gives a hard
/// edge (no division by zero); both -1 give 1; l = 0 gives c = 0. Bound: spot in [0, 1]; an
/// error E in c moves it by at most E / (cos_inner - cos_outer).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T spot_linear(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& s, T cos_inner, T cos_outer)
{
    const T c = -detail::dot(l, s);
    const T width = cos_inner - cos_outer;
    const T hard = detail::select(c >= cos_outer, T(1), T(0));
    const T t = detail::clamp((c - cos_outer) / detail::select(width > T(0), width, T(1)), T(0), T(1));
    return detail::select(width > T(0), t, hard);
}

} // namespace phong
