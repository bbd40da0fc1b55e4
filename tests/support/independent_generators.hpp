// Test support for tests/exact_bound.cpp: a second, independently written family of scene
// generators and an independent reference for the exact mode's derived error bound
// (phong::accuracy::exact_bound, docs/accuracy.md).
//
// Independent of tests/support/{stiff_classes,reference,wide}.hpp on purpose: another generator
// (xoshiro256**, not splitmix64), other distributions (log-uniform coordinates across the whole
// float/double range, n.l down to 1e-7, highlight windows 1 - r.v up to 1e-4 around the peak,
// m up to 1e6, one to four lights, directional (w = 0) and positional (w = 1)), and a
// reference that is the seed formula written literally in __float128 (libquadmath, declared here,
// so clang++ gets it too), sharing no code with the library or the project's reference.
#pragma once

#include "accuracy_analysis.hpp"
#include <phong/inputs/light.hpp>
#include <phong/inputs/material.hpp>
#include <phong/sum/shade.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

__extension__ typedef __float128 quad;
#if __has_include(<quadmath.h>)
extern "C" {
#  include <quadmath.h>
}
#else // Debian's clang++ does not find g++'s quadmath.h: the two functions used, declared (libquadmath)
extern "C" {
quad sqrtq(quad) noexcept;
quad powq(quad, quad) noexcept;
}
#endif

namespace independent {

// ---- the reference ------------------------------------------------------------------------

struct q3 {
    quad x = 0, y = 0, z = 0;
};
inline q3 operator+(q3 a, q3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline q3 operator-(q3 a, q3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline q3 operator*(q3 a, quad s) { return {a.x * s, a.y * s, a.z * s}; }
inline quad dot(q3 a, q3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline quad qabs(quad a) { return a < 0 ? -a : a; }
template <class V> q3 to_q(const V& v) { return {quad(v.x), quad(v.y), quad(v.z)}; }

/// One light at the point: its exact quantities and the conditioning the bound reads.
struct pair_info {
    phong::accuracy::pair_conditioning phong_k, blinn_k; ///< the same pair for either specular model
    bool lit = false;      ///< the light has a direction and the point a normal and a view
    quad f = 1;            ///< attenuation
    quad nl = 0;           ///< n.l
    quad s_phong = 0, s_blinn = 0; ///< the specular factors max(c, 0)^m (gated on n.l > 0)
};

/// A scene in T: the shape both generator families share (stiff_scene has the same fields).
template <class T>
struct scene {
    glm::vec<3, T> position{T(0)};
    glm::vec<3, T> normal{T(0), T(0), T(1)};
    phong::material<T> material{};
    std::vector<phong::light<T>> lights;
    phong::environment<T> environment{};
};

/// The exact channels (for either specular model) and the pairs' conditioning, from the inputs
/// as given in T. The seed formula, literally:
///   I = ka La + sum_i [kd Ld_i f_i max(n.l_i, 0) + ks Ls_i f_i s_i],
///   s_i = (n.l_i > 0) ? max(c_i, 0)^m : 0, c_i = r_i.v (r_i = 2 (n.l_i) n - l_i) or n.h_i,
///   f_i = 1 / max(c0 + c1 D + c2 D^2, floor) (w > 0, D = |L.xyz - w Q| / w), 1 (w = 0),
///   l_i = unit(L.xyz - w Q), n = unit(N), v = unit(-Q), pow(0, 0) = 1.
template <class T>
struct evaluation {
    quad phong[3] = {0, 0, 0}, blinn[3] = {0, 0, 0};
    std::vector<pair_info> pairs;
    double f_max = 0, k_max = 0;
};

template <class T, class Scene>
evaluation<T> evaluate(const Scene& s)
{
    using phong::accuracy::exact_square_in_range;
    evaluation<T> out;
    const q3 N = to_q(s.normal), Q = to_q(s.position);
    const quad nn = dot(N, N), qq = dot(Q, Q);
    const q3 n = nn > 0 ? N * (1 / sqrtq(nn)) : q3{};
    const q3 v = qq > 0 ? Q * (-1 / sqrtq(qq)) : q3{};
    const quad m = quad(s.material.shininess);
    const quad nv = dot(n, v);
    const auto& mat = s.material;
    double k_max = 0;
    for (int ch = 0; ch < 3; ++ch) {
        const quad amb = quad(mat.ka[ch]) * quad(s.environment.ambient[ch]);
        out.phong[ch] = out.blinn[ch] = amb;
        k_max = std::max({k_max, double(mat.ka[ch]), double(mat.kd[ch]), double(mat.ks[ch]), double(s.environment.ambient[ch])});
    }
    for (const phong::light<T>& L : s.lights) {
        pair_info p;
        const quad w = quad(L.position.w);
        const q3 d = to_q(L.position) - Q * w;
        const quad dd = dot(d, d);
        const quad len = sqrtq(dd);
        p.lit = nn > 0 && qq > 0 && dd > 0;
        const q3 l = dd > 0 ? d * (1 / len) : q3{};
        p.nl = dot(n, l);
        quad den = 0;
        if (w > 0) {
            const quad D = len / w;
            den = quad(L.attenuation.constant) + quad(L.attenuation.linear) * D + quad(L.attenuation.quadratic) * D * D;
            const quad floor = quad(phong::detail::attenuation_denominator_min<T>);
            p.f = 1 / (den < floor ? floor : den);
        }
        const q3 r = n * (2 * p.nl) - l;
        const quad c_phong = dot(r, v);
        const q3 lv = l + v;
        const quad sigma = sqrtq(dot(lv, lv));
        const quad c_blinn = sigma > 0 ? dot(n, lv) / sigma : 0;
        const auto power = [&](quad c) -> quad {
            if (!(p.lit && p.nl > 0)) return 0;
            if (m == 0) return 1;
            if (c <= 0) return 0;
            return powq(c > 1 ? 1 : c, m);
        };
        p.s_phong = power(c_phong);
        p.s_blinn = power(c_blinn);
        phong::accuracy::pair_conditioning k;
        k.m = double(m);
        k.nl = double(p.nl);
        k.nv = double(nv);
        k.w_ratio = (w == 0 || w == 1) ? 0.0 : double(qabs(w) * sqrtq(qq) / len);
        k.attenuated = w > 0;
        k.in_range = exact_square_in_range<T>((long double)nn) && exact_square_in_range<T>((long double)qq) &&
                     exact_square_in_range<T>((long double)dd) &&
                     (!k.attenuated || phong::accuracy::exact_denominator_in_range<T>((long double)den));
        p.phong_k = k;
        p.phong_k.c = double(c_phong);
        p.phong_k.specular = phong::specular_model::phong;
        p.blinn_k = k;
        p.blinn_k.c = double(c_blinn);
        p.blinn_k.blinn_sum = double(sigma);
        p.blinn_k.specular = phong::specular_model::blinn;
        for (int ch = 0; ch < 3; ++ch) {
            k_max = std::max({k_max, double(L.diffuse[ch]), double(L.specular[ch])});
            if (!p.lit) continue;
            const quad diffuse = quad(mat.kd[ch]) * quad(L.diffuse[ch]) * p.f * (p.nl > 0 ? p.nl : 0);
            const quad ks = quad(mat.ks[ch]) * quad(L.specular[ch]) * p.f;
            out.phong[ch] += diffuse + ks * p.s_phong;
            out.blinn[ch] += diffuse + ks * p.s_blinn;
        }
        out.f_max = std::max(out.f_max, double(p.f));
        out.pairs.push_back(p);
    }
    out.k_max = k_max;
    return out;
}

/// The bound of channel ch of a scene for specular model S: exact_bound of the largest term bound
/// over the terms present in the channel (a term whose coefficient product is 0 is absent), times
/// |I|, plus the absolute underflow allowance. +inf where a term has no relative bound.
template <class T, class Scene, phong::accuracy::power_kernel P = phong::accuracy::power_kernel::scalar>
double channel_bound(const Scene& s, const evaluation<T>& e, phong::specular_model S, int ch, double exact)
{
    namespace acc = phong::accuracy;
    double worst = 0;
    const int K = int(s.lights.size());
    for (std::size_t i = 0; i < e.pairs.size(); ++i) {
        const pair_info& p = e.pairs[i];
        const phong::light<T>& L = s.lights[i];
        if (!p.lit) continue; // both sides add nothing (the exact mode drops it too)
        const acc::pair_conditioning& k = S == phong::specular_model::phong ? p.phong_k : p.blinn_k;
        if (double(s.material.kd[ch]) * double(L.diffuse[ch]) > 0) worst = std::max(worst, acc::exact_diffuse_bound<T>(k));
        if (double(s.material.ks[ch]) * double(L.specular[ch]) > 0) worst = std::max(worst, acc::exact_specular_bound<T, P>(k));
    }
    if (!(worst < std::numeric_limits<double>::infinity())) return worst;
    return acc::exact_bound<T>(worst, K) * std::fabs(exact) + acc::exact_absolute_allowance<T>(K, e.f_max, e.k_max);
}

// ---- the generators -----------------------------------------------------------------------

/// xoshiro256** (Blackman and Vigna), seeded through its own state words.
struct xoshiro {
    std::uint64_t s[4];
    explicit xoshiro(std::uint64_t seed)
    {
        for (int i = 0; i < 4; ++i) {
            seed = seed * 6364136223846793005ull + 1442695040888963407ull;
            s[i] = seed ^ (seed >> 29) ^ 0xa0761d6478bd642full;
        }
    }
    static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
    std::uint64_t next()
    {
        const std::uint64_t r = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
        s[2] ^= s[0], s[3] ^= s[1], s[1] ^= s[2], s[0] ^= s[3], s[2] ^= t, s[3] = rotl(s[3], 45);
        return r;
    }
    long double unit() { return (long double)(next() >> 11) * 0x1p-53L; } ///< [0, 1)
    long double range(long double lo, long double hi) { return lo + (hi - lo) * unit(); }
    /// log-uniform in [lo, hi] (lo > 0), in long double so that double's whole range fits.
    long double log_range(long double lo, long double hi) { return lo * std::exp(std::log(hi / lo) * unit()); }
    bool chance(double p) { return unit() < p; }
    int below(int n) { return int(next() % std::uint64_t(n)); }
};

/// Vectors in long double (x87: 64-bit significand, exponent range far beyond double's).
struct l3 {
    long double x = 0, y = 0, z = 0;
};
inline l3 operator+(l3 a, l3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline l3 operator-(l3 a, l3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline l3 operator*(l3 a, long double s) { return {a.x * s, a.y * s, a.z * s}; }
inline long double ldot(l3 a, l3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline l3 lunit(l3 a) { return a * (1 / std::sqrt(ldot(a, a))); }

/// Uniform on the sphere: normalized Gaussian triple (Box-Muller).
inline l3 sphere(xoshiro& g)
{
    for (;;) {
        const long double u1 = g.unit(), u2 = g.unit(), u3 = g.unit(), u4 = g.unit();
        if (u1 <= 0 || u3 <= 0) continue;
        const long double two_pi = 6.283185307179586476925L;
        const long double r1 = std::sqrt(-2 * std::log(u1)), r2 = std::sqrt(-2 * std::log(u3));
        const l3 p{r1 * std::cos(two_pi * u2), r1 * std::sin(two_pi * u2), r2 * std::cos(two_pi * u4)};
        if (ldot(p, p) > 1e-6L) return lunit(p);
    }
}
/// A unit vector at exactly the cosine t from the unit vector a.
inline l3 at_cosine(xoshiro& g, l3 a, long double t)
{
    for (;;) {
        const l3 u = sphere(g);
        const l3 p = u - a * ldot(u, a);
        const long double pp = ldot(p, p);
        if (pp < 1e-4L) continue;
        return a * t + p * (std::sqrt(1 - t * t) / std::sqrt(pp));
    }
}
/// A unit vector at angle theta from a (theta small: 1 - cos = theta^2 / 2 to long double precision).
inline l3 at_angle(xoshiro& g, l3 a, long double theta)
{
    for (;;) {
        const l3 u = sphere(g);
        const l3 p = u - a * ldot(u, a);
        const long double pp = ldot(p, p);
        if (pp < 1e-4L) continue;
        return a * std::cos(theta) + p * (std::sin(theta) / std::sqrt(pp));
    }
}

/// x rounded to T; beyond T's range +-inf explicitly (no out-of-range conversion; such a scene
/// is drawn again).
template <class T> T to_t(long double x)
{
    const long double top = (long double)std::numeric_limits<T>::max();
    if (x > top || x < -top) return x > 0 ? std::numeric_limits<T>::infinity() : -std::numeric_limits<T>::infinity();
    return T(x);
}
template <class T> glm::vec<3, T> to_t(l3 a) { return {to_t<T>(a.x), to_t<T>(a.y), to_t<T>(a.z)}; }

/// The exponent range of T's coordinates: squares of |x| <= 2^half stay normal (with a margin).
template <class T> int half_range() { return std::numeric_limits<T>::max_exponent / 2 - 3; }

/// One scene: a point with a view, a normal at a chosen n.v, one to four lights each aimed at a
/// chosen conditioning (a highlight window, a grazing n.l, or a random direction), placed as a
/// directional, positional or homogeneous light at a log-uniform distance, coordinates scaled by a
/// power of two from the whole range of T (55 % within its squares' range, 20 % anywhere, 10 %
/// at the edges of the squares' range, where the exact mode keeps or drops a vector).
template <class T> bool finite_scene(const scene<T>& s)
{
    bool ok = std::isfinite(s.position.x) && std::isfinite(s.position.y) && std::isfinite(s.position.z) &&
              std::isfinite(s.normal.x) && std::isfinite(s.normal.y) && std::isfinite(s.normal.z);
    for (const phong::light<T>& L : s.lights)
        for (int k = 0; k < 4; ++k) ok = ok && std::isfinite(L.position[k]);
    return ok;
}

template <class T> scene<T> make_scene_once(xoshiro& g);

/// A scene with finite inputs (a draw whose coordinates overflow T is drawn again).
template <class T>
scene<T> make_scene(xoshiro& g)
{
    for (;;) {
        scene<T> s = make_scene_once<T>(g);
        if (finite_scene(s)) return s;
    }
}

template <class T>
scene<T> make_scene_once(xoshiro& g)
{
    scene<T> s;
    const int half = half_range<T>();
    const int full = std::numeric_limits<T>::max_exponent - 8;
    int e = 0;
    const long double pick = g.unit();
    // At a range edge: |Q| (and, below, |L - wQ|) within a factor 8 of sqrt(min) or sqrt(max),
    // where squares underflow or overflow and the exact mode's keep-or-drop decision is made.
    const int lo_edge = std::numeric_limits<T>::min_exponent / 2, hi_edge = std::numeric_limits<T>::max_exponent / 2;
    const bool edge = pick >= 0.9L;
    if (pick < 0.55L) e = int(g.range(-half, half));
    else if (pick < 0.75L) e = int(g.range(-full, full)); // vectors may leave the range: dropped
    else if (edge) { // (one draw per statement: argument order is unspecified, the scenes must not depend on the compiler)
        const int side = g.chance(0.5) ? lo_edge : hi_edge;
        e = side + int(g.range(-3, 3)) - 4; // distance in [0.5, 100]
    }
    const long double scale = std::ldexp(1.0L, e);
    const l3 v = sphere(g);
    const long double distance = g.log_range(0.5L, 100);
    s.position = to_t<T>(v * (-distance * scale));
    // The normal: n.v log-uniform down to 1e-7 (grazing view) or uniform, length anywhere near 1
    // (times the scale: the normal's length is free).
    const long double nv = g.chance(0.3) ? g.log_range(1e-7L, 1) : g.range(0.05L, 1);
    const l3 n = at_cosine(g, v, nv);
    const long double normal_base = g.log_range(1e-3L, 1e3L);
    const long double normal_length = normal_base * (g.chance(0.5) ? scale : 1);
    s.normal = to_t<T>(n * normal_length);
    // Material: m log-uniform up to 1e6 (sometimes 0 or below 1), coefficients in [0, 1], some 0.
    const long double mp = g.unit();
    const long double m = mp < 0.05L ? 0 : mp < 0.1L ? g.range(0, 1) : g.log_range(1, 1e6L);
    s.material.shininess = T(m);
    for (int ch = 0; ch < 3; ++ch) {
        s.material.ka[ch] = T(g.chance(0.3) ? 0 : g.unit());
        s.material.kd[ch] = T(g.chance(0.2) ? 0 : g.unit());
        s.material.ks[ch] = T(g.chance(0.2) ? 0 : g.unit());
        s.environment.ambient[ch] = T(g.chance(0.5) ? 0 : g.range(0, 0.2L));
    }
    const int K = 1 + g.below(4);
    for (int i = 0; i < K; ++i) {
        phong::light<T> L;
        // The direction l toward the light.
        l3 l;
        const int aim = g.below(5);
        const long double window = g.log_range(1e-12L, 1e-4L); // 1 - cos of the highlight
        const long double theta = std::sqrt(2 * window);
        if (aim == 0) { // Phong highlight: r at angle theta from v, l = reflect(-r, n)
            const l3 r = at_angle(g, v, theta);
            l = n * (2 * ldot(n, r)) - r;
        } else if (aim == 1) { // Blinn highlight: h at angle theta from n, l = reflect(-v, h)
            const l3 h = at_angle(g, n, theta);
            l = h * (2 * ldot(h, v)) - v;
        } else if (aim == 2) { // grazing: n.l log-uniform in [1e-7, 1e-2], either side
            const long double t = g.log_range(1e-7L, 1e-2L);
            l = at_cosine(g, n, g.chance(0.8) ? t : -t);
        } else { // random
            l = sphere(g);
        }
        const int kind = g.below(4);
        long double reach = g.log_range(1e-6L, 1e6L) * distance * scale;
        if (edge && g.chance(0.5)) {
            const long double mantissa = g.range(0.5L, 2);
            const int side = g.chance(0.5) ? lo_edge : hi_edge;
            reach = std::ldexp(mantissa, side + int(g.range(-3, 3)));
        }
        if (kind == 0) { // directional: |xyz| log-uniform
            const long double length = g.chance(0.2) ? std::ldexp(1.0L, int(g.range(-full, full))) : reach;
            L.position = glm::vec<4, T>(to_t<T>(l * length), T(0));
        } else if (kind == 3) { // positional again (validate accepts w = 0 or 1 only); the draw keeps the stream
            const long double w = g.chance(0.5) ? 1.0L : 1.0L;
            const l3 Q{(long double)s.position.x, (long double)s.position.y, (long double)s.position.z};
            L.position = glm::vec<4, T>(to_t<T>(Q * w + l * reach), T(w));
        } else { // positional
            const l3 Q{(long double)s.position.x, (long double)s.position.y, (long double)s.position.z};
            L.position = glm::vec<4, T>(to_t<T>(Q + l * reach), T(1));
        }
        for (int ch = 0; ch < 3; ++ch) {
            L.ambient[ch] = T(0);
            L.diffuse[ch] = T(g.chance(0.1) ? 0 : g.unit());
            L.specular[ch] = T(g.chance(0.1) ? 0 : g.unit());
        }
        // Attenuation scaled to the light's distance (f of order 1..1e-3), c0 = 0 one time in five.
        const long double D = reach;
        const auto coefficient = [](long double x) { // finite in T (a light validate() accepts)
            return x < (long double)std::numeric_limits<T>::max() / 4 ? T(x) : T(0);
        };
        L.attenuation.constant = T(g.chance(0.2) ? 0 : g.range(0.25L, 2));
        L.attenuation.linear = coefficient(g.chance(0.5) ? 0 : g.unit() / D);
        L.attenuation.quadratic = coefficient(g.chance(0.5) ? 0 : g.unit() / (D * D));
        if (!(L.attenuation.constant + L.attenuation.linear + L.attenuation.quadratic > T(0))) L.attenuation.constant = T(1);
        s.lights.push_back(L);
    }
    return s;
}

} // namespace independent
