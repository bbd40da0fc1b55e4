// phong: the evaluation route F picks (routes/exact.hpp or routes/stable.hpp), and the one loop over
// a point's lights: a std::array unrolled, a masked or weighted list (visibility.hpp), any input range.
// SPDX-License-Identifier: MIT
#pragma once

#include "../inputs/validate.hpp"
#include "../inputs/visibility.hpp"
#include "exact.hpp"
#include "stable.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include "../core/diagnostics_push.hpp"

namespace phong::detail {

/// The per-point frame of F's evaluation route.
template <features F, class T, glm::qualifier Q>
using frame_t = std::conditional_t<F.mode == evaluation::stable, stable::surface_frame<T, Q>, exact::surface_frame<T, Q>>;

/// The point's frame (unit normal, view vector, whether both exist, poison), by F's route
/// (given_view: read only for view_model::given).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr frame_t<F, T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                            const glm::vec<3, T, Q>& given_view, const environment<T, Q>& env,
                                            mask_t<T> front_facing)
{
    if constexpr (F.mode == evaluation::stable) return stable::prepare<F>(position, normal, given_view, env, front_facing);
    else return exact::prepare<F>(position, normal, given_view, env, front_facing);
}

/// One light's terms added to the sums, by F's route (m: the shininess T, or a lane type in
/// shade_batch; visibility: unweighted, or a weight that multiplies f).
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class Exponent, class W = unweighted>
PHONG_INLINE constexpr void add_light(Sums<T, Q>& sums, const frame_t<F, T, Q>& s, const Light& L, const Exponent& m,
                                  W visibility = {})
{
    if constexpr (F.mode == evaluation::stable) stable::add_light<F>(sums, s, L, m, visibility);
    else exact::add_light<F>(sums, s, L, m, visibility);
}

template <class R> struct is_std_array : std::false_type {};
template <class X, std::size_t N> struct is_std_array<std::array<X, N>> : std::true_type {};

/// check_light's body, out of line (PHONG_DETAIL_OUT_OF_LINE).
template <class Light>
PHONG_DETAIL_OUT_OF_LINE constexpr void validate_light_or_fail(const Light& L)
{
    const validation v = phong::validate(phong::to_light(L));
    require(static_cast<bool>(v), v.message());
}

/// Checks one light against validate() as it is shaded, as the light<U> it stands for: a compile
/// error in constant evaluation, an assertion in debug builds, nothing under NDEBUG.
template <class Light>
PHONG_INLINE constexpr void check_light([[maybe_unused]] const Light& L)
{
    if constexpr (std::is_floating_point_v<light_scalar_t<Light>>) {
        if (value_checks_on()) validate_light_or_fail(L);
    }
}

/// Checks one weight of weighted(): finite and >= 0 (else a negative or NaN colour), as check_light.
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

/// What shade<F> takes as lights: a range (masked() and weighted() ones too) of light_sources
/// (std::begin: clang++ 14 with libstdc++ cannot compile std::ranges' concepts).
template <class R> using list_element_t = decltype(*std::begin(std::declval<R&>()));
template <class Lights>
concept light_list = requires { typename list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>; } &&
                     light_source<list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>>;
/// What shade_incident<F> takes as lights: a range (masked() too) of incident_light_sources.
template <class Lights>
concept incident_light_list = requires { typename list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>; } &&
                              incident_light_source<list_element_t<typename iterated_range<std::remove_cvref_t<Lights>>::type>>;

/// The range a light list iterates (non-const where the list is: a filter view iterates only so).
template <class Lights>
PHONG_INLINE constexpr auto& light_range(Lights& lights)
{
    if constexpr (is_masked<std::remove_cvref_t<Lights>>::value || is_weighted<std::remove_cvref_t<Lights>>::value) return (lights.lights);
    else return (lights);
}

/// each_listed_light without a second range.
struct no_second_range {};

/// The one loop over a light list (SIMD lanes and shade_incident included): visit(L, i, on) for the
/// i-th light in order, on = bit i of masked()'s mask (true otherwise; past bit 63 off). second: a
/// range with an entry per light (weights, incidents) or no_second_range, never read past (every
/// build; within_bounds reports too_few): checked once per call where the range has a size, else
/// per light. PeelFirst: the first light in straight-line code before the loop (shade_incident's
/// -0 sums). A std::array is not visited here: each_array_light unrolls it.
template <bool PeelFirst = false, class Lights, class Second, class Visit>
PHONG_INLINE constexpr void each_listed_light(Lights& lights, [[maybe_unused]] const Second& second,
                                              [[maybe_unused]] const char* too_few, Visit&& visit)
{
    constexpr bool with_second = !std::is_same_v<Second, no_second_range>;
    constexpr bool masked_list = is_masked<std::remove_cvref_t<Lights>>::value;
    constexpr bool sized = requires { std::size(light_range(lights)); };
    if constexpr (with_second && sized)
        if (!within_bounds(std::size(light_range(lights)) <= std::size(second), too_few)) return;
    [[maybe_unused]] std::uint64_t bits = 0;
    if constexpr (masked_list) bits = lights.mask;
    std::size_t i = 0;
    auto it = std::begin(light_range(lights));
    const auto end = std::end(light_range(lights));
    const auto step = [&]() PHONG_DETAIL_LAMBDA_INLINE {
        if constexpr (with_second && !sized)
            if (!within_bounds(i < std::size(second), too_few)) return false;
        if constexpr (masked_list) {
            visit(*it, i, (bits & 1u) != 0);
            bits >>= 1;
        } else {
            visit(*it, i, true);
        }
        return true;
    };
    if constexpr (PeelFirst) {
        if (it == end || !step()) return;
        ++it, ++i;
    }
    for (; it != end; ++it, ++i)
        if (!step()) return;
}

/// F without its specular term.
template <features F>
inline constexpr features without_specular = F.with_specular(specular_model::none);

/// The lights of a std::array, unrolled at compile time (a function, not a lambda, to carry the
/// light loop's inlining attribute). An empty array reads none of its arguments.
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

/// Every light's terms added to the sums (Check: check_light per light; false: the caller checked).
template <features F, bool Check = true, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Frame,
          class Lights>
PHONG_INLINE constexpr void each_light(Sums<T, Q>& sums, const Frame& s, Lights&& lights, T m) // Frame: frame_t<F, T, Q>
{
    using R = std::remove_cvref_t<Lights>;
    if constexpr (is_std_array<R>::value) {
        each_array_light<F>(sums, s, lights, m, std::make_index_sequence<std::tuple_size<R>::value>{});
    } else if constexpr (is_weighted<R>::value) {
        each_listed_light(lights, lights.weights, "phong::weighted: fewer weights than lights",
                          [&](const auto& L, std::size_t i, bool) PHONG_DETAIL_LAMBDA_INLINE {
                              check_light_if<Check>(L);
                              const auto weight = lights.weights[i];
                              check_weight(weight);
                              if (weight != 0) detail::add_light<F>(sums, s, L, m, weight); // 0: the light is not seen
                          });
    } else {
        const auto add = [&](const auto& L, std::size_t, bool on) PHONG_DETAIL_LAMBDA_INLINE {
            check_light_if<Check && std::is_floating_point_v<T>>(L);
            if (on) detail::add_light<F>(sums, s, L, m, unweighted{});
        };
        if constexpr (std::is_floating_point_v<T> && !is_masked<R>::value) {
            // The same loop twice, each compiled knowing whether the point has a normal and a view
            // vector (g++ does not unswitch it).
            if (s.defined) each_listed_light(lights, no_second_range{}, nullptr, add);
            else each_listed_light(lights, no_second_range{}, nullptr, add);
        } else {
            each_listed_light(lights, no_second_range{}, nullptr, add);
        }
    }
}

/// Every light's terms added to the sums (light_sums, or folded_sums). A point without a view
/// vector has no specular term: scalars run F without it, SIMD lanes mask it.
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
#include "../core/diagnostics_pop.hpp"
