// phong: the shading normal: two-sided negation and the normal matrix.
// SPDX-License-Identifier: MIT
#pragma once

#include "vector.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

namespace phong {

/// Seed 000's conditional negation (two-sided lighting decided by the view):
///   n' = dot(n, v) < 0 ? -n : n
/// so the normal faces the viewer. Edge: dot(n, v) = 0 or n = 0 keeps n; NaN keeps n.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> face_viewer(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& v)
{
    return n * phong::select(phong::dot(n, v) < T(0), T(-1), T(1));
}

/// Two-sided lighting decided by the caller (e.g. gl_FrontFacing): n' = front_facing ? n : -n.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> face_flag(const glm::vec<3, T, Q>& n, bool front_facing)
{
    return front_facing ? n : -n;
}

/// The cofactor matrix of the linear map M (the adjugate transposed): cof(M) = det(M) M^{-T},
/// columns (b x c, c x a, a x b) for M's columns a, b, c.
/// Carries normals: n' = cof(M) n is normal to the transformed surface for every M, even a
/// singular one (det = 0: a plane squashed flat still gets its normal). Its orientation follows
/// det(M): a mirror (det < 0) flips n', so for outward normals multiply by sign(det) or use
/// normal_matrix_inverse_transpose. Scale is det-dependent; normalize afterwards.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::mat<3, 3, T, Q> normal_matrix_cofactor(const glm::mat<3, 3, T, Q>& M)
{
    const glm::vec<3, T, Q> a = M[0], b = M[1], c = M[2];
    return glm::mat<3, 3, T, Q>(phong::cross(b, c), phong::cross(c, a), phong::cross(a, b));
}

/// The classic normal matrix (GLSL's NormalMatrix): (M^{-1})^T = cof(M) / det(M).
/// Right for every invertible M, mirrors included (outward normals stay outward).
/// Edge: det(M) = 0 has no inverse; the cofactor is returned instead (the right direction up to
/// sign, finite), so the result is never NaN.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::mat<3, 3, T, Q> normal_matrix_inverse_transpose(const glm::mat<3, 3, T, Q>& M)
{
    const glm::mat<3, 3, T, Q> cof = phong::normal_matrix_cofactor(M);
    const T det = phong::dot(M[0], cof[0]); // a . (b x c)
    if (det == T(0)) return cof;
    const T inv = T(1) / det; // GLM's matrix operators are not constexpr: scale column-wise
    return glm::mat<3, 3, T, Q>(cof[0] * inv, cof[1] * inv, cof[2] * inv);
}

/// GLSL's NormalMatrix for a model-view matrix: the inverse transpose of its upper 3x3.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::mat<3, 3, T, Q> normal_matrix(const glm::mat<4, 4, T, Q>& model_view)
{
    const glm::mat<3, 3, T, Q> upper{glm::vec<3, T, Q>(model_view[0]), glm::vec<3, T, Q>(model_view[1]),
                                     glm::vec<3, T, Q>(model_view[2])};
    return phong::normal_matrix_inverse_transpose(upper);
}

/// n' = normalize(N n): a normal carried by a normal matrix N (seed 001's m = M m', seed 003's
/// tnorm = normalize(NormalMatrix * VertexNormal)). Edge: a zero result stays 0.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> transform_normal(const glm::mat<3, 3, T, Q>& N, const glm::vec<3, T, Q>& n)
{
    return phong::normalize(N[0] * n.x + N[1] * n.y + N[2] * n.z);
}

} // namespace phong
