// phong/terms/view.hpp: the eye from the projection matrix (eye_from_projection), the view vector
// (view_vector), and seed 000's two formulas (view_perspective, view_orthographic). Expected eye
// points are known from how the matrices are built with GLM (glm::perspective, glm::frustum,
// glm::ortho, glm::lookAt, a translation, a shear), not from phong.
#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/terms/view.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <type_traits>

using namespace phong_test;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> using mat4 = glm::mat<4, 4, T>;

// |a - b| <= ulps * eps * max(1, |b|) componentwise (eye points are O(1..10) here).
template <glm::length_t L, class T> bool close(const glm::vec<L, T>& a, const glm::vec<L, T>& b, int ulps)
{
    return approx_equal(a, b, tolerance<T>::rel(ulps), T(1));
}

// A shear that moves x and y along z: x' = x + a z, y' = y + b z. An orthographic projection
// times this is oblique (cabinet/cavalier); its projection rays run along (-a, -b, 1).
template <class T> mat4<T> shear_z(T a, T b)
{
    mat4<T> S(T(1));
    S[2][0] = a; // column 2 (the z column), row 0
    S[2][1] = b;
    return S;
}
} // namespace

TEST_CASE_TEMPLATE("view: eye_from_projection for perspective matrices is the centre of projection", T, float, double)
{
    // glm::perspective: the eye at the origin of eye coordinates.
    const mat4<T> P = glm::perspective(T(0.9), T(16.0 / 9.0), T(0.1), T(100));
    CHECK(close(phong::eye_from_projection(P), vec4<T>(0, 0, 0, 1), 4));
    // Off-axis glm::frustum (a stereo eye, a tiled display): still centred at the origin.
    const mat4<T> F = glm::frustum(T(-0.3), T(1.1), T(-0.2), T(0.7), T(0.5), T(50));
    CHECK(close(phong::eye_from_projection(F), vec4<T>(0, 0, 0, 1), 4));
    // A perspective matrix times a view translation: world point X goes to P (X - c), so the eye
    // is at c.
    const vec3<T> c(T(1.5), T(-2), T(4.25));
    const mat4<T> PT = P * glm::translate(mat4<T>(T(1)), -c);
    CHECK(close(phong::eye_from_projection(PT), vec4<T>(c, T(1)), 16));
    // glm::lookAt from eye e: the eye is e.
    const vec3<T> e(T(3), T(2), T(-5));
    const mat4<T> PV = F * glm::lookAt(e, vec3<T>(0), vec3<T>(0, 1, 0));
    CHECK(close(phong::eye_from_projection(PV), vec4<T>(e, T(1)), 64));
    // Scaling the matrix does not move the eye (w normalized to 1).
    CHECK(close(phong::eye_from_projection(P * T(-3)), vec4<T>(0, 0, 0, 1), 4));
}

TEST_CASE_TEMPLATE("view: eye_from_projection for orthographic matrices is the direction toward the viewer", T, float, double)
{
    // glm::ortho: (0, 0, 1, 0), also off-centre.
    const mat4<T> O = glm::ortho(T(-2), T(2), T(-1), T(1), T(0.1), T(10));
    CHECK(close(phong::eye_from_projection(O), vec4<T>(0, 0, 1, 0), 4));
    const mat4<T> O2 = glm::ortho(T(1), T(5), T(-3), T(-1), T(-4), T(20));
    CHECK(close(phong::eye_from_projection(O2), vec4<T>(0, 0, 1, 0), 4));
    CHECK(close(phong::detail::view_orthographic(O2), vec3<T>(0, 0, 1), 4));
    // Oblique: ortho times a shear. Seed 000's formula normalize(-M02/M00, -M12/M11, 1) is the
    // definition here; by construction M02/M00 = a and M12/M11 = b, so v = normalize(-a, -b, 1).
    const T a = T(0.5), b = T(-0.25);
    const mat4<T> M = O2 * shear_z(a, b);
    const wvec3 expected = wnormalize(wvec3{wide(-a), wide(-b), wide(1)});
    const vec3<T> ev(T(expected.x), T(expected.y), T(expected.z));
    CHECK(close(phong::detail::view_orthographic(M), ev, 4));
    CHECK(close(phong::eye_from_projection(M), vec4<T>(ev, T(0)), 8));
    // A rotated orthographic camera (lookAt): the direction toward the viewer is the rotated +z.
    const vec3<T> e(T(1), T(2), T(2)); // |e| = 3
    const mat4<T> OV = O * glm::lookAt(e, vec3<T>(0), vec3<T>(0, 1, 0));
    CHECK(close(phong::eye_from_projection(OV), vec4<T>(e / T(3), T(0)), 16));
}

// A projection matrix is defined up to a factor: P * 2^100 (float: 1.3e30) projects every point
// where P does, so the eye is the same. Its 3x3 minors (products of three entries, ~1e90) overflow
// float; eye_from_projection promises E (never NaN) for every invertible matrix. Expected values:
// glm::perspective's centre of projection is the origin, glm::ortho's viewer is along +z.
TEST_CASE_TEMPLATE("view: eye_from_projection of a scaled matrix, minors beyond T's range", T, float, double)
{
    const T scale = std::is_same_v<T, float> ? T(0x1p100) : T(0x1p900);
    const mat4<T> P = glm::perspective(T(0.9), T(16.0 / 9.0), T(0.1), T(100));
    CHECK(close(phong::eye_from_projection(P * scale), vec4<T>(0, 0, 0, 1), 4));
    const mat4<T> O = glm::ortho(T(-2), T(2), T(-1), T(1), T(0.1), T(10));
    CHECK(close(phong::eye_from_projection(O * scale), vec4<T>(0, 0, 1, 0), 4));
    const T tiny = std::is_same_v<T, float> ? T(0x1p-100) : T(0x1p-900);
    CHECK(close(phong::eye_from_projection(P * tiny), vec4<T>(0, 0, 0, 1), 4));
}

// A perspective matrix whose centre of projection lies beyond T's range: clip w = 1 - e z with
// e = the smallest subnormal puts the eye at z = 1/e (1/1.4e-45 > float's max). By hand: the rows
// x, y and w vanish at (0, 0, 1/e, 1), i.e. the eye is a point at infinity along +z, the limit
// of an orthographic camera looking down -z: E = (0, 0, 1, 0), finite.
TEST_CASE_TEMPLATE("view: eye_from_projection with the eye beyond T's range gives its direction", T, float, double)
{
    const T e = std::numeric_limits<T>::denorm_min();
    mat4<T> M(T(1)); // rows: x, y, depth = -z, w = 1 - e z
    M[2][2] = T(-1);
    M[2][3] = -e; // column 2 (z), row 3 (w)
    const vec4<T> E = phong::eye_from_projection(M);
    CHECK(E == vec4<T>(0, 0, 1, 0));
    CHECK(phong::view_vector(E, vec3<T>(1, 2, 3)) == vec3<T>(0, 0, 1));
}

TEST_CASE_TEMPLATE("view: view_vector from the eye equals seed 000's two formulas", T, float, double)
{
    const vec3<T> Qs[] = {vec3<T>(0.5, -1, -3), vec3<T>(-2, 3, -7.5), vec3<T>(0.1, 0.2, -0.3)};
    const mat4<T> P = glm::perspective(T(1.1), T(1.5), T(0.1), T(100));
    const mat4<T> F = glm::frustum(T(-0.3), T(1.1), T(-0.2), T(0.7), T(0.5), T(50));
    const mat4<T> M = glm::ortho(T(-2), T(3), T(-1), T(1), T(0.1), T(10)) * shear_z(T(-0.75), T(0.3));
    for (const vec3<T>& Q : Qs) {
        CAPTURE(Q.z);
        // Perspective: v = normalize(O - Q), O = (0, 0, 0); checked against the wide value too.
        const wvec3 vp = wnormalize(-widen(Q));
        CHECK(close(phong::detail::view_perspective(Q), vec3<T>(T(vp.x), T(vp.y), T(vp.z)), 2));
        CHECK(close(phong::view_vector(phong::eye_from_projection(P), Q), phong::detail::view_perspective(Q), 4));
        CHECK(close(phong::view_vector(phong::eye_from_projection(F), Q), phong::detail::view_perspective(Q), 4));
        // Orthographic: v = normalize(-M02/M00, -M12/M11, 1) at every Q.
        CHECK(close(phong::view_vector(phong::eye_from_projection(M), Q), phong::detail::view_orthographic(M), 8));
    }
    // An eye point: v = normalize(E - Q).
    CHECK(close(phong::view_vector(vec4<T>(1, 2, 3, 1), vec3<T>(1, 2, -1)), vec3<T>(0, 0, 1), 2));
}

TEST_CASE_TEMPLATE("view: documented edges", T, float, double)
{
    // Q at the eye: v = 0, not NaN.
    CHECK(phong::detail::view_perspective(vec3<T>(0)) == vec3<T>(0));
    CHECK(phong::view_vector(vec4<T>(1, 2, 3, 1), vec3<T>(1, 2, 3)) == vec3<T>(0));
    // A singular projection: E = 0, every view vector 0.
    mat4<T> S(T(0));
    S[0][0] = T(1);
    CHECK(phong::eye_from_projection(S) == vec4<T>(0));
    CHECK(phong::view_vector(phong::eye_from_projection(S), vec3<T>(1, 2, 3)) == vec3<T>(0));
    // Huge Q: rescaled, never NaN.
    const T big = std::numeric_limits<T>::max() / T(2);
    CHECK(phong::detail::view_perspective(vec3<T>(T(0), T(0), -big)) == vec3<T>(0, 0, 1));
}
