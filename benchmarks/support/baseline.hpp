// The baseline: what a user writes by hand from the seeds with plain GLM instead of using phong.
//
// Seed 003's phong.vert (ambient + diffuse + gated specular per light, positional lights, the eye
// at the origin), ported to C++ the obvious way: AoS light structs like the shader's LightInfo,
// glm::normalize / glm::dot / glm::reflect / glm::pow, no guards. Kept honest: no phong code, no
// tricks a typical user would not write, and the same per-light terms as phong's preset
// presets::glsl_ads, so both compute the same colour (its error is measured like any row's).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace phong_bench::naive {

template <class T>
struct LightInfo {
    glm::vec<4, T> Position; // light position in eye coords
    glm::vec<3, T> La;       // ambient light intensity
    glm::vec<3, T> Ld;       // diffuse light intensity
    glm::vec<3, T> Ls;       // specular light intensity
};

template <class T>
struct MaterialInfo {
    glm::vec<3, T> Ka, Kd, Ks;
    T Shininess;
};

/// Seed 003, phong.vert, summed over the lights (reflection-based specular, r = reflect(-s, n)).
template <class T>
glm::vec<3, T> ads(const glm::vec<3, T>& position, const glm::vec<3, T>& normal,
                   const std::vector<LightInfo<T>>& lights, const MaterialInfo<T>& material)
{
    using vec3 = glm::vec<3, T>;
    const vec3 n = glm::normalize(normal);
    const vec3 v = glm::normalize(-position);
    vec3 color(0);
    for (const LightInfo<T>& light : lights) {
        const vec3 s = glm::normalize(vec3(light.Position) - position);
        const vec3 r = glm::reflect(-s, n);
        const T sDotN = glm::max(glm::dot(s, n), T(0));
        const vec3 ambient = light.La * material.Ka;
        const vec3 diffuse = light.Ld * material.Kd * sDotN;
        vec3 spec(0);
        if (sDotN > T(0)) spec = light.Ls * material.Ks * glm::pow(glm::max(glm::dot(r, v), T(0)), material.Shininess);
        color += ambient + diffuse + spec;
    }
    return color;
}

/// The same with seed 001's halfway vector (Blinn-Phong): h = normalize(s + v), (n.h)^f.
template <class T>
glm::vec<3, T> ads_blinn(const glm::vec<3, T>& position, const glm::vec<3, T>& normal,
                         const std::vector<LightInfo<T>>& lights, const MaterialInfo<T>& material)
{
    using vec3 = glm::vec<3, T>;
    const vec3 n = glm::normalize(normal);
    const vec3 v = glm::normalize(-position);
    vec3 color(0);
    for (const LightInfo<T>& light : lights) {
        const vec3 s = glm::normalize(vec3(light.Position) - position);
        const vec3 h = glm::normalize(s + v);
        const T sDotN = glm::max(glm::dot(s, n), T(0));
        const vec3 ambient = light.La * material.Ka;
        const vec3 diffuse = light.Ld * material.Kd * sDotN;
        vec3 spec(0);
        if (sDotN > T(0)) spec = light.Ls * material.Ks * glm::pow(glm::max(glm::dot(n, h), T(0)), material.Shininess);
        color += ambient + diffuse + spec;
    }
    return color;
}

} // namespace phong_bench::naive
