// phong: BSDFs of phong's materials for path tracers: the modified Phong (Lafortune and Willems) and
// the normalized Blinn-Phong, each beside a Lambertian lobe: eval, pdf, sample, directional albedo.
// Opt-in (phong.hpp does not include it). Derivations, sampling and accuracy: docs/bsdf.md.
// SPDX-License-Identifier: MIT
//
// Directions are unit vectors in the shading point's local frame (local_frame: the normal is +z),
// pointing away from the surface: wo toward the viewer, wi toward the light. Reflection only,
// one-sided: f = 0 unless wo.z > 0 and wi.z > 0 (a two-sided surface flips its frame first).
#pragma once

#include "core/config.hpp"
#include "core/ieee.hpp"
#include "inputs/material.hpp"
#include "core/math.hpp"
#include "inputs/validate.hpp"
#include "core/vector.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>

#include "core/diagnostics_push.hpp"

namespace phong {

// ---- The local frame ----------------------------------------------------------------------------

/// An orthonormal frame (s, t, n), right-handed (s x t = n): the shading point's tangent, bitangent
/// and normal. to_local(v) = (v.s, v.t, v.n), to_world(v) = v.x s + v.y t + v.z n.
template <class T, glm::qualifier Q = glm::defaultp>
struct shading_frame {
    glm::vec<3, T, Q> s{T(1), T(0), T(0)}; ///< tangent
    glm::vec<3, T, Q> t{T(0), T(1), T(0)}; ///< bitangent
    glm::vec<3, T, Q> n{T(0), T(0), T(1)}; ///< normal, the local +z
    /// v in the frame's coordinates: (dot(v, s), dot(v, t), dot(v, n)).
    PHONG_INLINE constexpr glm::vec<3, T, Q> to_local(const glm::vec<3, T, Q>& v) const
    {
        return {detail::dot(v, s), detail::dot(v, t), detail::dot(v, n)};
    }
    /// The world vector of local coordinates v: v.x s + v.y t + v.z n.
    PHONG_INLINE constexpr glm::vec<3, T, Q> to_world(const glm::vec<3, T, Q>& v) const
    {
        return s * v.x + t * v.y + n * v.z;
    }
};

/// The local frame of a unit normal n (Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 2017):
///   sign = n.z < 0 ? -1 : 1,  a = -1 / (sign + n.z),  b = n.x n.y a,
///   s = (1 + sign n.x^2 a, sign b, -sign n.x),  t = (b, sign + n.y^2 a, -n.y).
/// No threshold, no normalization; s, t unit and orthogonal to n within a few ulps for every unit n.
/// Pre: n unit (else s, t are not unit). Edge: n = 0 gives s = (1, 0, 0), t = (0, 1, 0).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr shading_frame<T, Q> local_frame(const glm::vec<3, T, Q>& n)
{
    const T sign = n.z < T(0) ? T(-1) : T(1);
    const T a = T(-1) / (sign + n.z);
    const T b = n.x * n.y * a;
    return {{T(1) + sign * n.x * n.x * a, sign * b, -sign * n.x}, {b, sign + n.y * n.y * a, -n.y}, n};
}

// ---- Results and choices ------------------------------------------------------------------------

/// Which lobe a sample came from.
enum class bsdf_lobe : unsigned char { diffuse, specular };

/// What sample(wo, u) returns: wi (local frame, unit), its pdf (per steradian, pdf(wo, wi)) and the
/// weight f(wo, wi) wi.z / pdf. wi below the horizon, or wo not above it: pdf = 0, weight = 0.
template <class T, glm::qualifier Q = glm::defaultp>
struct bsdf_sample {
    glm::vec<3, T, Q> wi{T(0), T(0), T(1)}; ///< the sampled direction, toward the light
    T pdf = T(0);                            ///< its probability density (per steradian); 0: no sample
    glm::vec<3, T, Q> weight{T(0)};          ///< f cos / pdf: the path throughput factor
    bsdf_lobe lobe = bsdf_lobe::diffuse;     ///< the lobe it was drawn from
};

/// Normalization N of the Blinn-Phong lobe ks N (n.h)^m (docs/bsdf.md):
///  - exact: (m+2)(m+4) / (8 pi (2^(-m/2) + m)): albedo exactly 1 at normal incidence, energy conserving;
///  - approximate: (m+8) / (8 pi) (Real-Time Rendering): NOT energy conserving (albedo 1.075 at m = 10);
///  - three_js: (m+2) / (8 pi) (three.js BRDF_BlinnPhong without Fresnel): NOT normalized (0.34 at m = 1).
/// The last two match other renderers' pictures; validate() accepts them.
enum class blinn_normalization : unsigned char { exact, approximate, three_js };

namespace detail::bsdf {

template <class T> inline constexpr T pi = T(3.14159265358979323846264338327950288L);
template <class T> inline constexpr T inv_pi = T(0.318309886183790671537767526745028724L);
template <class T> inline constexpr T inv_two_pi = T(0.159154943091895335768883763372514362L);
template <class T> inline constexpr T ln2 = T(0.693147180559945309417232121458176568L);

/// Rec. 709 luminance, Mitsuba's weights for choosing a lobe.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T luminance(const glm::vec<3, T, Q>& c)
{
    return T(0.212671) * c.x + T(0.715160) * c.y + T(0.072169) * c.z;
}

/// The sample weight f cos / pdf, f <= C pdf. Below 2^-64, f and pdf are scaled by 2^64 first (exact,
/// the same quotient): -freciprocal-math turns the three divisions into f * (1 / pdf), and 1 / pdf
/// overflows for a subnormal pdf. opaque: -ffast-math may not regroup the scale out again.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> sample_weight(const glm::vec<3, T, Q>& f, T pdf, T cos)
{
    const T scale = pdf < T(0x1p-64) ? T(0x1p64) : T(1);
    const glm::vec<3, T, Q> scaled_f(ieee::opaque(f.x * scale), ieee::opaque(f.y * scale), ieee::opaque(f.z * scale));
    return scaled_f / ieee::opaque(pdf * scale) * cos;
}

/// Mitsuba 0.6's lobe choice: lum(ks) / (lum(kd) + lum(ks)); 0 when both are black.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T luminance_probability(const glm::vec<3, T, Q>& kd, const glm::vec<3, T, Q>& ks)
{
    const T d = luminance(kd), s = luminance(ks);
    return d + s > T(0) ? s / (d + s) : T(0);
}

/// cos a, 1 - cos a and sin a of a sample of the lobe (m+1)/(2 pi) cos^m a: t = log(u) / (m+1),
/// 1 - cos a = -expm1(t), sin a = sqrt((1 - cos a)(2 - (1 - cos a))), within a few ulps for u in (0, 1)
/// at any m >= 0 (cos a = u^(1/(m+1)) loses sin a in float from m ~ 1e3). float: in double (expm1 by
/// its Taylor series for |t| < 2^-6, log, exp by pow_unit's tables), rounded once. u = 0 or NaN:
/// cos a = 0, sin a = 1 (the limit u -> 0).
template <class T> struct cone {
    T one_minus_cos; ///< 1 - cos a, in [0, 1]
    T cos;           ///< cos a, in [0, 1]
    T sin;           ///< sin a, in [0, 1]
};
template <class T>
PHONG_INLINE constexpr cone<T> sample_cone(T u, T m)
{
    if (!(u > T(0))) return {T(1), T(0), T(1)};
    if constexpr (std::is_same_v<T, float>) {
        // log2 and exp2 by pow_unit's double kernels (core/power.hpp): errors far below a float ulp.
        const double inv = 1.0 / (double(m) + 1.0); // beside the log, not after it (the rounding: 2^-53)
#if defined(__CUDA_ARCH__) // device code: CUDA's double log and expm1
        const double omc = -detail::expm1(detail::log(double(u)) * inv);
#else
        const double t2 = power::log2_normal<true>(double(u)) * inv, t = t2 * double(ce::ln2);
        // -expm1(t) by its series to t^4 for |t| < 2^-6 (truncation t^4 / 120 relative, under 2^-30),
        // else 1 - 2^t2 (the short polynomial's 2^-34 relative: under 2^-28 of 1 - cos a >= 2^-6).
        const double omc = t > -0x1p-6 ? -(t + t * t * (0.5 + t * (1.0 / 6 + t * (1.0 / 24)))) : 1.0 - power::exp2_tabulated<true>(t2);
#endif
        return {float(omc), float(1.0 - omc), detail::sqrt(float(omc * (2.0 - omc)))}; // float's sqrt: 1 ulp
    } else {
        const T omc = -detail::expm1(detail::log(u) / (m + T(1)));
        return {omc, T(1) - omc, detail::sqrt(omc * (T(2) - omc))};
    }
}

/// (cos 2 pi u, sin 2 pi u). Run time: std::cos, std::sin. Constant evaluation: a Taylor series
/// in long double after reducing u to a quarter turn (exact: 4u - k).
template <class T>
PHONG_INLINE constexpr glm::vec<2, T> cos_sin_turns(T u)
{
    if (PHONG_DETAIL_CONSTANT_EVALUATED()) {
#if defined(__CUDA_ARCH__)
        using W = double; // device code has no long double
#else
        using W = ce::wide;
#endif
        const W q = static_cast<W>(u) * 4;
        W k = 0;
        for (int i = 0; i < 4 && k + 1 <= q; ++i) k += 1; // u in [0, 1]: at most 4 quarters
        const W x = (q - k) * (pi<W> / 2);
        W c = 1, s = x, tc = 1, ts = x;
        for (int i = 1; i < 30; ++i) {
            tc *= -x * x / static_cast<W>((2 * i - 1) * (2 * i));
            ts *= -x * x / static_cast<W>((2 * i) * (2 * i + 1));
            c += tc;
            s += ts;
        }
        const int quarter = static_cast<int>(k) % 4;
        if (quarter == 0) return {T(c), T(s)};
        if (quarter == 1) return {T(-s), T(c)};
        if (quarter == 2) return {T(-c), T(-s)};
        return {T(s), T(-c)};
    }
    const T phi = T(2) * pi<T> * u;
    return {std::cos(phi), std::sin(phi)};
}

/// 1 - a.b for unit a, b with cos_ab = a.b > 0: |(a - b) x b|^2 / (1 + a.b), within a few ulps even
/// where a ~ b (a - b exact, no cancellation), where 1 - a.b loses every digit.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T one_minus_cos(const glm::vec<3, T, Q>& a, const glm::vec<3, T, Q>& b, T cos_ab)
{
    // a - b kept as computed (opaque): -ffast-math would otherwise expand (a - b) x b to a x b, whose
    // components cancel where a ~ b.
    const glm::vec<3, T, Q> d{ieee::opaque(a.x - b.x), ieee::opaque(a.y - b.y), ieee::opaque(a.z - b.z)};
    const glm::vec<3, T, Q> x = detail::cross(d, b);
    return detail::dot(x, x) / (T(1) + cos_ab);
}

/// log1p(-x) for x in [0, 1): log(y) - ((y - 1) + x) / y, y = 1 - x rounded (its rounding error
/// corrected to first order; Goldberg 1991, theorem 4): within 2 ulps, by one log.
template <class W>
PHONG_INLINE constexpr W log1p_minus(W x)
{
    const W y = ieee::opaque(W(1) - x); // opaque: -ffast-math would fold (y - 1) + x to 0
    if (y == W(1)) return -x;
    return detail::log(y) - ((y - W(1)) + x) / y;
}

/// (c 2^g)^m rounded to float for c in double (not rounded to float first: that would cost m 2^-25 / c
/// relative), m >= 0 finite, |g| small (a correction of c, added to log2 c); c 2^g above 1 counts as 1.
/// 0 for c <= 0 or NaN and below the power floor. Branch-free: pow_unit's double tables with float's
/// short polynomials, relative error about m 2^-50 (their truncation, smaller where c is near 1) beside
/// the m 2^-52 of c's own rounding. NaN or infinite m: 0.
PHONG_INLINE constexpr float float_power(double c, double m, double g = 0.0)
{
    constexpr double least = double(ieee::power_floor_log2<double>);
#if defined(__CUDA_ARCH__) // device code: CUDA's double log and exp (power.hpp's tables are host code)
    const double y = m * detail::min(detail::log(detail::clamp(c, 0x1p-1022, 2.0)) * (1 / ln2<double>) + g, 0.0);
    const double p = detail::exp(detail::max(y, least) * ln2<double>);
#else
    const double y = m * detail::min(power::log2_normal<true>(detail::clamp(c, 0x1p-1022, 2.0)) + g, 0.0); // in bounds for any c
    const double p = power::exp2_tabulated<true>(detail::max(y, least));
#endif
    return float(c > 0.0 && y >= least ? p : 0.0);
}

/// cos^m a = exp(m log1p(-x)) for x = 1 - cos a in [0, 1), x clamped below 1 (m = 0 gives 1, not
/// 0 * -inf); m >= 0 finite; the double lobes' power (float's: float_power). Relative error about
/// (1 + m x) ulps beyond x's. double: branch-free, 2^(m log2(1 - x)) by pow_unit's exp2 table;
/// log2(1 - x) by the atanh series for x < 2^-4, else by the log2 table with y = 1 - x rounded and its
/// rounding corrected to first order, log2 y - ((y - 1) + x) / (y ln 2); results below the power floor
/// 2^-996 are 0.
template <class T>
PHONG_INLINE constexpr T lobe_power(T x, T m)
{
    constexpr T below_one = T(1) - std::numeric_limits<T>::epsilon() / 2;
#if !defined(__CUDA_ARCH__) // device code: the exp and log1p below (power.hpp's tables are host code)
    if constexpr (std::is_same_v<T, double>) {
        constexpr double least = double(ieee::power_floor_log2<double>), inv_ln2 = 1 / ln2<double>;
        const double xc = detail::clamp(x, 0.0, below_one), y = 1.0 - xc; // y >= 2^-53: normal
        // Near 1 (x < 2^-4), where the table's log2 has an absolute error of 2^-53 (large relative to
        // log2 y ~ -1.44 x): ln(1 - x) = -2 atanh(s), s = x / (2 - x) < 2^-4.9, its series to s^11
        // (truncation under s^12 / 13 < 2^-62 relative). Both are evaluated (no branch); one is kept.
        const double s = xc / (2.0 - xc), s2 = s * s;
        const double near = -2.0 * inv_ln2 * s * (1.0 + s2 * (1.0 / 3 + s2 * (1.0 / 5 + s2 * (1.0 / 7 + s2 * (1.0 / 9 + s2 * (1.0 / 11))))));
        const double yo = ieee::opaque(y); // -ffast-math would fold (y - 1) + x to 0
        const double far = power::log2_normal(yo) - ((yo - 1.0) + xc) / yo * inv_ln2;
        const double v = m * (xc < 0x1p-4 ? near : far);
        const double p = power::exp2_tabulated(detail::max(v, least));
        return v >= least ? p : 0.0;
    }
#endif
    return detail::exp(m * log1p_minus(detail::min(x, below_one)));
}

/// Choose the lobe with u0 and stretch u0 back onto [0, 1) for the lobe's own use.
template <class T>
PHONG_INLINE constexpr bool choose_specular(T& u0, T p)
{
    if (u0 < p || p >= T(1)) { // p = 1: u0 = 1 (allowed) would give 0 / 0 below
        u0 = u0 / p;
        return true;
    }
    u0 = (u0 - p) / (T(1) - p);
    return false;
}

/// The Lambertian sample (Malley): r = sqrt(u1), z = sqrt(1 - u1), phi = 2 pi u0. z > 0 for u1 < 1.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> sample_cosine(T u0, T u1)
{
    const glm::vec<2, T> cs = cos_sin_turns(u0);
    const T r = detail::sqrt(u1);
    return {r * cs.x, r * cs.y, detail::sqrt(T(1) - u1)};
}

/// int_0^xmax e^-x g(x) dx by 8-point Gauss-Legendre on panels 0, 1/4, ..., 28, 40 (truncation
/// e^-40 < 5e-18), the first in y = sqrt(x). Accuracy against a 2-D integration: docs/bsdf.md.
template <class T, class G>
inline T exp_weighted_integral(T xmax, G g)
{
    constexpr T node[4] = {T(0.1834346424956498049394761L), T(0.5255324099163289858177390L),
                           T(0.7966664774136267395915539L), T(0.9602898564975362316835609L)};
    constexpr T weight[4] = {T(0.3626837833783619829651504L), T(0.3137066458778872873379622L),
                             T(0.2223810344533744705443560L), T(0.1012285362903762591525314L)};
    constexpr T edge[] = {0, 0.25, 0.5, 1, 1.5, 2, 3, 4, 5, 6, 8, 10, 12, 16, 20, 28, 40};
    T sum = T(0);
    for (unsigned p = 0; p + 1 < sizeof(edge) / sizeof(edge[0]); ++p) {
        const T a = edge[p], b = detail::min(edge[p + 1], xmax);
        if (!(b > a)) break;
        if (p == 0) { // x = y^2 on the first panel: g may go as sqrt(x) there (wo on the horizon)
            const T hy = detail::sqrt(b) / 2;
            for (int k = 0; k < 4; ++k)
                for (const T y : {hy - hy * node[k], hy + hy * node[k]})
                    sum += hy * weight[k] * T(2) * y * std::exp(-y * y) * g(y * y);
            continue;
        }
        const T mid = (a + b) / 2, half = (b - a) / 2;
        for (int k = 0; k < 4; ++k)
            for (const T x : {mid - half * node[k], mid + half * node[k]})
                sum += half * weight[k] * std::exp(-x) * g(x);
    }
    return sum;
}

} // namespace detail::bsdf

// ---- The modified Phong -------------------------------------------------------------------------

/// The modified Phong BSDF (Lafortune and Willems 1994; Mitsuba 0.6's `phong`):
///   f(wo, wi) = kd / pi + ks (m+2) / (2 pi) max(0, wi.r)^m,   r = reflect(wo) = (-wo.x, -wo.y, wo.z),
/// for wo.z > 0 and wi.z > 0, else 0. Reciprocal. Specular albedo 1 at normal incidence, about
/// cos(theta_o) toward grazing, so kd + ks <= 1 conserves energy (validate). Sampling: the lobe
/// (m+1)/(2 pi) cos^m a about r with probability specular_probability, else cosine-weighted; its part
/// below the surface is wasted (pdf = 0, weight = 0). Uses the material's kd, ks and shininess (m).
template <class T, glm::qualifier Q = glm::defaultp>
struct modified_phong_bsdf {
    using vec3 = glm::vec<3, T, Q>; ///< the direction and colour type
    vec3 kd{T(0.7)};                  ///< diffuse albedo
    vec3 ks{T(0.2)};                  ///< specular albedo at normal incidence
    T shininess = T(32);              ///< m >= 0
    T specular_probability = T(0.5);  ///< probability of sampling the specular lobe, in [0, 1]

    constexpr modified_phong_bsdf() = default;
    /// From a material: kd, ks, shininess; the lobe chosen by luminance (Mitsuba 0.6).
    PHONG_INLINE constexpr explicit modified_phong_bsdf(const material<T, Q>& mat)
        : kd(mat.kd), ks(mat.ks), shininess(mat.shininess),
          specular_probability(detail::bsdf::luminance_probability(mat.kd, mat.ks)) {}
    /// From a material, with the lobe's probability given (e.g. from the albedo at wo).
    PHONG_INLINE constexpr modified_phong_bsdf(const material<T, Q>& mat, T specular_probability_)
        : kd(mat.kd), ks(mat.ks), shininess(mat.shininess), specular_probability(specular_probability_) {}

    /// cos^m of the angle between wi and r = reflect(wo); 0 where it exceeds 90 degrees. float: wo and
    /// wi unit within 2^-21 (float's rounding of a unit vector is within 2^-23); farther from unit
    /// their lengths count beyond that (the correction below is clamped), the result stays finite.
    PHONG_INLINE constexpr T specular_power(const vec3& wo, const vec3& wi) const
    {
        if constexpr (std::is_same_v<T, float>) {
            // float, in double, branch-free: c = wi.r (the products exact) over |wi| |r|, since
            // lengths off 1 by float's rounding, raised to m, would cost m 2^-24: log2(1 / sqrt(1 + e))
            // to second order added to log2 c, e = |wi|^2 |r|^2 - 1 (third order under 2^-62).
            const glm::dvec3 rd{-double(wo.x), -double(wo.y), double(wo.z)}, wd{wi};
            const double c = detail::dot(wd, rd), e = detail::dot(wd, wd) * detail::dot(rd, rd) - 1.0;
            const double ec = detail::clamp(e, -0x1p-20, 0x1p-20);
            constexpr double k = 1 / (4 * detail::bsdf::ln2<double>); // log2(1 / sqrt(1 + e)) = -2k (e - e^2 / 2 + ...)
            return detail::bsdf::float_power(c, double(shininess), ec * (-2 * k + ec * k));
        } else { // double: branch-free as well (a c <= 0 only selects 0 at the end)
            const vec3 r{-wo.x, -wo.y, wo.z};
            const T c = detail::dot(wi, r);
            const T pw = detail::bsdf::lobe_power(detail::bsdf::one_minus_cos(wi, r, detail::max(c, T(0))), shininess);
            return c > T(0) ? pw : T(0);
        }
    }

/// f(wo, wi) as above; 0 unless wo.z > 0 and wi.z > 0. Pre: wo, wi unit. Finite for finite m >= 0.
    PHONG_INLINE constexpr vec3 eval(const vec3& wo, const vec3& wi) const
    {
        // the power first and branch-free, so that pdf(wo, wi) next to eval(wo, wi) reuses it
        const T pw = specular_power(wo, wi);
        if (!(wo.z > T(0) && wi.z > T(0))) return vec3(T(0));
        return kd * detail::bsdf::inv_pi<T> + ks * ((shininess + T(2)) * detail::bsdf::inv_two_pi<T> * pw);
    }
    /// f(wo, wi) wi.z, the integrand of the rendering equation; 0 below the horizon.
    PHONG_INLINE constexpr vec3 eval_cos(const vec3& wo, const vec3& wi) const { return eval(wo, wi) * detail::max(wi.z, T(0)); }

/// The density of sample(wo, .) at wi: (1 - p) wi.z / pi + p (m+1)/(2 pi) max(0, wi.r)^m,
/// p = specular_probability; 0 unless wo.z > 0 and wi.z > 0.
    PHONG_INLINE constexpr T pdf(const vec3& wo, const vec3& wi) const
    {
        const T pw = specular_power(wo, wi); // first, as in eval
        if (!(wo.z > T(0) && wi.z > T(0))) return T(0);
        const T p = specular_probability;
        return (T(1) - p) * wi.z * detail::bsdf::inv_pi<T> + p * (shininess + T(1)) * detail::bsdf::inv_two_pi<T> * pw;
    }

/// A direction wi from u in [0, 1]^2: u.x chooses the lobe (then, stretched, the azimuth), u.y the
/// polar angle about r (specular) or the radius sqrt(u.y) (diffuse). Returns wi, pdf(wo, wi) and
/// f wi.z / pdf, evaluated at the returned wi as pdf() and eval() do (for MIS); pdf = 0, weight = 0
/// when wi is below the horizon or wo is not above it. Never NaN or inf for any unit wo, finite m >= 0.
    PHONG_INLINE constexpr bsdf_sample<T, Q> sample(const vec3& wo, const glm::vec<2, T, Q>& u) const
    {
        bsdf_sample<T, Q> out;
        if (!(wo.z > T(0))) return out;
        T u0 = u.x;
        if (detail::bsdf::choose_specular(u0, specular_probability)) {
            out.lobe = bsdf_lobe::specular;
            const vec3 r{-wo.x, -wo.y, wo.z};
            const auto cone = detail::bsdf::sample_cone(u.y, shininess);
            const glm::vec<2, T> cs = detail::bsdf::cos_sin_turns(u0);
            const shading_frame<T, Q> fr = local_frame(r);
            out.wi = fr.s * (cone.sin * cs.x) + fr.t * (cone.sin * cs.y) + r * cone.cos;
            if (!(out.wi.z > T(0))) return out;
        } else {
            out.wi = detail::bsdf::sample_cosine<T, Q>(u0, u.y);
        }
        // pdf and weight at the returned direction: one lobe power for both.
        const T pw = specular_power(wo, out.wi), p = specular_probability;
        const T cz = out.wi.z;
        out.pdf = (T(1) - p) * cz * detail::bsdf::inv_pi<T> + p * (shininess + T(1)) * detail::bsdf::inv_two_pi<T> * pw;
        if (!(out.pdf > T(0))) return bsdf_sample<T, Q>{out.wi, T(0), vec3(T(0)), out.lobe};
        const vec3 f = kd * detail::bsdf::inv_pi<T> + ks * ((shininess + T(2)) * detail::bsdf::inv_two_pi<T> * pw);
        out.weight = detail::bsdf::sample_weight(f, out.pdf, cz); // f / pdf is bounded even where both are subnormal
        return out;
    }

/// The specular lobe's directional albedo int f_s(wo, wi) wi.z dwi / ks, th the angle of wo:
///   cos th (1 - sin^(m+2) th) + (m+2)/(m+1) sin^(m+1) th int_0^inf e^-x G(sin th e^(-x/(m+1))) dx,
/// the lobe's unclipped part plus the clipped rest, G(c) = (c cos th acos(-c cos th / (sqrt(1 - c^2)
/// sin th)) + sqrt(sin^2 th - c^2)) / pi. 1 at normal incidence, 1/2 at m = 0 on the horizon; 0 unless
/// wo.z > 0. Not constexpr (std::acos). Accuracy: docs/bsdf.md.
    inline T specular_albedo(const vec3& wo) const
    {
        if (!(wo.z > T(0))) return T(0);
        const T m = shininess, co = detail::min(wo.z, T(1));
        const T so = detail::min(detail::sqrt(wo.x * wo.x + wo.y * wo.y), T(1));
        if (!(so > T(0))) return co;
        const T log_so = detail::log(so);
        T a = co * -detail::expm1((m + T(2)) * log_so); // cos th (1 - sin^(m+2) th)
        const T tk = detail::exp((m + T(1)) * log_so);
        if (tk > T(0)) {
            const T k = T(1) / (m + T(1));
            const auto g = [&](T x) {
                const T c = so * detail::exp(-x * k), s = detail::sqrt(detail::max(T(1) - c * c, T(0)));
                const T ratio = detail::min(c * co / (s * so), T(1));
                return (c * co * std::acos(-ratio) + so * detail::sqrt(-detail::expm1(T(-2) * x * k))) * detail::bsdf::inv_pi<T>;
            };
            a += (m + T(2)) * k * tk * detail::bsdf::exp_weighted_integral(T(40), g);
        }
        return a;
    }
/// The directional albedo int f(wo, wi) wi.z dwi = kd + ks specular_albedo(wo); 0 unless wo.z > 0.
    inline vec3 albedo(const vec3& wo) const
    {
        if (!(wo.z > T(0))) return vec3(T(0));
        return kd + ks * specular_albedo(wo);
    }
};

// ---- The normalized Blinn-Phong -----------------------------------------------------------------

/// The Blinn-Phong normalization N(m) of `kind` (blinn_normalization). exact as (m+2)/(8 pi) *
/// (m+4)/(2^(-m/2) + m): finite for every finite m >= 0 ((m+2)(m+4) overflows float). N(0) = 1/pi.
template <class T>
PHONG_INLINE constexpr T blinn_phong_normalization(T m, blinn_normalization kind = blinn_normalization::exact)
{
    constexpr T inv_8pi = detail::bsdf::inv_pi<T> / T(8);
    if (kind == blinn_normalization::approximate) return (m + T(8)) * inv_8pi;
    if (kind == blinn_normalization::three_js) return (m + T(2)) * inv_8pi;
    // The ratio first and opaque: -ffast-math would reorder to (m+2)(m+4), which overflows float.
    const T ratio = detail::ieee::opaque((m + T(4)) / (detail::exp(-m / T(2) * detail::bsdf::ln2<T>) + m));
    return (m + T(2)) * inv_8pi * ratio;
}

/// The normalized Blinn-Phong BSDF with a Lambertian lobe:
///   f(wo, wi) = kd / pi + ks N(m) (n.h)^m,   h = (wo + wi) / |wo + wi|,
/// for wo.z > 0 and wi.z > 0, else 0; N(m) per `normalization` (exact: albedo 1 at normal incidence,
/// below elsewhere, so kd + ks <= 1 conserves energy). Reciprocal. Sampling (pbrt-v2's Blinn): h from
/// the lobe (m+1)/(2 pi) (n.h)^m with probability specular_probability, wi = reflect(-wo, h), pdf
/// (m+1)/(2 pi) (n.h)^m / (4 wo.h); else cosine-weighted. wi below the horizon or wo.h <= 0 is wasted
/// (pdf = 0, weight = 0). Uses the material's kd, ks and shininess (m).
template <class T, glm::qualifier Q = glm::defaultp>
struct blinn_phong_bsdf {
    using vec3 = glm::vec<3, T, Q>; ///< the direction and colour type
    vec3 kd{T(0.7)};                 ///< diffuse albedo
    vec3 ks{T(0.2)};                 ///< specular albedo at normal incidence (exact normalization)
    T shininess = T(32);             ///< m >= 0
    T specular_probability = T(0.5); ///< probability of sampling the specular lobe, in [0, 1]
    blinn_normalization normalization = blinn_normalization::exact; ///< N(m)'s form
    T norm = blinn_phong_normalization(T(32));                      ///< N(m), set by the constructors

    constexpr blinn_phong_bsdf() = default;
    /// From a material: kd, ks, shininess; the lobe chosen by luminance; N(m) of `kind`.
    PHONG_INLINE constexpr explicit blinn_phong_bsdf(const material<T, Q>& mat, blinn_normalization kind = blinn_normalization::exact)
        : kd(mat.kd), ks(mat.ks), shininess(mat.shininess),
          specular_probability(detail::bsdf::luminance_probability(mat.kd, mat.ks)), normalization(kind),
          norm(blinn_phong_normalization(mat.shininess, kind)) {}
    /// From a material, with the lobe's probability given.
    PHONG_INLINE constexpr blinn_phong_bsdf(const material<T, Q>& mat, T specular_probability_,
                                            blinn_normalization kind = blinn_normalization::exact)
        : kd(mat.kd), ks(mat.ks), shininess(mat.shininess), specular_probability(specular_probability_),
          normalization(kind), norm(blinn_phong_normalization(mat.shininess, kind)) {}

/// (n.h)^m and |wo + wi| (= 2 wo.h), for wo.z > 0 and wi.z > 0. 1 - n.h = (H.x^2 + H.y^2) / (|H| (|H| + H.z)),
/// H = wo + wi: no cancellation near h = n; H.x = H.y = 0 gives h = n (also where |H| underflows).
    PHONG_INLINE constexpr glm::vec<2, T> half_power(const vec3& wo, const vec3& wi) const
    {
        if constexpr (std::is_same_v<T, float>) {
            // float: H and n.h = H.z / |H| in double (H exact), then float_power.
            const double hx = double(wo.x) + double(wi.x), hy = double(wo.y) + double(wi.y), hz = double(wo.z) + double(wi.z);
            const double len = detail::sqrt(hx * hx + hy * hy + hz * hz);
            const double c = len > 0.0 ? detail::min(hz / len, 1.0) : 1.0;
            return {detail::bsdf::float_power(c, double(shininess)), float(len)};
        } else {
            const vec3 H = wo + wi;
            const T xy = H.x * H.x + H.y * H.y, len = detail::sqrt(xy + H.z * H.z);
            return {detail::bsdf::lobe_power(xy > T(0) ? xy / (len * (len + H.z)) : T(0), shininess), len};
        }
    }
    /// The specular lobe's density (m+1)/(2 pi) (n.h)^m / (4 wo.h), 4 wo.h = 2 |H|; it diverges as
    /// wo.h -> 0 (wo and wi opposite, both on the horizon): clamped to the largest finite T.
    PHONG_INLINE constexpr T specular_pdf(const glm::vec<2, T>& hp) const
    {
        const T d = (shininess + T(1)) * detail::bsdf::inv_two_pi<T> * hp.x;
        // opaque: -fassociative-math would regroup (2 |H|) largest as |H| (2 largest) = |H| inf
        const T two_len = detail::ieee::opaque(T(2) * hp.y);
        return (two_len >= T(1) || d < two_len * detail::largest<T>()) ? d / two_len : detail::largest<T>();
    }

    /// f(wo, wi) = kd / pi + ks N(m) (n.h)^m; 0 unless wo.z > 0 and wi.z > 0. Pre: wo, wi unit.
    PHONG_INLINE constexpr vec3 eval(const vec3& wo, const vec3& wi) const
    {
        if (!(wo.z > T(0) && wi.z > T(0))) return vec3(T(0));
        return kd * detail::bsdf::inv_pi<T> + ks * (norm * half_power(wo, wi).x);
    }
    /// f(wo, wi) wi.z; 0 below the horizon.
    PHONG_INLINE constexpr vec3 eval_cos(const vec3& wo, const vec3& wi) const { return eval(wo, wi) * detail::max(wi.z, T(0)); }

/// The density of sample(wo, .) at wi: (1 - p) wi.z / pi + p (m+1)/(2 pi) (n.h)^m / (4 wo.h),
/// wo.h = |wo + wi| / 2, p = specular_probability; 0 unless wo.z > 0 and wi.z > 0.
    PHONG_INLINE constexpr T pdf(const vec3& wo, const vec3& wi) const
    {
        if (!(wo.z > T(0) && wi.z > T(0))) return T(0);
        const glm::vec<2, T> hp = half_power(wo, wi);
        const T p = specular_probability;
        return (T(1) - p) * wi.z * detail::bsdf::inv_pi<T> + p * specular_pdf(hp);
    }

/// As modified_phong_bsdf::sample, the specular lobe through h (stable cos th_h), wi = 2 (wo.h) h - wo.
    PHONG_INLINE constexpr bsdf_sample<T, Q> sample(const vec3& wo, const glm::vec<2, T, Q>& u) const
    {
        bsdf_sample<T, Q> out;
        if (!(wo.z > T(0))) return out;
        T u0 = u.x;
        if (detail::bsdf::choose_specular(u0, specular_probability)) {
            out.lobe = bsdf_lobe::specular;
            const auto cone = detail::bsdf::sample_cone(u.y, shininess);
            const glm::vec<2, T> cs = detail::bsdf::cos_sin_turns(u0);
            const vec3 h{cone.sin * cs.x, cone.sin * cs.y, cone.cos};
            const T oh = detail::dot(wo, h);
            const vec3 wi = h * (T(2) * oh) - wo;
            // opaque: -ffast-math would fold wo + wi below to 2 (wo.h) h, not pdf()'s sum of the rounded wi
            out.wi = vec3(detail::ieee::opaque(wi.x), detail::ieee::opaque(wi.y), detail::ieee::opaque(wi.z));
            if (!(oh > T(0) && out.wi.z > T(0))) return out;
        } else {
            out.wi = detail::bsdf::sample_cosine<T, Q>(u0, u.y);
        }
        const glm::vec<2, T> hp = half_power(wo, out.wi);
        const T p = specular_probability, cz = out.wi.z;
        out.pdf = (T(1) - p) * cz * detail::bsdf::inv_pi<T> + p * specular_pdf(hp);
        if (!(out.pdf > T(0))) return bsdf_sample<T, Q>{out.wi, T(0), vec3(T(0)), out.lobe};
        const vec3 f = kd * detail::bsdf::inv_pi<T> + ks * (norm * hp.x);
        out.weight = detail::bsdf::sample_weight(f, out.pdf, cz); // f / pdf is bounded even where both are subnormal
        return out;
    }

/// The specular lobe's directional albedo int N (n.h)^m wi.z dwi (ks = 1), over h:
///   N 2 pi / (m+1) int_0^1 H(c) dt,  c = cos th_h = t^(1/(m+1)),  H(c) the azimuthal integral of
/// 4 (wo.h) max(0, 2 (wo.h) c - cos th) / (2 pi) in closed form; the t integral split at its kinks
/// th_h = (pi/2 -+ th)/2. 1 at normal incidence with the exact N. 0 unless wo.z > 0. Not constexpr
/// (std::acos). Derivation and accuracy: docs/bsdf.md.
    inline T specular_albedo(const vec3& wo) const
    {
        if (!(wo.z > T(0))) return T(0);
        const T m = shininess, co = detail::min(wo.z, T(1));
        const T so = detail::min(detail::sqrt(wo.x * wo.x + wo.y * wo.y), T(1));
        const T th = std::atan2(so, co), quarter = detail::bsdf::pi<T> / 4;
        const T c1 = std::cos(quarter - th / 2), c2 = std::cos(quarter + th / 2); // c1 >= c2
        const T k = T(1) / (m + T(1));
        const auto H = [&](T c) {
            const T s = detail::sqrt(detail::max(T(1) - c * c, T(0)));
            const T A = c * co, B = s * so, q0 = co / (T(2) * c);
            T phi1;
            if (!(B > T(0))) phi1 = A > q0 ? detail::bsdf::pi<T> : T(0);
            else {
                const T kappa = (q0 - A) / B;
                phi1 = kappa <= T(-1) ? detail::bsdf::pi<T> : (kappa >= T(1) ? T(0) : std::acos(kappa));
            }
            if (!(phi1 > T(0))) return T(0);
            const T sn = std::sin(phi1), s2 = std::sin(T(2) * phi1);
            const T I1 = T(2) * (A * phi1 + B * sn);
            const T I2 = T(2) * (A * A * phi1 + T(2) * A * B * sn + B * B * (phi1 / T(2) + s2 / T(4)));
            return detail::max(T(8) * c * I2 - T(4) * co * I1, T(0)) * detail::bsdf::inv_two_pi<T>;
        };
        // int_{c_lo^(m+1)}^{c_hi^(m+1)} H dt with t = c_hi^(m+1) e^-x.
        const auto piece = [&](T c_hi, T c_lo) {
            if (!(c_hi > T(0) && c_hi > c_lo)) return T(0);
            const T log_hi = detail::log(c_hi);
            const T t_hi = detail::exp((m + T(1)) * log_hi);
            if (!(t_hi > T(0))) return T(0);
            const T xmax = c_lo > T(0) ? (m + T(1)) * (log_hi - detail::log(c_lo)) : T(40);
            return t_hi * detail::bsdf::exp_weighted_integral(detail::min(xmax, T(40)),
                                                              [&](T x) { return H(c_hi * detail::exp(-x * k)); });
        };
        return norm * T(2) * detail::bsdf::pi<T> * k * (piece(T(1), c1) + piece(c1, c2));
    }
/// kd + ks specular_albedo(wo); 0 unless wo.z > 0.
    inline vec3 albedo(const vec3& wo) const
    {
        if (!(wo.z > T(0))) return vec3(T(0));
        return kd + ks * specular_albedo(wo);
    }
};

// ---- validate -----------------------------------------------------------------------------------

namespace detail::bsdf {
template <class B>
PHONG_INLINE constexpr validation validate_common(const B& b)
{
    using T = decltype(b.shininess);
    if (!finite_non_negative(b.kd)) return {"bsdf.kd (material.kd): negative, NaN or inf"};
    if (!finite_non_negative(b.ks)) return {"bsdf.ks (material.ks): negative, NaN or inf"};
    if (!finite_non_negative(b.shininess)) return {"bsdf.shininess (material.shininess): must be finite and >= 0"};
    for (glm::length_t c = 0; c < 3; ++c)
        if (b.kd[c] + b.ks[c] > T(1))
            return {"material.kd + material.ks: above 1 in a channel, the BSDF would reflect more light than it receives"};
    const T p = b.specular_probability;
    if (!(p >= T(0) && p <= T(1))) return {"bsdf.specular_probability: must be in [0, 1]"};
    const bool has_d = b.kd[0] > T(0) || b.kd[1] > T(0) || b.kd[2] > T(0);
    const bool has_s = b.ks[0] > T(0) || b.ks[1] > T(0) || b.ks[2] > T(0);
    if (has_s && !(p > T(0))) return {"bsdf.specular_probability: 0 with ks > 0, the specular lobe is never sampled (biased)"};
    if (has_d && !(p < T(1))) return {"bsdf.specular_probability: 1 with kd > 0, the diffuse lobe is never sampled (biased)"};
    return {};
}
} // namespace detail::bsdf

/// Checks a modified Phong BSDF: kd, ks, shininess finite and >= 0; kd + ks <= 1 per channel (energy);
/// specular_probability in [0, 1], > 0 when ks > 0 and < 1 when kd > 0 (else a lobe is never sampled: biased).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr validation validate(const modified_phong_bsdf<T, Q>& b)
{
    return detail::bsdf::validate_common(b);
}

/// Checks a Blinn-Phong BSDF as validate(modified_phong_bsdf), and that norm is N(shininess) of its
/// normalization (catches a shininess changed after construction). approximate and three_js pass.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr validation validate(const blinn_phong_bsdf<T, Q>& b)
{
    if (const validation v = detail::bsdf::validate_common(b); !v) return v;
    if (!(b.norm == blinn_phong_normalization(b.shininess, b.normalization)))
        return {"bsdf.norm: not N(shininess) of its normalization (shininess changed after construction?)"};
    return {};
}

} // namespace phong
#include "core/diagnostics_pop.hpp"
