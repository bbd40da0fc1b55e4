// One lighting call, hand-written on GLM (benchmarks/compile_time.sh).
// SPDX-License-Identifier: MIT
#include "hand.hpp"

glm::vec4 lit(glm::vec3 Q, glm::vec3 N, const hand::material& m, std::span<const hand::light> lights)
{
    return hand::shade(Q, N, m, lights, glm::vec3(0.2f));
}
