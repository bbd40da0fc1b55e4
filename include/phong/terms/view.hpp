// phong: the view vector v, from the eye point, and the eye point from the projection matrix
// (classic Phong's ec_lds).
// SPDX-License-Identifier: MIT
#pragma once

#include "direction.hpp"

#include <glm/mat4x4.hpp>

#include "../core/diagnostics_push.hpp"

namespace phong {

namespace detail {
/// classic Phong, perspective: v = normalize(O - Q), O = (0, 0, 0) the eye in eye coordinates.
/// Edge: Q = O gives v = 0; huge and tiny Q are rescaled (never NaN for finite Q).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_perspective(const glm::vec<3, T, Q>& point)
{
    return detail::normalize(-point);
}

/// classic Phong, orthographic: v = normalize(-M02/M00, -M12/M11, 1), M the projection matrix
/// (M02: row 0, column 2, GLM's m[2][0]). Pre: M00, M11 != 0, the ratios finite; else NaN
/// components (eye_from_projection never divides).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_orthographic(const glm::mat<4, 4, T, Q>& projection)
{
    return detail::normalize(glm::vec<3, T, Q>(-projection[2][0] / projection[0][0], -projection[2][1] / projection[1][1], T(1)));
}
} // namespace detail

/// The eye as a homogeneous point from the projection matrix M (classic Phong's ec_lds): the null
/// vector E of M's rows 0, 1, 3 (a 4-D cross product), oriented toward the viewer:
///   perspective:  E = (x, y, z, 1), the centre of projection;
///   orthographic: E = (dx, dy, dz, 0), unit, toward the near plane (reversed-Z: negate).
/// Pre: rows 0, 1, 3 independent, finite. Edge: a singular M gives E = 0 (every v then 0); rows are
/// rescaled exactly; an eye beyond T's range is returned as its direction (w = 0).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<4, T, Q> eye_from_projection(const glm::mat<4, 4, T, Q>& M)
{
    // Rows of M (column-major: M[c][r]), rescaled so the 3x3 minors neither overflow nor underflow.
    const auto row = [&](glm::length_t r) { return detail::rescaled(glm::vec<4, T, Q>(M[0][r], M[1][r], M[2][r], M[3][r])); };
    const glm::vec<4, T, Q> a = row(0), b = row(1), c = row(3), depth = row(2);
    // 3x3 determinant of the columns i, j, k of the rows a, b, c.
    const auto det3 = [&](glm::length_t i, glm::length_t j, glm::length_t k) {
        return a[i] * (b[j] * c[k] - b[k] * c[j]) - a[j] * (b[i] * c[k] - b[k] * c[i]) + a[k] * (b[i] * c[j] - b[j] * c[i]);
    };
    glm::vec<4, T, Q> E(det3(1, 2, 3), -det3(0, 2, 3), det3(0, 1, 3), -det3(0, 1, 2));
    const glm::vec<3, T, Q> E_xyz(E.x, E.y, E.z);
    if (E.w != T(0)) {
        const glm::vec<4, T, Q> centre = E / E.w; // the centre of projection, w = 1
        if (detail::max_abs(glm::vec<3, T, Q>(centre.x, centre.y, centre.z)) <= detail::largest<T>()) return centre;
        return glm::vec<4, T, Q>(detail::normalize(E.w > T(0) ? E_xyz : -E_xyz), T(0)); // beyond T's range
    }
    const glm::vec<3, T, Q> dir = detail::normalize(E_xyz);
    const T depth_rate = depth.x * dir.x + depth.y * dir.y + depth.z * dir.z;
    return glm::vec<4, T, Q>(depth_rate > T(0) ? -dir : dir, T(0));
}

/// The view vector v = normalize(E.xyz - E.w Q) for the homogeneous eye E (w = 1 a point, w = 0 a
/// direction). Edge: Q at the eye gives 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_vector(const glm::vec<4, T, Q>& eye, const glm::vec<3, T, Q>& point)
{
    return phong::toward(eye, point).direction;
}

} // namespace phong
#include "../core/diagnostics_pop.hpp"
