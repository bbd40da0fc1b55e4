// Tests for phong::shade_vertex with the seed 003 presets: the same per-vertex computation written
// literally as seed 003's phong.vert and diffuse.vert read, with GLM's matrices and glm::normalize,
// glm::reflect, glm::dot, glm::max and glm::pow, in the same precision T, on RapidCheck inputs.
// The two differ only by rounding, so the tolerance is a few eps of T, scaled by the condition of
// the model-view matrix (the normal matrix) and by the shininess (pow amplifies the rounding of
// r.v by up to m).
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/inputs/features.hpp>
#include <phong/terms/normal.hpp>
#include <phong/sum/shade.hpp>

#include <doctest/doctest.h>

#include <glm/common.hpp>
#include <glm/exponential.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <array>
#include <cmath>

namespace {

template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> using mat3 = glm::mat<3, 3, T>;
template <class T> using mat4 = glm::mat<4, 4, T>;

/// Seed 003's uniforms.
template <class T> struct light_info {
    vec4<T> Position; // Light position in eye coords.
    vec3<T> La, Ld, Ls;
};
template <class T> struct material_info {
    vec3<T> Ka, Kd, Ks;
    T Shininess;
};

/// phong.vert's main(), line by line (LightIntensity only; gl_Position is not lighting).
template <class T>
vec3<T> phong_vert(const vec3<T>& VertexPosition, const vec3<T>& VertexNormal, const light_info<T>& Light,
                   const material_info<T>& Material, const mat4<T>& ModelViewMatrix, const mat3<T>& NormalMatrix)
{
    vec3<T> tnorm = glm::normalize(NormalMatrix * VertexNormal);
    vec4<T> eyeCoords = ModelViewMatrix * vec4<T>(VertexPosition, T(1.0));
    vec3<T> s = glm::normalize(vec3<T>(Light.Position - eyeCoords));
    vec3<T> v = glm::normalize(-vec3<T>(eyeCoords));
    vec3<T> r = glm::reflect(-s, tnorm);
    T sDotN = glm::max(glm::dot(s, tnorm), T(0.0));
    vec3<T> ambient = Light.La * Material.Ka;
    vec3<T> diffuse = Light.Ld * Material.Kd * sDotN;
    vec3<T> spec = vec3<T>(T(0.0));
    if (sDotN > T(0.0)) spec = Light.Ls * Material.Ks * glm::pow(glm::max(glm::dot(r, v), T(0.0)), Material.Shininess);
    return ambient + diffuse + spec;
}

/// diffuse.vert's main().
template <class T>
vec3<T> diffuse_vert(const vec3<T>& VertexPosition, const vec3<T>& VertexNormal, const vec4<T>& LightPosition,
                     const vec3<T>& Kd, const vec3<T>& Ld, const mat4<T>& ModelViewMatrix, const mat3<T>& NormalMatrix)
{
    vec3<T> tnorm = glm::normalize(NormalMatrix * VertexNormal);
    vec4<T> eyeCoords = ModelViewMatrix * vec4<T>(VertexPosition, T(1.0));
    vec3<T> s = glm::normalize(vec3<T>(LightPosition - eyeCoords));
    return Ld * Kd * glm::max(glm::dot(s, tnorm), T(0.0));
}

/// The inputs of one vertex: a model-view matrix (rotation about a grid axis, a non-uniform scale
/// in [0.5, 2], a translation that keeps the vertex in front of the eye), a vertex, its normal, a
/// light, a material.
template <class T> struct vertex_case {
    mat4<T> model_view;
    vec3<T> position, normal;
    light_info<T> light;
    material_info<T> material;
    T condition; // of the model-view's upper 3x3: max scale / min scale
};

template <class T> vec3<T> grid3(int lo, int hi, T step)
{
    return vec3<T>(*phong_test::grid<T>(lo, hi, step), *phong_test::grid<T>(lo, hi, step), *phong_test::grid<T>(lo, hi, step));
}

template <class T> vertex_case<T> gen_case()
{
    vertex_case<T> c;
    vec3<T> axis = grid3<T>(-4, 4, T(0.25));
    if (axis == vec3<T>(0)) axis = vec3<T>(0, 1, 0);
    const T angle = T(*rc::gen::inRange(0, 360));
    const vec3<T> scale = grid3<T>(2, 8, T(0.25));
    const vec3<T> translate(*phong_test::grid<T>(-8, 8, T(0.25)), *phong_test::grid<T>(-8, 8, T(0.25)),
                            *phong_test::grid<T>(-40, -16, T(0.25)));
    c.model_view = glm::scale(glm::rotate(glm::translate(mat4<T>(T(1)), translate), glm::radians(angle), axis), scale);
    c.condition = std::max({scale.x, scale.y, scale.z}) / std::min({scale.x, scale.y, scale.z});
    c.position = grid3<T>(-8, 8, T(0.125));
    c.normal = grid3<T>(-8, 8, T(0.125));
    c.light.Position = vec4<T>(grid3<T>(-40, 40, T(0.25)), T(1));
    c.light.La = grid3<T>(0, 16, T(1) / 16);
    c.light.Ld = grid3<T>(0, 16, T(1) / 16);
    c.light.Ls = grid3<T>(0, 16, T(1) / 16);
    c.material.Ka = grid3<T>(0, 16, T(1) / 16);
    c.material.Kd = grid3<T>(0, 16, T(1) / 16);
    c.material.Ks = grid3<T>(0, 16, T(1) / 16);
    c.material.Shininess = T(*rc::gen::element(1, 2, 5, 10, 25, 40, 80, 128, 200));
    return c;
}

template <class T> phong::material<T> to_phong(const material_info<T>& m)
{
    return phong::material<T>{.ka = m.Ka, .kd = m.Kd, .ks = m.Ks, .emission = vec3<T>(0), .shininess = m.Shininess, .alpha = T(1)};
}

template <class T> phong::light<T> to_phong(const light_info<T>& l)
{
    phong::light<T> L;
    L.position = l.Position;
    L.ambient = l.La;
    L.diffuse = l.Ld;
    L.specular = l.Ls;
    return L;
}

/// Whether the literal computation sits on a decision boundary where rounding may pick the other
/// side (the gate s.n > 0, or a degenerate vertex): such cases are skipped, not compared.
template <class T> bool near_boundary(const vertex_case<T>& c, const mat3<T>& NormalMatrix)
{
    const vec3<T> tnorm = glm::normalize(NormalMatrix * c.normal);
    const vec4<T> eye = c.model_view * vec4<T>(c.position, T(1));
    const vec3<T> d = vec3<T>(c.light.Position - eye);
    if (glm::dot(c.normal, c.normal) == T(0) || glm::dot(d, d) < T(1e-2)) return true;
    return std::abs(glm::dot(glm::normalize(d), tnorm)) < T(1e-3);
}

} // namespace

TEST_CASE_TEMPLATE("vertex: shade_vertex<glsl_ads> is phong.vert (property)", T, float, double)
{
    const T eps = phong_test::tolerance<T>::eps;
    phong_test::check_property("shade_vertex = phong.vert within a few ulp", [eps] {
        const vertex_case<T> c = gen_case<T>();
        // The application's NormalMatrix, as an OpenGL program computes it.
        const mat3<T> NormalMatrix = glm::transpose(glm::inverse(mat3<T>(c.model_view)));
        RC_PRE(!near_boundary(c, NormalMatrix));
        const vec3<T> expected = phong_vert(c.position, c.normal, c.light, c.material, c.model_view, NormalMatrix);
        const std::array<phong::light<T>, 1> lights{to_phong(c.light)};
        const phong::material<T> mat = to_phong(c.material);
        // Rounding budget per channel (observed worst over 5000 cases: 2.3 eps cond (1 + m), so the
        // factor 6 leaves a margin of 2.6): the ambient product (1 ulp), the diffuse factor s.n (a few
        // eps from the normalizations and the normal matrix, times its condition), the specular
        // base r.v (likewise, times m through pow), relative to the coefficients' products.
        const T m = c.material.Shininess;
        const vec3<T> budget = c.light.La * c.material.Ka + c.light.Ld * c.material.Kd * (T(6) * c.condition) +
                               c.light.Ls * c.material.Ks * (T(6) * c.condition * (T(1) + m));
        // With GLSL's NormalMatrix passed in (the renderer's uniform) ...
        const vec3<T> given = phong::shade_vertex<phong::presets::glsl_ads>(c.position, c.normal, c.model_view,
                                                                               NormalMatrix, mat, lights);
        // ... and with phong's own normal matrix.
        const vec3<T> own = phong::shade_vertex<phong::presets::glsl_ads>(
            c.position, c.normal, c.model_view, phong::normal_matrix(c.model_view), mat, lights);
        for (int k = 0; k < 3; ++k) {
            RC_ASSERT(std::abs(given[k] - expected[k]) <= eps * (budget[k] + std::abs(expected[k])));
            RC_ASSERT(std::abs(own[k] - expected[k]) <= eps * (budget[k] + std::abs(expected[k])));
        }
    });
}

TEST_CASE_TEMPLATE("vertex: shade_vertex<diffuse_only> is diffuse.vert (property)", T, float, double)
{
    const T eps = phong_test::tolerance<T>::eps;
    phong_test::check_property("shade_vertex = diffuse.vert within a few ulp", [eps] {
        const vertex_case<T> c = gen_case<T>();
        const mat3<T> NormalMatrix = glm::transpose(glm::inverse(mat3<T>(c.model_view)));
        RC_PRE(!near_boundary(c, NormalMatrix));
        const vec3<T> expected = diffuse_vert(c.position, c.normal, c.light.Position, c.material.Kd, c.light.Ld,
                                              c.model_view, NormalMatrix);
        // Everything but Kd and Ld set to values that would show if the preset used them.
        phong::light<T> L = to_phong(c.light);
        L.ambient = vec3<T>(1);
        L.specular = vec3<T>(1);
        phong::material<T> mat = to_phong(c.material);
        mat.ka = vec3<T>(1);
        mat.ks = vec3<T>(1);
        const std::array<phong::light<T>, 1> lights{L};
        const phong::environment<T> env{.ambient = vec3<T>(1)};
        const vec3<T> got = phong::shade_vertex<phong::presets::diffuse_only>(
            c.position, c.normal, c.model_view, phong::normal_matrix(c.model_view), mat, lights, env);
        const vec3<T> budget = c.light.Ld * c.material.Kd * (T(6) * c.condition);
        for (int k = 0; k < 3; ++k) RC_ASSERT(std::abs(got[k] - expected[k]) <= eps * (budget[k] + std::abs(expected[k])));
    });
}

TEST_CASE_TEMPLATE("vertex: a hand-computed vertex", T, float, double)
{
    // Identity model-view, vertex at (0, 0, -4) with normal +z, light at (0, 3, 0): s = (0, 3, 4)/5,
    // v = (0, 0, 1), r = reflect(-s, n) = (0, -3, 4)/5, s.n = 4/5, r.v = 4/5. With La = Ka = 1/2,
    // Ld = Kd = 1, Ls = Ks = 1, m = 2: 1/4 + 4/5 + 16/25 = 1.69, by hand.
    const mat4<T> I(T(1));
    phong::light<T> L;
    L.position = vec4<T>(0, 3, 0, 1);
    L.ambient = vec3<T>(T(0.5));
    L.diffuse = vec3<T>(1);
    L.specular = vec3<T>(1);
    const phong::material<T> mat{.ka = vec3<T>(T(0.5)), .kd = vec3<T>(1), .ks = vec3<T>(1), .emission = vec3<T>(0),
                                 .shininess = T(2), .alpha = T(1)};
    const std::array<phong::light<T>, 1> lights{L};
    const vec3<T> got = phong::shade_vertex<phong::presets::glsl_ads>(vec3<T>(0, 0, -4), vec3<T>(0, 0, 1), I,
                                                                         phong::normal_matrix(I), mat, lights);
    for (int k = 0; k < 3; ++k) CHECK(std::abs(got[k] - T(1.69)) <= phong_test::tolerance<T>::rel(16));
    // The light behind the surface (s.n < 0): ambient only, exactly La Ka = 1/4 (no gate leak).
    L.position = vec4<T>(0, 3, -8, 1);
    const std::array<phong::light<T>, 1> behind{L};
    CHECK(phong::shade_vertex<phong::presets::glsl_ads>(vec3<T>(0, 0, -4), vec3<T>(0, 0, 1), I, phong::normal_matrix(I),
                                                           mat, behind) == vec3<T>(T(0.25)));
}
