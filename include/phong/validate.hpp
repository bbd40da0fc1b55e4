// phong: the result type of validate(...) and the checks shared by light.hpp and material.hpp.
// SPDX-License-Identifier: MIT
#pragma once

#include "detail/config.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <limits>

namespace phong {

/// The result of validate(...): empty when the parameters are in the model's domain, else the
/// first problem found, as a message naming the field.
struct validation {
    const char* error = nullptr;
    PHONG_INLINE constexpr explicit operator bool() const { return error == nullptr; }
    PHONG_INLINE constexpr const char* message() const { return error ? error : "ok"; }
};

namespace detail {

// Comparisons only: inf - inf (the usual x - x == 0 test) is not a constant expression, so that
// test made validate() unusable in constant evaluation for infinite parameters. NaN compares false.
template <class T> PHONG_INLINE constexpr bool finite(T x)
{
    return x >= std::numeric_limits<T>::lowest() && x <= std::numeric_limits<T>::max();
}
template <class T> PHONG_INLINE constexpr bool finite_non_negative(T x) { return finite(x) && x >= T(0); }
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr bool finite_non_negative(const glm::vec<L, T, Q>& v)
{
    for (glm::length_t k = 0; k < L; ++k)
        if (!finite_non_negative(v[k])) return false;
    return true;
}
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr bool finite(const glm::vec<L, T, Q>& v)
{
    for (glm::length_t k = 0; k < L; ++k)
        if (!finite(v[k])) return false;
    return true;
}

} // namespace detail
} // namespace phong
