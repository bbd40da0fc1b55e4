// phong/sum/shade.hpp: shade<F> by hand, on every kind of light container, on the documented
// degenerate inputs (both evaluation modes), and against the __float128 reference model
// (tests/support/reference.hpp) over a strength-2 covering array of the feature options.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/reference.hpp"

#include <phong/sum/shade.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

using namespace phong_test;
using phong::evaluation;
using phong::features;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;

constexpr features with(features f, evaluation mode) { return phong::presets::with_mode(f, mode); }

// Every channel of a equals b within `ulps` ulp relative to the largest channel of b (floor 1e-30).
template <glm::length_t L, class T> bool close(const glm::vec<L, T>& a, const glm::vec<L, T>& b, int ulps)
{
    T scale = T(1e-30);
    for (glm::length_t k = 0; k < L; ++k) scale = std::max(scale, std::abs(b[k]));
    for (glm::length_t k = 0; k < L; ++k)
        if (!(std::abs(a[k] - b[k]) <= tolerance<T>::rel(ulps) * scale)) return false;
    return true;
}

// Error of c against the reference in eps relative to the largest reference channel.
template <glm::length_t L, class T> double error_eps(const glm::vec<L, T>& c, const wcolor& ref)
{
    wide scale = 0;
    for (glm::length_t k = 0; k < L; ++k) scale = wmax(scale, wabs(ref[int(k)]));
    if (scale == 0) scale = 1;
    double worst = 0;
    for (glm::length_t k = 0; k < L; ++k) {
        if (!std::isfinite(c[k])) return std::numeric_limits<double>::infinity();
        worst = std::max(worst, double(wabs(wide(c[k]) - ref[int(k)]) / scale / wide(tolerance<T>::eps)));
    }
    return worst;
}
} // namespace

// ---------------------------------------------------------------------------------------------
// By hand.

TEST_CASE_TEMPLATE("shade: one light straight above the point, by hand", T, float, double)
{
    // Q = (0, 0, -2), n = (0, 0, 1), light at the eye (0, 0, 0): l = v = r = n = (0, 0, 1), so
    // n.l = r.v = n.h = 1 and I = ka La + kd Ld + ks Ls for any m, Phong or Blinn.
    phong::material<T> mat;
    mat.ka = vec3<T>(0.5, 0.25, 0.125);
    mat.kd = vec3<T>(0.25, 0.5, 0.75);
    mat.ks = vec3<T>(0.125, 0.25, 0.0625);
    mat.shininess = T(37);
    const std::array<phong::light<T>, 1> lights{phong::light<T>::with_strength(vec4<T>(0, 0, 0, 1), vec3<T>(1, 0.5, 2))};
    phong::environment<T> env;
    env.ambient = vec3<T>(0.5, 1, 0.25);
    // 0.5*0.5 + 0.25*1 + 0.125*1 = 0.625; 0.25*1 + 0.5*0.5 + 0.25*0.5 = 0.625;
    // 0.125*0.25 + 0.75*2 + 0.0625*2 = 1.65625. All exact in binary.
    const vec3<T> expected(0.625, 0.625, 1.65625);
    const vec3<T> Q(0, 0, -2), n(0, 0, 1);
    CHECK(close(phong::shade<features{}>(Q, n, mat, lights, env), expected, 4));
    CHECK(close(phong::shade<with(features{}, evaluation::stable)>(Q, n, mat, lights, env), expected, 4));
    constexpr features blinn{.specular = phong::specular_model::blinn};
    CHECK(close(phong::shade<blinn>(Q, n, mat, lights, env), expected, 4));
    CHECK(close(phong::shade<with(blinn, evaluation::stable)>(Q, n, mat, lights, env), expected, 4));
    // Emission and alpha: added and appended.
    mat.emission = vec3<T>(0.25);
    mat.alpha = T(0.75);
    constexpr features ea{.emission = true, .alpha = true};
    const vec4<T> c = phong::shade<ea>(Q, n, mat, lights, env);
    CHECK(close(c, vec4<T>(expected + T(0.25), T(0.75)), 4));
    CHECK(c.a == T(0.75));
}

TEST_CASE_TEMPLATE("shade: 45 degree directional light with attenuation ignored, by hand", T, float, double)
{
    // Directional light along (1, 0, 1), Q = (0, 0, -1), n = (0, 0, 1), v = (0, 0, 1):
    // n.l = 1/sqrt2, (r.v)^2 = 1/2, (n.h)^2 = (2 + sqrt2)/4. Attenuation is not applied to
    // directional lights (w = 0), even when the light carries coefficients.
    phong::material<T> mat;
    mat.ka = vec3<T>(0);
    mat.kd = vec3<T>(1, 0, 0);
    mat.ks = vec3<T>(0, 1, 0);
    mat.shininess = T(2);
    phong::light<T> L = phong::light<T>::with_strength(vec4<T>(1, 0, 1, 0), vec3<T>(1));
    L.attenuation = {T(3), T(3), T(3), T(0.5)};
    const std::vector<phong::light<T>> lights{L};
    const vec3<T> Q(0, 0, -1), n(0, 0, 1);
    const T s = std::sqrt(T(0.5));
    constexpr features base{.scene_ambient = false, .attenuation = phong::attenuation_model::polynomial};
    CHECK(close(phong::shade<base>(Q, n, mat, lights), vec3<T>(s, 0.5, 0), 8));
    constexpr features windowed{.scene_ambient = false, .specular = phong::specular_model::blinn,
                                .attenuation = phong::attenuation_model::windowed};
    const T blinn = T((2 + std::sqrt(2.0L)) / 4);
    CHECK(close(phong::shade<windowed>(Q, n, mat, lights), vec3<T>(s, blinn, 0), 8));
    CHECK(close(phong::shade<with(windowed, evaluation::stable)>(Q, n, mat, lights), vec3<T>(s, blinn, 0), 8));
}

TEST_CASE_TEMPLATE("shade: std::array, std::span and std::vector give the same colour", T, float, double)
{
    scene_gen<T> g(99);
    constexpr features F{.light_ambient = true, .attenuation = phong::attenuation_model::polynomial,
                         .spot = phong::spot_model::opengl, .two_sided = phong::facing::view};
    for (int i = 0; i < 50; ++i) {
        const scene<T> s = g.make(F, 3);
        std::array<phong::light<T>, 3> arr{s.lights[0], s.lights[1], s.lights[2]};
        const vec3<T> a = phong::shade<F>(s.position, s.normal, s.mat, arr, s.env);
        const vec3<T> b = phong::shade<F>(s.position, s.normal, s.mat, std::span<const phong::light<T>>(s.lights), s.env);
        const vec3<T> c = phong::shade<F>(s.position, s.normal, s.mat, s.lights, s.env);
        CHECK(close(a, c, 2));
        CHECK(b == c);
    }
    // No lights: the scene ambient alone.
    const std::array<phong::light<T>, 0> none{};
    phong::material<T> mat;
    phong::environment<T> env;
    env.ambient = vec3<T>(0.5);
    CHECK(close(phong::shade<features{}>(vec3<T>(0, 0, -1), vec3<T>(0, 0, 1), mat, none, env), mat.ka * T(0.5), 1));
}

// ---------------------------------------------------------------------------------------------
// Degenerate input: each documented finite result, in both evaluation modes.

namespace {
// A feature set with every term that the edges touch.
constexpr features all_terms{.scene_ambient = true, .light_ambient = true, .diffuse = true,
                             .specular = phong::specular_model::phong, .specular_gate = true,
                             .lights = phong::light_kind::any, .attenuation = phong::attenuation_model::polynomial,
                             .spot = phong::spot_model::none, .attenuate_ambient = true,
                             .two_sided = phong::facing::none, .view = phong::view_model::eye_at_origin,
                             .emission = true, .alpha = false, .mode = evaluation::exact};

template <class T> phong::material<T> test_material(T m = T(8))
{
    phong::material<T> mat;
    mat.ka = vec3<T>(0.5, 0.25, 0.75);
    mat.kd = vec3<T>(0.25, 0.5, 1);
    mat.ks = vec3<T>(1, 0.5, 0.25);
    mat.emission = vec3<T>(0.0625, 0.125, 0);
    mat.shininess = m;
    return mat;
}
template <class T> phong::light<T> test_light(vec4<T> position)
{
    phong::light<T> L;
    L.position = position;
    L.ambient = vec3<T>(0.25, 0.5, 0.125);
    L.diffuse = vec3<T>(1, 0.75, 0.5);
    L.specular = vec3<T>(0.5, 1, 0.25);
    return L;
}
// What every edge below leaves: emission + ka (La + sum_i f_i La_i), f_i = 1.
template <class T> vec3<T> ambient_only(const phong::material<T>& mat, const phong::environment<T>& env,
                                        const std::vector<phong::light<T>>& lights)
{
    vec3<T> sum = env.ambient;
    for (const auto& L : lights) sum += L.ambient;
    return mat.emission + mat.ka * sum;
}
} // namespace

TEST_CASE_TEMPLATE("shade: documented edges, exact and stable", T, float, double)
{
    auto both = [](auto check) {
        check(std::integral_constant<evaluation, evaluation::exact>{});
        check(std::integral_constant<evaluation, evaluation::stable>{});
    };
    const phong::material<T> mat = test_material<T>();
    phong::environment<T> env;
    env.ambient = vec3<T>(0.25);
    const vec3<T> Q(1, -1, -4), n(0, 0, 1);
    const std::vector<phong::light<T>> two{test_light<T>(vec4<T>(2, 3, 1, 1)), test_light<T>(vec4<T>(-1, 0.5, 2, 0))};

    SUBCASE("zero normal: no diffuse or specular from any light")
    {
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            const vec3<T> c = phong::shade<F>(Q, vec3<T>(0), mat, two, env);
            CHECK(close(c, ambient_only(mat, env, two), 4));
            constexpr features G = [] { features f = with(all_terms, decltype(mode)::value); f.specular = phong::specular_model::blinn; f.two_sided = phong::facing::view; return f; }();
            CHECK(close(phong::shade<G>(Q, vec3<T>(0), mat, two, env), ambient_only(mat, env, two), 4));
        });
    }
    SUBCASE("light exactly at Q: it adds only its ambient term")
    {
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            std::vector<phong::light<T>> lights = two;
            lights.push_back(test_light<T>(vec4<T>(Q, T(1))));
            lights.back().ambient = vec3<T>(0.5);
            // c0 = 1: f = 1 at d = 0, so the ambient term is ka * La_i exactly.
            const vec3<T> with_it = phong::shade<F>(Q, n, mat, lights, env);
            const vec3<T> without = phong::shade<F>(Q, n, mat, two, env);
            CHECK(close(with_it, without + mat.ka * T(0.5), 4));
            // (A homogeneous w = 2 at 2 Q, once the same point, is outside the domain: a light's
            // w is 0 or 1, validate(light).)
        });
    }
    SUBCASE("c0 = 0 and d -> 0: f capped at 1 / attenuation_denominator_min")
    {
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            const T cap = T(1) / phong::detail::attenuation_denominator_min<T>;
            phong::light<T> L = test_light<T>(vec4<T>(Q, T(1)));
            L.attenuation = {T(0), T(0), T(1), std::numeric_limits<T>::infinity()};
            const std::vector<phong::light<T>> at{L};
            // At Q: only the (attenuated) ambient, ka * cap * La.
            phong::environment<T> dark;
            vec3<T> expected = mat.emission + mat.ka * (L.ambient * cap);
            CHECK(close(phong::shade<F>(Q, n, mat, at, dark), expected, 4));
            // A light 2^-40 above Q (d^2 = 2^-80 < 2^-63, float's cap): n.l = 1 and
            // r.v = 1 (Q on the view axis, the light at the eye); every term capped.
            // (double: 2^-300, d^2 = 2^-600 < 2^-511.)
            const vec3<T> Q0(T(0), T(0), -std::ldexp(T(1), std::is_same_v<T, float> ? -40 : -300));
            std::vector<phong::light<T>> near{L};
            near[0].position = vec4<T>(0, 0, 0, 1);
            const vec3<T> c = phong::shade<F>(Q0, n, mat, near, dark);
            expected = mat.emission + (mat.ka * L.ambient + mat.kd * L.diffuse + mat.ks * L.specular) * cap;
            CHECK(std::isfinite(c.x));
            CHECK(close(c, expected, 8));
        });
    }
    SUBCASE("Blinn with l = -v: n.h taken as 0")
    {
        both([&](auto mode) {
            constexpr features F = [] { features f = with(all_terms, decltype(mode)::value); f.specular = phong::specular_model::blinn; f.light_ambient = false; return f; }();
            // Q on the view axis, v = (0, 0, 1); a directional light from behind the eye's view:
            // l = (0, 0, -1) = -v; n = (0, 0, -1) so that n.l = 1 (lit, gate open).
            const vec3<T> Qa(0, 0, -3), na(0, 0, -1);
            const std::vector<phong::light<T>> L{test_light<T>(vec4<T>(0, 0, -5, 0))};
            const vec3<T> lit = mat.emission + mat.ka * env.ambient + mat.kd * L[0].diffuse;
            CHECK(close(phong::shade<F>(Qa, na, mat, L, env), lit, 4));                       // m > 0: 0
            CHECK(close(phong::shade<F>(Qa, na, test_material<T>(T(0)), L, env), lit + mat.ks * L[0].specular, 4)); // m = 0: 1
        });
    }
    SUBCASE("zero-length directional light: ambient only")
    {
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            std::vector<phong::light<T>> lights = two;
            lights.push_back(test_light<T>(vec4<T>(0, 0, 0, 0)));
            CHECK(close(phong::shade<F>(Q, n, mat, lights, env),
                        phong::shade<F>(Q, n, mat, two, env) + mat.ka * lights.back().ambient, 4));
            constexpr features D = [] { features f = with(all_terms, decltype(mode)::value); f.lights = phong::light_kind::directional; return f; }();
            const std::vector<phong::light<T>> only{test_light<T>(vec4<T>(0, 0, 0, 0))};
            CHECK(close(phong::shade<D>(Q, n, mat, only, env), ambient_only(mat, env, only), 4));
        });
    }
    SUBCASE("m = 0: the specular base^0 = 1 wherever the term is on")
    {
        both([&](auto mode) {
            constexpr features F = [] { features f = with(all_terms, decltype(mode)::value); f.light_ambient = false; f.emission = false; f.scene_ambient = false; return f; }();
            // Grazing light: n.l = 0.6 > 0, and v chosen so r.v < 0 (the base clamps to 0).
            const vec3<T> Qm(0, 0, -1);
            const std::vector<phong::light<T>> L{test_light<T>(vec4<T>(0.8, 0, 0.6, 0))}; // l = (0.8, 0, 0.6)
            // v = (0, 0, 1): r = 2 (0.6) n - l = (-0.8, 0, 0.6), r.v = 0.6 > 0. Pick Q off axis instead:
            const vec3<T> Qo(-4, 0, -1); // v = normalize(4, 0, 1): r.v = (-3.2 + 0.6)/sqrt17 < 0
            const vec3<T> expected = mat.kd * L[0].diffuse * T(0.6) + mat.ks * L[0].specular;
            CHECK(close(phong::shade<F>(Qo, n, test_material<T>(T(0)), L, env), expected, 8));
            // Gated off (n.l < 0): no specular even at m = 0.
            const std::vector<phong::light<T>> below{test_light<T>(vec4<T>(0.8, 0, -0.6, 0))};
            CHECK(phong::shade<F>(Qm, n, test_material<T>(T(0)), below, env) == vec3<T>(0));
            // Without the gate (seed 001) a light below still gets ks Ls at m = 0, and no diffuse.
            constexpr features U = [] { features f = with(all_terms, decltype(mode)::value); f.light_ambient = false; f.emission = false; f.scene_ambient = false; f.specular_gate = false; return f; }();
            CHECK(close(phong::shade<U>(Qm, n, test_material<T>(T(0)), below, env), mat.ks * below[0].specular, 4));
        });
    }
    SUBCASE("Q at the eye: the diffuse term is kept (it does not need v), no specular")
    {
        // By hand, n = (0, 0, 1), f = 1 (c0 = 1): from Q = 0 the positional light at (2, 3, 1)
        // has n.l = 1/sqrt(14), the directional (-1, 0.5, 2) n.l = 2/sqrt(5.25); from
        // Q = (1, -1, -4) the positional one has d = (1, 4, 5), n.l = 5/sqrt(42).
        const vec3<T> directional = two[1].diffuse * T(2 / std::sqrt(5.25));
        const vec3<T> at_origin = ambient_only(mat, env, two) + mat.kd * (two[0].diffuse * T(1 / std::sqrt(14.0)) + directional);
        const vec3<T> at_Q = ambient_only(mat, env, two) + mat.kd * (two[0].diffuse * T(5 / std::sqrt(42.0)) + directional);
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            CHECK(close(phong::shade<F>(vec3<T>(0), n, mat, two, env), at_origin, 8));
            constexpr features E = [] { features f = with(all_terms, decltype(mode)::value); f.view = phong::view_model::eye_point; return f; }();
            phong::environment<T> at = env;
            at.eye = vec4<T>(Q, T(1));
            CHECK(close(phong::shade<E>(Q, n, mat, two, at), at_Q, 8));
            // Blinn (whose h = normalize(l + v) would be l with v = 0) and m = 0 (pow(0, 0) = 1
            // where a specular term is on): still no specular term without a view vector.
            constexpr features B = [] { features f = with(all_terms, decltype(mode)::value); f.specular = phong::specular_model::blinn; return f; }();
            CHECK(close(phong::shade<B>(vec3<T>(0), n, mat, two, env), at_origin, 8));
            CHECK(close(phong::shade<F>(vec3<T>(0), n, test_material<T>(T(0)), two, env), at_origin, 8));
        });
    }
    SUBCASE("every edge is finite")
    {
        both([&](auto mode) {
            constexpr features F = with(all_terms, decltype(mode)::value);
            const vec3<T> c = phong::shade<F>(vec3<T>(0), vec3<T>(0), mat, std::vector<phong::light<T>>{test_light<T>(vec4<T>(0, 0, 0, 1)), test_light<T>(vec4<T>(0, 0, 0, 0))}, env);
            CHECK(std::isfinite(c.x));
            CHECK(std::isfinite(c.y));
            CHECK(std::isfinite(c.z));
        });
    }
}

// ---------------------------------------------------------------------------------------------
// Against the reference model over the feature options.
//
// A strength-2 covering array: the 27 points (a, b, c) of Z_3^3 and 9 pairwise independent
// linear forms a, b, c, a+b, a+2b, a+c, a+2c, b+c, b+2c. Every pair of factors meets all 9 pairs of
// levels (checked below at compile time). Crossed with both evaluation modes: 54 feature sets.

namespace {
constexpr int coverage_runs = 27, coverage_factors = 9;

constexpr int level(int run, int factor)
{
    const int a = run / 9, b = (run / 3) % 3, c = run % 3;
    const int forms[coverage_factors][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 2, 0},
                                            {1, 0, 1}, {1, 0, 2}, {0, 1, 1}, {0, 1, 2}};
    return (forms[factor][0] * a + forms[factor][1] * b + forms[factor][2] * c) % 3;
}

constexpr bool strength_two()
{
    for (int f = 0; f < coverage_factors; ++f)
        for (int g = f + 1; g < coverage_factors; ++g) {
            bool seen[3][3] = {};
            for (int r = 0; r < coverage_runs; ++r) seen[level(r, f)][level(r, g)] = true;
            for (auto& row : seen)
                for (bool s : row)
                    if (!s) return false;
        }
    return true;
}
static_assert(strength_two(), "the covering array must cover every pair of levels");

constexpr features feature_set(int run, evaluation mode)
{
    using namespace phong;
    features f{};
    f.specular = static_cast<specular_model>(level(run, 0));
    f.lights = static_cast<light_kind>(level(run, 1));
    f.attenuation = static_cast<attenuation_model>(level(run, 2));
    f.spot = static_cast<spot_model>(level(run, 3));
    f.two_sided = static_cast<facing>(level(run, 4));
    f.view = static_cast<view_model>(level(run, 5));
    switch (level(run, 6)) { // ambient options
    case 0: f.scene_ambient = true, f.light_ambient = false, f.attenuate_ambient = true; break;
    case 1: f.scene_ambient = false, f.light_ambient = true, f.attenuate_ambient = true; break;
    default: f.scene_ambient = true, f.light_ambient = true, f.attenuate_ambient = false; break;
    }
    switch (level(run, 7)) { // emission and alpha
    case 0: f.emission = false, f.alpha = false; break;
    case 1: f.emission = true, f.alpha = false; break;
    default: f.emission = true, f.alpha = true; break;
    }
    switch (level(run, 8)) { // diffuse and the specular gate
    case 0: f.diffuse = true, f.specular_gate = true; break;
    case 1: f.diffuse = true, f.specular_gate = false; break;
    default: f.diffuse = false, f.specular_gate = true; break;
    }
    f.mode = mode;
    return f;
}

constexpr auto all_feature_sets = [] {
    std::array<features, 2 * coverage_runs> sets{};
    for (int r = 0; r < coverage_runs; ++r) {
        sets[2 * r] = feature_set(r, evaluation::exact);
        sets[2 * r + 1] = feature_set(r, evaluation::stable);
    }
    return sets;
}();

struct sweep_result {
    double worst = 0;     // error / tolerance
    double worst_eps = 0; // largest error in eps relative to the largest channel
    double worst_m = 0;   // the shininess there
    int scenes = 0;
};

// Tolerance, in eps relative to the largest channel: 32 (a handful of roundings per term, summed
// over three lights) plus the specular power,
// whose base carries about 2 eps of rounding that (base)^m multiplies by m (exact mode; the stable
// mode has the same input rounding, see specular.hpp).
constexpr double tolerance_eps(double m) { return 32 + 2 * m; }

// The spot factor's own conditioning: its cone cosine c = -l.s carries a few eps (l and the
// normalized axis are rounded), which smoothstep multiplies by up to 1.5 / (cos_inner -
// cos_outer) and OpenGL's c^e by e / c (c >= 0.1 where well_conditioned keeps the cutoff away).
template <class T> double spot_slack_eps(const phong::features& F, const scene<T>& s)
{
    double slack = 0;
    for (const auto& L : s.lights) {
        if (F.spot == phong::spot_model::smooth && L.spot.cos_inner > L.spot.cos_outer)
            slack = std::max(slack, 6 / double(L.spot.cos_inner - L.spot.cos_outer));
        if (F.spot == phong::spot_model::opengl) slack = std::max(slack, 40 * double(L.spot.exponent));
    }
    return slack;
}

template <features F, class T> sweep_result sweep(std::uint64_t seed, int count)
{
    scene_gen<T> g(seed);
    sweep_result r;
    for (int i = 0; i < count; ++i) {
        const scene<T> s = g.make(F, 1 + i % 3, 1, 64);
        if (!well_conditioned(F, s)) continue;
        ++r.scenes;
        const auto c = phong::shade<F>(s.position, s.normal, s.mat, std::span<const phong::light<T>>(s.lights), s.env, s.front_facing);
        const wcolor ref = reference_shade<T>(F, s.position, s.normal, s.mat, s.lights, s.env, s.front_facing);
        const double e = error_eps(c, ref);
        r.worst = std::max(r.worst, e / (tolerance_eps(double(s.mat.shininess)) + spot_slack_eps(F, s)));
        if (e > r.worst_eps) r.worst_eps = e, r.worst_m = double(s.mat.shininess);
        if constexpr (F.alpha) {
            if (c.a != s.mat.alpha) r.worst = std::numeric_limits<double>::infinity();
        }
    }
    return r;
}

template <class T, std::size_t... I> void sweep_all(std::index_sequence<I...>)
{
    double worst = 0, worst_eps = 0, worst_m = 0, worst_stable_eps = 0;
    int scenes = 0;
    (
        [&] {
            constexpr features F = all_feature_sets[I];
            const sweep_result r = sweep<F, T>(1000 + I, 120);
            CAPTURE(I);
            CAPTURE(int(F.specular));
            CAPTURE(int(F.lights));
            CAPTURE(int(F.attenuation));
            CAPTURE(int(F.spot));
            CAPTURE(int(F.two_sided));
            CAPTURE(int(F.view));
            CAPTURE(int(F.mode));
            CAPTURE(r.worst_m);
            CHECK(r.worst <= 1.0);
            CHECK(r.scenes >= 30); // the filter must leave most scenes
            worst = std::max(worst, r.worst);
            if (r.worst_eps > worst_eps) worst_eps = r.worst_eps, worst_m = r.worst_m;
            if (F.mode == evaluation::stable) worst_stable_eps = std::max(worst_stable_eps, r.worst_eps);
            scenes += r.scenes;
        }(),
        ...);
    MESSAGE("shade vs reference: " << scenes << " scenes, worst error " << worst_eps << " eps (at m = " << worst_m
                                   << "), stable mode " << worst_stable_eps << " eps, worst error / tolerance " << worst);
}
} // namespace

TEST_CASE_TEMPLATE("shade: agrees with the reference model on every pair of feature options", T, float, double)
{
    sweep_all<T>(std::make_index_sequence<all_feature_sets.size()>{});
}
