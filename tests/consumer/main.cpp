// One point lit by one white directional light straight along its normal: l = v = n, so
// I = ka La + kd (n.l) L + ks (r.v)^m L = 0.2 * 0.5 + 0.6 * 1 + 0.3 * 1 = 1 in every channel.
#include <phong/phong.hpp>
#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using namespace phong;
    const std::array lights{light<double>::with_strength({0, 0, 1, 0}, {1, 1, 1})}; // w = 0: directional
    const material<double> mat{.ka = glm::dvec3(0.2), .kd = glm::dvec3(0.6), .ks = glm::dvec3(0.3), .shininess = 16};
    const environment<double> env{.ambient = glm::dvec3(0.5)};
    // Classic Phong in eye coordinates: the point Q = (0, 0, -2), its normal +z, the eye at the origin.
    const glm::dvec4 rgba = shade<presets::classic_phong>(glm::dvec3(0, 0, -2), glm::dvec3(0, 0, 1), mat, lights, env);
    std::printf("rgba = %.17g %.17g %.17g %.17g (expected 1)\n", rgba.r, rgba.g, rgba.b, rgba.a);
    for (int c = 0; c < 4; ++c)
        if (!(std::fabs(rgba[c] - 1.0) <= 4e-16)) return 1;
    return 0;
}
