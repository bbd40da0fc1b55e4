// phong: the stable mode on float SIMD lanes (shade_batch<F>, F.mode = stable, float points): the
// geometry of every pair in double lanes (within a few 2^-53, below float's u^2), the power and the
// sums in float; a step with m > max_shininess takes the twofold route (routes/stable.hpp).
// Bounds: accuracy::bounds<stable, float, twofold>; why double suffices: docs/accuracy.md#float-stable-lanes
// SPDX-License-Identifier: MIT
#pragma once

#include "backend.hpp"
#include "lanes_power.hpp"
#include "math_traits.hpp"
#include "../../terms/direction.hpp"
#include "../../terms/specular.hpp"
#include "../../routes/light_terms.hpp"
#include "../../core/twofold.hpp"

#include <cstddef>
#include <limits>
#include <type_traits>

#if PHONG_HAS_XSIMD && defined(__SSE2__)
#  include <immintrin.h>
#  define PHONG_STABLE_LANES 1
#elif PHONG_HAS_XSIMD && defined(__aarch64__)
#  include <arm_neon.h>
#  define PHONG_STABLE_LANES 1
#else
#  define PHONG_STABLE_LANES 0
#endif

#include "diagnostics_push.hpp"

namespace phong::detail::stable_lanes {

/// The largest shininess this route takes (steps with a larger m in any lane run the twofold
/// route): the double x then adds at most m 10 2^-53 <= 1.2e-9 (0.02 u) to (1 - x)^m's error.
inline constexpr float max_shininess = 1048576.0f; // 2^20

#if PHONG_STABLE_LANES
/// Whether V is a float batch of an x86 ISA (or NEON) that this route splits into two double batches.
template <class V> inline constexpr bool applies = false;
template <class A>
inline constexpr bool applies<xsimd::batch<float, A>> = sizeof(xsimd::batch<float, A>) == 16 ||
                                                        sizeof(xsimd::batch<float, A>) == 32 ||
                                                        sizeof(xsimd::batch<float, A>) == 64;

template <class V> struct double_of;
/// The double batch of the same ISA: half as many lanes.
template <class A> struct double_of<xsimd::batch<float, A>> {
    using type = xsimd::batch<double, A>;
};
template <class V> using double_t = typename double_of<V>::type;

/// The lower lanes [0, W/2) and the upper lanes [W/2, W) of a float batch as two double batches (exact).
template <class V> struct lane_parts {
    double_t<V> lower, upper;
};
template <class V> inline lane_parts<V> widen(const V& x)
{
    using D = double_t<V>;
    if constexpr (sizeof(V) == 64) {
#  if defined(__AVX512F__)
        const __m512 r = x;
        return {D(_mm512_cvtps_pd(_mm512_castps512_ps256(r))),
                D(_mm512_cvtps_pd(_mm256_castpd_ps(_mm512_extractf64x4_pd(_mm512_castps_pd(r), 1))))};
#  endif
    } else if constexpr (sizeof(V) == 32) {
#  if defined(__AVX__)
        const __m256 r = x;
        return {D(_mm256_cvtps_pd(_mm256_castps256_ps128(r))), D(_mm256_cvtps_pd(_mm256_extractf128_ps(r, 1)))};
#  endif
    } else {
#  if defined(__aarch64__)
        const float32x4_t r = x;
        return {D(vcvt_f64_f32(vget_low_f32(r))), D(vcvt_high_f64_f32(r))};
#  else
        const __m128 r = x;
        return {D(_mm_cvtps_pd(r)), D(_mm_cvtps_pd(_mm_movehl_ps(r, r)))};
#  endif
    }
}
/// The float batch of its two double parts (lower, upper lanes), each lane rounded once.
template <class V> inline V join(const double_t<V>& lower, const double_t<V>& upper)
{
    if constexpr (sizeof(V) == 64) {
#  if defined(__AVX512F__)
        const __m256 a = _mm512_cvtpd_ps(lower), b = _mm512_cvtpd_ps(upper);
        return V(_mm512_castpd_ps(_mm512_insertf64x4(_mm512_castpd256_pd512(_mm256_castps_pd(a)), _mm256_castps_pd(b), 1)));
#  endif
    } else if constexpr (sizeof(V) == 32) {
#  if defined(__AVX__)
        return V(_mm256_insertf128_ps(_mm256_castps128_ps256(_mm256_cvtpd_ps(lower)), _mm256_cvtpd_ps(upper), 1));
#  endif
    } else {
#  if defined(__aarch64__)
        return V(vcvt_high_f32_f64(vcvt_f32_f64(lower), upper));
#  else
        return V(_mm_movelh_ps(_mm_cvtpd_ps(lower), _mm_cvtpd_ps(upper)));
#  endif
    }
}

/// The float mask of two double masks (lanes [0, W/2) from lower).
template <class V> inline mask_t<V> join_mask(const xsimd::batch_bool<double, typename V::arch_type>& lower,
                                              const xsimd::batch_bool<double, typename V::arch_type>& upper)
{
#  if defined(__AVX512F__)
    if constexpr (sizeof(V) == 64) {
        const __mmask8 a = lower, b = upper;
        return mask_t<V>(typename mask_t<V>::register_type(__mmask16(unsigned(a) | unsigned(b) << 8)));
    }
#  endif
    using D = double_t<V>;
    return join<V>(xsimd::select(lower, D(1.0), D(0.0)), xsimd::select(upper, D(1.0), D(0.0))) > V(0.0f);
}

/// 1/sqrt(x) for x a positive normal double (other x: unspecified). AVX-512: the 2^-14 estimate y
/// corrected once to fourth order (r = 1 - x y^2, y (1 + r/2 + 3 r^2/8 + 5 r^3/16 + 35 r^4/128)):
/// |rel err| < 3 u (u = 2^-53). Elsewhere 1 / sqrt (1.5 u). One correction, not Newton steps: one
/// step from 2^-14 leaves 2^-27, and two cost more than this.
template <class D> inline D rsqrt_normal(const D& x)
{
#  if defined(__AVX512F__)
    if constexpr (sizeof(D) == 64) {
        const D y = D(_mm512_rsqrt14_pd(x));
        const D r = detail::fma(-(x * y), y, D(1.0));
        const D p = detail::fma(detail::fma(r, D(5.0 / 16), D(3.0 / 8)), r, D(0.5));
        return detail::fma(y * r, p, y);
    }
#  endif
    return D(1.0) / xsimd::sqrt(x);
}

/// 1/|v| from dd = |v|^2: 0 unless dd is a positive normal double (zero vector, NaN, inf).
template <class D> inline D inverse_length(const D& dd)
{
    const auto normal = (dd >= D(std::numeric_limits<double>::min())) && (dd <= D(std::numeric_limits<double>::max()));
    return xsimd::select(normal, rsqrt_normal(xsimd::select(normal, dd, D(1.0))), D(0.0));
}
/// The same for dd = |d|^2 of a float-derived d (Pre): dd is 0, in [2^-298, 2^257], or NaN or inf
/// (a poisoned lane): one test, dd > 0. Blinn's |l + v|^2 takes it too: nonzero, it is above 2^-662
/// (its components are at least float's least step over the longest float vector) and at most 4,
/// so the result is inverse_length's, bit for bit.
template <class D> inline D inverse_length_of_float_difference(const D& dd)
{
    return xsimd::select(dd > D(0.0), rsqrt_normal(dd), D(0.0));
}

/// One part (the lower or upper lanes) of a step's per-point frame, in double.
template <class D, glm::qualifier Q>
struct part_frame {
    glm::vec<3, D, Q> position;
    glm::vec<3, D, Q> normal{D(0.0)}; ///< unit, after two-sided negation (0 if undefined)
    glm::vec<3, D, Q> view{D(0.0)};   ///< unit (0 if undefined)
    glm::vec<3, D, Q> reflected_view{D(0.0)}; ///< Phong: 2 (n.v) n - v, the mirror image of v (r.v = l.that)
    D nv = D(0.0);                    ///< n.v
    xsimd::batch_bool<double, typename D::arch_type> defined;     ///< normal nonzero, inputs finite
    xsimd::batch_bool<double, typename D::arch_type> sees_viewer; ///< the view vector exists
};

/// The per-point frame of a step: its two double parts (lower, upper lanes), and the float poison of finish.
template <class V, glm::qualifier Q>
struct surface_frame {
    part_frame<double_t<V>, Q> part[2];
    V poison; ///< 0, or NaN when the point's inputs are not finite (poison_of)
};

template <class V, glm::qualifier Q>
inline void widen3(const glm::vec<3, V, Q>& v, glm::vec<3, double_t<V>, Q>& lower, glm::vec<3, double_t<V>, Q>& upper)
{
    for (glm::length_t k = 0; k < 3; ++k) {
        const lane_parts<V> h = widen(v[k]);
        lower[k] = h.lower, upper[k] = h.upper;
    }
}

/// The stable mode's frame (routes/stable.hpp's prepare) with n and v in double: the same view
/// models, two-sided rules and poison.
template <features F, class V, glm::qualifier Q>
inline surface_frame<V, Q> prepare(const glm::vec<3, V, Q>& position, const glm::vec<3, V, Q>& normal,
                                               const glm::vec<3, V, Q>& given_view, const environment<V, Q>& env,
                                               mask_t<V> front_facing)
{
    using D = double_t<V>;
    using vec3 = glm::vec<3, D, Q>;
    surface_frame<V, Q> s{};
    s.poison = poison_of<F>(position, normal, given_view, env);
    vec3 pos[2], nrm[2], given[2], eye[2];
    D eye_w[2] = {D(0.0), D(0.0)}, front[2] = {D(1.0), D(1.0)};
    widen3(position, pos[0], pos[1]);
    widen3(normal, nrm[0], nrm[1]);
    if constexpr (F.view == view_model::given) widen3(given_view, given[0], given[1]);
    if constexpr (F.view == view_model::fixed_direction || F.view == view_model::eye_point) {
        widen3(glm::vec<3, V, Q>(env.eye.x, env.eye.y, env.eye.z), eye[0], eye[1]);
        const lane_parts<V> w = widen(env.eye.w);
        eye_w[0] = w.lower, eye_w[1] = w.upper;
    }
    if constexpr (F.two_sided == facing::flag) {
        const lane_parts<V> f = widen(detail::select(front_facing, V(1.0f), V(0.0f)));
        front[0] = f.lower, front[1] = f.upper;
    } else {
        (void)front_facing;
    }
    for (int h = 0; h < 2; ++h) {
        part_frame<D, Q>& f = s.part[h];
        f.position = pos[h];
        const vec3 e = detail::unnormalized_view<F.view>(pos[h], given[h], eye[h], eye_w[h]); // eye_point: w Q exact in double
        const D ee = detail::dot(e, e), nn = detail::dot(nrm[h], nrm[h]);
        const D inv_e = inverse_length(ee), inv_n = inverse_length(nn);
        f.view = e * inv_e;
        f.normal = nrm[h] * inv_n;
        // NaN or inf input: poison (float) is NaN, and the terms are off.
        const D finite = detail::dot(pos[h], vec3(D(0.0))) + detail::dot(nrm[h], vec3(D(0.0))) + ee * D(0.0);
        f.defined = (inv_n > D(0.0)) && (finite == D(0.0));
        f.sees_viewer = inv_e > D(0.0);
        if constexpr (F.two_sided == facing::view) f.normal = f.normal * viewer_facing_sign(f.normal, f.view);
        if constexpr (F.two_sided == facing::flag) f.normal = f.normal * xsimd::select(front[h] > D(0.0), D(1.0), D(-1.0));
        f.nv = detail::dot(f.normal, f.view);
        if constexpr (F.specular == specular_model::phong) f.reflected_view = f.normal * (D(2.0) * f.nv) - f.view;
    }
    return s;
}

/// One part (the lower or upper lanes) of a pair's geometry: the diffuse weight f max(n.l, 0) (0 where off), the specular
/// weight f (0 where off), the specular cosine c (r.v or n.h) and its complement x = 1 - c, and f.
template <class D> struct part_terms {
    D diffuse, specular, x, c, f;
    xsimd::batch_bool<double, typename D::arch_type> specular_on; ///< where specular is (f = 1: the weight)
};

/// f is 1 for every pair: no attenuation (or only directional lights), no spot cone.
template <features F>
inline constexpr bool unit_factor = (F.attenuation == attenuation_model::none || F.lights == light_kind::directional) &&
                                    F.spot == spot_model::none;

/// L: the light in double (exact); f as the wider route takes it (float's attenuation cap).
template <features F, class D, glm::qualifier Q>
inline part_terms<D> part_light(const part_frame<D, Q>& s, const light<double, Q>& L)
{
    using vec3 = glm::vec<3, D, Q>;
    const D w = light_w<F, D>(L);
    const vec3 d = detail::homogeneous_difference<F.lights>(vec3(D(L.position.x), D(L.position.y), D(L.position.z)), w, s.position);
    const D dd = detail::dot(d, d);
    const D nd = detail::dot(s.normal, d);
    // 1/|d|, 0 where the light is at Q. Gated with f = 1, only the masks below read it off the lit
    // lanes (n.d > 0 implies dd > 0): NaN for dd = 0 is discarded, one compare and select fewer.
    D inv;
    if constexpr (gated<F> && unit_factor<F>) inv = rsqrt_normal(dd);
    else inv = inverse_length_of_float_difference(dd);
    // Rounded products: an fma contracted into Blinn's l + v would keep l = -v (d a power-of-two
    // multiple of -Q, as v's e) from cancelling exactly.
    const vec3 l(detail::rounded_product(d.x, inv), detail::rounded_product(d.y, inv), detail::rounded_product(d.z, inv));
    D distance(0.0);
    if constexpr (F.attenuation != attenuation_model::none && F.lights != light_kind::directional) distance = dd * inv;
    const D f = light_factor<F, D, Q, light<double, Q>, unweighted, float>(L, distance, w, l, unweighted{});
    // Lit: a defined normal, a light direction and, where gated, n.l > 0 (one compare: gated,
    // n.d > 0 implies a nonzero float-derived dd >= 2e-90, so inv > 0).
    auto on = s.defined;
    if constexpr (gated<F>) on = on && (nd > D(0.0));
    else on = on && (inv > D(0.0));
    const D nl = nd * inv;
    part_terms<D> t{D(0.0), D(0.0), D(1.0), D(0.0), f, on};
    if constexpr (F.diffuse) t.diffuse = xsimd::select(on, f * (gated<F> ? nl : xsimd::max(nl, D(0.0))), D(0.0));
    if constexpr (F.specular != specular_model::none) {
        if constexpr (F.specular == specular_model::phong) {
            t.c = detail::dot(d, s.reflected_view) * inv; // r.v = l.(2 (n.v) n - v)
        } else {
            const vec3 sum = l + s.view;
            const D inv_h = inverse_length_of_float_difference(detail::dot(sum, sum)); // 0: l = -v, n.h taken as 0
            t.c = (nl + s.nv) * inv_h;
        }
        t.x = D(1.0) - t.c; // pow_cosine takes x < 0 (rounding) as 0, c <= 0 as 0 (and NaN as 0)
        t.specular_on = on && s.sees_viewer;
        if constexpr (!unit_factor<F>) t.specular = xsimd::select(t.specular_on, f, D(0.0));
    }
    return t;
}

/// The specular power c^m of a step in float lanes: x and c rounded to float apiece (each accurate
/// where the kernel reads it), then pow_cosine (lanes_power.hpp).
template <class V, class D> inline V power(const part_terms<D>& lower, const part_terms<D>& upper, const V& m)
{
    return detail::lanes::pow_cosine(xsimd::max(join<V>(lower.x, upper.x), V(0.0f)), join<V>(lower.c, upper.c), m);
}

/// A light's geometry at a step's points: both parts (lower, upper lanes) in double.
template <class V> struct step_terms {
    part_terms<double_t<V>> lower, upper;
};
template <features F, class V, glm::qualifier Q>
inline step_terms<V> terms_of(const surface_frame<V, Q>& s, const light<double, Q>& wide)
{
    return {part_light<F>(s.part[0], wide), part_light<F>(s.part[1], wide)};
}

/// A light's terms (terms_of) added to the float sums of a step: the weights, x and c rounded to
/// float once, power and sums in float. L: the light's float lanes (with the material when folded).
template <features F, class V, glm::qualifier Q, template <class, glm::qualifier> class Sums>
inline void add_terms(Sums<V, Q>& sums, const step_terms<V>& t, const light<V, Q>& L, const V& m)
{
    const auto& lower = t.lower;
    const auto& upper = t.upper;
    if constexpr (F.light_ambient) add_ambient<F>(sums, L, F.attenuate_ambient ? join<V>(lower.f, upper.f) : V(1.0f));
    if constexpr (F.diffuse) sum_of<term_kind::diffuse>(sums) += L.diffuse * join<V>(lower.diffuse, upper.diffuse);
    if constexpr (F.specular != specular_model::none) {
        if constexpr (unit_factor<F>) { // the weight is 1 where on
            const mask_t<V> on = join_mask<V>(lower.specular_on, upper.specular_on);
            if (!xsimd::any(on)) return;
            sum_of<term_kind::specular>(sums) += L.specular * xsimd::select(on, power(lower, upper, m), V(0.0f));
        } else {
            const V weight = join<V>(lower.specular, upper.specular);
            if (!xsimd::any(weight != V(0.0f))) return;
            sum_of<term_kind::specular>(sums) += L.specular * (weight * power(lower, upper, m));
        }
    }
}

#endif

} // namespace phong::detail::stable_lanes

#include "diagnostics_pop.hpp"
