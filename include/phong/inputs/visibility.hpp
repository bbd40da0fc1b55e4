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

/// The lights whose bit is set in `visible` (bit i for the i-th light), for shade<F>: a light
/// whose bit is clear is skipped entirely, exactly as if it were not in the list (its ambient
/// term too). Nothing is copied: an lvalue list is held by reference (use the result within the
/// list's lifetime, as in shade<F>(..., masked(lights, bits), ...)), an rvalue one (a view) is moved in.
/// Pre: at most 64 lights (bits past the list are ignored; lights past bit 63 are not seen).
template <class Lights>
PHONG_INLINE constexpr detail::masked_lights<Lights> masked(Lights&& lights, std::uint64_t visible)
{
    return {static_cast<Lights&&>(lights), visible};
}

/// The lights weighted by `weights` (weights[i] for the i-th light), for shade<F>: light i's
/// f_i (attenuation times spot) is multiplied by weights[i] (soft shadows, partial occluders), so
/// every term of that light, its ambient term included, scales by it; a weight 0 skips the light
/// (the same as removing it), 1 leaves it as it is.
/// Pre: weights.size() >= the number of lights (debug builds report a shorter span, "phong::weighted:
/// fewer weights than lights"; in every build nothing is read past it: no light is shaded then, or
/// for a light range without a size the lights past the weights are not); each weight finite and >= 0 (checked in debug builds,
/// the message naming weights[i]). Weights in
/// [0, 1] are visibilities; one above 1 brightens the light, as a stronger light would.
/// Held as masked() holds it.
template <class Lights, class T>
PHONG_INLINE constexpr detail::weighted_lights<Lights, T> weighted(Lights&& lights, std::span<const T> weights)
{
    return {static_cast<Lights&&>(lights), weights};
}

} // namespace phong
