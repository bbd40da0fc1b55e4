// accuracy::exact_bound, the function itself: usable in constant evaluation, the class constants
// follow from it, it moves the right way with each conditioning parameter, and it says +inf or
// max(1, ...) exactly where docs/accuracy.md says no relative bound exists. (Its agreement with
// measurement is tests/exact_bound.cpp, run by ctest and tests/bounds_matrix.sh.)
#include "support/accuracy_analysis.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <limits>

namespace {

using phong::evaluation;
using phong::specular_model;
using phong::accuracy::exact_diffuse_bound;
using phong::accuracy::exact_specular_bound;
using phong::accuracy::input_class;
using phong::accuracy::pair_conditioning;

constexpr double inf = std::numeric_limits<double>::infinity();

constexpr pair_conditioning pair(double m, double nl, double c, specular_model s = specular_model::phong, double nv = 1)
{
    pair_conditioning k;
    k.m = m;
    k.nl = nl;
    k.nv = nv;
    k.c = c;
    k.specular = s;
    k.blinn_sum = s == specular_model::blinn ? nl + nv : 2;
    return k;
}

// Constant evaluation (the class tables are built from it at compile time).
static_assert(phong::accuracy::exact_bound<double>(pair(100, 0.5, 0.9), 3) > 0);
static_assert(phong::accuracy::of<evaluation::exact, double>(input_class::shininess_1e5).max_rel ==
              phong::accuracy::exact_class_bound<double>(input_class::shininess_1e5));

} // namespace

TEST_CASE_TEMPLATE("exact_bound: the class constants are the function at the class limits", T, float, double)
{
    for (std::size_t i = 0; i < phong::accuracy::input_class_count; ++i) {
        const auto c = static_cast<input_class>(i);
        if (c == input_class::non_finite) continue;
        const phong::accuracy::bound b = phong::accuracy::of<evaluation::exact, T>(c);
        INFO(phong::accuracy::name(c));
        CHECK(b.max_rel == phong::accuracy::exact_class_bound<T>(c));
        CHECK(b.max_ulp == b.max_rel / (double(std::numeric_limits<T>::epsilon()) / 2));
        if (phong::accuracy::exact_class_limits<T>(c).drops) CHECK(b.max_rel == 1);
        else CHECK(b.max_rel < (sizeof(T) == 4 ? 3.0 : 1e-8));
    }
}

TEST_CASE("exact_bound: the diffuse term, first order 7 u + 11 u / n.l for w = 0 or 1")
{
    const double u = 0x1p-53;
    for (double nl : {1.0, 1e-2, 1e-4, 1e-7}) {
        pair_conditioning k = pair(0, nl, 1, specular_model::none);
        k.attenuated = false; // directional: f = 1 exactly
        const double b = exact_diffuse_bound<double>(k);
        INFO("n.l = ", nl);
        CHECK(b >= 7 * u + 11 * u / nl);
        CHECK(b <= (7 * u + 11 * u / nl) * 1.01);
    }
    // Attenuation adds 17 u; general w adds 2 w_ratio u to rho.
    pair_conditioning k = pair(0, 1, 1, specular_model::none);
    CHECK(exact_diffuse_bound<double>(k) == doctest::Approx(35 * u).epsilon(0.01));
    k.w_ratio = 100;
    CHECK(exact_diffuse_bound<double>(k) > 35 * u + 200 * 3 * u);
}

TEST_CASE("exact_bound: monotone in m, n.l and c, and larger for Blinn as |l + v| shrinks")
{
    double last = 0;
    for (double m : {1.0, 10.0, 1e3, 1e5, 1e6}) {
        const double b = exact_specular_bound<double>(pair(m, 0.5, 0.99));
        CHECK(b > last);
        last = b;
    }
    CHECK(exact_diffuse_bound<float>(pair(1, 1e-3, 1)) > exact_diffuse_bound<float>(pair(1, 1e-2, 1)));
    CHECK(exact_specular_bound<double>(pair(100, 0.5, 0.1)) > exact_specular_bound<double>(pair(100, 0.5, 0.9)));
    pair_conditioning wide = pair(100, 0.5, 0.9, specular_model::blinn), narrow = wide;
    narrow.blinn_sum = 1e-3;
    CHECK(exact_specular_bound<double>(narrow) > 100 * exact_specular_bound<double>(wide));
    // m E_c / c: double at m = 1e6 near the peak is still a small relative error; float is not.
    CHECK(exact_specular_bound<double>(pair(1e6, 0.5, 1 - 1e-6)) < 1e-8);
    CHECK(exact_specular_bound<float>(pair(1e6, 0.5, 1 - 1e-6)) > 1);
}

TEST_CASE("exact_bound: where no relative bound exists")
{
    const double e = 11 * 0x1p-53; // the absolute error of n.l for w = 0 or 1
    // n.l <= 0 within its error: the gate may switch on a pair whose exact terms are 0.
    CHECK(exact_diffuse_bound<double>(pair(1, -0.5 * e, 1)) == inf);
    CHECK(exact_specular_bound<double>(pair(1, 0, 1)) == inf);
    // Clearly below the horizon: 0 on both sides.
    CHECK(exact_diffuse_bound<double>(pair(1, -1e-3, 1)) == 0);
    CHECK(exact_specular_bound<double>(pair(1, -1e-3, 1)) == 0);
    // Specular cosine within its error of 0: +inf at or below 0, max(1, ...) just above.
    CHECK(exact_specular_bound<double>(pair(10, 0.5, -1e-16)) == inf);
    CHECK(exact_specular_bound<double>(pair(10, 0.5, 1e-16)) >= 1);
    CHECK(exact_specular_bound<double>(pair(10, 0.5, -1e-3)) == 0);
    // m = 0: s = 1 on both sides whatever c is.
    CHECK(exact_specular_bound<double>(pair(0, 0.5, 1e-16)) < 1e-14);
    // Blinn: |l + v| = 0 bit for bit is exact (0), nearly 0 is +inf.
    pair_conditioning k = pair(10, 0.5, 0.3, specular_model::blinn);
    k.blinn_sum = 0;
    CHECK(exact_specular_bound<double>(k) == 0);
    k.blinn_sum = 1e-15;
    CHECK(exact_specular_bound<double>(k) == inf);
    // Out of range (a vector the exact mode may drop): at least 1.
    k = pair(10, 0.5, 0.9);
    k.in_range = false;
    CHECK(exact_specular_bound<double>(k) == 1);
    CHECK(exact_diffuse_bound<double>(k) == 1);
    CHECK(phong::accuracy::exact_square_in_range<float>(1e-37L));
    CHECK_FALSE(phong::accuracy::exact_square_in_range<float>(1e-38L));
    CHECK_FALSE(phong::accuracy::exact_square_in_range<float>(1e39L));
}
