// Test support: seeded generators of scenes for every input class of phong/accuracy.hpp (well
// conditioned, high exponents near the peak, grazing light (with and without specular), near and far lights, huge and tiny
// coordinates, subnormals, m = 0, l = -v, NaN/inf), and error statistics of shade<F> against the
// __float128 reference model. Shared by tests/accuracy.test.cpp, tests/accuracy_table.cpp and the
// benchmarks (which report the same errors beside their timings).
//
//   auto scenes = phong_test::make_class<float>(input_class::grazing, 1000, seed);
//   phong_test::error_stats e = phong_test::measure<F>(scenes);   // p50/p99/max ulp, max rel, NaN/inf
//
// Scenes (stiff_scene<T>) are features-independent: a point, its normal, a material, lights and an
// environment. (Not named `scene`: tests/support/generators.hpp has a phong_test::scene of another
// layout, and both headers are linked into phong_tests; one name for two types breaks the ODR.)
// They are generated in double from a small counter-based generator (splitmix64, so the same seed
// gives the same scenes on every compiler and library), then rounded to T; where a class needs an
// exact property in T (n.l ~ 1e-6, l = -v), it is established or checked on the rounded values.
#pragma once

#include "numeric.hpp"
#include "reference.hpp"

#include "accuracy_analysis.hpp"
#include <phong/sum/shade.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>
#include <vector>

namespace phong_test {

using phong::accuracy::input_class;

/// One shading problem, independent of the feature set.
template <class T>
struct stiff_scene {
    glm::vec<3, T> position{T(0)};
    glm::vec<3, T> normal{T(0), T(0), T(1)};
    phong::material<T> material{};
    std::vector<phong::light<T>> lights;
    phong::environment<T> environment{};
};

/// splitmix64: a tiny, fully specified generator (the standard distributions are not portable).
struct splitmix {
    std::uint64_t state;
    std::uint64_t next()
    {
        std::uint64_t z = (state += 0x9e3779b97f4a7c15ull);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        return z ^ (z >> 31);
    }
    double uniform() { return double(next() >> 11) * 0x1.0p-53; } ///< [0, 1)
    double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
    double log_uniform(double lo, double hi) { return lo * std::exp(std::log(hi / lo) * uniform()); }
    /// A unit vector, uniform on the sphere (rejection from the cube).
    glm::dvec3 unit()
    {
        for (;;) {
            const glm::dvec3 p(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
            const double r2 = p.x * p.x + p.y * p.y + p.z * p.z;
            if (r2 > 1e-4 && r2 <= 1) return p / std::sqrt(r2);
        }
    }
    /// A unit vector u with dot(u, axis) >= min_cos (axis unit).
    glm::dvec3 unit_around(const glm::dvec3& axis, double min_cos)
    {
        for (;;) {
            const glm::dvec3 u = unit();
            const double c = u.x * axis.x + u.y * axis.y + u.z * axis.z;
            if (c >= min_cos) return u;
            if (-c >= min_cos) return -u;
        }
    }
    /// A unit vector perpendicular to the unit vector axis.
    glm::dvec3 perpendicular(const glm::dvec3& axis)
    {
        for (;;) {
            const glm::dvec3 u = unit();
            const glm::dvec3 p = u - axis * (u.x * axis.x + u.y * axis.y + u.z * axis.z);
            const double r2 = p.x * p.x + p.y * p.y + p.z * p.z;
            if (r2 > 1e-2) return p / std::sqrt(r2);
        }
    }
};

namespace detail {

inline double ddot(const glm::dvec3& a, const glm::dvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline glm::dvec3 dnormalize(const glm::dvec3& a) { return a / std::sqrt(ddot(a, a)); }

template <class T> glm::vec<3, T> to(const glm::dvec3& v) { return glm::vec<3, T>(T(v.x), T(v.y), T(v.z)); }
template <class T> glm::vec<4, T> to(const glm::dvec3& v, double w) { return glm::vec<4, T>(T(v.x), T(v.y), T(v.z), T(w)); }

/// The smallest positive normal of T, and the subnormal range used by the denormal class.
template <class T> double subnormal_lo() { return sizeof(T) == 4 ? 1e-44 : 1e-321; }
template <class T> double subnormal_hi() { return sizeof(T) == 4 ? 1e-39 : 1e-309; }

/// Material with random coefficients in [0, 1) and m in [1, 200].
template <class T> phong::material<T> random_material(splitmix& g)
{
    phong::material<T> mat;
    mat.ka = to<T>({g.uniform(), g.uniform(), g.uniform()});
    mat.kd = to<T>({g.uniform(), g.uniform(), g.uniform()});
    mat.ks = to<T>({g.uniform(), g.uniform(), g.uniform()});
    mat.shininess = T(g.uniform(1, 200));
    return mat;
}

/// Light strengths in [0.1, 1) and attenuation c0 in [0.5, 1.5), c1 in [0, 0.2), c2 in [0, 0.05).
template <class T> phong::light<T> random_light(splitmix& g, const glm::vec<4, T>& position)
{
    phong::light<T> L;
    L.position = position;
    L.ambient = glm::vec<3, T>(T(0));
    L.diffuse = to<T>({g.uniform(0.1, 1), g.uniform(0.1, 1), g.uniform(0.1, 1)});
    L.specular = to<T>({g.uniform(0.1, 1), g.uniform(0.1, 1), g.uniform(0.1, 1)});
    L.attenuation.constant = T(g.uniform(0.5, 1.5));
    L.attenuation.linear = T(g.uniform(0, 0.2));
    L.attenuation.quadratic = T(g.uniform(0, 0.05));
    return L;
}

/// A point in front of the eye (perspective: the eye at the origin looking down -z).
inline glm::dvec3 random_point(splitmix& g) { return {g.uniform(-10, 10), g.uniform(-10, 10), g.uniform(-30, -2)}; }

/// A normal facing the viewer at Q (unit direction times a length in [0.5, 2)).
inline glm::dvec3 facing_normal(splitmix& g, const glm::dvec3& Q) { return g.unit_around(dnormalize(-Q), 0.05); }

/// The well-conditioned scene, in double; `scale` multiplies every coordinate (points, normal,
/// light positions) and divides c1 (c2 = 0 when scaled), so the scaled scene has the same colour.
template <class T> stiff_scene<T> well_conditioned(splitmix& g, double scale = 1)
{
    stiff_scene<T> s;
    const glm::dvec3 Q = random_point(g);
    s.position = to<T>(Q * scale);
    s.normal = to<T>(facing_normal(g, Q) * g.uniform(0.5, 2) * scale);
    s.material = random_material<T>(g);
    s.environment.ambient = to<T>({g.uniform(0, 0.3), g.uniform(0, 0.3), g.uniform(0, 0.3)});
    const int count = 1 + int(g.next() % 3);
    for (int i = 0; i < count; ++i) {
        const bool positional = g.next() % 2 == 0;
        const glm::dvec3 p = positional ? glm::dvec3(g.uniform(-20, 20), g.uniform(-20, 20), g.uniform(-25, 10))
                                        : g.unit() * g.uniform(0.5, 2);
        phong::light<T> L = random_light<T>(g, to<T>(p * scale, positional ? 1 : 0));
        if (scale != 1) {
            L.attenuation.linear = T(double(L.attenuation.linear) / scale);
            L.attenuation.quadratic = T(0);
        }
        s.lights.push_back(L);
    }
    return s;
}

/// Three strengths in [0.2, 1) rounded to T (a material's kd or ks), drawn in x, y, z order.
template <class T> glm::vec<3, T> random_strengths(splitmix& g) { return to<T>({g.uniform(0.2, 1), g.uniform(0.2, 1), g.uniform(0.2, 1)}); }

/// A light's homogeneous position (in double) at height c = n.l above the tangent plane of the
/// unit normal n at Q, in a random direction of that plane: positional at 1..10 from Q (w = 1)
/// or directional (w = 0, |xyz| in [0.5, 2)).
inline glm::dvec4 grazing_light_position(splitmix& g, const glm::dvec3& Q, const glm::dvec3& n, double c)
{
    const glm::dvec3 l = g.perpendicular(n) * std::sqrt(1 - c * c) + n * c;
    const bool positional = g.next() % 2 == 0;
    return positional ? glm::dvec4(Q + l * g.uniform(1, 10), 1) : glm::dvec4(l * g.uniform(0.5, 2), 0);
}

/// m = shininess near the peak: r at angle theta = k / sqrt(m), k in [0, 3), from v, so Phong's
/// exact factor (r.v)^m is at least exp(-4.5); h is then within about theta / 2 of n, so Blinn's
/// (n.h)^m is near its peak too. Specular only (ka = kd = 0).
template <class T> stiff_scene<T> near_peak(splitmix& g, double shininess)
{
    for (;;) {
        stiff_scene<T> s;
        const glm::dvec3 Q = random_point(g);
        const glm::dvec3 v = dnormalize(-Q);
        const glm::dvec3 n = g.unit_around(v, phong::accuracy::near_peak.min_nv);
        const double theta = g.uniform(0, phong::accuracy::near_peak.max_angle_sqrt_m) / std::sqrt(shininess);
        const glm::dvec3 r = v * std::cos(theta) + g.perpendicular(v) * std::sin(theta);
        const glm::dvec3 l = n * (2 * ddot(n, r)) - r; // reflect(-r, n)
        if (!(ddot(n, l) > phong::accuracy::near_peak.min_nl)) continue;
        s.position = to<T>(Q);
        s.normal = to<T>(n * g.uniform(0.5, 2));
        s.material.ka = s.material.kd = glm::vec<3, T>(T(0));
        s.material.ks = random_strengths<T>(g);
        s.material.shininess = T(shininess);
        const bool positional = g.next() % 2 == 0;
        const glm::dvec3 p = positional ? Q + l * g.uniform(2, 20) : l * g.uniform(0.5, 2);
        s.lights.push_back(random_light<T>(g, to<T>(p, positional ? 1 : 0)));
        return s;
    }
}

/// The exact n.l of a scene's first light, from the values in T.
template <class T> wide exact_nl(const stiff_scene<T>& s)
{
    const phong::light<T>& L = s.lights[0];
    const wvec3 d = wvec3{wide(L.position.x), wide(L.position.y), wide(L.position.z)} - widen(s.position) * wide(L.position.w);
    return wdot(wnormalize(widen(s.normal)), wnormalize(d));
}

/// n.l ~ 1e-6: the light direction at angle ~ 1e-6 above the tangent plane; kept when the exact
/// n.l of the rounded scene lies in [2.5e-7, 4e-6]. Diffuse only (ka = ks = 0).
template <class T> stiff_scene<T> grazing(splitmix& g)
{
    for (;;) {
        stiff_scene<T> s;
        const glm::dvec3 Q = random_point(g);
        const glm::dvec3 n = facing_normal(g, Q);
        const glm::dvec4 p = grazing_light_position(g, Q, n, g.uniform(0.5e-6, 2e-6));
        s.position = to<T>(Q);
        s.normal = to<T>(n * g.uniform(0.5, 2));
        s.material.ka = s.material.ks = glm::vec<3, T>(T(0));
        s.material.kd = random_strengths<T>(g);
        s.material.shininess = T(g.uniform(1, 200));
        s.lights.push_back(random_light<T>(g, to<T>(glm::dvec3(p), p.w)));
        const wide nl = exact_nl(s);
        if (nl >= wide(2.5e-7) && nl <= wide(4e-6)) return s;
    }
}

/// The exact specular cosines of light i of a scene: Phong's r.v and Blinn's n.h (h = 0 for l = -v),
/// from the values in T, eye at the origin (the view of accuracy::measured_features).
template <class T> void exact_cosines(const stiff_scene<T>& s, std::size_t i, wide& rv, wide& nh)
{
    const phong::light<T>& L = s.lights[i];
    const wvec3 Q = widen(s.position);
    const wvec3 l = wnormalize(wvec3{wide(L.position.x), wide(L.position.y), wide(L.position.z)} - Q * wide(L.position.w));
    const wvec3 n = wnormalize(widen(s.normal)), v = wnormalize(-Q);
    rv = wdot(n * (2 * wdot(n, l)) - l, v);
    nh = wdot(n, wnormalize(l + v));
}

/// Grazing light with a specular term: 1-4 lights, each at an angle ~ 2.5e-7 .. 3e-5 (log-uniform)
/// above the tangent plane, in a random direction of it, positional or directional; kd and ks in
/// [0.2, 1), m log-uniform in [1, 200]; no ambient (ka = 0, scene ambient 0), so a specular term
/// far from its peak ((r.v)^m down to ~1e-8) can outweigh the diffuse one, whose n.l is tiny.
/// Kept when every light's exact n.l lies in [2.5e-7, 3e-5] and both of its specular cosines
/// (r.v, n.h) lie outside (-5e-4, 0.05): the exact mode's class limits (exact_limits::c; the
/// stable mode near c = 0 is tested apart, tests/accuracy.test.cpp).
template <class T> stiff_scene<T> grazing_specular(splitmix& g)
{
    for (;;) {
        stiff_scene<T> s;
        const glm::dvec3 Q = random_point(g);
        const glm::dvec3 n = facing_normal(g, Q);
        s.position = to<T>(Q);
        s.normal = to<T>(n * g.uniform(0.5, 2));
        s.material.ka = glm::vec<3, T>(T(0));
        s.material.kd = random_strengths<T>(g);
        s.material.ks = random_strengths<T>(g);
        s.material.shininess = T(g.log_uniform(1, 200));
        const int count = 1 + int(g.next() % 4);
        for (int i = 0; i < count; ++i) {
            const glm::dvec4 p = grazing_light_position(g, Q, n, g.log_uniform(2.5e-7, 3e-5));
            s.lights.push_back(random_light<T>(g, to<T>(glm::dvec3(p), p.w)));
        }
        bool inside = true;
        for (std::size_t i = 0; i < s.lights.size(); ++i) {
            stiff_scene<T> one = s;
            one.lights = {s.lights[i]};
            const wide nl = exact_nl(one);
            wide rv, nh;
            exact_cosines(s, i, rv, nh);
            const auto near_zero = [](wide x) { return x > wide(-5e-4) && x < wide(0.05); };
            if (!(nl >= wide(2.5e-7) && nl <= wide(3e-5)) || near_zero(rv) || near_zero(nh)) inside = false;
        }
        if (inside) return s;
    }
}

/// Outside grazing_specular's exact-mode limits, on purpose: one grazing light (n.l log-uniform in
/// [1e-6, 3e-5], inside the class) whose specular cosine is near 0, where its term still outweighs the diffuse one
/// for small m (in [1, 4]). Phong: r.v = t (n.v) - s |v_t| cos(phi) set to c, log-uniform in
/// [1e-7, 0.05] (n.v in [0.2, 1]); Blinn: n.v log-uniform in [1e-6, 1e-2], so that
/// n.h = (n.l + n.v) / |l + v| is small. No ambient; kd, ks in [0.2, 1). Built in double from
/// the closed form (not by rejection, unlike the class generators), then rounded to T.
template <class T> stiff_scene<T> grazing_cosine_near_zero(splitmix& g, phong::specular_model S)
{
    stiff_scene<T> s;
    const glm::dvec3 Q = random_point(g);
    const glm::dvec3 v = dnormalize(-Q);
    const bool phong_model = S == phong::specular_model::phong;
    const double nv = phong_model ? g.uniform(0.2, 1) : g.log_uniform(1e-6, 1e-2);
    const glm::dvec3 a = g.perpendicular(v); // n = nv v + sqrt(1 - nv^2) a
    const glm::dvec3 n = v * nv + a * std::sqrt(1 - nv * nv);
    // The tangent frame (e1, e2) of n with v = nv n + sv e1.
    const double sv = std::sqrt(1 - nv * nv);
    const glm::dvec3 e1 = dnormalize(v - n * nv);
    const glm::dvec3 e2 = glm::dvec3(n.y * e1.z - n.z * e1.y, n.z * e1.x - n.x * e1.z, n.x * e1.y - n.y * e1.x);
    const double t = g.log_uniform(1e-6, 3e-5), st = std::sqrt(1 - t * t);
    double cos_phi = g.uniform(-1, 1);
    if (phong_model) cos_phi = (t * nv - g.log_uniform(1e-7, 0.05)) / (st * sv); // r.v = t nv - st sv cos(phi)
    const double sin_phi = std::sqrt(std::max(0.0, 1 - cos_phi * cos_phi)) * (g.next() % 2 == 0 ? 1 : -1);
    const glm::dvec3 l = n * t + (e1 * cos_phi + e2 * sin_phi) * st;
    s.position = to<T>(Q);
    s.normal = to<T>(n * g.uniform(0.5, 2));
    s.material.ka = glm::vec<3, T>(T(0));
    s.material.kd = random_strengths<T>(g);
    s.material.ks = random_strengths<T>(g);
    s.material.shininess = T(g.uniform(1, 4));
    s.lights.push_back(random_light<T>(g, to<T>(Q + l * g.uniform(1, 10), 1)));
    return s;
}

/// A positional light at distance ~ distance (x [0.5, 2)) from Q, Q at ~ 1000 * distance from
/// the eye (so L - Q is representable), the light above the surface.
template <class T> stiff_scene<T> near_light(splitmix& g, double distance, double c0_lo = 0.5)
{
    for (;;) {
        stiff_scene<T> s;
        const glm::dvec3 Q = dnormalize(random_point(g)) * (1000 * distance * g.uniform(0.5, 1));
        const glm::dvec3 n = facing_normal(g, Q);
        const glm::dvec3 l = g.unit_around(n, 0.1);
        s.position = to<T>(Q);
        s.normal = to<T>(n * g.uniform(0.5, 2));
        s.material = random_material<T>(g);
        s.environment.ambient = to<T>({g.uniform(0, 0.3), g.uniform(0, 0.3), g.uniform(0, 0.3)});
        s.lights.push_back(random_light<T>(g, to<T>(Q + l * (distance * g.uniform(0.5, 2)), 1)));
        if (c0_lo == 0) { // c0 = 0: 1 / (c1 d + c2 d^2), c1 = 0 half of the time
            s.lights[0].attenuation.constant = T(0);
            s.lights[0].attenuation.linear = T(g.next() % 2 == 0 ? 0 : g.uniform(0.1, 1));
            s.lights[0].attenuation.quadratic = T(g.uniform(0.1, 1));
        }
        if (exact_nl(s) > 0) return s; // rounding L can tip it below the horizon
    }
}

/// A directional light with xyz of length ~ length (x [0.5, 2)), above the surface.
template <class T> stiff_scene<T> tiny_directional(splitmix& g, double length)
{
    stiff_scene<T> s = well_conditioned<T>(g);
    s.lights.resize(1);
    const glm::dvec3 n = dnormalize(glm::dvec3(s.normal.x, s.normal.y, s.normal.z));
    s.lights[0].position = to<T>(g.unit_around(n, 0.1) * (length * g.uniform(0.5, 2)), 0);
    return s;
}

/// l = -v exactly: L = 2 Q (positional: L - Q = Q) or L.xyz = Q / 2 (directional), whose
/// normalizations are -v bit for bit; the normal faces the light (away from the viewer).
template <class T> stiff_scene<T> blinn_opposite(splitmix& g)
{
    stiff_scene<T> s = well_conditioned<T>(g);
    s.lights.resize(1);
    const glm::dvec3 Q(s.position.x, s.position.y, s.position.z);
    s.normal = to<T>(g.unit_around(dnormalize(Q), 0.1) * g.uniform(0.5, 2));
    const bool positional = g.next() % 2 == 0;
    s.lights[0].position = positional ? glm::vec<4, T>(s.position * T(2), T(1)) : glm::vec<4, T>(s.position * T(0.5), T(0));
    return s;
}

/// Subnormal inputs: the normal, a directional light's xyz and a positional light's c1, c2.
template <class T> stiff_scene<T> denormal(splitmix& g)
{
    stiff_scene<T> s = well_conditioned<T>(g);
    s.lights.clear();
    const double lo = subnormal_lo<T>(), hi = subnormal_hi<T>();
    const glm::dvec3 n = facing_normal(g, glm::dvec3(s.position.x, s.position.y, s.position.z));
    s.normal = to<T>(n * g.log_uniform(lo, hi));
    s.lights.push_back(random_light<T>(g, to<T>(g.unit_around(n, 0.1) * g.log_uniform(lo, hi), 0)));
    phong::light<T> L = random_light<T>(g, to<T>(glm::dvec3(g.uniform(-20, 20), g.uniform(-20, 20), g.uniform(-25, 10)), 1));
    L.attenuation.linear = T(g.log_uniform(lo, hi));
    L.attenuation.quadratic = T(g.log_uniform(lo, hi));
    s.lights.push_back(L);
    return s;
}

/// NaN or +-inf in one component of Q or of the normal.
template <class T> stiff_scene<T> non_finite(splitmix& g)
{
    stiff_scene<T> s = well_conditioned<T>(g);
    const T values[] = {std::numeric_limits<T>::quiet_NaN(), std::numeric_limits<T>::infinity(),
                        -std::numeric_limits<T>::infinity()};
    const T bad = values[g.next() % 3];
    const int k = int(g.next() % 3);
    if (g.next() % 2 == 0) s.position[k] = bad;
    else s.normal[k] = bad;
    return s;
}

} // namespace detail

/// n scenes of class c, reproducible from seed (the same seed gives the same scenes; scenes of
/// different classes or types use independent streams).
template <class T>
std::vector<stiff_scene<T>> make_class(input_class c, std::size_t n, std::uint64_t seed)
{
    splitmix g{seed ^ (0x51ed2705u * (std::uint64_t(c) + 1)) ^ (sizeof(T) == 4 ? 0 : 0xd1b54a32d192ed03ull)};
    std::vector<stiff_scene<T>> out;
    out.reserve(n);
    const double attenuation_lo = sizeof(T) == 4 ? 1e-30 : 1e-200;
    for (std::size_t i = 0; i < n; ++i) {
        switch (c) {
        case input_class::well_conditioned: out.push_back(detail::well_conditioned<T>(g)); break;
        case input_class::shininess_1e3: out.push_back(detail::near_peak<T>(g, 1e3)); break;
        case input_class::shininess_1e4: out.push_back(detail::near_peak<T>(g, 1e4)); break;
        case input_class::shininess_1e5: out.push_back(detail::near_peak<T>(g, 1e5)); break;
        case input_class::grazing: out.push_back(detail::grazing<T>(g)); break;
        case input_class::grazing_specular: out.push_back(detail::grazing_specular<T>(g)); break;
        case input_class::near_light_1e20: out.push_back(detail::near_light<T>(g, 1e-20)); break;
        case input_class::near_light_1e40: out.push_back(detail::near_light<T>(g, 1e-40)); break;
        case input_class::huge_1e20: out.push_back(detail::well_conditioned<T>(g, 1e20)); break;
        case input_class::huge_1e30: out.push_back(detail::well_conditioned<T>(g, 1e30)); break;
        case input_class::tiny_directional: out.push_back(detail::tiny_directional<T>(g, 1e-30)); break;
        case input_class::attenuation_c0_zero:
            out.push_back(detail::near_light<T>(g, g.log_uniform(attenuation_lo, 1e-1), 0));
            break;
        case input_class::blinn_opposite: out.push_back(detail::blinn_opposite<T>(g)); break;
        case input_class::denormal: out.push_back(detail::denormal<T>(g)); break;
        case input_class::shininess_zero: {
            stiff_scene<T> s = detail::well_conditioned<T>(g);
            s.material.shininess = T(0);
            out.push_back(s);
            break;
        }
        case input_class::non_finite: out.push_back(detail::non_finite<T>(g)); break;
        case input_class::count: break;
        }
    }
    return out;
}

/// Error statistics of computed channels against the reference.
struct error_stats {
    std::size_t channels = 0;  ///< channels compared
    std::size_t non_finite = 0; ///< computed NaN or inf
    double p50_ulp = 0, p99_ulp = 0, max_ulp = 0; ///< finite channels, ulp of the exact value in T
    double max_rel = 0;        ///< max |computed - exact| / |exact| over finite channels (absolute where exact = 0)
};

/// Accumulates channel errors; summary() gives the statistics.
class error_accumulator {
public:
    template <class T> void add(T computed, wide exact)
    {
        ++channels_;
        if (!finite_bits(computed)) {
            ++non_finite_;
            return;
        }
        ulp_.push_back(error_ulp<T>(computed, exact));
        max_rel_ = std::max(max_rel_, error_rel<T>(computed, exact));
    }
    error_stats summary()
    {
        error_stats e;
        e.channels = channels_;
        e.non_finite = non_finite_;
        e.max_rel = max_rel_;
        if (!ulp_.empty()) {
            std::sort(ulp_.begin(), ulp_.end());
            const auto at = [&](double q) { return ulp_[std::size_t(q * double(ulp_.size() - 1))]; };
            e.p50_ulp = at(0.5);
            e.p99_ulp = at(0.99);
            e.max_ulp = ulp_.back();
        }
        return e;
    }

private:
    std::vector<double> ulp_;
    double max_rel_ = 0;
    std::size_t channels_ = 0, non_finite_ = 0;
};

/// shade<F> of one scene.
template <phong::features F, class T> phong::color<F, T> shade_scene(const stiff_scene<T>& s)
{
    return phong::shade<F>(s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
}

/// The reference colour of one scene under F.
template <class T> wcolor reference_scene(const phong::features& F, const stiff_scene<T>& s)
{
    return reference_shade<T>(F, s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
}

/// Error statistics of shade<F> over the scenes, rgb channels, against reference_shade.
template <phong::features F, class T> error_stats measure(const std::vector<stiff_scene<T>>& scenes)
{
    error_accumulator acc;
    for (const stiff_scene<T>& s : scenes) {
        const auto c = shade_scene<F>(s);
        const wcolor r = reference_scene(F, s);
        for (int k = 0; k < 3; ++k) acc.add<T>(c[k], r[k]);
    }
    return acc.summary();
}

/// The same with the references computed once (they cost far more than shade): refs[i] is
/// reference_scene(F', scenes[i]) for any F' with the same model as F (the mode does not matter).
template <phong::features F, class T>
error_stats measure(const std::vector<stiff_scene<T>>& scenes, const std::vector<wcolor>& refs)
{
    error_accumulator acc;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const auto c = shade_scene<F>(scenes[i]);
        for (int k = 0; k < 3; ++k) acc.add<T>(c[k], refs[i][k]);
    }
    return acc.summary();
}

/// reference_scene(F, s) for every scene.
template <class T> std::vector<wcolor> references(const phong::features& F, const std::vector<stiff_scene<T>>& scenes)
{
    std::vector<wcolor> out;
    out.reserve(scenes.size());
    for (const stiff_scene<T>& s : scenes) out.push_back(reference_scene(F, s));
    return out;
}

} // namespace phong_test
