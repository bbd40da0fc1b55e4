// phong/terms/direction.hpp: toward(P, Q), the one homogeneous direction rule, and light_direction.
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/terms/direction.hpp>
#include <phong/terms/view.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> constexpr T pinf = std::numeric_limits<T>::infinity();
} // namespace

TEST_CASE_TEMPLATE("direction: positional, directional and general w by hand", T, float, double)
{
    // w = 1: normalize(P.xyz - Q), distance |P.xyz - Q|. (3, 4, 0) - 0 has length 5.
    const auto a = phong::toward(vec4<T>(3, 4, -2, 1), vec3<T>(0, 0, -2));
    CHECK(error_ulp(a.direction.x, wide(0.6)) < 2.0);
    CHECK(error_ulp(a.direction.y, wide(0.8)) < 2.0);
    CHECK(a.direction.z == T(0));
    CHECK(a.distance == T(5));
    // w = 0: normalize(P.xyz), independent of Q, distance +inf.
    const auto b = phong::toward(vec4<T>(0, 0, 7, 0), vec3<T>(100, -3, 2));
    CHECK(b.direction == vec3<T>(0, 0, 1));
    CHECK(b.distance == pinf<T>);
    // w = 2: the point (1, 1, 1); from Q = 0 the direction (1, 1, 1)/sqrt3, distance sqrt3.
    const auto c = phong::toward(vec4<T>(2, 2, 2, 2), vec3<T>(0));
    const wide third = wsqrt(wide(1) / 3);
    CHECK(error_ulp(c.direction.x, third) < 2.0);
    CHECK(error_ulp(c.direction.z, third) < 2.0);
    CHECK(error_ulp(c.distance, wsqrt(wide(3))) < 3.0);
    // light_direction is toward(...).direction.
    CHECK(phong::detail::light_direction(vec4<T>(3, 4, -2, 1), vec3<T>(0, 0, -2)) == a.direction);
    CHECK(phong::detail::light_direction(vec4<T>(0, 0, 7, 0), vec3<T>(1, 2, 3)) == vec3<T>(0, 0, 1));
}

TEST_CASE_TEMPLATE("direction: against the wide reference on random points", T, float, double)
{
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-10, 10);
    double worst_dir = 0, worst_dist = 0;
    for (int i = 0; i < 1000; ++i) {
        const vec3<T> Q(T(u(rng)), T(u(rng)), T(u(rng)));
        const T w = i % 3 == 0 ? T(0) : (i % 3 == 1 ? T(1) : T(0.25));
        const vec4<T> P(T(u(rng)), T(u(rng)), T(u(rng)), w);
        const wvec3 d = wvec3{wide(P.x), wide(P.y), wide(P.z)} - widen(Q) * wide(w);
        const wvec3 l = wnormalize(d);
        const auto r = phong::toward(P, Q);
        worst_dir = std::max({worst_dir, double(wabs(wide(r.direction.x) - l.x)), double(wabs(wide(r.direction.y) - l.y)),
                              double(wabs(wide(r.direction.z) - l.z))});
        if (w > 0) worst_dist = std::max(worst_dist, error_rel(r.distance, wlength(d) / wide(w)));
    }
    // Rounding of P.xyz - w Q (relative to |P| + |Q|, well conditioned here) then normalize.
    CHECK(worst_dir <= 16 * double(std::numeric_limits<T>::epsilon()));
    CHECK(worst_dist <= 16 * double(std::numeric_limits<T>::epsilon()));
}

TEST_CASE_TEMPLATE("direction: documented edges", T, float, double)
{
    // P at Q: direction 0, distance 0.
    const auto at = phong::toward(vec4<T>(1, 2, 3, 1), vec3<T>(1, 2, 3));
    CHECK(at.direction == vec3<T>(0));
    CHECK(at.distance == T(0));
    // P.xyz = 0 with w = 0: no direction. The doc comment of toward() says "distance 0";
    // direction_and_distance says "+inf for a point at infinity (w = 0)".
    const auto none = phong::toward(vec4<T>(0, 0, 0, 0), vec3<T>(1, 2, 3));
    CHECK(none.direction == vec3<T>(0));
    // w = 0 is a point at infinity even with xyz = 0: distance +inf (documented).
    CHECK(none.distance == std::numeric_limits<T>::infinity());
    // Huge and tiny differences are rescaled: unit length, exact distance.
    const T big = std::numeric_limits<T>::max() / T(4);
    const auto huge = phong::toward(vec4<T>(-big, T(0), T(0), T(1)), vec3<T>(big, T(0), T(0)));
    CHECK(huge.direction == vec3<T>(-1, 0, 0));
    CHECK(huge.distance == T(2) * big);
    const T tiny = std::numeric_limits<T>::denorm_min();
    const auto small = phong::toward(vec4<T>(T(0), tiny, T(0), T(1)), vec3<T>(0));
    CHECK(small.direction == vec3<T>(0, 1, 0));
    CHECK(small.distance == tiny);
    // A huge directional vector stays finite.
    CHECK(phong::toward(vec4<T>(big, big, big, T(0)), vec3<T>(1)).direction.x > T(0.57));
}

// Finite P and Q whose difference P.xyz - w Q overflows (|P.xyz - Q| > max): toward() promises a
// unit direction for finite input, and a distance that is inf only when the true one exceeds the
// largest T. Expected values by hand: (max, 0, 0) - (-max, 0, 0) points along +x, 2 max away;
// (max, max/2, 0) - (-max, -max/2, 0) = max (2, 1, 0): the direction (2, 1, 0)/sqrt(5).
TEST_CASE_TEMPLATE("direction: a difference that overflows still has its direction", T, float, double)
{
    const T top = std::numeric_limits<T>::max();
    const auto far = phong::toward(vec4<T>(top, T(0), T(0), T(1)), vec3<T>(-top, T(0), T(0)));
    CHECK(far.direction == vec3<T>(1, 0, 0));
    CHECK(far.distance == pinf<T>); // 2 max: beyond T's range
    const auto oblique = phong::toward(vec4<T>(top, top / 2, T(0), T(1)), vec3<T>(-top, -top / 2, T(0)));
    CHECK(error_ulp(oblique.direction.x, wide(2) / wsqrt(wide(5))) < 3.0);
    CHECK(error_ulp(oblique.direction.y, wide(1) / wsqrt(wide(5))) < 3.0);
    CHECK(oblique.direction.z == T(0));
    // A difference within range keeps its bits: -max/2 - max/4 = -0.75 max, along -x.
    const auto fits = phong::toward(vec4<T>(-top / 2, T(0), T(0), T(1)), vec3<T>(top / 4, T(0), T(0)));
    CHECK(fits.direction == vec3<T>(-1, 0, 0));
    CHECK(error_ulp(fits.distance, wide(top) / 2 + wide(top) / 4) < 1.0);
    // The same rule for the view vector and the light direction.
    CHECK(phong::detail::light_direction(vec4<T>(top, T(0), T(0), T(1)), vec3<T>(-top, T(0), T(0))) == vec3<T>(1, 0, 0));
    CHECK(phong::view_vector(vec4<T>(T(0), -top, T(0), T(1)), vec3<T>(T(0), top, T(0))) == vec3<T>(0, -1, 0));
}
