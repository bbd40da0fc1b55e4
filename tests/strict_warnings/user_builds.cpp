// A user's file: every public header, and a call into each (scalar shade, shade_batch, a BSDF
// sample, a primitive's normal, the GLSL defines). tests/strict_warnings/check.sh compiles it with
// g++ and clang++ and its strict warnings as errors, the ways users build: without exceptions and
// RTTI (-fno-exceptions -fno-rtti, as game engines do) and with GLM's macros that change its types.
// SPDX-License-Identifier: MIT
#include <phong/batch.hpp>
#include <phong/accuracy.hpp>
#include <phong/bsdf.hpp>
#include <phong/glsl.hpp>
#include <phong/phong.hpp>
#include <phong/primitives.hpp>

#include <span>
#include <string>

glm::vec4 user_shade(const glm::vec3& P, const glm::vec3& n, const phong::material<float>& m,
                     std::span<const phong::light<float>> lights)
{
    const phong::environment<float> env{.ambient = glm::vec3(0.2f)};
    return phong::shade<phong::presets::classic_phong>(P, n, m, lights, env) +
           phong::shade<phong::presets::with_mode(phong::presets::classic_phong, phong::evaluation::stable)>(P, n, m, lights, env);
}

void user_batch(std::span<const glm::vec3> P, std::span<const glm::vec3> n, const phong::material<float>& m,
                std::span<const phong::light<float>> lights, std::span<glm::vec3> out)
{
    phong::shade_batch<phong::presets::glsl_ads>(phong::aos_points<float>{P, n}, m, lights, out);
}

float user_bsdf(const phong::material<float>& m, const glm::vec3& n, const glm::vec3& wo_world, float u0, float u1)
{
    const phong::shading_frame<float> frame = phong::local_frame(n);
    const phong::bsdf_sample<float> s = phong::modified_phong_bsdf<float>(m).sample(frame.to_local(wo_world), glm::vec2(u0, u1));
    return s.pdf + phong::sphere_normal(wo_world).x;
}

std::string user_glsl() { return phong::glsl::defines(phong::presets::glsl_ads); }
