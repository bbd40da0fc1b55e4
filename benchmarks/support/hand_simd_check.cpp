// phong_hand_simd_check: asserts the error bounds stated in hand_simd.hpp and the kernel's
// agreement with phong's scalar shade<F> on the benchmark's inputs. Exit status 1 on any failure.
//  1. rsqrt + Newton: every float in [1, 4) (both exponent parities: the estimate's table is
//     indexed by mantissa and parity) and a sparse sweep of [2^-100, 2^100]; bound 1.6 u (AVX-512)
//     or 4.9 u (AVX2), u = 2^-24, against 1/sqrt in double.
//  2. x^m: every 127th float in [2^-126, 1] (8.4 million) for m = 0.5, 1, 32, 300, 1e4, against pow in double;
//     bound (3.5 |y| + 2.5) u, y = m log2 x, where x^m >= 2^-100 (below: flushed, |error| < 2^-100;
//     a margin of 0.1 % either side of the floor for the rounding of y).
//     Plus the edges x = 1 (exactly 1) and, through the model, pow(0, 0) = 1.
//  3. The model: typical inputs, N = 65536 - 3 (a tail too), K = 1, 4, 16, 64, Phong and Blinn,
//     against shade<F> within check_tolerance(m); and the check's power: the other specular model
//     and one light's ambient term left out must both fall outside the tolerance.
#if defined(__GNUC__) && !defined(__clang__) // g++ 12's own AVX-512 intrinsics, see shade.bench.cpp
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "hand_simd.hpp"
#include "inputs.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <vector>

#if PHONG_HAND_SIMD
namespace {

using namespace phong_bench;
using hand_simd::isa;
constexpr double u = 0x1p-24;
constexpr std::size_t W = hand_simd::width;
int failures = 0;

void verdict(bool ok, const char* what, double measured, double bound)
{
    std::printf("%-62s %10.4g (bound %.4g)  %s\n", what, measured, bound, ok ? "ok" : "FAIL");
    if (!ok) ++failures;
}

/// Applies f lane-wise to xs (a multiple of W long is not required).
template <class F>
std::vector<float> lanes(const std::vector<float>& xs, F f)
{
    std::vector<float> out(xs.size());
    alignas(64) float in[W], res[W];
    for (std::size_t i = 0; i < xs.size(); i += W) {
        for (std::size_t j = 0; j < W; ++j) in[j] = i + j < xs.size() ? xs[i + j] : 1.0f;
        isa::store(res, f(isa::load(in)));
        for (std::size_t j = 0; j < W && i + j < xs.size(); ++j) out[i + j] = res[j];
    }
    return out;
}

void check_rsqrt()
{
    std::vector<float> xs;
    for (float x = 1.0f; x < 4.0f; x = std::nextafter(x, 8.0f)) xs.push_back(x);
    for (double e = -100; e <= 100; e += 0.0173) xs.push_back(float(std::exp2(e)));
    const std::vector<float> ys = lanes(xs, [](hand_simd::V x) { return hand_simd::rsqrt(x); });
    double worst = 0;
    for (std::size_t i = 0; i < xs.size(); ++i) {
        const double exact = 1 / std::sqrt(double(xs[i]));
        worst = std::max(worst, std::abs(double(ys[i]) - exact) / exact / u);
    }
    const double bound = W == 16 ? 1.6 : 4.9;
    verdict(worst <= bound, "rsqrt + Newton: max relative error [u]", worst, bound);
}

void check_pow()
{
    std::vector<float> xs;
    for (std::uint32_t bits = std::bit_cast<std::uint32_t>(0x1p-126f); bits <= std::bit_cast<std::uint32_t>(1.0f); bits += 127)
        xs.push_back(std::bit_cast<float>(bits));
    xs.push_back(1.0f);
    for (float m : {0.5f, 1.0f, 32.0f, 300.0f, 1e4f}) {
        const std::vector<float> ys = lanes(xs, [m](hand_simd::V x) { return hand_simd::pow_unit(x, isa::set1(m)); });
        double worst = 0; // error / bound
        double worst_abs_flushed = 0;
        for (std::size_t i = 0; i < xs.size(); ++i) {
            const double exact = std::pow(double(xs[i]), double(m));
            if (exact < 0x1p-100 * 1.001) {
                worst_abs_flushed = std::max(worst_abs_flushed, std::abs(double(ys[i]) - exact));
                continue;
            }
            const double y = double(m) * std::log2(double(xs[i]));
            const double rel = std::abs(double(ys[i]) - exact) / exact;
            worst = std::max(worst, rel / ((3.5 * std::abs(y) + 2.5) * u));
        }
        char what[96];
        std::snprintf(what, sizeof what, "x^m, m = %g: max error / ((3.5|y| + 2.5) u)", double(m));
        verdict(worst <= 1, what, worst, 1);
        std::snprintf(what, sizeof what, "x^m, m = %g: max |error| where x^m < 2^-100", double(m));
        verdict(worst_abs_flushed < 0x1p-100 * 1.001, what, worst_abs_flushed, 0x1p-100 * 1.001);
    }
    const float one = lanes({1.0f}, [](hand_simd::V x) { return hand_simd::pow_unit(x, isa::set1(32.0f)); })[0];
    verdict(one == 1.0f, "x^m at x = 1, m = 32 (exactly 1)", one, 1);
}

template <bool Blinn>
void check_model(std::size_t K, float shininess)
{
    constexpr std::size_t N = 65536;
    scene sc = make_scene(input_set::typical, K);
    sc.shininess = shininess;
    const points<float> pts = make_points<float>(input_set::typical, N, K);
    std::vector<float> p[6], rgb[3];
    for (auto& v : p) v.resize(N);
    for (auto& v : rgb) v.resize(N);
    for (std::size_t i = 0; i < N; ++i)
        for (int k = 0; k < 3; ++k) p[k][i] = pts.position[i][k], p[3 + k][i] = pts.normal[i][k];
    const std::vector<phong::light<float>> lights = lights_of<float>(sc);
    const phong::material<float> mat = material_of<float>(sc);
    // N - 3: a tail shorter than the width too.
    const std::size_t n = N - 3;
    hand_simd::shade<Blinn>(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), p[5].data(), n,
                            hand_simd::make_constants(lights, mat), rgb[0].data(), rgb[1].data(), rgb[2].data());
    const double diff = hand_simd::max_difference_to_scalar<Blinn>(std::span(pts.position).first(n), std::span(pts.normal).first(n),
                                                                   lights, mat, std::span(rgb[0]).first(n),
                                                                   std::span(rgb[1]).first(n), std::span(rgb[2]).first(n));
    char what[96];
    std::snprintf(what, sizeof what, "model vs shade<F>, %s, K = %zu, m = %g: max rel diff", Blinn ? "blinn" : "phong", K,
                  double(shininess));
    verdict(diff <= hand_simd::check_tolerance(shininess), what, diff, hand_simd::check_tolerance(shininess));
    if (K != 4 || shininess != 32) return;
    // The check's power to tell models apart: the other specular model, and one light's ambient
    // term left out, must both be caught.
    const double other = hand_simd::max_difference_to_scalar<!Blinn>(std::span(pts.position).first(n), std::span(pts.normal).first(n),
                                                                     lights, mat, std::span(rgb[0]).first(n),
                                                                     std::span(rgb[1]).first(n), std::span(rgb[2]).first(n));
    std::snprintf(what, sizeof what, "  detects %s computed as %s: max rel diff", Blinn ? "blinn" : "phong", Blinn ? "phong" : "blinn");
    verdict(other > hand_simd::check_tolerance(shininess), what, other, hand_simd::check_tolerance(shininess));
    std::vector<phong::light<float>> fewer = lights;
    fewer[0].ambient = glm::vec3(0);
    hand_simd::shade<Blinn>(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data(), p[5].data(), n,
                            hand_simd::make_constants(fewer, mat), rgb[0].data(), rgb[1].data(), rgb[2].data());
    const double ambient = hand_simd::max_difference_to_scalar<Blinn>(std::span(pts.position).first(n), std::span(pts.normal).first(n),
                                                                      lights, mat, std::span(rgb[0]).first(n),
                                                                      std::span(rgb[1]).first(n), std::span(rgb[2]).first(n));
    verdict(ambient > hand_simd::check_tolerance(shininess), "  detects one light's ambient term left out: max rel diff", ambient,
            hand_simd::check_tolerance(shininess));
}

} // namespace

int main()
{
    std::printf("hand_simd kernel: %s, %zu lanes\n", hand_simd::isa_name, W);
    check_rsqrt();
    check_pow();
    for (std::size_t K : {1u, 4u, 16u, 64u}) {
        check_model<false>(K, 32);
        check_model<true>(K, 32);
    }
    check_model<false>(4, 0); // pow(0, 0) = 1 wherever the gate is on
    check_model<true>(4, 0);
    check_model<false>(4, 1);
    std::printf("%s\n", failures ? "FAILED" : "all checks passed");
    return failures ? 1 : 0;
}
#else
int main()
{
    std::printf("hand_simd kernel not compiled (needs AVX-512F, or AVX2 and FMA): nothing to check\n");
    return 0;
}
#endif
