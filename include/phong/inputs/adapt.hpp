// phong: a renderer's own 3-vector type as the glm::vec<3, T> that phong takes (vec3_of), through
// a specialization point like light_traits.
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/config.hpp"

#include <glm/vec3.hpp>

#include <type_traits>
#include <utility>

namespace phong {

/// How vec3_of reads a renderer's vector type V: specialize with
///   static T x(const V&), y(const V&), z(const V&)   (T: float or double)
/// for a type that has neither members x, y, z nor operator[] (those are read without one).
template <class V> struct vector_traits {};

namespace detail {
template <class V>
concept has_vector_traits = requires(const V& v) {
    vector_traits<V>::x(v);
    vector_traits<V>::y(v);
    vector_traits<V>::z(v);
};
template <class V>
concept has_xyz = requires(const V& v) {
    v.x;
    v.y;
    v.z;
};
template <class V>
concept has_index = requires(const V& v) { v[0]; };
} // namespace detail

/// v as a glm::vec<3, T>: (vector_traits<V>::x(v), ::y(v), ::z(v)) where specialized, else
/// (v.x, v.y, v.z), else (v[0], v[1], v[2]); T is the components' type (float, double; no
/// conversion). The copy is inlined (PHONG_INLINE): the components stay in the registers they are
/// in, so the call costs nothing in optimized code (tests/inlining/check.sh compares the
/// instructions of one shading loop written with glm::vec3 and with a renderer's own vector: the
/// same count). Pre: V has three components.
template <class V>
PHONG_INLINE constexpr auto vec3_of(const V& v)
{
    if constexpr (detail::has_vector_traits<V>) {
        using T = std::remove_cvref_t<decltype(vector_traits<V>::x(v))>;
        return glm::vec<3, T>(vector_traits<V>::x(v), vector_traits<V>::y(v), vector_traits<V>::z(v));
    } else if constexpr (detail::has_xyz<V>) {
        using T = std::remove_cvref_t<decltype(v.x)>;
        return glm::vec<3, T>(v.x, v.y, v.z);
    } else {
        static_assert(detail::has_index<V>, "phong::vec3_of: V needs members x, y, z, operator[], or a phong::vector_traits specialization");
        using T = std::remove_cvref_t<decltype(v[0])>;
        return glm::vec<3, T>(v[0], v[1], v[2]);
    }
}

} // namespace phong
