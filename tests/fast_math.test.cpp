// phong/core/fast_math.hpp: each approximation within its published constant on dense sweeps, against
// long double (64-bit significand: 1e-19 relative, far below the bounds), its edges, and never
// NaN or inf in the domain; scalars and SIMD batches (the batch test binary also builds this file
// with -march=native: AVX-512 lanes).
#include <phong/batch.hpp>
#include <phong/accuracy.hpp> // the fast kernels' bounds
#include <phong/core/fast_math.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace {

using W = long double;

/// Bases: 0, the subnormals' and normals' range by powers of two, a fine grid near 1 (where
/// m log2 x is small for large m), 1 itself.
template <class T> std::vector<T> pow_bases()
{
    std::vector<T> xs{T(0), std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::min(), T(1)};
    for (int e = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits; e <= 0; ++e)
        for (int k = 0; k < 16; ++k) xs.push_back(std::ldexp(T(1) + T(k) / 16, e - 1));
    for (int i = 1; i <= 20000; ++i) xs.push_back(T(i) / 20000);                  // [0, 1] evenly
    for (int i = 1; i <= 4000; ++i) xs.push_back(T(1) - T(i) * std::numeric_limits<T>::epsilon()); // just below 1
    for (int i = 1; i <= 4000; ++i) xs.push_back(T(1) - T(1e-6) * T(i)); // the highlight of m ~ 1e5
    return xs;
}
const std::vector<double> exponents{0, 1e-3, 0.1, 0.5, 1, 2, 3.7, 10, 32, 64, 128, 200, 1e3, 1e4, 1e5, 1e7, 1e30};

struct pow_error {
    double max_rel = 0;  // where the exact value >= 2^-24
    double max_abs = 0;  // elsewhere
    bool finite = true;
};

template <class T> void record(pow_error& e, T x, T m, T got)
{
    e.finite = e.finite && std::isfinite(got) && got >= T(0);
    const W ref = (m == T(0)) ? W(1) : std::pow(W(x), W(m));
    if (ref >= W(0x1p-24)) e.max_rel = std::max(e.max_rel, double(std::fabs(W(got) - ref) / ref));
    else e.max_abs = std::max(e.max_abs, double(std::fabs(W(got) - ref)));
}

template <class T> pow_error scalar_pow_error()
{
    pow_error e;
    for (double md : exponents)
        for (T x : pow_bases<T>()) record(e, x, T(md), phong::fast::pow_unit(x, T(md)));
    return e;
}

#if PHONG_HAS_XSIMD
template <class T> pow_error batch_pow_error()
{
    using V = phong::simd_batch<T>;
    constexpr std::size_t n = V::size;
    pow_error e;
    std::vector<T> xs = pow_bases<T>();
    while (xs.size() % n) xs.push_back(T(1));
    alignas(64) T in[64], out[64];
    for (double md : exponents) {
        for (std::size_t i = 0; i < xs.size(); i += n) {
            std::memcpy(in, &xs[i], n * sizeof(T));
            phong::fast::pow_unit(V::load_unaligned(in), V(T(md))).store_unaligned(out);
            for (std::size_t k = 0; k < n; ++k) record(e, in[k], T(md), out[k]);
        }
    }
    return e;
}
#endif

} // namespace

TEST_CASE_TEMPLATE("fast::pow_unit: within pow_unit_max_rel of x^m, never NaN or inf", T, float, double)
{
    const pow_error e = scalar_pow_error<T>();
    MESSAGE("fast::pow_unit, scalar: max relative error ", e.max_rel, " where x^m >= 2^-24, max absolute ", e.max_abs, " below");
    CHECK(e.finite);
    CHECK(e.max_rel <= phong::fast::pow_unit_max_rel);
    CHECK(e.max_abs <= 0x1p-24 * phong::fast::pow_unit_max_rel);
#if PHONG_HAS_XSIMD
    const pow_error b = batch_pow_error<T>();
    MESSAGE("fast::pow_unit, ", phong::batch_width<T>, " lanes: max relative error ", b.max_rel, ", max absolute ", b.max_abs);
    CHECK(b.finite);
    CHECK(b.max_rel <= phong::fast::pow_unit_max_rel);
    CHECK(b.max_abs <= 0x1p-24 * phong::fast::pow_unit_max_rel);
#endif
}

TEST_CASE_TEMPLATE("fast::pow_unit: the edges are exact", T, float, double)
{
    using phong::fast::pow_unit;
    const T huge = std::numeric_limits<T>::max();
    for (T m : {T(0), T(1e-3), T(1), T(200), T(1e5), huge}) CHECK(pow_unit(T(1), m) == T(1)); // 1^m = 1
    for (T x : {T(0), std::numeric_limits<T>::denorm_min(), T(0.5), T(1)}) CHECK(pow_unit(x, T(0)) == T(1)); // pow(0, 0) = 1
    for (T m : {T(1e-3), T(1), T(200), huge}) CHECK(pow_unit(T(0), m) == T(0));
    CHECK(pow_unit(T(0.5), T(1)) == T(0.5)); // 2^-1: r = 0 and t = 0, no polynomial error
    CHECK(pow_unit(T(0.5), huge) == T(0));   // flushed, no NaN from huge * log2
    CHECK(pow_unit(std::numeric_limits<T>::quiet_NaN(), T(2)) == T(0)); // outside the domain: finite
    CHECK(pow_unit(std::numeric_limits<T>::quiet_NaN(), T(0)) == T(1));
    static_assert(pow_unit(T(1), T(3)) == T(1) && pow_unit(T(0), T(0)) == T(1)); // constexpr for scalars
}

/// fast::detail::pow_integer for every n in [0, 64] over pow_bases, scalars and lanes: within (n - 1) u
/// (the derivation beside pow_integer_max_rel; u = T's unit roundoff) where x^n >= T's smallest
/// normal number, and pow_integer_max_rel overall; below, within 2^-126 absolute (float; double's
/// smallest normal in double).
TEST_CASE_TEMPLATE("fast::detail::pow_integer: within (n - 1) u of x^n for n in [0, 64], edges exact", T, float, double)
{
    using phong::fast::detail::pow_integer;
    const W u = W(std::numeric_limits<T>::epsilon()) / 2;
    const W tiny = W(std::numeric_limits<T>::min());
    const std::vector<T> xs = pow_bases<T>();
    double worst = 0, worst_abs = 0;
    bool within_each = true, finite = true;
    for (unsigned n = 0; n <= phong::fast::detail::pow_integer_max_exponent; ++n) {
        const W allowed = n == 0 ? W(0) : W(n - 1) * u * W(1.0001); // second-order terms: (n u)^2
        for (T x : xs) {
            const T got = pow_integer(x, n);
            finite = finite && std::isfinite(got) && got >= T(0);
            const W ref = n == 0 ? W(1) : std::pow(W(x), W(n));
            if (ref >= tiny) {
                const W rel = std::fabs(W(got) - ref) / ref;
                worst = std::max(worst, double(rel));
                within_each = within_each && rel <= allowed;
            } else {
                worst_abs = std::max(worst_abs, double(std::fabs(W(got) - ref)));
            }
        }
    }
    MESSAGE("fast::detail::pow_integer, scalar: max relative error ", worst, " (bound ", phong::fast::detail::pow_integer_max_rel<T>, "), max absolute ", worst_abs, " below the smallest normal");
    CHECK(finite);
    CHECK(within_each);
    CHECK(worst <= phong::fast::detail::pow_integer_max_rel<T>);
    CHECK(phong::fast::detail::pow_integer_max_rel<T> <= phong::fast::pow_unit_max_rel);
    CHECK(worst_abs <= double(tiny));
    CHECK(pow_integer(T(0), 0u) == T(1)); // pow(0, 0) = 1
    CHECK(pow_integer(T(0), 1u) == T(0));
    CHECK(pow_integer(T(0), 64u) == T(0));
    CHECK(pow_integer(T(1), 64u) == T(1));
    CHECK(pow_integer(T(0.5), 10u) == T(1) / T(1024)); // powers of two are exact
    CHECK(pow_integer(T(0.75), 3u) == T(0.421875));    // 27/64: exact in T
    static_assert(pow_integer(T(0.5), 2u) == T(0.25)); // constexpr for scalars
#if PHONG_HAS_XSIMD
    using V = phong::simd_batch<T>;
    constexpr std::size_t lanes = V::size;
    alignas(64) T in[64], out[64];
    bool same = true; // lanes: the same multiplications, so the scalar's bits
    for (unsigned n : {0u, 1u, 2u, 7u, 32u, 63u, 64u}) {
        for (std::size_t i = 0; i + lanes <= xs.size(); i += lanes) {
            std::memcpy(in, &xs[i], lanes * sizeof(T));
            pow_integer(V::load_unaligned(in), n).store_unaligned(out);
            for (std::size_t k = 0; k < lanes; ++k) same = same && out[k] == pow_integer(in[k], n);
        }
    }
    CHECK(same);
#endif
}

TEST_CASE("fast::rsqrt: within rsqrt_max_rel over every float from 1 to 4, edges")
{
    double worst = 0;
    for (float x = 1.0f; x < 4.0f; x = std::nextafter(x, 5.0f)) {
        const W ref = 1 / std::sqrt(W(x));
        worst = std::max(worst, double(std::fabs(W(phong::fast::rsqrt(x)) - ref) / ref));
    }
    MESSAGE("fast::rsqrt, float scalar: max relative error ", worst, " (every float from 1 to 4: the error repeats every two binades)");
    CHECK(worst <= phong::fast::rsqrt_max_rel<float>);
    for (float x : {std::numeric_limits<float>::min(), 1e-30f, 3e7f, std::numeric_limits<float>::max()}) {
        const W ref = 1 / std::sqrt(W(x));
        CHECK(double(std::fabs(W(phong::fast::rsqrt(x)) - ref) / ref) <= phong::fast::rsqrt_max_rel<float>);
    }
    double worst_double = 0; // double scalars: the exact 1/sqrt
    for (int i = 0; i < 100000; ++i) {
        const double x = 1 + 3 * double(i) / 100000;
        const W ref = 1 / std::sqrt(W(x));
        worst_double = std::max(worst_double, double(std::fabs(W(phong::fast::rsqrt(x)) - ref) / ref));
    }
    CHECK(worst_double <= phong::fast::rsqrt_max_rel<double>);
    CHECK(phong::fast::rsqrt(0.0f) == std::numeric_limits<float>::infinity());
    CHECK(phong::fast::rsqrt(std::numeric_limits<float>::infinity()) == 0.0f);
}

#if PHONG_HAS_XSIMD
TEST_CASE_TEMPLATE("fast::rsqrt on SIMD lanes: within rsqrt_max_rel, edges", T, float, double)
{
    using V = phong::simd_batch<T>;
    constexpr std::size_t n = V::size;
    alignas(64) T in[64], out[64];
    double worst = 0;
    const int steps = 1 << 20;
    for (int i = 0; i < steps; i += int(n)) {
        for (std::size_t k = 0; k < n; ++k) in[k] = T(1) + T(3) * T(i + int(k)) / T(steps); // [1, 4)
        phong::fast::rsqrt(V::load_unaligned(in)).store_unaligned(out);
        for (std::size_t k = 0; k < n; ++k) {
            const W ref = 1 / std::sqrt(W(in[k]));
            worst = std::max(worst, double(std::fabs(W(out[k]) - ref) / ref));
        }
    }
    MESSAGE("fast::rsqrt, ", n, " lanes: max relative error ", worst);
    CHECK(worst <= phong::fast::rsqrt_max_rel<T>);
    phong::fast::rsqrt(V(T(0))).store_unaligned(out);
    CHECK(out[0] == std::numeric_limits<T>::infinity());
    phong::fast::rsqrt(V(std::numeric_limits<T>::infinity())).store_unaligned(out);
    CHECK(out[0] == T(0));
}
#endif

/// fast::detail::reciprocal_normal over [1, 2) densely (the estimate's error repeats every binade), and at
/// the ends of the normal range: within reciprocal_max_rel of 1/x (long double), scalars (1/x
/// itself) and SIMD lanes (AVX-512 rcp14, AVX2 rcp + one Newton step; the derivation beside the
/// constant gives 1.06 u and 3.3 u).
TEST_CASE_TEMPLATE("fast::detail::reciprocal_normal: within reciprocal_max_rel of 1/x, scalars and lanes", T, float, double)
{
    const T ends[] = {std::numeric_limits<T>::min(), T(1e-30), T(3e7), std::numeric_limits<T>::max() / T(4)};
    double worst = 0;
    for (int i = 0; i < (1 << 16); ++i) {
        const T x = T(1) + T(i) / T(1 << 16);
        worst = std::max(worst, double(std::fabs(W(phong::fast::detail::reciprocal_normal(x)) * W(x) - 1)));
    }
    for (T x : ends) worst = std::max(worst, double(std::fabs(W(phong::fast::detail::reciprocal_normal(x)) * W(x) - 1)));
    static_assert(phong::fast::detail::reciprocal_normal(4.0f) == 0.25f && phong::fast::detail::reciprocal_normal(0.5) == 2.0); // constexpr for scalars
    MESSAGE("fast::detail::reciprocal_normal, scalar: max relative error ", worst);
    CHECK(worst <= phong::fast::detail::reciprocal_max_rel<T>);
#if PHONG_HAS_XSIMD
    using V = phong::simd_batch<T>;
    constexpr std::size_t n = V::size;
    alignas(64) T in[64], out[64];
    double worst_lanes = 0;
    const int steps = 1 << 20;
    for (int i = 0; i < steps; i += int(n)) {
        for (std::size_t k = 0; k < n; ++k) in[k] = T(1) + T(i + int(k)) / T(steps); // [1, 2)
        if (i == 0) for (std::size_t k = 0; k < 4 && k < n; ++k) in[k] = ends[k];
        phong::fast::detail::reciprocal_normal(V::load_unaligned(in)).store_unaligned(out);
        for (std::size_t k = 0; k < n; ++k) worst_lanes = std::max(worst_lanes, double(std::fabs(W(out[k]) * W(in[k]) - 1)));
    }
    MESSAGE("fast::detail::reciprocal_normal, ", n, " lanes: max relative error ", worst_lanes);
    CHECK(worst_lanes <= phong::fast::detail::reciprocal_max_rel<T>);
#endif
}

/// plan_pow_integer: the schedule written out by hand for a few n (n = 2^k: a chain of k
/// squarings; 45 = 101101b: 5 squarings, multiplications after the 2nd, 4th and 5th, the bits
/// 01101 below the top one), and pow_integer(x, plan) the same bits as pow_integer(x, n).
TEST_CASE("fast::detail::plan_pow_integer: the schedule of n's bits")
{
    using phong::fast::detail::plan_pow_integer;
    CHECK(plan_pow_integer(0).chain == 0u);
    CHECK(plan_pow_integer(1).chain == 1u);
    CHECK(plan_pow_integer(1).squarings == 0u);
    CHECK(plan_pow_integer(32).chain == 6u);
    CHECK(plan_pow_integer(32).squarings == 5u);
    CHECK(plan_pow_integer(32).multiplies == 0u);
    CHECK(plan_pow_integer(64).chain == 7u);
    CHECK(plan_pow_integer(45).chain == 8u);
    CHECK(plan_pow_integer(45).squarings == 5u);
    CHECK(plan_pow_integer(45).multiplies == 13u);
    CHECK(plan_pow_integer(3).multiplies == 1u);
    CHECK(phong::fast::detail::pow_integer(0.5f, plan_pow_integer(45)) == std::ldexp(1.0f, -45)); // powers of two: exact
    CHECK(phong::fast::detail::pow_integer(3.0f, plan_pow_integer(5)) == 243.0f); // 3^5, exact in float
    static_assert(plan_pow_integer(16).chain == 5u && phong::fast::detail::pow_integer(2.0, plan_pow_integer(10)) == 1024.0); // constexpr
}
