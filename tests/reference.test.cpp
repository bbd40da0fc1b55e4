// The reference model itself, checked against hand-worked values (so that the oracle the other
// tests lean on is not just trusted).
#include "support/numeric.hpp"
#include "support/reference.hpp"

#include <doctest/doctest.h>

#include <array>

using namespace phong_test;

TEST_CASE("reference: one light straight above, by hand")
{
    // Q = (0, 0, -2), n = (0, 0, 1), light at (0, 0, 0) w = 1: l = (0, 0, 1), v = (0, 0, 1),
    // n.l = 1, r = l, r.v = 1. I = ka La + kd Ld + ks Ls = 0.1*0.5 + 0.6*1 + 0.3*1 = 0.95.
    phong::material<double> mat{.ka = glm::dvec3(0.1), .kd = glm::dvec3(0.6), .ks = glm::dvec3(0.3), .shininess = 7};
    std::array<phong::light<double>, 1> L{phong::light<double>::with_strength({0, 0, 0, 1}, glm::dvec3(1))};
    phong::environment<double> env{.ambient = glm::dvec3(0.5)};
    const wcolor c = reference_shade<double>(phong::features{}, {0, 0, -2}, {0, 0, 1}, mat, L, env);
    CHECK(double(c.r) == doctest::Approx(0.95).epsilon(1e-15));
}

TEST_CASE("reference: 45 degree light, Phong and Blinn by hand")
{
    // Q = origin-shifted: Q = (0, 0, -1), n = (0, 0, 1), directional light along (1, 0, 1):
    // l = (1, 0, 1)/sqrt2, n.l = 1/sqrt2; v = (0, 0, 1).
    // Phong: r = 2 (n.l) n - l = (-1, 0, 1)/sqrt2, r.v = 1/sqrt2, (r.v)^2 = 1/2.
    // Blinn: h = normalize(l + v), n.h = cos(22.5 deg), (n.h)^2 = (1 + cos 45)/2 = (2 + sqrt2)/4.
    phong::material<double> mat{.ka = glm::dvec3(0), .kd = glm::dvec3(0), .ks = glm::dvec3(1), .shininess = 2};
    std::array<phong::light<double>, 1> L{phong::light<double>::with_strength({1, 0, 1, 0}, glm::dvec3(1))};
    phong::features F{.scene_ambient = false, .diffuse = false};
    const wcolor phong_c = reference_shade<double>(F, {0, 0, -1}, {0, 0, 1}, mat, L);
    CHECK(double(phong_c.r) == doctest::Approx(0.5).epsilon(1e-15));
    F.specular = phong::specular_model::blinn;
    const wcolor blinn_c = reference_shade<double>(F, {0, 0, -1}, {0, 0, 1}, mat, L);
    CHECK(double(blinn_c.r) == doctest::Approx((2 + std::sqrt(2.0)) / 4).epsilon(1e-15));
}
