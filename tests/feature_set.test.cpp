// phong::feature_set<F> (features.hpp): a feature set as a type, for CUDA kernels templated on it
// (docs/cuda.md; tests/cuda/recipe.cu compiles it in device code).
#include <doctest/doctest.h>

#include <phong/phong.hpp>

#include <array>
#include <type_traits>

namespace {

constexpr phong::features ads_fast = phong::presets::with_mode(phong::presets::glsl_ads, phong::evaluation::fast);

/// A function templated as a CUDA kernel would be: on a type, reading the features from it.
template <class Set>
glm::vec3 shade_with(const glm::vec3& p, const glm::vec3& n, const phong::material<float>& m, const std::array<phong::light<float>, 2>& lights)
{
    return phong::shade<Set::value>(p, n, m, lights);
}

} // namespace

TEST_CASE("feature_set<F>: one type per feature set, value is F, and shade<Set::value> is shade<F>")
{
    using fast_set = phong::feature_set<ads_fast>;
    static_assert(fast_set::value.mode == phong::evaluation::fast);
    static_assert(fast_set::value.specular == phong::specular_model::phong && fast_set::value.light_ambient && !fast_set::value.scene_ambient);
    static_assert(!std::is_same_v<fast_set, phong::feature_set<phong::presets::glsl_ads>>);
    static_assert(std::is_same_v<fast_set, phong::feature_set<phong::presets::with_mode(phong::presets::glsl_ads, phong::evaluation::fast)>>);

    std::array<phong::light<float>, 2> lights{phong::light<float>::with_strength({2, 2, 0, 1}, {1, 0.9f, 0.8f}),
                                              phong::light<float>::with_strength({-1, 3, 1, 1}, {0.5f, 0.5f, 0.7f})};
    lights[0].ambient = glm::vec3(0.1f);
    const phong::material<float> mat{.ka = glm::vec3(0.2f), .kd = glm::vec3(0.7f), .ks = glm::vec3(0.5f), .shininess = 32};
    for (const glm::vec3 p : {glm::vec3(0, 0, -4), glm::vec3(0.3f, -0.2f, -3), glm::vec3(-1, 1, -5)}) {
        const glm::vec3 n = glm::vec3(0.1f, 0.2f, 1.5f) - 0.1f * p;
        const glm::vec3 a = shade_with<fast_set>(p, n, mat, lights);
        const glm::vec3 b = phong::shade<ads_fast>(p, n, mat, lights);
        CHECK(a.x == b.x);
        CHECK(a.y == b.y);
        CHECK(a.z == b.z);
        const glm::vec3 e = shade_with<phong::feature_set<phong::presets::glsl_ads>>(p, n, mat, lights);
        CHECK(e.x > 0.0f); // a lit point, ambient at least
    }
}
