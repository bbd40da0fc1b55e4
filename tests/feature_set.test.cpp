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

namespace {
/// Two feature sets equal field by field: the same template argument (features has no operator==).
template <phong::features A, phong::features B>
constexpr bool same = std::is_same_v<phong::feature_set<A>, phong::feature_set<B>>;
} // namespace

TEST_CASE("features' setters: each changes its own field only, in any order, and match designated initializers")
{
    using namespace phong;
    constexpr features a = features{}.with_lights(light_kind::directional).with_view(view_model::fixed_direction).with_unit_inputs(true).with_specular_gate(false);
    constexpr features b = features{}.with_specular_gate(false).with_unit_inputs(true).with_view(view_model::fixed_direction).with_lights(light_kind::directional);
    constexpr features c{.specular_gate = false, .lights = light_kind::directional, .view = view_model::fixed_direction, .unit_inputs = true};
    static_assert(same<a, b> && same<a, c>);
    // every setter, from the default, against the field written directly
    constexpr features d = features{}
                               .with_scene_ambient(false)
                               .with_light_ambient(true)
                               .with_diffuse(false)
                               .with_specular(specular_model::blinn)
                               .with_attenuation(attenuation_model::windowed)
                               .with_spot(spot_model::smooth)
                               .with_attenuate_ambient(false)
                               .with_two_sided(facing::flag)
                               .with_emission(true)
                               .with_alpha(true)
                               .with_mode(evaluation::stable)
                               .with_precision(stable_precision::twofold)
                               .with_stable_twofold_above(64);
    constexpr features e{.scene_ambient = false, .light_ambient = true, .diffuse = false, .specular = specular_model::blinn,
                         .attenuation = attenuation_model::windowed, .spot = spot_model::smooth, .attenuate_ambient = false,
                         .two_sided = facing::flag, .emission = true, .alpha = true, .mode = evaluation::stable,
                         .precision = stable_precision::twofold, .stable_twofold_above = 64};
    static_assert(same<d, e>);
    // the value a setter is called on is unchanged; presets::with_mode is with_mode
    constexpr features p = presets::classic_phong;
    static_assert(p.with_mode(evaluation::fast).mode == evaluation::fast && p.mode == evaluation::exact);
    static_assert(same<presets::with_mode(p, evaluation::stable), p.with_mode(evaluation::stable)>);
    CHECK(a.lights == light_kind::directional); // a run-time line for doctest's count
}
