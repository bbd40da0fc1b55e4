// A renderer's shared library built with -fvisibility=hidden (tests/strict_warnings/check.sh): a
// failed precondition inside it must reach the handler its executable installed
// (handler_app.cpp), as set_precondition_handler promises (one handler for the process).
// SPDX-License-Identifier: MIT
#include <phong/phong.hpp>

#include <vector>

__attribute__((visibility("default"))) float library_shade()
{
    // shininess -1: validate() rejects it, in debug builds, through the precondition handler
    const phong::material<float> bad{.ka = glm::vec3(0.1f), .kd = glm::vec3(0.5f), .ks = glm::vec3(0.5f), .shininess = -1};
    const std::vector<phong::light<float>> lights = {phong::light<float>::with_strength(glm::vec4(0, 0, 1, 0), glm::vec3(1))};
    return phong::shade<phong::presets::glsl_ads>(glm::vec3(0, 0, -1), glm::vec3(0, 0, 1), bad, lights).r;
}
