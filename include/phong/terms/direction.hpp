// phong: the one homogeneous direction rule, shared by light directions and view vectors.
// SPDX-License-Identifier: MIT
#pragma once

#include "../inputs/features.hpp"
#include "../core/vector.hpp"

#include <limits>

namespace phong {

namespace detail {
/// The homogeneous rule's difference d = P.xyz - P.w Q; K fixes w at compile time when known
/// (positional: P.xyz - Q; directional: P.xyz). The one place the rule is written.
template <light_kind K = light_kind::any, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> homogeneous_difference(const glm::vec<3, T, Q>& xyz, [[maybe_unused]] T w,
                                                            [[maybe_unused]] const glm::vec<3, T, Q>& point)
{
    if constexpr (K == light_kind::directional) return xyz;
    else if constexpr (K == light_kind::positional) return xyz - point;
    else return xyz - point * w;
}

/// The unnormalized view vector for view model V: -Q, the given vector, E.xyz, or E.xyz - E.w Q;
/// each route normalizes it in its own arithmetic.
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
///   direction = normalize(P.xyz - P.w Q)
///   distance  = |P.xyz - P.w Q| / P.w for P.w > 0, +inf for P.w = 0.
/// Lights (w = 1 positional, w = 0 directional) and eyes alike, no branch on w.
/// Pre: P.w >= 0, finite. Edge: P at Q (w > 0) gives direction 0, distance 0; P.xyz = 0 with
/// w = 0 gives direction 0, distance +inf; an overflowing difference is taken from the halves
/// (still a unit direction). NaN or inf in P or Q: NaN components.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr detail::direction_and_distance<T, Q> toward(const glm::vec<4, T, Q>& P, const glm::vec<3, T, Q>& point)
{
    const glm::vec<3, T, Q> xyz(P.x, P.y, P.z);
    const glm::vec<3, T, Q> full = detail::homogeneous_difference(xyz, P.w, point);
    // Halving is exact: the halves' difference has the same direction (taken only on overflow).
    const T scale = detail::select(detail::max_abs(full) > detail::largest<T>(), T(0.5), T(1));
    const glm::vec<3, T, Q> d = detail::homogeneous_difference(xyz * scale, P.w * scale, point);
    const T inf = std::numeric_limits<T>::infinity();
    const T w = detail::select(P.w > T(0), P.w, T(1));
    return {detail::normalize(d), detail::select(P.w > T(0), detail::length(d) / (scale * w), inf)};
}

namespace detail {
/// classic Phong's light direction l_i (unit) from a homogeneous light position L (w = 1 or 0), eye coords.
/// The same as toward(L, Q).direction; see there for domain and edges.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> light_direction(const glm::vec<4, T, Q>& L, const glm::vec<3, T, Q>& point)
{
    return phong::toward(L, point).direction;
}
} // namespace detail

} // namespace phong
