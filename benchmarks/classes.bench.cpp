// The input classes of phong/accuracy.hpp (tests/support/stiff_classes.hpp's seeded generators),
// shaded with the feature set the published bounds are measured with
// (accuracy::measured_features(mode, specular)), so each row's error counters sit beside the bound
// they must respect. One scene per point (its own material and 1-3 lights), 4096 scenes, scalar
// path only (shade_batch shares one light list across points; the naive baseline has no
// attenuation). Row names: class.<mode>.<specular>.<type>/<class>/K:1/N:4096 (K: nominal).
#if __has_include("support/stiff_classes.hpp")
#include "support/harness.hpp"
#include "support/stiff_classes.hpp"

#include <phong/accuracy.hpp>
#include <phong/phong.hpp>

#include <benchmark/benchmark.h>

#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace phong_bench {
namespace {

using phong::accuracy::input_class;
constexpr std::size_t n_scenes = 4096;
constexpr std::uint64_t seed = 20261122;

template <class T>
const std::vector<phong_test::stiff_scene<T>>& cached_scenes(input_class c)
{
    static std::map<input_class, std::vector<phong_test::stiff_scene<T>>> cache;
    auto [it, fresh] = cache.try_emplace(c);
    if (fresh) it->second = phong_test::make_class<T>(c, n_scenes, seed);
    return it->second;
}

template <phong::evaluation M, phong::specular_model S, class T>
void class_row(benchmark::State& state, input_class c)
{
    constexpr phong::features F = phong::accuracy::measured_features(M, S);
    const std::vector<phong_test::stiff_scene<T>>& scenes = cached_scenes<T>(c);
    static std::map<input_class, std::vector<phong_test::wcolor>> refs; // one per (M, S, T, class)
    auto [it, fresh] = refs.try_emplace(c);
    if (fresh) it->second = phong_test::references<T>(F, scenes);
    std::vector<glm::vec<3, T>> out(scenes.size());
    std::size_t pairs = 0;
    for (const auto& s : scenes) pairs += s.lights.size();
    for (auto _ : state) {
        for (std::size_t i = 0; i < scenes.size(); ++i) {
            const phong_test::stiff_scene<T>& s = scenes[i];
            out[i] = phong::shade<F>(s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    // Time per (point, light) over the actual light count; the error counters over every scene.
    report(state, scenes.size(), 1, out, it->second, -1);
    state.counters["ns_per_pair"] = benchmark::Counter(double(state.iterations()) * double(pairs) * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    const phong::accuracy::bound b = phong::accuracy::of<M, T>(c);
    state.counters["bound"] = (b.max_rel == 0 && b.p99_ulp == 0 && b.max_ulp == 0) ? -1.0 : b.max_rel;
}

template <phong::evaluation M, phong::specular_model S, class T>
void add(input_class c)
{
    const std::string name = std::string("class.") + (M == phong::evaluation::exact ? "exact" : "stable") + "." +
                              (S == phong::specular_model::phong ? "phong" : "blinn") + "." +
                              (sizeof(T) == 4 ? "float" : "double") + "/" + phong::accuracy::name(c) + "/K:1/N:" +
                              std::to_string(n_scenes);
    benchmark::RegisterBenchmark(name.c_str(), [c](benchmark::State& st) { class_row<M, S, T>(st, c); })
        ->Unit(benchmark::kMicrosecond);
}

template <class T>
void add_all(input_class c)
{
    using phong::evaluation;
    using phong::specular_model;
    add<evaluation::exact, specular_model::phong, T>(c);
    add<evaluation::exact, specular_model::blinn, T>(c);
    add<evaluation::stable, specular_model::phong, T>(c);
    add<evaluation::stable, specular_model::blinn, T>(c);
}

const bool registered = [] {
    for (input_class c : {input_class::well_conditioned, input_class::shininess_1e4, input_class::grazing,
                          input_class::near_light_1e20, input_class::huge_1e20}) {
        add_all<float>(c);
        add_all<double>(c);
    }
    return true;
}();

} // namespace
} // namespace phong_bench
#endif
