// Compile-time half of the NaN / bad-input policy: shade() in constant evaluation with parameters
// that validate() rejects must not compile, and the compiler must name
// phong::detail::precondition_failed_see_phong_validate (detail/config.hpp) and print validate()'s
// message, which names the field (checked per case by tests/nan_policy/expect_compile_error.cmake). Compiled once per case
// by ctest (tests/nan_policy/checks.cmake) with -DPHONG_REJECT_CASE=N (1-9); case 0 is the valid control,
// which must compile cleanly (so a failure of the others is not a broken command line).
#include <phong/phong.hpp>

#include <array>
#include <limits>

#ifndef PHONG_REJECT_CASE
#  error "define PHONG_REJECT_CASE"
#endif

using namespace phong;

constexpr material<double> make_material()
{
    material<double> m{};
#if PHONG_REJECT_CASE == 1
    m.kd.y = -0.5; // negative reflectivity
#elif PHONG_REJECT_CASE == 2
    m.shininess = std::numeric_limits<double>::quiet_NaN();
#elif PHONG_REJECT_CASE == 3
    m.alpha = 1.5;
#endif
    return m;
}

constexpr light<double> make_light()
{
    light<double> L = light<double>::with_strength({1, 2, 3, 1}, {1, 1, 1});
#if PHONG_REJECT_CASE == 4
    L.attenuation.constant = -1; // negative attenuation coefficient
#elif PHONG_REJECT_CASE == 5
    L.spot.direction = {0, 0, 2}; // spot axis not unit length
#elif PHONG_REJECT_CASE == 6
    L.position.w = -1;
#elif PHONG_REJECT_CASE == 7
    L.diffuse.x = std::numeric_limits<double>::infinity();
#elif PHONG_REJECT_CASE == 8
    L.position = {2, 4, 6, 2}; // homogeneous w = 2: only w = 0 and w = 1 (light.hpp)
#endif
    return L;
}

constexpr environment<double> make_environment()
{
    environment<double> e{};
#if PHONG_REJECT_CASE == 9
    e.ambient.z = -0.25; // negative scene ambient La
#endif
    return e;
}

constexpr std::array<light<double>, 1> lights{make_light()};
constexpr features F{.attenuation = attenuation_model::polynomial, .spot = spot_model::opengl};
constexpr glm::dvec3 rgb = shade<F>(glm::dvec3(0, 0, -5), glm::dvec3(0, 0, 1), make_material(), lights, make_environment());
static_assert(rgb.x >= 0);
