// Built with -ffast-math (or -fassociative-math): the stable mode's twofold route (double, or float
// with precision = twofold) is a compile error naming the flag and the alternatives; the exact and
// fast modes and float's stable mode with precision = wider compile and are right there (case 0,
// the valid control). Case 1: double stable; case 2: float stable, precision = twofold. Built by
// tests/nan_policy/checks.cmake (with -ffast-math) and .ci/steps/36-fast-math.sh.
#include <phong/phong.hpp>

#include <array>

int main()
{
    using namespace phong;
    constexpr features stable = presets::with_mode(features{}, evaluation::stable);
#if PHONG_REJECT_CASE == 0
    constexpr features wider = stable;
    const std::array lights{light<float>::with_strength({0, 0, 1, 0}, glm::vec3(1))};
    const glm::vec3 a = shade<wider>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, lights);
    const std::array dlights{light<double>::with_strength({0, 0, 1, 0}, glm::dvec3(1))};
    const glm::dvec3 b = shade<features{}>(glm::dvec3(0, 0, -2), glm::dvec3(0, 0, 1), material<double>{}, dlights);
    const glm::dvec3 c = shade<presets::with_mode(features{}, evaluation::fast)>(glm::dvec3(0, 0, -2), glm::dvec3(0, 0, 1), material<double>{}, dlights);
    return a.x > 0 && b.x > 0 && c.x > 0 ? 0 : 1;
#elif PHONG_REJECT_CASE == 1
    const std::array lights{light<double>::with_strength({0, 0, 1, 0}, glm::dvec3(1))};
    return shade<stable>(glm::dvec3(0, 0, -2), glm::dvec3(0, 0, 1), material<double>{}, lights).x > 0 ? 0 : 1;
#else
    constexpr features twofold = [] {
        features f = presets::with_mode(features{}, evaluation::stable);
        f.precision = stable_precision::twofold;
        return f;
    }();
    const std::array lights{light<float>::with_strength({0, 0, 1, 0}, glm::vec3(1))};
    return shade<twofold>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, lights).x > 0 ? 0 : 1;
#endif
}
