// phong: a light source, and validate(light).
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/math.hpp"
#include "../core/vector.hpp"
#include "validate.hpp"

#include <limits>
#include <type_traits>
#include <utility>

#include "../core/diagnostics_push.hpp"

namespace phong {

/// Distance falloff coefficients of one light (OpenGL's constant, linear and quadratic
/// attenuation, and a range for the windowed model). Defaults: f = 1 at every distance.
template <class T>
struct falloff {
    T constant = T(1);  ///< c0 >= 0
    T linear = T(0);    ///< c1 >= 0
    T quadratic = T(0); ///< c2 >= 0; c0 + c1 + c2 > 0
    T range = std::numeric_limits<T>::infinity(); ///< windowed model: f = 0 from here on; > 0
};

/// A spot cone: its axis, OpenGL's exponent and cutoff, and the inner/outer cone (smooth and
/// linear edges). Default: no spot. A zero axis is no cone (spot = 1), so zeroed uniforms light.
template <class T, glm::qualifier Q = glm::defaultp>
struct spot_cone {
    glm::vec<3, T, Q> direction{T(0), T(0), T(-1)}; ///< unit axis s, from the light outward; zero: no cone
    T exponent = T(0);     ///< OpenGL spot exponent e >= 0
    T cos_cutoff = T(-1);  ///< cos of OpenGL's cutoff angle: in [0, 1] (0..90 degrees), or -1 (180: no spot)
    T cos_inner = T(-1);   ///< smooth and linear models: full strength where cos(angle) >= cos_inner
    T cos_outer = T(-1);   ///< smooth and linear models: zero where cos(angle) <= cos_outer; cos_outer <= cos_inner

    /// OpenGL spot: axis (normalized here), exponent, cutoff in degrees (0..90, or 180 = no spot).
    /// Edge: a zero axis gives no cone; another cutoff (or NaN) stores cos_cutoff = 2, which validate rejects.
    PHONG_INLINE static constexpr spot_cone opengl(const glm::vec<3, T, Q>& axis, T exponent, T cutoff_degrees)
    {
        spot_cone s;
        s.direction = detail::normalize(axis);
        s.exponent = exponent;
        const bool in_range = (cutoff_degrees >= T(0) && cutoff_degrees <= T(90)) || cutoff_degrees == T(180);
        s.cos_cutoff = in_range ? detail::cos_degrees(cutoff_degrees) : T(2);
        return s;
    }
    /// Smooth or linear spot (features::spot picks the edge): full strength inside inner_degrees,
    /// none outside outer_degrees, 0 <= inner <= outer <= 180 (equal: a hard edge). Edge: a zero
    /// axis gives no cone; an angle out of range (stored as cosine 2) or inner > outer: validate rejects.
    PHONG_INLINE static constexpr spot_cone smooth(const glm::vec<3, T, Q>& axis, T inner_degrees, T outer_degrees)
    {
        spot_cone s;
        s.direction = detail::normalize(axis);
        const auto in_range = [](T a) { return a >= T(0) && a <= T(180); };
        s.cos_inner = in_range(inner_degrees) ? detail::cos_degrees(inner_degrees) : T(2);
        s.cos_outer = in_range(outer_degrees) ? detail::cos_degrees(outer_degrees) : T(2);
        return s;
    }
};

/// One light source, in the shading coordinates. Classic Phong's L_i is diffuse = specular
/// (light::with_strength); the ray tracer's lightamb/diff/spec and GLSL's La/Ld/Ls map one to one.
template <class T, glm::qualifier Q = glm::defaultp>
struct light {
    /// w = 1 positional (xyz the point), w = 0 directional (xyz toward the light); validate
    /// rejects other w (light_kind::positional/directional do not read it): divide by w yourself.
    glm::vec<4, T, Q> position{T(0), T(0), T(1), T(0)};
    glm::vec<3, T, Q> ambient{T(0)};  ///< per-light ambient strength (the ray tracer model lightamb, the GLSL ADS shader La)
    glm::vec<3, T, Q> diffuse{T(1)};  ///< diffuse strength (the ray tracer model lightdiff, the GLSL ADS shader Ld, classic Phong L_i)
    glm::vec<3, T, Q> specular{T(1)}; ///< specular strength (the ray tracer model lightspec, the GLSL ADS shader Ls, classic Phong L_i)
    falloff<T> attenuation{};         ///< read when features::attenuation is not none (positional lights only)
    spot_cone<T, Q> spot{};           ///< read when features::spot is not none

    /// A light with diffuse = specular = strength and no ambient (document 000's L_i).
    PHONG_INLINE static constexpr light with_strength(const glm::vec<4, T, Q>& position, const glm::vec<3, T, Q>& strength,
                                                  falloff<T> attenuation = {})
    {
        light l;
        l.position = position;
        l.ambient = glm::vec<3, T, Q>(T(0));
        l.diffuse = strength;
        l.specular = strength;
        l.attenuation = attenuation;
        return l;
    }
};

/// How shade<F> reads a renderer's own light type L (no copy into a light<T>); unspecialized, shade
/// stops with a static_assert naming light_traits. Static functions, each returning a value or reference:
///   position(L) -> glm::vec<4, U, Q>  required by shade<F> (shade_incident: only for light_kind::any),
///                                      as light::position; U, Q are read from it, else from diffuse's
///   diffuse(L), specular(L) -> glm::vec<3, U, Q>  required: Ld, Ls
///   ambient(L) -> glm::vec<3, U, Q>   optional, default 0
///   attenuation(L) -> `falloff<U>`, spot(L) -> spot_cone<U, Q>  optional, defaults: none
/// Each is called at most once per light per point, for the terms F has. Example:
///   template <> struct phong::light_traits<my_light> {
///       static glm::vec4 position(const my_light& L) { return glm::vec4(L.position, 1.0f); }
///       static const glm::vec3& diffuse(const my_light& L) { return L.colour; }
///       static const glm::vec3& specular(const my_light& L) { return L.colour; }
///   };
/// Pre: values validate() accepts in a light<U, Q> (checked in debug builds, through to_light).
template <class L> struct light_traits {};

/// light<T, Q>'s own fields, by reference.
template <class T, glm::qualifier Q> struct light_traits<light<T, Q>> {
    /// L.position
    PHONG_INLINE static constexpr const glm::vec<4, T, Q>& position(const light<T, Q>& L) { return L.position; }
    /// L.ambient
    PHONG_INLINE static constexpr const glm::vec<3, T, Q>& ambient(const light<T, Q>& L) { return L.ambient; }
    /// L.diffuse
    PHONG_INLINE static constexpr const glm::vec<3, T, Q>& diffuse(const light<T, Q>& L) { return L.diffuse; }
    /// L.specular
    PHONG_INLINE static constexpr const glm::vec<3, T, Q>& specular(const light<T, Q>& L) { return L.specular; }
    /// L.attenuation
    PHONG_INLINE static constexpr const falloff<T>& attenuation(const light<T, Q>& L) { return L.attenuation; }
    /// L.spot
    PHONG_INLINE static constexpr const spot_cone<T, Q>& spot(const light<T, Q>& L) { return L.spot; }
};

namespace detail {
template <class V> struct homogeneous_position_of {};
template <class T, glm::qualifier Q> struct homogeneous_position_of<glm::vec<4, T, Q>> {
    using scalar = T;
    static constexpr glm::qualifier qualifier = Q;
};
template <class V> struct colour_of {};
template <class T, glm::qualifier Q> struct colour_of<glm::vec<3, T, Q>> {
    using scalar = T;
    static constexpr glm::qualifier qualifier = Q;
};
template <class L>
using light_position_t = std::remove_cvref_t<decltype(light_traits<L>::position(std::declval<const L&>()))>;
template <class L>
using light_diffuse_t = std::remove_cvref_t<decltype(light_traits<L>::diffuse(std::declval<const L&>()))>;
template <class L>
concept traits_with_position = requires(const L& l) { light_traits<L>::position(l); };
/// A light's scalar type and qualifier: from position's type, else diffuse's.
template <class L> struct light_fields : colour_of<light_diffuse_t<L>> {};
template <traits_with_position L> struct light_fields<L> : homogeneous_position_of<light_position_t<L>> {};
} // namespace detail

namespace detail {
/// A type shade_incident<F> takes as a light: light_traits<L> gives diffuse and specular.
template <class L>
concept incident_light_source = requires(const std::remove_cvref_t<L>& l) {
    light_traits<std::remove_cvref_t<L>>::diffuse(l);
    light_traits<std::remove_cvref_t<L>>::specular(l);
} && requires { typename detail::light_fields<std::remove_cvref_t<L>>::scalar; };
} // namespace detail

/// A type shade<F> takes as a light: light_traits<L> gives position (a glm::vec<4, U, Q>),
/// diffuse and specular (cv and references ignored).
template <class L>
concept light_source = detail::incident_light_source<L> && requires(const std::remove_cvref_t<L>& l) {
    light_traits<std::remove_cvref_t<L>>::position(l);
    typename detail::homogeneous_position_of<detail::light_position_t<std::remove_cvref_t<L>>>::scalar;
};

namespace detail {
/// The scalar type and qualifier of a light's fields (light_fields).
template <incident_light_source L>
using light_scalar_t = typename detail::light_fields<std::remove_cvref_t<L>>::scalar;
template <incident_light_source L>
inline constexpr glm::qualifier light_qualifier_v = detail::light_fields<std::remove_cvref_t<L>>::qualifier;
} // namespace detail

namespace detail {
/// A light's fields through light_traits, or light<U, Q>'s defaults for those it leaves out.
template <class L> PHONG_INLINE constexpr decltype(auto) position_of(const L& l) { return light_traits<L>::position(l); }
template <class L> PHONG_INLINE constexpr decltype(auto) diffuse_of(const L& l) { return light_traits<L>::diffuse(l); }
template <class L> PHONG_INLINE constexpr decltype(auto) specular_of(const L& l) { return light_traits<L>::specular(l); }
template <class L> PHONG_INLINE constexpr decltype(auto) ambient_of([[maybe_unused]] const L& l)
{
    if constexpr (requires { light_traits<L>::ambient(l); }) return light_traits<L>::ambient(l);
    else return glm::vec<3, light_scalar_t<L>, light_qualifier_v<L>>(light_scalar_t<L>(0));
}
template <class L> PHONG_INLINE constexpr decltype(auto) attenuation_of([[maybe_unused]] const L& l)
{
    if constexpr (requires { light_traits<L>::attenuation(l); }) return light_traits<L>::attenuation(l);
    else return falloff<light_scalar_t<L>>{};
}
template <class L> PHONG_INLINE constexpr decltype(auto) spot_of([[maybe_unused]] const L& l)
{
    if constexpr (requires { light_traits<L>::spot(l); }) return light_traits<L>::spot(l);
    else return spot_cone<light_scalar_t<L>, light_qualifier_v<L>>{};
}
} // namespace detail

/// The light<U, Q> a light source stands for (defaults for fields light_traits leaves out), for
/// validate() and shade_batch's span of light<T> (convert once per call, not per point).
template <detail::incident_light_source L>
PHONG_INLINE constexpr light<detail::light_scalar_t<L>, detail::light_qualifier_v<L>> to_light(const L& l)
{
    light<detail::light_scalar_t<L>, detail::light_qualifier_v<L>> out;
    if constexpr (detail::traits_with_position<L>) out.position = detail::position_of(l);
    out.ambient = detail::ambient_of(l);
    out.diffuse = detail::diffuse_of(l);
    out.specular = detail::specular_of(l);
    out.attenuation = detail::attenuation_of(l);
    out.spot = detail::spot_of(l);
    return out;
}

/// Checks a light against the model's domain. Rejected: a non-finite position or w not 0 or 1;
/// NaN, inf or negative strengths; attenuation negative, non-finite or all zero; range <= 0 or NaN;
/// a bad spot exponent; cos_cutoff outside [0, 1] but -1; cone cosines outside [-1, 1] or
/// cos_outer > cos_inner; a spot axis neither unit (within 1e-3) nor zero. Accepted: a directional
/// light with xyz = 0 (ambient only); a zero spot axis (no cone).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr validation validate(const light<T, Q>& L)
{
    using detail::finite;
    using detail::finite_non_negative;
    if (!finite(L.position)) return {"light.position: not finite"};
    if (!(L.position.w == T(0) || L.position.w == T(1)))
        return {"light.position.w: must be 1 (positional) or 0 (directional)"};
    if (!finite_non_negative(L.ambient)) return {"light.ambient: negative, NaN or inf"};
    if (!finite_non_negative(L.diffuse)) return {"light.diffuse: negative, NaN or inf"};
    if (!finite_non_negative(L.specular)) return {"light.specular: negative, NaN or inf"};
    const falloff<T>& a = L.attenuation;
    if (!finite_non_negative(a.constant)) return {"light.attenuation.constant: must be finite and >= 0"};
    if (!finite_non_negative(a.linear)) return {"light.attenuation.linear: must be finite and >= 0"};
    if (!finite_non_negative(a.quadratic)) return {"light.attenuation.quadratic: must be finite and >= 0"};
    if (a.constant + a.linear + a.quadratic <= T(0))
        return {"light.attenuation: constant + linear + quadratic must be > 0 (all zero: f = 1 / 0)"};
    if (!(detail::not_nan(a.range) && a.range > T(0))) return {"light.attenuation.range: must be > 0 (inf for no window)"};
    const spot_cone<T, Q>& s = L.spot;
    if (!finite_non_negative(s.exponent)) return {"light.spot.exponent: must be finite and >= 0"};
    if (!(finite(s.cos_cutoff) && (s.cos_cutoff == T(-1) || (s.cos_cutoff >= T(0) && s.cos_cutoff <= T(1)))))
        return {"light.spot.cos_cutoff: cutoff must be in [0, 90] degrees or 180"};
    if (!(finite(s.cos_inner) && s.cos_inner >= T(-1) && s.cos_inner <= T(1))) return {"light.spot.cos_inner: must be in [-1, 1] (inner angle in [0, 180] degrees)"};
    if (!(finite(s.cos_outer) && s.cos_outer >= T(-1) && s.cos_outer <= T(1))) return {"light.spot.cos_outer: must be in [-1, 1] (outer angle in [0, 180] degrees)"};
    if (s.cos_outer > s.cos_inner) return {"light.spot.cos_outer: must be <= cos_inner (outer cone narrower than inner)"};
    // Zero: every component 0 (a tiny axis whose square underflows is not zero: no cone in T, a
    // cone in the wider route's double).
    const bool zero_axis = s.direction.x == T(0) && s.direction.y == T(0) && s.direction.z == T(0);
    const T axis2 = s.direction.x * s.direction.x + s.direction.y * s.direction.y + s.direction.z * s.direction.z;
    if (!(zero_axis || (finite(axis2) && axis2 > T(0.998) && axis2 < T(1.002))))
        return {"light.spot.direction: must be unit length (or zero: no cone)"};
    return {};
}

} // namespace phong
#include "../core/diagnostics_pop.hpp"
