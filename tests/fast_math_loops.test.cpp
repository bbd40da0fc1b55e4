// fast::pow_unit inlined into a caller's loop, as a renderer writes it: a base computed in the loop
// and constant exponents, against long double's pow within the published bound. In IEEE builds this
// is what tests/fast_math.test.cpp checks; .ci/steps/36-fast-math.sh compiles this file with
// -ffast-math (with and without -march=native), where g++ reassociated log2's exponent k with the
// polynomial and returned 1 for every base near 1 (docs/compilers.md, "-ffast-math").
#include <phong/fast_math.hpp>

#include <doctest/doctest.h>

#include <cmath>

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
