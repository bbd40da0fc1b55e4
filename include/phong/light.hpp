// phong: a light source, and validate(light).
// SPDX-License-Identifier: MIT
#pragma once

#include "attenuation.hpp"
#include "validate.hpp"

namespace phong {

/// One light source, in the coordinates the surface is shaded in (eye coordinates for seeds 000
/// and 003, world coordinates for seed 001's ray tracer).
/// Seed 000's single strength L_i is diffuse = specular = L_i (use light::with_strength); seed 001's
/// lightamb / lightdiff / lightspec and seed 003's La / Ld / Ls map one to one.
template <class T, glm::qualifier Q = glm::defaultp>
struct light {
    /// Homogeneous position: w = 1 positional (xyz is the light's point), w = 0 directional (xyz
    /// points from the surface toward the light). No other w: validate rejects it, since
    /// light_kind::positional and ::directional do not read w (a point with w != 1 would be shaded
    /// at xyz there, at xyz / w with light_kind::any). Divide xyz by w yourself for other w > 0.
    glm::vec<4, T, Q> position{T(0), T(0), T(1), T(0)};
    glm::vec<3, T, Q> ambient{T(0)};  ///< per-light ambient strength (seed 001 lightamb, seed 003 La)
    glm::vec<3, T, Q> diffuse{T(1)};  ///< diffuse strength (seed 001 lightdiff, seed 003 Ld, seed 000 L_i)
    glm::vec<3, T, Q> specular{T(1)}; ///< specular strength (seed 001 lightspec, seed 003 Ls, seed 000 L_i)
    falloff<T> attenuation{};         ///< read when features::attenuation is not none (positional lights only)
    spot_cone<T, Q> spot{};           ///< read when features::spot is not none

    /// A light with one strength for diffuse and specular and no ambient term (source document
    /// 000's L_i): homogeneous position (w = 1 positional, w = 0 directional), strength, falloff.
    PHONG_HD static constexpr light with_strength(const glm::vec<4, T, Q>& position, const glm::vec<3, T, Q>& strength,
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
    /// The older name of with_strength (after source document 000).
    PHONG_HD static constexpr light seed000(const glm::vec<4, T, Q>& position, const glm::vec<3, T, Q>& strength,
                                            falloff<T> attenuation = {})
    {
        return with_strength(position, strength, attenuation);
    }
};

/// Checks a light against the model's domain. Rejected: a non-finite position or a w other than
/// 0 or 1 (-0 counts as 0); NaN,
/// inf or negative strengths; attenuation coefficients that are negative, non-finite or all
/// zero; range <= 0 or NaN; a spot exponent that is negative or non-finite; a cutoff cosine
/// outside [0, 1] other than -1 (180 degrees); smooth cone cosines outside [-1, 1] or with
/// cos_outer > cos_inner; a spot axis that is not unit length (within 1e-3).
/// Accepted although degenerate (shade gives a defined result): a directional light with
/// xyz = 0 (no direction: contributes its ambient only).
template <class T, glm::qualifier Q>
PHONG_HD constexpr validation validate(const light<T, Q>& L)
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
    if (!finite_non_negative(a.constant) || !finite_non_negative(a.linear) || !finite_non_negative(a.quadratic))
        return {"light.attenuation: coefficients must be finite and >= 0"};
    if (a.constant + a.linear + a.quadratic <= T(0)) return {"light.attenuation: c0 + c1 + c2 must be > 0"};
    if (!(a.range > T(0))) return {"light.attenuation.range: must be > 0 (inf for no window)"};
    const spot_cone<T, Q>& s = L.spot;
    if (!finite_non_negative(s.exponent)) return {"light.spot.exponent: must be finite and >= 0"};
    if (!(s.cos_cutoff == T(-1) || (s.cos_cutoff >= T(0) && s.cos_cutoff <= T(1))))
        return {"light.spot.cos_cutoff: cutoff must be in [0, 90] degrees or 180"};
    if (!(s.cos_inner >= T(-1) && s.cos_inner <= T(1) && s.cos_outer >= T(-1) && s.cos_outer <= T(1)))
        return {"light.spot: cos_inner and cos_outer must be in [-1, 1]"};
    if (s.cos_outer > s.cos_inner) return {"light.spot: outer cone narrower than inner cone"};
    const T axis2 = s.direction.x * s.direction.x + s.direction.y * s.direction.y + s.direction.z * s.direction.z;
    if (!(axis2 > T(0.998) && axis2 < T(1.002))) return {"light.spot.direction: must be unit length"};
    return {};
}

} // namespace phong
