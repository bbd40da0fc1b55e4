// phong/terms/attenuation.hpp: polynomial and windowed distance falloff, the OpenGL, smooth and linear
// spot cones (and a zero axis: no cone), and the spot_cone factories. Hand-worked values and the documented edges.
// (Monotonicity in distance: tests/properties.test.cpp.)
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/terms/attenuation.hpp>
#include <phong/inputs/light.hpp>
#include <phong/sum/shade.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> constexpr T pinf = std::numeric_limits<T>::infinity();
template <class T> constexpr T qnan = std::numeric_limits<T>::quiet_NaN();
} // namespace

TEST_CASE_TEMPLATE("attenuation: polynomial 1 / (c0 + c1 d + c2 d^2) by hand", T, float, double)
{
    CHECK(phong::attenuation_polynomial(T(7), T(1), T(0), T(0)) == T(1));
    CHECK(phong::attenuation_polynomial(T(2), T(0), T(0), T(1)) == T(0.25));
    CHECK(phong::attenuation_polynomial(T(4), T(0), T(1), T(0)) == T(0.25));
    CHECK(phong::attenuation_polynomial(T(2), T(1), T(0.5), T(0.25)) == T(1) / T(3)); // 1 + 1 + 1
    CHECK(phong::attenuation_polynomial(T(0), T(2), T(5), T(5)) == T(0.5));
    // Defaults of falloff: f = 1 everywhere.
    const phong::falloff<T> none{};
    CHECK(phong::attenuation_polynomial(T(123), none.constant, none.linear, none.quadratic) == T(1));
}

TEST_CASE_TEMPLATE("attenuation: polynomial edges", T, float, double)
{
    // d = 0 with c0 = 0: capped at 1 / phong::detail::attenuation_denominator_min<T>, which is sqrt(smallest
    // normal): 2^-63 for float, 2^-511 for double (hand: float min 2^-126, double min 2^-1022).
    const T cap = T(1) / phong::detail::attenuation_denominator_min<T>;
    CHECK(phong::attenuation_polynomial(T(0), T(0), T(0), T(1)) == cap);
    CHECK(phong::attenuation_polynomial(T(0), T(0), T(1), T(0)) == cap);
    if constexpr (std::is_same_v<T, float>) CHECK(cap == std::ldexp(1.0f, 63));
    else CHECK(cap == std::ldexp(1.0, 511));
    CHECK(std::isfinite(cap));
    // d = inf: 0 when c1 + c2 > 0, c0's 1/c0 when only c0 (no 0 * inf).
    CHECK(phong::attenuation_polynomial(pinf<T>, T(1), T(0), T(1)) == T(0));
    // With c2 = 0 and c1 > 0, d = inf is taken as max (documented): f = 1 / (c0 + c1 max),
    // tiny (2.9e-39 in float), finite and non-negative.
    const T linear_only = phong::attenuation_polynomial(pinf<T>, T(1), T(1), T(0));
    CHECK(linear_only >= T(0));
    CHECK(linear_only <= T(1) / std::numeric_limits<T>::max() * T(1.0001));
    CHECK(phong::attenuation_polynomial(pinf<T>, T(2), T(0), T(0)) == T(0.5));
    // A huge finite d with c2 = 0: finite, tiny.
    const T big = std::numeric_limits<T>::max() / T(2);
    const T f = phong::attenuation_polynomial(big, T(1), T(1), T(0));
    CHECK(f >= T(0));
    CHECK(f < T(1e-30));
    // NaN d gives NaN.
    CHECK(std::isnan(phong::attenuation_polynomial(qnan<T>, T(1), T(1), T(1))));
}

TEST_CASE_TEMPLATE("attenuation: windowed inverse square by hand", T, float, double)
{
    // d = range / 2: window = (1 - 1/16)^2 = 225/256, f = 225/256 / d^2.
    CHECK(error_ulp(phong::attenuation_windowed(T(2), T(4)), wide(225) / 256 / 4) <= 2.0);
    CHECK(error_ulp(phong::attenuation_windowed(T(0.5), T(1)), wide(225) / 256 * 4) <= 2.0);
    // d = range and beyond: exactly 0.
    CHECK(phong::attenuation_windowed(T(4), T(4)) == T(0));
    CHECK(phong::attenuation_windowed(T(5), T(4)) == T(0));
    CHECK(phong::attenuation_windowed(T(1e30), T(4)) == T(0));
    CHECK(phong::attenuation_windowed(pinf<T>, T(4)) == T(0));
    // range = inf: pure inverse square.
    CHECK(phong::attenuation_windowed(T(2), pinf<T>) == T(0.25));
    CHECK(phong::attenuation_windowed(T(8), pinf<T>) == T(1) / T(64));
    // d = 0: the same finite cap as the polynomial model.
    CHECK(phong::attenuation_windowed(T(0), T(4)) == T(1) / phong::detail::attenuation_denominator_min<T>);
}

TEST_CASE_TEMPLATE("attenuation: OpenGL spot cone", T, float, double)
{
    const vec3<T> s(0, 0, -1);           // the light points down -z
    const vec3<T> l_axis(0, 0, 1);       // Q straight below the light: l toward the light is +z
    const T h = T(1) / std::sqrt(T(2));
    const vec3<T> l_45(h, T(0), h);      // 45 degrees off the axis: c = cos 45
    const vec3<T> l_side(1, 0, 0);       // 90 degrees: c = 0
    // cos_cutoff = -1 (180 degrees): no spot, 1 everywhere, even behind.
    CHECK(phong::spot_opengl(l_axis, s, T(5), T(-1)) == T(1));
    CHECK(phong::spot_opengl(-l_axis, s, T(5), T(-1)) == T(1));
    // Inside the cutoff: max(c, 0)^e; on the axis c = 1.
    CHECK(phong::spot_opengl(l_axis, s, T(5), T(0.5)) == T(1));
    CHECK(error_ulp(phong::spot_opengl(l_45, s, T(2), T(0.5)), wide(0.5)) <= 2.0); // (1/sqrt2)^2
    // Outside (45 degrees with a 30 degree cutoff): 0.
    CHECK(phong::spot_opengl(l_45, s, T(2), phong::detail::cos_degrees(T(30))) == T(0));
    // e = 0: a hard-edged cone of strength 1.
    CHECK(phong::spot_opengl(l_45, s, T(0), T(0.5)) == T(1));
    // Documented edge: l = 0 (light at Q) gives c = 0: inside only for a 90 degree cutoff, then
    // 0^e (1 for e = 0).
    CHECK(phong::spot_opengl(vec3<T>(0), s, T(3), T(0)) == T(0));
    CHECK(phong::spot_opengl(vec3<T>(0), s, T(0), T(0)) == T(1));
    CHECK(phong::spot_opengl(vec3<T>(0), s, T(0), T(0.5)) == T(0));
    CHECK(phong::spot_opengl(l_side, s, T(0), T(0)) == T(1)); // c = 0 >= cos 90 = 0
}

TEST_CASE_TEMPLATE("attenuation: smooth spot cone", T, float, double)
{
    const vec3<T> s(0, 0, -1);
    auto l_at = [](double degrees) { // l toward the light for Q at `degrees` off the axis
        const double a = degrees * 3.14159265358979323846 / 180;
        return vec3<T>(T(std::sin(a)), T(0), T(std::cos(a)));
    };
    const T cos_inner = T(0.8), cos_outer = T(0.6);
    CHECK(phong::spot_smooth(l_at(0), s, cos_inner, cos_outer) == T(1));
    CHECK(phong::spot_smooth(l_at(80), s, cos_inner, cos_outer) == T(0));
    // c = 0.7, halfway: t = 1/2, smoothstep = 1/4 (3 - 1) = 1/2.
    const vec3<T> l_mid(T(std::sqrt(0.51)), T(0), T(0.7));
    CHECK(error_rel(phong::spot_smooth(l_mid, s, cos_inner, cos_outer), wide(0.5)) <= 16 * double(tolerance<T>::eps));
    // c = 0.65: t = 1/4, smoothstep = 1/16 (3 - 1/2) = 5/32.
    const vec3<T> l_q(T(std::sqrt(1 - 0.65 * 0.65)), T(0), T(0.65));
    CHECK(error_rel(phong::spot_smooth(l_q, s, cos_inner, cos_outer), wide(5) / 32) <= 64 * double(tolerance<T>::eps));
    // cos_inner == cos_outer: a hard edge, no division by zero.
    CHECK(phong::spot_smooth(l_at(10), s, T(0.9), T(0.9)) == T(1));
    CHECK(phong::spot_smooth(l_at(30), s, T(0.9), T(0.9)) == T(0));
    // Both -1: no spot.
    CHECK(phong::spot_smooth(l_at(170), s, T(-1), T(-1)) == T(1));
    // Defaults of spot_cone: no spot in either model.
    const phong::spot_cone<T> none{};
    CHECK(phong::spot_opengl(l_at(120), none.direction, none.exponent, none.cos_cutoff) == T(1));
    CHECK(phong::spot_smooth(l_at(120), none.direction, none.cos_inner, none.cos_outer) == T(1));
}

TEST_CASE_TEMPLATE("attenuation: linear spot cone", T, float, double)
{
    const vec3<T> s(0, 0, -1);
    auto l_at = [](double degrees) { // l toward the light for Q at `degrees` off the axis
        const double a = degrees * 3.14159265358979323846 / 180;
        return vec3<T>(T(std::sin(a)), T(0), T(std::cos(a)));
    };
    // LearnOpenGL's flashlight: inner 12.5 degrees, outer 17.5; the formula written literally in
    // long double, clamp((theta - outer) / (inner - outer), 0, 1), at angles across the edge.
    const T cos_inner = T(std::cos(12.5L * 3.14159265358979323846L / 180)), cos_outer = T(std::cos(17.5L * 3.14159265358979323846L / 180));
    for (const double degrees : {0.0, 5.0, 12.0, 13.0, 14.0, 15.0, 16.0, 17.0, 17.4, 18.0, 45.0, 90.0, 135.0, 180.0}) {
        CAPTURE(degrees);
        const vec3<T> l = l_at(degrees);
        const long double theta = -(static_cast<long double>(l.x) * s.x + static_cast<long double>(l.y) * s.y +
                                    static_cast<long double>(l.z) * s.z);
        const long double literal = std::clamp((theta - cos_outer) / (static_cast<long double>(cos_inner) - cos_outer), 0.0L, 1.0L);
        const T got = phong::spot_linear(l, s, cos_inner, cos_outer);
        // The bound: the cosine's rounding (3 eps) over the cone's width, plus the quotient's 2 eps.
        const long double width = static_cast<long double>(cos_inner) - cos_outer;
        CHECK(std::fabs(static_cast<long double>(got) - literal) <= (3 / width + 2) * tolerance<T>::eps);
        CHECK(got >= T(0));
        CHECK(got <= T(1));
    }
    // By hand: cos_inner 0.8, cos_outer 0.6; c = 0.7 is halfway (1/2), c = 0.65 a quarter (1/4),
    // 0 outside, 1 inside.
    const vec3<T> l_mid(T(std::sqrt(0.51)), T(0), T(0.7));
    CHECK(error_rel(phong::spot_linear(l_mid, s, T(0.8), T(0.6)), wide(0.5)) <= 32 * double(tolerance<T>::eps));
    const vec3<T> l_q(T(std::sqrt(1 - 0.65 * 0.65)), T(0), T(0.65));
    CHECK(error_rel(phong::spot_linear(l_q, s, T(0.8), T(0.6)), wide(0.25)) <= 64 * double(tolerance<T>::eps));
    CHECK(phong::spot_linear(l_at(0), s, T(0.8), T(0.6)) == T(1));
    CHECK(phong::spot_linear(l_at(80), s, T(0.8), T(0.6)) == T(0));
    // Below smoothstep inside the edge's lower half, above it in the upper half (t < 1/2: t > t^2 (3 - 2t)).
    CHECK(phong::spot_linear(l_q, s, T(0.8), T(0.6)) > phong::spot_smooth(l_q, s, T(0.8), T(0.6)));
    // cos_inner == cos_outer: a hard edge, no division by zero.
    CHECK(phong::spot_linear(l_at(10), s, T(0.9), T(0.9)) == T(1));
    CHECK(phong::spot_linear(l_at(30), s, T(0.9), T(0.9)) == T(0));
    CHECK(phong::spot_linear(l_at(0), s, T(0), T(0)) == T(1));
    // Both -1: no cone. l = 0 (light at Q): c = 0.
    CHECK(phong::spot_linear(l_at(170), s, T(-1), T(-1)) == T(1));
    CHECK(phong::spot_linear(vec3<T>(0), s, T(0.5), T(-0.5)) == T(0.5));
    const phong::spot_cone<T> none{};
    CHECK(phong::spot_linear(l_at(120), none.direction, none.cos_inner, none.cos_outer) == T(1));
}

namespace {
/// One light at (0, 0, 4) above the point Q = 0 with normal +z: diffuse only, so the colour is
/// the light factor f times n.l = 1 (kd = Ld = 1, no ambient).
template <phong::spot_model Spot, class T> T lit_by(const phong::spot_cone<T>& cone)
{
    constexpr phong::features F{.scene_ambient = false, .specular = phong::specular_model::none, .spot = Spot};
    phong::light<T> L = phong::light<T>::with_strength({0, 0, 4, 1}, {1, 1, 1});
    L.spot = cone;
    const phong::material<T> m{.ka = vec3<T>(0), .kd = vec3<T>(1), .ks = vec3<T>(0), .shininess = T(1)};
    const std::array lights{L};
    return phong::shade<F>(vec3<T>(0), vec3<T>(0, 0, 1), m, lights).x;
}
} // namespace

// The convention for lights without a cone: shader uniforms default to 0, so a light whose spot
// fields are all zero (axis 0, cos_inner = cos_outer = cos_cutoff = 0, exponent 0) is lit by every
// spot model, not dark; validate accepts it.
TEST_CASE_TEMPLATE("attenuation: a zero spot axis is no cone, in every spot model", T, float, double)
{
    const phong::spot_cone<T> zero{.direction = vec3<T>(0), .exponent = T(0), .cos_cutoff = T(0), .cos_inner = T(0), .cos_outer = T(0)};
    CHECK(lit_by<phong::spot_model::opengl>(zero) == T(1));
    CHECK(lit_by<phong::spot_model::smooth>(zero) == T(1));
    CHECK(lit_by<phong::spot_model::linear>(zero) == T(1));
    phong::light<T> L = phong::light<T>::with_strength({0, 0, 4, 1}, {1, 1, 1});
    L.spot = zero;
    CHECK(static_cast<bool>(phong::validate(L)));
    // The same cone with an axis pointing away from Q (Q is 180 degrees off it): dark.
    phong::spot_cone<T> away = zero;
    away.direction = vec3<T>(0, 0, 1);
    CHECK(lit_by<phong::spot_model::opengl>(away) == T(0));
    CHECK(lit_by<phong::spot_model::smooth>(away) == T(0));
    CHECK(lit_by<phong::spot_model::linear>(away) == T(0));
    // A linear cone through shade, by hand: the axis (-0.6, 0, -0.8), edges at cos 0.9 and 0.5.
    phong::spot_cone<T> cone{.direction = vec3<T>(T(-0.6), T(0), T(-0.8)), .cos_inner = T(0.9), .cos_outer = T(0.5)};
    // c = -l.s with l = (0, 0, 1): c = 0.8; spot = (0.8 - 0.5) / 0.4 = 0.75.
    CHECK(error_rel(lit_by<phong::spot_model::linear>(cone), wide(0.75)) <= 16 * double(tolerance<T>::eps));
    // smoothstep of t = 0.75: 0.5625 (3 - 1.5) = 0.84375.
    CHECK(error_rel(lit_by<phong::spot_model::smooth>(cone), wide(0.84375)) <= 32 * double(tolerance<T>::eps));
}

TEST_CASE_TEMPLATE("attenuation: spot_cone factories", T, float, double)
{
    const auto gl = phong::spot_cone<T>::opengl(vec3<T>(0, 0, -4), T(3), T(60));
    CHECK(gl.direction == vec3<T>(0, 0, -1)); // normalized
    CHECK(gl.exponent == T(3));
    CHECK(error_ulp(gl.cos_cutoff, wide(0.5)) <= 1.0); // cos 60
    CHECK(phong::spot_cone<T>::opengl(vec3<T>(1, 0, 0), T(0), T(180)).cos_cutoff == T(-1));
    CHECK(phong::spot_cone<T>::opengl(vec3<T>(1, 0, 0), T(0), T(90)).cos_cutoff == T(0));
    const auto sm = phong::spot_cone<T>::smooth(vec3<T>(0, 3, 4), T(0), T(60));
    CHECK(error_ulp(sm.direction.y, wide(0.6)) < 2.0);
    CHECK(error_ulp(sm.direction.z, wide(0.8)) < 2.0);
    CHECK(sm.cos_inner == T(1));
    CHECK(error_ulp(sm.cos_outer, wide(0.5)) <= 1.0);
}

namespace {
/// validate(light) of a light carrying the given cone: the message, or "ok".
template <class T> constexpr const char* cone_verdict(const phong::spot_cone<T>& cone)
{
    phong::light<T> L = phong::light<T>::with_strength({0, 0, 1, 1}, {1, 1, 1});
    L.spot = cone;
    return phong::validate(L).message();
}
template <class T> constexpr bool cone_rejected(const phong::spot_cone<T>& cone, const char* field)
{
    const char* m = cone_verdict(cone);
    for (std::size_t i = 0; field[i] != '\0'; ++i)
        if (m[i] != field[i]) return false;
    return true;
}
} // namespace

// validate keeps attenuation.hpp's word: an OpenGL cutoff outside [0, 90] other than 180, or a
// smooth angle outside [0, 180], is rejected, although its cosine is that of an angle in range
// (cos(-10) = cos(10), cos(270) = cos(90), cos(200) = cos(160)).
TEST_CASE_TEMPLATE("attenuation: validate rejects spot cutoffs and smooth cones out of range", T, float, double)
{
    const vec3<T> axis(0, 0, -1);
    using cone = phong::spot_cone<T>;
    for (const T bad : {T(-10), T(-1e-3), T(90.5), T(179), T(181), T(270), T(-180), std::numeric_limits<T>::quiet_NaN()}) {
        CAPTURE(bad);
        CHECK(cone_rejected(cone::opengl(axis, T(2), bad), "light.spot.cos_cutoff"));
    }
    for (const T good : {T(0), T(10), T(90), T(180)}) {
        CAPTURE(good);
        CHECK(std::string(cone_verdict(cone::opengl(axis, T(2), good))) == "ok");
    }
    CHECK(cone_rejected(cone::smooth(axis, T(20), T(200)), "light.spot.cos_outer"));
    CHECK(cone_rejected(cone::smooth(axis, T(-30), T(40)), "light.spot.cos_inner"));
    CHECK(cone_rejected(cone::smooth(axis, T(-30), T(-20)), "light.spot.cos_inner"));
    CHECK(cone_rejected(cone::smooth(axis, T(40), T(30)), "light.spot.cos_outer")); // inner beyond outer
    CHECK(cone_rejected(cone::smooth(axis, T(10), T(190)), "light.spot.cos_outer"));
    CHECK(std::string(cone_verdict(cone::smooth(axis, T(0), T(180)))) == "ok");
    CHECK(std::string(cone_verdict(cone::smooth(axis, T(30), T(30)))) == "ok"); // a hard edge
}

// The same in constant evaluation.
static_assert(cone_rejected(phong::spot_cone<float>::opengl({0, 0, -1}, 2.0f, -10.0f), "light.spot.cos_cutoff"));
static_assert(cone_rejected(phong::spot_cone<double>::opengl({0, 0, -1}, 2.0, 270.0), "light.spot.cos_cutoff"));
static_assert(cone_rejected(phong::spot_cone<float>::smooth({0, 0, -1}, 20.0f, 200.0f), "light.spot.cos_outer"));
static_assert(cone_rejected(phong::spot_cone<double>::smooth({0, 0, -1}, -5.0, 40.0), "light.spot.cos_inner"));
static_assert(cone_rejected(phong::spot_cone<double>::smooth({0, 0, -1}, 50.0, 40.0), "light.spot.cos_outer"));
static_assert(cone_verdict(phong::spot_cone<float>::opengl({0, 0, -1}, 2.0f, 45.0f))[0] == 'o');
