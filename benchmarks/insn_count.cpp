// Shading calls to count executed instructions per (point, light) where no hardware counters are
// at hand (aarch64 under qemu-user: benchmarks/support/qemu_insn_count.c). Shades N typical points
// (benchmarks/support/inputs.hpp, float, K positional lights, m = 32) R times with the route named
// (scalar: a loop of shade<F>; batch: shade_batch<F>; hand: the hand-written kernel of
// support/hand_simd.hpp), F the hand kernel's model (hand_simd::model: glsl_ads) in the mode named;
// with "check", prints the largest relative difference to phong's scalar shade<F> (after the
// calls: outside the count's interest) and fails if the hand kernel's exceeds its tolerance
// (hand_simd::check_tolerance; .ci/steps/37-aarch64.sh checks the NEON kernel so). Two runs
// with R = 1 and R = 2 give the count of one call, their difference, and / (N K) the count per
// pair: start-up and the scene's set-up cancel.
//
// Usage: phong_insn_count <scalar|batch|hand> <exact|fast|stable> <phong|blinn> N K R [check]
// docs/batch.md ("aarch64") has the commands and the figures.
#include <phong/batch.hpp>

#include "support/hand_simd.hpp"
#include "support/inputs.hpp"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

using namespace phong_bench;

template <bool Blinn, phong::evaluation Mode>
int run(const std::string& route, std::size_t N, std::size_t K, std::size_t R, bool check)
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
    const auto shade_once = [&]() -> int {
        if (route == "scalar") {
            for (std::size_t i = 0; i < N; ++i) {
                const glm::vec3 c = phong::shade<F>(pts.position[i], pts.normal[i], mat, std::span<const phong::light<float>>(lights));
                s.r[i] = c.r, s.g[i] = c.g, s.b[i] = c.b;
            }
        } else if (route == "batch") {
            phong::shade_batch<F>(phong::soa3<float>{S(s.px), S(s.py), S(s.pz)}, phong::soa3<float>{S(s.nx), S(s.ny), S(s.nz)}, mat,
                                  std::span<const phong::light<float>>(lights), phong::soa_rgba<float>{s.r, s.g, s.b, {}});
        } else if (route == "hand") {
#if PHONG_HAND_SIMD
            const hand_simd::constants c = hand_simd::make_constants(lights, mat);
            hand_simd::shade<Blinn>(s.px.data(), s.py.data(), s.pz.data(), s.nx.data(), s.ny.data(), s.nz.data(), N, c, s.r.data(), s.g.data(), s.b.data());
#else
            std::fprintf(stderr, "phong_insn_count: no hand-written kernel for this target\n");
            return 2;
#endif
        } else {
            std::fprintf(stderr, "phong_insn_count: unknown route %s\n", route.c_str());
            return 2;
        }
        return 0;
    };
    for (std::size_t rep = 0; rep < R; ++rep)
        if (const int error = shade_once()) return error;
    if (check) {
        const double d = hand_simd::max_difference_to_scalar<Blinn>(pts.position, pts.normal, lights, mat, s.r, s.g, s.b);
        const double tolerance = hand_simd::check_tolerance(mat.shininess);
        std::printf("%s: largest relative difference to shade<F>: %.3g (hand kernel's tolerance %.3g)\n", route.c_str(), d, tolerance);
        if (route == "hand" && !(d <= tolerance)) return 1; // the hand kernel computes another model
    }
    return 0;
}

template <bool Blinn>
int run_mode(const std::string& mode, const std::string& route, std::size_t N, std::size_t K, std::size_t R, bool check)
{
    if (mode == "fast") return run<Blinn, phong::evaluation::fast>(route, N, K, R, check);
    if (mode == "stable") return run<Blinn, phong::evaluation::stable>(route, N, K, R, check);
    return run<Blinn, phong::evaluation::exact>(route, N, K, R, check);
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 7) {
        std::fprintf(stderr, "usage: phong_insn_count <scalar|batch|hand> <exact|fast|stable> <phong|blinn> N K R [check]\n");
        return 2;
    }
    const std::string route = argv[1], mode = argv[2];
    const bool blinn = std::strcmp(argv[3], "blinn") == 0;
    const std::size_t N = std::strtoul(argv[4], nullptr, 10), K = std::strtoul(argv[5], nullptr, 10);
    const std::size_t R = std::strtoul(argv[6], nullptr, 10);
    const bool check = argc > 7 && std::strcmp(argv[7], "check") == 0;
    return blinn ? run_mode<true>(mode, route, N, K, R, check) : run_mode<false>(mode, route, N, K, R, check);
}
