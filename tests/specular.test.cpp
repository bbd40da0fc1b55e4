// phong/terms/specular.hpp: the reflection-based and halfway-based factors, exact and stable, and
// pow_one_minus. Hand-worked values, the documented edges (gate, m = 0, l = 0, v = 0, l = -v),
// and random unit vectors against the __float128 evaluation of the same formula.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/terms/specular.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;

// The four factors, so that each check runs on all of them.
template <class T> struct factor {
    const char* name;
    bool halfway;
    T (*f)(const vec3<T>&, const vec3<T>&, const vec3<T>&, T);
};
template <class T> const factor<T> factors[] = {
    {"specular_reflection", false, &phong::specular_reflection<T, glm::defaultp>},
    {"specular_reflection_stable", false, &phong::detail::specular_reflection_stable<T, glm::defaultp>},
    {"specular_halfway", true, &phong::specular_halfway<T, glm::defaultp>},
    {"specular_halfway_stable", true, &phong::detail::specular_halfway_stable<T, glm::defaultp>},
};

// The factor in the wide type, from the formulas in the doc comments applied to the given vectors.
template <class T> wide reference_factor(bool halfway, const vec3<T>& n, const vec3<T>& l, const vec3<T>& v, T m)
{
    const wvec3 N = widen(n), Lw = widen(l), V = widen(v);
    const wide nl = wdot(N, Lw);
    if (!(nl > 0)) return 0;
    wide base;
    if (halfway) base = wclamp(wdot(N, wnormalize(Lw + V)), 0, 1);
    else base = wclamp(wdot(N * (2 * nl) - Lw, V), 0, 1);
    if (m == 0) return 1;
    return base == 0 ? wide(0) : wpow(base, wide(m));
}
} // namespace

TEST_CASE_TEMPLATE("specular: 45 degree light by hand", T, float, double)
{
    // n = (0, 0, 1), l = (1, 0, 1)/sqrt2, v = (0, 0, 1):
    // Phong: r = 2 (n.l) n - l = (-1, 0, 1)/sqrt2, r.v = 1/sqrt2, (r.v)^2 = 1/2, (r.v)^3 = 1/(2 sqrt2).
    // Blinn: n.h = cos 22.5 deg, (n.h)^2 = (1 + cos 45)/2 = (2 + sqrt2)/4.
    const T h = T(1) / std::sqrt(T(2));
    const vec3<T> n(0, 0, 1), l(h, 0, h), v(0, 0, 1);
    const double tol = 8; // ulp: a handful of roundings (l itself is rounded)
    for (const factor<T>& fn : factors<T>) {
        CAPTURE(fn.name);
        if (fn.halfway) {
            CHECK(error_ulp(fn.f(n, l, v, T(2)), (2 + wsqrt(wide(2))) / 4) <= tol);
        } else {
            CHECK(error_ulp(fn.f(n, l, v, T(2)), wide(0.5)) <= tol);
            CHECK(error_ulp(fn.f(n, l, v, T(3)), 1 / (2 * wsqrt(wide(2)))) <= tol);
        }
        // At the highlight (r = v, or h = n): 1 for every m.
        CHECK(fn.f(n, n, n, T(200)) == T(1));
    }
}

TEST_CASE_TEMPLATE("specular: documented edges", T, float, double)
{
    const T h = T(1) / std::sqrt(T(2));
    const vec3<T> n(0, 0, 1), l(h, 0, h), v(0, 0, 1);
    for (const factor<T>& fn : factors<T>) {
        CAPTURE(fn.name);
        // The gate: 0 when n.l <= 0, even where the base would be 1 (v along r or h).
        const vec3<T> below(h, 0, -h);
        CHECK(fn.f(n, below, -n, T(4)) == T(0));
        CHECK(fn.f(n, below, phong::reflect(-below, n), T(4)) == T(0));
        CHECK(fn.f(n, vec3<T>(1, 0, 0), v, T(4)) == T(0)); // n.l = 0 exactly
        // m = 0: 1 wherever lit (pow(0, 0) = 1), also where the base is 0.
        CHECK(fn.f(n, l, v, T(0)) == T(1));
        CHECK(fn.f(n, l, vec3<T>(h, 0, -h), T(0)) == T(1)); // r.v = 0, n.h = 0
        // l = 0: n.l = 0, so 0.
        CHECK(fn.f(n, vec3<T>(0), v, T(4)) == T(0));
        CHECK(fn.f(n, vec3<T>(0), v, T(0)) == T(0));
        if (fn.halfway) {
            // l = -v: no halfway vector; n.h taken as 0: 0 for m > 0, 1 for m = 0, never NaN.
            CHECK(fn.f(n, l, -l, T(4)) == T(0));
            CHECK(fn.f(n, l, -l, T(0)) == T(1));
        } else {
            // v = 0: 0 for m > 0 (documented), 1 for m = 0 (lit, pow(0, 0) = 1).
            CHECK(fn.f(n, l, vec3<T>(0), T(4)) == T(0));
            CHECK(fn.f(n, l, vec3<T>(0), T(0)) == T(1));
        }
        // Base clamped to [0, 1]: a v on the far side gives 0, not a negative base to a power.
        CHECK(fn.f(n, l, vec3<T>(h, 0, -h) * T(-1), T(3)) >= T(0));
        CHECK(fn.f(n, l, -v, T(3)) == T(0));
    }
}

TEST_CASE_TEMPLATE("specular: pow_one_minus", T, float, double)
{
    CHECK(phong::detail::pow_one_minus(T(0), T(50)) == T(1));
    CHECK(phong::detail::pow_one_minus(T(0), T(0)) == T(1));
    CHECK(phong::detail::pow_one_minus(T(1), T(3)) == T(0));
    CHECK(phong::detail::pow_one_minus(T(1), T(0)) == T(1)); // pow(0, 0) = 1
    CHECK(phong::detail::pow_one_minus(T(7), T(2)) == T(0)); // x >= 1 gives 0
    CHECK(phong::detail::pow_one_minus(T(7), T(0)) == T(1));
    CHECK(error_ulp(phong::detail::pow_one_minus(T(0.5), T(3)), wide(0.125)) <= 4.0);
    // Random x, m against the wide (1 - x)^m: the relative error of exp(m log1p(-x)) is at most
    // about (|m log1p(-x)| + 1) u for the logarithm's and the exponential's roundings. Below the
    // power floor (2^-100 float, 2^-996 double; 0.1 % either side for the rounding) the result is 0.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(0, 1);
    const wide floor = wide(std::ldexp(1.0, phong::detail::ieee::power_floor_log2<T>));
    double worst = 0;
    long flushed = 0;
    for (int i = 0; i < 2000; ++i) {
        const T x = T(std::pow(u(rng), 3)), m = T(u(rng) * 1000);
        const wide exact = wpow(1 - wide(x), wide(m));
        if (exact < floor * wide(0.999)) {
            CHECK(phong::detail::pow_one_minus(x, m) == T(0));
            ++flushed;
        }
        if (exact < floor * wide(1.001)) continue;
        const double bound = (std::abs(double(m) * std::log1p(-double(x))) + 2) * double(tolerance<T>::eps);
        worst = std::max(worst, error_rel(phong::detail::pow_one_minus(x, m), exact) / bound);
    }
    CHECK(worst <= 1.0);
    CHECK(flushed > 0); // the floor is met
    CHECK(phong::detail::pow_one_minus(T(0.5), T(-phong::detail::ieee::power_floor_log2<T> + 1)) == T(0)); // 2^-101 (2^-997)
}

TEST_CASE_TEMPLATE("specular: random unit vectors against the wide formula", T, float, double)
{
    // The absolute error of base^m is at most m (error of the base) + its own rounding; the base
    // (a dot product of rounded unit vectors, or of the halfway vector) carries a few eps.
    // Stable and exact evaluate the same factor, so both meet the same bound here.
    scene_gen<T> g(17);
    double worst = 0;
    for (int i = 0; i < 3000; ++i) {
        const vec3<T> n = g.direction(), l = g.direction(), v = g.direction();
        const T m = g.coin(0.1) ? T(0) : g.uniform(0.5, 64);
        // Keep away from the gate and from l = -v (discontinuities).
        if (std::abs(double(phong::detail::dot(n, l))) < 1e-3 || double(phong::detail::length(l + v)) < 1e-2) continue;
        for (const factor<T>& fn : factors<T>) {
            const wide ref = reference_factor(fn.halfway, n, l, v, m);
            const double err = double(wabs(wide(fn.f(n, l, v, m)) - ref));
            const double bound = (8 + 8 * double(m)) * double(tolerance<T>::eps);
            worst = std::max(worst, err / bound);
        }
    }
    CHECK(worst <= 1.0);
}
