// A screen-space rasterizer's fragment (issue 27): the normal +z, one directional light along
// l = (0, 3/5, 4/5), the view along +z (fixed_direction, used as given with unit_inputs), per-pixel
// kd, ks and exponent as a phong::surface, no position:
//   I = La kd + kd (n.l) + ks (r.v)^m = 0.1 * 0.5 + 0.5 * 0.8 + 0.25 * 0.8^2 = 0.05 + 0.4 + 0.16 = 0.61.
#include <phong/phong.hpp>
#include <array>
#include <cmath>
#include <cstdio>

int main() {
    using namespace phong;
    constexpr features screen{.scene_ambient = true, .light_ambient = false, .specular_gate = false,
                              .lights = light_kind::directional, .view = view_model::fixed_direction, .unit_inputs = true};
    const std::array lights{light<double>::with_strength({0, 0.6, 0.8, 0}, {1, 1, 1})};
    const std::array<incident<double>, 1> incidents{{{{0, 0.6, 0.8}, 0}}};
    const environment<double> env{.ambient = glm::dvec3(0.1), .eye = {0, 0, 1, 0}};
    const surface<double> texel{.ka = glm::dvec3(0.5), .kd = glm::dvec3(0.5), .ks = glm::dvec3(0.25), .shininess = 2};
    const glm::dvec3 rgb = shade_incident<screen>(glm::dvec3(0, 0, 1), texel, lights, incidents, env);
    std::printf("rgb = %.17g %.17g %.17g (expected 0.61)\n", rgb.r, rgb.g, rgb.b);
    for (int c = 0; c < 3; ++c)
        if (!(std::fabs(rgb[c] - 0.61) <= 1e-15)) return 1;
    return 0;
}
