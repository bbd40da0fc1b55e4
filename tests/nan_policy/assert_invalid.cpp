// Run-time half of the NaN / bad-input policy: in a debug build (no NDEBUG) shade() checks
// validate() and shade_batch() its spans; a failure goes to the precondition handler, whose default
// prints "phong: precondition failed: <message> (file:line)" and aborts. `assert_invalid valid`
// shades valid parameters and exits 0 (the control); every other mode must abort with the message
// naming the field (ctest checks stderr, tests/nan_policy/checks.cmake):
//   invalid        material.kd negative          -> "material.kd"
//   light_w        a light with w = 2            -> "light.position.w"
//   batch_overlap  shade_batch's red channel one element past positions.x -> "overlaps an input"
#include <phong/batch.hpp>
#include <phong/phong.hpp>

#include <array>
#include <cstdio>
#include <cstring>
#include <vector>

int main(int argc, char** argv)
{
    using namespace phong;
    const char* mode = argc > 1 ? argv[1] : "valid";
    material<float> mat{};
    std::array<light<float>, 1> lights{light<float>::with_strength({0, 0, 1, 0}, {1, 1, 1})};
    if (std::strcmp(mode, "invalid") == 0) mat.kd.x = -1.0f; // negative reflectivity: validate(mat) fails
    if (std::strcmp(mode, "light_w") == 0) lights[0].position = {0.0f, 0.0f, 2.0f, 2.0f};
    if (std::strcmp(mode, "batch_overlap") == 0) {
        const std::size_t n = 20;
        std::vector<float> x(n + 1, 0.0f), y(n, 0.0f), z(n, -2.0f), nx(n, 0.0f), ny(n, 0.0f), nz(n, 1.0f), g(n), b(n);
        shade_batch<features{}>(soa3<float>{std::span<const float>(x.data(), n), y, z}, soa3<float>{nx, ny, nz}, mat,
                                std::span<const light<float>>(lights),
                                soa_rgba<float>{std::span<float>(x.data() + 1, n), g, b, {}});
        std::printf("assert_invalid: shade_batch returned\n");
        return 0;
    }
    const glm::vec3 c = shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), mat, lights, environment<float>{});
    std::printf("assert_invalid: %s, shade returned (%g, %g, %g)\n", mode, c.x, c.y, c.z);
    return 0;
}
