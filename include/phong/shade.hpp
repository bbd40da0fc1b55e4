// phong: the full multi-light sum, shade<features>(...), and the per-vertex pipeline of seed 003.
// SPDX-License-Identifier: MIT
//
// This header only orchestrates: prepare the point, add every light, finish. The arithmetic of
// each evaluation route lives in its own unit, one small function per step of the data flow:
// detail/exact.hpp (the exact mode, and the stable mode's wider route for float: the exact route
// in double) and detail/stable.hpp (the stable mode's twofold route); the steps that every route
// shares are in detail/light_terms.hpp and in the public term headers (direction.hpp,
// attenuation.hpp, specular.hpp).
#pragma once

#include "detail/exact.hpp"
#include "detail/stable.hpp"
#include "environment.hpp"
#include "features.hpp"
#include "light.hpp"
#include "material.hpp"
#include "normal.hpp"
#include "view.hpp"

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>

namespace phong {

/// The colour shade<F> returns: rgb, or rgba when F.alpha.
template <features F, class T, glm::qualifier Q = glm::defaultp>
using color = std::conditional_t<F.alpha, glm::vec<4, T, Q>, glm::vec<3, T, Q>>;

namespace detail {

/// The per-point frame of F's evaluation route.
template <features F, class T, glm::qualifier Q>
using frame_t = std::conditional_t<F.mode == evaluation::stable, stable::surface_frame<T, Q>, exact::surface_frame<T, Q>>;

/// The point's frame (unit normal, view vector, whether both exist, poison), by F's route.
template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr frame_t<F, T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                            const environment<T, Q>& env, mask_t<T> front_facing)
{
    if constexpr (F.mode == evaluation::stable) return stable::prepare<F>(position, normal, env, front_facing);
    else return exact::prepare<F>(position, normal, env, front_facing);
}

/// One light's terms added to the sums, by F's route (U: the light's scalar type).
template <features F, class T, glm::qualifier Q, class U>
PHONG_HD constexpr void add_light(light_sums<T, Q>& sums, const frame_t<F, T, Q>& s, const light<U, Q>& L, T m)
{
    if constexpr (F.mode == evaluation::stable) stable::add_light<F>(sums, s, L, m);
    else exact::add_light<F>(sums, s, L, m);
}

/// The colour from the per-light sums: emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i
/// max(n.l_i, 0) + ks sum_i f_i Ls_i s_i, plus the point's poison in every channel; alpha appended.
template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr color<F, T, Q> finish(const light_sums<T, Q>& sums, const frame_t<F, T, Q>& s,
                                         const material<T, Q>& mat, const environment<T, Q>& env)
{
    glm::vec<3, T, Q> c(s.poison);
    if constexpr (F.emission) c += mat.emission;
    if constexpr (F.scene_ambient && F.light_ambient) c += mat.ka * (env.ambient + sums.ambient);
    else if constexpr (F.scene_ambient) c += mat.ka * env.ambient;
    else if constexpr (F.light_ambient) c += mat.ka * sums.ambient;
    if constexpr (F.diffuse) c += mat.kd * sums.diffuse;
    if constexpr (F.specular != specular_model::none) c += mat.ks * sums.specular;
    if constexpr (F.alpha) return glm::vec<4, T, Q>(c, mat.alpha + s.poison);
    else return c;
}

/// validate() every parameter: a compile error in constant evaluation, an assertion in debug
/// builds, nothing at all under NDEBUG (the checks are not even evaluated).
template <class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr void check_parameters([[maybe_unused]] const material<T, Q>& mat, [[maybe_unused]] const Lights& lights)
{
    if constexpr (std::is_floating_point_v<T>) {
#if defined(NDEBUG)
        if (!std::is_constant_evaluated()) return;
#endif
        const validation vm = phong::validate(mat);
        require(static_cast<bool>(vm), vm.message());
        for (const light<T, Q>& L : lights) {
            const validation vl = phong::validate(L);
            require(static_cast<bool>(vl), vl.message());
        }
    }
}

template <class R> struct is_std_array : std::false_type {};
template <class X, std::size_t N> struct is_std_array<std::array<X, N>> : std::true_type {};

/// The stable mode's wider path applies: float arithmetic carried out in double.
template <features F, class T>
inline constexpr bool widened = F.mode == evaluation::stable && F.precision == stable_precision::wider && std::is_same_v<T, float>;

/// F as the wider path runs it: the exact mode's formulas (in double, on float inputs).
template <features F>
inline constexpr features exact_of = [] {
    features e = F;
    e.mode = evaluation::exact;
    return e;
}();

template <class W, class T, glm::qualifier Q>
PHONG_HD constexpr material<W, Q> widen(const material<T, Q>& m)
{
    return {glm::vec<3, W, Q>(m.ka), glm::vec<3, W, Q>(m.kd), glm::vec<3, W, Q>(m.ks), glm::vec<3, W, Q>(m.emission), W(m.shininess), W(m.alpha)};
}
template <class W, class T, glm::qualifier Q>
PHONG_HD constexpr environment<W, Q> widen(const environment<T, Q>& e)
{
    return {glm::vec<3, W, Q>(e.ambient), glm::vec<4, W, Q>(e.eye)};
}

/// prepare, every light, finish: the whole model at one point in arithmetic type T (the lights'
/// scalar type may be narrower: the wider path).
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> evaluate(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                           const material<T, Q>& mat, const Lights& lights,
                                           const environment<T, Q>& env, bool front_facing)
{
    const frame_t<F, T, Q> s = prepare<F>(position, normal, env, front_facing);
    light_sums<T, Q> sums{};
    if constexpr (is_std_array<Lights>::value) {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (detail::add_light<F>(sums, s, lights[I], mat.shininess), ...);
        }(std::make_index_sequence<std::tuple_size_v<Lights>>{});
    } else {
        if constexpr (std::is_floating_point_v<T>) {
            // The same loop twice, so each copy is compiled knowing whether the point has a
            // normal and a view vector (g++ does not unswitch it by itself).
            if (s.defined) for (const auto& L : lights) detail::add_light<F>(sums, s, L, mat.shininess);
            else for (const auto& L : lights) detail::add_light<F>(sums, s, L, mat.shininess);
        } else {
            for (const auto& L : lights) detail::add_light<F>(sums, s, L, mat.shininess);
        }
    }
    return finish<F>(sums, s, mat, env);
}


} // namespace detail

/// The full local lighting model at one point (seeds 000, 001 and 003 are presets of it):
///   I = emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i max(n.l_i, 0)
///                + ks sum_i f_i Ls_i s_i,
///   s_i = max(r_i.v, 0)^m (r_i = reflect(-l_i, n)) or max(n.h_i, 0)^m (h_i = normalize(l_i + v)),
///   f_i = attenuation(d_i) * spot_i,   l_i = normalize(L_i.xyz - L_i.w Q),
/// with rgba = (I, alpha) when F.alpha. Each term is compiled only when F asks for it.
///
/// position, normal: Q and its normal (any length; normalized here) in the lights' coordinates.
/// lights: a std::array<light, N> (unrolled at compile time), std::span, std::vector, ...
/// front_facing: read only for facing::flag.
///
/// Pre: validate(mat) and validate(L) for every light (checked: a compile error in constant
/// evaluation, an assertion in debug builds). Edges (finite input never gives NaN or inf):
///  * a light at Q (or a directional light with xyz = 0): no direction; that light adds only its
///    ambient term;
///  * normal = 0 or Q at the eye (v = 0): no diffuse or specular from any light;
///  * Blinn with l = -v: n.h taken as 0 (0 for m > 0, 1 for m = 0);
///  * m = 0: the specular base^0 = 1 wherever the specular term is on (pow(0, 0) = 1);
///  * c0 = 0 and d -> 0: f capped at 1 / attenuation_denominator_min<T>;
///  * NaN or inf in position, normal or (eye_point) eye: every channel is NaN.
/// Accuracy: per F.mode and input class, the constants phong::accuracy::bounds<M, T, P> (tested in
/// tests/accuracy.test.cpp, table in README.md). exact: a vector whose squared length is not a
/// normal number (|L - Q|, |n| or |Q| below ~1.1e-19 or above ~1.8e19 in float, 1.5e-154 and
/// 1.3e154 in double) is dropped: its light gives 0 (relative error 1), never NaN. stable: every
/// finite input. Float with F.precision = wider (the default): the exact formulas evaluated in
/// double (every float input is exact there and no square of one overflows or underflows) and
/// rounded once: within 1 ulp, correctly rounded but for near-ties, m = 1e5 and n.l ~ 1e-6
/// included. Double, and float with F.precision = twofold: unit vectors, n.l and the specular
/// chords carried twofold (detail/twofold.hpp), within a few ulp on the same classes.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> shade(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                        const material<T, Q>& mat, const Lights& lights,
                                        const environment<T, Q>& env = {}, bool front_facing = true)
{
    detail::check_parameters(mat, lights);
    if constexpr (detail::widened<F, T>) {
        using W = double;
        return color<F, T, Q>(detail::evaluate<detail::exact_of<F>>(glm::vec<3, W, Q>(position), glm::vec<3, W, Q>(normal),
                                                                     detail::widen<W>(mat), lights, detail::widen<W>(env), front_facing));
    } else {
        return detail::evaluate<F>(position, normal, mat, lights, env, front_facing);
    }
}

/// Seed 003's per-vertex pipeline (phong.vert, diffuse.vert): object-space position and normal,
///   eyeCoords = ModelView * (p, 1),  tnorm = normalize(NormalMatrix * n),
/// then shade<F>(eyeCoords.xyz, tnorm, ...) with lights in eye coordinates.
/// Pre: model_view affine (last row 0, 0, 0, 1), as in the seed, which drops eyeCoords.w.
/// normal_matrix(model_view) gives NormalMatrix.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> shade_vertex(const glm::vec<3, T, Q>& vertex_position, const glm::vec<3, T, Q>& vertex_normal,
                                               const glm::mat<4, 4, T, Q>& model_view, const glm::mat<3, 3, T, Q>& normal_mat,
                                               const material<T, Q>& mat, const Lights& lights,
                                               const environment<T, Q>& env = {})
{
    const glm::vec<4, T, Q> eye = model_view[0] * vertex_position.x + model_view[1] * vertex_position.y +
                                  model_view[2] * vertex_position.z + model_view[3];
    return shade<F>(glm::vec<3, T, Q>(eye.x, eye.y, eye.z), phong::transform_normal(normal_mat, vertex_normal), mat, lights, env);
}

} // namespace phong
