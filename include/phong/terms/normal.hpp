// phong: the shading normal: two-sided negation and the normal matrix.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/vector.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <type_traits>

namespace phong {

namespace detail {
/// The sign that faces n toward the viewer: -1 where n.v < 0, else 1 (face_viewer, and
/// shade<F>'s facing::view).
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
/// The cofactor matrix of the linear map M (the adjugate transposed): cof(M) = det(M) M^{-T},
/// columns (b x c, c x a, a x b) for M's columns a, b, c.
/// Carries normals: n' = cof(M) n is normal to the transformed surface M x for every M, even a
/// singular one (det = 0: a sphere squashed to a disk still gets the disk's normal; where the
/// surface collapses to a curve or a point, n' = 0). Orientation: det > 0 keeps outward normals
/// outward; a mirror (det < 0) flips them inward, so use it where only the normal's line matters
/// (two-sided shading, face_viewer) or multiply by sign(det); for outward normals under mirrors
/// use normal_matrix_inverse_transpose. Scale is det-dependent; normalize afterwards.
/// Pre: the products of two entries of M finite (else inf - inf gives NaN).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::mat<3, 3, T, Q> normal_matrix_cofactor(const glm::mat<3, 3, T, Q>& M)
{
    const glm::vec<3, T, Q> a = M[0], b = M[1], c = M[2];
    return glm::mat<3, 3, T, Q>(detail::cross(b, c), detail::cross(c, a), detail::cross(a, b));
}

/// The classic normal matrix (GLSL's NormalMatrix): (M^{-1})^T = cof(M) / det(M).
/// Right for every invertible M, mirrors included (outward normals stay outward): for a surface
/// point x with outward normal n, (M^{-T} n) . (M y) = n . y for every vector y, so tangents stay
/// orthogonal and the outward side stays positive. the ray tracer model's "m = M m'" is right only with this
/// matrix for its M; the object's transform itself (M m') tilts normals under non-uniform scale.
/// Pre: as normal_matrix_cofactor. Edge: det(M) = 0 (or a det that underflows to 0) has no
/// inverse; the cofactor is returned instead (the right direction up to sign, finite). When
/// 1 / det overflows (|det| below about 1 / max, e.g. diag(1e-20, 1e-20, 1) in float),
/// cof(M) sign(det) is returned: the direction and orientation of M^{-T} n, not its scale.
/// Never NaN for finite M within the precondition.
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

/// GLSL's NormalMatrix for a model-view matrix: the inverse transpose of its upper 3x3
/// (translation ignored). Pre and edges: those of normal_matrix_inverse_transpose (a singular
/// upper 3x3 gives its cofactor matrix; never NaN for finite entries whose pairwise products are finite).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::mat<3, 3, T, Q> normal_matrix(const glm::mat<4, 4, T, Q>& model_view)
{
    const glm::mat<3, 3, T, Q> upper{glm::vec<3, T, Q>(model_view[0]), glm::vec<3, T, Q>(model_view[1]),
                                     glm::vec<3, T, Q>(model_view[2])};
    return detail::normal_matrix_inverse_transpose(upper);
}

/// n' = normalize(N n): a normal carried by a normal matrix N (the ray tracer model's m = M m' with M the
/// transpose of the inverse transform, the GLSL ADS shader's tnorm = normalize(NormalMatrix * VertexNormal)).
/// N should come from normal_matrix / normal_matrix_inverse_transpose (or the cofactor, see
/// there), not be the model matrix itself. Edge: a zero result stays 0 (never NaN for finite
/// input); where N n overflows, N and n are first scaled by powers of two (exact: the same
/// direction). NaN or inf in N or n: NaN components.
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
