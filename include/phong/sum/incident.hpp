// phong: shading from what the renderer already has: each light's unit direction and distance (a
// shadow ray), the normal and the view vector (given, or one fixed direction); no position.
// SPDX-License-Identifier: MIT
#pragma once

#include "shade.hpp"

#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include "../core/diagnostics_push.hpp"

namespace phong {

/// One light as seen from the shaded point Q, when the renderer has computed it already:
///   direction = l = (L.xyz - w Q) / |L.xyz - w Q|   (unit, from Q toward the light),
///   distance  = |L.xyz - Q|                          (positional lights; read only by attenuation).
/// A shadow ray's direction and length are exactly these.
template <class T, glm::qualifier Q = glm::defaultp>
struct incident {
    glm::vec<3, T, Q> direction{T(0), T(0), T(1)}; ///< l, unit length (within 1e-3)
    T distance = T(0);                             ///< |L.xyz - Q| >= 0, finite; read only with attenuation
};

/// A point's surface data as texture maps give it: material<T, Q>'s per-point terms, without
/// emission (0) and alpha (1). shade_incident takes it or a material<T, Q>.
template <class T, glm::qualifier Q = glm::defaultp>
struct surface {
    glm::vec<3, T, Q> ka{T(0)}; ///< ambient reflectivity, as material::ka
    glm::vec<3, T, Q> kd{T(0)}; ///< diffuse reflectivity, as material::kd
    glm::vec<3, T, Q> ks{T(0)}; ///< specular reflectivity, as material::ks
    T shininess = T(1);         ///< the specular exponent m >= 0, as material::shininess
};

namespace detail {

template <class S> struct is_surface : std::false_type {};
template <class T, glm::qualifier Q> struct is_surface<surface<T, Q>> : std::true_type {};

/// The material a surface stands for (emission 0, alpha 1), built where read.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr material<T, Q> material_of(const surface<T, Q>& s)
{
    return {s.ka, s.kd, s.ks, glm::vec<3, T, Q>(T(0)), s.shininess, T(1)};
}
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr const material<T, Q>& material_of(const material<T, Q>& m)
{
    return m;
}

/// features::unit_inputs' check of a given light direction (debug builds, constant evaluation).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr void check_incident([[maybe_unused]] const incident<T, Q>& in)
{
    if constexpr (std::is_floating_point_v<T>) {
        if (!value_checks_on()) return;
        const T ll = detail::dot(in.direction, in.direction);
        require(ll >= T(0.998) && ll <= T(1.002), "phong::incident: direction must be unit length");
        require(in.distance >= T(0) && in.distance <= std::numeric_limits<T>::max(), "phong::incident: distance must be finite and >= 0");
    }
}

/// The per-point frame without a position: unit normal, view vector (given, or eye's direction for
/// fixed_direction; as is under unit_inputs), whether both exist, the poison, n.v. Apart from
/// exact::prepare because its bits differ: the NaN test reads no |Q|^2, and fixed_direction's v is
/// unit_of(eye) where exact::prepare normalizes with rescaling (non-finite or non-unit eye).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr exact::surface_frame<T, Q> incident_frame(const glm::vec<3, T, Q>& normal, const glm::vec<3, T, Q>& given_view,
                                                                 const environment<T, Q>& env, bool front_facing)
{
    using vec3 = glm::vec<3, T, Q>;
    using exact::unit_vector;
    const vec3 view_input = F.view == view_model::given ? given_view : vec3(env.eye.x, env.eye.y, env.eye.z);
    unit_vector<T, Q> n{normal, T(1), true};
    if constexpr (!F.unit_inputs) n = exact::unit_of(normal);
    unit_vector<T, Q> v{view_input, T(1), true};
    if constexpr (!F.unit_inputs) v = exact::view_unit<F>(view_input, T(1));
    T poison = T(0);
    if (!(n.square <= largest<T>() && v.square <= largest<T>())) [[unlikely]] {
        const vec3 zero(T(0));
        poison = detail::dot(normal, zero) + detail::dot(view_input, zero);
    }
    const bool defined = n.ok && poison == T(0);
    vec3 unit_normal = n.unit;
    if constexpr (F.two_sided != facing::none) unit_normal = unit_normal * facing_sign<F>(unit_normal, v.unit, front_facing);
    else (void)front_facing;
    T nv = T(0);
    if constexpr (F.specular != specular_model::none) nv = detail::dot(unit_normal, v.unit);
    return {vec3(T(0)), unit_normal, v.unit, defined, v.ok, poison, nv, {}};
}

/// One light's terms from its given direction l and distance, as the exact route forms them from
/// d = l, |d| = 1. Apart from exact::add_light because its bits differ: no |d|^2, no 1/|d|, no range
/// test, and f reads the given distance (add_light on d = l would add those roundings back).
template <features F, class T, glm::qualifier Q, class Light, class U>
PHONG_INLINE constexpr void add_incident_light(light_sums<T, Q>& sums, const exact::surface_frame<T, Q>& s, const Light& L,
                                               const incident<U, Q>& in, T m)
{
    using vec3 = glm::vec<3, T, Q>;
    check_incident(in);
    const vec3 l(in.direction);
    const T w = light_w<F, T>(L);
    const T f = light_factor<F>(L, T(in.distance), w, l, unweighted{});
    add_ambient<F>(sums, L, f);
    const T nl = detail::dot(s.normal, l);
    if (!(s.defined && (!gated<F> || nl > T(0)))) return;
    if constexpr (F.specular != specular_model::none) {
        if (s.sees_viewer) {
            if constexpr (F.specular == specular_model::phong)
                exact::add_specular<F.mode>(sums, L, f, detail::reflection_cosine_scaled(nl, s.nv, l, s.view), T(1), m, true);
            else
                exact::add_specular<F.mode>(sums, L, f, nl + s.nv, exact::route_inverse_halfway_length<F.mode>(l, s.view), m, true);
        }
    }
    if constexpr (F.diffuse) add_diffuse<F>(sums, L, f, nl, true);
}

/// The lights with their incidents (incidents[i] for the i-th light, masked or not) by the one light
/// loop (each_listed_light): never read past a shorter incident list (within_bounds). The first
/// light is added in straight-line code from the sums' -0 (evaluate_incident): -0 + x = x folds.
template <features F, class T, glm::qualifier Q, class Lights, class Incidents>
PHONG_INLINE constexpr void add_incident_lights(light_sums<T, Q>& sums, const exact::surface_frame<T, Q>& s, const Lights& lights,
                                                const Incidents& incidents, T m)
{
    each_listed_light<true>(lights, incidents, "phong::shade_incident: fewer incidents than lights",
                            [&](const auto& L, std::size_t i, bool on) PHONG_DETAIL_LAMBDA_INLINE {
                                check_light(L);
                                if (on) add_incident_light<F>(sums, s, L, incidents[i], m);
                            });
}

/// The wider route reads the incident list lazily: incident<float> converted to double per light.
template <features F, class T, glm::qualifier Q, class Surface, class Lights, class Incidents>
PHONG_INLINE constexpr shading_terms<T, Q> evaluate_incident(const glm::vec<3, T, Q>& normal, const glm::vec<3, T, Q>& view,
                                                             const Surface& surf, const Lights& lights, const Incidents& incidents,
                                                             const environment<T, Q>& env, bool front_facing)
{
    const material<T, Q>& mat = material_of(surf);
    const exact::surface_frame<T, Q> s = incident_frame<F>(normal, view, env, front_facing);
    // Every sum starts at -0 (-0 + x = x: the first light's terms become the sums). The colour has
    // +0's bits: total_of starts from emission + poison, which turns a -0 term into +0.
    const glm::vec<3, T, Q> negative_zero(-T(0));
    light_sums<T, Q> sums{negative_zero, negative_zero, negative_zero};
    add_incident_lights<F>(sums, s, lights, incidents, mat.shininess);
    return terms_of<F>(sums, s, mat, env);
}

/// shade_incident's body: checks, then the exact formulas in T (in double for float's wider mode).
template <features F, class T, glm::qualifier Q, class Surface, class Lights, class Incidents>
PHONG_INLINE constexpr color<F, T, Q> shade_incident_at(const glm::vec<3, T, Q>& normal, const glm::vec<3, T, Q>& view, const Surface& surf,
                                                        const Lights& lights, const Incidents& incidents, const environment<T, Q>& env,
                                                        bool front_facing)
{
    if constexpr (incident_light_list<Lights>)
        static_assert(F.lights != light_kind::any ||
                          light_source<list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>>,
                      "shade_incident with light_kind::any reads each light's w: give light_traits a position, or set "
                      "features::lights to positional or directional");
    static_assert(!is_weighted<std::remove_cvref_t<Lights>>::value, "shade_incident: weighted() lists are not supported (use masked())");
    static_assert(F.view == view_model::given || F.view == view_model::fixed_direction,
                  "shade_incident reads no position: features::view must be given or fixed_direction");
    static_assert(!is_surface<Surface>::value || (!F.emission && !F.alpha), "phong::surface has no emission or alpha: pass a material");
    const material<T, Q>& mat = material_of(surf);
    check_inputs<F, entry_point::shade_incident, Lights>(normal, view, mat, env);
    if constexpr (!incident_light_list<Lights>) {
        return {}; // not instantiated further: check_inputs' static_assert is the one error reported
    } else if constexpr (widened<F, T>) {
        using W = double;
        constexpr features E = exact_of<F>;
        return color<F, T, Q>(total_of<F>(evaluate_incident<E>(glm::vec<3, W, Q>(normal), glm::vec<3, W, Q>(view), widen<W>(mat), lights,
                                                                 incidents, widen<W>(env), front_facing)));
    } else {
        // the twofold route's formulas start from an error-free L - Q: from a given l, the exact ones
        constexpr features G = F.mode == evaluation::stable ? F.with_mode(evaluation::exact) : F;
        return total_of<F>(evaluate_incident<G>(normal, view, mat, lights, incidents, env, front_facing));
    }
}

} // namespace detail

/// The full model of shade<F> from what the renderer already has, for a feature set that reads no
/// position (features::view = view_model::given or fixed_direction):
///   I = emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i max(n.l_i, 0) + ks sum_i f_i Ls_i s_i,
/// with l_i = incidents[i].direction (unit) and, for attenuation, d_i = incidents[i].distance given;
/// s_i and f_i as shade<F>, from l_i.
/// normal: any length (unit and used as is with unit_inputs). surf: a material<T, Q> or a
/// surface<T, Q>. lights: a range of light<T> or of a light_traits type (position() optional:
/// incident_light_source; w read with light_kind::any), or masked(lights, bits). incidents: a
/// random-access range, incidents[i] for the i-th light, masked or not. The viewer: given (the
/// overload below) or fixed_direction (eye.xyz, normalized once per call unless unit_inputs).
/// Pre: an incident for every light (fewer is reported in debug builds and constant evaluation;
/// nothing is read past them in any build); directions unit (within 1e-3), distances finite and
/// >= 0; n, v (and eye.xyz for fixed_direction) unit with unit_inputs; validate(surf as a material),
/// validate(env), validate(light) (checked in debug builds and constant evaluation).
/// Edges as shade<F> (a zero normal, no view vector, l = -v, m = 0, distance 0 with c0 = 0); NaN or
/// inf in the normal or the view input read makes every channel NaN.
/// Modes: exact and fast as shade<F>; stable float: the wider route; double and twofold run the
/// exact formulas (the given l is already rounded: no error-free L - Q).
/// Result: shade<F>'s colour for those l_i, d_i, within phong::accuracy's exact bound.
template <features F, class T, glm::qualifier Q, class Surface, class Lights, class Incidents>
PHONG_INLINE constexpr color<F, T, Q> shade_incident(const glm::vec<3, T, Q>& normal, const Surface& surf, const Lights& lights,
                                                     const Incidents& incidents, const environment<T, Q>& env = {},
                                                     bool front_facing = true)
{
    static_assert(F.view == view_model::fixed_direction, "view_model::given: pass the view vector, shade_incident<F>(normal, view, ...)");
    return detail::shade_incident_at<F>(normal, glm::vec<3, T, Q>(T(0)), surf, lights, incidents, env, front_facing);
}

/// shade_incident<F> with the view vector v given per call (features::view = view_model::given):
/// v from the point toward the viewer (a ray tracer's -ray.dir), any length (unit with unit_inputs).
template <features F, class T, glm::qualifier Q, class Surface, class Lights, class Incidents>
PHONG_INLINE constexpr color<F, T, Q> shade_incident(const glm::vec<3, T, Q>& normal, const glm::vec<3, T, Q>& view, const Surface& surf,
                                                     const Lights& lights, const Incidents& incidents, const environment<T, Q>& env = {},
                                                     bool front_facing = true)
{
    static_assert(F.view == view_model::given, "a view vector is read only with features::view = view_model::given");
    return detail::shade_incident_at<F>(normal, view, surf, lights, incidents, env, front_facing);
}

} // namespace phong
#include "../core/diagnostics_pop.hpp"
