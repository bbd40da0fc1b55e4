// The hand-written intrinsics baseline (support/hand_simd.hpp) beside shade.bench.cpp's rows: the
// same model, points, lights, reference and counters, so report.py can put phong's batch rows
// over it. Registered only when the kernel is compiled (AVX-512F, or AVX2 + FMA).
// Row names: hand_simd.exact.<phong|blinn>.float/typical/K:<K>/N:65536.
// Each row first checks the kernel against phong's scalar shade<F> on all of its points
// (hand_simd::check_tolerance); a row that disagrees reports an error instead of a time.
#if defined(__GNUC__) && !defined(__clang__) // g++ 12's own AVX-512 intrinsics, see shade.bench.cpp
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "support/hand_simd.hpp"
#include "support/harness.hpp"

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#if PHONG_HAND_SIMD
namespace phong_bench {
namespace {

template <bool Blinn>
void hand_row(benchmark::State& state, input_set set, std::size_t N, std::size_t K)
{
    const scene sc = make_scene(set, K);
    const points<float>& pts = cached_points<float>(set, N, K);
    soa_float_points s(pts);
    const std::vector<phong::light<float>> lights = lights_of<float>(sc);
    const phong::material<float> mat = material_of<float>(sc);

    // Same model as phong's rows, or no row.
    const hand_simd::constants c = hand_simd::make_constants(lights, mat);
    hand_simd::shade<Blinn>(s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data(), N, c, s.r.data(), s.g.data(), s.b.data());
    const double diff = hand_simd::max_difference_to_scalar<Blinn>(pts.position, pts.normal, lights, mat, s.r, s.g, s.b);
    if (!(diff <= hand_simd::check_tolerance(mat.shininess))) {
        state.SkipWithError(("hand_simd disagrees with phong::shade<F>: max relative difference " + std::to_string(diff) +
                             " > tolerance " + std::to_string(hand_simd::check_tolerance(mat.shininess)))
                                .c_str());
        return;
    }

    for (auto _ : state) {
        // Constants hoisted per call, as shade_batch broadcasts its lights per call.
        const hand_simd::constants cc = hand_simd::make_constants(lights, mat);
        hand_simd::shade<Blinn>(s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data(), N, cc, s.r.data(), s.g.data(), s.b.data());
        benchmark::DoNotOptimize(s.r.data());
        benchmark::ClobberMemory();
    }
    std::vector<glm::vec3> rgb(N);
    for (std::size_t i = 0; i < N; ++i) rgb[i] = {s.r[i], s.g[i], s.b[i]};
    report(state, N, K, rgb, cached_reference(hand_simd::model(Blinn), set, N, K), -1);
    state.counters["check_max_rel_diff"] = diff; // against phong::shade<F>, float
    state.SetLabel(hand_simd::isa_name);
}

const bool registered = [] {
    for (std::size_t K : {1u, 4u, 16u, 64u})
        for (bool blinn : {false, true}) {
            const std::string name = std::string("hand_simd.exact.") + (blinn ? "blinn" : "phong") + ".float/" +
                                     phong_bench::name(input_set::typical) + "/K:" + std::to_string(K) + "/N:65536";
            benchmark::RegisterBenchmark(name.c_str(), [blinn, K](benchmark::State& st) {
                if (blinn) hand_row<true>(st, input_set::typical, 65536, K);
                else hand_row<false>(st, input_set::typical, 65536, K);
            })->Unit(benchmark::kMillisecond);
        }
    return true;
}();

} // namespace
} // namespace phong_bench
#endif
