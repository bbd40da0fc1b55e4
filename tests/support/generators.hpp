// Test support: random scenes. Two sources of inputs, for two kinds of tests:
//  * scene_gen<T>: a deterministic sweep (std::mt19937_64 with a fixed seed) producing whole
//    scenes for comparisons against the reference over many feature sets;
//  * rc generators (gen_*): RapidCheck generators built from integer grids (see property.hpp),
//    for property tests that shrink to a small counterexample.
// And `well_conditioned`: whether a scene is far enough from the model's discontinuities (gate,
// cutoff, two-sided flip, l = -v, light at Q) that a small rounding cannot move it across one,
// evaluated in the wide type.
#pragma once

#include "property.hpp"
#include "wide.hpp"

#include <phong/inputs/features.hpp>
#include <phong/inputs/light.hpp>
#include <phong/inputs/material.hpp>
#include <phong/sum/shade.hpp>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

namespace phong_test {

/// One shading problem: the arguments of phong::shade.
template <class T>
struct scene {
    glm::vec<3, T> position{T(0), T(0), T(-3)};
    glm::vec<3, T> normal{T(0), T(0), T(1)};
    phong::material<T> mat{};
    std::vector<phong::light<T>> lights;
    phong::environment<T> env{};
    bool front_facing = true;
};

/// Deterministic random scenes. All values are drawn in double and rounded once to T, so the
/// inputs are exactly representable in T and the reference sees exactly what the library sees.
template <class T>
class scene_gen {
public:
    explicit scene_gen(std::uint64_t seed) : rng_(seed) {}

    /// d rounded once to T, through a volatile, so that the scene holds T values whatever the
    /// optimizer does: g++ 12 (-O2 and up) folds a rounding to float and phong's widening back to
    /// double, once SLP-vectorized in pairs, (vector(2) double)(vector(2) float) x, to x (a wrong-code
    /// fold of its value numbering), so with shade<F> inlined into the generating loop the wider
    /// route saw the unrounded doubles (docs/compilers.md, "Inlining").
    static T rounded(double d)
    {
        volatile T r = static_cast<T>(d);
        return r;
    }

    // The draws below are libstdc++'s std::uniform_real_distribution, uniform_int_distribution,
    // bernoulli_distribution and normal_distribution written out: the standard fixes the engine's
    // sequence but not the distributions', so libc++ (macOS, Android) drew other scenes, and a test
    // that needs a highlight among its points found none there.
    T uniform(double lo, double hi) { return rounded(canonical() * (hi - lo) + lo); }
    int integer(int lo, int hi)
    {
        // Lemire's multiply-and-reject on the 64-bit draw (libstdc++ 12).
        const std::uint64_t range = std::uint64_t(std::int64_t(hi) - lo) + 1;
        wide_product p = multiply(rng_(), range);
        if (p.low < range) {
            const std::uint64_t threshold = (0 - range) % range;
            while (p.low < threshold) p = multiply(rng_(), range);
        }
        return int(std::int64_t(lo) + std::int64_t(p.high));
    }
    bool coin(double p = 0.5) { return canonical() < p; }

    glm::vec<3, T> in_box(double lo, double hi) { return {uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)}; }
    glm::vec<3, T> color(double lo = 0, double hi = 1) { return in_box(lo, hi); }

    /// A direction uniform on the sphere, rounded to T (so only nearly unit).
    glm::vec<3, T> direction()
    {
        double x, y, z, n;
        do {
            double pair[2];
            polar_pair(pair); // y, then the saved x (a fresh std::normal_distribution per call)
            x = pair[0], y = pair[1];
            polar_pair(pair);
            z = pair[0];
            n = std::sqrt(x * x + y * y + z * z);
        } while (n < 1e-3);
        return {rounded(x / n), rounded(y / n), rounded(z / n)};
    }

    /// A surface point in front of the eye (eye coordinates look down -z).
    glm::vec<3, T> point() { return {uniform(-3, 3), uniform(-3, 3), uniform(-9, -1)}; }

    /// A material with coefficients in [0, 1], shininess in [m_lo, m_hi], alpha in [0, 1].
    phong::material<T> material(double m_lo = 1, double m_hi = 64)
    {
        phong::material<T> m;
        m.ka = color();
        m.kd = color();
        m.ks = color();
        m.emission = color(0, 0.5);
        m.shininess = uniform(m_lo, m_hi);
        m.alpha = uniform(0, 1);
        return m;
    }

    /// A light near the point Q: positional (w = 1; `any_w` only consumes the draws that once chose w = 0.5 or 2) or
    /// directional, with strengths in [0, 1], attenuation coefficients, a range beyond Q and spot
    /// cones (both parametrizations) whose axis points roughly at Q.
    phong::light<T> light(const glm::vec<3, T>& Q, bool directional, bool any_w = false)
    {
        phong::light<T> L;
        glm::vec<3, double> to_light; // from Q toward the light, for the spot axis
        if (directional) {
            const glm::vec<3, T> d = direction();
            const double s = uniform(0.5, 4);
            L.position = {rounded(d.x * s), rounded(d.y * s), rounded(d.z * s), T(0)};
            to_light = glm::vec<3, double>(L.position);
        } else {
            const glm::vec<3, T> p = {rounded(Q.x + uniform(-5, 5)), rounded(Q.y + uniform(-5, 5)), rounded(Q.z + uniform(-5, 5))};
            // validate(light) accepts w = 1 only for a positional light (issue 15): the draws that
            // picked w = 0.5 or 2 here are kept, so the rest of the random stream is unchanged.
            if (any_w && coin(0.3)) (void)coin();
            L.position = {p.x, p.y, p.z, T(1)};
            to_light = glm::vec<3, double>(p) - glm::vec<3, double>(Q);
        }
        L.ambient = color(0, 0.5);
        L.diffuse = color();
        L.specular = color();
        L.attenuation.constant = uniform(0.25, 1);
        L.attenuation.linear = uniform(0, 0.5);
        L.attenuation.quadratic = uniform(0, 0.25);
        const double dist = std::sqrt(to_light.x * to_light.x + to_light.y * to_light.y + to_light.z * to_light.z);
        L.attenuation.range = rounded(dist * double(uniform(1.1, 3)));
        // Spot axis: from the light toward Q, tilted by up to ~25 degrees.
        glm::vec<3, double> axis = -to_light / dist;
        const glm::vec<3, T> jitter = direction();
        axis += glm::vec<3, double>(jitter) * double(uniform(0, 0.45));
        axis /= std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
        const glm::vec<3, T> axis_t(rounded(axis.x), rounded(axis.y), rounded(axis.z));
        const phong::spot_cone<T> gl = phong::spot_cone<T>::opengl(axis_t, uniform(0, 8), coin(0.2) ? T(180) : uniform(15, 90));
        const double inner = double(uniform(2, 30));
        const phong::spot_cone<T> sm = phong::spot_cone<T>::smooth(axis_t, rounded(inner), rounded(inner + double(uniform(0, 30))));
        L.spot = gl;
        L.spot.cos_inner = sm.cos_inner;
        L.spot.cos_outer = sm.cos_outer;
        return L;
    }

    /// The eye for the view model: ignored (perspective), a direction toward the viewer
    /// (orthographic) or a homogeneous point, w = 1 or w = 0 (eye_point).
    glm::vec<4, T> eye(phong::view_model view)
    {
        using phong::view_model;
        if (view == view_model::fixed_direction) return {uniform(-0.5, 0.5), uniform(-0.5, 0.5), uniform(0.5, 2), T(0)};
        if (view == view_model::eye_point) {
            if (coin(0.2)) return {uniform(-0.5, 0.5), uniform(-0.5, 0.5), T(1), T(0)};
            return {uniform(-2, 2), uniform(-2, 2), uniform(0, 4), T(1)};
        }
        return {T(0), T(0), T(0), T(1)};
    }

    /// A whole scene with n_lights lights of the kinds F allows.
    scene<T> make(const phong::features& F, int n_lights, double m_lo = 1, double m_hi = 64)
    {
        scene<T> s;
        s.position = point();
        s.normal = direction() * uniform(0.25, 4); // any length: shade normalizes
        s.mat = material(m_lo, m_hi);
        for (int i = 0; i < n_lights; ++i) {
            const bool directional = F.lights == phong::light_kind::directional ||
                                     (F.lights == phong::light_kind::any && coin(0.4));
            s.lights.push_back(light(s.position, directional, F.lights == phong::light_kind::any));
        }
        s.env.ambient = color(0, 0.5);
        s.env.eye = eye(F.view);
        s.front_facing = coin();
        return s;
    }

private:
    /// a b as 128 bits, from 32-bit halves (no __int128 on 32-bit targets and MSVC).
    struct wide_product {
        std::uint64_t high, low;
    };
    static wide_product multiply(std::uint64_t a, std::uint64_t b)
    {
        const std::uint64_t a0 = a & 0xffffffffu, a1 = a >> 32, b0 = b & 0xffffffffu, b1 = b >> 32;
        const std::uint64_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
        const std::uint64_t middle = (p00 >> 32) + (p01 & 0xffffffffu) + (p10 & 0xffffffffu);
        return {p11 + (p01 >> 32) + (p10 >> 32) + (middle >> 32), (middle << 32) | (p00 & 0xffffffffu)};
    }
    /// [0, 1): the 64-bit draw over 2^64, rounded (std::generate_canonical<double, 53>).
    double canonical()
    {
        const double u = double(rng_()) * 0x1p-64;
        return u < 1 ? u : std::nextafter(1.0, 0.0);
    }
    /// Two standard normal values by Marsaglia's polar method, in the order
    /// std::normal_distribution returns them.
    void polar_pair(double (&out)[2])
    {
        double x, y, r2;
        do {
            x = 2.0 * canonical() - 1.0;
            y = 2.0 * canonical() - 1.0;
            r2 = x * x + y * y;
        } while (r2 > 1.0 || r2 == 0.0);
        const double mult = std::sqrt(-2 * std::log(r2) / r2);
        out[0] = y * mult;
        out[1] = x * mult;
    }
    std::mt19937_64 rng_;
};

/// Whether shade<F> on s is at least `margin` (in cosine or relative distance units) away from
/// every discontinuity of the model, so float rounding cannot flip a branch: the n.l gate and
/// the diffuse kink, the two-sided flip (n.v), Blinn's l = -v, the OpenGL cutoff, the smooth
/// cone's ends, a light at Q. Evaluated in the wide type from the inputs.
template <class T>
bool well_conditioned(const phong::features& F, const scene<T>& s, double margin = 1e-3)
{
    using namespace phong;
    const wvec3 Q = widen(s.position);
    const wvec3 eye{wide(s.env.eye.x), wide(s.env.eye.y), wide(s.env.eye.z)};
    wvec3 v;
    if (F.view == view_model::eye_at_origin) v = wnormalize(-Q);
    else if (F.view == view_model::fixed_direction) v = wnormalize(eye);
    else v = wnormalize(eye - Q * wide(s.env.eye.w));
    if (wdot(v, v) < 0.5) return false;
    wvec3 n = wnormalize(widen(s.normal));
    if (wabs(wdot(n, v)) < margin) return false;
    if (F.two_sided == facing::view && wdot(n, v) < 0) n = -n;
    if (F.two_sided == facing::flag && !s.front_facing) n = -n;
    for (const light<T>& L : s.lights) {
        const wide w = F.lights == light_kind::directional ? wide(0)
                     : F.lights == light_kind::positional  ? wide(1)
                                                           : wide(L.position.w);
        const wvec3 d = wvec3{wide(L.position.x), wide(L.position.y), wide(L.position.z)} - Q * w;
        if (wlength(d) < margin) return false;
        const wvec3 l = wnormalize(d);
        if (wabs(wdot(n, l)) < margin) return false;
        const wvec3 lv = l + v;
        if (wlength(lv) < margin) return false;
        const wide c = -wdot(l, widen(L.spot.direction));
        if (F.spot == spot_model::opengl && wabs(c - wide(L.spot.cos_cutoff)) < margin) return false;
        if ((F.spot == spot_model::smooth || F.spot == spot_model::linear) &&
            (wabs(c - wide(L.spot.cos_inner)) < margin || wabs(c - wide(L.spot.cos_outer)) < margin)) return false;
        if (F.attenuation == attenuation_model::windowed && w > 0 &&
            wabs(wlength(d) / w - wide(L.attenuation.range)) < margin * wide(L.attenuation.range)) return false;
        // The specular base at 0: the clamp's kink (harmless) but also pow(0, m) vs tiny values.
    }
    return true;
}

// ---------------------------------------------------------------------------------------------
// RapidCheck generators (integer grids; see property.hpp).

/// A vector with components on the grid {lo..hi} * step.
template <class T>
rc::Gen<glm::vec<3, T>> gen_vec3(int lo, int hi, T step)
{
    return rc::gen::map(rc::gen::tuple(grid<T>(lo, hi, step), grid<T>(lo, hi, step), grid<T>(lo, hi, step)),
                        [](const std::tuple<T, T, T>& t) { return glm::vec<3, T>(std::get<0>(t), std::get<1>(t), std::get<2>(t)); });
}

/// A nonzero vector with components on the grid {lo..hi} * step.
template <class T>
rc::Gen<glm::vec<3, T>> gen_nonzero_vec3(int lo, int hi, T step)
{
    return rc::gen::suchThat(gen_vec3<T>(lo, hi, step), [](const glm::vec<3, T>& v) { return v != glm::vec<3, T>(T(0)); });
}

/// An rgb colour with channels in [0, 1] on a grid of 1/steps.
template <class T>
rc::Gen<glm::vec<3, T>> gen_color(int steps = 64)
{
    return gen_vec3<T>(0, steps, T(1) / T(steps));
}

/// A valid material: coefficients in [0, 1], emission in [0, 1], shininess in [0, m_max] on a
/// grid of 1/4, alpha in [0, 1].
template <class T>
rc::Gen<phong::material<T>> gen_material(int m_max = 128)
{
    return rc::gen::map(rc::gen::tuple(gen_color<T>(), gen_color<T>(), gen_color<T>(), gen_color<T>(),
                                       grid<T>(0, 4 * m_max, T(0.25)), grid<T>(0, 64, T(1) / T(64))),
                        [](const auto& t) {
                            phong::material<T> m;
                            m.ka = std::get<0>(t);
                            m.kd = std::get<1>(t);
                            m.ks = std::get<2>(t);
                            m.emission = std::get<3>(t);
                            m.shininess = std::get<4>(t);
                            m.alpha = std::get<5>(t);
                            return m;
                        });
}

/// A valid light with strengths in [0, 1]: positional (w = 1) with position on a grid in
/// [-8, 8]^3, or directional (w = 0) with a nonzero direction; default attenuation and spot.
template <class T>
rc::Gen<phong::light<T>> gen_light(bool directional)
{
    return rc::gen::map(rc::gen::tuple(gen_nonzero_vec3<T>(-32, 32, T(0.25)), gen_color<T>(), gen_color<T>(), gen_color<T>()),
                        [directional](const auto& t) {
                            phong::light<T> L;
                            const glm::vec<3, T> p = std::get<0>(t);
                            L.position = glm::vec<4, T>(p, directional ? T(0) : T(1));
                            L.ambient = std::get<1>(t);
                            L.diffuse = std::get<2>(t);
                            L.specular = std::get<3>(t);
                            return L;
                        });
}

} // namespace phong_test
