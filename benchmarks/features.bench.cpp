// The cost of each feature: scene presets, each timed per (point, light) with its error against
// the __float128 reference. Float, exact mode, K = 4, N = 65536, the typical input set, lights with
// OpenGL attenuation and a spot cone (both read only when the preset turns them on).
// Row names: feature.<preset>.float/typical/K:4/N:65536. The instruction-count check that a
// removed feature costs nothing is benchmarks/feature_cost.sh.
#include "support/bounds.hpp"
#include "support/harness.hpp"

#include <phong/phong.hpp>

#include <benchmark/benchmark.h>

#include <span>
#include <string>
#include <vector>

namespace phong_bench {
namespace {

using phong::features;

/// Everything on: scene and per-light ambient, diffuse, Phong specular, lights of any kind (w read
/// at run time), polynomial attenuation, OpenGL spot, two-sided by the view.
constexpr features full{.scene_ambient = true, .light_ambient = true, .diffuse = true,
                        .specular = phong::specular_model::phong, .specular_gate = true,
                        .lights = phong::light_kind::any, .attenuation = phong::attenuation_model::polynomial,
                        .spot = phong::spot_model::opengl, .two_sided = phong::facing::view};

constexpr features change(features f, auto edit)
{
    edit(f);
    return f;
}

constexpr features no_spot = change(full, [](features& f) { f.spot = phong::spot_model::none; });
constexpr features no_attenuation = change(full, [](features& f) { f.attenuation = phong::attenuation_model::none; });
constexpr features one_sided = change(full, [](features& f) { f.two_sided = phong::facing::none; });
constexpr features blinn = change(full, [](features& f) { f.specular = phong::specular_model::blinn; });
constexpr features positional_only = change(full, [](features& f) { f.lights = phong::light_kind::positional; });
constexpr features directional_only = change(full, [](features& f) {
    f.lights = phong::light_kind::directional;
    f.attenuation = phong::attenuation_model::none;
});
constexpr features ambient_diffuse = change(full, [](features& f) { f.specular = phong::specular_model::none; });
constexpr features minimal = {.scene_ambient = false, .light_ambient = false, .diffuse = true,
                              .specular = phong::specular_model::none, .lights = phong::light_kind::directional};
constexpr features stable_full = change(full, [](features& f) { f.mode = phong::evaluation::stable; });

template <features F>
void preset_row(benchmark::State& state, light_style style)
{
    constexpr std::size_t N = 65536, K = 4;
    using T = float;
    const scene sc = make_scene(input_set::typical, K);
    const points<T>& pts = cached_points<T>(input_set::typical, N, K);
    const std::vector<phong::light<T>> lights = lights_of<T>(sc, style);
    const std::span<const phong::light<T>> L(lights);
    const phong::material<T> mat = material_of<T>(sc);
    const phong::environment<T> env = environment_of<T>(sc);
    std::vector<glm::vec<3, T>> out(N);
    for (auto _ : state) {
        for (std::size_t i = 0; i < N; ++i) out[i] = phong::shade<F>(pts.position[i], pts.normal[i], mat, L, env);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    report(state, N, K, out, cached_reference(F, input_set::typical, N, K, style), published_bound<T>(F, input_set::typical));
}

void add(const char* preset, void (*fn)(benchmark::State&, light_style), light_style style)
{
    const std::string name = std::string("feature.") + preset + ".float/typical/K:4/N:65536";
    benchmark::RegisterBenchmark(name.c_str(), [fn, style](benchmark::State& st) { fn(st, style); })->Unit(benchmark::kMillisecond);
}

const bool registered = [] {
    const light_style spot = light_style::attenuated_spot;
    add("full", &preset_row<full>, spot);
    add("no_spot", &preset_row<no_spot>, spot);
    add("spot_on_lights_without_cone", &preset_row<full>, light_style::plain); // compiled in, cone of 180 degrees
    add("no_attenuation", &preset_row<no_attenuation>, spot);
    add("one_sided", &preset_row<one_sided>, spot);
    add("blinn", &preset_row<blinn>, spot);
    add("positional_only", &preset_row<positional_only>, spot);
    add("directional_only", &preset_row<directional_only>, light_style::directional);
    add("ambient_diffuse_only", &preset_row<ambient_diffuse>, spot);
    add("diffuse_only_directional", &preset_row<minimal>, light_style::directional);
    add("full_stable", &preset_row<stable_full>, spot);
    return true;
}();

} // namespace
} // namespace phong_bench
