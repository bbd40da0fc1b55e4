// The lighting a renderer writes by hand on GLM: presets::classic_phong's model (scene ambient,
// diffuse, Phong specular r.v with std::pow, positional or directional lights with polynomial
// attenuation, the normal turned toward the viewer, the eye at the origin, alpha from the
// material). The compile-time benchmark's baseline (benchmarks/compile_time.sh).
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/glm.hpp>

#include <cmath>
#include <span>

namespace hand {

struct light {
    glm::vec4 position;    // w = 0: directional
    glm::vec3 diffuse, specular;
    glm::vec3 attenuation; // c0, c1, c2
};
struct material {
    glm::vec3 ka, kd, ks;
    float shininess, alpha;
};

inline glm::vec4 shade(glm::vec3 Q, glm::vec3 N, const material& m, std::span<const light> lights, glm::vec3 ambient)
{
    const glm::vec3 v = glm::normalize(-Q);
    glm::vec3 n = glm::normalize(N);
    if (glm::dot(n, v) < 0.0f) n = -n;
    glm::vec3 sum = m.ka * ambient;
    for (const light& L : lights) {
        const glm::vec3 d = glm::vec3(L.position) - L.position.w * Q;
        const float dist = glm::length(d);
        const glm::vec3 l = d / dist;
        const float f = L.position.w != 0.0f ? 1.0f / (L.attenuation.x + dist * (L.attenuation.y + L.attenuation.z * dist)) : 1.0f;
        const float nl = glm::max(glm::dot(n, l), 0.0f);
        const glm::vec3 r = glm::reflect(-l, n);
        const float s = std::pow(glm::max(glm::dot(r, v), 0.0f), m.shininess);
        sum += f * (m.kd * L.diffuse * nl + m.ks * L.specular * s);
    }
    return glm::vec4(sum, m.alpha);
}

} // namespace hand
