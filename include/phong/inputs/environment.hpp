// phong: what surrounds the shaded point: the scene's ambient light and the eye; validate(environment).
// SPDX-License-Identifier: MIT
#pragma once

#include "validate.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace phong {

/// What surrounds the shaded point: the scene's ambient light and the eye.
template <class T, glm::qualifier Q = glm::defaultp>
struct environment {
    glm::vec<3, T, Q> ambient{T(0)}; ///< La (classic Phong) = GlobalAmbient (ray tracer model), >= 0; read when features::scene_ambient
    /// The homogeneous eye, read by view_model::eye_point (w = 1 a point, w = 0 a direction) and
    /// fixed_direction (xyz); eye_from_projection() makes it. w >= 0; NaN or inf gives NaN channels.
    glm::vec<4, T, Q> eye{T(0), T(0), T(0), T(1)};
};

/// Checks an environment against the model's domain. Rejected: a negative, NaN or inf ambient;
/// a finite eye.w < 0. Not rejected: a NaN or inf eye (shade's NaN policy: NaN in every channel).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr validation validate(const environment<T, Q>& e)
{
    if (!detail::finite_non_negative(e.ambient)) return {"environment.ambient: negative, NaN or inf"};
    if (detail::finite(e.eye.w) && e.eye.w < T(0)) return {"environment.eye.w: must be >= 0 (1: a point, 0: a direction)"};
    return {};
}

} // namespace phong
