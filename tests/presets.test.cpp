// The seed presets of features.hpp against their seeds' formulas, written out literally in
// tests/support/seeds.hpp (plain GLM, std::pow, long double), on random inputs:
//   classic_phong   ~ seeds::seed000 (perspective and orthographic ec_lds, oblique included)
//   blinn_phong_per_light_ambient ~ seeds::seed001 (steps 1-18)
//   glsl_ads       ~ seeds::phong_vert   (through shade_vertex, ModelView and NormalMatrix)
//   diffuse_only   ~ seeds::diffuse_vert
// The documented deviations of classic_phong (dot products clamped at 0, no gate) are part of
// seeds::seed000 as written there. Seeds 000 and 001 are checked in both evaluation modes.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/seeds.hpp"

#include <phong/sum/shade.hpp>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace phong_test;
using R = long double; // the precision the seeds are evaluated in

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> using mat4 = glm::mat<4, 4, T>;

// Error of the library's colour against the seed's, in eps of T relative to the largest channel
// (or to `floor` when that is larger).
template <glm::length_t L, class T> double error_eps(const glm::vec<L, T>& c, const glm::vec<L, R>& seed, R floor = 0)
{
    R scale = floor;
    for (glm::length_t k = 0; k < L; ++k) scale = std::max(scale, std::abs(seed[k]));
    if (scale == 0) scale = 1;
    double worst = 0;
    for (glm::length_t k = 0; k < L; ++k) {
        if (!std::isfinite(c[k])) return 1e300;
        worst = std::max(worst, double(std::abs(R(c[k]) - seed[k]) / scale / R(tolerance<T>::eps)));
    }
    return worst;
}

// "A few ulp": the tolerance in eps relative to the largest channel. 8 for the roundings of the
// normalizations, dot products and sums, plus the specular power's amplification of the ~1 eps
// rounding of its base by m (pow's condition number).
double few_ulp(double m) { return 8 + 1.0 * m; }

template <class T> mat4<R> widen(const mat4<T>& M) { return mat4<R>(M); }
template <class T> vec3<R> wid(const vec3<T>& v) { return vec3<R>(v); }

// A random affine model-view matrix whose products with grid points are exact in T: a
// translation on a grid of 1/16, a signed permutation of the axes (rotations by multiples of 90
// degrees and mirrors) and a scale by powers of two per axis. The seed's eyeCoords and
// NormalMatrix are then the library's exactly, and the comparison measures the lighting alone
// (the transforms' own rounding is normal.test.cpp's and vertex.test.cpp's subject).
template <class T> mat4<T> random_model_view(scene_gen<T>& g)
{
    auto on_grid = [&](int lo, int hi) { return T(g.integer(lo * 16, hi * 16)) / T(16); };
    mat4<T> M(T(0));
    int axes[3] = {0, 1, 2};
    std::shuffle(axes, axes + 3, std::mt19937(unsigned(g.integer(0, 1 << 30))));
    const T scales[3] = {T(0.5), T(1), T(2)};
    for (int c = 0; c < 3; ++c) M[c][axes[c]] = (g.coin() ? T(1) : T(-1)) * scales[g.integer(0, 2)];
    M[3] = vec4<T>(on_grid(-2, 2), on_grid(-2, 2), on_grid(-9, -4), T(1));
    return M;
}
template <class T> vec3<T> grid_point(scene_gen<T>& g)
{
    return vec3<T>(T(g.integer(-64, 64)), T(g.integer(-64, 64)), T(g.integer(-64, 64))) / T(64);
}

// A random projection for seed 000: glm::perspective, an off-axis glm::frustum, glm::ortho, or
// an oblique orthographic matrix (ortho times a shear along z).
template <class T> mat4<T> random_projection(scene_gen<T>& g, bool& perspective)
{
    switch (g.integer(0, 3)) {
    case 0: perspective = true; return glm::perspective(g.uniform(0.5, 1.5), g.uniform(0.5, 2), T(0.1), T(100));
    case 1: perspective = true; return glm::frustum(g.uniform(-1, 0), g.uniform(0.1, 1), g.uniform(-1, 0), g.uniform(0.1, 1), T(0.5), T(50));
    case 2: perspective = false; return glm::ortho(g.uniform(-4, -1), g.uniform(1, 4), g.uniform(-3, -1), g.uniform(1, 3), T(0.1), T(20));
    default: {
        perspective = false;
        mat4<T> S(T(1));
        S[2][0] = g.uniform(-0.7, 0.7);
        S[2][1] = g.uniform(-0.7, 0.7);
        return glm::ortho(T(-2), T(2), T(-2), T(2), T(0.1), T(20)) * S;
    }
    }
}
} // namespace

TEST_CASE_TEMPLATE("presets: classic_phong equals seed 000's formula", T, float, double)
{
    constexpr phong::features F = phong::presets::classic_phong;
    scene_gen<T> g(2000);
    double worst = 0, worst_eps = 0;
    int tested = 0, orthographic = 0;
    for (int i = 0; i < 400; ++i) {
        bool perspective = true;
        const mat4<T> ec_lds = random_projection(g, perspective);
        scene<T> s = g.make(F, 1 + i % 3, 1, 32);
        s.env.eye = phong::eye_from_projection(ec_lds);
        for (auto& L : s.lights) {
            L.specular = L.diffuse; // seed 000's single strength L_i
            if (L.position.w != T(0)) L.position = vec4<T>(vec3<T>(L.position) / L.position.w, T(1)); // w = 1 or 0
        }
        // Away from the two-sided flip (n.v = 0), the one discontinuity of this preset.
        if (!well_conditioned(F, s)) continue;
        seeds::seed000_uniforms<R> u;
        u.ka = wid(s.mat.ka), u.kd = wid(s.mat.kd), u.ks = wid(s.mat.ks), u.La = wid(s.env.ambient);
        u.m = R(s.mat.shininess);
        u.ec_lds = widen(ec_lds);
        u.perspective = perspective;
        u.alpha = R(s.mat.alpha);
        std::vector<seeds::seed000_light<R>> lights;
        for (const auto& L : s.lights)
            lights.push_back({vec4<R>(L.position), wid(L.diffuse), R(L.attenuation.constant), R(L.attenuation.linear),
                              R(L.attenuation.quadratic)});
        const vec4<R> expected = seeds::seed000<R>(wid(s.position), wid(s.normal), u, lights);
        const vec4<T> c = phong::shade<F>(s.position, s.normal, s.mat, s.lights, s.env);
        // The same feature set in the stable mode computes the same model.
        constexpr phong::features S = phong::presets::with_mode(F, phong::evaluation::stable);
        const vec4<T> c_stable = phong::shade<S>(s.position, s.normal, s.mat, s.lights, s.env);
        const double e = std::max(error_eps(c, expected), error_eps(c_stable, expected));
        worst = std::max(worst, e / few_ulp(double(s.mat.shininess)));
        worst_eps = std::max(worst_eps, e);
        CHECK(c.a == s.mat.alpha);
        ++tested;
        orthographic += !perspective;
    }
    MESSAGE("classic_phong vs seed 000: " << tested << " scenes (" << orthographic << " orthographic), worst " << worst_eps << " eps");
    CHECK(tested >= 300);
    CHECK(orthographic >= 100);
    CHECK(worst <= 1.0);
}

TEST_CASE_TEMPLATE("presets: blinn_phong_per_light_ambient equals seed 001's steps 1-18", T, float, double)
{
    constexpr phong::features F = phong::presets::blinn_phong_per_light_ambient;
    scene_gen<T> g(2001);
    double worst = 0, worst_eps = 0;
    int tested = 0;
    for (int i = 0; i < 400; ++i) {
        const vec3<T> P = g.point();
        const vec3<T> m = g.direction() * g.uniform(0.5, 2);
        const vec3<T> ray_start = g.in_box(-2, 2);
        seeds::seed001_material<R> mat{wid(g.color()), wid(g.color()), wid(g.color()), R(g.uniform(1, 32))};
        phong::material<T> pm;
        pm.ka = vec3<T>(mat.materialamb), pm.kd = vec3<T>(mat.materialdiff), pm.ks = vec3<T>(mat.materialspec);
        pm.shininess = T(mat.f);
        std::vector<seeds::seed001_light<R>> lights;
        std::vector<phong::light<T>> pl;
        bool ok = true;
        for (int k = 0; k < 1 + i % 3; ++k) {
            phong::light<T> L;
            L.position = vec4<T>(P + g.in_box(-5, 5), T(1));
            L.ambient = g.color(0, 0.5), L.diffuse = g.color(), L.specular = g.color();
            pl.push_back(L);
            lights.push_back({vec3<R>(L.position), wid(L.ambient), wid(L.diffuse), wid(L.specular)});
            // Away from l = -e (h undefined) and a light at P.
            const vec3<R> l = glm::normalize(vec3<R>(L.position) - wid(P)), e = glm::normalize(wid(ray_start) - wid(P));
            ok = ok && glm::length(l + e) > R(1e-2) && glm::length(vec3<R>(L.position) - wid(P)) > R(1e-2);
        }
        if (!ok) continue;
        const vec3<T> GlobalAmbient = g.color(0, 0.5);
        phong::environment<T> env;
        env.ambient = GlobalAmbient;
        env.eye = vec4<T>(ray_start, T(1)); // e = ray.start - P
        const vec3<R> expected = seeds::seed001<R>(wid(P), wid(m), wid(ray_start), lights, mat, wid(GlobalAmbient));
        const vec3<T> c = phong::shade<F>(P, m, pm, pl, env);
        constexpr phong::features S = phong::presets::with_mode(F, phong::evaluation::stable);
        const vec3<T> c_stable = phong::shade<S>(P, m, pm, pl, env);
        const double e = std::max(error_eps(c, expected), error_eps(c_stable, expected));
        worst = std::max(worst, e / few_ulp(double(pm.shininess)));
        worst_eps = std::max(worst_eps, e);
        ++tested;
    }
    MESSAGE("blinn_phong_per_light_ambient vs seed 001: " << tested << " hit points, worst " << worst_eps << " eps");
    CHECK(tested >= 350);
    CHECK(worst <= 1.0);
}

TEST_CASE_TEMPLATE("presets: glsl_ads and diffuse_only equal phong.vert and diffuse.vert", T, float, double)
{
    constexpr phong::features ads = phong::presets::glsl_ads;
    constexpr phong::features diffuse = phong::presets::diffuse_only;
    scene_gen<T> g(2003);
    double worst_ads = 0, worst_diffuse = 0, worst_eps = 0;
    int tested = 0;
    for (int i = 0; i < 400; ++i) {
        const mat4<T> MV = random_model_view(g);
        const vec3<T> VertexPosition = grid_point(g), VertexNormal = g.direction();
        seeds::LightInfo<R> Light{vec4<R>(wid(g.in_box(-5, 5)), R(1)), wid(g.color(0, 0.5)), wid(g.color()), wid(g.color())};
        seeds::MaterialInfo<R> Material{wid(g.color()), wid(g.color()), wid(g.color()), R(g.uniform(1, 32))};
        // The seed's NormalMatrix, from GLM in long double (not from phong::normal_matrix).
        const mat4<R> MVw = widen(MV);
        const glm::mat<3, 3, R> NormalMatrix = glm::inverseTranspose(glm::mat<3, 3, R>(MVw));
        // Away from the gate sDotN = 0 and from a light at the vertex.
        const vec4<R> eyeCoords = MVw * vec4<R>(wid(VertexPosition), R(1));
        const vec3<R> s = glm::normalize(vec3<R>(Light.Position - eyeCoords));
        const R sn = glm::dot(s, glm::normalize(NormalMatrix * wid(VertexNormal)));
        if (std::abs(sn) < R(1e-3) || glm::length(vec3<R>(Light.Position - eyeCoords)) < R(1e-2)) continue;

        phong::light<T> L;
        L.position = vec4<T>(Light.Position), L.ambient = vec3<T>(Light.La), L.diffuse = vec3<T>(Light.Ld),
        L.specular = vec3<T>(Light.Ls);
        const std::array<phong::light<T>, 1> lights{L};
        phong::material<T> mat;
        mat.ka = vec3<T>(Material.Ka), mat.kd = vec3<T>(Material.Kd), mat.ks = vec3<T>(Material.Ks);
        mat.shininess = T(Material.Shininess);
        const glm::mat<3, 3, T> N = phong::normal_matrix(MV);

        const vec3<R> expected_ads = seeds::phong_vert<R>(wid(VertexPosition), wid(VertexNormal), Light, Material, MVw, NormalMatrix);
        const vec3<T> c_ads = phong::shade_vertex<ads>(VertexPosition, VertexNormal, MV, N, mat, lights);
        // Relative to the largest channel of Ld Kd at least: the cosine s.n near grazing has a
        // small absolute rounding error but a large relative one (a dot product's cancellation),
        // which the diffuse-only shader, without an ambient term, shows unscaled.
        const vec3<R> LdKd = Light.Ld * Material.Kd;
        const R floor = std::max({LdKd.x, LdKd.y, LdKd.z});
        const double e_ads = error_eps(c_ads, expected_ads, floor);
        worst_ads = std::max(worst_ads, e_ads / few_ulp(double(mat.shininess)));

        const vec3<R> expected_diffuse = seeds::diffuse_vert<R>(wid(VertexPosition), wid(VertexNormal), Light.Position,
                                                                Material.Kd, Light.Ld, MVw, NormalMatrix);
        const vec3<T> c_diffuse = phong::shade_vertex<diffuse>(VertexPosition, VertexNormal, MV, N, mat, lights);
        const double e_diffuse = error_eps(c_diffuse, expected_diffuse, floor);
        worst_diffuse = std::max(worst_diffuse, e_diffuse / few_ulp(0));
        worst_eps = std::max({worst_eps, e_ads, e_diffuse});
        ++tested;
    }
    MESSAGE("seed003 presets vs phong.vert / diffuse.vert: " << tested << " vertices, worst " << worst_eps << " eps");
    CHECK(tested >= 350);
    CHECK(worst_ads <= 1.0);
    CHECK(worst_diffuse <= 1.0);
}
