// phong/core/vector.hpp: dot, dot_compensated, max_abs, rescaled, length, normalize,
// normalize_unscaled, reflect, faceforward, cross. Hand-worked values, the __float128
// reference, and the documented edges (zero in, zero out; huge and tiny vectors).
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/core/vector.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> constexpr T qnan = std::numeric_limits<T>::quiet_NaN();
template <class T> constexpr T pinf = std::numeric_limits<T>::infinity();

// Largest error of the components of a unit vector against the exact unit vector of v, in ulp
// of 1 (eps: the natural unit for a unit vector, whose length is 1).
template <class T> double unit_error_ulp(const vec3<T>& computed, const vec3<T>& v)
{
    const wvec3 u = wnormalize(widen(v));
    const wide e = wmax(wmax(wabs(wide(computed.x) - u.x), wabs(wide(computed.y) - u.y)), wabs(wide(computed.z) - u.z));
    return double(e / wide(std::numeric_limits<T>::epsilon()));
}
// The same in ulp of each component: the relative error of v_k / |v| is at most about 2.75 u
// (|v|^2: 2.5 u, halved by sqrt, + sqrt, division and product 0.5 u each), so < 3 ulp.
template <class T> double component_error_ulp(const vec3<T>& computed, const vec3<T>& v)
{
    const wvec3 u = wnormalize(widen(v));
    return std::max({error_ulp(computed.x, u.x), error_ulp(computed.y, u.y), error_ulp(computed.z, u.z)});
}
} // namespace

TEST_CASE_TEMPLATE("vector: dot and cross by hand", T, float, double)
{
    CHECK(phong::detail::dot(vec3<T>(1, 2, 3), vec3<T>(4, -5, 6)) == T(12));
    CHECK(phong::detail::dot(glm::vec<2, T>(3, 4), glm::vec<2, T>(3, 4)) == T(25));
    CHECK(phong::detail::dot(glm::vec<4, T>(1, 1, 1, 1), glm::vec<4, T>(1, 2, 3, 4)) == T(10));
    CHECK(phong::detail::cross(vec3<T>(1, 0, 0), vec3<T>(0, 1, 0)) == vec3<T>(0, 0, 1));
    CHECK(phong::detail::cross(vec3<T>(0, 1, 0), vec3<T>(1, 0, 0)) == vec3<T>(0, 0, -1));
    CHECK(phong::detail::cross(vec3<T>(1, 2, 3), vec3<T>(4, 5, 6)) == vec3<T>(-3, 6, -3));
    // Any qualifier: packed_highp as well as the default.
    const glm::vec<3, T, glm::packed_highp> a(1, 2, 3), b(4, -5, 6);
    CHECK(phong::detail::dot(a, b) == T(12));
    CHECK(phong::detail::max_abs(vec3<T>(-7, 2, 3)) == T(7));
}

TEST_CASE_TEMPLATE("vector: dot_compensated is as if computed in twice the precision", T, float, double)
{
    // a.b = (1 + e)(1 - e) - 1 = -e^2 exactly; the plain dot product rounds the first product to 1
    // and returns 0.
    constexpr T e = std::numeric_limits<T>::epsilon();
    const vec3<T> a(T(1) + e, T(1), T(0)), b(T(1) - e, T(-1), T(0));
    CHECK(phong::detail::dot(a, b) == T(0));
    CHECK(phong::detail::dot_compensated(a, b) == -e * e);
    // Random ill-conditioned sums against the wide reference: error <= eps |dot| + 9 eps^2 sum|a_k b_k|.
    // Needs a reference with twice T's precision (__float128; long double only for float).
    if constexpr (wide_digits < 2 * std::numeric_limits<T>::digits + 2) return;
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 500; ++i) {
        const vec3<T> x(T(u(rng)), T(u(rng)), T(u(rng)));
        vec3<T> y(T(u(rng)), T(u(rng)), T(0));
        y.z = T(-(double(x.x) * y.x + double(x.y) * y.y) / double(x.z)); // nearly orthogonal
        const wide exact = wdot(widen(x), widen(y));
        const wide abs_sum = wabs(wide(x.x) * wide(y.x)) + wabs(wide(x.y) * wide(y.y)) + wabs(wide(x.z) * wide(y.z));
        const wide bound = wide(e) * wabs(exact) + 9 * wide(e) * wide(e) * abs_sum;
        const wide err = wabs(wide(phong::detail::dot_compensated(x, y)) - exact);
        if (!(err <= bound)) {
            CHECK(double(err) <= double(bound));
            break;
        }
    }
}

TEST_CASE_TEMPLATE("vector: length by hand, and over the whole finite range", T, float, double)
{
    CHECK(phong::detail::length(vec3<T>(3, 4, 0)) == T(5));
    CHECK(phong::detail::length(vec3<T>(2, 3, 6)) == T(7));
    CHECK(phong::detail::length(vec3<T>(0)) == T(0));
    CHECK(phong::detail::length(glm::vec<2, T>(-5, 12)) == T(13));
    // Huge, tiny and subnormal: no overflow, no underflow, < 2 ulp.
    const T big = std::numeric_limits<T>::max() / T(4);
    const T tiny = std::numeric_limits<T>::denorm_min() * T(3);
    for (const vec3<T>& v : {vec3<T>(big, big, big), vec3<T>(tiny, tiny * T(4), T(0)), vec3<T>(T(3e-30), T(4e-30), T(0)),
                             vec3<T>(std::numeric_limits<T>::max(), T(0), T(0))}) {
        CAPTURE(v.x);
        CHECK(error_ulp(phong::detail::length(v), wlength(widen(v))) < 2.0);
    }
    // Edge: inf only when the true length exceeds the largest finite T; inf in gives inf.
    const T mx = std::numeric_limits<T>::max();
    CHECK(phong::detail::length(vec3<T>(mx, mx, T(0))) == pinf<T>);
    CHECK(phong::detail::length(vec3<T>(pinf<T>, T(1), T(1))) == pinf<T>);
}

TEST_CASE_TEMPLATE("vector: normalize", T, float, double)
{
    const vec3<T> n = phong::detail::normalize(vec3<T>(3, 4, 0));
    CHECK(error_ulp(n.x, wide(0.6)) < 2.0);
    CHECK(error_ulp(n.y, wide(0.8)) < 2.0);
    CHECK(n.z == T(0));
    CHECK(phong::detail::normalize(vec3<T>(0, 0, -5)) == vec3<T>(0, 0, -1));
    // Zero in, zero out (GLM gives NaN).
    CHECK(phong::detail::normalize(vec3<T>(0)) == vec3<T>(0));
    CHECK(phong::detail::normalize(glm::vec<4, T>(0)) == glm::vec<4, T>(0));
    // Every finite nonzero v gives a unit vector within 2 ulp per component, also huge and tiny.
    const T mx = std::numeric_limits<T>::max();
    const T dmin = std::numeric_limits<T>::denorm_min();
    for (const vec3<T>& v : {vec3<T>(mx, mx, -mx), vec3<T>(dmin, T(0), T(0)), vec3<T>(dmin, dmin, dmin),
                             vec3<T>(T(1e-40), T(2e-40), T(-3e-40)), vec3<T>(T(1e30), T(-2e30), T(5e29)),
                             vec3<T>(T(1), T(1e-6), T(1e-7))}) {
        CAPTURE(v.x);
        CHECK(unit_error_ulp(phong::detail::normalize(v), v) < 2.0);
    }
    // Random directions of random magnitude.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-1, 1), ex(-30, 30);
    double worst = 0, worst_component = 0;
    for (int i = 0; i < 1000; ++i) {
        const double s = std::pow(10.0, ex(rng));
        const vec3<T> v(T(u(rng) * s), T(u(rng) * s), T(u(rng) * s));
        if (v == vec3<T>(0)) continue;
        worst = std::max(worst, unit_error_ulp(phong::detail::normalize(v), v));
        worst_component = std::max(worst_component, component_error_ulp(phong::detail::normalize(v), v));
    }
    CHECK(worst < 2.0);
    CHECK(worst_component < 3.0);
    // NaN in, NaN out: the NaN component stays NaN.
    const vec3<T> with_nan = phong::detail::normalize(vec3<T>(qnan<T>, T(1), T(0)));
    CHECK(std::isnan(with_nan.x));
    // The other components become 0 (documented): the NaN length takes the zero branch.
    CHECK(with_nan.y == T(0));
    CHECK(with_nan.z == T(0));
}

TEST_CASE_TEMPLATE("vector: normalize_unscaled", T, float, double)
{
    const vec3<T> n = phong::detail::normalize_unscaled(vec3<T>(0, 3, 4));
    CHECK(error_ulp(n.y, wide(0.6)) < 2.0);
    CHECK(error_ulp(n.z, wide(0.8)) < 2.0);
    CHECK(phong::detail::normalize_unscaled(vec3<T>(0)) == vec3<T>(0));
    // Documented edges: |v|^2 overflowing or underflowing to 0 gives 0, never NaN.
    const T big = std::sqrt(std::numeric_limits<T>::max()) * T(4);
    const T small = std::sqrt(std::numeric_limits<T>::denorm_min()) / T(4);
    CHECK(phong::detail::normalize_unscaled(vec3<T>(big, T(0), T(0))) == vec3<T>(0));
    CHECK(phong::detail::normalize_unscaled(vec3<T>(small, small, T(0))) == vec3<T>(0));
}

TEST_CASE_TEMPLATE("vector: rescaled keeps the direction bit for bit", T, float, double)
{
    const vec3<T> v(T(3e-20), T(-5e-21), T(1e-22));
    const vec3<T> w = phong::detail::rescaled(v);
    CHECK(phong::detail::max_abs(w) >= T(1));
    CHECK(phong::detail::max_abs(w) < T(2));
    const T s = w.x / v.x; // a power of two: every component scaled by it exactly
    CHECK(w.y == v.y * s);
    CHECK(w.z == v.z * s);
    CHECK(phong::detail::rescaled(vec3<T>(0)) == vec3<T>(0));
}

TEST_CASE_TEMPLATE("vector: reflect and faceforward by hand", T, float, double)
{
    // GLSL: reflect(i, n) = i - 2 dot(n, i) n.
    CHECK(phong::reflect(vec3<T>(1, -1, 0), vec3<T>(0, 1, 0)) == vec3<T>(1, 1, 0));
    CHECK(phong::reflect(vec3<T>(0, 0, -1), vec3<T>(0, 0, 1)) == vec3<T>(0, 0, 1));
    CHECK(phong::reflect(vec3<T>(3, 5, 7), vec3<T>(1, 0, 0)) == vec3<T>(-3, 5, 7));
    // reflect(-l, n) = 2 (n.l) n - l: seed 000's r for l = (1, 0, 1)/sqrt2 is (-1, 0, 1)/sqrt2.
    const T h = T(1) / std::sqrt(T(2));
    const vec3<T> r = phong::reflect(-vec3<T>(h, 0, h), vec3<T>(0, 0, 1));
    CHECK(r.x == -h);
    CHECK(r.y == T(0));
    CHECK(r.z == h);
    // faceforward(n, i, nref) = dot(nref, i) < 0 ? n : -n.
    const vec3<T> n(0, 0, 1);
    CHECK(phong::faceforward(n, vec3<T>(0, 0, -1), n) == n);
    CHECK(phong::faceforward(n, vec3<T>(0, 0, 1), n) == -n);
    CHECK(phong::faceforward(n, vec3<T>(1, 0, 0), n) == -n); // dot = 0: not < 0
}
