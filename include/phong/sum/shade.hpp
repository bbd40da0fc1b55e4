// phong: the full multi-light sum, shade<features>(...), and the GLSL ADS shader's per-vertex
// pipeline. Orchestration only: prepare the point, add every light, finish (routes/route.hpp).
// SPDX-License-Identifier: MIT
#pragma once

#include "../routes/route.hpp"
#include "../inputs/environment.hpp"
#include "../inputs/features.hpp"
#include "../inputs/light.hpp"
#include "../inputs/material.hpp"
#include "../terms/normal.hpp"
#include "shading_terms.hpp"
#include "../terms/view.hpp"
#include "../inputs/visibility.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

namespace phong {

namespace detail {

/// check_parameters' body, out of line (PHONG_DETAIL_OUT_OF_LINE).
template <class T, glm::qualifier Q>
PHONG_DETAIL_OUT_OF_LINE constexpr void validate_parameters_or_fail(const material<T, Q>& mat, const environment<T, Q>& env)
{
    const validation vm = phong::validate(mat);
    require(static_cast<bool>(vm), vm.message());
    const validation ve = phong::validate(env);
    require(static_cast<bool>(ve), ve.message());
}

/// validate(material) and validate(environment): a compile error in constant evaluation, an
/// assertion in debug builds, nothing under NDEBUG (not even evaluated).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr void check_parameters([[maybe_unused]] const material<T, Q>& mat, [[maybe_unused]] const environment<T, Q>& env)
{
    if constexpr (std::is_floating_point_v<T>) {
        if (value_checks_on()) validate_parameters_or_fail(mat, env);
    }
}

/// The stable mode's wider path applies: float arithmetic carried out in double.
template <features F, class T>
inline constexpr bool widened = F.mode == evaluation::stable && F.precision == stable_precision::wider && std::is_same_v<T, float>;

/// F as the wider path runs it: the exact mode's formulas (in double, on float inputs).
template <features F>
inline constexpr features exact_of = F.with_mode(evaluation::exact);

template <class W, class T, glm::qualifier Q>
PHONG_INLINE constexpr material<W, Q> widen(const material<T, Q>& m)
{
    return {glm::vec<3, W, Q>(m.ka), glm::vec<3, W, Q>(m.kd), glm::vec<3, W, Q>(m.ks), glm::vec<3, W, Q>(m.emission), W(m.shininess), W(m.alpha)};
}
template <class W, class T, glm::qualifier Q>
PHONG_INLINE constexpr environment<W, Q> widen(const environment<T, Q>& e)
{
    return {glm::vec<3, W, Q>(e.ambient), glm::vec<4, W, Q>(e.eye)};
}

/// features::unit_inputs' precondition: |v| = 1 within 1e-3 and finite (debug builds, constant evaluation).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr void check_unit([[maybe_unused]] const glm::vec<3, T, Q>& v, [[maybe_unused]] const char* message)
{
    if constexpr (std::is_floating_point_v<T>) {
        if (!value_checks_on()) return;
        const T vv = detail::dot(v, v);
        require(vv >= T(0.998) && vv <= T(1.002), message);
    }
}

/// prepare, every light, finish: the model's terms at one point in arithmetic type T (the lights'
/// may be narrower: the wider route).
template <features F, bool Check = true, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr shading_terms<T, Q> evaluate(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                                const glm::vec<3, T, Q>& given_view, const material<T, Q>& mat,
                                                Lights&& lights, const environment<T, Q>& env, bool front_facing)
{
    const frame_t<F, T, Q> s = detail::prepare<F>(position, normal, given_view, env, front_facing);
    light_sums<T, Q> sums{};
    add_lights<F, Check>(sums, s, static_cast<Lights&&>(lights), mat.shininess);
    return terms_of<F>(sums, s, mat, env);
}

/// The arithmetic type of shade<F> on T: double for float's stable mode (the wider route), else T.
template <features F, class T>
using arithmetic_t = std::conditional_t<widened<F, T>, double, T>;

/// Which public entry point checks its inputs (check_inputs): the messages name it.
enum class entry_point : unsigned char { shade, shade_incident };

/// The entry checks of shade<F> and shade_incident<F>, written once: a light list (static_assert
/// naming light_traits), validate(material), validate(environment), and unit_inputs' unit vectors
/// (debug-only, value_checks_on); the messages name the entry point.
template <features F, entry_point E, class Lights, class T, glm::qualifier Q>
PHONG_INLINE constexpr void check_inputs([[maybe_unused]] const glm::vec<3, T, Q>& normal, [[maybe_unused]] const glm::vec<3, T, Q>& view,
                                         const material<T, Q>& mat, const environment<T, Q>& env)
{
    if constexpr (E == entry_point::shade)
        static_assert(light_list<Lights>, "phong: the lights must be a range of phong::light<T> or of a type with a "
                                          "phong::light_traits specialization (position, diffuse, specular; see light.hpp), "
                                          "or masked() / weighted() of one");
    else
        static_assert(incident_light_list<Lights>, "phong: the lights must be a range of phong::light<T> or of a type with a "
                                                   "phong::light_traits specialization (diffuse, specular; see light.hpp), "
                                                   "or masked() of one");
    check_parameters(mat, env);
    if constexpr (F.unit_inputs) {
        constexpr bool incident = E == entry_point::shade_incident;
        check_unit(normal, incident ? "shade_incident: normal must be unit length (features::unit_inputs)"
                                    : "shade: normal must be unit length (features::unit_inputs)");
        if constexpr (F.view == view_model::given)
            check_unit(view, incident ? "shade_incident: view vector must be unit length (features::unit_inputs)"
                                      : "shade: view vector must be unit length (features::unit_inputs)");
        if constexpr (F.view == view_model::fixed_direction)
            check_unit(glm::vec<3, T, Q>(env.eye), incident ? "shade_incident: environment::eye.xyz must be unit length (features::unit_inputs)"
                                                            : "shade: environment::eye.xyz must be unit length (fixed_direction, features::unit_inputs)");
    }
}

/// shade<F>'s body: checks, then the route (float's stable mode: the exact route in double), terms
/// in the arithmetic type. Check = false: no checks (shade_batch checked once per call).
template <features F, bool Check = true, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr shading_terms<arithmetic_t<F, T>, Q> shade_at(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                                                 const glm::vec<3, T, Q>& view, const material<T, Q>& mat,
                                                                 Lights&& lights, const environment<T, Q>& env, bool front_facing)
{
    if constexpr (Check) check_inputs<F, entry_point::shade, Lights>(normal, view, mat, env);
    if constexpr (!light_list<Lights>) {
        return {}; // not instantiated further: check_inputs' static_assert is the one error reported
    } else if constexpr (widened<F, T>) {
        using W = double;
        return evaluate<exact_of<F>, Check>(glm::vec<3, W, Q>(position), glm::vec<3, W, Q>(normal), glm::vec<3, W, Q>(view),
                                     widen<W>(mat), static_cast<Lights&&>(lights), widen<W>(env), front_facing);
    } else {
        return evaluate<F, Check>(position, normal, view, mat, static_cast<Lights&&>(lights), env, front_facing);
    }
}

} // namespace detail

/// The full local lighting model at one point (classic Phong, 001 and 003 are presets of it):
///   I = emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i max(n.l_i, 0) + ks sum_i f_i Ls_i s_i,
///   s_i = max(r_i.v, 0)^m (r_i = reflect(-l_i, n)) or max(n.h_i, 0)^m (h_i = normalize(l_i + v)),
///   f_i = attenuation(d_i) * spot_i,   l_i = normalize(L_i.xyz - L_i.w Q),
/// with rgba = (I, alpha) when F.alpha. Each term is compiled only when F asks for it.
/// position, normal: Q and its normal in the lights' coordinates (any length; unit and used as is
/// with features::unit_inputs). lights: light<T> (or light<U>) values or the renderer's own type
/// through light_traits (light.hpp; nothing copied), from any input range (std::array: unrolled;
/// span, vector, views) or masked() / weighted() of one (visibility.hpp); each read once; anything
/// else is a compile error naming light_traits. The viewer per features::view (eye_at_origin:
/// v = normalize(-Q); fixed_direction, eye_point: from env.eye; given: the overload below).
/// front_facing: read only for facing::flag.
/// Pre: validate(mat), validate(env), validate(L) for every light, weighted() weights finite and
/// >= 0 (a compile error in constant evaluation, the precondition handler in debug builds, nothing
/// under NDEBUG). Edges (finite input never gives NaN or inf):
///  * a light at Q (or directional with xyz = 0): only its ambient term;
///  * normal = 0: no diffuse or specular; no view vector (Q at the eye, a zero v): diffuse only;
///  * Blinn with l = -v: n.h = 0;  m = 0: the specular base^0 = 1 wherever the term is on;
///  * c0 = 0 and d -> 0: f capped at 1 / attenuation_denominator_min<T>;
///  * NaN or inf in position, normal or the view input read: every channel NaN (not kept when
///    unit_inputs' precondition is broken).
/// Accuracy (phong::accuracy::bounds<M, T, P>; docs/accuracy.md): exact drops a vector whose squared
/// length is not a normal number (its light gives 0, never NaN); stable covers every finite input:
/// float wider (the default) is the exact formulas in double rounded once (within 1 ulp, spot lights
/// too); double, and float twofold, carry unit vectors, n.l and the chords twofold (a few ulp).
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr color<F, T, Q> shade(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                        const material<T, Q>& mat, Lights&& lights,
                                        const environment<T, Q>& env = {}, bool front_facing = true)
{
    static_assert(F.view != view_model::given, "view_model::given: pass the view vector, shade<F>(position, normal, view, ...)");
    const glm::vec<3, T, Q> unused(T(0));
    return color<F, T, Q>(detail::total_of<F>(detail::shade_at<F>(position, normal, unused, mat, static_cast<Lights&&>(lights), env, front_facing)));
}

/// shade<F> with the view vector given per call (view_model::given): from the point toward the
/// viewer, any length (unit with unit_inputs). A ray tracer passes -ray.dir (right for every ray
/// kind; an eye point is right for primary rays only). A NaN or inf view makes every channel NaN,
/// a zero one gives no diffuse or specular term.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr color<F, T, Q> shade(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                        const glm::vec<3, T, Q>& view, const material<T, Q>& mat, Lights&& lights,
                                        const environment<T, Q>& env = {}, bool front_facing = true)
{
    static_assert(F.view == view_model::given, "a view vector is read only with features::view = view_model::given");
    return color<F, T, Q>(detail::total_of<F>(detail::shade_at<F>(position, normal, view, mat, static_cast<Lights&&>(lights), env, front_facing)));
}

namespace detail {
/// The public terms: the point's poison in every one, so that a NaN point has every term NaN.
template <class A, glm::qualifier Q>
PHONG_INLINE constexpr shading_terms<A, Q> poisoned(shading_terms<A, Q> t)
{
    const A poison = t.alpha - t.alpha; // 0, or NaN for a NaN point (alpha carries the poison)
    t.ambient += poison;
    t.diffuse += poison;
    t.specular += poison;
    return t;
}
} // namespace detail

/// shade<F>'s model with its terms apart (emission, ambient, diffuse, specular, alpha), for renderers
/// that weight, tone-map or store them. terms.sum() is shade<F>'s colour bit for bit; the terms are
/// in shade<F>'s arithmetic type (double for float's stable mode: float(terms.sum()) is the colour).
/// Arguments, preconditions and edges as shade<F>.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr shading_terms<detail::arithmetic_t<F, T>, Q> shade_terms(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                                                            const material<T, Q>& mat, Lights&& lights,
                                                                            const environment<T, Q>& env = {}, bool front_facing = true)
{
    static_assert(F.view != view_model::given, "view_model::given: pass the view vector, shade_terms<F>(position, normal, view, ...)");
    const glm::vec<3, T, Q> unused(T(0));
    return detail::poisoned(detail::shade_at<F>(position, normal, unused, mat, static_cast<Lights&&>(lights), env, front_facing));
}

/// shade_terms<F> with the view vector given per call (view_model::given).
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr shading_terms<detail::arithmetic_t<F, T>, Q> shade_terms(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                                                            const glm::vec<3, T, Q>& view, const material<T, Q>& mat,
                                                                            Lights&& lights, const environment<T, Q>& env = {},
                                                                            bool front_facing = true)
{
    static_assert(F.view == view_model::given, "a view vector is read only with features::view = view_model::given");
    return detail::poisoned(detail::shade_at<F>(position, normal, view, mat, static_cast<Lights&&>(lights), env, front_facing));
}

/// The GLSL ADS shader's per-vertex pipeline (phong.vert, diffuse.vert):
///   eyeCoords = ModelView * (p, 1),  tnorm = normalize(NormalMatrix * n),  then shade<F>(eyeCoords.xyz, tnorm, ...)
/// with lights in eye coordinates. Pre: model_view affine (eyeCoords.w dropped, as the seed does);
/// normal_matrix(model_view) gives NormalMatrix; F.view not given. Edges as shade<F> and
/// transform_normal; eye coordinates that overflow T shade as an inf position (NaN in every channel).
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_INLINE constexpr color<F, T, Q> shade_vertex(const glm::vec<3, T, Q>& vertex_position, const glm::vec<3, T, Q>& vertex_normal,
                                               const glm::mat<4, 4, T, Q>& model_view, const glm::mat<3, 3, T, Q>& normal_mat,
                                               const material<T, Q>& mat, Lights&& lights,
                                               const environment<T, Q>& env = {})
{
    const glm::vec<4, T, Q> eye = model_view[0] * vertex_position.x + model_view[1] * vertex_position.y +
                                  model_view[2] * vertex_position.z + model_view[3];
    return shade<F>(glm::vec<3, T, Q>(eye.x, eye.y, eye.z), phong::transform_normal(normal_mat, vertex_normal), mat,
                    static_cast<Lights&&>(lights), env);
}

} // namespace phong
