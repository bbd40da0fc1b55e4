// A light type without a phong::light_traits specialization: shade<F> stops with one static_assert
// that names light_traits (the fix), not a cascade from inside the route. Case 0 is the valid
// control (the same type with its specialization); case 1 must fail. Built by
// tests/nan_policy/checks.cmake.
#include <phong/sum/shade.hpp>

#include <vector>

struct tracer_light {
    glm::vec3 position, colour;
};

#if PHONG_REJECT_CASE == 0
template <> struct phong::light_traits<tracer_light> {
    static glm::vec4 position(const tracer_light& L) { return glm::vec4(L.position, 1.0f); }
    static const glm::vec3& diffuse(const tracer_light& L) { return L.colour; }
    static const glm::vec3& specular(const tracer_light& L) { return L.colour; }
};
#endif

int main()
{
    const std::vector<tracer_light> lights{{{1, 2, 3}, {1, 1, 1}}};
    const glm::vec3 c = phong::shade<phong::presets::raytracer_phong>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), glm::vec3(0, 0, 1),
                                                                      phong::material<float>{}, phong::masked(lights, 1u));
    return c.r >= 0 ? 0 : 1;
}
