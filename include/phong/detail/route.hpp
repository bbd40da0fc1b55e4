// phong: the evaluation route F picks (detail/exact.hpp or detail/stable.hpp), and the loop over a
// point's lights: a std::array unrolled, a masked or weighted list (visibility.hpp), any input range.
// SPDX-License-Identifier: MIT
#pragma once

#include "../validate.hpp"
#include "../visibility.hpp"
#include "exact.hpp"
#include "stable.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <type_traits>
#include <utility>

namespace phong::detail {

/// The per-point frame of F's evaluation route.
template <features F, class T, glm::qualifier Q>
using frame_t = std::conditional_t<F.mode == evaluation::stable, stable::surface_frame<T, Q>, exact::surface_frame<T, Q>>;

/// The point's frame (unit normal, view vector, whether both exist, poison), by F's route.
/// given_view: the view vector for view_model::given (not read otherwise).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr frame_t<F, T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                            const glm::vec<3, T, Q>& given_view, const environment<T, Q>& env,
                                            mask_t<T> front_facing)
{
    if constexpr (F.mode == evaluation::stable) return stable::prepare<F>(position, normal, given_view, env, front_facing);
    else return exact::prepare<F>(position, normal, given_view, env, front_facing);
}

/// One light's terms added to the sums, by F's route (Light: a light_source, light.hpp, read
/// through light_traits; m: the shininess, T, or exact::lane_shininess<T> / integer_exponent<T> in
/// shade_batch's lanes; visibility: unweighted, or a weight that multiplies f).
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class Exponent, class W = unweighted>
PHONG_INLINE constexpr void add_light(Sums<T, Q>& sums, const frame_t<F, T, Q>& s, const Light& L, const Exponent& m,
                                  W visibility = {})
{
    if constexpr (F.mode == evaluation::stable) stable::add_light<F>(sums, s, L, m, visibility);
    else exact::add_light<F>(sums, s, L, m, visibility);
}

template <class R> struct is_std_array : std::false_type {};
template <class X, std::size_t N> struct is_std_array<std::array<X, N>> : std::true_type {};

/// Checks one light against validate(): a compile error in constant evaluation, an assertion in
/// debug builds, nothing under NDEBUG (not even evaluated). Done as the light is shaded, so a
/// single-pass range of lights is read once. Every light is checked as the light<U> it stands for
/// (to_light: a copy, in debug builds and constant evaluation only).
template <class Light>
PHONG_INLINE constexpr void check_light([[maybe_unused]] const Light& L)
{
    if constexpr (std::is_floating_point_v<light_scalar_t<Light>>) {
        if (!value_checks_on()) return;
        const validation v = phong::validate(phong::to_light(L));
        require(static_cast<bool>(v), v.message());
    }
}

/// Checks one weight of weighted(): finite and >= 0 (a negative or NaN weight would give a
/// negative or NaN colour). As check_light: a compile error in constant evaluation, the handler
/// in debug builds, nothing under NDEBUG.
template <class W>
PHONG_INLINE constexpr void check_weight([[maybe_unused]] W weight)
{
    if constexpr (std::is_floating_point_v<W>) {
        if (!value_checks_on()) return;
        require(finite_non_negative(weight), "phong::weighted: weights[i] must be finite and >= 0");
    }
}

template <class R> struct is_masked : std::false_type {};
template <class R> struct is_masked<masked_lights<R>> : std::true_type {};
template <class R> struct is_weighted : std::false_type {};
template <class R, class W> struct is_weighted<weighted_lights<R, W>> : std::true_type {};

/// The range a light list iterates: the list itself, or the one inside masked() / weighted().
template <class R> struct iterated_range { using type = R; };
template <class R> struct iterated_range<masked_lights<R>> { using type = std::remove_cvref_t<R>; };
template <class R, class W> struct iterated_range<weighted_lights<R, W>> { using type = std::remove_cvref_t<R>; };

/// What shade<F> takes as lights: a range (masked() and weighted() ones too) whose elements are
/// light_sources (light<T>, or a type with a light_traits specialization).
/// (std::begin, not std::ranges: clang++ 14 with libstdc++ cannot compile its range concepts.)
template <class R> using list_element_t = decltype(*std::begin(std::declval<R&>()));
template <class Lights>
concept light_list = requires { typename list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>; } &&
                     light_source<list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>>;
/// What shade_incident<F> takes as lights: a range (masked() too) of incident_light_sources
/// (light_traits without a position: shade_incident reads each light's direction from its incident).
template <class Lights>
concept incident_light_list = requires { typename list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>; } &&
                              incident_light_source<list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>>;

/// F without its specular term.
template <features F>
inline constexpr features without_specular = F.with_specular(specular_model::none);

/// The lights of a std::array, unrolled at compile time (each_light; a function rather than a
/// lambda, so that it carries the same inlining attribute as every step of the light loop). An
/// empty array reads none of its arguments.
template <features F, class Sums, class Frame, class Lights, class M, std::size_t... I>
PHONG_INLINE constexpr void each_array_light([[maybe_unused]] Sums& sums, [[maybe_unused]] const Frame& s,
                                             [[maybe_unused]] const Lights& lights, [[maybe_unused]] M m, std::index_sequence<I...>)
{
    ((check_light(lights[I]), detail::add_light<F>(sums, s, lights[I], m, unweighted{})), ...);
}

/// check_light(L) where Check (shade_batch checks its lights once per call, not per point).
template <bool Check, class Light>
PHONG_INLINE constexpr void check_light_if(const Light& L)
{
    if constexpr (Check) check_light(L);
    else (void)L;
}

/// Every light's terms added to the sums: a std::array unrolled at compile time, a masked or
/// weighted list (visibility.hpp), or any input range of lights (views included). Check: each
/// light checked against validate() as it is shaded (check_light; false: checked by the caller).
template <features F, bool Check = true, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Frame,
          class Lights>
PHONG_INLINE constexpr void each_light(Sums<T, Q>& sums, const Frame& s, Lights&& lights, T m) // Frame: frame_t<F, T, Q>
{
    using R = std::remove_cvref_t<Lights>;
    if constexpr (is_std_array<R>::value) {
        each_array_light<F>(sums, s, lights, m, std::make_index_sequence<std::tuple_size_v<R>>{});
    } else if constexpr (is_masked<R>::value) {
        std::uint64_t bits = lights.mask;
        for (auto&& L : lights.lights) {
            check_light_if<Check>(L);
            if (bits & 1u) detail::add_light<F>(sums, s, L, m, unweighted{});
            bits >>= 1;
        }
    } else if constexpr (is_weighted<R>::value) {
        // A weight for every light: once per call where the list has a size, else per light.
        constexpr bool sized = requires { std::size(lights.lights); };
        constexpr const char* too_few = "phong::weighted: fewer weights than lights";
        if constexpr (sized)
            if (!within_bounds(std::size(lights.lights) <= lights.weights.size(), too_few)) return;
        std::size_t i = 0;
        for (auto&& L : lights.lights) {
            if constexpr (!sized)
                if (!within_bounds(i < lights.weights.size(), too_few)) return;
            check_light_if<Check>(L);
            const auto weight = lights.weights[i++];
            check_weight(weight);
            if (weight != 0) detail::add_light<F>(sums, s, L, m, weight); // 0: the light is not seen
        }
    } else if constexpr (std::is_floating_point_v<T>) {
        // The same loop twice, so each copy is compiled knowing whether the point has a normal
        // and a view vector (g++ does not unswitch it by itself).
        if (s.defined) {
            for (auto&& L : lights) check_light_if<Check>(L), detail::add_light<F>(sums, s, L, m, unweighted{});
        } else {
            for (auto&& L : lights) check_light_if<Check>(L), detail::add_light<F>(sums, s, L, m, unweighted{});
        }
    } else {
        for (auto&& L : lights) detail::add_light<F>(sums, s, L, m, unweighted{});
    }
}

/// Every light's terms added to the sums (each_light; Sums: light_sums, or folded_sums in
/// shade_batch with one material). A point without a view vector (at the
/// eye, or a zero given v) keeps its diffuse term, which does not need v, and has no specular
/// term: scalars run it with F's specular term removed (no per-light test), SIMD lanes mask it.
template <features F, bool Check = true, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Lights>
PHONG_INLINE constexpr void add_lights(Sums<T, Q>& sums, const frame_t<F, T, Q>& s, Lights&& lights, T m)
{
    if constexpr (F.specular != specular_model::none && std::is_floating_point_v<T>) {
        if (s.defined && !s.sees_viewer) [[unlikely]] {
            constexpr features G = without_specular<F>; // a local constant: nvcc 13 cannot take the variable template as an argument
            each_light<G, Check>(sums, s, static_cast<Lights&&>(lights), m);
            return;
        }
    }
    each_light<F, Check>(sums, s, static_cast<Lights&&>(lights), m);
}

} // namespace phong::detail
