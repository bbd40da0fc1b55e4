// Tests for phong/terms/normal.hpp: two-sided negation (face_viewer, face_flag) and the normal matrix
// (cofactor, inverse transpose, from a model-view matrix, transform_normal).
// Oracle for the normal matrices: finite differences of the transformed surface x -> M x(u, v),
// in long double. The generic surfaces are parametrized by circles and straight lines, for which a
// central difference is exactly parallel to the tangent (a circle's is sin(h)/h times it, a line's
// is the tangent), so the test's only error is rounding: the tolerance is a few eps of T times the
// condition number of M. "Outward" is checked with the implicit function of the surface, through
// M^{-1} computed by GLM in long double.
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/terms/normal.hpp>
#include <phong/primitives.hpp>

#include <doctest/doctest.h>

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <limits>
#include <numbers>

namespace {

using ld = long double;
using lvec3 = glm::vec<3, ld>;
using lmat3 = glm::mat<3, 3, ld>;
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using mat3 = glm::mat<3, 3, T>;

template <class T> vec3<T> narrow(const lvec3& v) { return vec3<T>(T(v.x), T(v.y), T(v.z)); }
template <class T> lvec3 widen3(const vec3<T>& v) { return lvec3(ld(v.x), ld(v.y), ld(v.z)); }
template <class T> lmat3 widen33(const mat3<T>& m) { return lmat3(widen3(m[0]), widen3(m[1]), widen3(m[2])); }
ld ldot(const lvec3& a, const lvec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
ld llen(const lvec3& a) { return std::sqrt(ldot(a, a)); }
ld cos_angle(const lvec3& a, const lvec3& b) { return ldot(a, b) / (llen(a) * llen(b)); }
ld frobenius(const lmat3& m) { return std::sqrt(ldot(m[0], m[0]) + ldot(m[1], m[1]) + ldot(m[2], m[2])); }

constexpr ld pi = std::numbers::pi_v<long double>;

/// A surface point of a generic primitive: the parametrization at (u, v), the implicit function
/// (> 0 outside) and the generic normal m' phong gives there (computed in T).
enum class surface { sphere, wall, plane };

struct sample {
    surface kind;
    ld s; // taper of the wall
    ld u, v;
};

/// x(u, v): sphere (cos v cos u, cos v sin u, sin v): u along a latitude circle, v along a
/// meridian (both circles); wall (w(v) cos u, w(v) sin u, v): u a circle, v a straight generator
/// line; plane (u, v, 0): lines.
lvec3 point(const sample& p, ld u, ld v)
{
    switch (p.kind) {
    case surface::sphere: return {std::cos(v) * std::cos(u), std::cos(v) * std::sin(u), std::sin(v)};
    case surface::wall: {
        const ld w = 1 + (p.s - 1) * v;
        return {w * std::cos(u), w * std::sin(u), v};
    }
    default: return {u, v, 0};
    }
}

ld implicit(const sample& p, const lvec3& x)
{
    switch (p.kind) {
    case surface::sphere: return ldot(x, x) - 1;
    case surface::wall: {
        const ld w = 1 + (p.s - 1) * x.z;
        return x.x * x.x + x.y * x.y - w * w;
    }
    default: return x.z;
    }
}

template <class T> vec3<T> generic_normal(const sample& p)
{
    const vec3<T> x = narrow<T>(point(p, p.u, p.v));
    switch (p.kind) {
    case surface::sphere: return phong::sphere_normal(x);
    case surface::wall: return phong::tapered_cylinder_wall_normal(x, T(p.s));
    default: return phong::plane_normal(x);
    }
}

/// Central differences of M x(u, v) along u and along v (h = 1/64, exact in binary).
std::pair<lvec3, lvec3> world_tangents(const lmat3& M, const sample& p)
{
    const ld h = ld(1) / 64;
    const lvec3 du = M * (point(p, p.u + h, p.v) - point(p, p.u - h, p.v));
    const lvec3 dv = M * (point(p, p.u, p.v + h) - point(p, p.u, p.v - h));
    return {du, dv};
}

rc::Gen<sample> gen_sample()
{
    return rc::gen::apply(
        [](int kind, int s16, int u, int v) {
            sample p{surface(kind), ld(s16) / 16, 0, 0};
            if (p.kind == surface::sphere) p.u = ld(u) * pi / 180, p.v = ld(v % 85) * pi / 180;
            else if (p.kind == surface::wall) p.u = ld(u) * pi / 180, p.v = ld((v + 90) % 61 + 2) / 64;
            else p.u = ld(u - 180) / 32, p.v = ld(v) / 32;
            return p;
        },
        rc::gen::inRange(0, 3), rc::gen::inRange(0, 33), rc::gen::inRange(0, 360), rc::gen::inRange(-90, 91));
}

/// A matrix with entries k / 4, k in [-8, 8]: products of two entries are exact in float, so the
/// cofactor is exact and the test sees the normal matrix's own error only.
template <class T> rc::Gen<mat3<T>> gen_matrix()
{
    return rc::gen::map(rc::gen::container<std::vector<int>>(9, rc::gen::inRange(-8, 9)), [](const std::vector<int>& k) {
        mat3<T> m;
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) m[c][r] = T(k[std::size_t(3 * c + r)]) / T(4);
        return m;
    });
}

/// Condition number ||M||_F ||M^{-1}||_F in long double, +inf when singular.
ld condition(const lmat3& M)
{
    const ld det = glm::determinant(M);
    if (det == 0) return std::numeric_limits<ld>::infinity();
    return frobenius(M) * frobenius(glm::inverse(M));
}

template <class T> ld tol(ld cond) { return ld(phong_test::tolerance<T>::rel(32)) * cond; }

} // namespace

// ---- two-sided: face_viewer, face_flag --------------------------------------------------------

TEST_CASE_TEMPLATE("normal: face_viewer negates a normal facing away from the viewer", T, float, double)
{
    const vec3<T> n(T(0.6), T(0), T(0.8)), v(0, 0, 1);
    CHECK(phong::face_viewer(n, v) == n);                          // n.v > 0: kept
    CHECK(phong::face_viewer(-n, v) == n);                         // n.v < 0: negated
    CHECK(phong::face_viewer(vec3<T>(1, 0, 0), v) == vec3<T>(1, 0, 0)); // n.v = 0: kept
    CHECK(phong::face_viewer(vec3<T>(0), v) == vec3<T>(0));       // n = 0: 0
    CHECK(phong::face_viewer(n, vec3<T>(0)) == n);                 // v = 0: kept
    const T nan = std::numeric_limits<T>::quiet_NaN();
    CHECK(phong::face_viewer(-n, vec3<T>(nan, 0, 0)) == -n); // NaN view: kept (documented)
}

TEST_CASE_TEMPLATE("normal: face_viewer faces the viewer, keeps the length, is idempotent (property)", T, float, double)
{
    phong_test::check_property("face_viewer", [] {
        const vec3<T> n(*phong_test::grid<T>(-16, 16, T(0.125)), *phong_test::grid<T>(-16, 16, T(0.125)),
                        *phong_test::grid<T>(-16, 16, T(0.125)));
        const vec3<T> v(*phong_test::grid<T>(-16, 16, T(0.125)), *phong_test::grid<T>(-16, 16, T(0.125)),
                        *phong_test::grid<T>(-16, 16, T(0.125)));
        const vec3<T> f = phong::face_viewer(n, v);
        // The grid values are dyadic with few bits, so the dot products below are exact.
        RC_ASSERT(f.x * v.x + f.y * v.y + f.z * v.z >= T(0));
        RC_ASSERT((f == n || f == -n));
        RC_ASSERT(phong::face_viewer(f, v) == f);
    });
}

TEST_CASE_TEMPLATE("normal: face_flag follows the caller's facing flag", T, float, double)
{
    const vec3<T> n(T(0.25), T(-0.5), T(2));
    CHECK(phong::detail::face_flag(n, true) == n);
    CHECK(phong::detail::face_flag(n, false) == -n);
    CHECK(phong::detail::face_flag(phong::detail::face_flag(n, false), false) == n);
    CHECK(phong::detail::face_flag(vec3<T>(0), false) == vec3<T>(0));
}

// ---- the normal matrix against finite differences ---------------------------------------------

TEST_CASE_TEMPLATE("normal: the inverse transpose carries normals to normals, outward stays outward (property)", T, float, double)
{
    phong_test::check_property("(M^-1)^T m' is orthogonal to the transformed tangents and points outward", [] {
        const mat3<T> M = *gen_matrix<T>();
        const sample p = *gen_sample();
        const lmat3 LM = widen33(M);
        const ld cond = condition(LM);
        RC_PRE(cond < ld(200));
        const lvec3 n = widen3(phong::transform_normal(phong::detail::normal_matrix_inverse_transpose(M), generic_normal<T>(p)));
        RC_ASSERT(std::abs(llen(n) - 1) <= tol<T>(1));
        const auto [du, dv] = world_tangents(LM, p);
        RC_ASSERT(std::abs(cos_angle(n, du)) <= tol<T>(cond));
        RC_ASSERT(std::abs(cos_angle(n, dv)) <= tol<T>(cond));
        // Outward: a step along n leaves the transformed surface on its outside (mirrors included).
        const lvec3 X = LM * point(p, p.u, p.v);
        const lvec3 outside = glm::inverse(LM) * (X + n * (ld(1e-3) / cond));
        RC_ASSERT(implicit(p, outside) > 0);
    });
}

TEST_CASE_TEMPLATE("normal: the cofactor gives the same line; it flips for mirrors (property)", T, float, double)
{
    phong_test::check_property("cof(M) m' orthogonal to the tangents, outward iff det > 0", [] {
        const mat3<T> M = *gen_matrix<T>();
        const sample p = *gen_sample();
        const lmat3 LM = widen33(M);
        const ld cond = condition(LM);
        RC_PRE(cond < ld(200));
        const lvec3 n = widen3(phong::transform_normal(phong::detail::normal_matrix_cofactor(M), generic_normal<T>(p)));
        const auto [du, dv] = world_tangents(LM, p);
        RC_ASSERT(std::abs(cos_angle(n, du)) <= tol<T>(cond));
        RC_ASSERT(std::abs(cos_angle(n, dv)) <= tol<T>(cond));
        const lvec3 X = LM * point(p, p.u, p.v);
        const lvec3 stepped = glm::inverse(LM) * (X + n * (ld(1e-3) / cond));
        const bool outward = implicit(p, stepped) > 0;
        RC_ASSERT(outward == (glm::determinant(LM) > 0));
    });
}

TEST_CASE_TEMPLATE("normal: seed 001's m = M m' taken literally is wrong under a non-uniform scale", T, float, double)
{
    // Sphere point p' = (1, 1, 0)/sqrt 2 under M = diag(1, 3, 1): the ellipse's tangent there is
    // M (-1, 1, 0) = (-1, 3, 0) (up to scale). M m' = (1, 3, 0) is not orthogonal to it
    // (dot = 8); (M^{-1})^T m' = (1, 1/3, 0) is (dot = 0), by hand.
    const mat3<T> M(vec3<T>(1, 0, 0), vec3<T>(0, 3, 0), vec3<T>(0, 0, 1));
    const vec3<T> m(1, 1, 0), tangent(-1, 3, 0);
    const vec3<T> literal = M * m;
    CHECK(literal.x * tangent.x + literal.y * tangent.y + literal.z * tangent.z == T(8));
    const vec3<T> right = phong::transform_normal(phong::detail::normal_matrix_inverse_transpose(M), m);
    CHECK(std::abs(right.x * tangent.x + right.y * tangent.y + right.z * tangent.z) <= phong_test::tolerance<T>::rel(4));
    // ... and the finite-difference oracle agrees: the literal normal is off by about 37 degrees.
    const sample p{surface::sphere, 0, pi / 4, 0};
    const auto [du, dv] = world_tangents(widen33(M), p);
    CHECK(std::abs(cos_angle(widen3(literal), du)) > ld(0.5));
    CHECK(std::abs(cos_angle(widen3(right), du)) <= tol<T>(10));
    (void)dv;
}

TEST_CASE_TEMPLATE("normal: singular maps keep a finite normal (cofactor)", T, float, double)
{
    // diag(1, 1, 0) squashes the sphere to the unit disk in z = 0: its normal is +-z.
    const mat3<T> flat(vec3<T>(1, 0, 0), vec3<T>(0, 1, 0), vec3<T>(0, 0, 0));
    const mat3<T> cof = phong::detail::normal_matrix_cofactor(flat);
    CHECK(cof == mat3<T>(vec3<T>(0), vec3<T>(0), vec3<T>(0, 0, 1))); // diag(bc, ca, ab) = diag(0, 0, 1)
    CHECK(phong::detail::normal_matrix_inverse_transpose(flat) == cof);      // det = 0: the cofactor
    const vec3<T> n = phong::transform_normal(cof, vec3<T>(T(0.6), T(0), T(0.8)));
    CHECK(n == vec3<T>(0, 0, 1));
    // Where the surface collapses to a curve (the disk's rim, p'.z = 0) there is no normal: 0.
    CHECK(phong::transform_normal(cof, vec3<T>(1, 0, 0)) == vec3<T>(0));
    // A rank-1 map: every cofactor is 0.
    const mat3<T> line(vec3<T>(1, 2, 3), vec3<T>(2, 4, 6), vec3<T>(0));
    CHECK(phong::detail::normal_matrix_cofactor(line) == mat3<T>(T(0)));
}

TEST_CASE_TEMPLATE("normal: a determinant whose inverse overflows gives a finite, oriented normal", T, float, double)
{
    // det = tiny^2 is a nonzero subnormal (about 1.8e-40 in float), so 1 / det overflows to inf.
    const T tiny = std::sqrt(std::numeric_limits<T>::min()) / T(8);
    REQUIRE(tiny * tiny > T(0));
    REQUIRE(std::isinf(T(1) / (tiny * tiny)));
    for (const T sign : {T(1), T(-1)}) {
        const mat3<T> M(vec3<T>(sign * tiny, 0, 0), vec3<T>(0, tiny, 0), vec3<T>(0, 0, 1));
        const mat3<T> N = phong::detail::normal_matrix_inverse_transpose(M);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) CHECK(std::isfinite(N[c][r]));
        // (M^{-1})^T = diag(sign / tiny, 1 / tiny, 1): the x axis keeps the direction sign * x.
        CHECK(phong::transform_normal(N, vec3<T>(1, 0, 0)) == vec3<T>(sign, 0, 0));
        CHECK(phong::transform_normal(N, vec3<T>(0, 0, 1)) == vec3<T>(0, 0, 1));
    }
}

// transform_normal promises a unit (or zero) normal for finite input, also where N n itself
// overflows: N = (max / 2) I and n = (3, 4, 0) give N n = (1.5 max, 2 max, 0), beyond T, whose
// direction is (0.6, 0.8, 0) (a 3-4-5 triangle, by hand).
TEST_CASE_TEMPLATE("normal: transform_normal where N n overflows keeps the direction", T, float, double)
{
    const T half_max = std::numeric_limits<T>::max() / T(2);
    const mat3<T> N(vec3<T>(half_max, 0, 0), vec3<T>(0, half_max, 0), vec3<T>(0, 0, half_max));
    const vec3<T> n = phong::transform_normal(N, vec3<T>(3, 4, 0));
    CHECK(std::abs(double(n.x) - 0.6) <= 2 * double(std::numeric_limits<T>::epsilon()));
    CHECK(std::abs(double(n.y) - 0.8) <= 2 * double(std::numeric_limits<T>::epsilon()));
    CHECK(n.z == T(0));
    // In range: the same bits as before (no rescaling there): (2, 0, 0) -> (1, 0, 0).
    CHECK(phong::transform_normal(mat3<T>(T(2)), vec3<T>(1, 0, 0)) == vec3<T>(1, 0, 0));
}

TEST_CASE_TEMPLATE("normal: normal_matrix(model_view) is GLSL's NormalMatrix", T, float, double)
{
    // Oracle: glm::transpose(glm::inverse(glm::mat3(MV))), what an OpenGL program uploads.
    phong_test::check_property("normal_matrix = transpose(inverse(mat3(MV))), translation ignored", [] {
        const mat3<T> A = *gen_matrix<T>();
        const ld cond = condition(widen33(A));
        RC_PRE(cond < ld(200));
        glm::mat<4, 4, T> MV(A);
        MV[3] = glm::vec<4, T>(*phong_test::grid<T>(-64, 64, T(0.25)), *phong_test::grid<T>(-64, 64, T(0.25)),
                               *phong_test::grid<T>(-64, 64, T(0.25)), T(1));
        const mat3<T> mine = phong::normal_matrix(MV);
        const mat3<T> glsl = glm::transpose(glm::inverse(mat3<T>(MV)));
        const lmat3 exact = glm::transpose(glm::inverse(widen33(A)));
        const ld scale = frobenius(exact);
        for (int c = 0; c < 3; ++c)
            for (int r = 0; r < 3; ++r) {
                RC_ASSERT(std::abs(ld(mine[c][r]) - exact[c][r]) <= tol<T>(cond) * scale);
                RC_ASSERT(std::abs(ld(glsl[c][r]) - exact[c][r]) <= tol<T>(cond) * scale);
            }
    });
}

TEST_CASE("normal: constant evaluation")
{
    // diag(2, 4, 8): (M^{-1})^T = diag(1/2, 1/4, 1/8) exactly; cof = diag(32, 16, 8).
    constexpr glm::dmat3 M(glm::dvec3(2, 0, 0), glm::dvec3(0, 4, 0), glm::dvec3(0, 0, 8));
    constexpr glm::dmat3 N = phong::detail::normal_matrix_inverse_transpose(M);
    static_assert(N[0] == glm::dvec3(0.5, 0, 0) && N[1] == glm::dvec3(0, 0.25, 0) && N[2] == glm::dvec3(0, 0, 0.125));
    constexpr glm::dmat3 C = phong::detail::normal_matrix_cofactor(M);
    static_assert(C[0] == glm::dvec3(32, 0, 0) && C[1] == glm::dvec3(0, 16, 0) && C[2] == glm::dvec3(0, 0, 8));
    static_assert(phong::transform_normal(M, glm::dvec3(0, 0, 3)) == glm::dvec3(0, 0, 1));
    static_assert(phong::face_viewer(glm::dvec3(0, 0, 1), glm::dvec3(0, 0, -1)) == glm::dvec3(0, 0, -1));
    CHECK(true);
}
