// phong: what surrounds the shaded point: the scene's ambient light and the eye.
// SPDX-License-Identifier: MIT
#pragma once

#include "detail/config.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace phong {

/// What surrounds the shaded point: the scene's ambient light and the eye.
template <class T, glm::qualifier Q = glm::defaultp>
struct environment {
    glm::vec<3, T, Q> ambient{T(0)}; ///< La (seed 000) = GlobalAmbient (seed 001); read when features::scene_ambient
    /// The eye as a homogeneous point: read for view_model::eye_point (w = 1: a point such as seed
    /// 001's ray start; w = 0: a direction) and view_model::fixed_direction (xyz: toward the viewer).
    /// eye_from_projection(ec_lds) gives it from a projection matrix.
    glm::vec<4, T, Q> eye{T(0), T(0), T(0), T(1)};
};

} // namespace phong
