// One shade<presets::classic_phong> call (benchmarks/compile_time.sh); PHONG_HEADER picks the
// header it comes from (<phong/phong.hpp> or <phong/sum/shade.hpp>).
// SPDX-License-Identifier: MIT
#include PHONG_HEADER

#include <span>

glm::vec4 lit(glm::vec3 Q, glm::vec3 N, const phong::material<float>& m, std::span<const phong::light<float>> lights)
{
    const phong::environment<float> env{.ambient = glm::vec3(0.2f)};
    return phong::shade<phong::presets::classic_phong>(Q, N, m, lights, env);
}
