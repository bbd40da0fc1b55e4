// Shades one point with an installed phong and checks the result against the seed formula
// evaluated by hand (see the numbers below); exit status 0 on success.
#include <phong/phong.hpp>

#include <array>
#include <cmath>
#include <cstdio>

int main()
{
    using namespace phong;
    // Q = (0, 0, -2) facing the eye (n = +z), one white directional light straight along n:
    // l = v = n, so n.l = 1 and r = reflect(-l, n) = n, r.v = 1. Seed 000:
    //   I = ka La + kd (n.l) L + ks (r.v)^m L = 0.2 * 0.5 + 0.6 * 1 + 0.3 * 1 = 1.0 (every channel).
    const std::array<light<double>, 1> lights{light<double>::seed000({0, 0, 1, 0}, {1, 1, 1})};
    const material<double> mat{.ka = glm::dvec3(0.2), .kd = glm::dvec3(0.6), .ks = glm::dvec3(0.3), .shininess = 16};
    const environment<double> env{.ambient = glm::dvec3(0.5)};
    const glm::dvec3 rgb = shade<features{}>(glm::dvec3(0, 0, -2), glm::dvec3(0, 0, 1), mat, lights, env);
    std::printf("consumer: shade = %.17g %.17g %.17g (expected 1)\n", rgb.r, rgb.g, rgb.b);
    for (int c = 0; c < 3; ++c)
        if (!(std::fabs(rgb[c] - 1.0) <= 4e-16)) return 1;
    return 0;
}
