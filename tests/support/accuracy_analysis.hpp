// The error analysis behind phong/accuracy.hpp's derived bounds (the exact and fast modes): the
// functions that bound a colour channel's error from each light's conditioning, the input classes'
// limits, and the class tables they give. Only tests and tools use it (tests/support, docs/accuracy.md
// and docs/exact_bound.md step by step): phong/accuracy.hpp holds the resulting tables as literals,
// printed by tests/tools/print_tables.cpp from derived_bounds below and checked against it bit for
// bit by tests/tables.test.cpp.
// SPDX-License-Identifier: MIT
#pragma once

#include <phong/accuracy.hpp>
#include <phong/core/constexpr_math.hpp>
#include <phong/core/fast_math.hpp>
#include <phong/inputs/features.hpp>

#include <array>
#include <cstddef>
#include <limits>

namespace phong::accuracy {

// ---------------------------------------------------------------------------------------------
// The exact mode's error bound, derived (docs/accuracy.md has the derivation step by step).
//
// What it bounds: one colour channel I of shade<F> in the exact mode, F = measured_features(exact,
// S) (scene ambient, diffuse, gated Phong or Blinn specular, lights of any kind, polynomial
// attenuation, perspective view; also emission and light ambient terms, which add no error of
// their own beyond the summation), against the exact model evaluated on the exact input values:
//   |computed I - exact I| <= exact_bound<T>(max over the channel's terms of the term bound, K) |I|
//                             + exact_absolute_allowance<T>(K, f_max, k_max)
// The channel is a sum of non-negative terms: emission, ka La, and per light i the diffuse term
// kd Ld_i f_i max(n.l_i, 0) and the specular term ks Ls_i f_i s_i. exact_diffuse_bound and
// exact_specular_bound bound the relative error of each light's two terms (the factor f_i n.l_i,
// resp. f_i s_i) from that light's conditioning; the sums and the material products add at most
// gamma_{K+5} (K lights). The absolute allowance covers gradual underflow only (a term or a
// product below the smallest normal number; it is far below u I unless I is that small).
//
// Model of arithmetic: IEEE binary32/binary64, round to nearest, unit roundoff u = 2^-24 / 2^-53,
// gradual underflow; every operation of the exact path rounds once (|fl(a op b) - a op b| <=
// u |a op b| + a subnormal half-ulp). A compiler may contract a * b + c into one fma (g++ does by
// default, -ffp-contract=fast; clang with -march=native does on its own terms): that removes a
// rounding, never adds one, and each bound below counts the roundings of the uncontracted form
// and holds for every evaluation order of a dot product (Higham: |fl(x.y) - x.y| <= gamma_3
// sum |x_k y_k| for any order and any mix of fma). Nothing here depends on -O1/-O2/-O3 or -march:
// the exact path has no compensated (error-free) steps that contraction could break; the one
// place where contraction would change a result qualitatively (Blinn's l = -v) is guarded in
// shade.hpp by rounded products (SIMD lanes: h = d / |d| + v fused on purpose, one rounding per
// component, and |h| < u taken as l = -v: detail::exact::lanes_inverse_halfway_length, whose
// error is below the E_s of the rounded route used below, and whose cut-off lies where E_c is +inf). First-order coefficients k u are used as g(k) = k u (1 + 2^-10)
// / (1 - 2 k u), which is at least Higham's gamma_k = k u / (1 - k u) (a product of k factors
// (1 + delta), |delta| <= u) and covers the products of two such errors (for w = 0 or 1 every k
// is below 200: k u <= 2^-16). pow_unit's own documented bound (detail/power.hpp) enters
// as a stated input: double 3 (|y| + m + 4) 2^-53 with y = m log2(base); float the rounding to
// float plus its short polynomials' truncation (m 2^-50 + 2^-34).
//
// The steps (rho = 1 + 2 w_ratio: the relative error of d = L.xyz - w Q in units of u; rho = 1
// for w = 0 or 1, where d is a single rounding or exact):
//   n = N rsqrt(N.N), v = -Q rsqrt(Q.Q): each component relative 6u (dot 3 incl. underflow 3, sqrt,
//     division, product: 3 + 1 + 1 + 1).
//   n.d: absolute (10 + rho) u |d|  (n 6, d rho, dot 3, underflow 1).
//   1/|d| = rsqrt(d.d): relative (rho + 5) u.     n.v: absolute 16 u.   d.v: absolute (10 + rho) u |d|.
//   n.l = (n.d)(1/|d|): |err| <= (rho + 6) u n.l + (10 + rho) u  ->  relative (rho + 6) u + (10 + rho) u / n.l.
//     The gate n.d > 0 is decided right when |n.l| > (10 + rho) u; a pair with n.l <= 0 and
//     |n.l| below that may be switched on (its exact terms are 0): no relative bound (+inf).
//   Phong: c = r.v = (2 (n.d)(n.v) - d.v) / |d|: absolute E_c = u [2 (10 + rho) |n.v| + 32 n.l
//     + 2 n.l |n.v| + (10 + rho) + (rho + 7) |c|] (product 1, difference 1, scaling rho + 6).
//   Blinn: c = n.h = (n.l + n.v) / |l + v|, l rounded from d (2 rho + 6), sigma = |l + v|:
//     |fl(l + v) - (l + v)| <= E_s = u (2 rho + 12 + sigma); E_c = (c E_s + u ((rho + 6) n.l + 26
//     + rho + sigma c)) / (sigma - E_s) + 6 u (c + ...). sigma = 0 exactly is the one case the
//     exact mode resolves exactly (the rounded l and v cancel bit for bit: L = 2Q, or L.xyz = Q/2
//     with the perspective view): the term is 0 on both sides. Else sigma <= 2 E_s: +inf.
//   c^m: the clamp to 1 only moves c~ toward c; |c~ - c| <= E_c gives |c~^m / c^m - 1| <=
//     expm1(m E_c / c) (Bernoulli below, exp above), and 1 where E_c >= c > 0 (the term may drop).
//     c <= -E_c: the term is 0 on both sides; |c| < E_c with c <= 0: +inf. m = 0: s = 1 exactly.
//   f = 1 / max(c0 + D (c1 + c2 D), floor), D = |d| / w: relative (2 rho + 15) u (D: rho + 5;
//     the c2 D^2 term 2 (rho + 5) + 4; the division 1); f = 1 exactly for directional lights.
//   Terms: (1 + f)(1 + n.l) - 1 and (1 + f)(1 + base)(1 + pow) - 1; the channel adds gamma_{K+5}
//     (f n.l or f s: 1, times Ld or Ls: 1, K additions into the sum, times kd or ks: 1, 2 additions).
// Range: the exact mode drops a vector whose computed squared length is not a normal number;
// outside exact_square_in_range (|N|^2, |Q|^2, |L - wQ|^2 within [min (1 + 2^-10), max (1 -
// 2^-10)]) or when the attenuation denominator is within 2^-10 of overflowing, the term may be 0
// (relative error 1): the bound is then max(1, formula).

/// One light at one point: the conditioning the exact mode's error depends on. All exact values
/// (from the inputs as given, unit n, l and v), as a caller or a test computes them in a wider type.
struct pair_conditioning {
    double m = 1;           ///< shininess m >= 0
    double nl = 1;          ///< n.l (the diffuse cosine; its sign is the gate)
    double nv = 1;          ///< n.v
    double c = 1;           ///< the specular cosine: r.v (Phong) or n.h (Blinn)
    double blinn_sum = 2;   ///< |l + v| (Blinn): >= n.l + n.v; 0 only where the rounded l and v cancel bit for bit
    double w_ratio = 0;     ///< |w| |Q| / |L.xyz - w Q| for a light with w not 0 or 1 (w Q rounded), else 0
    bool attenuated = true; ///< a positional light (w > 0) with polynomial attenuation; false: f = 1 exactly
    bool in_range = true;   ///< exact_square_in_range of |N|^2, |Q|^2, |L - wQ|^2 and exact_denominator_in_range
    specular_model specular = specular_model::phong; ///< none: the pair has no specular term
};

/// Which x^m the exact mode runs: shade<F>'s scalar kernel (detail/power.hpp), or shade_batch's
/// SIMD lanes (float: detail/simd/lanes_power.hpp's polynomial, whose error grows with |m log2 x|).
/// The rest of the derivation holds for both: the lanes' reciprocal square roots (AVX-512's
/// estimate and one Newton step, 1.6 u; baseline SSE2 and double lanes: 1 / sqrt) are within the
/// scalar path's two roundings of a square root and a division. AVX2 float lanes (estimate error
/// 1.5 2^-12, 4.9 u after the step) are not covered by the derivation: docs/exact_bound.md.
enum class power_kernel : unsigned char { scalar, lanes };

namespace detail {
template <class T> inline constexpr double unit_roundoff = double(std::numeric_limits<T>::epsilon()) / 2;
/// First-order coefficient k (in units of u) as a bound with its second-order terms:
/// k u (1 + 2^-10) / (1 - 2 k u), at least Higham's gamma_k = k u / (1 - k u) (+inf for 2 k u >= 1).
template <class T> constexpr double g(double k)
{
    const double ku = k * unit_roundoff<T>;
    return 2 * ku < 1 ? ku * (1 + 0x1p-10) / (1 - 2 * ku) : inf;
}
/// (1 + a)(1 + b) - 1: relative errors of a product.
constexpr double compose(double a, double b) { return (a < inf && b < inf) ? a + b + a * b : inf; }
/// An upper bound of expm1(t) for t >= 0.
constexpr double expm1_upper(double t)
{
    if (t <= 0x1p-10) return t * (1 + t);       // expm1(t) <= t + t^2 for t <= 1
    if (t > 700) return inf;
    return double(phong::detail::ce::exp(t)) * (1 + 0x1p-40) - 1;
}
constexpr double maxd(double a, double b) { return a < b ? b : a; }
constexpr double mind(double a, double b) { return a < b ? a : b; }
constexpr double absd(double a) { return a < 0 ? -a : a; }
/// Relative error of d = L.xyz - w Q, in units of u.
constexpr double rho_of(const pair_conditioning& k) { return 1 + 2 * k.w_ratio; }
/// Absolute error bound of the computed n.l (and of n.d / |d|), before the final scaling.
template <class T> constexpr double nl_absolute(const pair_conditioning& k) { return g<T>(10 + rho_of(k)); }
template <class T> constexpr double attenuation_error(const pair_conditioning& k) { return k.attenuated ? g<T>(2 * rho_of(k) + 15) : 0; }
/// The relative error of the power kernel for base >= lo: the scalar kernel's documented bound
/// (detail/power.hpp), or for float SIMD lanes (shade_batch) detail/simd/lanes_power.hpp's
/// (3.5 |y| + 2.5) u with y = m log2(base) capped at 150 (below 2^-150 the term is 0 in float and
/// the absolute allowance covers it). Double lanes (xsimd's exp(m log x)) are held to the scalar
/// kernel's bound, which tests/lanes_power.test.cpp checks for them.
template <class T, power_kernel P = power_kernel::scalar> constexpr double pow_error(double m, double lo)
{
    const double log2_inv = lo > 0 ? double(-phong::detail::ce::log(lo) / phong::detail::ce::ln2) * (1 + 0x1p-30) : 1022;
    if constexpr (P == power_kernel::lanes && sizeof(T) == 4) {
        const double y = mind(150, m * maxd(log2_inv, 0));
        return (3.5 * y + 2.5) * 0x1p-24;
    }
    const double y = mind(1022, m * maxd(log2_inv, 0));
    const double kernel = 3 * (y + m + 4) * 0x1p-53;
    if constexpr (sizeof(T) == 4) return unit_roundoff<float> + kernel + m * 0x1p-50 + 0x1p-34;
    else return kernel;
}
} // namespace detail

/// The squared length s of |N|, |Q| (the view) or |L - wQ| is safely inside T's normal range (the
/// exact mode keeps the vector): s in [min (1 + 2^-10), max (1 - 2^-10)].
template <class T> constexpr bool exact_square_in_range(long double s)
{
    return s >= static_cast<long double>(std::numeric_limits<T>::min()) * (1 + 0x1p-10L) &&
           s <= static_cast<long double>(std::numeric_limits<T>::max()) * (1 - 0x1p-10L);
}
/// The attenuation denominator c0 + c1 D + c2 D^2 does not overflow in T.
template <class T> constexpr bool exact_denominator_in_range(long double denominator)
{
    return denominator <= static_cast<long double>(std::numeric_limits<T>::max()) * (1 - 0x1p-10L);
}

/// Relative error bound of a light's diffuse factor f max(n.l, 0) in the exact mode (+inf where no
/// relative bound exists: n.l <= 0 within the error of n.l; 0 where both sides are exactly 0).
template <class T> constexpr double exact_diffuse_bound(const pair_conditioning& k)
{
    const double e = detail::nl_absolute<T>(k);
    if (k.nl <= 0) return k.nl < -e ? 0 : detail::inf;
    const double rho = detail::rho_of(k);
    const double r = detail::compose(detail::attenuation_error<T>(k), detail::g<T>(rho + 6) + e * (1 + detail::g<T>(rho + 6)) / k.nl);
    return k.in_range ? r : detail::maxd(1, r);
}

/// The absolute error bound E_c of the computed specular cosine (Phong r.v or Blinn n.h), or +inf
/// where Blinn's l + v cancels within its error.
template <class T> constexpr double exact_cosine_error(const pair_conditioning& k)
{
    using detail::g;
    const double rho = detail::rho_of(k), nl = detail::absd(k.nl), nv = detail::absd(k.nv), c = detail::absd(k.c);
    if (k.specular == specular_model::blinn) {
        const double s = k.blinn_sum;
        const double es = g<T>(2 * rho + 12 + s);
        if (s <= 2 * es) return detail::inf;
        const double first = (c * es + g<T>((rho + 6) * nl + 26 + rho + s * c)) / (s - es);
        return first + g<T>(6) * (c + first);
    }
    return g<T>(2 * (10 + rho) * nv + 32 * nl + 2 * nl * nv + (10 + rho) + (rho + 7) * c);
}

/// Relative error bound of a light's specular factor f s, s = max(c, 0)^m, in the exact mode
/// (gated on n.l > 0; +inf where no relative bound exists, 0 where both sides are exactly 0).
template <class T, power_kernel P = power_kernel::scalar> constexpr double exact_specular_bound(const pair_conditioning& k)
{
    if (k.specular == specular_model::none) return 0;
    const double e = detail::nl_absolute<T>(k);
    if (k.nl <= 0) return k.nl < -e ? 0 : detail::inf;
    const double f = detail::attenuation_error<T>(k);
    double r = f; // m = 0: s = 1 on both sides (pow(0, 0) = 1)
    if (k.m != 0) {
        if (k.specular == specular_model::blinn && k.blinn_sum == 0) return 0; // l = -v bit for bit: 0 both sides
        const double ec = exact_cosine_error<T>(k);
        if (!(ec < detail::inf)) return detail::inf;
        if (k.c <= ec) {
            if (k.c < -ec) return 0;
            if (k.c <= 0) return detail::inf;
        }
        double base = detail::expm1_upper(k.m * ec / k.c);
        if (k.c <= ec) base = detail::maxd(1, base); // the term may drop to 0
        r = detail::compose(f, detail::compose(base, detail::pow_error<T, P>(k.m, k.c - ec)));
    }
    if (k.nl <= e) r = detail::maxd(1, r); // the gate may switch the pair off
    return k.in_range ? r : detail::maxd(1, r);
}

/// The larger of a pair's two term bounds.
template <class T, power_kernel P = power_kernel::scalar> constexpr double exact_pair_bound(const pair_conditioning& k)
{
    return detail::maxd(exact_diffuse_bound<T>(k), exact_specular_bound<T, P>(k));
}

/// The channel's relative error bound from the largest term bound of its terms and the number of
/// lights K: (1 + term)(1 + gamma_{K+5}) - 1.
template <class T> constexpr double exact_bound(double term_bound, int lights)
{
    return detail::compose(term_bound, detail::g<T>(lights + 5));
}
/// The same for a worst-case pair: exact_bound(exact_pair_bound(worst), K).
template <class T, power_kernel P = power_kernel::scalar> constexpr double exact_bound(const pair_conditioning& worst, int lights)
{
    return exact_bound<T>(exact_pair_bound<T, P>(worst), lights);
}

/// The absolute allowance for gradual underflow of a channel: (8 K + 4) max(1, f_max) max(1,
/// k_max)^2 times the smallest normal number of T (each light has at most 8 roundings that may
/// underflow, each off by at most a subnormal half-ulp < u min, or min for double's flush of a
/// power below 2^-1022, scaled by at most f and two coefficients; f_max: the largest f_i, k_max:
/// the largest material or light coefficient), plus 2 K max(1, f_max) max(1, k_max)^2 times the
/// power floor 2^ieee::power_floor_log2<T> (2^-100 float, 2^-996 double): each light's specular
/// power and spot factor are returned as 0 below the floor, an absolute error of at most the floor
/// times the coefficients and f that scale them (docs/accuracy.md, 'The power floor').
template <class T> constexpr double exact_absolute_allowance(int lights, double f_max, double k_max)
{
    const double scale = detail::maxd(1, f_max) * detail::maxd(1, k_max) * detail::maxd(1, k_max);
    const double floor = double(std::numeric_limits<T>::min()) * 0x1p26; // 2^power_floor_log2<T>
    static_assert(phong::detail::ieee::power_floor_log2<T> == std::numeric_limits<T>::min_exponent - 1 + 26);
    return (8.0 * lights + 4) * scale * double(std::numeric_limits<T>::min()) + 2.0 * lights * scale * floor;
}

/// A class's worst-case conditioning for the exact mode (the class's limits): every lit pair has
/// |n.l| >= nl, |n.v| >= nv, a specular cosine c >= c or c <= -c / 100 (where m > 0), shininess
/// <= m, at most `lights` lights, lights with w = 0 or 1, Blinn's |l + v| >= nl + nv (implied
/// where n.v > 0), and kd = 0 where !diffuse, ks = 0 where !specular. `drops`: the class is built
/// so that the exact mode drops a vector (bound 1); otherwise every squared length is in range.
struct exact_limits {
    bool drops = false;  ///< the class makes the exact mode drop a vector (bound 1)
    int lights = 1;      ///< at most this many lights
    double m = 200;      ///< the largest shininess
    double nl = 0.05;    ///< the least |n.l| of a lit pair
    double nv = 0.05;    ///< the least |n.v|
    double c = 0.5;      ///< the least specular cosine (or at most -c / 100)
    bool diffuse = true; ///< kd may be nonzero
    bool specular = true; ///< ks may be nonzero
    bool blinn_cancels = false; ///< Blinn's l = -v bit for bit (blinn_opposite): its term is 0
};

namespace detail {
/// cos(x) for small x (the shininess classes' c = cos(3 / sqrt(m))): 1 - x^2/2 + x^4/24 - x^6/720 (a lower bound).
constexpr double cos_small(double x) { const double x2 = x * x; return 1 - x2 / 2 + x2 * x2 / 24 - x2 * x2 * x2 / 720; }
constexpr double sqrt_newton(double x) { double r = x < 1 ? 1 : x; for (int i = 0; i < 100; ++i) r = (r + x / r) / 2; return r; }

template <class T> constexpr exact_limits limits_of(input_class c)
{
    constexpr bool f = sizeof(T) == 4;
    exact_limits k;
    const auto peak = [&](double m) {
        k.m = m; k.nl = 0.05; k.nv = 0.5; k.c = cos_small(3 / sqrt_newton(m)); k.diffuse = false;
    };
    switch (c) {
    case input_class::well_conditioned: k.lights = 3; break;
    case input_class::shininess_1e3: peak(1e3); break;
    case input_class::shininess_1e4: peak(1e4); break;
    case input_class::shininess_1e5: peak(1e5); break;
    case input_class::grazing: k.nl = 2.5e-7; k.specular = false; break;
    case input_class::near_light_1e20:
    case input_class::near_light_1e40: k.drops = f; k.nl = 0.1; break;
    case input_class::huge_1e20:
    case input_class::huge_1e30: k.drops = f; k.lights = 3; break;
    case input_class::tiny_directional: k.drops = f; k.nl = 0.1; break;
    case input_class::attenuation_c0_zero: k.drops = true; break;
    case input_class::blinn_opposite: k.nl = 0.1; k.nv = 0.1; k.blinn_cancels = true; break;
    case input_class::denormal: k.drops = true; k.lights = 2; break;
    case input_class::shininess_zero: k.lights = 3; k.m = 0; break;
    // Specular cosines c >= 0.05 or c <= -5e-4 (the generator keeps those scenes): a scene of the
    // class with a cosine in between has the bound exact_bound gives for it (+inf at c = 0).
    case input_class::grazing_specular: k.lights = 4; k.nl = 2.5e-7; k.c = 0.05; break;
    default: k.drops = true; break;
    }
    return k;
}

/// The exact bound at a class's limits: the worst of each term's monotone extremes (n.l and n.v
/// at 1 inside E_c, the smallest c, n.l and |l + v| where they divide), both specular models.
template <class T> constexpr double class_bound(const exact_limits& k)
{
    if (k.drops) return 1;
    double worst = 0;
    if (k.diffuse) {
        pair_conditioning p;
        p.nl = k.nl;
        p.specular = specular_model::none;
        worst = maxd(worst, exact_diffuse_bound<T>(p));
    }
    if (k.specular) {
        pair_conditioning p;
        p.m = k.m;
        p.nl = 1;
        p.nv = 1;
        p.c = k.c;
        p.specular = specular_model::phong;
        worst = maxd(worst, exact_specular_bound<T>(p));
        if (!k.blinn_cancels) {
            p.specular = specular_model::blinn;
            p.blinn_sum = k.nl + k.nv;
            worst = maxd(worst, exact_specular_bound<T>(p));
        }
    }
    return exact_bound<T>(worst, k.lights);
}

/// A derived table: max_rel = bound(the class's limits) and max_ulp from it, measured p99.
template <class T, class Bound> constexpr table derived_table(const std::array<double, input_class_count>& p99, Bound bound)
{
    table t{};
    for (std::size_t i = 0; i < input_class_count; ++i) {
        const auto c = static_cast<input_class>(i);
        if (c == input_class::non_finite) {
            t[i] = {inf, inf, inf};
            continue;
        }
        const double rel = bound(limits_of<T>(c));
        t[i] = {p99[i], rel / unit_roundoff<T>, rel};
    }
    return t;
}

/// The exact mode's table: derived max_rel and max_ulp, measured p99.
template <class T> constexpr table exact_table(const std::array<double, input_class_count>& p99)
{
    return derived_table<T>(p99, [](const exact_limits& k) { return class_bound<T>(k); });
}
} // namespace detail


/// The exact mode's bound for class c at its limits (exact_limits): the published max_rel.
/// c = input_class::count (or past it) is no class: +inf.
template <class T> constexpr double exact_class_bound(input_class c)
{
    return static_cast<std::size_t>(c) >= input_class_count ? detail::inf : detail::class_bound<T>(detail::limits_of<T>(c));
}
/// The limits a class's exact bound is stated for.
template <class T> constexpr exact_limits exact_class_limits(input_class c) { return detail::limits_of<T>(c); }

/// The shininess classes' limits (input_class::shininess_1e3, 1e4, 1e5), read by both generator
/// families (tests/support/stiff_classes.hpp, tests/stable_p99.cpp): the angle between r and v
/// below max_angle_sqrt_m / sqrt(m), n.v >= min_nv, n.l > min_nl. n.v >= 1/2 keeps Blinn-Phong's
/// n.h as near its peak as r.v (angle(n, h) <= angle(r, v) there), so both powers lie in
/// [exp(-4.5), 1]; with n.v near 0 the same angle(r, v) puts (n.h)^m anywhere down to 0, a
/// different class (the stable mode's error grows like |m ln c| u there).
struct near_peak_limits {
    double max_angle_sqrt_m = 3; ///< angle(r, v) <= max_angle_sqrt_m / sqrt(m)
    double min_nv = 0.5;         ///< n.v >= min_nv
    double min_nl = 0.05;        ///< n.l > min_nl
};
inline constexpr near_peak_limits near_peak{};


/// The derived tables of phong/accuracy.hpp (bounds<exact, T> and bounds<fast, T>), by constant
/// evaluation: max_rel = the class bound at the class's limits, max_ulp = max_rel / u; p99_ulp, a
/// statistic (twice the worst p99 of `phong_accuracy_table 200000 7`, exact; `--fast`, fast), given.
template <evaluation M, class T> inline constexpr detail::table derived_bounds{};
// clang-format off
// The exact mode's max_rel and max_ulp are derived, not measured: exact_class_bound<T>(c), the
// bound function exact_bound evaluated at the class's worst-case conditioning (exact_limits, see
// the derivation above and docs/accuracy.md); max_ulp = max_rel / u (an error of r |x| is below
// r / u ulp of x). p99_ulp stays a statistic (a percentile cannot be derived): twice the worst
// p99 of `phong_accuracy_table 200000 7`. Classes that drop a vector (a squared length that is not
// a normal number: float |L - Q| ~ 1e-20, 1e-40, coordinates 1e20, 1e30, |xyz| = 1e-30, c0 = 0 with
// d -> 0, subnormal normals; double: the last two) state relative error 1 (the channel keeps only
// the terms it still has).
template <> inline constexpr detail::table derived_bounds<evaluation::exact, float> =
    detail::exact_table<float>({40, 10000, 100000, 1e+06, 2e+06, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 30, 0x1p24, 4, 2e+06, detail::inf});
template <> inline constexpr detail::table derived_bounds<evaluation::exact, double> =
    detail::exact_table<double>({40, 10000, 100000, 1e+06, 2e+06, 60, 60, 40, 40, 60, 0x1p53, 30, 0x1p53, 4, 2e+06, detail::inf});
// clang-format on

// ---------------------------------------------------------------------------------------------
// The fast mode's bound, derived like the exact mode's. The fast mode runs the exact route with two
// approximations (phong/core/fast_math.hpp): 1/|d| by fast::rsqrt (relative error fast::rsqrt_max_rel<T>
// in place of the exact 1/sqrt's) and the specular power by fast::pow_unit (fast::pow_unit_max_rel
// where x^m >= 2^-24). Per light, on top of the exact term bounds:
//   diffuse:  n.l = n.d / |d| gains rsqrt_max_rel relative;
//   specular: the cosine c gains rsqrt_max_rel relative (Phong: c = x / |d|) or at most
//             rsqrt_max_rel (1 + 1 / |l + v|) (Blinn: n.l and l = d / |d| both carry 1/|d|, and
//             |l + v| moves by at most |l| rsqrt_max_rel), so c^m gains expm1(m that) relative, and
//             the power pow_unit_max_rel relative. Blinn pairs with |l + v| < 4 rsqrt_max_rel have
//             no halfway vector in the fast mode (n.h taken as 0, as the exact mode does for l = -v
//             bit for bit, which the fast 1/|d| no longer gives): no relative bound below 5 of it.
// Where c^m < 2^-24 the power's error is absolute instead, at most 2^-24 pow_unit_max_rel per unit of
// ks Ls f: fast_absolute_allowance, below 5e-13 per unit light (the class scenes have scene ambient,
// so it is inside their relative figures). The class constants are fast_class_bound at the exact
// mode's class limits (exact_class_limits): derived, not measured; their p99_ulp column is a
// statistic of the accuracy table's run (phong_accuracy_table 200000 7 --bounds --fast).
// ---------------------------------------------------------------------------------------------

/// The fast mode's extra relative error for one light's terms at the conditioning k (see above).
template <class T> constexpr double fast_pair_extra(const pair_conditioning& k)
{
    const double er = fast::rsqrt_max_rel<T>;
    double extra = er; // the diffuse cosine
    if (k.specular != specular_model::none && k.m != 0) {
        // Blinn with |l + v| < 4 rsqrt_max_rel: no halfway vector in the fast mode (n.h taken as 0).
        if (k.specular == specular_model::blinn && k.blinn_sum > 0 && k.blinn_sum < 5 * er) return detail::inf;
        const double cosine = k.specular == specular_model::blinn ? er * (1 + 1 / detail::maxd(k.blinn_sum, 0x1p-1000)) : er;
        extra = detail::maxd(extra, detail::compose(detail::expm1_upper(k.m * cosine), fast::pow_unit_max_rel));
    }
    return extra;
}

/// The fast mode's bound of one colour channel from its worst pair's conditioning: the exact
/// bound composed with fast_pair_extra (plus fast_absolute_allowance, absolute).
template <class T> constexpr double fast_bound(const pair_conditioning& worst, int lights)
{
    return detail::compose(exact_bound<T>(worst, lights), fast_pair_extra<T>(worst));
}

/// The absolute part of the fast bound: 2^-24 pow_unit_max_rel per unit of ks Ls f, summed over
/// the lights (spec_weight_sum = sum_i ks Ls_i f_i of the channel).
constexpr double fast_absolute_allowance(double spec_weight_sum) { return 0x1p-24 * fast::pow_unit_max_rel * spec_weight_sum; }

namespace detail {
template <class T> constexpr double fast_class_bound(const exact_limits& k)
{
    if (k.drops) return 1;
    double extra = 0;
    if (k.diffuse) {
        pair_conditioning p;
        p.nl = k.nl;
        p.specular = specular_model::none;
        extra = fast_pair_extra<T>(p);
    }
    if (k.specular) {
        pair_conditioning p;
        p.m = k.m;
        p.nl = k.nl;
        p.nv = k.nv;
        p.c = k.c;
        p.specular = specular_model::phong;
        extra = maxd(extra, fast_pair_extra<T>(p));
        if (!k.blinn_cancels) { // l = -v bit for bit: the term is 0 in both modes
            p.specular = specular_model::blinn;
            p.blinn_sum = k.nl + k.nv;
            extra = maxd(extra, fast_pair_extra<T>(p));
        }
    }
    return compose(class_bound<T>(k), extra);
}

template <class T> constexpr table fast_table(const std::array<double, input_class_count>& p99)
{
    return derived_table<T>(p99, [](const exact_limits& k) { return fast_class_bound<T>(k); });
}
} // namespace detail

/// The fast mode's bound for class c at its limits (exact_limits, the exact mode's): the published
/// max_rel of bounds<evaluation::fast, T>; c = input_class::count (or past it): +inf.
template <class T> constexpr double fast_class_bound(input_class c)
{
    return static_cast<std::size_t>(c) >= input_class_count ? detail::inf : detail::fast_class_bound<T>(detail::limits_of<T>(c));
}

// p99_ulp: measured (phong_accuracy_table 200000 7 --bounds --fast --code), twice the worst rounded up
// (classes where a light may be dropped: 2^24 / 2^53, as in the exact table). Double's p99 is ~1e9
// ulp: the fast power is float-accurate in double too (relative ~2e-7 typical, pow_unit_max_rel at most).
template <> inline constexpr detail::table derived_bounds<evaluation::fast, float> =
    detail::fast_table<float>({50, 20000, 200000, 2e+06, 2e+06, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 0x1p24, 30, 0x1p24, 4, 2e+06, detail::inf});
template <> inline constexpr detail::table derived_bounds<evaluation::fast, double> =
    detail::fast_table<double>({2e+09, 3e+09, 3e+09, 3e+09, 2e+06, 2e+09, 2e+09, 2e+09, 2e+09, 2e+09, 0x1p53, 2e+09, 0x1p53, 4, 2e+10, detail::inf});

} // namespace phong::accuracy
