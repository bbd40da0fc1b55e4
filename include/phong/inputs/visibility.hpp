// phong: which lights a point sees: a light list with a visibility mask or per-light weights, so
// that a renderer's shadow test does not rebuild the light list per point.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/config.hpp"

#include <cstdint>
#include <span>

namespace phong {

namespace detail {
/// A light list with a visibility mask: bit i set means light i is seen. See masked().
/// Lights is a reference to the caller's list (an lvalue), or the list itself (an rvalue).
template <class Lights>
struct masked_lights {
    Lights lights;      ///< the renderer's lights (any range of lights)
    std::uint64_t mask; ///< bit i: light i (in iteration order) is visible
};

/// A light list with one visibility weight per light. See weighted().
template <class Lights, class T>
struct weighted_lights {
    Lights lights;              ///< the renderer's lights (any range of lights)
    std::span<const T> weights; ///< weights[i] in [0, 1] for light i (in iteration order)
};
} // namespace detail

/// The lights whose bit is set in `visible` (bit i: light i), for shade<F>; a clear bit skips the
/// light entirely (ambient too). An lvalue list is held by reference (use it within the list's
/// lifetime), an rvalue moved in. Pre: at most 64 lights (lights past bit 63 are not seen).
template <class Lights>
PHONG_INLINE constexpr detail::masked_lights<Lights> masked(Lights&& lights, std::uint64_t visible)
{
    return {static_cast<Lights&&>(lights), visible};
}

/// The lights weighted by `weights`, for shade<F>: light i's f_i, so each of its terms (ambient
/// too), is multiplied by weights[i] (soft shadows); 0 skips the light. Held as masked() holds it.
/// Pre: weights.size() >= the number of lights (never read past: debug builds report it, and no
/// light is shaded); each weight finite and >= 0 (debug-checked).
template <class Lights, class T>
PHONG_INLINE constexpr detail::weighted_lights<Lights, T> weighted(Lights&& lights, std::span<const T> weights)
{
    return {static_cast<Lights&&>(lights), weights};
}

} // namespace phong
