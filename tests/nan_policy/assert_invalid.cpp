// Run-time half of the NaN / bad-input policy: in a debug build (no NDEBUG) shade() asserts
// validate(), so calling it with an invalid material aborts. `assert_invalid valid` shades valid
// parameters and exits 0 (the control); `assert_invalid invalid` must abort with an assertion
// message (ctest checks it, tests/nan_policy/checks.cmake).
#include <phong/phong.hpp>

#include <array>
#include <cstdio>
#include <cstring>

int main(int argc, char** argv)
{
    using namespace phong;
    const bool invalid = argc > 1 && std::strcmp(argv[1], "invalid") == 0;
    material<float> mat{};
    if (invalid) mat.kd.x = -1.0f; // negative reflectivity: validate(mat) fails
    const std::array<light<float>, 1> lights{light<float>::seed000({0, 0, 1, 0}, {1, 1, 1})};
    const glm::vec3 c = shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), mat, lights, environment<float>{});
    std::printf("assert_invalid: %s parameters, shade returned (%g, %g, %g)\n", invalid ? "invalid" : "valid", c.x, c.y, c.z);
    return 0;
}
