// Batch / hand-written kernel time ratios in one process, interleaved: the quick, quieter check of
// issue 14's targets (the report's rows run each kernel in its own repetitions, minutes apart).
// For K = 1, 4, 16 and Phong / Blinn: 60 repetitions, each times the hand-written AVX-512 (or AVX2)
// kernel (support/hand_simd.hpp) and then shade_batch<F> (F = hand_simd::model, the mode given) on
// the same typical points (float, N = 65536, SoA), thread CPU time; prints the best time per pair
// of each and the median over repetitions of the per-repetition ratio batch / hand.
// Each repetition runs both kernels twice: in the default floating-point environment and with
// flush-to-zero and denormals-are-zero set in MXCSR (what -ffast-math's start-up code does), in
// alternating order; a second line per case gives the FTZ/DAZ ratio and each kernel's time in the
// default environment over its time under FTZ/DAZ (1.00: no subnormal costs anything; on Intel
// cores each subnormal operand or result costs a microcode assist). The first line is the CPU.
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
#include <fstream>
#include <string>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <vector>

#if PHONG_HAND_SIMD
#  include <xmmintrin.h>
namespace {

using namespace phong_bench;

double thread_seconds()
{
    timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

/// The CPU's model name with its family and model numbers (/proc/cpuinfo: a virtual machine may name
/// only the vendor's line, e.g. "AMD EPYC"; family 25 model 17 is Zen 4), or "unknown CPU".
std::string cpu_model()
{
    std::ifstream in("/proc/cpuinfo");
    std::string name, family, model;
    const auto value = [](const std::string& line) { return line.substr(line.find(':') + 2); };
    for (std::string line; std::getline(in, line) && (name.empty() || family.empty() || model.empty());) {
        if (line.find(':') == std::string::npos || line.find(':') + 2 > line.size()) continue;
        if (line.rfind("model name", 0) == 0) name = value(line);
        else if (line.rfind("cpu family", 0) == 0) family = value(line);
        else if (line.rfind("model\t", 0) == 0) model = value(line);
    }
    if (name.empty()) return "unknown CPU";
    return family.empty() ? name : name + " (family " + family + ", model " + model + ")";
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
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
    // MXCSR: the default environment (FTZ, bit 15, and DAZ, bit 6, clear) and FTZ/DAZ set.
    const unsigned saved = _mm_getcsr();
    const unsigned environments[2] = {saved & ~0x8040u, saved | 0x8040u};
    double best_hand[2] = {1e30, 1e30}, best_batch[2] = {1e30, 1e30};
    std::vector<double> ratios[2], hand_slowdown, batch_slowdown;
    for (int rep = 0; rep < 60; ++rep) {
        double hand[2], batch[2];
        for (int j = 0; j < 2; ++j) {
            const int e = (rep + j) % 2; // alternate which environment runs first
            _mm_setcsr(environments[e]);
            const double t0 = thread_seconds();
            const hand_simd::constants c = hand_simd::make_constants(lights, mat); // per call, as shade_batch
            hand_simd::shade<Blinn>(s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data(), N, c, s.r.data(), s.g.data(), s.b.data());
            const double t1 = thread_seconds();
            phong::shade_batch<F>(phong::soa3<float>{S(s.px), S(s.py), S(s.pz)}, phong::soa3<float>{S(s.nx), S(s.ny), S(s.nz)}, mat,
                                  std::span<const phong::light<float>>(lights), phong::soa_rgba<float>{s.r, s.g, s.b, {}});
            const double t2 = thread_seconds();
            hand[e] = t1 - t0, batch[e] = t2 - t1;
        }
        _mm_setcsr(saved);
        for (int e = 0; e < 2; ++e) {
            best_hand[e] = std::min(best_hand[e], hand[e]);
            best_batch[e] = std::min(best_batch[e], batch[e]);
            ratios[e].push_back(batch[e] / hand[e]);
        }
        hand_slowdown.push_back(hand[0] / hand[1]);
        batch_slowdown.push_back(batch[0] / batch[1]);
    }
    const double pairs = double(N * K);
    const char* mode = Mode == phong::evaluation::fast ? "fast" : Mode == phong::evaluation::stable ? "stable" : "exact";
    const char* spec = Blinn ? "blinn" : "phong";
    std::printf("%-5s K=%-2zu  hand %.3f ns/pair  batch %s %.3f ns/pair  ratio of best %.3f  median ratio %.3f\n", spec, K,
                best_hand[0] * 1e9 / pairs, mode, best_batch[0] * 1e9 / pairs, best_batch[0] / best_hand[0], median(ratios[0]));
    std::printf("%-5s K=%-2zu  ftz/daz  hand %.3f ns/pair  batch %s %.3f ns/pair  median ratio %.3f  "
                "default/ftz: batch %.3f  hand %.3f\n",
                spec, K, best_hand[1] * 1e9 / pairs, mode, best_batch[1] * 1e9 / pairs, median(ratios[1]), median(batch_slowdown),
                median(hand_slowdown));
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
    std::printf("CPU: %s\n", cpu_model().c_str());
    std::printf("hand-written kernel: %s, float, typical points, N = %zu, 60 interleaved repetitions, default environment and FTZ/DAZ\n",
                hand_simd::isa_name, N);
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
