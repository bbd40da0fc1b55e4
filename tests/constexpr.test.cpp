// Compile-time evaluation: static_asserts of the scalar kernels' special values, of the vector
// functions, of the view, attenuation and specular factors, and of whole 3-light shades
// (positional + directional + spot, attenuation, Phong and Blinn, exact, stable and fast) against
// hand-worked values. Compiled by g++ and clang++ (clang rejects any non-constexpr std:: call in
// constant evaluation that g++ would fold). Then, at run time, the constant-evaluation path
// against the run-time path: tables evaluated at compile time, and detail::ce called directly.
#include "support/numeric.hpp"

#include <phong/accuracy.hpp> // the fast kernels' bounds
#include <phong/core/fast_math.hpp>
#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;

template <class T> constexpr bool is_nan(T x) { return x != x; }
template <class T> constexpr T cabs(T x) { return x < 0 ? -x : x; }
// |a - b| <= ulps * eps * max(|b|, 1e-30)
template <class T> constexpr bool close(T a, T b, int ulps)
{
    const T scale = cabs(b) > T(1e-30) ? cabs(b) : T(1e-30);
    return cabs(a - b) <= T(ulps) * std::numeric_limits<T>::epsilon() * scale;
}
template <glm::length_t L, class T> constexpr bool close(const glm::vec<L, T>& a, const glm::vec<L, T>& b, int ulps)
{
    T scale = T(1e-30);
    for (glm::length_t k = 0; k < L; ++k) scale = cabs(b[k]) > scale ? cabs(b[k]) : scale;
    for (glm::length_t k = 0; k < L; ++k)
        if (!(cabs(a[k] - b[k]) <= T(ulps) * std::numeric_limits<T>::epsilon() * scale)) return false;
    return true;
}

constexpr long double sqrt2 = 1.41421356237309504880168872420969808L;

// ---------------------------------------------------------------------------------------------
// Scalar kernels in constant evaluation: special values first (gcem's order), then values.
template <class T> constexpr bool scalar_kernels()
{
    constexpr T inf = std::numeric_limits<T>::infinity();
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    static_assert(phong::detail::sqrt(T(0)) == T(0));
    static_assert(phong::detail::sqrt(T(4)) == T(2));
    static_assert(phong::detail::sqrt(T(0.0625)) == T(0.25));
    static_assert(phong::detail::sqrt(inf) == inf);
    static_assert(is_nan(phong::detail::sqrt(T(-1))));
    static_assert(is_nan(phong::detail::sqrt(nan)));
    static_assert(close(phong::detail::sqrt(T(2)), T(sqrt2), 1));
    static_assert(close(phong::detail::sqrt(T(2e-30)), T(sqrt2 * 1e-15L), 1));
    static_assert(phong::detail::exp(T(0)) == T(1));
    static_assert(phong::detail::exp(T(1000)) == inf);
    static_assert(phong::detail::exp(T(-1000)) == T(0));
    static_assert(phong::detail::exp(-inf) == T(0));
    static_assert(is_nan(phong::detail::exp(nan)));
    static_assert(close(phong::detail::exp(T(1)), T(2.71828182845904523536028747135266250L), 1));
    static_assert(phong::detail::log(T(1)) == T(0));
    static_assert(phong::detail::log(T(0)) == -inf);
    static_assert(phong::detail::log(inf) == inf);
    static_assert(is_nan(phong::detail::log(T(-1))));
    static_assert(close(phong::detail::log(T(2)), T(0.693147180559945309417232121458176568L), 1));
    static_assert(close(phong::detail::log(T(1e10)), T(23.0258509299404568401799145468436421L), 1));
    static_assert(phong::detail::log1p(T(0)) == T(0));
    static_assert(phong::detail::log1p(T(-1)) == -inf);
    static_assert(is_nan(phong::detail::log1p(T(-2))));
    static_assert(close(phong::detail::log1p(T(1e-10)), T(9.9999999995000000000333333333308e-11L), 1));
    static_assert(phong::detail::pow(T(0), T(0)) == T(1)); // m = 0 convention
    static_assert(phong::detail::pow(T(0), T(3)) == T(0));
    static_assert(phong::detail::pow(T(0), T(-1)) == inf);
    static_assert(phong::detail::pow(nan, T(0)) == T(1));
    static_assert(phong::detail::pow(T(1), nan) == T(1));
    static_assert(phong::detail::pow(T(2), T(10)) == T(1024));
    static_assert(phong::detail::pow(T(-2), T(3)) == T(-8));
    static_assert(is_nan(phong::detail::pow(T(-2), T(0.5))));
    static_assert(close(phong::detail::pow(T(0.5), T(0.5)), T(1 / sqrt2), 1));
    static_assert(phong::detail::pow<0>(nan) == T(1));
    static_assert(phong::detail::pow<1>(T(0.3)) == T(0.3));
    static_assert(phong::detail::pow<4>(T(3)) == T(81));
    static_assert(phong::detail::pow<10>(T(1.5)) == T(59049.0 / 1024.0));
    static_assert(phong::detail::fma(T(3), T(4), T(5)) == T(17));
    static_assert(phong::detail::fma(T(1) + std::numeric_limits<T>::epsilon(), T(1) - std::numeric_limits<T>::epsilon(), T(-1)) ==
                  -std::numeric_limits<T>::epsilon() * std::numeric_limits<T>::epsilon());
    static_assert(phong::detail::cos_degrees(T(90)) == T(0) && phong::detail::cos_degrees(T(180)) == T(-1));
    static_assert(close(phong::detail::cos_degrees(T(60)), T(0.5), 1));
    return true;
}
static_assert(scalar_kernels<float>());
static_assert(scalar_kernels<double>());

// ---------------------------------------------------------------------------------------------
// Vector functions, direction, view, attenuation, specular.
template <class T> constexpr bool vector_functions()
{
    static_assert(phong::detail::dot(vec3<T>(1, 2, 3), vec3<T>(4, -5, 6)) == T(12));
    static_assert(phong::detail::cross(vec3<T>(1, 0, 0), vec3<T>(0, 1, 0)) == vec3<T>(0, 0, 1));
    static_assert(phong::detail::length(vec3<T>(3, 4, 0)) == T(5));
    static_assert(phong::detail::length(vec3<T>(2, 3, 6)) == T(7));
    static_assert(phong::detail::length(vec3<T>(T(3e-30), T(4e-30), T(0))) == T(5e-30) ||
                  close(phong::detail::length(vec3<T>(T(3e-30), T(4e-30), T(0))), T(5e-30), 2));
    static_assert(phong::detail::normalize(vec3<T>(0, 0, -5)) == vec3<T>(0, 0, -1));
    static_assert(phong::detail::normalize(vec3<T>(0)) == vec3<T>(0));
    static_assert(close(phong::detail::normalize(vec3<T>(3, 4, 0)), vec3<T>(0.6, 0.8, 0), 2));
    static_assert(phong::detail::normalize_unscaled(vec3<T>(0)) == vec3<T>(0));
    static_assert(phong::reflect(vec3<T>(1, -1, 0), vec3<T>(0, 1, 0)) == vec3<T>(1, 1, 0));
    static_assert(phong::faceforward(vec3<T>(0, 0, 1), vec3<T>(0, 0, 1), vec3<T>(0, 0, 1)) == vec3<T>(0, 0, -1));
    static_assert(phong::detail::dot_compensated(vec3<T>(T(1) + std::numeric_limits<T>::epsilon(), 1, 0),
                                         vec3<T>(T(1) - std::numeric_limits<T>::epsilon(), -1, 0)) ==
                  -std::numeric_limits<T>::epsilon() * std::numeric_limits<T>::epsilon());
    // direction.hpp
    static_assert(phong::toward(vec4<T>(3, 4, -2, 1), vec3<T>(0, 0, -2)).distance == T(5));
    static_assert(phong::toward(vec4<T>(0, 0, 7, 0), vec3<T>(1, 2, 3)).direction == vec3<T>(0, 0, 1));
    static_assert(phong::toward(vec4<T>(1, 2, 3, 1), vec3<T>(1, 2, 3)).direction == vec3<T>(0));
    // view.hpp: a perspective matrix written out (glm::perspective is not constexpr): f/aspect,
    // f, -(far+near)/(far-near), -1, -2 far near/(far-near). The eye: (0, 0, 0, 1).
    constexpr glm::mat<4, 4, T> P(T(1.5), 0, 0, 0, 0, T(2), 0, 0, 0, 0, T(-1.25), T(-1), 0, 0, T(-0.5), 0);
    static_assert(phong::eye_from_projection(P) == vec4<T>(0, 0, 0, 1));
    // glm::ortho(-2, 2, -1, 1, 0, 4) written out: the direction toward the viewer (0, 0, 1, 0).
    constexpr glm::mat<4, 4, T> O(T(0.5), 0, 0, 0, 0, T(1), 0, 0, 0, 0, T(-0.5), 0, 0, 0, T(-1), T(1));
    static_assert(phong::eye_from_projection(O) == vec4<T>(0, 0, 1, 0));
    static_assert(phong::detail::view_orthographic(O) == vec3<T>(0, 0, 1));
    static_assert(phong::detail::view_perspective(vec3<T>(0, 0, -3)) == vec3<T>(0, 0, 1));
    static_assert(phong::view_vector(vec4<T>(1, 2, 3, 1), vec3<T>(1, 2, 3)) == vec3<T>(0));
    // attenuation.hpp
    static_assert(phong::attenuation_polynomial(T(2), T(1), T(0.5), T(0.25)) == T(1) / T(3));
    static_assert(phong::attenuation_polynomial(T(0), T(0), T(0), T(1)) == T(1) / phong::detail::attenuation_denominator_min<T>);
    static_assert(phong::attenuation_windowed(T(4), T(4)) == T(0));
    static_assert(phong::attenuation_windowed(T(2), std::numeric_limits<T>::infinity()) == T(0.25));
    // Floor = float in T = double: float's floor 2^-63 under the denominator, by hand. d = 2^-62 and
    // range 2^-61: window (1 - 1/16)^2 = 225/256 over 2^-63 = 225 2^55 (the window applied below
    // the floor too); d = 0 with c2 = 1: 2^63.
    static_assert(phong::attenuation_windowed<double, float>(0x1p-62, 0x1p-61) == 225 * 0x1p55);
    static_assert(phong::attenuation_polynomial<double, float>(0.0, 0.0, 0.0, 1.0) == 0x1p63);
    static_assert(phong::spot_opengl(vec3<T>(0, 0, 1), vec3<T>(0, 0, -1), T(5), T(0.5)) == T(1));
    static_assert(phong::spot_opengl(vec3<T>(1, 0, 0), vec3<T>(0, 0, -1), T(5), T(0.5)) == T(0));
    static_assert(phong::spot_smooth(vec3<T>(0, 0, 1), vec3<T>(0, 0, -1), T(0.9), T(0.8)) == T(1));
    // specular.hpp: the 45 degree light, m = 2: 1/2 (Phong), (2 + sqrt2)/4 (Blinn).
    constexpr T h = T(1 / sqrt2);
    constexpr vec3<T> n(0, 0, 1), l(h, 0, h), v(0, 0, 1);
    static_assert(close(phong::specular_reflection(n, l, v, T(2)), T(0.5), 8));
    static_assert(close(phong::detail::specular_reflection_stable(n, l, v, T(2)), T(0.5), 8));
    static_assert(close(phong::specular_halfway(n, l, v, T(2)), T((2 + sqrt2) / 4), 8));
    static_assert(close(phong::detail::specular_halfway_stable(n, l, v, T(2)), T((2 + sqrt2) / 4), 8));
    static_assert(phong::specular_halfway(n, l, -l, T(4)) == T(0));   // l = -v
    static_assert(phong::specular_halfway(n, l, -l, T(0)) == T(1));
    static_assert(phong::specular_reflection(n, -l, v, T(0)) == T(0)); // gate
    return true;
}
static_assert(vector_functions<float>());
static_assert(vector_functions<double>());

// ---------------------------------------------------------------------------------------------
// A whole 3-light shade at compile time.
//
// Q = (0, 0, -2), n = (0, 0, 1), perspective: v = (0, 0, 1). m = 2.
//  A: positional at the eye (0, 0, 0), attenuation (1, 1/2, 1/4): d = 2, f = 1/(1 + 1 + 1) = 1/3;
//     l = (0, 0, 1): n.l = 1, r.v = 1, n.h = 1.
//  B: directional along (1, 0, 1) (its attenuation coefficients are not used: w = 0):
//     n.l = 1/sqrt2; Phong (r.v)^2 = 1/2; Blinn (n.h)^2 = (2 + sqrt2)/4.
//  C: a spot at (0, 0, 2) pointing down (0, 0, -1), 30 degrees, exponent 4 (OpenGL) or inner 10
//     / outer 30 degrees (smooth); attenuation (0, 0, 1): d = 4, f = 1/16; Q on the axis: spot 1.
// I = ka (La + La_A/3 + La_B + La_C/16) + kd (Ld_A/3 + Ld_B/sqrt2 + Ld_C/16)
//                                       + ks (Ls_A/3 + Ls_B s_B + Ls_C/16),  plus emission; alpha appended.

constexpr phong::features three_light_features(phong::specular_model s, phong::spot_model spot, phong::evaluation mode)
{
    return {.scene_ambient = true, .light_ambient = true, .diffuse = true, .specular = s, .specular_gate = true,
            .lights = phong::light_kind::any, .attenuation = phong::attenuation_model::polynomial, .spot = spot,
            .attenuate_ambient = true, .two_sided = phong::facing::view, .view = phong::view_model::eye_at_origin,
            .emission = true, .alpha = true, .mode = mode};
}

template <class T> constexpr std::array<phong::light<T>, 3> three_lights()
{
    phong::light<T> A, B, C;
    A.position = vec4<T>(0, 0, 0, 1);
    A.ambient = vec3<T>(0.25, 0, 0);
    A.diffuse = vec3<T>(1, 0.5, 0.25);
    A.specular = vec3<T>(0.5, 0.5, 1);
    A.attenuation = {T(1), T(0.5), T(0.25), std::numeric_limits<T>::infinity()};
    B.position = vec4<T>(1, 0, 1, 0);
    B.ambient = vec3<T>(0, 0.125, 0);
    B.diffuse = vec3<T>(0.5, 1, 0.5);
    B.specular = vec3<T>(1, 0.25, 0.5);
    B.attenuation = {T(2), T(2), T(2), std::numeric_limits<T>::infinity()}; // ignored: directional
    C.position = vec4<T>(0, 0, 2, 1);
    C.ambient = vec3<T>(0, 0, 1);
    C.diffuse = vec3<T>(4, 8, 16);
    C.specular = vec3<T>(16, 8, 4);
    C.attenuation = {T(0), T(0), T(1), std::numeric_limits<T>::infinity()};
    const auto gl = phong::spot_cone<T>::opengl(vec3<T>(0, 0, -1), T(4), T(30));
    const auto sm = phong::spot_cone<T>::smooth(vec3<T>(0, 0, -1), T(10), T(30));
    C.spot = gl;
    C.spot.cos_inner = sm.cos_inner;
    C.spot.cos_outer = sm.cos_outer;
    return {A, B, C};
}

template <class T> constexpr phong::material<T> three_light_material()
{
    phong::material<T> m;
    m.ka = vec3<T>(0.5, 0.25, 1);
    m.kd = vec3<T>(0.75, 0.5, 0.25);
    m.ks = vec3<T>(0.25, 1, 0.5);
    m.emission = vec3<T>(0.0625, 0, 0.125);
    m.shininess = T(2);
    m.alpha = T(0.5);
    return m;
}

template <class T> constexpr phong::environment<T> three_light_environment()
{
    phong::environment<T> e;
    e.ambient = vec3<T>(0.5, 0.25, 0.125);
    return e;
}

// The hand-worked colour.
template <class T> constexpr vec4<T> three_light_expected(bool blinn)
{
    using W = long double;
    const auto L = three_lights<T>();
    const auto mat = three_light_material<T>();
    const auto env = three_light_environment<T>();
    const W sB = blinn ? (2 + sqrt2) / 4 : W(0.5);
    vec4<T> out(T(0), T(0), T(0), mat.alpha);
    for (int k = 0; k < 3; ++k) {
        const W ambient = W(env.ambient[k]) + W(L[0].ambient[k]) / 3 + W(L[1].ambient[k]) + W(L[2].ambient[k]) / 16;
        const W diffuse = W(L[0].diffuse[k]) / 3 + W(L[1].diffuse[k]) / sqrt2 + W(L[2].diffuse[k]) / 16;
        const W specular = W(L[0].specular[k]) / 3 + W(L[1].specular[k]) * sB + W(L[2].specular[k]) / 16;
        out[k] = T(W(mat.emission[k]) + W(mat.ka[k]) * ambient + W(mat.kd[k]) * diffuse + W(mat.ks[k]) * specular);
    }
    return out;
}

template <phong::features F, class T> constexpr vec4<T> three_light_shade()
{
    return phong::shade<F>(vec3<T>(0, 0, -2), vec3<T>(0, 0, 1), three_light_material<T>(), three_lights<T>(),
                           three_light_environment<T>());
}

using phong::evaluation;
using phong::specular_model;
using phong::spot_model;
template <class T> constexpr bool three_light_shades()
{
    // Tolerance: 16 eps relative to the largest channel (a few roundings per term, three lights).
    static_assert(close(three_light_shade<three_light_features(specular_model::phong, spot_model::opengl, evaluation::exact), T>(),
                        three_light_expected<T>(false), 16));
    static_assert(close(three_light_shade<three_light_features(specular_model::phong, spot_model::opengl, evaluation::stable), T>(),
                        three_light_expected<T>(false), 16));
    static_assert(close(three_light_shade<three_light_features(specular_model::blinn, spot_model::opengl, evaluation::exact), T>(),
                        three_light_expected<T>(true), 16));
    static_assert(close(three_light_shade<three_light_features(specular_model::blinn, spot_model::opengl, evaluation::stable), T>(),
                        three_light_expected<T>(true), 16));
    static_assert(close(three_light_shade<three_light_features(specular_model::phong, spot_model::smooth, evaluation::stable), T>(),
                        three_light_expected<T>(false), 16));
    static_assert(close(three_light_shade<three_light_features(specular_model::blinn, spot_model::smooth, evaluation::exact), T>(),
                        three_light_expected<T>(true), 16));
    static_assert(three_light_shade<three_light_features(specular_model::blinn, spot_model::smooth, evaluation::exact), T>().w == T(0.5));
    // The seed presets evaluate at compile time too.
    static_assert(phong::shade<phong::presets::classic_phong>(vec3<T>(0, 0, -2), vec3<T>(0, 0, 1), three_light_material<T>(),
                                                                three_lights<T>(), three_light_environment<T>())
                      .w == T(0.5));
    static_assert(phong::shade<phong::presets::diffuse_only>(vec3<T>(0, 0, -2), vec3<T>(0, 0, 1), three_light_material<T>(),
                                                                std::array<phong::light<T>, 1>{three_lights<T>()[0]})
                      .x == T(0.75));
    return true;
}
static_assert(three_light_shades<float>());
static_assert(three_light_shades<double>());

// The documented degenerate inputs are constant expressions too (no 1/0, no NaN), in both modes:
// a zero normal, a light at Q, a zero-length directional light, Q at the eye, Blinn with l = -v.
template <class T, evaluation mode> constexpr bool degenerate_shades()
{
    constexpr phong::features F = three_light_features(specular_model::blinn, spot_model::opengl, mode);
    constexpr auto mat = three_light_material<T>();
    constexpr auto env = three_light_environment<T>();
    // Ambient only: emission + ka (La + La_A/3 + La_B + La_C/16), from the 3-light scene above.
    constexpr auto lights = three_lights<T>();
    constexpr vec4<T> expected_ambient = [] {
        vec4<T> e(T(0), T(0), T(0), T(0.5));
        const auto L = three_lights<T>();
        const auto m = three_light_material<T>();
        const auto en = three_light_environment<T>();
        for (int k = 0; k < 3; ++k)
            e[k] = m.emission[k] + m.ka[k] * (en.ambient[k] + L[0].ambient[k] / T(3) + L[1].ambient[k] + L[2].ambient[k] / T(16));
        return e;
    }();
    static_assert(close(phong::shade<F>(vec3<T>(0, 0, -2), vec3<T>(0), mat, lights, env), expected_ambient, 8)); // zero normal
    // Q at the eye: the distances to A (now 0: f = 1/c0 = 1, ambient only), B, C change; no
    // diffuse or specular. Only checks that it is a finite constant.
    static_assert(phong::shade<F>(vec3<T>(0), vec3<T>(0, 0, 1), mat, lights, env).x >= T(0));
    // A light at Q and a zero-length directional light: ambient only.
    constexpr std::array<phong::light<T>, 2> degenerate = [] {
        std::array<phong::light<T>, 2> d{};
        d[0].position = vec4<T>(1, 2, -3, 1);
        d[0].ambient = vec3<T>(0.5);
        d[1].position = vec4<T>(0, 0, 0, 0);
        d[1].ambient = vec3<T>(0.25);
        return d;
    }();
    constexpr vec4<T> only_ambient(mat.emission + mat.ka * (env.ambient + vec3<T>(0.75)), T(0.5));
    static_assert(close(phong::shade<F>(vec3<T>(1, 2, -3), vec3<T>(0, 0, 1), mat, degenerate, env), only_ambient, 8));
    // Blinn with l = -v, m > 0: the lit diffuse only (n.h = 0).
    constexpr std::array<phong::light<T>, 1> behind_eye = [] {
        std::array<phong::light<T>, 1> d{};
        d[0].position = vec4<T>(0, 0, -1, 0); // l = (0, 0, -1) = -v at Q on the axis
        d[0].diffuse = vec3<T>(1);
        d[0].specular = vec3<T>(1);
        return d;
    }();
    constexpr phong::features G = [] {
        phong::features f = three_light_features(specular_model::blinn, spot_model::none, mode);
        f.two_sided = phong::facing::none;
        return f;
    }();
    constexpr vec4<T> lit(mat.emission + mat.ka * env.ambient + mat.kd, T(0.5));
    static_assert(close(phong::shade<G>(vec3<T>(0, 0, -2), vec3<T>(0, 0, -1), mat, behind_eye, env), lit, 8));
    return true;
}
static_assert(degenerate_shades<float, evaluation::exact>());
static_assert(degenerate_shades<float, evaluation::stable>());
static_assert(degenerate_shades<double, evaluation::exact>());
static_assert(degenerate_shades<double, evaluation::stable>());
static_assert(degenerate_shades<float, evaluation::fast>());
static_assert(degenerate_shades<double, evaluation::fast>());

// The fast mode's approximations (phong/core/fast_math.hpp) are constant expressions for scalars:
// within their published relative bounds of hand-worked values, and whole fast shades within the
// power's bound (plus the shade's 16 eps) of the three-light scene's expected colour.
template <class T> constexpr bool within_rel(T a, double b, double rel) { return cabs(double(a) - b) <= rel * cabs(b); }
template <class T> constexpr bool within_rel(const vec4<T>& a, const vec4<T>& b, double rel)
{
    double scale = 0;
    for (int k = 0; k < 4; ++k) scale = cabs(double(b[k])) > scale ? cabs(double(b[k])) : scale;
    for (int k = 0; k < 4; ++k)
        if (!(cabs(double(a[k]) - double(b[k])) <= rel * scale)) return false;
    return true;
}
template <class T> constexpr bool fast_kernels()
{
    using phong::fast::pow_unit_max_rel;
    using phong::fast::rsqrt_max_rel;
    static_assert(within_rel(phong::fast::pow_unit(T(0.5), T(2)), 0.25, pow_unit_max_rel));
    static_assert(within_rel(phong::fast::pow_unit(T(0.75), T(10)), 0.056313514709472656, pow_unit_max_rel)); // 3^10 / 4^10
    static_assert(within_rel(phong::fast::pow_unit(T(0.9), T(0.5)), 0.94868329805051379, pow_unit_max_rel));  // sqrt(0.9)
    static_assert(phong::fast::pow_unit(T(1), T(200)) == T(1) && phong::fast::pow_unit(T(0), T(3)) == T(0));
    static_assert(phong::fast::detail::pow_integer(T(0.5), 10) == T(0x1p-10) && phong::fast::detail::pow_integer(T(0), 0) == T(1) &&
                  phong::fast::detail::pow_integer(T(0), 5) == T(0)); // powers of two are exact; pow(0, 0) = 1
    static_assert(within_rel(phong::fast::detail::pow_integer(T(0.75), 32), 0.00010045242572063329, phong::fast::detail::pow_integer_max_rel<T>)); // (3/4)^32
    static_assert(within_rel(phong::fast::detail::pow_integer(T(0.9375), 63), 0.01714708944101614, phong::fast::detail::pow_integer_max_rel<T>)); // (15/16)^63
    static_assert(within_rel(phong::fast::rsqrt(T(4)), 0.5, rsqrt_max_rel<T>));
    static_assert(within_rel(phong::fast::rsqrt(T(3)), 0.57735026918962576, rsqrt_max_rel<T>));
    constexpr double shade_rel = pow_unit_max_rel + 16 * double(std::numeric_limits<T>::epsilon());
    static_assert(within_rel(three_light_shade<three_light_features(specular_model::phong, spot_model::opengl, evaluation::fast), T>(),
                             three_light_expected<T>(false), shade_rel));
    static_assert(within_rel(three_light_shade<three_light_features(specular_model::blinn, spot_model::smooth, evaluation::fast), T>(),
                             three_light_expected<T>(true), shade_rel));
    return true;
}
static_assert(fast_kernels<float>());
static_assert(fast_kernels<double>());

// ---------------------------------------------------------------------------------------------
// Constant evaluation against run time.

// Tables of arguments, and of results computed at compile time through the public functions.
constexpr int table_size = 96;
template <class T> constexpr std::array<T, table_size> table_args(int kind)
{
    std::array<T, table_size> a{};
    for (int i = 0; i < table_size; ++i) {
        const T frac = T(1) + T((i * 37) % 64) / T(64); // [1, 2)
        switch (kind) {
        case 0: { // sqrt, log: spread over magnitudes 2^-60 .. 2^60
            T s = T(1);
            const int e = (i * 11) % 121 - 60;
            for (int k = 0; k < (e < 0 ? -e : e); ++k) s = e < 0 ? s / 2 : s * 2;
            a[i] = frac * s;
            break;
        }
        case 1: a[i] = T(i - table_size / 2) * T(1.7); break;            // exp: [-82, 80]
        case 2: a[i] = T(i) / T(table_size) * T(4) - T(0.99); break;     // log1p: [-0.99, 3]
        default: a[i] = frac / T(2); break;                              // pow base: [0.5, 1)
        }
    }
    return a;
}
template <class T> constexpr std::array<T, table_size> table_results(int kind)
{
    const std::array<T, table_size> a = table_args<T>(kind == 4 ? 0 : kind); // log: the sqrt arguments
    std::array<T, table_size> r{};
    for (int i = 0; i < table_size; ++i) {
        switch (kind) {
        case 0: r[i] = phong::detail::sqrt(a[i]); break;
        case 1: r[i] = phong::detail::exp(a[i]); break;
        case 2: r[i] = phong::detail::log1p(a[i]); break;
        case 3: r[i] = phong::detail::pow(a[i], T(i) * T(2.5)); break; // m in [0, 237.5]
        default: r[i] = phong::detail::log(a[i]); break;
        }
    }
    return r;
}
template <class T> constexpr auto ce_sqrt_table = table_results<T>(0);
template <class T> constexpr auto ce_exp_table = table_results<T>(1);
template <class T> constexpr auto ce_log1p_table = table_results<T>(2);
template <class T> constexpr auto ce_pow_table = table_results<T>(3);
template <class T> constexpr auto ce_log_table = table_results<T>(4);
} // namespace

TEST_CASE_TEMPLATE("constexpr: compile-time tables equal the run-time functions within constexpr_tolerance_ulp", T, float, double)
{
    const auto tol = std::uint64_t(phong::detail::constexpr_tolerance_ulp);
    const auto sqrt_args = table_args<T>(0), exp_args = table_args<T>(1), log1p_args = table_args<T>(2), pow_args = table_args<T>(3);
    std::uint64_t worst = 0;
    for (int i = 0; i < table_size; ++i) {
        CAPTURE(i);
        worst = std::max(worst, ulp_distance(ce_sqrt_table<T>[i], phong::detail::sqrt(sqrt_args[i])));
        worst = std::max(worst, ulp_distance(ce_log_table<T>[i], phong::detail::log(sqrt_args[i])));
        worst = std::max(worst, ulp_distance(ce_exp_table<T>[i], phong::detail::exp(exp_args[i])));
        worst = std::max(worst, ulp_distance(ce_log1p_table<T>[i], phong::detail::log1p(log1p_args[i])));
        const T p = phong::detail::pow(pow_args[i], T(i) * T(2.5));
        if (std::isnormal(p)) worst = std::max(worst, ulp_distance(ce_pow_table<T>[i], p));
    }
    MESSAGE("compile-time tables vs run time: worst " << worst << " ulp (constexpr_tolerance_ulp = " << tol << ")");
    CHECK(worst <= tol);
}

TEST_CASE_TEMPLATE("constexpr: detail::ce at run time equals std:: within constexpr_tolerance_ulp", T, float, double)
{
    namespace ce = phong::detail::ce;
    const auto tol = std::uint64_t(phong::detail::constexpr_tolerance_ulp);
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> u(0, 1);
    const int range = std::is_same_v<T, float> ? 120 : 1000;
    std::uint64_t w_sqrt = 0, w_exp = 0, w_log = 0, w_log1p = 0, w_pow = 0;
    for (int i = 0; i < 20000; ++i) {
        const T x = T(std::ldexp(1 + u(rng), int((u(rng) * 2 - 1) * range)));
        w_sqrt = std::max(w_sqrt, ulp_distance(T(ce::sqrt(x)), std::sqrt(x)));
        w_log = std::max(w_log, ulp_distance(T(ce::log(x)), std::log(x)));
        const T xe = T((u(rng) * 2 - 1) * (std::is_same_v<T, float> ? 87 : 708));
        w_exp = std::max(w_exp, ulp_distance(T(ce::exp(xe)), std::exp(xe)));
        const T x1 = u(rng) < 0.5 ? T(std::ldexp(u(rng) - 0.5, -int(u(rng) * 60))) : T(u(rng) * 100 - 0.999);
        w_log1p = std::max(w_log1p, ulp_distance(T(ce::log1p(x1)), std::log1p(x1)));
        const T b = T(u(rng)), m = T(u(rng) * 2000);
        const T p = std::pow(b, m);
        if (std::isnormal(p)) w_pow = std::max(w_pow, ulp_distance(T(ce::pow(b, m)), p));
    }
    MESSAGE("detail::ce vs std::, worst ulp: sqrt " << w_sqrt << ", exp " << w_exp << ", log " << w_log << ", log1p " << w_log1p
                                                   << ", pow " << w_pow);
    CHECK(w_sqrt <= tol);
    CHECK(w_exp <= tol);
    CHECK(w_log <= tol);
    CHECK(w_log1p <= tol);
    CHECK(w_pow <= tol);
}

namespace {
// Shade at compile time over a small set of scenes (the three lights seen from several points
// and normals, all feature variants above), stored in constexpr arrays.
constexpr int shade_points = 6;
template <class T> constexpr vec3<T> scene_point(int i)
{
    const vec3<T> Q[shade_points] = {vec3<T>(0, 0, -2), vec3<T>(0.5, -0.25, -3), vec3<T>(-1, 0.75, -1.5),
                                     vec3<T>(0.25, 0.25, -5), vec3<T>(2, -1, -4), vec3<T>(-0.5, -0.5, -2.5)};
    return Q[i];
}
template <class T> constexpr vec3<T> scene_normal(int i)
{
    const vec3<T> n[shade_points] = {vec3<T>(0, 0, 1), vec3<T>(0.25, 0.5, 1), vec3<T>(-0.5, 0.25, 0.75),
                                     vec3<T>(0, -1, 1), vec3<T>(1, 0.5, 0.25), vec3<T>(0.125, 0.125, -1)};
    return n[i];
}
template <phong::features F, class T> constexpr std::array<vec4<T>, shade_points> shade_table()
{
    std::array<vec4<T>, shade_points> r{};
    for (int i = 0; i < shade_points; ++i)
        r[i] = phong::shade<F>(scene_point<T>(i), scene_normal<T>(i), three_light_material<T>(), three_lights<T>(),
                               three_light_environment<T>());
    return r;
}
template <phong::features F, class T> constexpr auto ce_shade_table = shade_table<F, T>();

// Stated tolerance for a whole shade: each kernel call differs by at most constexpr_tolerance_ulp
// between the paths; a shade chains a few (normalizations, the power with m = 2, the spot's
// power with exponent 4) and sums three lights: 8 times the kernel bound, relative to the
// largest channel.
constexpr int shade_constexpr_tolerance_ulp = 8 * phong::detail::constexpr_tolerance_ulp;

template <phong::features F, class T> double shade_table_error()
{
    double worst = 0;
    for (int i = 0; i < shade_points; ++i) {
        const vec4<T> rt = phong::shade<F>(scene_point<T>(i), scene_normal<T>(i), three_light_material<T>(), three_lights<T>(),
                                           three_light_environment<T>());
        const vec4<T>& ct = ce_shade_table<F, T>[i];
        T scale = T(1e-30);
        for (int k = 0; k < 4; ++k) scale = std::max(scale, std::abs(rt[k]));
        for (int k = 0; k < 4; ++k)
            worst = std::max(worst, double(std::abs(ct[k] - rt[k]) / scale / std::numeric_limits<T>::epsilon()));
    }
    return worst;
}
} // namespace

TEST_CASE_TEMPLATE("constexpr: shade evaluated at compile time equals shade at run time", T, float, double)
{
    const double worst = std::max({
        shade_table_error<three_light_features(specular_model::phong, spot_model::opengl, evaluation::exact), T>(),
        shade_table_error<three_light_features(specular_model::phong, spot_model::opengl, evaluation::stable), T>(),
        shade_table_error<three_light_features(specular_model::blinn, spot_model::smooth, evaluation::exact), T>(),
        shade_table_error<three_light_features(specular_model::blinn, spot_model::smooth, evaluation::stable), T>(),
    });
    MESSAGE("shade, compile time vs run time: worst " << worst << " eps of the largest channel (tolerance "
                                                       << shade_constexpr_tolerance_ulp << ")");
    CHECK(worst <= shade_constexpr_tolerance_ulp);
    // The table holds real colours, not zeros: the lights reach the points.
    CHECK(ce_shade_table<three_light_features(specular_model::phong, spot_model::opengl, evaluation::exact), T>[1].r > T(0.3));
}

// Finite in-domain coordinates around 1e30 in float's exact mode evaluate in constant evaluation
// with g++ too: the squared length 1e60 overflows float, which g++ rejects as "not a constant
// expression" when a finite operation gives inf; dot() then returns the inf such an overflow gives
// at run time (vector.hpp), and the scaled length takes over as it does at run time.
namespace {
template <class T> constexpr glm::vec<4, T> huge_scene_color(T scale)
{
    const std::array lights{phong::light<T>::with_strength({T(3) * scale, T(4) * scale, T(12) * scale, T(1)}, {T(1), T(1), T(1)})};
    const phong::material<T> mat{.ka = glm::vec<3, T>(T(0.1)), .kd = glm::vec<3, T>(T(0.6)), .ks = glm::vec<3, T>(T(0.3)), .shininess = T(8)};
    const phong::environment<T> env{.ambient = glm::vec<3, T>(T(0.5))};
    return phong::shade<phong::presets::classic_phong>(glm::vec<3, T>(T(0), T(0), -scale), glm::vec<3, T>(T(0), T(0), T(1)), mat, lights, env);
}
constexpr glm::vec4 huge_float = huge_scene_color(1e30f);
constexpr glm::dvec4 huge_double = huge_scene_color(1e300);
// Finite: the exact mode drops the light, whose squared distance leaves T's range (vector.hpp's
// normal_square, accuracy.hpp's "drops"), leaving the ambient term ka La = 0.1 * 0.5.
static_assert(!is_nan(huge_float.x) && close(huge_float.x, 0.05f, 2) && huge_float.w == 1.0f);
static_assert(!is_nan(huge_double.x) && close(huge_double.x, 0.05, 2) && huge_double.w == 1.0);
} // namespace

TEST_CASE("constexpr: coordinates around 1e30 (float) and 1e300 (double): constant evaluation equals run time")
{
    const float scale_f = 1e30f; // not constant-folded: run time
    const double scale_d = 1e300;
    CHECK(huge_float == huge_scene_color(scale_f));
    CHECK(huge_double == huge_scene_color(scale_d));
}

// dot's constant-evaluation overflow test at float's threshold: max + half an ulp rounds to inf,
// just below it to max (round to nearest), as at run time.
static_assert(phong::detail::dot(glm::vec2(3.4028235e38f, 1e30f), glm::vec2(1.0f, 1.0f)) == 3.4028235e38f); // 1e30 < half an ulp (1e31)
static_assert(phong::detail::dot(glm::vec2(3.4028235e38f, 2.1e31f), glm::vec2(1.0f, 1.0f)) == std::numeric_limits<float>::infinity());
static_assert(phong::detail::dot(glm::vec2(2e19f, 2e19f), glm::vec2(2e19f, 2e19f)) == std::numeric_limits<float>::infinity()); // 4e38 + 4e38
static_assert(is_nan(phong::detail::dot(glm::vec2(2e19f, -2e19f), glm::vec2(2e19f, 2e19f))));                      // inf - inf, as at run time
