// phong/core/math.hpp: special values, pow<N>, fma, min/max/clamp NaN rules, the power-of-two scale,
// cos_degrees, and the constant-evaluation kernels (detail::ce) against the __float128 reference.
// (The constexpr path against the run-time path: tests/constexpr.test.cpp.)
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/core/math.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace phong_test;

namespace {

template <class T> constexpr T pinf = std::numeric_limits<T>::infinity();
template <class T> constexpr T qnan = std::numeric_limits<T>::quiet_NaN();

// The constant-evaluation kernel, called at run time, rounded to T like math_traits does.
template <class T> T ce_sqrt(T x) { return static_cast<T>(phong::detail::ce::sqrt(x)); }
template <class T> T ce_exp(T x) { return static_cast<T>(phong::detail::ce::exp(x)); }
template <class T> T ce_log(T x) { return static_cast<T>(phong::detail::ce::log(x)); }
template <class T> T ce_log1p(T x) { return static_cast<T>(phong::detail::ce::log1p(x)); }
template <class T> T ce_pow(T x, T y) { return static_cast<T>(phong::detail::ce::pow(x, y)); }

// log(1 + x) in the wide type.
wide wlog1p(wide x)
{
#if defined(PHONG_HAVE_QUADMATH)
    return log1pq(x);
#else
    return std::log1p(x);
#endif
}

} // namespace

TEST_CASE_TEMPLATE("math: special values at run time and in the constant-evaluation kernels", T, float, double)
{
    // sqrt: sqrt(-0) = -0, x < 0 gives NaN, inf stays inf.
    for (auto f : {+[](T x) { return phong::detail::sqrt(x); }, +[](T x) { return ce_sqrt(x); }}) {
        CHECK(f(T(0)) == T(0));
        CHECK(std::signbit(f(T(-0.0))));
        CHECK(std::isnan(f(T(-1))));
        CHECK(f(pinf<T>) == pinf<T>);
        CHECK(std::isnan(f(qnan<T>)));
        CHECK(f(T(4)) == T(2));
        CHECK(f(T(0.25)) == T(0.5));
    }
    // exp: overflow to inf, underflow to 0, exp(0) = 1.
    for (auto f : {+[](T x) { return phong::detail::exp(x); }, +[](T x) { return ce_exp(x); }}) {
        CHECK(f(T(0)) == T(1));
        CHECK(f(T(1000)) == pinf<T>);
        CHECK(f(T(-1000)) == T(0));
        CHECK(f(pinf<T>) == pinf<T>);
        CHECK(f(-pinf<T>) == T(0));
        CHECK(std::isnan(f(qnan<T>)));
    }
    // log: log(0) = -inf, x < 0 NaN, log(1) = 0, log(inf) = inf.
    for (auto f : {+[](T x) { return phong::detail::log(x); }, +[](T x) { return ce_log(x); }}) {
        CHECK(f(T(1)) == T(0));
        CHECK(f(T(0)) == -pinf<T>);
        CHECK(std::isnan(f(T(-1))));
        CHECK(f(pinf<T>) == pinf<T>);
        CHECK(std::isnan(f(qnan<T>)));
    }
    // log1p: log1p(-1) = -inf, x < -1 NaN, log1p(0) = 0.
    for (auto f : {+[](T x) { return phong::detail::log1p(x); }, +[](T x) { return ce_log1p(x); }}) {
        CHECK(f(T(0)) == T(0));
        CHECK(f(T(-1)) == -pinf<T>);
        CHECK(std::isnan(f(T(-2))));
        CHECK(f(pinf<T>) == pinf<T>);
        CHECK(std::isnan(f(qnan<T>)));
    }
    // pow: IEEE rules the lighting model relies on (pow(0, 0) = 1 at m = 0).
    for (auto f : {+[](T x, T y) { return phong::detail::pow(x, y); }, +[](T x, T y) { return ce_pow(x, y); }}) {
        CHECK(f(T(0), T(0)) == T(1));
        CHECK(f(T(0), T(2.5)) == T(0));
        CHECK(f(T(0), T(-1)) == pinf<T>);
        CHECK(f(qnan<T>, T(0)) == T(1));
        CHECK(f(T(1), qnan<T>) == T(1));
        CHECK(std::isnan(f(T(0.5), qnan<T>)));
        CHECK(f(T(2), T(10)) == T(1024));
        CHECK(f(T(-2), T(3)) == T(-8));
        CHECK(std::isnan(f(T(-2), T(0.5))));
    }
}

TEST_CASE_TEMPLATE("math: pow<N> by repeated squaring", T, float, double)
{
    CHECK(phong::detail::pow<0>(qnan<T>) == T(1)); // documented: pow<0>(x) = 1 for every x
    CHECK(phong::detail::pow<0>(T(0)) == T(1));
    CHECK(phong::detail::pow<1>(T(0.3)) == T(0.3));
    CHECK(phong::detail::pow<2>(T(3)) == T(9));
    CHECK(phong::detail::pow<5>(T(2)) == T(32));
    CHECK(phong::detail::pow<10>(T(1.5)) == T(59049.0 / 1024.0)); // 3^10 / 2^10, exact in float
    CHECK(phong::detail::pow<7>(T(-2)) == T(-128));
    // Accuracy against the wide reference. Each squaring doubles the relative error already
    // present, so the rounding errors add up to at most (N - 1) u (u = eps / 2) relative, which
    // is at most N - 1 ulp of the result.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> base(0.05, 1.0);
    auto check_n = [&](auto n_constant) {
        constexpr unsigned N = decltype(n_constant)::value;
        const double bound = double(N - 1);
        for (int i = 0; i < 200; ++i) {
            const T x = T(base(rng));
            const double err = error_ulp(phong::detail::pow<N>(x), wpow(wide(x), wide(N)));
            if (!(err <= bound)) { CHECK(err <= bound); return; }
        }
        CHECK(true);
    };
    check_n(std::integral_constant<unsigned, 2>{});
    check_n(std::integral_constant<unsigned, 5>{});
    check_n(std::integral_constant<unsigned, 16>{});
    check_n(std::integral_constant<unsigned, 33>{});
    check_n(std::integral_constant<unsigned, 128>{});
}

TEST_CASE_TEMPLATE("math: fma rounds once, at run time and in constant evaluation", T, float, double)
{
    // (1 + eps)(1 - eps) - 1 = -eps^2 exactly; a separately rounded product gives 0.
    constexpr T eps = std::numeric_limits<T>::epsilon();
    const T a = T(1) + eps, b = T(1) - eps;
    CHECK(phong::detail::fma(a, b, T(-1)) == -eps * eps);
    constexpr T ce = phong::detail::fma(T(1) + eps, T(1) - eps, T(-1));
    CHECK(ce == -eps * eps);
    constexpr T plain = phong::detail::fma(T(3), T(4), T(5));
    CHECK(plain == T(17));
}

TEST_CASE_TEMPLATE("math: abs, min, max, clamp, select and their NaN rules", T, float, double)
{
    CHECK(phong::detail::abs(T(-2)) == T(2));
    CHECK(!std::signbit(phong::detail::abs(T(-0.0))));
    CHECK(phong::detail::min(T(1), T(2)) == T(1));
    CHECK(phong::detail::max(T(1), T(2)) == T(2));
    // Documented: a NaN first argument is returned, a NaN second argument is not.
    CHECK(std::isnan(phong::detail::min(qnan<T>, T(1))));
    CHECK(std::isnan(phong::detail::max(qnan<T>, T(1))));
    CHECK(phong::detail::min(T(1), qnan<T>) == T(1));
    CHECK(phong::detail::max(T(1), qnan<T>) == T(1));
    CHECK(std::isnan(phong::detail::clamp(qnan<T>, T(0), T(1))));
    CHECK(phong::detail::clamp(T(-3), T(0), T(1)) == T(0));
    CHECK(phong::detail::clamp(T(3), T(0), T(1)) == T(1));
    CHECK(phong::detail::clamp(T(0.5), T(0), T(1)) == T(0.5));
    CHECK(phong::detail::select(true, T(1), T(2)) == T(1));
    CHECK(phong::detail::select(false, T(1), T(2)) == T(2));
}

TEST_CASE_TEMPLATE("math: inverse_pow2_scale brings |x| into 1..2 with a power of two", T, float, double)
{
    using traits = phong::detail::math_traits<T>;
    auto is_pow2 = [](T s) {
        int e = 0;
        return std::frexp(s, &e) == T(0.5);
    };
    const T values[] = {T(1), T(1.5), T(3), T(1e-3), T(1e3), std::numeric_limits<T>::min(), std::numeric_limits<T>::max(),
                        T(0.75) * std::numeric_limits<T>::max(), T(12345.678)};
    for (T x : values) {
        const T s = traits::inverse_pow2_scale(x);
        CAPTURE(x);
        CHECK(is_pow2(s));
        CHECK(std::isnormal(s));
        // The top binade needs 2^-(max exponent), which is not normal: clamped, so [2, 4) there.
        const bool top = x >= std::ldexp(T(1), std::numeric_limits<T>::max_exponent - 1);
        CHECK(x * s >= T(top ? 2 : 1));
        CHECK(x * s < T(top ? 4 : 2));
    }
    // Subnormal: the largest normal scale, which lands the float subnormal in [2^-22, 2)
    // (documented for float); in general x * s stays finite, nonzero and < 2.
    const T sub = std::numeric_limits<T>::denorm_min() * T(5);
    const T s = traits::inverse_pow2_scale(sub);
    CHECK(std::isnormal(s));
    CHECK(sub * s > T(0));
    CHECK(sub * s < T(2));
    if constexpr (std::is_same_v<T, float>) CHECK(sub * s >= std::ldexp(1.0f, -22));
    CHECK(std::isnormal(traits::inverse_pow2_scale(T(0)))); // zero: some finite scale
}

TEST_CASE_TEMPLATE("math: cos_degrees", T, float, double)
{
    CHECK(phong::detail::cos_degrees(T(0)) == T(1));
    CHECK(phong::detail::cos_degrees(T(90)) == T(0));
    CHECK(phong::detail::cos_degrees(T(180)) == T(-1));
    // cos 60 = 1/2, cos 45 = sqrt(1/2), cos 120 = -1/2, cos 30 = sqrt(3)/2: within 1 ulp.
    CHECK(error_ulp(phong::detail::cos_degrees(T(60)), wide(0.5)) <= 1.0);
    CHECK(error_ulp(phong::detail::cos_degrees(T(120)), wide(-0.5)) <= 1.0);
    CHECK(error_ulp(phong::detail::cos_degrees(T(45)), wsqrt(wide(0.5))) <= 1.0);
    CHECK(error_ulp(phong::detail::cos_degrees(T(30)), wsqrt(wide(3)) / 2) <= 1.0);
    // Monotone decreasing on [0, 180].
    T previous = T(2);
    for (int d = 0; d <= 180; ++d) {
        const T c = phong::detail::cos_degrees(T(d));
        if (!(c < previous)) { CHECK(c < previous); break; }
        previous = c;
    }
}

// The kernels work in long double and round once: for float and double they are within 1 ulp of
// the exact value (nearly correctly rounded), well inside constexpr_tolerance_ulp.
TEST_CASE_TEMPLATE("math: constant-evaluation kernels against the __float128 reference", T, float, double)
{
    constexpr bool is_float = std::is_same_v<T, float>;
    std::mt19937_64 rng(2026);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst_sqrt = 0, worst_exp = 0, worst_log = 0, worst_log1p = 0, worst_pow = 0;
    const double max_exp = is_float ? 88 : 709;
    for (int i = 0; i < 2000; ++i) {
        // Arguments spread over the exponent range of T.
        const double e = (unit(rng) * 2 - 1) * (is_float ? 120 : 1000);
        const T x = T(std::ldexp(1 + unit(rng), int(e)));
        worst_sqrt = std::max(worst_sqrt, error_ulp(ce_sqrt(x), wsqrt(wide(x))));
        worst_log = std::max(worst_log, error_ulp(ce_log(x), wlog(wide(x))));
        const T xe = T((unit(rng) * 2 - 1) * max_exp);
        worst_exp = std::max(worst_exp, error_ulp(ce_exp(xe), wexp(wide(xe))));
        const T x1 = unit(rng) < 0.3 ? T(std::ldexp(unit(rng) - 0.5, -int(unit(rng) * 40))) : T(unit(rng) * 10 - 0.99);
        worst_log1p = std::max(worst_log1p, error_ulp(ce_log1p(x1), wlog1p(wide(x1))));
        // pow over the lighting range: base in (0, 1], exponent in [0, 1000].
        const T b = T(unit(rng) * 0.999 + 0.001), y = T(unit(rng) * unit(rng) * 1000);
        const wide ref = wpow(wide(b), wide(y));
        if (ref > wide(std::numeric_limits<T>::min())) worst_pow = std::max(worst_pow, error_ulp(ce_pow(b, y), ref));
    }
    MESSAGE("ce kernels, worst ulp: sqrt " << worst_sqrt << ", exp " << worst_exp << ", log " << worst_log
                                           << ", log1p " << worst_log1p << ", pow " << worst_pow);
    CHECK(worst_sqrt <= 1.0);
    CHECK(worst_exp <= 1.0);
    CHECK(worst_log <= 1.0);
    CHECK(worst_log1p <= 1.0);
    CHECK(worst_pow <= 1.0);
}
