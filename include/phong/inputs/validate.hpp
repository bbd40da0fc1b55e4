// phong: the result type of validate(...) and the checks shared by light.hpp and material.hpp.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/config.hpp"
#include "../core/ieee.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <bit>
#include <limits>
#include <type_traits>

namespace phong {

/// The result of validate(...): empty when the parameters are in the model's domain, else the
/// first problem found, as a message naming the field.
struct validation {
    const char* error = nullptr; ///< the first problem found, naming the field; null when valid
    /// Whether the parameters are valid.
    PHONG_INLINE constexpr explicit operator bool() const { return error == nullptr; }
    /// The error message, or "ok".
    PHONG_INLINE constexpr const char* message() const { return error ? error : "ok"; }
};

namespace detail {

// Comparisons (x - x == 0 is not constant for inf) or, for float and double, bits (not folded by -ffinite-math-only).
template <class T> PHONG_INLINE constexpr bool finite(T x)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) return ieee::is_finite(x);
    else return x >= std::numeric_limits<T>::lowest() && x <= std::numeric_limits<T>::max();
}
// The sign by bits too: under DAZ, x >= 0 holds for a negative subnormal x.
template <class T> PHONG_INLINE constexpr bool finite_non_negative(T x)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
        const auto b = std::bit_cast<ieee::bits_of<T>>(x);
        return finite(x) && ((b & ieee::sign_bit<T>) == 0 || b == ieee::sign_bit<T>); // x >= +0, or x = -0
    } else {
        return finite(x) && x >= T(0);
    }
}
/// x is not NaN (+-inf allowed); by bits for float and double, as finite.
template <class T> PHONG_INLINE constexpr bool not_nan(T x)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) return !ieee::is_nan(x);
    else return x == x;
}
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
