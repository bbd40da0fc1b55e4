// Benchmark inputs: reproducible scenes (points, normals, lights, material) in float and double.
//
// Every value is generated in double, rounded once to float, and the double inputs are that float
// widened exactly: float and double rows see the same geometric inputs, so they share one
// high-precision reference and their error columns compare like with like. Each point is a pure
// function of (set, index) (a counter-based hash), so a sample of a 4M-point set costs nothing
// extra to regenerate and two runs produce identical inputs on any platform.
#pragma once

#include <phong/phong.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace phong_bench {

/// splitmix64: a counter-based hash, so point i of a set does not depend on the others.
inline std::uint64_t mix(std::uint64_t x)
{
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

/// Uniform in [0, 1) from (stream, index, component): 53 random bits.
inline double uniform(std::uint64_t stream, std::uint64_t index, unsigned component)
{
    const std::uint64_t h = mix(mix(stream * 0x100000001b3ull + component) ^ index);
    return double(h >> 11) * 0x1.0p-53;
}
inline double uniform(std::uint64_t stream, std::uint64_t index, unsigned component, double lo, double hi)
{
    return lo + (hi - lo) * uniform(stream, index, component);
}

using dvec3 = glm::dvec3;

/// x rounded to float and widened back: the value both precisions will see.
/// A scalar noinline function on purpose: g++ 12 -O2 miscompiled the vector form
/// dvec3(float(v.x), float(v.y), float(v.z)) in this translation unit (its SLP vectorizer copied x
/// and y unrounded; only z was rounded), which the error counters caught as a 1e-2 "error".
[[gnu::noinline]] inline double to_float(double x)
{
    return static_cast<double>(static_cast<float>(x));
}
inline dvec3 to_float_grid(dvec3 v) { return {to_float(v.x), to_float(v.y), to_float(v.z)}; }

/// The kinds of input the benchmarks shade.
enum class input_set {
    typical,   ///< a lit sphere in front of the camera, lights around it, m = 32 (a renderer's frame)
    highlight, ///< stiff: m = 1e4, every point near the mirror direction of one light (r.v ~ 1 - 1e-4)
    grazing,   ///< stiff: every light in the tangent plane up to n.l ~ 1e-6 .. 1e-5, components O(1)
};

inline const char* name(input_set s)
{
    switch (s) {
    case input_set::typical: return "typical";
    case input_set::highlight: return "stiff_highlight_m1e4";
    case input_set::grazing: return "stiff_grazing_nl1e-6";
    }
    return "?";
}

/// One scene in double precision (already on the float grid): positional lights (w = 1) or
/// directional ones (w = 0), the material and the scene's ambient light.
struct scene {
    std::vector<dvec3> position, normal;
    std::vector<glm::dvec4> light_position;
    std::vector<dvec3> light_ambient, light_diffuse, light_specular;
    std::vector<dvec3> spot_axis;      // unit, on the float grid (renormalized in double, then rounded)
    dvec3 ka{0.1, 0.1, 0.1}, kd{0.7, 0.45, 0.3}, ks{0.35, 0.35, 0.35};
    double shininess = 32;
    dvec3 scene_ambient{0.1, 0.1, 0.12};
};

/// A random unit vector (uniform on the sphere) from three uniforms.
inline dvec3 unit_vector(std::uint64_t stream, std::uint64_t index, unsigned c0)
{
    const double z = uniform(stream, index, c0, -1, 1);
    const double phi = uniform(stream, index, c0 + 1, 0, 6.283185307179586);
    const double r = std::sqrt(1 - z * z);
    return {r * std::cos(phi), r * std::sin(phi), z};
}

/// A right-handed orthonormal frame (t1, t2, n) around the unit vector n.
inline void frame(dvec3 n, dvec3& t1, dvec3& t2)
{
    const dvec3 a = std::abs(n.x) < 0.6 ? dvec3(1, 0, 0) : dvec3(0, 1, 0);
    t1 = glm::normalize(glm::cross(a, n));
    t2 = glm::cross(n, t1);
}

/// Lights for `set`: positional, at 2..6 units from the scene's centre (typical, highlight), or in
/// one plane (grazing). Strengths in [0.3, 1], per-light ambient 0.04 (0 for the stiff sets, so
/// their hard terms are not hidden under an ambient floor).
inline void make_lights(scene& s, input_set set, std::size_t K)
{
    const std::uint64_t stream = 1000 + static_cast<std::uint64_t>(set);
    const dvec3 centre(0, 0, -4);
    dvec3 t1, t2;
    const dvec3 plane_normal = glm::normalize(dvec3(0.48, 0.6, 0.64));
    frame(plane_normal, t1, t2);
    for (std::size_t i = 0; i < K; ++i) {
        dvec3 p;
        if (set == input_set::grazing) {
            // In the plane through the centre with normal plane_normal, 2..6 units away.
            const double a = uniform(stream, i, 0, 0, 6.283185307179586), r = uniform(stream, i, 1, 2, 6);
            p = centre + t1 * (r * std::cos(a)) + t2 * (r * std::sin(a));
        } else {
            // On the viewer's side of the sphere (z > -4), 2..6 units from its centre.
            dvec3 u = unit_vector(stream, i, 0);
            u.z = std::abs(u.z) * 0.8 + 0.2;
            p = centre + glm::normalize(u) * uniform(stream, i, 3, 2, 6);
        }
        s.light_position.push_back(glm::dvec4(to_float_grid(p), 1));
        const double strength = uniform(stream, i, 4, 0.3, 1);
        const dvec3 tint(uniform(stream, i, 5, 0.8, 1), uniform(stream, i, 6, 0.8, 1), uniform(stream, i, 7, 0.8, 1));
        s.light_diffuse.push_back(to_float_grid(tint * strength));
        s.light_specular.push_back(to_float_grid(tint * strength));
        s.light_ambient.push_back(to_float_grid(dvec3(set == input_set::typical ? 0.04 : 0.0)));
        // A spot axis from the light toward the sphere's centre (used by the feature presets).
        s.spot_axis.push_back(glm::normalize(centre - p));
    }
}

/// Point i of `set` (position and normal, on the float grid), given the scene's lights.
inline void make_point(const scene& s, input_set set, std::uint64_t i, dvec3& q, dvec3& n)
{
    const std::uint64_t stream = 2000 + static_cast<std::uint64_t>(set);
    const dvec3 centre(0, 0, -4);
    if (set == input_set::typical) {
        // The visible half of a unit sphere centred at (0, 0, -4): n.v > 0 up to its silhouette.
        dvec3 u = unit_vector(stream, i, 0);
        u.z = std::abs(u.z);
        q = centre + u;
        n = u;
    } else if (set == input_set::highlight) {
        // Near the mirror direction of light j = i mod K: r = reflect(-l, n) within ~2/sqrt(m) of v,
        // so (r.v)^m with m = 1e4 spans [e^-4, 1]. Built backwards: pick Q and n, then put the
        // light's mirror image ... here the light is fixed, so pick n as the (perturbed) bisector of
        // l and v at a random Q on the sphere: then r is v rotated by twice the perturbation.
        const std::size_t K = s.light_position.size();
        const glm::dvec4 L = s.light_position[i % K];
        dvec3 u = unit_vector(stream, i, 0);
        u.z = std::abs(u.z);
        q = centre + u;
        const dvec3 l = glm::normalize(dvec3(L) - q), v = glm::normalize(-q);
        dvec3 h = glm::normalize(l + v), t1, t2;
        frame(h, t1, t2);
        const double angle = uniform(stream, i, 2, 0, 1.0 / std::sqrt(1e4)); // |r - v| ~ 2 angle
        const double phi = uniform(stream, i, 3, 0, 6.283185307179586);
        n = glm::normalize(h + (t1 * std::cos(phi) + t2 * std::sin(phi)) * std::tan(angle));
    } else {
        // The plane of the lights, offset by h along its normal: n.l = h / |d| ~ 1e-6 .. 1e-5 with
        // every component of n and l of order 1 (so n.l cancels in floating point).
        const dvec3 plane_normal = glm::normalize(dvec3(0.48, 0.6, 0.64));
        dvec3 t1, t2;
        frame(plane_normal, t1, t2);
        const double x = uniform(stream, i, 0, -1, 1), y = uniform(stream, i, 1, -1, 1);
        const double h = uniform(stream, i, 2, 0.5e-5, 2e-5);
        q = centre + t1 * x + t2 * y - plane_normal * h;
        n = plane_normal;
    }
    q = to_float_grid(q);
    n = to_float_grid(n);
}

/// The same scene in number type T: AoS arrays of points and normals, phong lights and material,
/// and the naive baseline's own light structs are built from these.
template <class T>
struct points {
    std::vector<glm::vec<3, T>> position, normal;
};

/// Float points as SoA arrays, with SoA colour outputs r, g, b of the same length: the layout of
/// the hand-written kernel (support/hand_simd.hpp) and of shade_batch's soa3 inputs.
struct soa_float_points {
    std::vector<float> px, py, pz, nx, ny, nz, r, g, b;
    explicit soa_float_points(const points<float>& pts)
    {
        for (std::vector<float>* v : {&px, &py, &pz, &nx, &ny, &nz, &r, &g, &b}) v->resize(pts.position.size());
        for (std::size_t i = 0; i < pts.position.size(); ++i) {
            px[i] = pts.position[i].x, py[i] = pts.position[i].y, pz[i] = pts.position[i].z;
            nx[i] = pts.normal[i].x, ny[i] = pts.normal[i].y, nz[i] = pts.normal[i].z;
        }
    }
};

template <class T>
phong::material<T> material_of(const scene& s)
{
    phong::material<T> m;
    // On the float grid, like every other input: float and double rows see the same numbers.
    m.ka = glm::vec<3, T>(to_float_grid(s.ka));
    m.kd = glm::vec<3, T>(to_float_grid(s.kd));
    m.ks = glm::vec<3, T>(to_float_grid(s.ks));
    m.shininess = T(s.shininess);
    return m;
}

/// How a scene's lights are handed to phong. `plain`: positional, no attenuation, no spot (the
/// seed 003 model). `directional`: w = 0, xyz the direction toward the light seen from the
/// sphere's centre (the directional limit of the same light). `attenuated_spot`: positional with
/// OpenGL attenuation (1, 0.09, 0.032) and a spot cone (exponent 8, cutoff 60 degrees) aimed at
/// the sphere's centre, for the feature presets.
enum class light_style { plain, directional, attenuated_spot };

template <class T>
std::vector<phong::light<T>> lights_of(const scene& s, light_style style = light_style::plain)
{
    std::vector<phong::light<T>> out;
    for (std::size_t i = 0; i < s.light_position.size(); ++i) {
        phong::light<T> L;
        glm::dvec4 p = s.light_position[i];
        if (style == light_style::directional) p = glm::dvec4(to_float_grid(glm::normalize(dvec3(p) - dvec3(0, 0, -4))), 0);
        L.position = glm::vec<4, T>(p);
        L.ambient = glm::vec<3, T>(s.light_ambient[i]);
        L.diffuse = glm::vec<3, T>(s.light_diffuse[i]);
        L.specular = glm::vec<3, T>(s.light_specular[i]);
        if (style == light_style::attenuated_spot) {
            // Float-grid values, so the float and double lights are the same numbers.
            L.attenuation = {T(1), T(0.09f), T(0.032f)};
            L.spot.direction = glm::vec<3, T>(to_float_grid(s.spot_axis[i]));
            L.spot.exponent = T(8);
            L.spot.cos_cutoff = T(0.5); // 60 degrees
        }
        out.push_back(L);
    }
    return out;
}

template <class T>
phong::environment<T> environment_of(const scene& s)
{
    phong::environment<T> env;
    env.ambient = glm::vec<3, T>(to_float_grid(s.scene_ambient));
    return env;
}

/// The scene (lights, material) of (set, K). Light i depends only on i: the lights of K = 4 are
/// the first four of K = 16.
inline scene make_scene(input_set set, std::size_t K)
{
    scene sc;
    make_lights(sc, set, K);
    if (set == input_set::highlight) sc.shininess = 1e4;
    return sc;
}

/// The N points of (set, K) in T (only the highlight set's points depend on the lights).
template <class T>
points<T> make_points(input_set set, std::size_t N, std::size_t K)
{
    const scene sc = make_scene(set, K);
    points<T> pts;
    pts.position.resize(N);
    pts.normal.resize(N);
    for (std::size_t i = 0; i < N; ++i) {
        dvec3 q, n;
        make_point(sc, set, i, q, n);
        pts.position[i] = glm::vec<3, T>(q);
        pts.normal[i] = glm::vec<3, T>(n);
    }
    return pts;
}

} // namespace phong_bench
