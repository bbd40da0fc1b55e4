// phong: which lights a point sees: a light list with a visibility mask or per-light weights, so
// that a renderer's shadow test does not rebuild the light list per point.
// SPDX-License-Identifier: MIT
#pragma once

#include "detail/config.hpp"

#include <cstdint>
#include <ranges>
#include <span>

namespace phong {

/// A light list with a visibility mask: bit i set means light i is seen. See masked().
template <class Lights>
struct masked_lights {
    Lights lights;      ///< a view of the renderer's lights
    std::uint64_t mask; ///< bit i: light i (in iteration order) is visible
};

/// A light list with one visibility weight per light. See weighted().
template <class Lights, class T>
struct weighted_lights {
    Lights lights;             ///< a view of the renderer's lights
    std::span<const T> weights; ///< weights[i] in [0, 1] for light i (in iteration order)
};

/// The lights whose bit is set in `visible` (bit i for the i-th light), for shade<F>: a light
/// whose bit is clear is skipped entirely, exactly as if it were not in the list (its ambient
/// term too). Nothing is copied: `lights` is held as a view (std::views::all).
/// Pre: at most 64 lights (bits past the list are ignored; lights past bit 63 are not seen).
template <std::ranges::viewable_range Lights>
constexpr masked_lights<std::views::all_t<Lights>> masked(Lights&& lights, std::uint64_t visible)
{
    return {std::views::all(static_cast<Lights&&>(lights)), visible};
}

/// The lights weighted by `weights` (weights[i] for the i-th light), for shade<F>: light i's
/// f_i (attenuation times spot) is multiplied by weights[i] (soft shadows, partial occluders), so
/// every term of that light, its ambient term included, scales by it; a weight 0 skips the light
/// (the same as removing it), 1 leaves it as it is.
/// Pre: weights.size() >= the number of lights (checked in debug builds); each weight finite and
/// in [0, 1] (a weight above 1 brightens the light, as a stronger light would).
template <std::ranges::viewable_range Lights, class T>
constexpr weighted_lights<std::views::all_t<Lights>, T> weighted(Lights&& lights, std::span<const T> weights)
{
    return {std::views::all(static_cast<Lights&&>(lights)), weights};
}

} // namespace phong
