// phong/core/fast_sfu.hpp on the CPU: the bound of the SFU power (x^m = ex2(m lg2(x)) in float CUDA
// device code) checked through an emulation of the two instructions at their documented worst
// errors, in both directions, against long double. benchmarks/cuda/shade.cu checks the same bounds
// on a GPU, with the instructions themselves.
#include <doctest/doctest.h>

#include <phong/accuracy.hpp> // the fast kernels' bounds
#include <phong/core/fast_math.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

/// The float at most `error` from `exact`, as far as possible on the side `side` (+1 above, -1 below):
/// what an instruction with that documented worst error may return.
float worst_float(long double exact, long double error, int side)
{
    float f = static_cast<float>(exact + side * error);
    while (std::fabs(static_cast<long double>(f) - exact) > error) f = std::nextafter(f, side > 0 ? -INFINITY : INFINITY);
    return f;
}

/// fast::pow_unit's device formula, 2^min(fl(m lg2(x)), 0), with lg2 off by its documented absolute
/// error (sfu_log2_abs max(1, |log2 x|)) on side a and ex2 by its relative one on side b; the
/// product in float, rounded to nearest as mul.f32.
float emulated_pow_unit(float x, float m, int a, int b)
{
    const long double lx = std::log2(static_cast<long double>(x));
    const float lg2 = worst_float(lx, phong::fast::detail::sfu_log2_abs * std::max(1.0L, std::fabs(lx)), a);
    volatile float product = m * lg2; // one float rounding, never contracted or kept wider
    const float y = std::min(static_cast<float>(product), 0.0f);
    const long double e = std::exp2(static_cast<long double>(y));
    if (e < 0x1p-126L) return 0.0f; // below float's normal range: flushed (-ftz), or subnormal within 2^-149
    return worst_float(e, phong::fast::detail::sfu_exp2_rel * e, b);
}

struct worst {
    double rel = 0; ///< where x^m >= 2^-24
    double abs = 0; ///< below
};

worst sweep(float m)
{
    std::vector<float> xs;
    for (int e = 1; e <= 40; ++e) // 512 points per binade [2^-e, 2^(1-e))
        for (int j = 0; j < 512; ++j) xs.push_back(std::ldexp(1.0f + float(j) / 512.0f, -e));
    for (int j = 1; j <= 4096; ++j) xs.push_back(1.0f - float(j) * 0x1p-24f); // x near 1: lg2's absolute error matters most
    for (int j = 1; j <= 4096; ++j) xs.push_back(std::exp2(-24.0f / m) * (1.0f + float(j - 2048) * 0x1p-20f)); // x^m near 2^-24
    xs.push_back(1.0f);
    worst w;
    for (const float x : xs) {
        if (!(x > 0.0f && x <= 1.0f)) continue;
        const long double r = std::pow(static_cast<long double>(x), static_cast<long double>(m));
        for (const int a : {-1, 1})
            for (const int b : {-1, 1}) {
                const long double p = emulated_pow_unit(x, m, a, b);
                const double err = static_cast<double>(std::fabs(p - r));
                if (r >= 0x1p-24L) w.rel = std::max(w.rel, static_cast<double>(err / r));
                else w.abs = std::max(w.abs, err);
            }
    }
    return w;
}

} // namespace

TEST_CASE("fast::pow_unit_sfu_max_rel: the emulated lg2/ex2 power at the instructions' worst errors stays within it, and reaches half of it")
{
    for (const float m : {0.5f, 1.0f, 2.0f, 8.0f, 24.0f, 32.0f, 40.0f, 100.0f, 1000.0f, 10000.0f}) {
        CAPTURE(m);
        const double bound = phong::fast::pow_unit_sfu_max_rel(m);
        const worst w = sweep(m);
        CAPTURE(w.rel);
        CAPTURE(bound);
        CHECK(w.rel <= bound);
        CHECK(w.abs <= 0x1p-24 * bound);
        CHECK(w.rel >= 0.5 * bound); // the bound is the documented errors' worst case, not a loose one
    }
}

TEST_CASE("fast::pow_unit_sfu_max_rel: within the CPU kernels' pow_unit_max_rel up to m = 40, growing like m ln2 2^-22 beyond")
{
    for (double m = 0; m <= 40; m += 0.5) CHECK(phong::fast::pow_unit_sfu_max_rel(m) <= phong::fast::pow_unit_max_rel);
    CHECK(phong::fast::pow_unit_sfu_max_rel(41) > phong::fast::pow_unit_max_rel);
    // m = 1e4: ln 2 (1e4 + 24 / 4 ...) 2^-22 to first order, 1.65e-3
    CHECK(phong::fast::pow_unit_sfu_max_rel(1e4) == doctest::Approx(0.6931471805599453 * 1e4 * 0x1p-22).epsilon(0.01));
    CHECK(std::isinf(phong::fast::pow_unit_sfu_max_rel(1e7))); // t > 1: no bound
    // rsqrtf's 2 ulp is within the fast mode's published 1/|d| bound
    CHECK(phong::fast::rsqrt_sfu_max_rel <= phong::fast::rsqrt_max_rel<float>);
}
