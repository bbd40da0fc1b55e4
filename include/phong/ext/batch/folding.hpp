// phong: one material for every point folded into the lights (La_i ka, Ld_i kd, Ls_i ks) and the
// lights' ambient sum hoisted out of the light loop.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
#include "../simd/math_traits.hpp"
#include "layout.hpp"

#include <cmath>
#include <limits>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

/// The lights' ambient terms La_i f_i do not depend on the point (f_i = 1, or ambient not
/// attenuated): with one material and no masks, shade_batch adds their sum once per call.
template <features F>
inline constexpr bool ambient_hoistable = F.light_ambient && (!F.attenuate_ambient || ((F.attenuation == attenuation_model::none ||
                                                                                       F.lights == light_kind::directional) &&
                                                                                      F.spot == spot_model::none));
/// F as shade_lanes runs it with the ambient hoisted: the loop has no light ambient term (the
/// folded sums start at ka (La + sum_i La_i), shade_points_impl).
template <features F>
inline constexpr features ambient_hoisted = F.with_light_ambient(false);

/// Whether one material can be folded into the lights: every product La_i ka, Ld_i kd, Ls_i ks is
/// 0 exactly or a normal number. An underflowed product would drop a term f_i (up to ~1e38 in float)
/// may scale back to a visible size; an overflowed one would turn a finite colour into inf.
template <class T, glm::qualifier Q>
bool foldable(const material<T, Q>& m, std::span<const light<T, Q>> lights)
{
    const auto fine = [](T a, T b) {
        const T p = a * b;
        return a == T(0) || b == T(0) || (std::abs(p) >= std::numeric_limits<T>::min() && std::abs(p) <= std::numeric_limits<T>::max());
    };
    for (const light<T, Q>& L : lights)
        for (glm::length_t c = 0; c < 3; ++c)
            if (!fine(m.ka[c], L.ambient[c]) || !fine(m.kd[c], L.diffuse[c]) || !fine(m.ks[c], L.specular[c])) return false;
    return true;
}

/// The lights in lanes, splatted once per call; with one material for all points and fold, the
/// material folded into them (La_i ka, Ld_i kd, Ls_i ks: shade_lanes' folded_sums).
template <class V, class T, glm::qualifier Q, class Materials>
std::vector<light<V, Q>> lane_lights_of(std::span<const light<T, Q>> lights, const Materials& materials, [[maybe_unused]] bool fold)
{
    std::vector<light<V, Q>> lanes;
    lanes.reserve(lights.size());
    for (light<T, Q> L : lights) {
        if constexpr (std::is_same_v<Materials, material<T, Q>>)
            if (fold) L.ambient *= materials.ka, L.diffuse *= materials.kd, L.specular *= materials.ks;
        lanes.push_back(splat<V>(L));
    }
    return lanes;
}

/// The environment in lanes. With one material, its ambient is the folded sums' start: emission +
/// ka La, + ka sum_i La_i where hoisted (ambient_hoistable, no masks).
template <features F, class V, class T, glm::qualifier Q, class Materials>
environment<V, Q> lane_environment(const environment<T, Q>& env, const Materials& materials, std::span<const light<T, Q>> lights,
                                   [[maybe_unused]] bool masks, [[maybe_unused]] bool fold)
{
    environment<T, Q> e = env;
    if constexpr (std::is_same_v<Materials, material<T, Q>>) {
        if (!fold) return {splat<V>(e.ambient), splat<V>(e.eye)};
        glm::vec<3, T, Q> ambient(T(0));
        if constexpr (F.scene_ambient) ambient = env.ambient;
        if constexpr (ambient_hoistable<F>) {
            if (!masks) {
                glm::vec<3, T, Q> sum(T(0));
                for (const light<T, Q>& L : lights) sum += L.ambient;
                ambient = F.scene_ambient ? env.ambient + sum : sum;
            }
        }
        glm::vec<3, T, Q> start = materials.ka * ambient;
        if constexpr (F.emission) start = materials.emission + start;
        e.ambient = start;
    }
    return {splat<V>(e.ambient), splat<V>(e.eye)};
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
