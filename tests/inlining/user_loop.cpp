// A renderer's shading loops as a user writes them (scalar shade<F> per point, several presets,
// modes and light lists), compiled by tests/inlining/check.sh: every phong function must be
// inlined into these extern "C" loops, so that the object file defines no phong symbol.
// SPDX-License-Identifier: MIT
#include <phong/inputs/adapt.hpp>
#include <phong/phong.hpp>

#include <array>
#include <cstddef>
#include <span>

namespace {
using vec3 = glm::vec3;

/// A renderer's own light, read through light_traits (PHONG_INLINE, as light.hpp suggests).
struct user_light {
    vec3 position, colour;
};
} // namespace

template <> struct phong::light_traits<user_light> {
    PHONG_INLINE static glm::vec4 position(const user_light& L) { return glm::vec4(L.position, 1.0f); }
    PHONG_INLINE static const vec3& diffuse(const user_light& L) { return L.colour; }
    PHONG_INLINE static const vec3& specular(const user_light& L) { return L.colour; }
};

namespace {
template <phong::features F, class Lights>
void loop(const vec3* P, const vec3* n, const phong::material<float>& m, const Lights& lights, vec3* out, std::size_t N)
{
    const phong::environment<float> env{.ambient = vec3(0.1f), .eye = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
    for (std::size_t i = 0; i < N; ++i) out[i] = vec3(phong::shade<F>(P[i], n[i], m, lights, env));
}
template <phong::features F, class Lights>
void loop_given(const vec3* P, const vec3* n, const vec3* v, const unsigned* visible, const phong::material<float>& m,
                const Lights& lights, vec3* out, std::size_t N)
{
    const phong::environment<float> env{.ambient = vec3(0.1f)};
    for (std::size_t i = 0; i < N; ++i) out[i] = vec3(phong::shade<F>(P[i], n[i], v[i], m, phong::masked(lights, visible[i]), env));
}
constexpr phong::features with(phong::features f, phong::evaluation mode, bool unit = false)
{
    f.mode = mode;
    f.unit_inputs = unit;
    return f;
}
constexpr phong::features everything = [] {
    phong::features f = phong::presets::classic_phong;
    f.light_ambient = true;
    f.attenuation = phong::attenuation_model::polynomial;
    f.spot = phong::spot_model::smooth;
    f.two_sided = phong::facing::view;
    f.emission = true;
    f.alpha = true;
    return f;
}();
constexpr phong::features blinn_fixed = [] {
    phong::features f = phong::presets::classic_phong;
    f.specular = phong::specular_model::blinn;
    f.lights = phong::light_kind::directional;
    f.view = phong::view_model::fixed_direction;
    return f;
}();
constexpr phong::features twofold = [] {
    phong::features f = phong::presets::with_mode(phong::presets::glsl_ads, phong::evaluation::stable);
    f.precision = phong::stable_precision::twofold;
    return f;
}();
} // namespace

using span_lights = std::span<const phong::light<float>>;
using array_lights = std::array<phong::light<float>, 2>;
using user_lights = std::span<const user_light>;

extern "C" {
void user_classic(const vec3* P, const vec3* n, const phong::material<float>* m, const phong::light<float>* L, std::size_t K, vec3* out, std::size_t N)
{
    loop<phong::presets::classic_phong>(P, n, *m, span_lights(L, K), out, N);
    loop<with(phong::presets::classic_phong, phong::evaluation::stable)>(P, n, *m, span_lights(L, K), out, N);
    loop<with(phong::presets::classic_phong, phong::evaluation::fast)>(P, n, *m, span_lights(L, K), out, N);
}
void user_ads(const vec3* P, const vec3* n, const phong::material<float>* m, const array_lights* L, vec3* out, std::size_t N)
{
    loop<phong::presets::glsl_ads>(P, n, *m, *L, out, N);
    loop<twofold>(P, n, *m, *L, out, N);
    loop<phong::presets::diffuse_only>(P, n, *m, *L, out, N);
}
void user_everything(const vec3* P, const vec3* n, const phong::material<float>* m, const phong::light<float>* L, std::size_t K, vec3* out, std::size_t N)
{
    loop<everything>(P, n, *m, span_lights(L, K), out, N);
    loop<with(everything, phong::evaluation::stable)>(P, n, *m, span_lights(L, K), out, N);
    loop<with(everything, phong::evaluation::fast)>(P, n, *m, span_lights(L, K), out, N);
    loop<blinn_fixed>(P, n, *m, span_lights(L, K), out, N);
    loop<phong::presets::blinn_phong_per_light_ambient>(P, n, *m, span_lights(L, K), out, N);
}
void user_tracer(const vec3* P, const vec3* n, const vec3* v, const unsigned* visible, const phong::material<float>* m, const user_light* L,
                 std::size_t K, vec3* out, std::size_t N)
{
    loop_given<phong::presets::raytracer_phong>(P, n, v, visible, *m, user_lights(L, K), out, N);
    loop_given<with(phong::presets::raytracer_phong, phong::evaluation::exact, true)>(P, n, v, visible, *m, user_lights(L, K), out, N);
    loop_given<with(phong::presets::raytracer_phong, phong::evaluation::stable, true)>(P, n, v, visible, *m, user_lights(L, K), out, N);
    loop_given<with(phong::presets::raytracer_phong, phong::evaluation::fast, true)>(P, n, v, visible, *m, user_lights(L, K), out, N);
}
/// shade_incident: the shadow rays' directions and distances given (phong/sum/incident.hpp)
void user_incident(const vec3* n, const vec3* v, const unsigned* visible, const phong::incident<float>* shadows, const vec3* kd,
                   const float* exponent, const phong::material<float>* m, const user_light* L, std::size_t K, vec3* out, std::size_t N)
{
    constexpr phong::features tracer = with(phong::presets::raytracer_phong, phong::evaluation::exact, true);
    constexpr phong::features screen = [] {
        phong::features f = with(phong::presets::glsl_ads, phong::evaluation::exact, true);
        f.lights = phong::light_kind::directional;
        f.view = phong::view_model::fixed_direction;
        return f;
    }();
    const phong::environment<float> env{.ambient = vec3(0.1f), .eye = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
    for (std::size_t i = 0; i < N; ++i) {
        const std::span<const phong::incident<float>> in(shadows + i * K, K);
        out[i] = phong::shade_incident<tracer>(n[i], v[i], *m, phong::masked(user_lights(L, K), visible[i]), in, env);
        out[i] += phong::shade_incident<with(tracer, phong::evaluation::stable, true)>(n[i], v[i], *m, user_lights(L, K), in, env);
        const phong::surface<float> surf{.ka = kd[i], .kd = kd[i], .ks = vec3(0.5f), .shininess = exponent[i]};
        out[i] += phong::shade_incident<screen>(n[i], surf, user_lights(L, K), in, env);
    }
}

/// One screen-space fragment twice: with glm::vec3, and with a renderer's own vector type read
/// through phong::vec3_of (check.sh: the two functions have the same number of instructions; one
/// fragment and no loop, so that no unrolling or vectorization decision tells them apart).
struct own3 {
    float x, y, z;
};
constexpr phong::features screen_model{.scene_ambient = true, .light_ambient = false, .specular_gate = false,
                                       .lights = phong::light_kind::directional, .view = phong::view_model::fixed_direction,
                                       .unit_inputs = true};
void user_screen_glm(const vec3* n, const vec3* kd, float exponent, const array_lights* L, const std::array<phong::incident<float>, 2>* in,
                     vec3* out)
{
    const phong::environment<float> env{.ambient = vec3(0.1f), .eye = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
    *out = phong::shade_incident<screen_model>(*n, phong::surface<float>{*kd, *kd, vec3(0.5f), exponent}, *L, *in, env);
}
void user_screen_own(const own3* n, const own3* kd, float exponent, const array_lights* L, const std::array<phong::incident<float>, 2>* in,
                     own3* out)
{
    const phong::environment<float> env{.ambient = vec3(0.1f), .eye = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
    const vec3 c = phong::shade_incident<screen_model>(phong::vec3_of(*n), phong::surface<float>{phong::vec3_of(*kd), phong::vec3_of(*kd), vec3(0.5f), exponent},
                                                       *L, *in, env);
    *out = own3{c.x, c.y, c.z};
}
}
