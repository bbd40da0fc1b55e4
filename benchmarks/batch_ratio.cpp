// Batch / hand-written kernel time ratios in one process, interleaved: the quick, quieter check of
// issue 14's targets (the report's rows run each kernel in its own repetitions, minutes apart).
// For K = 1, 4, 16 and Phong / Blinn: 60 repetitions, each times the hand-written AVX-512 (or AVX2)
// kernel (support/hand_simd.hpp) and then shade_batch<F> (F = hand_simd::model, the mode given) on
// the same typical points (float, N = 65536, SoA), thread CPU time; prints the best time per pair
// of each and the median over repetitions of the per-repetition ratio batch / hand.
//
// Usage: build/bench/benchmarks/phong_batch_ratio [exact|fast|stable] [N]
#if defined(__GNUC__) && !defined(__clang__) // g++ 12's own AVX-512 intrinsics, see shade.bench.cpp
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <phong/batch.hpp>

#include "support/hand_simd.hpp"
#include "support/inputs.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <vector>

#if PHONG_HAND_SIMD
namespace {

using namespace phong_bench;

double thread_seconds()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

template <bool Blinn, phong::evaluation Mode> void compare(std::size_t N, std::size_t K)
{
    const scene sc = make_scene(input_set::typical, K);
    const points<float> pts = make_points<float>(input_set::typical, N, K);
    soa_float_points s(pts);
    const std::vector<phong::light<float>> lights = lights_of<float>(sc);
    const phong::material<float> mat = material_of<float>(sc);
    constexpr phong::features F = [] {
        phong::features f = hand_simd::model(Blinn);
        f.mode = Mode;
        return f;
    }();
    using S = std::span<const float>;
    double best_hand = 1e30, best_batch = 1e30;
    std::vector<double> ratios;
    for (int rep = 0; rep < 60; ++rep) {
        const double t0 = thread_seconds();
        const hand_simd::constants c = hand_simd::make_constants(lights, mat); // per call, as shade_batch
        hand_simd::shade<Blinn>(s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data(), N, c, s.r.data(), s.g.data(), s.b.data());
        const double t1 = thread_seconds();
        phong::shade_batch<F>(phong::soa3<float>{S(s.px), S(s.py), S(s.pz)}, phong::soa3<float>{S(s.nx), S(s.ny), S(s.nz)}, mat,
                              std::span<const phong::light<float>>(lights), phong::soa_rgba<float>{s.r, s.g, s.b, {}});
        const double t2 = thread_seconds();
        best_hand = std::min(best_hand, t1 - t0);
        best_batch = std::min(best_batch, t2 - t1);
        ratios.push_back((t2 - t1) / (t1 - t0));
    }
    std::sort(ratios.begin(), ratios.end());
    const double pairs = double(N * K);
    std::printf("%-5s K=%-2zu  hand %.3f ns/pair  batch %s %.3f ns/pair  ratio of best %.3f  median ratio %.3f\n",
                Blinn ? "blinn" : "phong", K, best_hand * 1e9 / pairs, Mode == phong::evaluation::fast ? "fast" : Mode == phong::evaluation::stable ? "stable" : "exact",
                best_batch * 1e9 / pairs, best_batch / best_hand, ratios[ratios.size() / 2]);
}

template <phong::evaluation Mode> void compare_all(std::size_t N)
{
    for (std::size_t K : {1, 4, 16}) {
        compare<false, Mode>(N, K);
        compare<true, Mode>(N, K);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const bool fast = argc > 1 && std::strcmp(argv[1], "fast") == 0;
    const std::size_t N = argc > 2 ? std::size_t(std::strtoul(argv[2], nullptr, 10)) : 65536;
    std::printf("hand-written kernel: %s, float, typical points, N = %zu, 60 interleaved repetitions\n", hand_simd::isa_name, N);
    const bool stable = argc > 1 && std::strcmp(argv[1], "stable") == 0;
    if (fast) compare_all<phong::evaluation::fast>(N);
    else if (stable) compare_all<phong::evaluation::stable>(N);
    else compare_all<phong::evaluation::exact>(N);
}
#else
int main()
{
    std::printf("phong_batch_ratio: the hand-written kernel needs AVX-512F or AVX2 + FMA\n");
}
#endif
