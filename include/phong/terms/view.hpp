// phong: the view vector v, from the eye point, and the eye point from the projection matrix
// (classic Phong's ec_lds).
// SPDX-License-Identifier: MIT
#pragma once

#include "direction.hpp"

#include <glm/mat4x4.hpp>

namespace phong {

namespace detail {
/// classic Phong, perspective: v = normalize(O - Q), O = (0, 0, 0) the eye in eye coordinates.
/// Edge: Q = O gives v = 0; huge and tiny Q are rescaled (never NaN for finite Q).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_perspective(const glm::vec<3, T, Q>& point)
{
    return detail::normalize(-point);
}

/// classic Phong, orthographic: v = normalize(-M02/M00, -M12/M11, 1), M = the projection matrix (classic Phong
/// 's ec_lds); M02 is row 0, column 2 (GLM's m[2][0]).
/// Pre: M00 != 0 and M11 != 0 (any invertible orthographic matrix), the ratios M02/M00 and
/// M12/M11 finite. Edge: M00 or M11 = 0, or a ratio beyond T's range, gives NaN components; use
/// eye_from_projection, which never divides by them.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_orthographic(const glm::mat<4, 4, T, Q>& projection)
{
    return detail::normalize(glm::vec<3, T, Q>(-projection[2][0] / projection[0][0], -projection[2][1] / projection[1][1], T(1)));
}
} // namespace detail

/// The eye as a homogeneous point, derived from the projection matrix M (classic Phong's ec_lds): the common
/// null vector E of rows 0, 1 and 3 of M (the points that project to the centre of every
/// clip-space x, y and to w = 0), computed as a 4-D cross product, then oriented toward the viewer.
///   perspective (glm::perspective, glm::frustum, off-axis):  E = (x, y, z, 1), the centre of projection;
///   orthographic (glm::ortho, oblique):  E = (dx, dy, dz, 0), unit, the direction toward the viewer;
///   glm::ortho gives (0, 0, 1, 0), and in general (-M02/M00, -M12/M11, 1) normalized: classic Phong's formula.
/// Orientation: w > 0 for a finite eye; for w = 0 the direction in which clip depth (row 2)
/// decreases, i.e. toward the near plane (OpenGL's convention; reversed-Z matrices need negating).
/// Then v = toward(E, Q).direction (the same rule as for lights).
/// Pre: rows 0, 1, 3 of M linearly independent (any invertible projection), finite. Edge: a
/// singular M gives E = 0, and then every view vector is 0 (never NaN). Each row is scaled by a
/// power of two first (exact; the null vector does not change), so huge or tiny entries (M times
/// 1e30) give the same E. An eye point beyond T's range (E.xyz / E.w overflows) is returned as
/// its direction from the origin (w = 0), the limit it tends to.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<4, T, Q> eye_from_projection(const glm::mat<4, 4, T, Q>& M)
{
    // Rows of M (GLM is column-major: M[c][r]), each rescaled so that its 3x3 minors neither
    // overflow nor underflow.
    const auto row = [&](int r) { return detail::rescaled(glm::vec<4, T, Q>(M[0][r], M[1][r], M[2][r], M[3][r])); };
    const glm::vec<4, T, Q> a = row(0), b = row(1), c = row(3), depth = row(2);
    // 3x3 determinant of the columns i, j, k of the rows a, b, c.
    const auto det3 = [&](int i, int j, int k) {
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

/// The view vector v at Q for the homogeneous eye E (w = 1: an eye point, as for perspective and
/// for the ray tracer model's ray start; w = 0: a direction toward the viewer, orthographic):
///   v = normalize(E.xyz - E.w Q). Edge: Q at the eye gives 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> view_vector(const glm::vec<4, T, Q>& eye, const glm::vec<3, T, Q>& point)
{
    return phong::toward(eye, point).direction;
}

} // namespace phong
