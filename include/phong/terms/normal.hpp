// phong: the shading normal: two-sided negation and the normal matrix.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/vector.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <type_traits>

#include "../core/diagnostics_push.hpp"

namespace phong {

namespace detail {
/// The sign that faces n toward the viewer: -1 where n.v < 0, else 1.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T viewer_facing_sign(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& v)
{
    return detail::select(detail::dot(n, v) < T(0), T(-1), T(1));
}
} // namespace detail

/// classic Phong's conditional negation (two-sided lighting decided by the view):
///   n' = dot(n, v) < 0 ? -n : n
/// so the normal faces the viewer. Edge: dot(n, v) = 0 or n = 0 keeps n; NaN keeps n.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> face_viewer(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& v)
{
    return n * detail::viewer_facing_sign(n, v);
}

namespace detail {
/// Two-sided lighting decided by the caller (e.g. gl_FrontFacing): n' = front_facing ? n : -n.
/// Edge: any n (zero, NaN) is passed through, negated or not.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> face_flag(const glm::vec<3, T, Q>& n, bool front_facing)
{
    return front_facing ? n : -n;
}
} // namespace detail

namespace detail {
/// The cofactor matrix cof(M) = det(M) M^{-T}, columns (b x c, c x a, a x b) for M's columns a, b, c:
/// cof(M) n is normal to the surface M x for every M, even singular (collapsed: 0). A mirror
/// (det < 0) flips outward normals inward (use normal_matrix_inverse_transpose); normalize after.
/// Pre: the products of two entries of M finite (else inf - inf gives NaN).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::mat<3, 3, T, Q> normal_matrix_cofactor(const glm::mat<3, 3, T, Q>& M)
{
    const glm::vec<3, T, Q> a = M[0], b = M[1], c = M[2];
    return glm::mat<3, 3, T, Q>(detail::cross(b, c), detail::cross(c, a), detail::cross(a, b));
}

/// The classic normal matrix (GLSL's NormalMatrix): (M^{-1})^T = cof(M) / det(M), right for every
/// invertible M, mirrors included ((M^{-T} n) . (M y) = n . y).
/// Pre: as normal_matrix_cofactor. Edge: det(M) = 0 gives the cofactor; where 1 / det overflows,
/// cof(M) sign(det) (direction and orientation, not scale). Never NaN for finite M.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::mat<3, 3, T, Q> normal_matrix_inverse_transpose(const glm::mat<3, 3, T, Q>& M)
{
    const glm::mat<3, 3, T, Q> cof = detail::normal_matrix_cofactor(M);
    const T det = detail::dot(M[0], cof[0]); // a . (b x c)
    if (det == T(0)) return cof;
    T inv = T(1) / det; // GLM's matrix operators are not constexpr: scale column-wise
    if (inv - inv != T(0)) inv = det < T(0) ? T(-1) : T(1); // 1/det overflowed: inf * 0 would give NaN
    return glm::mat<3, 3, T, Q>(cof[0] * inv, cof[1] * inv, cof[2] * inv);
}
} // namespace detail

/// GLSL's NormalMatrix for a model-view matrix: normal_matrix_inverse_transpose of its upper 3x3
/// (translation ignored; same pre and edges).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::mat<3, 3, T, Q> normal_matrix(const glm::mat<4, 4, T, Q>& model_view)
{
    const glm::mat<3, 3, T, Q> upper{glm::vec<3, T, Q>(model_view[0]), glm::vec<3, T, Q>(model_view[1]),
                                     glm::vec<3, T, Q>(model_view[2])};
    return detail::normal_matrix_inverse_transpose(upper);
}

/// n' = normalize(N n), N a normal matrix (normal_matrix, not the model matrix; GLSL's
/// tnorm = normalize(NormalMatrix * VertexNormal)). Edge: a zero result stays 0; overflow is
/// avoided by exact rescaling; NaN or inf in N or n: NaN components.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> transform_normal(const glm::mat<3, 3, T, Q>& N, const glm::vec<3, T, Q>& n)
{
    glm::vec<3, T, Q> r = N[0] * n.x + N[1] * n.y + N[2] * n.z;
    if constexpr (std::is_floating_point_v<T>) {
        if (!(detail::max_abs(r) <= detail::largest<T>())) [[unlikely]] { // overflow (or NaN input, which stays NaN)
            const T s = detail::math_traits<T>::inverse_pow2_scale(
                detail::max(detail::max(detail::max_abs(N[0]), detail::max_abs(N[1])), detail::max_abs(N[2])));
            const glm::vec<3, T, Q> m = detail::rescaled(n);
            r = (N[0] * s) * m.x + (N[1] * s) * m.y + (N[2] * s) * m.z;
        }
    }
    return detail::normalize(r);
}

} // namespace phong
#include "../core/diagnostics_pop.hpp"
