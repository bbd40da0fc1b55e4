// Tests for phong/primitives.hpp: seed 001's generic normals and ray hits.
// Oracles: the implicit equations of the generic surfaces and their parametrizations (tangents
// derived by hand from the parametrization, not from the gradient the code uses), evaluated in
// long double; hand-solved hit times; geometric properties (a ray aimed at a surface point of a
// convex primitive hits it no later than that point).
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/primitives.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <tuple>
#include <vector>

namespace {

using phong::primitive_part;
using ld = long double;
using lvec3 = glm::vec<3, ld>;

template <class T> using vec3 = glm::vec<3, T>;

template <class T> vec3<T> narrow(const lvec3& v) { return vec3<T>(T(v.x), T(v.y), T(v.z)); }
template <class T> lvec3 widen3(const vec3<T>& v) { return lvec3(ld(v.x), ld(v.y), ld(v.z)); }
ld ldot(const lvec3& a, const lvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ld llen(const lvec3& a) { return std::sqrt(ldot(a, a)); }

/// Cosine of the angle between a and b (|a|, |b| > 0).
ld cos_angle(const lvec3& a, const lvec3& b) { return ldot(a, b) / (llen(a) * llen(b)); }

/// Implicit functions of the generic surfaces, > 0 outside.
ld sphere_f(const lvec3& p) { return ldot(p, p) - 1; }
ld wall_f(const lvec3& p, ld s) { const ld w = 1 + (s - 1) * p.z; return p.x * p.x + p.y * p.y - w * w; }

/// Tolerance on an angle cosine or a residual computed in T: `ulps` epsilons of T.
template <class T> ld tol(int ulps) { return ld(phong_test::tolerance<T>::rel(ulps)); }

constexpr ld pi = std::numbers::pi_v<long double>;

} // namespace

TEST_CASE_TEMPLATE("primitives: generic normals are the seed's formulas", T, float, double)
{
    const vec3<T> p(T(0.6), T(-0.8), T(0.25));
    CHECK(phong::sphere_normal(p) == p); // m' = P'
    CHECK(phong::plane_normal(p) == vec3<T>(0, 0, 1));
    CHECK(phong::square_normal(p) == vec3<T>(0, 0, 1));
    CHECK(phong::tapered_cylinder_base_normal(p) == vec3<T>(0, 0, -1));
    CHECK(phong::tapered_cylinder_cap_normal(p) == vec3<T>(0, 0, 1));
    // Wall, s = 0.5 at z = 0.25: (x, y, -(s - 1)(1 + (s - 1) z)) = (0.6, -0.8, 0.5 * 0.875), by hand.
    CHECK(phong::tapered_cylinder_wall_normal(p, T(0.5)) == vec3<T>(T(0.6), T(-0.8), T(0.4375)));
    // s = 1: a straight cylinder, radial normal with no z component.
    CHECK(phong::tapered_cylinder_wall_normal(p, T(1)) == vec3<T>(T(0.6), T(-0.8), T(0)));
    // Cone apex (s = 0, z = 1, x = y = 0): no normal, 0 (documented edge).
    CHECK(phong::tapered_cylinder_wall_normal(vec3<T>(0, 0, 1), T(0)) == vec3<T>(0));
    // Dispatch by part.
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), primitive_part::wall) == phong::tapered_cylinder_wall_normal(p, T(0.5)));
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), primitive_part::base) == vec3<T>(0, 0, -1));
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), primitive_part::cap) == vec3<T>(0, 0, 1));
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), primitive_part::none) == vec3<T>(0));
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), primitive_part::surface) == vec3<T>(0));
    CHECK(phong::tapered_cylinder_normal(p, T(0.5), static_cast<primitive_part>(9)) == vec3<T>(0)); // out of range
    // Cube: the face of the largest |coordinate|, ties to the first axis.
    CHECK(phong::cube_normal(vec3<T>(T(0.3), T(-1), T(0.5))) == vec3<T>(0, -1, 0));
    CHECK(phong::cube_normal(vec3<T>(T(-1), T(0.2), T(0.9))) == vec3<T>(-1, 0, 0));
    CHECK(phong::cube_normal(vec3<T>(T(0.1), T(0.2), T(1))) == vec3<T>(0, 0, 1));
    CHECK(phong::cube_normal(vec3<T>(T(1), T(1), T(-1))) == vec3<T>(1, 0, 0)); // corner: x first
    CHECK(phong::cube_normal(vec3<T>(T(0.5), T(-1), T(-1))) == vec3<T>(0, -1, 0)); // edge: y before z
}

TEST_CASE_TEMPLATE("primitives: the wall normal is orthogonal to the wall and points outward (property)", T, float, double)
{
    // Wall point of the parametrization (w cos phi, w sin phi, z), w = 1 + (s - 1) z; its tangents
    // d/dphi = (-w sin phi, w cos phi, 0) and d/dz = ((s - 1) cos phi, (s - 1) sin phi, 1), by hand.
    phong_test::check_property("wall normal orthogonal to both tangents, outward", [] {
        const ld s = ld(*rc::gen::inRange(0, 41)) / 16;        // 0 .. 2.5
        const ld z = ld(*rc::gen::inRange(0, 65)) / 64;        // 0 .. 1
        const ld phi = ld(*rc::gen::inRange(0, 360)) * pi / 180;
        const ld w = 1 + (s - 1) * z;
        RC_PRE(w > ld(1) / 64); // the apex of a cone has no normal
        const lvec3 p(w * std::cos(phi), w * std::sin(phi), z);
        const lvec3 m = widen3(phong::tapered_cylinder_wall_normal(narrow<T>(p), T(s)));
        const lvec3 t_phi(-w * std::sin(phi), w * std::cos(phi), 0);
        const lvec3 t_z((s - 1) * std::cos(phi), (s - 1) * std::sin(phi), 1);
        RC_ASSERT(std::abs(cos_angle(m, t_phi)) <= tol<T>(8) / w);
        RC_ASSERT(std::abs(cos_angle(m, t_z)) <= tol<T>(8) / w);
        const lvec3 outside = p + m * (ld(1e-3) / llen(m));
        RC_ASSERT(wall_f(outside, s) > 0);
    });
}

TEST_CASE_TEMPLATE("primitives: known ray hits, solved by hand", T, float, double)
{
    const vec3<T> down(0, 0, -1);
    // Sphere from (0, 0, 5) down: (t - 5)^2 = 1, t = 4 and 6.
    auto h = phong::ray_sphere(vec3<T>(0, 0, 5), down);
    CHECK(h.part == primitive_part::surface);
    CHECK(h.t == T(4));
    CHECK(phong::ray_sphere(vec3<T>(0, 0, 5), down, T(5)).t == T(6)); // t_min skips the near hit
    CHECK(phong::ray_sphere(vec3<T>(0, 0, 0), down).t == T(1));       // from inside: the far side
    CHECK(phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0, 0, -2)).t == T(2)); // t in units of c
    CHECK_FALSE(phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0, 0, 1)));   // pointing away
    CHECK_FALSE(phong::ray_sphere(vec3<T>(2, 0, 5), down));               // passes beside
    CHECK_FALSE(phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0)));         // c = 0
    // Plane z = 0 and square.
    CHECK(phong::ray_plane(vec3<T>(7, -3, 2), vec3<T>(0, 0, T(-0.5))).t == T(4));
    CHECK_FALSE(phong::ray_plane(vec3<T>(0, 0, 2), vec3<T>(1, 0, 0)));   // parallel
    CHECK_FALSE(phong::ray_plane(vec3<T>(0, 0, 0), vec3<T>(1, 0, 0)));   // in the plane
    CHECK(phong::ray_square(vec3<T>(T(0.5), T(-0.5), 3), down).t == T(3));
    CHECK(phong::ray_square(vec3<T>(1, -1, 3), down).t == T(3));          // the corner belongs to it
    CHECK_FALSE(phong::ray_square(vec3<T>(T(1.25), 0, 3), down));
    CHECK(phong::ray_square(vec3<T>(0, 0, -3), vec3<T>(0, 0, 1)).t == T(3)); // from behind
    // Tapered cylinder s = 0.5: cap (radius 0.5) from above, base from below, wall from the side.
    h = phong::ray_tapered_cylinder(vec3<T>(T(0.25), 0, 5), down, T(0.5));
    CHECK(h.part == primitive_part::cap);
    CHECK(h.t == T(4));
    h = phong::ray_tapered_cylinder(vec3<T>(T(0.75), 0, 5), down, T(0.5)); // beside the cap: the wall
    CHECK(h.part == primitive_part::wall);
    CHECK(h.t == T(4.5)); // radius 1 - z/2 = 0.75 at z = 0.5
    h = phong::ray_tapered_cylinder(vec3<T>(T(0.9), 0, -2), vec3<T>(0, 0, 1), T(0.5));
    CHECK(h.part == primitive_part::base);
    CHECK(h.t == T(2));
    h = phong::ray_tapered_cylinder(vec3<T>(5, 0, T(0.5)), vec3<T>(-1, 0, 0), T(0.5));
    CHECK(h.part == primitive_part::wall);
    CHECK(h.t == T(4.25));
    // Cone (s = 0): no cap; a ray along a generator line (A = 0) uses the linear root: from
    // (1.5, 0, -1) along (-1, 0, 1) it enters through the base at t = 1 and leaves through the
    // wall where 1.5 - t = -(2 - t) ... i.e. |1.5 - t| = 1 - z = 2 - t, t = 1.75.
    h = phong::ray_tapered_cylinder(vec3<T>(T(1.5), 0, -1), vec3<T>(-1, 0, 1), T(0));
    CHECK(h.part == primitive_part::base);
    CHECK(h.t == T(1));
    h = phong::ray_tapered_cylinder(vec3<T>(T(1.5), 0, -1), vec3<T>(-1, 0, 1), T(0), T(1.25));
    CHECK(h.part == primitive_part::wall);
    CHECK(h.t == T(1.75));
    h = phong::ray_tapered_cylinder(vec3<T>(0, 0, 5), down, T(0)); // straight onto the apex
    CHECK(h.part == primitive_part::wall);
    CHECK(h.t == T(4));
    CHECK_FALSE(phong::ray_tapered_cylinder(vec3<T>(0, 0, 5), vec3<T>(1, 0, 0), T(0.5))); // above it
    // Cube [-1, 1]^3.
    CHECK(phong::ray_cube(vec3<T>(T(0.5), T(0.5), 5), down).t == T(4));
    CHECK(phong::ray_cube(vec3<T>(0, 0, 0), vec3<T>(1, 0, 0)).t == T(1)); // from inside: the exit
    CHECK_FALSE(phong::ray_cube(vec3<T>(2, 0, 5), down));                 // parallel, outside the slab
}

TEST_CASE_TEMPLATE("primitives: no NaN and no hit from degenerate rays", T, float, double)
{
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const vec3<T> S(0, 0, 5), c(0, 0, -1), bad(nan, 0, 0);
    CHECK_FALSE(phong::ray_sphere(bad, c));
    CHECK_FALSE(phong::ray_sphere(S, bad));
    CHECK_FALSE(phong::ray_plane(vec3<T>(0, 0, nan), c));
    CHECK_FALSE(phong::ray_square(bad, c));
    CHECK_FALSE(phong::ray_tapered_cylinder(bad, c, T(0.5)));
    CHECK_FALSE(phong::ray_tapered_cylinder(S, vec3<T>(0), T(0.5)));
    CHECK_FALSE(phong::ray_cube(vec3<T>(0, nan, 5), c));
    CHECK_FALSE(phong::ray_cube(S, vec3<T>(0)));
    const phong::ray_hit<T> miss;
    CHECK(miss.t == std::numeric_limits<T>::infinity());
    CHECK(miss.part == primitive_part::none);
}

TEST_CASE_TEMPLATE("primitives: a ray aimed at a surface point hits no later than it, on the surface (property)", T, float, double)
{
    // Convex primitives: from an outside origin S toward a surface point X = S + 1 c, the first
    // hit is at t <= 1, and exactly there when X faces S. The hit point satisfies the surface's
    // implicit equation.
    phong_test::check_property("sphere", [] {
        const ld th = ld(*rc::gen::inRange(-89, 90)) * pi / 180, ph = ld(*rc::gen::inRange(0, 360)) * pi / 180;
        const lvec3 X(std::cos(th) * std::cos(ph), std::cos(th) * std::sin(ph), std::sin(th));
        const lvec3 S(ld(*rc::gen::inRange(-40, 41)) / 8, ld(*rc::gen::inRange(-40, 41)) / 8, ld(*rc::gen::inRange(-40, 41)) / 8);
        RC_PRE(sphere_f(S) > ld(0.25));
        const vec3<T> s = narrow<T>(S), c = narrow<T>(X - S);
        const auto h = phong::ray_sphere(s, c);
        RC_ASSERT(bool(h));
        // The roots' conditioning: merging roots (a short chord) amplify the rounding of S and c.
        const lvec3 C = widen3(c), SS = widen3(s);
        const ld a = ldot(C, C), b = ldot(SS, C), disc = b * b - a * (ldot(SS, SS) - 1);
        const ld cond = 1 + std::abs(b) / std::sqrt(std::max(disc, ld(1e-30)));
        RC_ASSERT(ld(h.t) <= 1 + tol<T>(64) * cond);
        const lvec3 P = SS + C * ld(h.t);
        RC_ASSERT(std::abs(sphere_f(P)) <= tol<T>(64) * cond * (1 + ldot(SS, SS)));
        if (ldot(X, S - X) > ld(0.05) * llen(S - X)) RC_ASSERT(std::abs(ld(h.t) - 1) <= tol<T>(64) * cond); // X visible from S
    });
    phong_test::check_property("tapered cylinder wall", [] {
        const ld s = ld(*rc::gen::inRange(0, 33)) / 16;
        const ld z = ld(*rc::gen::inRange(1, 64)) / 64;
        const ld ph = ld(*rc::gen::inRange(0, 360)) * pi / 180;
        const ld w = 1 + (s - 1) * z;
        const lvec3 X(w * std::cos(ph), w * std::sin(ph), z);
        // S outside, beside the wall on X's side: X pushed out along its radial direction, then up or down.
        const ld out = ld(*rc::gen::inRange(1, 33)) / 8, dz = ld(*rc::gen::inRange(-16, 17)) / 32;
        const lvec3 S(X.x + out * std::cos(ph), X.y + out * std::sin(ph), X.z + dz);
        RC_PRE(S.z < 0 || S.z > 1 || wall_f(S, s) > ld(0.01)); // outside (the wall may slant over S)
        // Not on the wall's extension either: from there a cone's ray (dz = -out, s = 0) runs in
        // the surface itself, touches the base's rim and grazes the wall: no hit is as right as any.
        RC_PRE(std::abs(wall_f(S, s)) > ld(0.01));
        const vec3<T> sS = narrow<T>(S), c = narrow<T>(X - S);
        const auto h = phong::ray_tapered_cylinder(sS, c, T(s));
        RC_ASSERT(bool(h));
        RC_ASSERT(ld(h.t) <= 1 + tol<T>(256));
        const lvec3 P = widen3(sS) + widen3(c) * ld(h.t);
        if (h.part == primitive_part::wall) {
            RC_ASSERT(std::abs(wall_f(P, s)) <= tol<T>(256) * (1 + out * out));
            RC_ASSERT(P.z >= 0);
            RC_ASSERT(P.z <= 1);
        } else if (h.part == primitive_part::base) {
            RC_ASSERT(std::abs(P.z) <= tol<T>(64));
            RC_ASSERT(P.x * P.x + P.y * P.y <= 1 + tol<T>(64));
        } else {
            RC_ASSERT(h.part == primitive_part::cap);
            RC_ASSERT(std::abs(P.z - 1) <= tol<T>(64));
            RC_ASSERT(P.x * P.x + P.y * P.y <= s * s + tol<T>(64));
        }
    });
    phong_test::check_property("cube", [] {
        const int face = *rc::gen::inRange(0, 6);
        const ld u = ld(*rc::gen::inRange(-16, 17)) / 16, v = ld(*rc::gen::inRange(-16, 17)) / 16;
        lvec3 X(u, v, u);
        X[face / 2] = face % 2 ? ld(1) : ld(-1);
        X[(face / 2 + 1) % 3] = u;
        X[(face / 2 + 2) % 3] = v;
        lvec3 S = X;
        S[face / 2] *= ld(*rc::gen::inRange(9, 40)) / 8; // outside, in front of that face
        S[(face / 2 + 1) % 3] += ld(*rc::gen::inRange(-4, 5)) / 8;
        const vec3<T> sS = narrow<T>(S), c = narrow<T>(X - S);
        const auto h = phong::ray_cube(sS, c);
        RC_ASSERT(bool(h));
        // S lies on the outer side of X's face plane, so the ray enters through that face, at X.
        RC_ASSERT(std::abs(ld(h.t) - 1) <= tol<T>(64));
        const lvec3 P = widen3(sS) + widen3(c) * ld(h.t);
        RC_ASSERT(std::abs(std::abs(P[face / 2]) - 1) <= tol<T>(64) * 8);
        const ld inf_norm = std::max({std::abs(P.x), std::abs(P.y), std::abs(P.z)});
        RC_ASSERT(std::abs(inf_norm - 1) <= tol<T>(64) * 8);
    });
}

TEST_CASE_TEMPLATE("primitives: ray_sphere with vectors whose squares overflow", T, float, double)
{
    // x: |x|^2 overflows T, x itself is finite (float 1e20, double 1e160).
    const T x = sizeof(T) == 4 ? T(1e20) : T(1e160);
    const T eps = std::numeric_limits<T>::epsilon();
    // From the centre along a huge c: |S + t c| = 1 at t = 1 / |c| (by hand).
    const auto h1 = phong::ray_sphere(vec3<T>(0), vec3<T>(x, 0, 0));
    REQUIRE(static_cast<bool>(h1));
    CHECK(std::abs(h1.t * x - T(1)) <= 2 * eps);
    // S = (x, 1/2, 0) toward -x: the line y = 1/2 meets the sphere at x' = +-sqrt(3)/2, so
    // t = (x - sqrt(3)/2) / x, which is 1 in T to within eps.
    const auto h2 = phong::ray_sphere(vec3<T>(x, T(0.5), 0), vec3<T>(-x, 0, 0));
    REQUIRE(static_cast<bool>(h2));
    CHECK(std::abs(h2.t - T(1)) <= 2 * eps);
    // A huge S with a unit c: roots x -+ 1, both x in T; after t_min = 2x there is no hit (the
    // overflowing S.S once gave a hit at t = inf).
    const auto h3 = phong::ray_sphere(vec3<T>(x, 0, 0), vec3<T>(-1, 0, 0));
    REQUIRE(static_cast<bool>(h3));
    CHECK(std::abs(h3.t / x - T(1)) <= 2 * eps);
    CHECK_FALSE(static_cast<bool>(phong::ray_sphere(vec3<T>(x, 0, 0), vec3<T>(-1, 0, 0), 2 * x)));
    // Away from the sphere: no hit; an inf component: no hit.
    CHECK_FALSE(static_cast<bool>(phong::ray_sphere(vec3<T>(x, 0, 0), vec3<T>(x, 0, 0))));
    CHECK_FALSE(static_cast<bool>(phong::ray_sphere(vec3<T>(0), vec3<T>(std::numeric_limits<T>::infinity(), 0, 0))));
}

/// The tapered cylinder's first hit after t = 0 of S + t c in the reference's wide type
/// (__float128 where available), from the formulas written out (wall: |(x, y)| = 1 + (s - 1) z,
/// 0 <= z <= 1, by the quadratic formula; base z = 0, |(x, y)| <= 1; cap z = 1, |(x, y)| <= s),
/// and how far it lies from a rim (closer, a perturbation of the ray may change the part hit).
struct tapered_reference {
    phong_test::wide t = std::numeric_limits<ld>::infinity();
    primitive_part part = primitive_part::none;
    phong_test::wide rim_distance = std::numeric_limits<ld>::infinity();
};
tapered_reference tapered_first_hit(const phong_test::wvec3& S, const phong_test::wvec3& c, phong_test::wide s)
{
    using phong_test::wide;
    using phong_test::wsqrt;
    tapered_reference r;
    const auto consider = [&](wide t, primitive_part part, wide rim) {
        if (t > 0 && t < r.t) r = {t, part, rim};
    };
    const wide k = s - 1;
    const wide a = c.x * c.x + c.y * c.y - k * k * c.z * c.z;
    const wide b = 2 * (S.x * c.x + S.y * c.y - (1 + k * S.z) * k * c.z);
    const wide cc = S.x * S.x + S.y * S.y - (1 + k * S.z) * (1 + k * S.z);
    const wide disc = b * b - 4 * a * cc;
    // Roots as q / a and cc / q, q = -(b + sign(b) sqrt(disc)) / 2: a ray parallel to a cone's
    // generator line has a ~ 1e-16 (the rounding of c), where (-b -+ sqrt(disc)) / 2a cancels
    // to two digits in long double (the reference type without __float128).
    const wide q = -(b + (b < 0 ? -wsqrt(disc) : wsqrt(disc))) / 2;
    if (disc >= 0 && q != 0)
        for (const wide t : {cc / q, a != 0 ? q / a : wide(-1)}) {
            const wide z = S.z + t * c.z;
            if (z >= 0 && z <= 1) consider(t, primitive_part::wall, phong_test::wmin(z, 1 - z));
        }
    for (const auto& [z0, radius, part] : {std::tuple{wide(0), wide(1), primitive_part::base}, std::tuple{wide(1), s, primitive_part::cap}}) {
        if (c.z == 0) continue;
        const wide t = (z0 - S.z) / c.z, x = S.x + t * c.x, y = S.y + t * c.y;
        const wide rho = wsqrt(x * x + y * y);
        if (rho <= radius) consider(t, part, radius - rho);
    }
    return r;
}

TEST_CASE_TEMPLATE("primitives: ray_tapered_cylinder from far away keeps its digits", T, float, double)
{
    // Rays from a distance D onto the wall, at most 60 degrees off its outward normal, against
    // the long double reference on the same (rounded) S and c. Solved at a far S, B^2 and A C
    // (~D^2) cancelled down to the discriminant: float lost the hit's digits from D ~ 10 on
    // (1.5 % of t at D = 100) and missed hits from D ~ 1e3. The hit is now found to within the
    // rounding of a point of the ray near the object, a few eps D: |t - t_ref| <= 64 eps (t + 1)
    // off the rims.
    const T eps = std::numeric_limits<T>::epsilon();
    std::vector<ld> distances{4, 10, 100, 1e3, 1e4};
    // The reference's own cancellation, ~2^-digits D^2, must stay far below double's tolerance.
    if (sizeof(T) == 8 && phong_test::wide_digits >= 113) distances.insert(distances.end(), {1e5, 1e6});
    int compared = 0;
    for (const ld s : {ld(0.5), ld(1), ld(0), ld(1.5)})
        for (const ld D : distances)
            for (int i = 0; i < 64; ++i) {
                const ld z = ld(1 + i % 7) / 8, ph = ld(i) * 2 * pi / 64 + ld(0.1);
                const ld w = 1 + (s - 1) * z;
                const lvec3 X(w * std::cos(ph), w * std::sin(ph), z);
                const lvec3 m = lvec3(std::cos(ph), std::sin(ph), -(s - 1)) / std::sqrt(1 + (s - 1) * (s - 1)); // outward unit normal
                const lvec3 tilt = lvec3(-std::sin(ph), std::cos(ph), 0) * ((ld(i % 5) - 2) / 4) + lvec3(0, 0, (ld(i % 3) - 1) / 4);
                const lvec3 u = (m + tilt) / llen(m + tilt); // cos(u, m) >= 0.6
                const vec3<T> S = narrow<T>(X + u * D), c = narrow<T>(-u);
                const tapered_reference want = tapered_first_hit(phong_test::widen(S), phong_test::widen(c), s);
                CAPTURE(s);
                CAPTURE(D);
                CAPTURE(i);
                REQUIRE(want.part != primitive_part::none);
                if (want.rim_distance < ld(0.01)) continue; // a perturbation of the ray may change the part
                const auto h = phong::ray_tapered_cylinder(S, c, T(s));
                CHECK(h.part == want.part);
                CHECK(std::abs(ld(h.t) - ld(want.t)) <= 64 * ld(eps) * (ld(want.t) + 1));
                ++compared;
            }
    CHECK(compared > 1000);
}

TEST_CASE_TEMPLATE("primitives: ray_tapered_cylinder with vectors whose squares overflow", T, float, double)
{
    const T x = sizeof(T) == 4 ? T(1e20) : T(1e160); // |x|^2 overflows T
    const T eps = std::numeric_limits<T>::epsilon();
    // From (x, 0, 1/2) toward -x: the wall of s = 1/2 has radius 3/4 at z = 1/2, t = x - 3/4,
    // which is x in T (by hand). It was a miss: B^2 - A C = inf - inf.
    const auto h1 = phong::ray_tapered_cylinder(vec3<T>(x, 0, T(0.5)), vec3<T>(-1, 0, 0), T(0.5));
    CHECK(h1.part == primitive_part::wall);
    CHECK(std::abs(h1.t / x - T(1)) <= 2 * eps);
    CHECK_FALSE(static_cast<bool>(phong::ray_tapered_cylinder(vec3<T>(x, 0, T(0.5)), vec3<T>(-1, 0, 0), T(0.5), 2 * x)));
    // From (5, 0, 1/2) along a huge c = (-x, 0, 0): t = 4.25 / x (4.25 for a unit c, as by hand above).
    const auto h2 = phong::ray_tapered_cylinder(vec3<T>(5, 0, T(0.5)), vec3<T>(-x, 0, 0), T(0.5));
    CHECK(h2.part == primitive_part::wall);
    CHECK(std::abs(h2.t * x / T(4.25) - T(1)) <= 4 * eps);
    // Pointing away, and an inf component: no hit.
    CHECK_FALSE(static_cast<bool>(phong::ray_tapered_cylinder(vec3<T>(x, 0, T(0.5)), vec3<T>(1, 0, 0), T(0.5))));
    CHECK_FALSE(static_cast<bool>(phong::ray_tapered_cylinder(vec3<T>(5, 0, T(0.5)), vec3<T>(-std::numeric_limits<T>::infinity(), 0, 0), T(0.5))));
}

TEST_CASE_TEMPLATE("primitives: rays with a direction so short that c.c underflows", T, float, double)
{
    // |c| = y, y^2 below T's smallest normal (float 1e-25, double 1e-170): the same hits as for a
    // unit c, at t / y (by hand, as in the cases above). The sphere missed them (c.c = 0), the
    // wall's quadratic lost its leading coefficient (4.4375 / y instead of 4.25 / y).
    const T y = sizeof(T) == 4 ? T(1e-25) : T(1e-170);
    const T eps = std::numeric_limits<T>::epsilon();
    const auto h1 = phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0, 0, -y));
    REQUIRE(static_cast<bool>(h1));
    CHECK(std::abs(h1.t * y / T(4) - T(1)) <= 2 * eps);
    const auto h2 = phong::ray_tapered_cylinder(vec3<T>(5, 0, T(0.5)), vec3<T>(-y, 0, 0), T(0.5));
    CHECK(h2.part == primitive_part::wall);
    CHECK(std::abs(h2.t * y / T(4.25) - T(1)) <= 4 * eps);
    // A subnormal c: t = 4 / c is beyond T's range, no hit (not t = inf); c = 0: no hit.
    const T tiny = std::numeric_limits<T>::denorm_min();
    CHECK_FALSE(static_cast<bool>(phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0, 0, -tiny))));
    CHECK_FALSE(static_cast<bool>(phong::ray_tapered_cylinder(vec3<T>(T(0.25), 0, 5), vec3<T>(0, 0, -tiny), T(0.5))));
    CHECK_FALSE(static_cast<bool>(phong::ray_sphere(vec3<T>(0, 0, 5), vec3<T>(0))));
    // A subnormal c from just outside the sphere: t = eps / tiny stays in range (float:
    // 2^-23 / 2^-149 = 2^126; double 2^1022).
    const T s0 = T(1) + eps;
    const auto h3 = phong::ray_sphere(vec3<T>(0, 0, s0), vec3<T>(0, 0, -tiny));
    REQUIRE(static_cast<bool>(h3));
    CHECK(std::abs(h3.t * tiny / (s0 - T(1)) - T(1)) <= 4 * eps);
}

TEST_CASE("primitives: constant evaluation")
{
    static_assert(phong::ray_sphere(glm::dvec3(0, 0, 5), glm::dvec3(0, 0, -1)).t == 4.0);
    static_assert(phong::ray_tapered_cylinder(glm::dvec3(0.25, 0, 5), glm::dvec3(0, 0, -1), 0.5).part == primitive_part::cap);
    static_assert(phong::ray_cube(glm::vec3(0, 0, 5), glm::vec3(0, 0, -1)).t == 4.0f);
    static_assert(phong::tapered_cylinder_wall_normal(glm::dvec3(1, 0, 0), 0.5) == glm::dvec3(1, 0, 0.5));
    CHECK(true);
}
