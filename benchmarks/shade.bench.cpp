// shade<F> over an array of points against the naive GLM baseline: time per (point, light) and
// error against the __float128 reference, for every variant (exact / stable mode, float / double,
// Phong / Blinn-Phong), K = 1, 4, 16, 64 lights, a cache-sized and a DRAM-sized N, and two stiff
// input classes (m = 1e4 near the highlight, grazing n.l ~ 1e-6).
//
// Row names: <path>.<mode>.<specular>.<type>/<input set>/K:<K>/N:<N>, path = naive_glm | scalar |
// batch; mode = exact | stable (float: evaluated in double) | stable_twofold (float arithmetic with
// twofold vectors, features::precision = twofold: the GPU route, and what batches and double run) |
// stable_m256 (batch, double: twofold only above m = 256) | fast (phong/core/fast_math.hpp's approximations).
// g++ 12 flags the _mm512_undefined_* placeholders inside its own AVX-512 intrinsics as
// uninitialized once xsimd's kernels are inlined (batch.hpp). The diagnostic state that counts is
// the one at the intrinsics header's lines, which may be included before batch.hpp's own pragma:
// silence it for the whole file, before any include.
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "support/baseline.hpp"
#include "support/bounds.hpp"
#include "support/harness.hpp"

#include <phong/phong.hpp>
#if __has_include(<phong/batch.hpp>)
#  include <phong/batch.hpp>
#  define PHONG_BENCH_BATCH 1
#endif

#include <benchmark/benchmark.h>

#include <map>
#include <span>
#include <tuple>
#include <string>
#include <vector>

namespace phong_bench {
namespace {

/// The model every row of this file computes: seed 003's phong.vert summed over positional lights
/// (per-light ambient, diffuse, specular gated on n.l > 0, eye at the origin).
constexpr phong::features model(phong::specular_model spec, phong::evaluation mode,
                                phong::stable_precision precision = phong::stable_precision::wider, unsigned twofold_above = 0)
{
    phong::features f = phong::presets::glsl_ads;
    f.specular = spec;
    f.mode = mode;
    f.precision = precision;                // stable_twofold rows: float arithmetic with twofold vectors
    f.stable_twofold_above = twofold_above; // stable_m256 rows: once-rounded components up to m = 256
    return f;
}

template <class T>
std::vector<naive::LightInfo<T>> naive_lights(const scene& sc)
{
    std::vector<naive::LightInfo<T>> out;
    for (std::size_t i = 0; i < sc.light_position.size(); ++i)
        out.push_back({glm::vec<4, T>(sc.light_position[i]), glm::vec<3, T>(sc.light_ambient[i]),
                       glm::vec<3, T>(sc.light_diffuse[i]), glm::vec<3, T>(sc.light_specular[i])});
    return out;
}

/// The baseline: naive::ads (or ads_blinn) on every point.
template <class T, bool Blinn>
void naive_row(benchmark::State& state, input_set set, std::size_t N, std::size_t K)
{
    const scene sc = make_scene(set, K);
    const points<T>& pts = cached_points<T>(set, N, K);
    const std::vector<naive::LightInfo<T>> lights = naive_lights<T>(sc);
    const phong::material<T> m = material_of<T>(sc); // the same numbers as every other row
    const naive::MaterialInfo<T> mat{m.ka, m.kd, m.ks, m.shininess};
    std::vector<glm::vec<3, T>> out(N);
    for (auto _ : state) {
        for (std::size_t i = 0; i < N; ++i)
            out[i] = Blinn ? naive::ads_blinn(pts.position[i], pts.normal[i], lights, mat)
                           : naive::ads(pts.position[i], pts.normal[i], lights, mat);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    constexpr phong::features F = model(Blinn ? phong::specular_model::blinn : phong::specular_model::phong, phong::evaluation::exact);
    report(state, N, K, out, cached_reference(F, set, N, K), -1);
}

/// phong::shade<F> on every point, lights as a run-time span.
template <class T, phong::features F>
void scalar_row(benchmark::State& state, input_set set, std::size_t N, std::size_t K)
{
    const scene sc = make_scene(set, K);
    const points<T>& pts = cached_points<T>(set, N, K);
    const std::vector<phong::light<T>> lights = lights_of<T>(sc);
    const std::span<const phong::light<T>> L(lights);
    const phong::material<T> mat = material_of<T>(sc);
    const phong::environment<T> env = environment_of<T>(sc);
    std::vector<glm::vec<3, T>> out(N);
    for (auto _ : state) {
        for (std::size_t i = 0; i < N; ++i) out[i] = phong::shade<F>(pts.position[i], pts.normal[i], mat, L, env);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    report(state, N, K, out, cached_reference(F, set, N, K), published_bound<T>(F, set));
}

#if defined(PHONG_BENCH_BATCH)
/// The same points as structure of arrays (built once per input set).
template <class T>
struct soa_points {
    std::vector<T> px, py, pz, nx, ny, nz;
};

template <class T>
const soa_points<T>& cached_soa(input_set set, std::size_t N, std::size_t K)
{
    static std::map<std::tuple<int, std::size_t, std::size_t>, soa_points<T>> cache;
    auto [it, fresh] = cache.try_emplace({static_cast<int>(set), N, set == input_set::highlight ? K : 0});
    if (fresh) {
        const points<T>& p = cached_points<T>(set, N, K);
        soa_points<T>& s = it->second;
        for (std::size_t i = 0; i < N; ++i) {
            s.px.push_back(p.position[i].x), s.py.push_back(p.position[i].y), s.pz.push_back(p.position[i].z);
            s.nx.push_back(p.normal[i].x), s.ny.push_back(p.normal[i].y), s.nz.push_back(p.normal[i].z);
        }
    }
    return it->second;
}

/// phong::shade_batch<F> over SoA spans (SIMD lanes through xsimd).
template <class T, phong::features F>
void batch_row(benchmark::State& state, input_set set, std::size_t N, std::size_t K)
{
    const scene sc = make_scene(set, K);
    const soa_points<T>& p = cached_soa<T>(set, N, K);
    const std::vector<phong::light<T>> lights = lights_of<T>(sc);
    const phong::material<T> mat = material_of<T>(sc);
    const phong::environment<T> env = environment_of<T>(sc);
    std::vector<T> r(N), g(N), b(N);
    const phong::soa3<T> pos{p.px, p.py, p.pz}, nrm{p.nx, p.ny, p.nz};
    const phong::soa_rgba<T> out{r, g, b, {}};
    for (auto _ : state) {
        phong::shade_batch<F>(pos, nrm, mat, std::span<const phong::light<T>>(lights), out, env);
        benchmark::DoNotOptimize(r.data());
        benchmark::ClobberMemory();
    }
    std::vector<glm::vec<3, T>> rgb(N);
    for (std::size_t i = 0; i < N; ++i) rgb[i] = {r[i], g[i], b[i]};
    report(state, N, K, rgb, cached_reference(F, set, N, K), published_bound<T>(F, set, true));
}
#endif

using row_fn = void (*)(benchmark::State&, input_set, std::size_t, std::size_t);

struct variant {
    std::string name;
    row_fn fn;
};

template <class T>
const char* type_name() { return sizeof(T) == 4 ? "float" : "double"; }

template <class T>
std::vector<variant> variants_of()
{
    using phong::evaluation;
    using phong::specular_model;
    constexpr phong::stable_precision twofold = phong::stable_precision::twofold;
    const std::string t = type_name<T>();
    std::vector<variant> rows{
        {"naive_glm.exact.phong." + t, &naive_row<T, false>},
        {"naive_glm.exact.blinn." + t, &naive_row<T, true>},
        {"scalar.exact.phong." + t, &scalar_row<T, model(specular_model::phong, evaluation::exact)>},
        {"scalar.exact.blinn." + t, &scalar_row<T, model(specular_model::blinn, evaluation::exact)>},
        {"scalar.stable.phong." + t, &scalar_row<T, model(specular_model::phong, evaluation::stable)>},
        {"scalar.stable.blinn." + t, &scalar_row<T, model(specular_model::blinn, evaluation::stable)>},
        {"scalar.stable_twofold.phong." + t, &scalar_row<T, model(specular_model::phong, evaluation::stable, twofold)>},
        {"scalar.stable_twofold.blinn." + t, &scalar_row<T, model(specular_model::blinn, evaluation::stable, twofold)>},
        {"scalar.fast.phong." + t, &scalar_row<T, model(specular_model::phong, evaluation::fast)>},
        {"scalar.fast.blinn." + t, &scalar_row<T, model(specular_model::blinn, evaluation::fast)>},
#if defined(PHONG_BENCH_BATCH)
        {"batch.exact.phong." + t, &batch_row<T, model(specular_model::phong, evaluation::exact)>},
        {"batch.exact.blinn." + t, &batch_row<T, model(specular_model::blinn, evaluation::exact)>},
        {"batch.stable.phong." + t, &batch_row<T, model(specular_model::phong, evaluation::stable)>},
        {"batch.stable.blinn." + t, &batch_row<T, model(specular_model::blinn, evaluation::stable)>},
        {"batch.fast.phong." + t, &batch_row<T, model(specular_model::phong, evaluation::fast)>},
        {"batch.fast.blinn." + t, &batch_row<T, model(specular_model::blinn, evaluation::fast)>},
#endif
    };
#if defined(PHONG_BENCH_BATCH)
    // Double lanes only: float lanes take double lanes up to m = 2^20 and never read
    // stable_twofold_above (docs/batch.md), so float rows would time batch.stable again.
    if constexpr (std::is_same_v<T, double>) {
        rows.push_back({"batch.stable_m256.phong." + t, &batch_row<T, model(specular_model::phong, evaluation::stable, twofold, 256)>});
        rows.push_back({"batch.stable_m256.blinn." + t, &batch_row<T, model(specular_model::blinn, evaluation::stable, twofold, 256)>});
    }
#endif
    return rows;
}

void add(const variant& v, input_set set, std::size_t K, std::size_t N)
{
    const std::string name = v.name + "/" + phong_bench::name(set) + "/K:" + std::to_string(K) + "/N:" + std::to_string(N);
    benchmark::RegisterBenchmark(name.c_str(), [fn = v.fn, set, K, N](benchmark::State& st) { fn(st, set, N, K); })
        ->Unit(benchmark::kMillisecond);
}

constexpr std::size_t n_cache = 65536;      // points + normals + colours: 2.3 MB in float (L2/L3)
constexpr std::size_t n_dram = 4u << 20;    // 4M points: 150 MB in float, far beyond the 32 MB L3

const bool registered = [] {
    std::vector<variant> all = variants_of<float>();
    for (const variant& v : variants_of<double>()) all.push_back(v);
    // The main grid: every variant, K = 1, 4, 16, 64, cache-sized N.
    for (const variant& v : all)
        for (std::size_t K : {1u, 4u, 16u, 64u}) add(v, input_set::typical, K, n_cache);
    // DRAM-sized N at K = 1, where memory traffic per pair is largest.
    for (const variant& v : all) add(v, input_set::typical, 1, n_dram);
    // Scaling with N (K = 1) for the float Phong rows.
    for (const variant& v : all)
        if (v.name.ends_with(".phong.float"))
            for (std::size_t N : {std::size_t(1024), std::size_t(16384), std::size_t(262144), std::size_t(1u << 20)})
                add(v, input_set::typical, 1, N);
    // Stiff classes: what each variant's speed costs on hard inputs.
    for (const variant& v : all)
        for (input_set s : {input_set::highlight, input_set::grazing}) add(v, s, 4, n_cache);
    return true;
}();

} // namespace
} // namespace phong_bench
