// phong: the full multi-light sum, shade<features>(...), and the per-vertex pipeline of seed 003.
// SPDX-License-Identifier: MIT
#pragma once

#include "attenuation.hpp"
#include "detail/twofold.hpp"
#include "features.hpp"
#include "light.hpp"
#include "material.hpp"
#include "normal.hpp"
#include "specular.hpp"
#include "view.hpp"

#include <array>
#include <cstddef>
#include <limits>
#include <type_traits>
#include <utility>

namespace phong {

/// What surrounds the shaded point: the scene's ambient light and the eye.
template <class T, glm::qualifier Q = glm::defaultp>
struct environment {
    glm::vec<3, T, Q> ambient{T(0)}; ///< La (seed 000) = GlobalAmbient (seed 001); read when features::scene_ambient
    /// The eye as a homogeneous point: read for view_model::eye_point (w = 1: a point such as seed
    /// 001's ray start; w = 0: a direction) and view_model::orthographic (xyz: toward the viewer).
    /// eye_from_projection(ec_lds) gives it from a projection matrix.
    glm::vec<4, T, Q> eye{T(0), T(0), T(0), T(1)};
};

/// The colour shade<F> returns: rgb, or rgba when F.alpha.
template <features F, class T, glm::qualifier Q = glm::defaultp>
using color = std::conditional_t<F.alpha, glm::vec<4, T, Q>, glm::vec<3, T, Q>>;

namespace detail {

/// Per-point quantities, computed once and shared by every light. The stable mode's twofold
/// extras live in a derived struct, so the exact mode's frame is five fields a compiler keeps in
/// registers (a larger frame was built on the stack and copied: +10 instructions per pair).
template <class T, glm::qualifier Q>
struct surface_frame {
    glm::vec<3, T, Q> position; ///< Q
    glm::vec<3, T, Q> normal;   ///< unit normal after two-sided negation (0 if undefined)
    glm::vec<3, T, Q> view;     ///< unit view vector v (0 if undefined; exact mode without a term reading v: 1 or 0)
    mask_t<T> defined;          ///< normal and view both nonzero, inputs finite
    T poison;                   ///< 0, or NaN when the point's inputs are not finite
    T nv = T(0);                ///< exact mode with a specular term: n.v
};

template <class T, glm::qualifier Q>
struct surface_frame_twofold : surface_frame<T, Q> {
    glm::vec<3, T, Q> normal_scaled;   ///< the normal before its last rounding, rescaled exactly
    T inv_normal_length;               ///< 1 / |normal_scaled|
    glm::vec<3, T, Q> normal_lo{T(0)}; ///< rounding error of normal (normal + normal_lo to O(eps^2))
    glm::vec<3, T, Q> view_lo{T(0)};   ///< rounding error of view
};

template <features F, class T, glm::qualifier Q>
using frame_t = std::conditional_t<F.mode == evaluation::stable, surface_frame_twofold<T, Q>, surface_frame<T, Q>>;

/// Per-light sums, weighted by attenuation; the material multiplies them once at the end.
template <class T, glm::qualifier Q>
struct light_sums {
    glm::vec<3, T, Q> ambient{T(0)};
    glm::vec<3, T, Q> diffuse{T(0)};
    glm::vec<3, T, Q> specular{T(0)};
};

/// The exact mode's threshold on a squared length: the smallest normal number of T. Below it
/// |v|^2 has lost bits to underflow and v / |v| would not be a unit vector (a light 1e-22 from Q
/// in float gave n.l and r.v off by factors), so such a vector counts as zero: the light, normal
/// or view is dropped (its terms give 0, a relative error of at most 1, never garbage or NaN).
template <class T> PHONG_HD constexpr T exact_min_square() { return T(std::numeric_limits<scalar_t<T>>::min()); }

/// The exact mode's 1/|v| from dd = |v|^2: 0 when dd is not a normal number (rsqrt(inf) = 0 too).
template <class T>
PHONG_HD constexpr T exact_inverse_length(T dd)
{
    return phong::select(dd >= exact_min_square<T>(), phong::rsqrt(dd), T(0));
}

/// The exact mode's unit vector with its squared length: v / |v|, or 0 when |v|^2 is not a
/// normal number (dd < min: lost to underflow; dd = inf: overflowed; NaN).
template <class T, glm::qualifier Q>
struct exact_unit {
    glm::vec<3, T, Q> unit;
    T square;    ///< |v|^2 as computed (inf or NaN when v is not finite or overflows)
    mask_t<T> ok; ///< unit is a unit vector
};
template <class T, glm::qualifier Q>
PHONG_HD constexpr exact_unit<T, Q> exact_unit_of(const glm::vec<3, T, Q>& v, T sign = T(1))
{
    const T dd = phong::dot(v, v);
    const T inv = exact_inverse_length(dd);
    return {v * (inv * sign), dd, inv > T(0)};
}

/// x * 0 is 0 for finite x and NaN for NaN or inf: the NaN policy's poison of a point.
template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr T poison_of(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal, const environment<T, Q>& env)
{
    const glm::vec<3, T, Q> zero(T(0));
    T poison = phong::dot(position, zero) + phong::dot(normal, zero);
    if constexpr (F.view == view_model::eye_point) poison += phong::dot(glm::vec<4, T, Q>(env.eye), glm::vec<4, T, Q>(T(0)));
    return poison;
}

/// Two-sided lighting: the sign that faces the normal n toward the viewer (or the caller's flag).
template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr T facing_sign(const glm::vec<3, T, Q>& n, const glm::vec<3, T, Q>& v, mask_t<T> front_facing)
{
    if constexpr (F.two_sided == facing::view) return phong::select(phong::dot(n, v) < T(0), T(-1), T(1));
    else return phong::select(front_facing, T(1), T(-1));
}

/// The exact mode's per-point frame. Built from locals and returned as one aggregate: assigning
/// vectors into a frame object made g++ build it on the stack through integer moves (+5
/// instructions per pair at K = 4, feature_cost.sh).
template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr surface_frame<T, Q> prepare_exact(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                                     const environment<T, Q>& env, mask_t<T> front_facing)
{
    using vec3 = glm::vec<3, T, Q>;
    // Each unit vector comes with its squared length, which says whether it exists and, for
    // scalars, whether the inputs can be NaN or inf at all (a finite square: no).
    const exact_unit<T, Q> n = exact_unit_of(normal);
    vec3 unit_normal = n.unit, view;
    mask_t<T> view_ok;
    T view_square; // |Q|^2 (perspective) or |E - wQ|^2: not finite only if the inputs may not be
    if constexpr (F.view == view_model::orthographic) {
        view = phong::normalize(vec3(env.eye.x, env.eye.y, env.eye.z));
        view_ok = phong::dot(view, view) > T(0);
        view_square = phong::dot(position, position);
    } else {
        // v = unit(e), e = E.xyz - E.w Q; perspective: e = -Q, taken as Q times -1/|Q| (no copy
        // and no negation of the vector).
        const auto view_of = [&](const vec3& e, T sign) {
            if constexpr (F.specular == specular_model::none && F.two_sided != facing::view) {
                // No term reads v, only whether it exists (exactly when its square is a normal
                // number): a removed specular term leaves no normalization of v behind (feature_cost.sh).
                view_square = phong::dot(e, e);
                view_ok = math_traits<T>::both(view_square >= exact_min_square<T>(), view_square <= largest<T>());
                view = vec3(phong::select(view_ok, T(1), T(0)));
            } else {
                const exact_unit<T, Q> v = exact_unit_of(e, sign);
                view_ok = v.ok;
                view_square = v.square;
                view = v.unit;
            }
        };
        if constexpr (F.view == view_model::perspective) view_of(position, T(-1));
        else view_of(vec3(env.eye.x, env.eye.y, env.eye.z) - position * env.eye.w, T(1));
    }
    T poison;
    if constexpr (std::is_floating_point_v<T>) {
        // Finite squares: finite inputs, poison 0. Else (rare: NaN, inf, or a square that
        // overflowed) the exact test; a branch, so the common case pays two compares.
        poison = T(0);
        if (!(n.square <= largest<T>() && view_square <= largest<T>())) [[unlikely]]
            poison = poison_of<F>(position, normal, env);
    } else {
        poison = poison_of<F>(position, normal, env);
    }
    if constexpr (F.two_sided != facing::none) unit_normal = unit_normal * facing_sign<F>(unit_normal, view, front_facing);
    else (void)front_facing;
    // A NaN point has every channel NaN through poison; its terms are switched off so that no
    // garbage (or a NaN power) is computed for it.
    const mask_t<T> defined = math_traits<T>::both(math_traits<T>::both(n.ok, view_ok), poison == T(0));
    // Vectors rebuilt from their components: copied whole, g++ moved them through the stack.
    T nv = T(0);
    if constexpr (F.specular != specular_model::none) nv = phong::dot(unit_normal, view);
    return {vec3(position.x, position.y, position.z), vec3(unit_normal.x, unit_normal.y, unit_normal.z),
            vec3(view.x, view.y, view.z), defined, poison, nv};
}

template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr frame_t<F, T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                            const environment<T, Q>& env, mask_t<T> front_facing)
{
    using vec3 = glm::vec<3, T, Q>;
    if constexpr (F.mode != evaluation::stable) {
        return prepare_exact<F>(position, normal, env, front_facing);
    } else {
        frame_t<F, T, Q> s{};
        s.position = position;
        // v and n twofold (detail/twofold.hpp), from the exact E.xyz - E.w Q and the exact normal.
        vec3 e(T(0)), e_lo(T(0));
        if constexpr (F.view == view_model::perspective) {
            e = -position;
        } else if constexpr (F.view == view_model::orthographic) {
            e = vec3(env.eye.x, env.eye.y, env.eye.z);
        } else {
            vec3 p(T(0));
            for (int k = 0; k < 3; ++k) p[k] = detail::rounded_product(position[k], env.eye.w);
            e = vec3(env.eye.x, env.eye.y, env.eye.z) - p;
            for (int k = 0; k < 3; ++k)
                e_lo[k] = detail::two_sum_error(env.eye[k], -p[k], e[k]) - phong::fma(env.eye.w, position[k], -p[k]);
        }
        const unit_twofold<T, Q> uv = detail::unit_of(e, e_lo);
        s.view = uv.hi;
        s.view_lo = uv.lo;
        const unit_twofold<T, Q> un = detail::unit_of(normal, vec3(T(0)));
        s.normal = un.hi;
        s.normal_lo = un.lo;
        s.normal_scaled = phong::rescaled(normal);
        s.inv_normal_length = un.inv_scaled;
        s.defined = math_traits<T>::both(phong::dot(s.normal, s.normal) > T(0), phong::dot(s.view, s.view) > T(0));
        s.poison = poison_of<F>(position, normal, env);
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
}

/// a - b = hi + lo exactly (Knuth's TwoSum on a + (-b)); returns lo.
template <class T>
PHONG_HD constexpr T difference_error(T a, T b, T hi)
{
    const T bb = hi - a;
    return (a - (hi - bb)) - (b + bb);
}

/// A light's vector in the arithmetic type T: the vector itself when it already is (a reference,
/// so no copy), else widened exactly (the stable mode's wider path).
template <class T, int N, class U, glm::qualifier Q>
PHONG_HD constexpr decltype(auto) in_type(const glm::vec<N, U, Q>& v)
{
    if constexpr (std::is_same_v<U, T>) return (v);
    else return glm::vec<N, T, Q>(v);
}

/// One light's terms added to the sums. T is the arithmetic type; U the light's scalar type (U = T,
/// or float lights in the double arithmetic of the stable mode's wider path: fields are widened
/// where they are read, exactly).
template <features F, class T, glm::qualifier Q, class U>
PHONG_HD constexpr void add_light(light_sums<T, Q>& sums, const frame_t<F, T, Q>& s, const light<U, Q>& L, T m)
{
    using vec3 = glm::vec<3, T, Q>;
    constexpr bool stable = F.mode == evaluation::stable;
    const vec3 Lxyz(T(L.position.x), T(L.position.y), T(L.position.z));

    // d = L.xyz - L.w Q (the homogeneous rule; w is known at compile time for one kind of light).
    // The stable mode also keeps lo, the rounding error of d, so n.l is computed on the exact d.
    vec3 d, lo(T(0));
    T w = T(1);
    if constexpr (F.lights == light_kind::directional) {
        d = Lxyz;
        w = T(0);
    } else if constexpr (F.lights == light_kind::positional) {
        d = Lxyz - s.position;
        if constexpr (stable)
            for (int k = 0; k < 3; ++k) lo[k] = difference_error(Lxyz[k], s.position[k], d[k]);
    } else {
        w = T(L.position.w);
        vec3 p = s.position * w;
        if constexpr (stable) // a product the compiler may not fuse into L - p (twofold.hpp)
            for (int k = 0; k < 3; ++k) p[k] = detail::rounded_product(s.position[k], w);
        d = Lxyz - p;
        if constexpr (stable)
            for (int k = 0; k < 3; ++k)
                lo[k] = difference_error(Lxyz[k], p[k], d[k]) - phong::fma(w, s.position[k], -p[k]);
    }

    vec3 l;
    T nl, inv;
    [[maybe_unused]] T length_d = T(0);
    [[maybe_unused]] T dd = T(0), nd = T(0); // exact mode: |d|^2 and n.d = |d| (n.l)
    [[maybe_unused]] vec3 l_lo(T(0)); // stable: l + l_lo and nl + nl_lo to O(eps^2) (detail/twofold.hpp)
    [[maybe_unused]] T nl_lo = T(0);
    // Stable mode, two depths. Twofold (the default): l, n.l and the specular chords to about
    // eps^2. With F.stable_twofold_above = M > 0, pairs whose shininess is at most M (and whose
    // l + v does not nearly cancel, for Blinn) round each component once instead: the rounding
    // moves the specular factor by about sqrt(m) eps, and the cost drops to about a third.
    // A SIMD batch goes twofold when any of its lanes needs it.
    [[maybe_unused]] bool twofold = true;
    if constexpr (stable && F.stable_twofold_above > 0) {
        if constexpr (F.specular == specular_model::none) twofold = false;
        else twofold = math_traits<T>::any(m > T(F.stable_twofold_above));
    }
    if constexpr (stable) {
        const auto twofold_light = [&] {
            const unit_twofold<T, Q> u = detail::unit_of(d, lo); // rescaled: any finite nonzero d
            l = u.hi;
            l_lo = u.lo;
            inv = u.inv_scaled;
            detail::dot_twofold(s.normal, s.normal_lo, l, l_lo, nl, nl_lo);
            length_d = u.length;
        };
        if (twofold) {
            twofold_light();
        } else {
            // d rescaled by a power of two (exact: huge and tiny d survive), l rounded once, and
            // n.l compensated on the exact d = hi + lo and the exact (rescaled) normal.
            const T largest_d = phong::max_abs(d);
            const mask_t<T> in_range = largest_d <= largest<T>(); // an overflowed d has no direction
            const T scale = math_traits<T>::inverse_pow2_scale(phong::select(in_range, largest_d, T(1)));
            vec3 hs(T(0)), ls(T(0));
            for (int k = 0; k < 3; ++k) {
                hs[k] = phong::select(in_range, d[k] * scale, T(0));
                ls[k] = phong::select(in_range, lo[k] * scale, T(0)); // lo is NaN when d overflowed
            }
            const T hh = phong::dot(hs, hs);
            inv = phong::select(hh > T(0), phong::rsqrt(phong::select(hh > T(0), hh, T(1))), T(0));
            l = hs * inv;
            T nh, nlo;
            detail::dot_twofold(s.normal_scaled, vec3(T(0)), hs, ls, nh, nlo);
            nl = (nh + nlo) * (s.inv_normal_length * inv);
            length_d = phong::select(in_range, phong::sqrt(hh) / scale, T(std::numeric_limits<scalar_t<T>>::infinity()));
            if constexpr (F.specular == specular_model::blinn) {
                // l + v nearly cancels (|l + v| < 2^-10): h from once-rounded l and v is noise there.
                const vec3 lv = l + s.view;
                if (math_traits<T>::any(phong::dot(lv, lv) < T(1.0 / 1048576))) {
                    twofold = true;
                    twofold_light();
                }
            }
        }
    } else {
        // Dot products with d itself, scaled by 1/|d| once the pair is known to be on: the signs
        // that decide the branches below do not wait for a square root and a division (a scalar
        // light loop stalls on every mispredicted branch until its condition is known).
        dd = phong::dot(d, d);
        nd = phong::dot(s.normal, d);
        if constexpr (F.spot != spot_model::none) {
            // The spot factor reads l for every pair. An overflowed d gives l = inf * 0 = NaN there.
            inv = exact_inverse_length(dd);
            l = d * inv;
            for (int k = 0; k < 3; ++k) l[k] = phong::select(inv > T(0), l[k], T(0));
        }
        if constexpr (F.attenuation != attenuation_model::none && F.lights != light_kind::directional)
            length_d = phong::sqrt(dd); // only attenuation reads the distance
    }
    // f_i(Q): distance attenuation (positional lights only) times the spot factor.
    T f = T(1);
    if constexpr (F.attenuation != attenuation_model::none && F.lights != light_kind::directional) {
        T dist = length_d;
        if constexpr (F.lights == light_kind::any) dist = length_d / phong::select(w > T(0), w, T(1));
        T fa;
        if constexpr (F.attenuation == attenuation_model::polynomial)
            fa = phong::attenuation_polynomial(dist, T(L.attenuation.constant), T(L.attenuation.linear), T(L.attenuation.quadratic));
        else
            fa = phong::attenuation_windowed(dist, T(L.attenuation.range));
        // The wider path keeps the user type's cap on f (attenuation.hpp), so a light at Q gives
        // the same large finite value as in U's own arithmetic.
        if constexpr (!std::is_same_v<U, T>) fa = phong::min(fa, T(1 / attenuation_denominator_min<U>));
        if constexpr (F.lights == light_kind::any) f = phong::select(w > T(0), fa, T(1));
        else f = fa;
    }
    if constexpr (F.spot == spot_model::opengl) f = f * phong::spot_opengl(l, in_type<T>(L.spot.direction), T(L.spot.exponent), T(L.spot.cos_cutoff));
    if constexpr (F.spot == spot_model::smooth) f = f * phong::spot_smooth(l, in_type<T>(L.spot.direction), T(L.spot.cos_inner), T(L.spot.cos_outer));

    if constexpr (F.light_ambient) {
        if constexpr (F.attenuate_ambient) sums.ambient += in_type<T>(L.ambient) * f;
        else sums.ambient += in_type<T>(L.ambient);
    }
    // The diffuse and specular terms only where they can be nonzero: a lit pair (the light has a
    // direction: not at Q, not a zero directional vector, no overflow; the point has a normal and
    // a view vector) and, with the gate (or without a specular term, where max(n.l, 0) says the
    // same), n.l > 0. Otherwise only the light's ambient term is added. A scalar branches (no
    // power computed for pairs that are off), a SIMD batch skips when no lane is on.
    constexpr bool gated = F.specular_gate || F.specular == specular_model::none;
    mask_t<T> on;
    if constexpr (stable) {
        on = math_traits<T>::both(s.defined, inv > T(0));
        if constexpr (gated) on = math_traits<T>::both(on, nl > T(0));
    } else if constexpr (std::is_floating_point_v<T>) {
        // One short-circuit condition, the sign of n.d first (it rejects about a third of a
        // typical scene's pairs): g++ then branches on each compare instead of combining flags.
        on = s.defined && (!gated || nd > T(0)) && dd >= exact_min_square<T>() && dd <= largest<T>();
    } else {
        on = math_traits<T>::both(s.defined, math_traits<T>::both(dd >= exact_min_square<T>(), dd <= largest<T>()));
        if constexpr (gated) on = math_traits<T>::both(on, nd > T(0));
    }
    if (!math_traits<T>::any(on)) return;
    if constexpr (!stable) {
        if constexpr (F.specular == specular_model::none && F.spot == spot_model::none) {
            // Only n.l is needed: n.d / |d|, one rounding (a SIMD batch's lanes that are off may
            // divide by 0 here; they are not selected).
            nl = nd / phong::sqrt(dd);
        } else {
            if constexpr (F.spot == spot_model::none) {
                // A scalar gets here only with |d|^2 a normal number, where 1/|d| needs no test.
                if constexpr (std::is_floating_point_v<T>) inv = phong::rsqrt(dd);
                else inv = exact_inverse_length(dd);
                // Rounded products: contracted into l + v below (an fma), l = -v would no longer
                // cancel exactly and h = normalize(l + v) would be noise (blinn_opposite).
                if constexpr (F.specular == specular_model::blinn) // (whole: constexpr, l has no active member yet)
                    l = vec3(detail::rounded_product(d.x, inv), detail::rounded_product(d.y, inv), detail::rounded_product(d.z, inv));
            }
            nl = nd * inv;
        }
    }
    const auto add_diffuse = [&] {
        const T lambert = gated ? nl : phong::max(nl, T(0)); // gated: on implies n.l > 0
        sums.diffuse += in_type<T>(L.diffuse) * (f * (std::is_floating_point_v<T> ? lambert : phong::select(on, lambert, T(0))));
    };
    // The exact mode's specular term Ls f max(c, 0)^m for the cosine c = x * scale (scale >= 0; c
    // clamped to 1, pow(0, 0) = 1). A scalar branches on the sign of x, known a square root and a
    // division before c, and adds nothing where the power is 0; a SIMD batch clamps.
    [[maybe_unused]] const auto add_specular_power = [&](T x, T scale) {
        if constexpr (std::is_floating_point_v<T>) {
            if (x > T(0)) sums.specular += in_type<T>(L.specular) * (f * detail::pow_unit_in_domain(phong::min(x * scale, T(1)), m));
            else if (m == T(0)) sums.specular += in_type<T>(L.specular) * f;
        } else {
            const T spec = phong::select(on, phong::pow_unit(phong::clamp(x * scale, T(0), T(1)), m), T(0));
            sums.specular += in_type<T>(L.specular) * (f * spec);
        }
    };
    if constexpr (F.specular != specular_model::none && !stable) {
        if constexpr (F.diffuse) add_diffuse();
        if constexpr (F.specular == specular_model::phong) {
            // |d| r.v = 2 (n.d)(n.v) - d.v (r = reflect(-l, n), l = d / |d|), n.v once per point.
            add_specular_power(T(2) * nd * s.nv - phong::dot(d, s.view), inv);
        } else {
            // n.h = n.(l + v) / |l + v| = (n.l + n.v) / |l + v|: no wait for the second square root
            // before the sign is known (l = -v: 0).
            const vec3 sum = l + s.view;
            add_specular_power(nl + s.nv, exact_inverse_length(phong::dot(sum, sum)));
        }
    } else if constexpr (F.specular != specular_model::none) {
        const vec3& n = s.normal;
        const vec3& v = s.view;
        T spec = T(0);
        // The stable mode: 1 - cosine from a chord, the power as (1 - x)^m.
        if constexpr (F.specular == specular_model::phong) {
            // 1 - r.v = |r - v|^2 / 2, the chord r - v = 2 (n.l) n - l - v (twofold by default).
            if (twofold) {
                spec = phong::pow_one_minus(detail::one_minus_rv(n, s.normal_lo, nl, nl_lo, l, l_lo, v, s.view_lo), m);
            } else {
                const vec3 chord = n * (T(2) * nl) - l - v;
                spec = phong::pow_one_minus(phong::dot(chord, chord) * T(0.5), m);
            }
        } else {
            if (!twofold) {
                // h = normalize(l + v) rounded once (l + v does not nearly cancel here); 1 - n.h = |n - h|^2 / 2.
                const vec3 sum = l + v;
                const vec3 chord = n - sum * phong::rsqrt(phong::dot(sum, sum));
                spec = phong::pow_one_minus(phong::dot(chord, chord) * T(0.5), m);
            } else {
                // h = normalize(l + v) twofold from the twofold sum; 1 - n.h = |n - h|^2 / 2.
                vec3 sum(T(0)), sum_lo(T(0));
                for (int k = 0; k < 3; ++k) {
                    sum[k] = l[k] + v[k];
                    sum_lo[k] = detail::two_sum_error(l[k], v[k], sum[k]) + (l_lo[k] + s.view_lo[k]);
                    // Renormalize: where l and v cancel in the high parts, lo can exceed hi, and
                    // unit_of (which scales by the high parts) then overflows lo to inf (NaN out).
                    const T t = sum[k] + sum_lo[k];
                    sum_lo[k] = detail::two_sum_error(sum[k], sum_lo[k], t);
                    sum[k] = t;
                }
                const unit_twofold<T, Q> h = detail::unit_of(sum, sum_lo); // l = -v: h = 0, x = 1
                spec = phong::pow_one_minus(phong::select(h.inv_scaled > T(0), detail::one_minus_nh(n, s.normal_lo, h.hi, h.lo), T(1)), m);
            }
        }
        if constexpr (!std::is_floating_point_v<T>) spec = phong::select(on, spec, T(0)); // lanes computed but off
        if constexpr (F.diffuse) add_diffuse();
        sums.specular += in_type<T>(L.specular) * (f * spec);
    } else if constexpr (F.diffuse) {
        add_diffuse();
    }
}

template <features F, class T, glm::qualifier Q>
PHONG_HD constexpr color<F, T, Q> finish(const light_sums<T, Q>& sums, const frame_t<F, T, Q>& s,
                                         const material<T, Q>& mat, const environment<T, Q>& env)
{
    glm::vec<3, T, Q> c(s.poison);
    if constexpr (F.emission) c += mat.emission;
    if constexpr (F.scene_ambient && F.light_ambient) c += mat.ka * (env.ambient + sums.ambient);
    else if constexpr (F.scene_ambient) c += mat.ka * env.ambient;
    else if constexpr (F.light_ambient) c += mat.ka * sums.ambient;
    if constexpr (F.diffuse) c += mat.kd * sums.diffuse;
    if constexpr (F.specular != specular_model::none) c += mat.ks * sums.specular;
    if constexpr (F.alpha) return glm::vec<4, T, Q>(c, mat.alpha + s.poison);
    else return c;
}

/// validate() every parameter: a compile error in constant evaluation, an assertion in debug
/// builds, nothing at all under NDEBUG (the checks are not even evaluated).
template <class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr void check_parameters([[maybe_unused]] const material<T, Q>& mat, [[maybe_unused]] const Lights& lights)
{
    if constexpr (std::is_floating_point_v<T>) {
#if defined(NDEBUG)
        if (!std::is_constant_evaluated()) return;
#endif
        const validation vm = phong::validate(mat);
        require(static_cast<bool>(vm), vm.message());
        for (const light<T, Q>& L : lights) {
            const validation vl = phong::validate(L);
            require(static_cast<bool>(vl), vl.message());
        }
    }
}

template <class R> struct is_std_array : std::false_type {};
template <class X, std::size_t N> struct is_std_array<std::array<X, N>> : std::true_type {};

/// The stable mode's wider path applies: float arithmetic carried out in double.
template <features F, class T>
inline constexpr bool widened = F.mode == evaluation::stable && F.precision == stable_precision::wider && std::is_same_v<T, float>;

/// F as the wider path runs it: the exact mode's formulas (in double, on float inputs).
template <features F>
inline constexpr features exact_of = [] {
    features e = F;
    e.mode = evaluation::exact;
    return e;
}();

template <class W, class T, glm::qualifier Q>
PHONG_HD constexpr material<W, Q> widen(const material<T, Q>& m)
{
    return {glm::vec<3, W, Q>(m.ka), glm::vec<3, W, Q>(m.kd), glm::vec<3, W, Q>(m.ks), glm::vec<3, W, Q>(m.emission), W(m.shininess), W(m.alpha)};
}
template <class W, class T, glm::qualifier Q>
PHONG_HD constexpr environment<W, Q> widen(const environment<T, Q>& e)
{
    return {glm::vec<3, W, Q>(e.ambient), glm::vec<4, W, Q>(e.eye)};
}

/// prepare, every light, finish: the whole model at one point in arithmetic type T (the lights'
/// scalar type may be narrower: the wider path).
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> evaluate(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                           const material<T, Q>& mat, const Lights& lights,
                                           const environment<T, Q>& env, bool front_facing)
{
    const frame_t<F, T, Q> s = prepare<F>(position, normal, env, front_facing);
    light_sums<T, Q> sums{};
    if constexpr (is_std_array<Lights>::value) {
        [&]<std::size_t... I>(std::index_sequence<I...>) {
            (add_light<F>(sums, s, lights[I], mat.shininess), ...);
        }(std::make_index_sequence<std::tuple_size_v<Lights>>{});
    } else {
        if constexpr (std::is_floating_point_v<T>) {
            // The same loop twice, so each copy is compiled knowing whether the point has a
            // normal and a view vector (g++ does not unswitch it by itself).
            if (s.defined) for (const auto& L : lights) add_light<F>(sums, s, L, mat.shininess);
            else for (const auto& L : lights) add_light<F>(sums, s, L, mat.shininess);
        } else {
            for (const auto& L : lights) add_light<F>(sums, s, L, mat.shininess);
        }
    }
    return finish<F>(sums, s, mat, env);
}


} // namespace detail

/// The full local lighting model at one point (seeds 000, 001 and 003 are presets of it):
///   I = emission + ka (La + sum_i f_i La_i) + kd sum_i f_i Ld_i max(n.l_i, 0)
///                + ks sum_i f_i Ls_i s_i,
///   s_i = max(r_i.v, 0)^m (r_i = reflect(-l_i, n)) or max(n.h_i, 0)^m (h_i = normalize(l_i + v)),
///   f_i = attenuation(d_i) * spot_i,   l_i = normalize(L_i.xyz - L_i.w Q),
/// with rgba = (I, alpha) when F.alpha. Each term is compiled only when F asks for it.
///
/// position, normal: Q and its normal (any length; normalized here) in the lights' coordinates.
/// lights: a std::array<light, N> (unrolled at compile time), std::span, std::vector, ...
/// front_facing: read only for facing::flag.
///
/// Pre: validate(mat) and validate(L) for every light (checked: a compile error in constant
/// evaluation, an assertion in debug builds). Edges (finite input never gives NaN or inf):
///  * a light at Q (or a directional light with xyz = 0): no direction; that light adds only its
///    ambient term;
///  * normal = 0 or Q at the eye (v = 0): no diffuse or specular from any light;
///  * Blinn with l = -v: n.h taken as 0 (0 for m > 0, 1 for m = 0);
///  * m = 0: the specular base^0 = 1 wherever the specular term is on (pow(0, 0) = 1);
///  * c0 = 0 and d -> 0: f capped at 1 / attenuation_denominator_min<T>;
///  * NaN or inf in position, normal or (eye_point) eye: every channel is NaN.
/// Accuracy: per F.mode and input class, the constants phong::accuracy::bounds<M, T, P> (tested in
/// tests/accuracy.test.cpp, table in README.md). exact: a vector whose squared length is not a
/// normal number (|L - Q|, |n| or |Q| below ~1.1e-19 or above ~1.8e19 in float, 1.5e-154 and
/// 1.3e154 in double) is dropped: its light gives 0 (relative error 1), never NaN. stable: every
/// finite input. Float with F.precision = wider (the default): the exact formulas evaluated in
/// double (every float input is exact there and no square of one overflows or underflows) and
/// rounded once: within 1 ulp, correctly rounded but for near-ties, m = 1e5 and n.l ~ 1e-6
/// included. Double, and float with F.precision = twofold: unit vectors, n.l and the specular
/// chords carried twofold (detail/twofold.hpp), within a few ulp on the same classes.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> shade(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                        const material<T, Q>& mat, const Lights& lights,
                                        const environment<T, Q>& env = {}, bool front_facing = true)
{
    detail::check_parameters(mat, lights);
    if constexpr (detail::widened<F, T>) {
        using W = double;
        return color<F, T, Q>(detail::evaluate<detail::exact_of<F>>(glm::vec<3, W, Q>(position), glm::vec<3, W, Q>(normal),
                                                                     detail::widen<W>(mat), lights, detail::widen<W>(env), front_facing));
    } else {
        return detail::evaluate<F>(position, normal, mat, lights, env, front_facing);
    }
}

/// Seed 003's per-vertex pipeline (phong.vert, diffuse.vert): object-space position and normal,
///   eyeCoords = ModelView * (p, 1),  tnorm = normalize(NormalMatrix * n),
/// then shade<F>(eyeCoords.xyz, tnorm, ...) with lights in eye coordinates.
/// Pre: model_view affine (last row 0, 0, 0, 1), as in the seed, which drops eyeCoords.w.
/// normal_matrix(model_view) gives NormalMatrix.
template <features F, class T, glm::qualifier Q, class Lights>
PHONG_HD constexpr color<F, T, Q> shade_vertex(const glm::vec<3, T, Q>& vertex_position, const glm::vec<3, T, Q>& vertex_normal,
                                               const glm::mat<4, 4, T, Q>& model_view, const glm::mat<3, 3, T, Q>& normal_mat,
                                               const material<T, Q>& mat, const Lights& lights,
                                               const environment<T, Q>& env = {})
{
    const glm::vec<4, T, Q> eye = model_view[0] * vertex_position.x + model_view[1] * vertex_position.y +
                                  model_view[2] * vertex_position.z + model_view[3];
    return shade<F>(glm::vec<3, T, Q>(eye.x, eye.y, eye.z), phong::transform_normal(normal_mat, vertex_normal), mat, lights, env);
}

} // namespace phong
