// phong: f_i(Q), the attenuation of light i at point Q: distance falloff and spot cones.
// SPDX-License-Identifier: MIT
#pragma once

#include "vector.hpp"

#include <limits>

namespace phong {

/// Smallest denominator an attenuation divides by: sqrt(smallest normal T), about 1.1e-19 in
/// float and 1.5e-154 in double. It caps f at 1 / attenuation_denominator_min<T> (9.2e18 in float)
/// when c0 = 0 and d -> 0, so a light at the surface point gives a large finite value, never inf.
template <class T>
inline constexpr T attenuation_denominator_min = T(1.0842021724855044e-19L); // 2^-63, float's sqrt(min)
template <>
inline constexpr double attenuation_denominator_min<double> = 1.4916681462400413e-154; // 2^-511
template <>
inline constexpr long double attenuation_denominator_min<long double> = 1.4916681462400413e-154L;

/// Distance falloff coefficients of one light (OpenGL's constant, linear and quadratic
/// attenuation, and a range for the windowed model). Defaults: f = 1 at every distance.
template <class T>
struct falloff {
    T constant = T(1);  ///< c0 >= 0
    T linear = T(0);    ///< c1 >= 0
    T quadratic = T(0); ///< c2 >= 0; c0 + c1 + c2 > 0
    T range = std::numeric_limits<T>::infinity(); ///< windowed model: f = 0 from here on; > 0
};

/// Polynomial attenuation (seed 000's f_i(Q), OpenGL):
///   f = 1 / max(c0 + c1 d + c2 d^2, attenuation_denominator_min<Floor>)
/// evaluated as c0 + d (c1 + c2 d), so c2 = 0 with a huge d gives no 0 * inf.
/// Pre: c0, c1, c2 >= 0 and finite, d >= 0. Edge: d = 0 with c0 = 0 gives the cap
/// 1 / attenuation_denominator_min<T>; d = inf is taken as the largest finite T, which gives 0
/// when c2 > 0 and at most 1 / (c1 max) (2.9e-39 in float) when only c1 > 0; NaN d gives NaN.
/// Floor: the type whose attenuation_denominator_min applies (T's scalar; float lights evaluated
/// in double pass float, so the result is float's formula evaluated in double).
template <class T, class Floor = scalar_t<T>>
PHONG_INLINE constexpr T attenuation_polynomial(T d, T c0, T c1, T c2)
{
    d = phong::min(d, largest<T>()); // inf -> max: keeps c2 * d finite
    const T denominator = c0 + d * (c1 + c2 * d);
    return T(1) / phong::max(denominator, T(attenuation_denominator_min<Floor>));
}

/// Windowed inverse square (Filament, three.js "physically based" falloff):
///   f = clamp(1 - (d / range)^4, 0, 1)^2 / max(d^2, attenuation_denominator_min<Floor>)
/// Reaches exactly 0 at d >= range and stays finite at d = 0 (cap 1/attenuation_denominator_min).
/// Pre: range > 0 (inf allowed: pure inverse square), d >= 0. Edge: d = inf gives 0.
/// Floor: as for attenuation_polynomial. The floor bounds d^2 before the window multiplies, so
/// capping the quotient afterwards would differ (by up to 1/window^2) where d^2 < the floor.
template <class T, class Floor = scalar_t<T>>
PHONG_INLINE constexpr T attenuation_windowed(T d, T range)
{
    d = phong::min(d, largest<T>());
    const T ratio = phong::min(d / range, T(65536)); // ratio^4 stays finite; window is 0 anyway
    const T window = phong::clamp(T(1) - pow<4>(ratio), T(0), T(1));
    return window * window / phong::max(d * d, T(attenuation_denominator_min<Floor>));
}

/// A spot cone: the axis the light points along and its two parametrizations, OpenGL's
/// (exponent and cutoff) and the smooth inner/outer cone. The default is no spot.
template <class T, glm::qualifier Q = glm::defaultp>
struct spot_cone {
    glm::vec<3, T, Q> direction{T(0), T(0), T(-1)}; ///< unit axis s, from the light outward
    T exponent = T(0);     ///< OpenGL spot exponent e >= 0
    T cos_cutoff = T(-1);  ///< cos of OpenGL's cutoff angle: in [0, 1] (0..90 degrees), or -1 (180: no spot)
    T cos_inner = T(-1);   ///< smooth model: full strength where cos(angle) >= cos_inner
    T cos_outer = T(-1);   ///< smooth model: zero where cos(angle) <= cos_outer; cos_outer <= cos_inner

    /// OpenGL spot: axis (normalized here), exponent, cutoff in degrees (0..90, or 180 = no spot).
    /// Edge: a zero axis or a cutoff outside that range (negative, above 90 other than 180, NaN)
    /// makes a cone validate(light) rejects, naming light.spot.direction or light.spot.cos_cutoff
    /// (the cosine alone cannot tell -10 from 10 degrees, so such a cutoff stores cos_cutoff = 2).
    PHONG_INLINE static constexpr spot_cone opengl(const glm::vec<3, T, Q>& axis, T exponent, T cutoff_degrees)
    {
        spot_cone s;
        s.direction = phong::normalize(axis);
        s.exponent = exponent;
        const bool in_range = (cutoff_degrees >= T(0) && cutoff_degrees <= T(90)) || cutoff_degrees == T(180);
        s.cos_cutoff = in_range ? phong::cos_degrees(cutoff_degrees) : T(2);
        return s;
    }
    /// Smooth spot: full strength inside inner_degrees, none outside outer_degrees
    /// (0 <= inner <= outer <= 180). Edge: a zero axis, an angle outside [0, 180] (or NaN) or
    /// inner > outer makes a cone validate(light) rejects (light.spot.direction; light.spot.cos_inner
    /// or light.spot.cos_outer, stored as 2 for an angle out of range; light.spot.cos_outer for
    /// inner > outer); inner = outer: a hard edge.
    PHONG_INLINE static constexpr spot_cone smooth(const glm::vec<3, T, Q>& axis, T inner_degrees, T outer_degrees)
    {
        spot_cone s;
        s.direction = phong::normalize(axis);
        const auto in_range = [](T a) { return a >= T(0) && a <= T(180); };
        s.cos_inner = in_range(inner_degrees) ? phong::cos_degrees(inner_degrees) : T(2);
        s.cos_outer = in_range(outer_degrees) ? phong::cos_degrees(outer_degrees) : T(2);
        return s;
    }
};

/// OpenGL spot factor for the unit light direction l (from Q toward the light) and unit axis s:
///   c = dot(-l, s);  spot = c >= cos_cutoff ? clamp(c, 0, 1)^e : 0;  cos_cutoff = -1 (180 deg) gives 1.
/// Pre: l, s unit; e >= 0. Edge: l = 0 (light at Q) gives c = 0: inside only for a 90 degree
/// cutoff, then 0^e (1 for e = 0). e = 0 gives a hard-edged cone of strength 1. spot <= 1: the
/// base is clamped at 1, since rounding (or an axis accepted by validate within 1e-3 of unit
/// length) can give c slightly above 1, and (1 + eps)^e overflows for large e. A factor below the
/// power floor (2^-100 float, 2^-996 double: detail::ieee::power_floor_log2) is 0, as the
/// specular power: no subnormal number is made.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T spot_opengl(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& s, T exponent, T cos_cutoff)
{
    const mask_t<T> no_cone = cos_cutoff <= T(-1);
    if (math_traits<T>::all(no_cone)) return T(1); // 180 degrees: skip the power (every lane of a batch)
    const T c = -phong::dot(l, s);
    const T inside = phong::select(c >= cos_cutoff, detail::pow_unit_in_domain(phong::clamp(c, T(0), T(1)), exponent), T(0));
    return phong::select(no_cone, T(1), inside);
}

/// Smooth spot factor: t = clamp((c - cos_outer) / (cos_inner - cos_outer), 0, 1),
/// spot = t^2 (3 - 2 t) (smoothstep), c = dot(-l, s).
/// Pre: l, s unit; cos_outer <= cos_inner. Edge: cos_inner == cos_outer gives a hard edge
/// (1 where c >= cos_outer, else 0), no division by zero; cos_outer = -1 and cos_inner = -1 give 1.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T spot_smooth(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& s, T cos_inner, T cos_outer)
{
    const T c = -phong::dot(l, s);
    const T width = cos_inner - cos_outer;
    const T hard = phong::select(c >= cos_outer, T(1), T(0));
    const T t = phong::clamp((c - cos_outer) / phong::select(width > T(0), width, T(1)), T(0), T(1));
    return phong::select(width > T(0), t * t * (T(3) - T(2) * t), hard);
}

} // namespace phong
