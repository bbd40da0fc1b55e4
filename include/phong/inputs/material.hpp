// phong: a surface material, and validate(material).
// SPDX-License-Identifier: MIT
#pragma once

#include "validate.hpp"

namespace phong {

/// A surface material: classic Phong's ka, kd, ks, m (001's materialamb/diff/spec, f; 003's Ka,
/// Kd, Ks, Shininess), emission, and the alpha appended to the colour.
template <class T, glm::qualifier Q = glm::defaultp>
struct material {
    glm::vec<3, T, Q> ka{T(0.1)};      ///< ambient reflectivity (often ka = kd)
    glm::vec<3, T, Q> kd{T(0.7)};      ///< diffuse reflectivity
    glm::vec<3, T, Q> ks{T(0.2)};      ///< specular reflectivity
    glm::vec<3, T, Q> emission{T(0)};  ///< emitted light, added when features::emission
    T shininess = T(32);               ///< specular exponent m (the ray tracer model: 0..200), >= 0
    T alpha = T(1);                    ///< opacity appended as the 4th channel when features::alpha
};

/// Checks a material against the model's domain. Rejected: negative, NaN or inf coefficients
/// (ka, kd, ks, emission); a shininess that is negative, NaN or inf; alpha outside [0, 1] or NaN.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr validation validate(const material<T, Q>& m)
{
    using detail::finite_non_negative;
    if (!finite_non_negative(m.ka)) return {"material.ka: negative, NaN or inf"};
    if (!finite_non_negative(m.kd)) return {"material.kd: negative, NaN or inf"};
    if (!finite_non_negative(m.ks)) return {"material.ks: negative, NaN or inf"};
    if (!finite_non_negative(m.emission)) return {"material.emission: negative, NaN or inf"};
    if (!finite_non_negative(m.shininess)) return {"material.shininess: must be finite and >= 0"};
    if (!(detail::finite_non_negative(m.alpha) && m.alpha <= T(1))) return {"material.alpha: must be in [0, 1]"};
    return {};
}

} // namespace phong
