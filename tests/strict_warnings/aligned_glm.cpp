// GLM with 16-byte vec3 (GLM_FORCE_DEFAULT_ALIGNED_GENTYPES + GLM_FORCE_INTRINSICS, which a user
// sets before any GLM header): shade_batch on glm::vec3 arrays (aos_points; colours as vec4 for
// classic_phong, as vec3 for blinn_phong_per_light_ambient) must give, point by point, what shade<F> gives for the same point. Exits 1 on the first
// point whose colour differs by more than 1e-5 relative (the batch's float lanes round differently)
// or if vec3 is not 16 bytes (the macros did not take effect). Run by tests/strict_warnings/check.sh.
// SPDX-License-Identifier: MIT
#include <phong/batch.hpp>
#include <phong/phong.hpp>

#include <cmath>
#include <cstdio>
#include <vector>

int main()
{
    static_assert(sizeof(glm::vec3) == 16, "GLM_FORCE_DEFAULT_ALIGNED_GENTYPES did not take effect");
    constexpr phong::features F = phong::presets::classic_phong, G = phong::presets::blinn_phong_per_light_ambient; // RGBA, RGB
    const phong::material<float> m{.ka = glm::vec3(0.1f), .kd = glm::vec3(0.6f, 0.5f, 0.4f), .ks = glm::vec3(0.3f), .shininess = 24};
    const std::vector<phong::light<float>> lights = {phong::light<float>::with_strength(glm::vec4(1, 2, 3, 1), glm::vec3(1), {1, 0.1f, 0.01f}),
                                                     phong::light<float>::with_strength(glm::vec4(0, 0, 1, 0), glm::vec3(0.5f))};
    const phong::environment<float> env{.ambient = glm::vec3(0.2f), .eye = glm::vec4(0.1f, 0.2f, 0.3f, 1)};
    const std::size_t n = 1003; // not a multiple of any lane count
    std::vector<glm::vec3> P(n), N(n), out3(n);
    std::vector<glm::vec4> out4(n);
    for (std::size_t i = 0; i < n; ++i) {
        const float t = float(i) / float(n);
        P[i] = glm::vec3(std::sin(7.0f * t), std::cos(5.0f * t), -2.0f - t);
        N[i] = glm::normalize(glm::vec3(std::cos(11.0f * t), std::sin(3.0f * t), 1.0f));
    }
    phong::shade_batch<F>(phong::aos_points<float>{P, N}, m, lights, out4, env);
    phong::shade_batch<G>(phong::aos_points<float>{P, N}, m, lights, out3, env);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec4 want4 = phong::shade<F>(P[i], N[i], m, lights, env);
        const glm::vec3 want3 = phong::shade<G>(P[i], N[i], m, lights, env);
        for (glm::length_t c = 0; c < 4; ++c) {
            const float got = out4[i][c], want = want4[c], got3 = c < 3 ? out3[i][c] : 0.0f, expected3 = c < 3 ? want3[c] : 0.0f;
            if (!(std::fabs(got - want) <= 1e-5f * std::fabs(want)) || !(std::fabs(got3 - expected3) <= 1e-5f * std::fabs(expected3))) {
                std::printf("aligned_glm: point %zu channel %d: batch %.9g / %.9g, shade %.9g / %.9g\n", i, int(c), double(got),
                            double(got3), double(want), double(expected3));
                return 1;
            }
        }
    }
    std::printf("aligned_glm: %zu points, shade_batch on 16-byte vec3 arrays agrees with shade<F>\n", n);
    return 0;
}
