// phong: the stable evaluation route (features::mode = stable: double, double SIMD lanes, float
// twofold; float's default is routes/exact.hpp in double, float SIMD lanes ext/simd/stable_lanes.hpp).
// Vectors are rescaled by powers of two (every finite input in range); n, l, v (h), n.l and the
// chords are twofold from the exact L.xyz - w Q; the power is (1 - x)^m of the half chord x.
// stable_twofold_above: docs/accuracy.md. Bounds in phong/accuracy.hpp.
// SPDX-License-Identifier: MIT
#pragma once

#include "../terms/direction.hpp"
#include "../terms/specular.hpp"
#include "light_terms.hpp"
#include "../core/twofold.hpp"

#include <limits>
#include <type_traits>

#include "../core/diagnostics_push.hpp"

namespace phong::detail::stable {

/// Per-point quantities, computed once and shared by every light.
template <class T, glm::qualifier Q>
struct surface_frame {
    glm::vec<3, T, Q> position;        ///< Q
    glm::vec<3, T, Q> normal{T(0)};    ///< unit normal after two-sided negation, rounded (0 if undefined)
    glm::vec<3, T, Q> view{T(0)};      ///< unit view vector, rounded (0 if undefined)
    mask_t<T> defined;                 ///< the normal is nonzero and the inputs finite
    mask_t<T> sees_viewer;             ///< the view vector is nonzero (specular can be on)
    T poison;                          ///< 0, or NaN when the point's inputs are not finite
    glm::vec<3, T, Q> normal_scaled;   ///< the normal before its last rounding, rescaled exactly
    T inv_normal_length;               ///< 1 / |normal_scaled|
    glm::vec<3, T, Q> normal_lo{T(0)}; ///< rounding error of normal (normal + normal_lo to O(eps^2))
    glm::vec<3, T, Q> view_lo{T(0)};   ///< rounding error of view
};

/// A vector with the rounding error of its last operation: hi + lo exact.
template <class T, glm::qualifier Q>
struct twofold_vector {
    glm::vec<3, T, Q> hi, lo;
};

/// The homogeneous difference d = P.xyz - w Q (direction.hpp) with its rounding error, so that
/// directions are computed on the exact d: w Q is a rounded product (error by fma), the
/// difference's error by TwoSum.
template <light_kind K, class T, glm::qualifier Q>
PHONG_INLINE constexpr twofold_vector<T, Q> difference_twofold(const glm::vec<3, T, Q>& xyz, T w, const glm::vec<3, T, Q>& point)
{
    twofold_vector<T, Q> d{xyz, glm::vec<3, T, Q>(T(0))};
    if constexpr (K == light_kind::positional) {
        d.hi = xyz - point;
        for (glm::length_t k = 0; k < 3; ++k) d.lo[k] = difference_error(xyz[k], point[k], d.hi[k]);
    } else if constexpr (K == light_kind::any) {
        glm::vec<3, T, Q> p(T(0));
        for (glm::length_t k = 0; k < 3; ++k) p[k] = rounded_product(point[k], w); // not fused into xyz - p
        d.hi = xyz - p;
        for (glm::length_t k = 0; k < 3; ++k) d.lo[k] = difference_error(xyz[k], p[k], d.hi[k]) - detail::fma(w, point[k], -p[k]);
    } else {
        (void)w;
        (void)point;
    }
    return d;
}

/// The per-point frame: n and v twofold from the exact normal and view vector (-Q, the given v,
/// E.xyz - E.w Q), also under unit_inputs (the mode's accuracy rests on them). Apart from
/// exact::prepare because its bits differ: pairs (hi, lo) from rescaled inputs where it rounds once.
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr surface_frame<T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                               const glm::vec<3, T, Q>& given_view, const environment<T, Q>& env,
                                               mask_t<T> front_facing)
{
    using vec3 = glm::vec<3, T, Q>;
    surface_frame<T, Q> s{};
    s.position = position;
    const vec3 eye(env.eye.x, env.eye.y, env.eye.z);
    twofold_vector<T, Q> e{eye, vec3(T(0))};
    if constexpr (F.view != view_model::eye_point) {
        e.hi = detail::unnormalized_view<F.view>(position, given_view, eye, env.eye.w);
    } else {
        // d = E.xyz - E.w Q as 2^(a+b) d = 2^a (E.xyz 2^b) - (E.w 2^a)(Q 2^b), exactly d's direction:
        // 2^b brings the larger of E.xyz and Q to [1, 2), then 2^a the larger of E.xyz 2^b and E.w;
        // scaling up first keeps tiny inputs' bits. A subnormal product's rounding error is inexact,
        // which matters only where d cancels far below its terms (|d| < 2^-900 double, 2^-100
        // float): d is then formed again with both terms scaled by 2^1000 (float 2^120). Otherwise
        // unit_twofold_of gives the unscaled bits; |E.w Q| > max leaves the viewer a direction.
        using S = scalar_t<T>;
        constexpr bool is_float = std::is_same_v<S, float>;
        const T b = math_traits<T>::inverse_pow2_scale(detail::max(detail::max_abs(eye), detail::max_abs(position)));
        const vec3 position_b = position * b;
        const glm::vec<4, T, Q> eye_ab_w_a = detail::rescaled(glm::vec<4, T, Q>(eye * b, T(env.eye.w))); // 2^a (E.xyz 2^b, E.w)
        const vec3 eye_ab(eye_ab_w_a.x, eye_ab_w_a.y, eye_ab_w_a.z);
        const T w_a = eye_ab_w_a.w;
        e = difference_twofold<light_kind::any>(eye_ab, w_a, position_b);
        const mask_t<T> cancelled = detail::max_abs(e.hi) < T(is_float ? S(0x1p-100) : S(0x1p-900));
        if (math_traits<T>::any(cancelled)) {
            // Q from the input: 2^b < 1 may have dropped its subnormal bits, 2^b times the large
            // scale cannot (2^b > 1 only where E.xyz and Q are below 1: then Q 2^b is exact).
            const T up = detail::select(cancelled, T(is_float ? S(0x1p120) : S(0x1p1000)), T(1));
            const mask_t<T> down = b <= T(1);
            const T bu = b * up;
            vec3 position_up(T(0));
            for (glm::length_t k = 0; k < 3; ++k) position_up[k] = detail::select(down, position[k] * bu, position_b[k] * up);
            e = difference_twofold<light_kind::any>(eye_ab * up, w_a, position_up);
        }
    }
    const unit_twofold<T, Q> uv = unit_twofold_of(e.hi, e.lo);
    s.view = uv.hi;
    s.view_lo = uv.lo;
    const unit_twofold<T, Q> un = unit_twofold_of(normal, vec3(T(0)));
    s.normal = un.hi;
    s.normal_lo = un.lo;
    s.normal_scaled = detail::rescaled(normal);
    s.inv_normal_length = un.inv_scaled;
    s.poison = poison_of<F>(position, normal, given_view, env);
    s.defined = detail::dot(s.normal, s.normal) > T(0);
    s.sees_viewer = detail::dot(s.view, s.view) > T(0);
    if constexpr (F.two_sided != facing::none) {
        const T sign = facing_sign<F>(s.normal, s.view, front_facing);
        s.normal = s.normal * sign;
        s.normal_scaled = s.normal_scaled * sign;
        s.normal_lo = s.normal_lo * sign;
    } else {
        (void)front_facing;
    }
    s.defined = math_traits<T>::both(s.defined, s.poison == T(0));
    return s;
}

/// The unit light vector and n.l of one pair: l + l_lo and nl + nl_lo (the lo parts 0 when
/// rounded once), 1/|d| of the rescaled d (0: no direction), and the distance |d|.
template <class T, glm::qualifier Q>
struct light_unit {
    glm::vec<3, T, Q> l, l_lo;
    T nl, nl_lo, inv, length;
};

/// l and n.l to about eps^2 (core/twofold.hpp), from the exact d = hi + lo.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr light_unit<T, Q> light_twofold(const surface_frame<T, Q>& s, const twofold_vector<T, Q>& d)
{
    const unit_twofold<T, Q> u = unit_twofold_of(d.hi, d.lo); // rescaled: any finite nonzero d
    light_unit<T, Q> r{u.hi, u.lo, T(0), T(0), u.inv_scaled, u.length};
    dot_twofold(s.normal, s.normal_lo, u.hi, u.lo, r.nl, r.nl_lo);
    return r;
}

/// l rounded once from d rescaled by a power of two (exact: huge and tiny d survive), and n.l
/// compensated on the exact d = hi + lo and the exact (rescaled) normal.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr light_unit<T, Q> light_rounded_once(const surface_frame<T, Q>& s, const twofold_vector<T, Q>& d)
{
    using vec3 = glm::vec<3, T, Q>;
    const T largest_d = detail::max_abs(d.hi);
    const mask_t<T> in_range = largest_d <= largest<T>(); // an overflowed d has no direction
    const T scale = math_traits<T>::inverse_pow2_scale(detail::select(in_range, largest_d, T(1)));
    vec3 hs(T(0)), ls(T(0));
    for (glm::length_t k = 0; k < 3; ++k) {
        hs[k] = detail::select(in_range, d.hi[k] * scale, T(0));
        ls[k] = detail::select(in_range, d.lo[k] * scale, T(0)); // lo is NaN when d overflowed
    }
    const T hh = detail::dot(hs, hs);
    const T inv = detail::select(hh > T(0), detail::rsqrt(detail::select(hh > T(0), hh, T(1))), T(0));
    T nh, nlo;
    dot_twofold(s.normal_scaled, vec3(T(0)), hs, ls, nh, nlo);
    const T length = detail::select(in_range, detail::sqrt(hh) / scale, T(std::numeric_limits<scalar_t<T>>::infinity()));
    return {hs * inv, vec3(T(0)), (nh + nlo) * (s.inv_normal_length * inv), T(0), inv, length};
}

/// c^m = (1 - x)^m from both roundings of the cosine (core/twofold.hpp's cosine_complement):
/// exp(m log1p(-x)) where x <= 1/2, else pow_unit(c): each the rounding with the smaller effect
/// (x's: m x / (1 - x) eps / 2 relative; c's: m eps / 2, below the power's |y| eps where x > 1/2).
/// A SIMD batch takes the second power only where a lane needs it. Edges: x >= 1 gives 0 (1 for m = 0).
template <class T>
PHONG_INLINE constexpr T power_of_cosine(const cosine_complement<T>& p, T m)
{
    const mask_t<T> near_peak = p.complement <= T(0.5);
    if (math_traits<T>::all(near_peak)) return detail::pow_one_minus(p.complement, m);
    const T far = detail::pow_unit_in_domain(detail::clamp(p.cosine, T(0), T(1)), m); // the power floor (ieee::power_floor_log2)
    if (!math_traits<T>::any(near_peak)) return far;
    return detail::select(near_peak, detail::pow_one_minus(p.complement, m), far);
}

/// The specular factor (1 - x)^m, x = 1 - r.v or 1 - n.h from chords (specular.hpp's once-rounded
/// steps, or core/twofold.hpp's with the cosine itself where small: power_of_cosine).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr T specular_factor(const surface_frame<T, Q>& s, const light_unit<T, Q>& u, bool twofold, T m)
{
    if constexpr (F.specular == specular_model::phong) {
        if (twofold) return power_of_cosine(one_minus_rv(s.normal, s.normal_lo, u.nl, u.nl_lo, u.l, u.l_lo, s.view, s.view_lo), m);
        return detail::pow_one_minus(detail::one_minus_reflection_cosine(s.normal, u.nl, u.l, s.view), m);
    } else {
        if (twofold) return power_of_cosine(one_minus_halfway(s.normal, s.normal_lo, u.l, u.l_lo, s.view, s.view_lo), m);
        return detail::pow_one_minus(detail::one_minus_halfway_cosine(s.normal, u.l, s.view), m);
    }
}

/// One light's terms added to the sums (twofold where any lane needs it). Apart from exact::add_light
/// because its bits differ: d carries its rounding error; l, n.l and the chord are twofold. The
/// shared steps are light_terms.hpp's.
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class W>
PHONG_INLINE constexpr void add_light(Sums<T, Q>& sums, const surface_frame<T, Q>& s, const Light& L, T m, W visibility)
{
    using vec3 = glm::vec<3, T, Q>;
    const T w = light_w<F, T>(L);
    decltype(auto) p = position_of(L);
    const twofold_vector<T, Q> d = difference_twofold<F.lights>(vec3(T(p.x), T(p.y), T(p.z)), w, s.position);

    // Twofold unless stable_twofold_above = M > 0 and no lane's shininess is above M.
    bool twofold = F.stable_twofold_above == 0 ||
                   (F.specular != specular_model::none && math_traits<T>::any(m > T(F.stable_twofold_above)));
    light_unit<T, Q> u = twofold ? light_twofold(s, d) : light_rounded_once(s, d);
    if constexpr (F.specular == specular_model::blinn && F.stable_twofold_above > 0) {
        // l + v nearly cancels (|l + v| < 2^-10): h from once-rounded l and v is noise there.
        const vec3 lv = u.l + s.view;
        if (!twofold && math_traits<T>::any(detail::dot(lv, lv) < T(1.0 / 1048576))) {
            twofold = true;
            u = light_twofold(s, d);
        }
    }
    const T f = light_factor<F>(L, u.length, w, u.l, visibility);
    add_ambient<F>(sums, L, f);

    mask_t<T> on = math_traits<T>::both(s.defined, u.inv > T(0));
    if constexpr (gated<F>) on = math_traits<T>::both(on, u.nl > T(0));
    if (!math_traits<T>::any(on)) return;
    if constexpr (F.diffuse) add_diffuse<F>(sums, L, f, u.nl, on);
    if constexpr (F.specular != specular_model::none) {
        T spec = specular_factor<F>(s, u, twofold, m);
        if constexpr (!std::is_floating_point_v<T>) // lanes computed but off, or without a view vector
            spec = detail::select(math_traits<T>::both(on, s.sees_viewer), spec, T(0));
        sum_of<term_kind::specular>(sums) += in_type<T>(specular_of(L)) * (f * spec);
    }
}

} // namespace phong::detail::stable
#include "../core/diagnostics_pop.hpp"
