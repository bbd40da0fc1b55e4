// phong: the per-light steps every evaluation route shares: f_i(Q) (attenuation and spot), the
// ambient and diffuse sums, and the sums themselves.
// SPDX-License-Identifier: MIT
#pragma once

#include "../terms/attenuation.hpp"
#include "../inputs/environment.hpp"
#include "../inputs/features.hpp"
#include "../inputs/light.hpp"
#include "../terms/normal.hpp"

#include <type_traits>

namespace phong::detail {

/// Per-light sums, weighted by f; the material multiplies them once at the end (finish).
template <class T, glm::qualifier Q>
struct light_sums {
    glm::vec<3, T, Q> ambient{T(0)};
    glm::vec<3, T, Q> diffuse{T(0)};
    glm::vec<3, T, Q> specular{T(0)};
};

/// shade_batch's sums with one material: the material folded into the lights once per call, so
/// every term goes into one rgb (three accumulators in registers, not nine; no products in finish).
template <class T, glm::qualifier Q>
struct folded_sums {
    glm::vec<3, T, Q> total{T(0)};
};

/// Which sum a term goes to: its own in light_sums, the one total in folded_sums.
enum class term_kind : unsigned char { ambient, diffuse, specular };
template <term_kind K, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q>& sum_of(light_sums<T, Q>& sums)
{
    if constexpr (K == term_kind::ambient) return sums.ambient;
    else if constexpr (K == term_kind::diffuse) return sums.diffuse;
    else return sums.specular;
}
template <term_kind K, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q>& sum_of(folded_sums<T, Q>& sums)
{
    return sums.total;
}

/// A light's vector in the arithmetic type T: the vector itself when it already is (a reference,
/// no copy), else widened exactly (float lights in the stable mode's double arithmetic).
template <class T, glm::length_t N, class U, glm::qualifier Q>
PHONG_INLINE constexpr decltype(auto) in_type(const glm::vec<N, U, Q>& v)
{
    if constexpr (std::is_same_v<U, T>) return (v);
    else return glm::vec<N, T, Q>(v);
}

/// The light's w as F knows it: 1 for positional, 0 for directional lights, else L.position.w.
template <features F, class T, class Light>
PHONG_INLINE constexpr T light_w([[maybe_unused]] const Light& L)
{
    if constexpr (F.lights == light_kind::positional) return T(1);
    else if constexpr (F.lights == light_kind::directional) return T(0);
    else return T(position_of(L).w);
}

/// x * 0 is 0 for finite x and NaN for NaN or inf: the NaN policy's poison of a point (its
/// position, normal, and the view input F reads: the given view vector or the eye point).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr T poison_of(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                               [[maybe_unused]] const glm::vec<3, T, Q>& given_view, [[maybe_unused]] const environment<T, Q>& env)
{
    const glm::vec<3, T, Q> zero(T(0));
    T poison = detail::dot(position, zero) + detail::dot(normal, zero);
    if constexpr (F.view == view_model::eye_point) poison += detail::dot(glm::vec<4, T, Q>(env.eye), glm::vec<4, T, Q>(T(0)));
    if constexpr (F.view == view_model::given) poison += detail::dot(given_view, zero);
    return poison;
}

/// The weight of a light that is fully visible: no multiplication at all.
struct unweighted {};

/// Two-sided lighting: the sign that faces the normal n toward the viewer (or the caller's flag).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr T facing_sign(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& v, mask_t<T> front_facing)
{
    if constexpr (F.two_sided == facing::view) return viewer_facing_sign(n, v);
    else return detail::select(front_facing, T(1), T(-1));
}

/// f_i(Q) = attenuation(distance) * spot(l) * visibility: the light's weight at the point.
/// distance = |L.xyz - Q|, read only with attenuation (directional lights: none); l = the unit
/// light vector (0 if none), read only with a spot; visibility: unweighted or a weight in [0, 1].
/// LightScalar: the light's own scalar type, whose attenuation floor applies, so float lights
/// shaded in double give float's formula (a light at Q: the same large finite value).
template <features F, class T, glm::qualifier Q, class Light, class W, class LightScalar = light_scalar_t<Light>>
PHONG_INLINE constexpr T light_factor([[maybe_unused]] const Light& L, [[maybe_unused]] T distance, [[maybe_unused]] T w,
                                  [[maybe_unused]] const glm::vec<3, T, Q>& l, [[maybe_unused]] W visibility)
{
    using U = light_scalar_t<Light>;
    T f = T(1);
    if constexpr (F.attenuation != attenuation_model::none && F.lights != light_kind::directional) {
        T fa;
        decltype(auto) a = attenuation_of(L);
        // The larger floor of T's and the light's: float lights shaded in double get float's formula.
        using S = scalar_t<LightScalar>;
        using Floor = std::conditional_t<(double(attenuation_denominator_min<S>) > double(attenuation_denominator_min<scalar_t<T>>)), S, scalar_t<T>>;
        if constexpr (F.attenuation == attenuation_model::polynomial)
            fa = phong::attenuation_polynomial<T, Floor>(distance, T(a.constant), T(a.linear), T(a.quadratic));
        else
            fa = phong::attenuation_windowed<T, Floor>(distance, T(a.range));
        if constexpr (F.lights == light_kind::any) f = detail::select(w > T(0), fa, T(1));
        else f = fa;
    }
    if constexpr (F.spot != spot_model::none) {
        // validate accepts an axis within 1e-3 of unit length, and a float axis is unit only to
        // float precision: normalized, so the wider route does not carry that rounding.
        decltype(auto) cone = spot_of(L);
        glm::vec<3, T, Q> s(cone.direction);
        // A zero axis is no cone (spot_cone's convention: zero spot fields light the point).
        const mask_t<T> has_cone = detail::dot(s, s) > T(0);
        if constexpr (std::is_same_v<U, T>) s = detail::normalize_unscaled(s); // |s| within 1e-3 of 1: in range
        else s = detail::normalize(s);
        T spot;
        if constexpr (F.spot == spot_model::opengl) spot = phong::spot_opengl(l, s, T(cone.exponent), T(cone.cos_cutoff));
        else if constexpr (F.spot == spot_model::smooth) spot = phong::spot_smooth(l, s, T(cone.cos_inner), T(cone.cos_outer));
        else spot = phong::spot_linear(l, s, T(cone.cos_inner), T(cone.cos_outer));
        f = f * detail::select(has_cone, spot, T(1));
    }
    if constexpr (!std::is_same_v<W, unweighted>) f = f * T(visibility);
    return f;
}

/// The light's ambient term: La_i f (or La_i, without features::attenuate_ambient).
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light>
PHONG_INLINE constexpr void add_ambient(Sums<T, Q>& sums, [[maybe_unused]] const Light& L, [[maybe_unused]] T f)
{
    if constexpr (F.light_ambient) {
        if constexpr (F.attenuate_ambient) sum_of<term_kind::ambient>(sums) += in_type<T>(ambient_of(L)) * f;
        else sum_of<term_kind::ambient>(sums) += in_type<T>(ambient_of(L));
    }
}

/// Whether a lit pair needs n.l > 0: with the specular gate, and without a specular term (where
/// max(n.l, 0) says the same).
template <features F> inline constexpr bool gated = F.specular_gate || F.specular == specular_model::none;

/// The diffuse term Ld_i f max(n.l, 0) of a lit pair (on: the lanes that are lit; gated: on
/// already implies n.l > 0).
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light>
PHONG_INLINE constexpr void add_diffuse(Sums<T, Q>& sums, const Light& L, T f, T nl, [[maybe_unused]] mask_t<T> on)
{
    const T lambert = gated<F> ? nl : detail::max(nl, T(0));
    glm::vec<3, T, Q>& sum = sum_of<term_kind::diffuse>(sums);
    if constexpr (std::is_floating_point_v<T>) sum += in_type<T>(diffuse_of(L)) * (f * lambert);
    else sum += in_type<T>(diffuse_of(L)) * (f * detail::select(on, lambert, T(0)));
}

} // namespace phong::detail
