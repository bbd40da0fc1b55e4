// phong: the one homogeneous direction rule, shared by light directions and view vectors.
// SPDX-License-Identifier: MIT
#pragma once

#include "../inputs/features.hpp"
#include "../core/vector.hpp"

#include <limits>

namespace phong {

namespace detail {
/// The homogeneous rule's difference d = P.xyz - P.w Q (light: L.xyz - L.w Q; eye: E.xyz - E.w Q).
/// K fixes w at compile time when it is known: positional (w = 1: P.xyz - Q, no product) or
/// directional (w = 0: P.xyz, Q not read). The one place the rule is written: toward(), the view
/// vector and every evaluation route's light vector call it.
template <light_kind K = light_kind::any, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> homogeneous_difference(const glm::vec<3, T, Q>& xyz, [[maybe_unused]] T w,
                                                            [[maybe_unused]] const glm::vec<3, T, Q>& point)
{
    if constexpr (K == light_kind::directional) return xyz;
    else if constexpr (K == light_kind::positional) return xyz - point;
    else return xyz - point * w;
}

/// The view vector before normalization, e, for the view model V: -Q (eye_at_origin), the given
/// vector (given), E.xyz (fixed_direction) or E.xyz - E.w Q (eye_point; the homogeneous rule
/// above). The one place the view models are told apart: each route normalizes e in its own
/// arithmetic (the exact mode's unit_of, the stable mode's twofold unit vector, the stable float
/// lanes' double) and calls this on that type. Two routes keep a model of their own, each said
/// where: the exact mode's eye_at_origin (-Q folded into the sign of 1/|Q|) and fixed_direction
/// (E.xyz with |Q|^2 for the NaN test), and the stable mode's eye_point (rescaled, twofold).
template <view_model V, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> unnormalized_view([[maybe_unused]] const glm::vec<3, T, Q>& position,
                                                       [[maybe_unused]] const glm::vec<3, T, Q>& given_view,
                                                       [[maybe_unused]] const glm::vec<3, T, Q>& eye_xyz, [[maybe_unused]] T eye_w)
{
    if constexpr (V == view_model::eye_at_origin) return -position;
    else if constexpr (V == view_model::given) return given_view;
    else if constexpr (V == view_model::eye_point) return homogeneous_difference(eye_xyz, eye_w, position);
    else return eye_xyz;
}
} // namespace detail

namespace detail {
/// A unit direction and the distance along it.
template <class T, glm::qualifier Q = glm::defaultp>
struct direction_and_distance {
    glm::vec<3, T, Q> direction; ///< unit vector, or 0 when undefined
    T distance;                  ///< distance to the point; +inf for a point at infinity (w = 0)
};
} // namespace detail

/// The unit vector from Q toward the homogeneous point P:
///   direction = normalize(P.xyz - P.w Q)      (TeX: \hat l = (P_{xyz} - P_w Q) / |P_{xyz} - P_w Q|)
///   distance  = |P.xyz - P.w Q| / P.w for P.w > 0, +inf for P.w = 0.
/// w = 1 is classic Phong's positional light normalize(L.xyz - Q), w = 0 its directional light
/// normalize(L.xyz); the same rule gives the ray tracer model's e = normalize(eye - P) and the orthographic
/// view vector. One rule, no branch on w for the direction.
/// Pre: P.w >= 0 (a negative w flips the direction), finite. Edge: P at Q (w > 0) gives
/// direction 0 and distance 0; P.xyz = 0 with w = 0 gives direction 0 and distance +inf (still a
/// point at infinity); huge and tiny differences are rescaled (see normalize); a difference that
/// overflows although P and Q are finite (|P.xyz - Q| > max) is taken from the halves, exactly:
/// the direction stays a unit vector, the distance is inf only when the true one exceeds the
/// largest T. NaN or inf in P or Q: NaN components.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr detail::direction_and_distance<T, Q> toward(const glm::vec<4, T, Q>& P, const glm::vec<3, T, Q>& point)
{
    const glm::vec<3, T, Q> xyz(P.x, P.y, P.z);
    const glm::vec<3, T, Q> full = detail::homogeneous_difference(xyz, P.w, point);
    // Halving is exact (for normal numbers), so the halves' difference has the same direction and
    // half the length; it is taken only where the full one overflowed (elsewhere scale = 1: the same bits).
    const T scale = detail::select(detail::max_abs(full) > detail::largest<T>(), T(0.5), T(1));
    const glm::vec<3, T, Q> d = detail::homogeneous_difference(xyz * scale, P.w * scale, point);
    const T inf = std::numeric_limits<T>::infinity();
    const T w = detail::select(P.w > T(0), P.w, T(1));
    return {detail::normalize(d), detail::select(P.w > T(0), detail::length(d) / (scale * w), inf)};
}

namespace detail {
/// classic Phong's light direction \hat l_i from a homogeneous light position L (w = 1 or 0), eye coords.
/// The same as toward(L, Q).direction; see there for domain and edges.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> light_direction(const glm::vec<4, T, Q>& L, const glm::vec<3, T, Q>& point)
{
    return phong::toward(L, point).direction;
}
} // namespace detail

} // namespace phong
