// phong: a light source, and validate(light).
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/math.hpp"
#include "../core/vector.hpp"
#include "validate.hpp"

#include <limits>
#include <type_traits>
#include <utility>

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

/// A spot cone: the axis the light points along and its parametrizations, OpenGL's (exponent and
/// cutoff) and the inner/outer cone (read by the smooth and the linear edge). The default is no
/// spot. A zero axis is no cone either (every spot model gives 1): a light whose spot fields are
/// all left at zero, as GLSL and HLSL uniforms are, is lit, not dark.
template <class T, glm::qualifier Q = glm::defaultp>
struct spot_cone {
    glm::vec<3, T, Q> direction{T(0), T(0), T(-1)}; ///< unit axis s, from the light outward; zero: no cone
    T exponent = T(0);     ///< OpenGL spot exponent e >= 0
    T cos_cutoff = T(-1);  ///< cos of OpenGL's cutoff angle: in [0, 1] (0..90 degrees), or -1 (180: no spot)
    T cos_inner = T(-1);   ///< smooth and linear models: full strength where cos(angle) >= cos_inner
    T cos_outer = T(-1);   ///< smooth and linear models: zero where cos(angle) <= cos_outer; cos_outer <= cos_inner

    /// OpenGL spot: axis (normalized here), exponent, cutoff in degrees (0..90, or 180 = no spot).
    /// Edge: a zero axis stores direction 0, no cone (spot = 1). A cutoff outside that range
    /// (negative, above 90 other than 180, NaN) makes a cone validate(light) rejects, naming
    /// light.spot.cos_cutoff (the cosine alone cannot tell -10 from 10 degrees, so such a cutoff
    /// stores cos_cutoff = 2).
    PHONG_INLINE static constexpr spot_cone opengl(const glm::vec<3, T, Q>& axis, T exponent, T cutoff_degrees)
    {
        spot_cone s;
        s.direction = detail::normalize(axis);
        s.exponent = exponent;
        const bool in_range = (cutoff_degrees >= T(0) && cutoff_degrees <= T(90)) || cutoff_degrees == T(180);
        s.cos_cutoff = in_range ? detail::cos_degrees(cutoff_degrees) : T(2);
        return s;
    }
    /// Smooth or linear spot (the same fields; features::spot picks the edge): full strength
    /// inside inner_degrees, none outside outer_degrees
    /// (0 <= inner <= outer <= 180). Edge: a zero axis stores direction 0, no cone (spot = 1);
    /// an angle outside [0, 180] (or NaN) or inner > outer makes a cone validate(light) rejects
    /// (light.spot.cos_inner or light.spot.cos_outer, stored as 2 for an angle out of range;
    /// light.spot.cos_outer for inner > outer); inner = outer: a hard edge.
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

/// One light source, in the coordinates the surface is shaded in (eye coordinates for classic Phong
/// and 003, world coordinates for the ray tracer model's ray tracer).
/// classic Phong's single strength L_i is diffuse = specular = L_i (use light::with_strength); the ray tracer model's
/// lightamb / lightdiff / lightspec and the GLSL ADS shader's La / Ld / Ls map one to one.
template <class T, glm::qualifier Q = glm::defaultp>
struct light {
    /// Homogeneous position: w = 1 positional (xyz is the light's point), w = 0 directional (xyz
    /// points from the surface toward the light). No other w: validate rejects it, since
    /// light_kind::positional and ::directional do not read w (a point with w != 1 would be shaded
    /// at xyz there, at xyz / w with light_kind::any). Divide xyz by w yourself for other w > 0.
    glm::vec<4, T, Q> position{T(0), T(0), T(1), T(0)};
    glm::vec<3, T, Q> ambient{T(0)};  ///< per-light ambient strength (the ray tracer model lightamb, the GLSL ADS shader La)
    glm::vec<3, T, Q> diffuse{T(1)};  ///< diffuse strength (the ray tracer model lightdiff, the GLSL ADS shader Ld, classic Phong L_i)
    glm::vec<3, T, Q> specular{T(1)}; ///< specular strength (the ray tracer model lightspec, the GLSL ADS shader Ls, classic Phong L_i)
    falloff<T> attenuation{};         ///< read when features::attenuation is not none (positional lights only)
    spot_cone<T, Q> spot{};           ///< read when features::spot is not none

    /// A light with one strength for diffuse and specular and no ambient term (source document
    /// 000's L_i): homogeneous position (w = 1 positional, w = 0 directional), strength, falloff.
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

/// How shade<F> reads a light of type L: the specialization point for a renderer's own light type
/// (an adaptor), so that its light list goes to shade<F> as it is, nothing copied into
/// a light<T> per point. light<T, Q> has one (below); any other type has none: shade<F> then
/// stops with a static_assert that names light_traits. A specialization has static functions
/// (PHONG_HD ones for CUDA device code), each returning a value or a reference:
///   position(L) -> glm::vec<4, U, Q>  required by shade<F> (shade_incident<F> reads it only with
///                                      light_kind::any, for w): the homogeneous position, as
///                                      light::position (w = 1 positional, w = 0 directional; U, Q:
///                                      the light's scalar type and qualifier, read from this
///                                      function's return type, else from diffuse's);
///   diffuse(L)  -> glm::vec<3, U, Q>  required: Ld (the ray tracer model lightdiff);
///   specular(L) -> glm::vec<3, U, Q>  required: Ls (the ray tracer model lightspec);
///   ambient(L)  -> glm::vec<3, U, Q>  optional, default 0: La (the ray tracer model lightamb);
///   attenuation(L) -> `falloff<U>`    optional, default `falloff<U>{}` (f = 1): read with attenuation;
///   spot(L)     -> spot_cone<U, Q>    optional, default spot_cone<U, Q>{} (no cone): read with a spot.
/// Each function is called where the model reads that field (inlined: the same code as for the
/// member of a light<T>), at most once per light per point, and only for the terms F has. A point
/// light with one colour, for instance:
///   template <> struct phong::light_traits<my_light> {
///       static glm::vec4 position(const my_light& L) { return glm::vec4(L.position, 1.0f); }
///       static const glm::vec3& diffuse(const my_light& L) { return L.colour; }
///       static const glm::vec3& specular(const my_light& L) { return L.colour; }
///   };
/// Pre: the values returned are those validate() accepts in a light<U, Q> (checked in debug builds
/// and in constant evaluation, through to_light).
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
/// A light's scalar type and qualifier: from position's glm::vec<4, U, Q> where the traits have
/// one, else from diffuse's glm::vec<3, U, Q> (a light that only shade_incident reads).
template <class L> struct light_fields : colour_of<light_diffuse_t<L>> {};
template <traits_with_position L> struct light_fields<L> : homogeneous_position_of<light_position_t<L>> {};
} // namespace detail

namespace detail {
/// A type shade_incident<F> takes as a light: light_traits<L> gives diffuse and specular (a
/// glm::vec<3, U, Q>; cv and references ignored); position is optional (shade_incident reads the
/// light's direction from its incident, and w only with light_kind::any).
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
/// The scalar type U (light_scalar_t) and qualifier (light_qualifier_v) of a light's fields, read
/// from light_traits<L>::position's return type glm::vec<4, U, Q> (from diffuse's glm::vec<3, U, Q>
/// for a light without a position).
template <incident_light_source L>
using light_scalar_t = typename detail::light_fields<std::remove_cvref_t<L>>::scalar;
template <incident_light_source L>
inline constexpr glm::qualifier light_qualifier_v = detail::light_fields<std::remove_cvref_t<L>>::qualifier;
} // namespace detail

namespace detail {
/// The fields of a light_source as shade<F> reads them: light_traits' function, or the default
/// of light<U, Q> where the traits leave an optional field out. References stay references.
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

/// The light<U, Q> a light_source stands for: every field read through light_traits (defaults
/// where the traits leave one out; light<U, Q>'s default position for an incident_light_source
/// without one). For what needs a light<T> itself: validate(), and shade_batch, which takes a span
/// of light<T> (convert the list once per call, not per point).
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

/// Checks a light against the model's domain. Rejected: a non-finite position or a w other than
/// 0 or 1 (-0 counts as 0); NaN,
/// inf or negative strengths; attenuation coefficients that are negative, non-finite or all
/// zero; range <= 0 or NaN; a spot exponent that is negative or non-finite; a cutoff cosine
/// outside [0, 1] other than -1 (180 degrees); smooth cone cosines outside [-1, 1] or with
/// cos_outer > cos_inner; a spot axis that is neither unit length (within 1e-3) nor zero.
/// Accepted although degenerate (shade gives a defined result): a directional light with
/// xyz = 0 (no direction: contributes its ambient only); a zero spot axis (no cone).
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
    const T axis2 = s.direction.x * s.direction.x + s.direction.y * s.direction.y + s.direction.z * s.direction.z;
    if (!(finite(axis2) && ((axis2 > T(0.998) && axis2 < T(1.002)) || axis2 == T(0))))
        return {"light.spot.direction: must be unit length (or zero: no cone)"};
    return {};
}

} // namespace phong
