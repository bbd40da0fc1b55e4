// The float SIMD power of shade_batch's exact mode (include/phong/ext/simd/lanes_power.hpp, through
// phong::detail::math_traits<simd_batch<float>>::pow_unit) against pow in the wide reference type (support/wide.hpp:
// __float128 with g++, long double with clang++), on inputs its derivation did not pick: seeded
// log-uniform bases over the whole normal range, bases within a few ulp of 1, subnormal bases,
// exponents from 0 to 1e30. Checks the documented bound (detail::lanes::pow_unit_lanes_error) where
// the exact result is at least the power floor 2^-100 (detail::ieee::power_floor_log2<float>; 0.1 %
// above it, for the rounding of y), 2^-100 absolute below (flushed to 0), and the edges by identity.
// Compiled twice: in phong_tests (baseline ISA: the exponent-field path) and in
// phong_batch_native_tests (AVX-512 here: the scalef path).
#include "support/wide.hpp"

#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#if PHONG_HAS_XSIMD
namespace {

using V = phong::simd_batch<float>;
constexpr std::size_t W = phong::batch_width<float>;
/// The power floor: results below it are 0 (detail::ieee::power_floor_log2).
const double power_floor = std::ldexp(1.0, phong::detail::ieee::power_floor_log2<float>);

/// kernel(x, m) on lanes all holding x and m, one lane read back.
template <class Kernel> float on_lanes(Kernel kernel, float x, float m)
{
    alignas(64) float out[W];
    kernel(V(x), V(m)).store_aligned(out);
    return out[W / 2];
}

/// pow_unit on one lane value (the others: copies), read back.
float lanes_pow(float x, float m)
{
    return on_lanes([](const V& a, const V& b) { return phong::detail::math_traits<V>::pow_unit(a, b); }, x, m);
}

struct worst_case {
    double ratio = 0; // measured error / bound
    float x = 0, m = 0;
};

/// Checks x^m against the wide reference; returns the error in units of the bound.
double check(float x, float m)
{
    const float got = lanes_pow(x, m);
    REQUIRE(std::isfinite(got));
    const phong_test::wide exact = phong_test::wpow(phong_test::wide(x), phong_test::wide(m));
    const double ref = static_cast<double>(exact);
    if (ref >= power_floor * 1.001) {
        const double y = double(m) * std::log2(double(x)); // exact y to double precision
        const double bound = phong::detail::lanes::pow_unit_lanes_error(y);
        const double rel = std::abs(double(got) - ref) / ref;
        if (!(rel <= bound)) MESSAGE("x = " << x << ", m = " << m << ": relative error " << rel << " > bound " << bound);
        CHECK(rel <= bound);
        return rel / bound;
    }
    const double abs_err = std::abs(double(got) - ref);
    CHECK(abs_err <= power_floor * 1.001);
    if (ref < power_floor * 0.999) CHECK(got == 0.0f); // flushed: no subnormal result, nor one from a product
    return 0;
}

} // namespace

TEST_CASE("shade_batch's float power: within its documented bound on seeded bases and exponents")
{
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> unit(0, 1);
    const float exponents[] = {0.25f, 0.5f, 1, 2, 3.7f, 8, 32, 100, 128, 200, 1000, 1e5f};
    worst_case worst;
    int checked = 0;
    for (float m : exponents) {
        for (int i = 0; i < 4000; ++i) {
            // log-uniform over [2^-126, 1]: every binade, the bit-splitting at every exponent
            const float x = static_cast<float>(std::exp2(-126.0 * unit(rng)));
            const double r = check(x, m);
            if (r > worst.ratio) worst = {r, x, m};
            ++checked;
        }
        for (int k = 0; k < 300; ++k) { // just below 1: t near 0, e = 0 (the highlight's peak)
            const float x = std::nextafter(1.0f, 0.0f) - float(k) * 0x1p-24f;
            const double r = check(x, m);
            if (r > worst.ratio) worst = {r, x, m};
            ++checked;
        }
        for (float x : {0.70710677f, 0.70710683f, 0.5f, 0.25f, 0x1p-10f, 1.4142135f / 2}) { // split boundaries
            const double r = check(x, m);
            if (r > worst.ratio) worst = {r, x, m};
            ++checked;
        }
    }
    // Random exponents in [0, 200] (validate's typical range) on random bases.
    for (int i = 0; i < 20000; ++i) {
        const float m = static_cast<float>(200 * unit(rng));
        const float x = static_cast<float>(unit(rng));
        if (x == 0) continue;
        const double r = check(x, m);
        if (r > worst.ratio) worst = {r, x, m};
        ++checked;
    }
    MESSAGE(checked << " inputs; worst error / bound = " << worst.ratio << " at x = " << worst.x << ", m = " << worst.m);
    CHECK(worst.ratio > 0.05); // the bound is not vacuous by orders of magnitude
}

/// (1 - x)^m through phong::detail::math_traits<V>::pow_one_minus (the stable mode's power), one lane value.
float lanes_pow_one_minus(float x, float m)
{
    return on_lanes([](const V& a, const V& b) { return phong::detail::math_traits<V>::pow_one_minus(a, b); }, x, m);
}

/// Checks (1 - x)^m against the wide reference on the exact 1 - x; returns error / bound.
double check_one_minus(float x, float m)
{
    const float got = lanes_pow_one_minus(x, m);
    REQUIRE(std::isfinite(got));
    const phong_test::wide base = phong_test::wide(1) - phong_test::wide(x);
    const double ref = static_cast<double>(phong_test::wpow(base, phong_test::wide(m)));
    if (ref >= power_floor * 1.001) {
        const double y = double(m) * std::log2(static_cast<double>(base));
        const double bound = phong::detail::lanes::pow_one_minus_lanes_error(y);
        const double rel = std::abs(double(got) - ref) / ref;
        if (!(rel <= bound)) MESSAGE("x = " << x << ", m = " << m << ": relative error " << rel << " > bound " << bound);
        CHECK(rel <= bound);
        return rel / bound;
    }
    CHECK(std::abs(double(got) - ref) <= power_floor * 1.001);
    if (ref < power_floor * 0.999) CHECK(got == 0.0f);
    return 0;
}

TEST_CASE("shade_batch's float (1 - x)^m: within its documented bound, tiny x keeps its relative accuracy")
{
    std::mt19937_64 rng(20261125);
    std::uniform_real_distribution<double> unit(0, 1);
    worst_case worst;
    int checked = 0;
    for (float m : {0.5f, 1.0f, 7.0f, 32.0f, 200.0f, 1e4f, 1e6f, 1e9f}) {
        for (int i = 0; i < 4000; ++i) {
            // x log-uniform over [2^-60, 1): highlights (x ~ 1 - cos) down to far below u
            const float x = static_cast<float>(std::exp2(-60.0 * unit(rng)));
            if (!(x < 1)) continue;
            const double r = check_one_minus(x, m);
            if (r > worst.ratio) worst = {r, x, m};
            ++checked;
        }
        for (float x : {0.29289323f, 0.29289320f, 0.5f, 0.75f, std::nextafter(1.0f, 0.0f)}) { // branch and split edges
            const double r = check_one_minus(x, m);
            if (r > worst.ratio) worst = {r, x, m};
            ++checked;
        }
    }
    MESSAGE(checked << " inputs; worst error / bound = " << worst.ratio << " at x = " << worst.x << ", m = " << worst.m);
    CHECK(worst.ratio > 0.02);
    // Edges: x = 0 gives 1, x >= 1 gives 0 (m > 0) or 1 (m = 0).
    CHECK(lanes_pow_one_minus(0.0f, 1e30f) == 1.0f);
    CHECK(lanes_pow_one_minus(1.0f, 3.0f) == 0.0f);
    CHECK(lanes_pow_one_minus(1.5f, 3.0f) == 0.0f);
    CHECK(lanes_pow_one_minus(1.0f, 0.0f) == 1.0f);
    CHECK(lanes_pow_one_minus(0x1p-30f, 1.0f) == 1.0f);              // 1 - 2^-30 rounds to 1 in float
    CHECK(lanes_pow_one_minus(0x1p-20f, 1e6f) < 0.4f);                // (1 - 2^-20)^1e6 = 0.385: x's bits kept
}

TEST_CASE("shade_batch's float power: edges")
{
    const float tiny = std::numeric_limits<float>::denorm_min();
    for (float m : {0.0f, 0.5f, 1.0f, 32.0f, 1e30f, std::numeric_limits<float>::max()}) {
        CHECK(lanes_pow(1.0f, m) == 1.0f); // 1^m = 1 exactly
        if (m > 0) {
            CHECK(lanes_pow(0.0f, m) == 0.0f); // 0^m = 0 (also for m < 1, where 2^(-126 m) is not 0)
        } else {
            CHECK(lanes_pow(0.0f, m) == 1.0f); // pow(0, 0) = 1
            CHECK(lanes_pow(tiny, m) == 1.0f);
            CHECK(lanes_pow(0.3f, m) == 1.0f);
        }
    }
    // Below the domain: x <= 0 and NaN are powered like 0 (shade_batch passes an unclamped-below cosine).
    for (float x : {-0.0f, -tiny, -0.5f, -1.0f, -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
        CAPTURE(x);
        CHECK(lanes_pow(x, 32.0f) == 0.0f);
        CHECK(lanes_pow(x, 0.5f) == 0.0f);
        CHECK(lanes_pow(x, 0.0f) == 1.0f);
    }
    CHECK(lanes_pow(0.5f, 1.0f) == 0.5f); // powers of two: y integral, r = 0, 2^k exact
    CHECK(lanes_pow(0.25f, 2.0f) == 0.0625f);
    CHECK(lanes_pow(0.5f, 149.0f) == 0.0f); // below the power floor 2^-100: 0
    CHECK(lanes_pow(0.5f, 101.0f) == 0.0f);
    CHECK(lanes_pow(0.5f, 100.0f) == 0x1p-100f); // at it: kept, exactly
    // Subnormal bases are taken as 2^-126: the result lies between the exact power and 2^(-126 m)
    // (2^-63 for m = 1/2, where the exact sqrt(2^-149) is 2^-74.5).
    const float half = lanes_pow(tiny, 0.5f);
    CHECK(half >= float(std::sqrt(double(tiny))));
    CHECK(half <= 0x1p-63f * (1 + 1e-6f));
    CHECK(lanes_pow(tiny, 2.0f) == 0.0f); // 2^-252: below the floor
    // Huge exponents on bases just below 1 underflow to (almost) 0, never NaN or inf.
    const float r = lanes_pow(std::nextafter(1.0f, 0.0f), 1e30f);
    CHECK(std::isfinite(r));
    CHECK(r == 0.0f);
}

// pow_unit_positive (shade_batch's exact float lanes with exact::step_specular): pow_unit without
// its select, m bounded by 2^100 (no clamp of m log2 x under AVX-512). Where pow_unit keeps its
// power (x > 0, or m = 0) the two agree bit for bit, seeded bases over (0, 1] and exponents up to
// 2^100 included; with m = 0 every base gives 1; below the domain the result is finite (the caller
// selects it away).
TEST_CASE("shade_batch's float power without its select: the same bits where the power is kept")
{
    const auto positive = [](float x, float m) {
        return on_lanes([](const V& a, const V& b) { return phong::detail::math_traits<V>::pow_unit_positive(a, b); }, x, m);
    };
    std::mt19937 rng(20261124);
    std::uniform_real_distribution<float> exponent(-40.0f, 0.0f);
    for (float m : {0.0f, 0.5f, 1.0f, 32.0f, 1e4f, 3e7f, 0x1p100f}) {
        CAPTURE(m);
        for (int i = 0; i < 2000; ++i) {
            const float x = std::exp2(exponent(rng));
            CAPTURE(x);
            CHECK(positive(x, m) == lanes_pow(x, m));
        }
        for (float x : {1.0f, std::nextafter(1.0f, 0.0f), std::numeric_limits<float>::min(), std::numeric_limits<float>::denorm_min()})
            CHECK(positive(x, m) == lanes_pow(x, m));
    }
    for (float x : {0.0f, -0.5f, -std::numeric_limits<float>::infinity()}) {
        CAPTURE(x);
        CHECK(positive(x, 0.0f) == 1.0f);
        CHECK(std::isfinite(positive(x, 32.0f)));
        CHECK(std::isfinite(positive(x, 0x1p100f)));
    }
}

#if PHONG_STABLE_LANES
TEST_CASE("stable_lanes: float lanes widened to double and back exactly; the double 1/sqrt within 3 ulp over the float-derived range")
{
    namespace sl = phong::detail::stable_lanes;
    using D = sl::double_t<V>;
    constexpr std::size_t H = W / 2;
    // widen/join: lane k of the float batch is lane k % H of part k / H (lower, upper), exactly
    // (floats are doubles); join rounds each lane once (exact here: the values came from floats).
    alignas(64) float in[W], back[W];
    for (std::size_t k = 0; k < W; ++k) in[k] = std::ldexp(1.0f + float(k) / 64, int(k) * 9 - 70); // 2^-70 .. 2^65
    in[1] = std::numeric_limits<float>::denorm_min();
    const sl::lane_parts<V> h = sl::widen(V::load_aligned(in));
    alignas(64) double lo[H], hi[H];
    h.lower.store_aligned(lo);
    h.upper.store_aligned(hi);
    for (std::size_t k = 0; k < H; ++k) {
        CHECK(lo[k] == double(in[k]));
        CHECK(hi[k] == double(in[H + k]));
    }
    sl::join<V>(h.lower, h.upper).store_aligned(back);
    for (std::size_t k = 0; k < W; ++k) CHECK(back[k] == in[k]);

    // 1/sqrt(x) against the wide type's, log-uniform over [2^-298, 2^257] (the squares of float
    // differences) and at its ends; the documented bound is 3 u of double.
    std::mt19937_64 rng(20261124);
    double worst = 0;
    for (int i = 0; i < 20000; ++i) {
        const double e = std::uniform_real_distribution<double>(-298, 257)(rng);
        const double x = i == 0 ? 0x1p-298 : i == 1 ? 0x1.fffffffffffffp256 : std::exp2(e);
        alignas(64) double y[H];
        sl::rsqrt_normal(D(x)).store_aligned(y);
        const phong_test::wide exact = phong_test::wide(1) / phong_test::wsqrt(phong_test::wide(x));
        worst = std::max(worst, double(phong_test::wabs(phong_test::wide(y[0]) - exact) / exact) / 0x1p-53);
    }
    MESSAGE("stable_lanes rsqrt_normal (double): worst " << worst << " u");
    CHECK(worst <= 3.0);
}
#endif

#if defined(__aarch64__)
namespace {
/// x << n and x >> n of every count on NEON lanes of T against the scalar shifts (arithmetic right
/// shift for signed T, as C++20's), through ext/simd/backend.hpp's neon64 overloads.
template <class T> int shift_mismatches()
{
    using B = xsimd::batch<T, phong::simd_arch>;
    alignas(16) T in[B::size], out[B::size];
    int bad = 0;
    for (int n = 0; n < int(sizeof(T) * 8); ++n) {
        for (std::size_t i = 0; i < B::size; ++i) in[i] = T(T(0x9b3f7a15c3e1d2f7ull >> (i * 7)) * T(i % 2 ? -1 : 1));
        const B x = B::load_aligned(in);
        (x << n).store_aligned(out);
        for (std::size_t i = 0; i < B::size; ++i) bad += out[i] != T(in[i] << n);
        (x >> n).store_aligned(out);
        for (std::size_t i = 0; i < B::size; ++i) bad += out[i] != T(in[i] >> n);
    }
    return bad;
}
/// bitwise_cast from F lanes to I lanes and back: the bits of each lane, unchanged.
template <class F, class I> int cast_mismatches()
{
    using BF = xsimd::batch<F, phong::simd_arch>;
    using BI = xsimd::batch<I, phong::simd_arch>;
    alignas(16) F f[BF::size], back[BF::size];
    alignas(16) I bits[BF::size];
    for (std::size_t i = 0; i < BF::size; ++i) f[i] = F(-1.5) * F(i + 1) / F(3);
    xsimd::bitwise_cast<BI>(BF::load_aligned(f)).store_aligned(bits);
    xsimd::bitwise_cast<BF>(BI::load_aligned(bits)).store_aligned(back);
    int bad = 0;
    for (std::size_t i = 0; i < BF::size; ++i) {
        I expected;
        std::memcpy(&expected, &f[i], sizeof expected);
        bad += bits[i] != expected;
        bad += std::memcmp(&back[i], &f[i], sizeof(F)) != 0;
    }
    return bad;
}
} // namespace

TEST_CASE("NEON: the lanes' bit casts and shifts by a count (phong's neon64 overloads of xsimd's)")
{
    CHECK(shift_mismatches<std::int32_t>() == 0);
    CHECK(shift_mismatches<std::uint32_t>() == 0);
    CHECK(shift_mismatches<std::int64_t>() == 0);
    CHECK(shift_mismatches<std::uint64_t>() == 0);
    CHECK(cast_mismatches<float, std::int32_t>() == 0);
    CHECK(cast_mismatches<float, std::uint32_t>() == 0);
    CHECK(cast_mismatches<double, std::int64_t>() == 0);
    CHECK(cast_mismatches<double, std::uint64_t>() == 0);
}
#endif
#endif
