// phong::detail::pow_unit (include/phong/core/power.hpp): x^m for x in [0, 1], m >= 0.
//  * accuracy on seeded random inputs against pow in the wide reference type (support/wide.hpp:
//    __float128 with g++, long double with clang++), double and float;
//  * edges: 0^0, 0^m, 1^m, x^0, x^1, monotonicity, range, flush to 0, NaN, outside the domain;
//  * constant evaluation: static_asserts, and constexpr results = run-time results bit for bit;
//  * the two tables (log2 points, 2^(j/64)) against the wide reference.
// Expected values come from the wide pow/log, from exact identities (powers of two) or from
// std::pow (which the kernel is documented to defer to outside its domain), never from the kernel.
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/core/math.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

using namespace phong_test;

namespace {

constexpr double u53 = 0x1p-53; // unit roundoff of double

// The documented relative-error bound of pow_unit is "about" (|m log2 x| + m + 4) * 2^-53
// (math.hpp). The tests allow a safety factor of 3 on top of it: y = m log2 x is computed as
// m ((k + log2 c) + p) (with a - 64 for subnormal x), up to 3 (4) roundings each as large as
// |y| 2^-53, which 2^y turns into a relative error of ln 2 times that: up to 2.1 (2.8) |y| 2^-53
// where |y| lies just above a power of two. (A targeted search measured 2.03 at |y| just above
// 512; the seeded "|m log2 x| in 512 .. 521" inputs below reach 1.95.)
constexpr double safety = 3.0;

wide wlog2(wide x) { return wlog(x) / wlog(wide(2)); }

/// A double or float written exactly (hex float), for failure messages.
template <class T> std::string hex(T v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%a", static_cast<double>(v));
    return buf;
}

/// Defeats constant folding: the run-time path of the kernel is what gets called.
template <class T> T launder(T v)
{
    volatile T t = v;
    return t;
}

/// The documented error bound for x^m, in units of 2^-53, from the wide reference.
double bound_units(double x, double m)
{
    return double(wabs(wide(m) * wlog2(wide(x)))) + m + 4;
}

/// Accumulates the worst ratio error / documented bound, and the flush rule, over many inputs.
struct double_stats {
    long samples = 0, checked = 0, flushed = 0;
    double worst_ratio = 0, worst_x = 0, worst_m = 0, worst_rel = 0; // worst of error / bound
    long out_of_range = 0, subnormal = 0, not_flushed = 0, bad_near_flush = 0;
    std::string first_bad;

    void add(double x, double m)
    {
        ++samples;
        const double r = phong::detail::pow_unit(launder(x), launder(m));
        const wide ref = wpow(wide(x), wide(m));
        auto bad = [&](const char* what) {
            if (first_bad.empty())
                first_bad = std::string(what) + ": x = " + hex(x) + ", m = " + hex(m) + ", result " + hex(r) +
                            ", reference " + hex(double(ref));
        };
        if (!(r >= 0 && r <= 1)) { ++out_of_range; bad("result outside [0, 1]"); }
        if (r != 0 && r < 0x1p-1022) { ++subnormal; bad("subnormal result"); }
        if (ref >= wide(0x1p-1021)) {
            ++checked;
            const double rel = error_rel(r, ref);
            const double ratio = rel / (bound_units(x, m) * u53);
            if (ratio > worst_ratio) { worst_ratio = ratio; worst_x = x; worst_m = m; worst_rel = rel; }
        } else if (ref < wide(0x1p-1023)) {
            // y = m log2 x < -1023: the computed y is below -1022 too, the result is flushed.
            ++flushed;
            if (r != 0) { ++not_flushed; bad("not flushed"); }
        } else if (r != 0 && error_rel(r, ref) > safety * bound_units(x, m) * u53) {
            // 2^-1023 <= x^m < 2^-1021: either flushed or accurate.
            ++bad_near_flush;
            bad("near the flush threshold, neither 0 nor accurate");
        }
    }

    void report(const std::string& name) const
    {
        MESSAGE(name << ": " << samples << " samples, " << checked << " checked against the bound, " << flushed
                     << " flushed; worst error " << worst_rel << " = " << worst_rel / u53 << " * 2^-53 = "
                     << worst_ratio << " * (|m log2 x| + m + 4) 2^-53 at x = " << hex(worst_x)
                     << ", m = " << hex(worst_m));
        INFO(first_bad);
        CHECK(checked > samples / 4);
        CHECK(worst_ratio <= safety);
        CHECK(out_of_range == 0);
        CHECK(subnormal == 0);
        CHECK(not_flushed == 0);
        CHECK(bad_near_flush == 0);
    }
};

constexpr std::array<double, 9> fixed_m = {0, 0.5, 1, 2, 32, 200, 1e3, 1e4, 1e5};

/// m: the fixed list for even i, log-uniform in [1e-3, 1e6] for odd i.
template <class T> T pick_m(std::mt19937_64& g, long i)
{
    if (i % 2 == 0) return static_cast<T>(fixed_m[static_cast<std::size_t>((i / 2) % long(fixed_m.size()))]);
    return static_cast<T>(std::pow(10.0, std::uniform_real_distribution<double>(-3, 6)(g)));
}

/// The three classes of x for T: uniform in (0, 1], 1 - 2^-k (near 1), 2^-k (tiny, down to the
/// smallest subnormal of T). Odd samples of the last two classes get a random significand.
/// (m comes from pick_m; the hard cases for double, |y| just above 512, are made in the test.)
template <class T> T pick_x(std::mt19937_64& g, int cls, long i)
{
    constexpr int digits = std::numeric_limits<T>::digits;                        // 53 / 24
    constexpr int min_exp = std::numeric_limits<T>::min_exponent - digits;        // -1074 / -149
    std::uniform_real_distribution<double> unit(1, 2);
    switch (cls) {
    case 0: { // uniform on the grid k 2^-digits, k = 1 .. 2^digits
        const std::uint64_t k = (g() >> (64 - digits)) + 1;
        return static_cast<T>(std::ldexp(static_cast<double>(k), -digits));
    }
    case 1: {
        const int k = 1 + static_cast<int>(g() % digits);
        const double d = i % 2 == 0 ? std::ldexp(1.0, -k) : std::ldexp(unit(g), -k - 1);
        return static_cast<T>(T(1) - static_cast<T>(d)); // rounded to T: a valid input either way
    }
    default: {
        const int k = 1 + static_cast<int>(g() % static_cast<std::uint64_t>(-min_exp));
        const double x = i % 2 == 0 ? std::ldexp(1.0, -k) : std::ldexp(unit(g), -k - 1);
        const T t = static_cast<T>(x);
        return t > 0 ? t : std::numeric_limits<T>::denorm_min();
    }
    }
}

const std::string class_names[3] = {"x uniform in (0, 1]", "x = 1 - 2^-k", "x = 2^-k"};

} // namespace

// ---------------------------------------------------------------------------------------------
// 1. Accuracy against the wide reference.

TEST_CASE("pow_unit: double accuracy against the wide pow on seeded random inputs")
{
    std::mt19937_64 g(0x5eed'0f'0ddba11ull);
    for (int cls = 0; cls < 3; ++cls) {
        double_stats s;
        for (long i = 0; i < 40000; ++i) {
            const double x = pick_x<double>(g, cls, i);
            s.add(x, pick_m<double>(g, i));
        }
        s.report(class_names[cls]);
    }
    // The hardest case for the bound: |y| = |m log2 x| just above 512, where the roundings of
    // k + log2 c, of + p and of m * (and of - 64 for subnormal x) are each as large as |y| 2^-53.
    double_stats s;
    std::uniform_real_distribution<double> unit(1, 2);
    for (long i = 0; i < 40000; ++i) {
        if (i % 2 == 0) {
            const double x = std::ldexp(unit(g), -513 - int(g() % 8));
            s.add(x, 1 + (unit(g) - 1) / 64);
        } else {
            const double x = std::ldexp(unit(g), -1023 - int(g() % 51)); // subnormal
            s.add(x, std::uniform_real_distribution<double>(512, 520)(g) / -std::log2(x));
        }
    }
    s.report("|m log2 x| in 512 .. 521, x normal or subnormal");
}

TEST_CASE("pow_unit: float results within 1 ulp of the wide pow and correctly rounded but for near-ties")
{
    std::mt19937_64 g(0xf10a7'5eedull);
    long n = 0, correct = 0, nontrivial = 0, nontrivial_correct = 0;
    double worst_ulp = 0;
    std::string worst;
    for (int cls = 0; cls < 3; ++cls) {
        for (long i = 0; i < 60000; ++i) {
            const float x = pick_x<float>(g, cls, i);
            const float m = pick_m<float>(g, i);
            const float r = phong::detail::pow_unit(launder(x), launder(m));
            const wide ref = wpow(wide(x), wide(m));
            const float rounded = static_cast<float>(ref); // one rounding from the wide value
            const double e = error_ulp<float>(r, ref);
            if (e > worst_ulp) {
                worst_ulp = e;
                worst = "x = " + hex(x) + ", m = " + hex(m) + ": " + hex(r) + ", correctly rounded " + hex(rounded);
            }
            ++n;
            correct += r == rounded;
            // Non-trivial: a normal float result that float cannot hold exactly.
            if (rounded >= std::numeric_limits<float>::min() && wide(rounded) != ref) {
                ++nontrivial;
                nontrivial_correct += r == rounded;
            }
        }
    }
    const double rate = double(correct) / double(n);
    const double nontrivial_rate = double(nontrivial_correct) / double(nontrivial);
    MESSAGE("float: worst error " << worst_ulp << " ulp (" << worst << "); correctly rounded " << correct << " / " << n
                                  << " = " << 100 * rate << " %; among normal inexact results " << nontrivial_correct
                                  << " / " << nontrivial << " = " << 100 * nontrivial_rate << " %");
    INFO(worst);
    CHECK(worst_ulp <= 1.0);
    CHECK(nontrivial > n / 4);
    CHECK(rate > 0.999);
    CHECK(nontrivial_rate > 0.999);
}

// ---------------------------------------------------------------------------------------------
// 2. Edges.

TEST_CASE_TEMPLATE("pow_unit: zero and one as base or exponent", T, float, double)
{
    constexpr T inf = std::numeric_limits<T>::infinity();
    std::mt19937_64 g(2024);
    // 0^0 = 1 (IEEE), 0^m = 0 for every m > 0, also the smallest and an infinite m.
    CHECK(phong::detail::pow_unit(launder(T(0)), launder(T(0))) == T(1));
    constexpr T tiny = std::numeric_limits<T>::denorm_min(), big = std::numeric_limits<T>::max();
    for (T m : {tiny, T(1e-30), T(0.5), T(1), T(2), T(1e5), big, inf}) {
        CAPTURE(m);
        const T r = phong::detail::pow_unit(launder(T(0)), launder(m));
        CHECK(r == T(0));
        CHECK(!std::signbit(r));
    }
    // 1^m = 1 exactly for every finite m >= 0.
    std::vector<T> ms = {T(0), tiny, T(1), T(32), T(1e5), T(1e6), big};
    for (int i = 0; i < 2000; ++i)
        ms.push_back(static_cast<T>(std::pow(10.0, std::uniform_real_distribution<double>(-40, 38)(g))));
    for (T m : ms) {
        CAPTURE(m);
        CHECK(phong::detail::pow_unit(launder(T(1)), launder(m)) == T(1));
    }
    // x^0 = 1 for every x in [0, 1], subnormals included.
    std::vector<T> xs = {T(0), std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::min(), T(0.5), T(1),
                         std::nextafter(T(1), T(0))};
    for (int i = 0; i < 2000; ++i) xs.push_back(pick_x<T>(g, i % 3, i / 3));
    for (T x : xs) {
        CAPTURE(x);
        CHECK(phong::detail::pow_unit(launder(x), launder(T(0))) == T(1));
    }
}

TEST_CASE("pow_unit: x^1 against x, and exact powers of two")
{
    // Powers of two: y = m log2 2^-k = -k m is exact, and when it is a multiple of 1/64 the result
    // is a table entry 2^(j/64) scaled by a power of two. So (2^-k)^1 = 2^-k, (2^-k)^2 = 2^-2k
    // exactly, and (2^-k)^(1/2) is the correctly rounded sqrt (std::sqrt is correctly rounded,
    // IEEE 754), also for subnormal 2^-k.
    for (int k = 0; k <= 1074; ++k) {
        CAPTURE(k);
        const double x = std::ldexp(1.0, -k);
        if (k <= 1021) CHECK(phong::detail::pow_unit(launder(x), launder(1.0)) == x);
        if (2 * k <= 1021) CHECK(phong::detail::pow_unit(launder(x), launder(2.0)) == std::ldexp(1.0, -2 * k));
        CHECK(phong::detail::pow_unit(launder(x), launder(0.5)) == std::sqrt(x));
    }

    // x^1: within the documented bound everywhere above the flush threshold (it grows with |log2 x|,
    // the kernel has no special case for m = 1), and within 1 ulp of x for at least 99.9 % of x in
    // [0.5, 1].
    std::mt19937_64 g(11);
    long n = 0, within_1ulp = 0;
    std::uint64_t worst_ulp_top = 0, worst_ulp_all = 0;
    double worst_ratio = 0, worst_x = 0;
    for (long i = 0; i < 200000; ++i) {
        const bool top = i % 2 == 0;
        const double x = top ? std::uniform_real_distribution<double>(0.5, 1)(g)
                             : std::ldexp(std::uniform_real_distribution<double>(1, 2)(g), -1 - int(g() % 1020));
        const double r = phong::detail::pow_unit(launder(x), launder(1.0));
        const double ratio = error_rel(r, wide(x)) / (bound_units(x, 1) * u53);
        if (ratio > worst_ratio) { worst_ratio = ratio; worst_x = x; }
        const std::uint64_t d = ulp_distance(r, x);
        worst_ulp_all = std::max(worst_ulp_all, d);
        if (top) {
            ++n;
            within_1ulp += d <= 1;
            worst_ulp_top = std::max(worst_ulp_top, d);
        }
    }
    MESSAGE("x^1: within 1 ulp of x for " << within_1ulp << " / " << n << " x in [0.5, 1) (worst " << worst_ulp_top
                                          << " ulp); worst over [2^-1020, 1): " << worst_ulp_all << " ulp, "
                                          << worst_ratio << " * bound at x = " << hex(worst_x));
    CHECK(worst_ratio <= safety);
    CHECK(double(within_1ulp) / double(n) > 0.999);
    CHECK(phong::detail::pow_unit(launder(1.0), launder(1.0)) == 1.0);
    CHECK(phong::detail::pow_unit(launder(0.75f), launder(1.0f)) == 0.75f);
}

TEST_CASE("pow_unit: monotone in m and in x on sweeps, results in 0..1")
{
    // Sweeps whose steps are far larger than the documented error, so a reversal is a bug, not
    // rounding. (At the ulp level the kernel is not monotone across table boundaries; that is
    // within its error bound and measured below.)
    long evaluations = 0, outside = 0, reversals = 0;
    std::string first;
    auto note = [&](const char* what, double x, double m, double r, double previous) {
        if (first.empty())
            first = std::string(what) + ": x = " + hex(x) + ", m = " + hex(m) + ", result " + hex(r) + ", previous " +
                    hex(previous);
    };
    std::vector<double> ms = {0};
    for (double m = 1e-3; m <= 1e6; m *= 1.0 + 1.0 / 64) ms.push_back(m);
    for (double x : {0x1p-1074, 1e-300, 1e-20, 1e-5, 0.1, 0.5, 0.7, 0.9, 0.99, 0.999999, 1 - 0x1p-30, 1 - 0x1p-53}) {
        double previous = 1;
        for (double m : ms) {
            const double r = phong::detail::pow_unit(launder(x), launder(m));
            ++evaluations;
            if (!(r >= 0 && r <= 1)) { ++outside; note("outside [0, 1]", x, m, r, previous); }
            if (r > previous) { ++reversals; note("increases with m", x, m, r, previous); }
            previous = r;
        }
    }
    // x = 2^t, t from -1074 to 0 in steps of 1/256 (x grows by 0.27 % a step).
    for (double m : {1e-3, 0.5, 1.0, 2.0, 32.0, 200.0, 1e3, 1e4, 1e5, 1e6}) {
        double previous = 0;
        for (int step = -1074 * 256; step <= 0; ++step) {
            const double x = std::exp2(step / 256.0);
            const double r = phong::detail::pow_unit(launder(x), launder(m));
            ++evaluations;
            if (!(r >= 0 && r <= 1)) { ++outside; note("outside [0, 1]", x, m, r, previous); }
            if (r < previous) { ++reversals; note("decreases with x", x, m, r, previous); }
            previous = r;
        }
        if (previous != 1) { ++reversals; note("1^m is not 1", 1, m, previous, previous); }
    }
    MESSAGE("sweeps: " << evaluations << " evaluations");
    {
        INFO(first);
        CHECK(outside == 0);
        CHECK(reversals == 0);
    }

    // Adjacent doubles across every log2-table boundary (x) and every 2^(n/64) boundary (y = -m
    // at x = 0.5): a reversal must stay within the documented error of the two results.
    long boundary_reversals = 0, boundaries = 0;
    double worst = 0;
    for (double m : {0.5, 2.0, 32.0, 1e3}) {
        for (int e = 0; e <= 60; ++e) {
            for (std::uint64_t i = 0; i < 128; ++i) {
                const double b = std::ldexp(std::bit_cast<double>(0x3fe6000000000000ull + (i << 45)), -e);
                if (b >= 1) continue;
                const double a = std::nextafter(b, 0.0);
                const double fa = phong::detail::pow_unit(launder(a), launder(m)), fb = phong::detail::pow_unit(launder(b), launder(m));
                ++boundaries;
                if (fa > fb) {
                    ++boundary_reversals;
                    const double rel = (fa - fb) / fb / (bound_units(b, m) * u53);
                    worst = std::max(worst, rel);
                    CHECK(rel <= 2 * safety);
                }
            }
        }
    }
    for (int n = 1; n < 1022 * 64; ++n) {
        const double m = n / 64.0 - 1 / 128.0; // y = -m around the middle of two table steps, then
        for (double mm : {m, n / 64.0}) {      // at a step
            const double lo = mm, hi = std::nextafter(mm, 2048.0);
            const double flo = phong::detail::pow_unit(launder(0.5), launder(lo));
            const double fhi = phong::detail::pow_unit(launder(0.5), launder(hi));
            ++boundaries;
            if (fhi > flo) {
                ++boundary_reversals;
                const double rel = (fhi - flo) / flo / (bound_units(0.5, hi) * u53);
                worst = std::max(worst, rel);
                CHECK(rel <= 2 * safety);
            }
        }
    }
    MESSAGE("adjacent inputs across table boundaries: " << boundary_reversals << " reversals in " << boundaries
                                                        << " pairs, worst " << worst << " * bound");
}

TEST_CASE("pow_unit: results below 2^-1022 flush to 0, never subnormal")
{
    struct in { double x, m; };
    // y = m log2 x < -1022 by more than the error: exactly 0 (pow would give a subnormal or 0).
    for (in c : {in{0.5, 1023}, in{0.5, 1022.5}, in{0.5, 1e6}, in{0x1p-600, 2}, in{0x1p-1022, 1.5}, in{0x1p-1074, 1},
                 in{0x1p-1074, 0.96}, in{0.999, 1e6}, in{1 - 0x1p-20, 1e9}, in{0.1, 308}, in{0x1p-1022, 1.0001}}) {
        CAPTURE(c.x);
        CAPTURE(c.m);
        REQUIRE(wpow(wide(c.x), wide(c.m)) < wide(0x1p-1022)); // the premise, from the reference
        const double r = phong::detail::pow_unit(launder(c.x), launder(c.m));
        CHECK(r == 0);
        CHECK(!std::signbit(r));
        CHECK(phong::detail::pow_unit(launder(float(c.x)), launder(float(c.m))) == 0.0f);
    }
    // Just above the threshold: normal and accurate.
    for (in c : {in{0.5, 1021}, in{0.5, 1021.9}, in{0x1p-1074, 0.95}, in{0.1, 307}}) {
        CAPTURE(c.x);
        CAPTURE(c.m);
        const wide ref = wpow(wide(c.x), wide(c.m));
        REQUIRE(ref > wide(0x1p-1022));
        const double r = phong::detail::pow_unit(launder(c.x), launder(c.m));
        CHECK(r >= 0x1p-1022);
        CHECK(error_rel(r, ref) <= safety * bound_units(c.x, c.m) * u53);
    }
}

TEST_CASE_TEMPLATE("pow_unit: NaN and out-of-domain inputs give std::pow's value", T, float, double)
{
    constexpr T inf = std::numeric_limits<T>::infinity();
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    for (T m : {T(0.5), T(1), T(2), T(32), T(1e5), inf}) {
        CAPTURE(m);
        CHECK(std::isnan(phong::detail::pow_unit(launder(nan), launder(m))));
    }
    for (T x : {T(0), std::numeric_limits<T>::denorm_min(), T(0.25), T(0.5), std::nextafter(T(1), T(0))}) {
        CAPTURE(x);
        CHECK(std::isnan(phong::detail::pow_unit(launder(x), launder(nan))));
    }
    // IEEE's two exceptions, kept: pow(NaN, 0) = 1 and pow(1, NaN) = 1.
    CHECK(phong::detail::pow_unit(launder(nan), launder(T(0))) == T(1));
    CHECK(phong::detail::pow_unit(launder(T(1)), launder(nan)) == T(1));

    // Outside the domain: the value of std::pow (bit for bit, or both NaN); for float, of the
    // double std::pow rounded to float (the float kernel works in double).
    using bits_t = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    auto same = [](T a, T b) {
        return (std::isnan(a) && std::isnan(b)) || std::bit_cast<bits_t>(a) == std::bit_cast<bits_t>(b);
    };
    struct in { T x, m; };
    const in cases[] = {
        {T(2), T(2)}, {T(2), T(3)}, {T(-0.5), T(2)}, {T(-0.5), T(3)}, {T(0.5), T(-1)}, {T(2), T(-1)}, {T(0), T(-1)},
        {T(0.25), T(-0.5)}, {T(-0.5), T(0.5)}, {T(-2), T(3)}, {T(1.5), T(2.5)}, {T(3), T(1e5)}, {inf, T(2)},
        {-inf, T(3)}, {T(0.5), -inf}, {T(0), -inf}, {std::numeric_limits<T>::denorm_min(), T(-1)}, {T(-0.0), T(-1)},
        {nan, T(-1)}, {T(-1), nan}, {T(2), nan},
    };
    for (const in& c : cases) {
        CAPTURE(c.x);
        CAPTURE(c.m);
        const T r = phong::detail::pow_unit(launder(c.x), launder(c.m));
        const T expected = static_cast<T>(std::pow(launder(double(c.x)), launder(double(c.m))));
        CHECK(same(r, expected));
    }
    // The values themselves, from identities (so std::pow is not trusted blindly either).
    CHECK(phong::detail::pow_unit(launder(T(2)), launder(T(2))) == T(4));
    CHECK(phong::detail::pow_unit(launder(T(2)), launder(T(3))) == T(8));
    CHECK(phong::detail::pow_unit(launder(T(-0.5)), launder(T(2))) == T(0.25));
    CHECK(phong::detail::pow_unit(launder(T(-0.5)), launder(T(3))) == T(-0.125));
    CHECK(phong::detail::pow_unit(launder(T(0.5)), launder(T(-1))) == T(2));
    CHECK(phong::detail::pow_unit(launder(T(0)), launder(T(-1))) == inf);
    CHECK(std::isnan(phong::detail::pow_unit(launder(T(-0.5)), launder(T(0.5)))));
}

TEST_CASE_TEMPLATE("pow_unit_in_domain: pow_unit's bits for x in 0..1 and m >= 0, NaN outside, no libm fallback", T, float, double)
{
    // The shading loop's entry point: the same arithmetic as pow_unit inside the domain (so the
    // accuracy tests above cover it), but for results below the power floor (2^-100 float, 2^-996
    // double), which are 0, and NaN instead of std::pow's value outside it.
    using bits_t = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const T floor = std::ldexp(T(1), phong::detail::ieee::power_floor_log2<T>);
    std::mt19937_64 g(20261122);
    long compared = 0, flushed = 0;
    for (int cls = 0; cls < 3; ++cls)
        for (long i = 0; i < 20000; ++i) {
            const T x = pick_x<T>(g, cls, i), m = pick_m<T>(g, i);
            const T a = phong::detail::pow_unit_in_domain(launder(x), launder(m)), b = phong::detail::pow_unit(launder(x), launder(m));
            // Flushed: 0 where pow_unit's result is below the floor (within its rounding of y).
            if (a == T(0) && b != T(0) && b < floor * T(1.001)) {
                ++flushed;
            } else if (std::bit_cast<bits_t>(a) != std::bit_cast<bits_t>(b)) {
                CAPTURE(class_names[cls]);
                CAPTURE(hex(x));
                CAPTURE(hex(m));
                FAIL_CHECK("pow_unit_in_domain differs from pow_unit");
            }
            ++compared;
        }
    CHECK(compared == 60000);
    CHECK(flushed > 0); // the floor is met by the sweep
    // Below the floor by hand: 0.5^101 = 2^-101 in float, 0.5^997 in double; at it, kept.
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0.5)), launder(T(-phong::detail::ieee::power_floor_log2<T> + 1))) == T(0));
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0.5)), launder(T(-phong::detail::ieee::power_floor_log2<T>))) == floor);
    // Edges by hand: 0^0 = 1, 0^m = 0, 1^m = 1, x^0 = 1, and the flush below 2^-1022 (0.5^1100).
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0)), launder(T(0))) == T(1));
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0)), launder(T(3))) == T(0));
    CHECK(phong::detail::pow_unit_in_domain(launder(T(1)), launder(T(1e5))) == T(1));
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0.3)), launder(T(0))) == T(1));
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0.5)), launder(T(1100))) == T(0));
    // Outside the domain (a shininess validate() rejects, or a NaN cosine): NaN.
    constexpr T nan = std::numeric_limits<T>::quiet_NaN();
    for (T x : {T(0), T(0.5), T(1)}) {
        CAPTURE(x);
        CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(x), launder(nan))));
        if (x < T(1)) CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(x), launder(T(-1)))));
        else CHECK(phong::detail::pow_unit_in_domain(launder(x), launder(T(-1))) == T(1)); // 1^m = 1 exactly
    }
    CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(nan), launder(T(2)))));
    CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(T(-0.5)), launder(T(2)))));
    CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(T(2)), launder(T(2))))); // x > 1
    // m = +inf: the limit 0 below 1; 1^inf = inf * 0 in the exponent: NaN.
    constexpr T inf = std::numeric_limits<T>::infinity();
    CHECK(phong::detail::pow_unit_in_domain(launder(T(0.5)), launder(inf)) == T(0));
    CHECK(std::isnan(phong::detail::pow_unit_in_domain(launder(T(1)), launder(inf))));
}

TEST_CASE_TEMPLATE("pow_unit_at_most_one: pow_unit's bits for x in 0..1 and m >= 0 without the test y <= 0", T, float, double)
{
    // cosine_power's entry point skips the test y = m log2 x <= 0, which holds for every x <= 1
    // only if the kernel's log2 is never positive there: were it positive, pow_unit (which
    // tests y) and this entry point would differ. Compared on random bases, on every float of
    // the last 2^16 below 1 (the interval whose table point c is 1, where log2 x is r / ln 2
    // with r = x - 1 <= 0) and at 1 itself, for exponents from 0 to 1e5. Below the power floor
    // (2^-100 float, 2^-996 double) this entry point gives 0, as pow_unit_in_domain.
    using bits_t = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const T floor = std::ldexp(T(1), phong::detail::ieee::power_floor_log2<T>);
    std::mt19937_64 g(20261127);
    long differ = 0, compared = 0;
    const auto compare = [&](T x, T m) {
        const T a = phong::detail::pow_unit_at_most_one(launder(x), launder(m)), b = phong::detail::pow_unit(launder(x), launder(m));
        ++compared;
        if (std::bit_cast<bits_t>(a) == std::bit_cast<bits_t>(b)) return;
        if (a == T(0) && b < floor * T(1.001)) return; // flushed
        if (++differ <= 5) {
            CAPTURE(hex(x));
            CAPTURE(hex(m));
            FAIL_CHECK("pow_unit_at_most_one differs from pow_unit");
        }
    };
    for (int cls = 0; cls < 3; ++cls)
        for (long i = 0; i < 20000; ++i) compare(pick_x<T>(g, cls, i), pick_m<T>(g, i));
    T x = T(1);
    for (int i = 0; i <= (1 << 16); ++i, x = std::nextafter(x, T(0)))
        for (T m : {T(0), T(0.5), T(1), T(7), T(128), T(1e5)}) compare(x, m);
    CHECK(differ == 0);
    CHECK(compared == 60000 + 6 * ((1 << 16) + 1));
    // The edges pow_unit_in_domain has inside the domain.
    CHECK(phong::detail::pow_unit_at_most_one(launder(T(0)), launder(T(0))) == T(1));
    CHECK(phong::detail::pow_unit_at_most_one(launder(T(0)), launder(T(3))) == T(0));
    CHECK(phong::detail::pow_unit_at_most_one(launder(T(1)), launder(T(1e5))) == T(1));
    CHECK(phong::detail::pow_unit_at_most_one(launder(T(0.5)), launder(T(1100))) == T(0));
    constexpr T nan = std::numeric_limits<T>::quiet_NaN(), inf = std::numeric_limits<T>::infinity();
    CHECK(std::isnan(phong::detail::pow_unit_at_most_one(launder(T(0.5)), launder(nan))));
    CHECK(std::isnan(phong::detail::pow_unit_at_most_one(launder(nan), launder(T(2)))));
    CHECK(phong::detail::pow_unit_at_most_one(launder(T(0.5)), launder(inf)) == T(0));
    CHECK(std::isnan(phong::detail::pow_unit_at_most_one(launder(T(1)), launder(inf))));
}

// The in-domain entry point in constant evaluation: exact powers of two.
static_assert(phong::detail::pow_unit_in_domain(0.5, 2.0) == 0.25);
static_assert(phong::detail::pow_unit_in_domain(0.25f, 0.5f) == 0.5f);
static_assert(phong::detail::pow_unit_in_domain(0.0, 0.0) == 1.0);
static_assert(phong::detail::pow_unit_in_domain(0x1p-600, 2.0) == 0.0); // 2^-1200: flushed

// ---------------------------------------------------------------------------------------------
// 3. Constant evaluation.

namespace {
constexpr bool near(double a, double b, double units) // |a - b| <= units 2^-53 |b|
{
    const double d = a < b ? b - a : a - b;
    return d <= units * u53 * (b < 0 ? -b : b);
}

// Identities: powers of two are exact; x^2 = x x, x^(1/2) = sqrt.
static_assert(phong::detail::pow_unit(0.0, 0.0) == 1.0);
static_assert(phong::detail::pow_unit(0.0, 2.5) == 0.0);
static_assert(phong::detail::pow_unit(1.0, 1e6) == 1.0);
static_assert(phong::detail::pow_unit(0.3, 0.0) == 1.0);
static_assert(phong::detail::pow_unit(0.5, 2.0) == 0.25);
static_assert(phong::detail::pow_unit(0.25, 0.5) == 0.5);
static_assert(phong::detail::pow_unit(0x1p-1074, 0.5) == 0x1p-537); // subnormal base, exact
static_assert(phong::detail::pow_unit(0x1p-600, 2.0) == 0.0);       // 2^-1200: flushed
static_assert(phong::detail::pow_unit(0.5, 1023.0) == 0.0);
static_assert(near(phong::detail::pow_unit(0.3, 2.0), 0.3 * 0.3, safety * (2 * 1.74 + 2 + 4) + 1)); // + 0.3 * 0.3's rounding
static_assert(near(phong::detail::pow_unit(0.81, 0.5), 0.9, safety * (0.5 * 0.31 + 0.5 + 4) + 2)); // + 0.81's, 0.9's roundings
static_assert(phong::detail::pow_unit(0.5f, 3.0f) == 0.125f);
static_assert(phong::detail::pow_unit(0.0f, 0.0f) == 1.0f);
static_assert(phong::detail::pow_unit(1.0f, 7.5f) == 1.0f);

struct pair { double x, m; };

// splitmix64: a constexpr generator for the inputs.
constexpr std::uint64_t splitmix(std::uint64_t& s)
{
    std::uint64_t z = (s += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

constexpr double from_bits(std::uint64_t mantissa, int exponent) // 1.mantissa * 2^exponent, normal
{
    return std::bit_cast<double>((std::uint64_t(exponent + 1023) << 52) | (mantissa & ((1ull << 52) - 1)));
}

constexpr std::size_t n_constexpr = 1024;

constexpr std::array<pair, n_constexpr> constexpr_inputs = [] {
    std::array<pair, n_constexpr> a{};
    constexpr std::array<double, 12> ms = {0, 0.5, 1, 2, 32, 200, 1e3, 1e4, 1e5, 1e6, 1e-3, 7.25};
    std::uint64_t s = 42;
    std::size_t i = 0;
    // Special inputs first.
    for (pair p : {pair{0, 0}, pair{0, 3}, pair{1, 0}, pair{1, 1e6}, pair{0.5, 1021.9}, pair{0.5, 1022.1},
                   pair{0x1p-1074, 0.5}, pair{0x1p-1074, 0.9}, pair{0x0.fffffffffffffp-1022, 1}, pair{1 - 0x1p-53, 1e6},
                   pair{1 - 0x1p-53, 1e-3}, pair{0x1p-1022, 1}, pair{0x1.0000000000001p-1022, 0.999}})
        a[i++] = p;
    for (; i < n_constexpr; ++i) {
        const std::uint64_t r = splitmix(s), q = splitmix(s);
        double x = 0;
        switch (i % 5) {
        case 0: x = from_bits(r, -1 - int(q % 8)); break;             // (2^-8, 1)
        case 1: x = 1 - from_bits(r, -1 - int(q % 53)); break;         // near 1
        case 2: x = from_bits(r, -1 - int(q % 1022)); break;           // tiny normal
        case 3: x = std::bit_cast<double>(r >> (12 + q % 52)); break; // subnormal (or 0)
        default: {                                                     // near a log2-table boundary
            // z: bits of 0.6875 + i 2^45 (a boundary), moved by up to 2^41 ulp either way; x = z 2^-e.
            const std::uint64_t z = 0x3fe6000000000000ull + ((r % 128) << 45) + (q >> 22) - (1ull << 41);
            x = std::bit_cast<double>(z - (std::uint64_t(1 + (r >> 60)) << 52));
            break;
        }
        }
        const double m = (q >> 32) % 2 == 0 ? ms[(q >> 40) % ms.size()]
                                            : from_bits(q, int((q >> 52) % 30) - 10); // 2^-10 .. 2^20
        a[i] = {x, m};
    }
    return a;
}();

constexpr std::array<double, n_constexpr> constexpr_results = [] {
    std::array<double, n_constexpr> r{};
    for (std::size_t i = 0; i < n_constexpr; ++i) r[i] = phong::detail::pow_unit(constexpr_inputs[i].x, constexpr_inputs[i].m);
    return r;
}();

// The float inputs are converted once, here: both sides then use the same floats. (clang++ 14
// converts some subnormal doubles to float differently in constant evaluation, e.g.
// 0x0.000001dc1e30cp-1022 to 2^-149 instead of 0, which is no concern of pow_unit's.)
struct pair_float { float x, m; };
constexpr std::array<pair_float, n_constexpr> constexpr_inputs_float = [] {
    std::array<pair_float, n_constexpr> a{};
    for (std::size_t i = 0; i < n_constexpr; ++i)
        a[i] = {static_cast<float>(constexpr_inputs[i].x), static_cast<float>(constexpr_inputs[i].m)};
    return a;
}();

constexpr std::array<float, n_constexpr> constexpr_results_float = [] {
    std::array<float, n_constexpr> r{};
    for (std::size_t i = 0; i < n_constexpr; ++i)
        r[i] = phong::detail::pow_unit(constexpr_inputs_float[i].x, constexpr_inputs_float[i].m);
    return r;
}();
} // namespace

TEST_CASE("pow_unit: constant evaluation and run time give the same bits")
{
    long nonzero = 0;
    for (std::size_t i = 0; i < n_constexpr; ++i) {
        const double x = constexpr_inputs[i].x, m = constexpr_inputs[i].m;
        CAPTURE(i);
        INFO("x = " << hex(x) << ", m = " << hex(m) << ", constexpr " << hex(constexpr_results[i]));
        const double r = phong::detail::pow_unit(launder(x), launder(m));
        CHECK(std::bit_cast<std::uint64_t>(r) == std::bit_cast<std::uint64_t>(constexpr_results[i]));
        const pair_float f = constexpr_inputs_float[i];
        const float rf = phong::detail::pow_unit(launder(f.x), launder(f.m));
        INFO("float x = " << hex(f.x) << ", m = " << hex(f.m) << ", constexpr " << hex(constexpr_results_float[i]));
        CHECK(std::bit_cast<std::uint32_t>(rf) == std::bit_cast<std::uint32_t>(constexpr_results_float[i]));
        nonzero += r != 0 && r != 1;
        // And the values are right (equal bits alone would also pass a kernel wrong in both paths).
        const wide ref = wpow(wide(x), wide(m));
        if (x > 0 && ref >= wide(0x1p-1021)) CHECK(error_rel(r, ref) <= safety * bound_units(x, m) * u53);
    }
    MESSAGE(nonzero << " of " << n_constexpr << " constexpr results are neither 0 nor 1");
    CHECK(nonzero > long(n_constexpr) / 4);
}

// ---------------------------------------------------------------------------------------------
// 4. The tables.

TEST_CASE("pow_unit: log2 and exp2 tables against the wide reference")
{
    namespace pw = phong::detail::power;
    // The reference has its own rounding (long double with clang++: 2^-64 relative); allow it.
    const wide ref_slack = 4 * wpow(wide(2), wide(-wide_digits)); // relative
    const auto& L = pw::log2_table;
    REQUIRE(L.size() == 128);
    int holding_one = -1;
    double worst_log = 0, worst_r = 0;
    for (std::size_t i = 0; i < L.size(); ++i) {
        CAPTURE(i);
        // Interval i: the z whose bits lie in [0.6875's bits + i 2^45, + (i + 1) 2^45).
        const double lo = std::bit_cast<double>(0x3fe6000000000000ull + (std::uint64_t(i) << 45));
        const double hi = std::bit_cast<double>(0x3fe6000000000000ull + (std::uint64_t(i + 1) << 45));
        const double inv_c = L[i].inv_c, log2_c = L[i].log2_c;
        INFO("interval " << hex(lo) << " .. " << hex(hi) << ": inv_c = " << hex(inv_c) << ", log2_c = " << hex(log2_c));
        if (lo <= 1 && 1 < hi) {
            holding_one = int(i);
            CHECK(inv_c == 1.0);
            CHECK(wabs(wide(log2_c)) <= wide(1e-30));
        } else {
            const wide ref = -wlog2(wide(inv_c)); // log2 c = -log2(inv_c), for the rounded inv_c
            const wide err = wabs(wide(log2_c) - ref);
            const double in_ulp = double(err / ulp_of<double>(ref));
            worst_log = std::max(worst_log, in_ulp);
            CHECK(err <= wide(0.5) * ulp_of<double>(ref) + ref_slack * wabs(ref));
            // 1 / inv_c lies in the interval (to its rounding): the reduction r = z inv_c - 1 is small.
            const wide r_lo = wide(lo) * wide(inv_c) - 1, r_hi = wide(hi) * wide(inv_c) - 1;
            CHECK(r_lo < 0);
            CHECK(r_hi > 0);
            const double r = double(wmax(wabs(r_lo), wabs(r_hi)));
            worst_r = std::max(worst_r, r);
            CHECK(r <= 0x1p-8);
        }
    }
    CHECK(holding_one == 80); // 1.0's bits - 0.6875's bits = 80 2^45
    MESSAGE("log2 table: worst " << worst_log << " ulp; |z inv_c - 1| <= " << worst_r * 256
                                 << " 2^-8 (the interval holding 1, inv_c = 1, has r in [0, 2^-7))");

    const auto& E = pw::exp2_table;
    REQUIRE(E.size() == 64);
    double worst_exp = 0;
    for (std::uint64_t j = 0; j < E.size(); ++j) {
        CAPTURE(j);
        // Entry j holds bits(2^(j/64)) - (j << 46).
        const double v = std::bit_cast<double>(E[j] + (j << 46));
        const wide ref = wpow(wide(2), wide(double(j) / 64)); // j / 64 is exact
        const wide err = wabs(wide(v) - ref);
        worst_exp = std::max(worst_exp, double(err / ulp_of<double>(ref)));
        CHECK(err <= wide(0.5) * ulp_of<double>(ref) + ref_slack * ref);
        // The same entry scaled by 2^e through the exponent field, as the kernel uses it.
        for (int e : {-1021, -500, -1}) {
            const double scaled = std::bit_cast<double>(E[j] + ((j + std::uint64_t(64 * std::int64_t(e))) << 46));
            CHECK(scaled == std::ldexp(v, e));
        }
    }
    CHECK(E[0] == std::bit_cast<std::uint64_t>(1.0));
    MESSAGE("exp2 table: worst " << worst_exp << " ulp");
}
