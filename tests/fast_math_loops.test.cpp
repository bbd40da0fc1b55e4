// phong's power kernels inlined into a caller's loop, as a renderer writes it, against long double
// within their bounds: fast::pow_unit (bases near 1, constant exponents) and the exact mode's lane
// kernels (math_traits over xsimd: float's pow_unit, double's exp, log, log1p and pow_unit). In IEEE
// builds this repeats tests/fast_math.test.cpp and tests/lanes_power.test.cpp; .ci/steps/36-fast-math.sh
// compiles this file with -ffast-math, with -march=native and at the x86-64 baseline, where g++
// reassociated log2's exponent k with the polynomial (every base near 1 gave 1), and clang++ at SSE2
// saw through xsimd's rounding tricks (docs/compilers.md, "-ffast-math").
#include <phong/batch.hpp>
#include <phong/accuracy.hpp> // the fast kernels' bounds
#include <phong/core/fast_math.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace {

// The worst relative error over bases x = T(1 - i 4e-5) (i < 5000: down to 0.8) and four constant
// exponents, where x^m >= 2^-24 (below it the bound is absolute, and checked as such).
template <class T> double worst_pow_unit_error()
{
    const T ms[4] = {T(1), T(8), T(64), T(1000)};
    double worst = 0;
    for (int i = 0; i < 5000; ++i) {
        const T x = T(1.0 - i * 4e-5);
        for (int k = 0; k < 4; ++k) {
            const T p = phong::fast::pow_unit(x, ms[k]);
            const long double r = std::pow(static_cast<long double>(x), static_cast<long double>(ms[k]));
            const long double err = std::fabs(static_cast<long double>(p) - r);
            const long double scale = r >= 0x1p-24L ? r : 0x1p-24L;
            worst = std::max(worst, static_cast<double>(err / scale));
        }
    }
    return worst;
}

} // namespace

TEST_CASE_TEMPLATE("fast::pow_unit in a loop of bases near 1 with constant exponents: within its bound", T, float, double)
{
    CHECK(worst_pow_unit_error<T>() <= phong::fast::pow_unit_max_rel);
}

#if PHONG_HAS_XSIMD
// The exact mode's float lanes' power (detail/simd/lanes_power.hpp, through phong::detail::math_traits), bases and
// exponents varying per lane, against long double's pow within its documented bound
// (pow_unit_lanes_error(m log2 x), relative, where x^m >= 2^-126; 0 allowed below the power floor).
TEST_CASE("float lanes' pow_unit in a loop: within pow_unit_lanes_error")
{
    using V = xsimd::batch<float>;
    constexpr std::size_t n = V::size;
    double worst = 0; // error / bound
    std::vector<float> xs(n), ms(n), out(n);
    for (int i = 0; i < 4000; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            xs[j] = float(1.0 - double(i * n + j) * (0.8 / (4000.0 * n)));
            ms[j] = float(1 + (i % 50) * int(j % 4));
        }
        phong::detail::math_traits<V>::pow_unit(V::load_unaligned(xs.data()), V::load_unaligned(ms.data())).store_unaligned(out.data());
        for (std::size_t j = 0; j < n; ++j) {
            const long double r = std::pow(static_cast<long double>(xs[j]), static_cast<long double>(ms[j]));
            if (r < 0x1p-126L) continue;
            // Below the power floor (2^-100: ieee::power_floor_log2) the lanes may return 0
            // (docs/accuracy.md, 'The power floor'); a value they keep is held to the bound.
            if (out[j] == 0.0f && r < std::ldexp(1.0L, phong::detail::ieee::power_floor_log2<float>)) continue;
            const double bound = phong::detail::lanes::pow_unit_lanes_error(double(ms[j]) * std::log2(double(xs[j])));
            worst = std::max(worst, static_cast<double>(std::fabs(static_cast<long double>(out[j]) - r) / r) / bound);
        }
    }
    CHECK(worst <= 1.0);
}

// The double lanes' exp, log, log1p and the power built on them (math_traits over xsimd), against
// long double: exp(y log x) carries the rounding of y = m log x times |y|, so the tolerance is
// 16 (|y| + 1) double epsilons (a few ulp of each kernel, with a margin).
TEST_CASE("double lanes' exp, log, log1p and pow_unit in a loop: within a few ulp")
{
    using V = xsimd::batch<double>;
    using M = phong::detail::math_traits<V>;
    constexpr std::size_t n = V::size;
    constexpr double eps = 0x1p-52;
    double worst[4] = {0, 0, 0, 0}; // error / tolerance: exp, log, log1p, pow_unit
    std::vector<double> xs(n), ms(n), o[4];
    for (auto& v : o) v.resize(n);
    for (int i = 0; i < 3000; ++i) {
        for (std::size_t j = 0; j < n; ++j) {
            xs[j] = 1.0 - double(i * n + j) * (0.9 / (3000.0 * n));
            ms[j] = double(1 + (i % 50) * int(j % 4 + 1));
        }
        const V x = V::load_unaligned(xs.data()), m = V::load_unaligned(ms.data());
        M::exp(-m * x).store_unaligned(o[0].data());
        M::log(x).store_unaligned(o[1].data());
        M::log1p(-x).store_unaligned(o[2].data());
        M::pow_unit(x, m).store_unaligned(o[3].data());
        for (std::size_t j = 0; j < n; ++j) {
            const long double X = xs[j], Mj = ms[j], y = Mj * std::log(X);
            const long double ref[4] = {std::exp(-static_cast<long double>(ms[j] * xs[j])), std::log(X), std::log1p(-X), std::exp(y)};
            const long double mag[4] = {Mj * X, 1, 1, std::fabs(y)};
            for (int k = 0; k < 4; ++k) {
                const long double rel = std::fabs((static_cast<long double>(o[k][j]) - ref[k]) / ref[k]);
                worst[k] = std::max(worst[k], static_cast<double>(rel / (16 * eps * (mag[k] + 1))));
            }
        }
    }
    CHECK(worst[0] <= 1.0);
    CHECK(worst[1] <= 1.0);
#if !PHONG_FP_REASSOCIATION
    // log1p only in IEEE builds: xsimd's log1p corrects 1 + x by (x - (u - 1)) / u, which
    // -fassociative-math folds (measured 150 eps with g++ -O3 -march=native -ffast-math); its one
    // user, the stable mode's twofold route, refuses such builds (detail/ieee.hpp).
    CHECK(worst[2] <= 1.0);
#endif
    CHECK(worst[3] <= 1.0);
}
#endif
