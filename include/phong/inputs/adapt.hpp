// phong: a renderer's own 3-vector type to and from glm::vec<3, T> (vec3_of, from_vec3).
// SPDX-License-Identifier: MIT
#pragma once

#include "../core/config.hpp"

#include <glm/vec3.hpp>

#include <concepts>
#include <type_traits>
#include <utility>

namespace phong {

/// How vec3_of reads V and from_vec3 makes one, for a V without members x, y, z or operator[],
/// or not made by V{x, y, z}: static T x(const V&), y(const V&), z(const V&); optional static V make(T, T, T).
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
template <class V, class T>
concept has_make = requires(T t) {
    { vector_traits<V>::make(t, t, t) } -> std::convertible_to<V>;
};
} // namespace detail

/// v as a glm::vec<3, T> (T the components' type): vector_traits<V> where specialized, else
/// (v.x, v.y, v.z), else (v[0], v[1], v[2]). Pre: V has three components.
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

/// c (a colour or vector phong returned) as V: vector_traits<V>::make(c.x, c.y, c.z) where
/// specialized, else V{c.x, c.y, c.z} (no narrowing). An rgba colour passes its xyz.
template <class V, glm::length_t L, class T, glm::qualifier Q>
    requires(L >= 3)
PHONG_INLINE constexpr V from_vec3(const glm::vec<L, T, Q>& c)
{
    if constexpr (detail::has_make<V, T>) {
        return vector_traits<V>::make(c.x, c.y, c.z);
    } else {
        static_assert(requires { V{c.x, c.y, c.z}; },
                      "phong::from_vec3: V is not made by V{x, y, z}: specialize phong::vector_traits<V>::make");
        return V{c.x, c.y, c.z};
    }
}

} // namespace phong
