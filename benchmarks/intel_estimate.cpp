// The batch path and the hand-written AVX-512 kernel (support/hand_simd.hpp) as two out-of-line
// functions, for benchmarks/intel_estimate.sh: it profiles each kernel on the typical scene (the
// scene of phong_batch_ratio) to find its hot loops, and gives those loops to llvm-mca with an
// Intel CPU model. Build: -O3 -march=x86-64-v4 -DMODE=exact|stable. Run: K hand|batch repetitions.
#if defined(__GNUC__) && !defined(__clang__) // g++ 12's own AVX-512 intrinsics, see shade.bench.cpp
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <phong/batch.hpp>

#include "support/hand_simd.hpp"
#include "support/inputs.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if PHONG_HAND_SIMD
using namespace phong_bench;
using S = std::span<const float>;

#  if !defined(MODE)
#    define MODE exact
#  endif

constexpr phong::features F = [] {
    phong::features f = hand_simd::model(false); // Phong
    f.mode = phong::evaluation::MODE;
    return f;
}();

extern "C" __attribute__((noinline)) void run_hand(const float* const* in, std::size_t N, const hand_simd::constants& c, float* r,
                                                   float* g, float* b)
{
    hand_simd::shade<false>(in[0], in[1], in[2], in[3], in[4], in[5], N, c, r, g, b);
}

extern "C" __attribute__((noinline)) void run_batch(const float* const* in, std::size_t N, const phong::material<float>& mat,
                                                    std::span<const phong::light<float>> lights, float* r, float* g, float* b)
{
    phong::shade_batch<F>(phong::soa3<float>{S(in[0], N), S(in[1], N), S(in[2], N)},
                          phong::soa3<float>{S(in[3], N), S(in[4], N), S(in[5], N)}, mat, lights,
                          phong::soa_rgba<float>{std::span<float>(r, N), std::span<float>(g, N), std::span<float>(b, N), {}});
}

int main(int argc, char** argv)
{
    if (argc != 4) return 2;
    const std::size_t K = std::strtoul(argv[1], nullptr, 10), N = 65536;
    const bool hand = std::strcmp(argv[2], "hand") == 0;
    const int reps = std::atoi(argv[3]);
    const scene sc = make_scene(input_set::typical, K);
    const points<float> pts = make_points<float>(input_set::typical, N, K);
    soa_float_points s(pts);
    const std::vector<phong::light<float>> lights = lights_of<float>(sc);
    const phong::material<float> mat = material_of<float>(sc);
    const float* in[6] = {s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data()};
    const hand_simd::constants c = hand_simd::make_constants(lights, mat);
    double sum = 0;
    for (int i = 0; i < reps; ++i) {
        if (hand) run_hand(in, N, c, s.r.data(), s.g.data(), s.b.data());
        else run_batch(in, N, mat, lights, s.r.data(), s.g.data(), s.b.data());
        sum += double(s.r[std::size_t(i) % N]);
    }
    std::printf("%g\n", sum);
}
#else
int main() { return 2; }
#endif
