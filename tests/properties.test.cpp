// Property tests (RapidCheck, through phong_test::check_property): the lighting model's
// mathematical properties on generated inputs. Inputs come from integer grids (support/property.hpp,
// support/generators.hpp); the seed is pinned by RC_PARAMS in ctest's environment.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/phong.hpp>

#include <glm/gtc/matrix_transform.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace phong_test;
using phong::evaluation;
using phong::features;

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> using mat4 = glm::mat<4, 4, T>;

template <class T> constexpr T eps = std::numeric_limits<T>::epsilon();

// |a - b| <= ulps eps scale, componentwise.
template <glm::length_t L, class T> bool near(const glm::vec<L, T>& a, const glm::vec<L, T>& b, double ulps, T scale)
{
    for (glm::length_t k = 0; k < L; ++k)
        if (!(std::abs(double(a[k]) - double(b[k])) <= ulps * double(eps<T>) * double(scale))) return false;
    return true;
}
template <glm::length_t L, class T> T max_channel(const glm::vec<L, T>& v)
{
    T m = T(0);
    for (glm::length_t k = 0; k < L; ++k) m = std::max(m, std::abs(v[k]));
    return m;
}

// A surface point in front of the eye and a nonzero normal, on grids.
template <class T> vec3<T> gen_point()
{
    const T step = T(1) / T(8);
    return *rc::gen::map(rc::gen::tuple(grid<T>(-32, 32, step), grid<T>(-32, 32, step), grid<T>(-64, -8, step)),
                         [](const auto& t) { return vec3<T>(std::get<0>(t), std::get<1>(t), std::get<2>(t)); });
}
template <class T> vec3<T> gen_normal() { return *gen_nonzero_vec3<T>(-8, 8, T(0.25)); }
template <class T> std::vector<phong::light<T>> gen_lights(int lo, int hi)
{
    const int n = *rc::gen::inRange(lo, hi + 1);
    std::vector<phong::light<T>> lights;
    for (int i = 0; i < n; ++i) lights.push_back(*gen_light<T>(*rc::gen::arbitrary<bool>()));
    return lights;
}

// Feature sets the properties run on: both specular models, both modes, every optional term
// that keeps the model linear in the lights.
constexpr features rich{.scene_ambient = true, .light_ambient = true, .diffuse = true,
                        .specular = phong::specular_model::blinn, .specular_gate = true,
                        .lights = phong::light_kind::any, .attenuation = phong::attenuation_model::polynomial,
                        .spot = phong::spot_model::none, .attenuate_ambient = true,
                        .two_sided = phong::facing::view, .view = phong::view_model::eye_at_origin,
                        .emission = true, .alpha = false, .mode = evaluation::stable};
constexpr features classic{}; // seed 000's defaults, exact

// Only the light's diffuse and specular terms: no ambient, no emission, no two-sided flip.
// (Variables, not functions: clang++ 16 flags an internal function called only in constant
// expressions, -Wunneeded-internal-declaration.)
template <phong::specular_model S, evaluation E> constexpr features lit_only = [] {
    features f{.scene_ambient = false, .light_ambient = false};
    f.specular = S;
    f.mode = E;
    return f;
}();
constexpr features rich_phong_exact = [] {
    features f = rich;
    f.specular = phong::specular_model::phong;
    f.mode = evaluation::exact;
    return f;
}();
constexpr features classic_blinn_stable = [] {
    features f = classic;
    f.specular = phong::specular_model::blinn;
    f.mode = evaluation::stable;
    return f;
}();

template <features F, class T> vec3<T> shade_of(const vec3<T>& Q, const vec3<T>& n, const phong::material<T>& mat,
                                                const std::vector<phong::light<T>>& lights, const phong::environment<T>& env)
{
    return phong::shade<F>(Q, n, mat, lights, env);
}
} // namespace

TEST_CASE_TEMPLATE("properties: outputs are non-negative and bounded by the coefficients", T, float, double)
{
    auto property = [](auto f_constant) {
        return [] {
            constexpr features F = decltype(f_constant)::value;
            const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
            const phong::material<T> mat = *gen_material<T>(128);
            const std::vector<phong::light<T>> lights = gen_lights<T>(0, 4);
            phong::environment<T> env;
            env.ambient = *gen_color<T>();
            const vec3<T> c = shade_of<F>(Q, n, mat, lights, env);
            // f_i <= 1 (c0 = 1 by default), n.l, base^m, spot <= 1: each term at most its coefficient.
            vec3<T> ambient = env.ambient, diffuse(0), specular(0);
            for (const auto& L : lights) ambient += L.ambient, diffuse += L.diffuse, specular += L.specular;
            vec3<T> bound = mat.ka * ambient + mat.kd * diffuse + mat.ks * specular;
            if constexpr (F.emission) bound += mat.emission;
            for (int k = 0; k < 3; ++k) {
                RC_ASSERT(c[k] >= T(0));
                RC_ASSERT(c[k] <= bound[k] * (T(1) + T(64) * eps<T>));
            }
        };
    };
    check_property("0 <= shade <= emission + ka (La + sum La_i) + kd sum Ld_i + ks sum Ls_i (rich)",
                   property(std::integral_constant<features, rich>{}));
    check_property("0 <= shade <= ka La + kd sum Ld_i + ks sum Ls_i (classic)",
                   property(std::integral_constant<features, classic>{}));
    check_property("... (rich, Phong, exact)", property(std::integral_constant<features, rich_phong_exact>{}));
}

TEST_CASE_TEMPLATE("properties: superposition, the sum over lights is the sum of single-light shades", T, float, double)
{
    auto property = [](auto f_constant) {
        return [] {
            constexpr features F = decltype(f_constant)::value;
            const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
            const phong::material<T> mat = *gen_material<T>(128);
            const std::vector<phong::light<T>> lights = gen_lights<T>(1, 4);
            phong::environment<T> env;
            env.ambient = *gen_color<T>();
            const vec3<T> all = shade_of<F>(Q, n, mat, lights, env);
            // The scene terms (emission, ka La) belong to every single-light shade: count them once.
            vec3<T> scene_terms = mat.ka * env.ambient;
            if constexpr (F.emission) scene_terms += mat.emission;
            vec3<T> sum = scene_terms;
            T scale = max_channel(all);
            for (const auto& L : lights) {
                const vec3<T> single = shade_of<F>(Q, n, mat, std::vector<phong::light<T>>{L}, env);
                sum += single - scene_terms;
                scale = std::max(scale, max_channel(single));
            }
            RC_ASSERT(near(all, sum, 32, scale));
        };
    };
    check_property("shade(L1..Ln) = scene + sum_i (shade(Li) - scene) (rich)", property(std::integral_constant<features, rich>{}));
    check_property("shade(L1..Ln) = scene + sum_i (shade(Li) - scene) (classic)", property(std::integral_constant<features, classic>{}));
}

TEST_CASE_TEMPLATE("properties: linear in each light's strength", T, float, double)
{
    auto property = [](auto f_constant) {
        return [] {
            constexpr features F = decltype(f_constant)::value;
            const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
            const phong::material<T> mat = *gen_material<T>(128);
            std::vector<phong::light<T>> lights = gen_lights<T>(1, 3);
            phong::environment<T> env;
            env.ambient = *gen_color<T>();
            const T k = *grid<T>(0, 64, T(1) / T(8)); // 0 .. 8
            const std::size_t i = *rc::gen::inRange<std::size_t>(0, lights.size());
            auto with_strength = [&](T s) {
                std::vector<phong::light<T>> ls = lights;
                ls[i].ambient *= s, ls[i].diffuse *= s, ls[i].specular *= s;
                return shade_of<F>(Q, n, mat, ls, env);
            };
            const vec3<T> zero = with_strength(T(0)), one = with_strength(T(1)), scaled = with_strength(k);
            // shade(k L_i) = shade(0 L_i) + k (shade(L_i) - shade(0 L_i)).
            const vec3<T> expected = zero + (one - zero) * k;
            RC_ASSERT(near(scaled, expected, 32, std::max({max_channel(scaled), max_channel(one) * std::max(k, T(1))})));
        };
    };
    check_property("shade is linear in L_i's strengths (rich)", property(std::integral_constant<features, rich>{}));
    check_property("shade is linear in L_i's strengths (classic)", property(std::integral_constant<features, classic>{}));
}

TEST_CASE_TEMPLATE("properties: a light behind the surface gives no diffuse and no specular", T, float, double)
{
    auto property = [](auto f_constant) {
        return [] {
            constexpr features F = decltype(f_constant)::value;
            const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
            // The light behind the tangent plane: toward it d = -a n + t, t = n x u along the plane.
            const T a = *grid<T>(1, 64, T(0.25));
            const vec3<T> d = -a * n + phong::detail::cross(n, *gen_vec3<T>(-8, 8, T(0.5)));
            phong::light<T> L = *gen_light<T>(false);
            L.position = *rc::gen::arbitrary<bool>() ? vec4<T>(Q + d, T(1)) : vec4<T>(d, T(0));
            // Strictly behind (n.d < 0, with a margin so that rounding cannot move it across).
            const vec3<T> dd = vec3<T>(L.position) - Q * L.position.w;
            RC_PRE(double(phong::detail::dot(n, dd)) < -1e-3 * double(phong::detail::length(n)) * double(phong::detail::length(dd)));
            const phong::material<T> mat = *gen_material<T>(128);
            phong::environment<T> env;
            const vec3<T> c = phong::shade<F>(Q, n, mat, std::vector<phong::light<T>>{L}, env);
            RC_ASSERT(c == vec3<T>(0));
        };
    };
    check_property("n.l < 0: diffuse = specular = 0 (Phong, exact)",
                   property(std::integral_constant<features, lit_only<phong::specular_model::phong, evaluation::exact>>{}));
    check_property("n.l < 0: diffuse = specular = 0 (Phong, stable)",
                   property(std::integral_constant<features, lit_only<phong::specular_model::phong, evaluation::stable>>{}));
    check_property("n.l < 0: diffuse = specular = 0 (Blinn, exact)",
                   property(std::integral_constant<features, lit_only<phong::specular_model::blinn, evaluation::exact>>{}));
    check_property("n.l < 0: diffuse = specular = 0 (Blinn, stable)",
                   property(std::integral_constant<features, lit_only<phong::specular_model::blinn, evaluation::stable>>{}));
}

TEST_CASE_TEMPLATE("properties: reflect keeps length and is an involution", T, float, double)
{
    check_property("|reflect(i, n)| = |i| and reflect(reflect(i, n), n) = i for unit n", [] {
        const vec3<T> i = *gen_vec3<T>(-64, 64, T(1) / T(16));
        const vec3<T> n = phong::detail::normalize(*gen_nonzero_vec3<T>(-16, 16, T(0.25)));
        const vec3<T> r = phong::reflect(i, n);
        const T len = phong::detail::length(i);
        // A few roundings in dot(n, i) n, relative to |i|; n itself is unit within ~1 eps.
        RC_ASSERT(std::abs(phong::detail::length(r) - len) <= T(8) * eps<T> * len);
        RC_ASSERT(near(phong::reflect(r, n), i, 16, len));
        // The mirror image: the component along n flips, the rest stays.
        RC_ASSERT(std::abs(phong::detail::dot(r, n) + phong::detail::dot(i, n)) <= T(8) * eps<T> * len);
    });
}

TEST_CASE_TEMPLATE("properties: pow_unit is a power, x^(a+b) = x^a x^b, in [0, 1] and non-increasing in m", T, float, double)
{
    check_property("pow_unit(x, a + b) = pow_unit(x, a) pow_unit(x, b), 0 <= x^m <= 1, a <= b gives x^a >= x^b", [] {
        const T x = T(*rc::gen::inRange(1, 257)) / T(256); // (0, 1] on a grid
        const T a = T(*rc::gen::inRange(0, 513)) / T(8);   // [0, 64]
        const T b = T(*rc::gen::inRange(0, 513)) / T(8);
        const T xa = phong::detail::pow_unit(x, a), xb = phong::detail::pow_unit(x, b), xab = phong::detail::pow_unit(x, a + b);
        for (const T r : {xa, xb, xab}) RC_ASSERT(r >= T(0) && r <= T(1));
        RC_ASSERT(phong::detail::pow_unit(x, T(0)) == T(1)); // x^0 = 1, 0^0 included
        // Each result within its documented bound, the product rounded once more: a relative
        // tolerance of a few ulp (float: 1 ulp each) or 3 (|y| + m + 4) 2^-53 each (double).
        const double y = double(a + b) * std::abs(std::log2(double(x)));
        const double tol = sizeof(T) == 4 ? 4 * double(eps<T>) : 9 * (y + double(a + b) + 4) * 0x1p-53 + 2 * double(eps<T>);
        if (double(xab) > 1e-30) RC_ASSERT(std::abs(double(xa) * double(xb) - double(xab)) <= tol * double(xab));
        // Monotone in m for x < 1 (a few ulp of slack: the kernel is monotone only up to rounding).
        if (a <= b) RC_ASSERT(double(xa) >= double(xb) * (1 - 4 * double(eps<T>)));
    });
}

TEST_CASE_TEMPLATE("properties: a directional light is the limit of a far positional one", T, float, double)
{
    auto property = [](auto f_constant) {
        return [] {
            constexpr features F = decltype(f_constant)::value;
            const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
            phong::material<T> mat = *gen_material<T>(32);
            const vec3<T> dir = phong::detail::normalize(*gen_nonzero_vec3<T>(-8, 8, T(0.25)));
            phong::light<T> directional = *gen_light<T>(true);
            directional.position = vec4<T>(dir, T(0));
            // Far away along dir: positional at Q + t dir (t = 2^20 in float, 2^40 in double).
            const T t = std::is_same_v<T, float> ? T(1 << 20) : T(1ull << 40);
            phong::light<T> positional = directional;
            positional.position = vec4<T>(Q + dir * t, T(1));
            // Away from the gate (n.l = 0), where the limit is not uniform.
            RC_PRE(std::abs(double(phong::detail::dot(phong::detail::normalize(n), dir))) > 1e-2);
            phong::environment<T> env;
            const vec3<T> a = phong::shade<F>(Q, n, mat, std::vector<phong::light<T>>{directional}, env);
            const vec3<T> b = phong::shade<F>(Q, n, mat, std::vector<phong::light<T>>{positional}, env);
            // The directions differ by about |Q| / t (plus the rounding of Q + t dir, ~eps), which
            // the specular power multiplies by m; plus the usual roundings.
            const double angle = (double(phong::detail::length(Q)) + 1) / double(t) + 4 * double(eps<T>);
            const double tol = (4 + 2 * double(mat.shininess)) * angle + 64 * double(eps<T>);
            for (int k = 0; k < 3; ++k) RC_ASSERT(std::abs(double(a[k]) - double(b[k])) <= tol);
        };
    };
    check_property("directional = lim_{t->inf} positional at Q + t dir (classic)", property(std::integral_constant<features, classic>{}));
    check_property("directional = lim_{t->inf} positional at Q + t dir (Blinn, stable)",
                   property(std::integral_constant<features, classic_blinn_stable>{}));
}

TEST_CASE_TEMPLATE("properties: attenuation is monotone non-increasing in distance", T, float, double)
{
    check_property("polynomial: d1 <= d2 => f(d1) >= f(d2)", [] {
        const T c0 = *grid<T>(0, 16, T(0.125)), c1 = *grid<T>(0, 16, T(0.125)), c2 = *grid<T>(0, 16, T(0.125));
        RC_PRE(c0 + c1 + c2 > T(0));
        T d1 = *grid<T>(0, 4000, T(1) / T(32)), d2 = *grid<T>(0, 4000, T(1) / T(32));
        if (d2 < d1) std::swap(d1, d2);
        const T f1 = phong::attenuation_polynomial(d1, c0, c1, c2), f2 = phong::attenuation_polynomial(d2, c0, c1, c2);
        RC_ASSERT(f1 >= f2);
        RC_ASSERT(f2 >= T(0));
        RC_ASSERT(std::isfinite(f1));
    });
    check_property("windowed: d1 <= d2 => f(d1) >= f(d2), 0 from the range on", [] {
        const T range = *grid<T>(1, 512, T(0.25));
        T d1 = *grid<T>(0, 4000, T(1) / T(32)), d2 = *grid<T>(0, 4000, T(1) / T(32));
        if (d2 < d1) std::swap(d1, d2);
        const T f1 = phong::attenuation_windowed(d1, range), f2 = phong::attenuation_windowed(d2, range);
        RC_ASSERT(f1 >= f2);
        RC_ASSERT(f2 >= T(0));
        RC_ASSERT(std::isfinite(f1));
        if (d2 >= range) RC_ASSERT(f2 == T(0));
    });
    check_property("shade: a light moved away along its direction gets no brighter (attenuation, spot none)", [] {
        constexpr features F{.attenuation = phong::attenuation_model::polynomial};
        const vec3<T> Q = gen_point<T>(), n = gen_normal<T>();
        const vec3<T> dir = phong::detail::normalize(*gen_nonzero_vec3<T>(-8, 8, T(0.25)));
        phong::light<T> L = *gen_light<T>(false);
        L.attenuation = {T(1), *grid<T>(0, 16, T(0.125)), *grid<T>(0, 16, T(0.125)), std::numeric_limits<T>::infinity()};
        // Away from the gate (n.l = 0), where the specular term jumps.
        RC_PRE(std::abs(double(phong::detail::dot(phong::detail::normalize(n), dir))) > 1e-2);
        const T t1 = *grid<T>(1, 256, T(0.125)), t2 = *grid<T>(1, 256, T(0.125));
        phong::material<T> mat = *gen_material<T>(64);
        phong::light<T> near_light = L, far_light = L;
        near_light.position = vec4<T>(Q + dir * std::min(t1, t2), T(1));
        far_light.position = vec4<T>(Q + dir * std::max(t1, t2), T(1));
        phong::environment<T> env;
        const vec3<T> a = phong::shade<F>(Q, n, mat, std::vector<phong::light<T>>{near_light}, env);
        const vec3<T> b = phong::shade<F>(Q, n, mat, std::vector<phong::light<T>>{far_light}, env);
        // The same l up to the rounding of Q + t dir (an angle of about eps |Q| / t, which the
        // specular power multiplies by m); r.v and n.l stay put, f decreases. Values are <= 2.
        const double angle = 4 * double(eps<T>) * (1 + double(phong::detail::length(Q)) / double(std::min(t1, t2)));
        for (int k = 0; k < 3; ++k) RC_ASSERT(double(b[k]) <= double(a[k]) + (8 + 2 * double(mat.shininess)) * angle);
    });
}

TEST_CASE_TEMPLATE("properties: the general view vector equals seed 000's formulas", T, float, double)
{
    // glm::perspective and off-axis glm::frustum: view_vector(eye_from_projection(M), Q) =
    // phong::detail::view_perspective(Q) = normalize(O - Q).
    check_property("perspective, frustum: v = normalize(-Q)", [] {
        const vec3<T> Q = gen_point<T>();
        mat4<T> M;
        if (*rc::gen::arbitrary<bool>()) {
            M = glm::perspective(*grid<T>(2, 30, T(0.1)), *grid<T>(2, 40, T(0.1)), T(0.1), *grid<T>(2, 100, T(10)));
        } else {
            const T l = *grid<T>(-40, -1, T(0.05)), r = *grid<T>(1, 40, T(0.05));
            const T b = *grid<T>(-40, -1, T(0.05)), t = *grid<T>(1, 40, T(0.05));
            const T dx = *grid<T>(-20, 20, T(0.05)); // shift the window off axis
            M = glm::frustum(l + dx, r + dx, b, t, *grid<T>(1, 10, T(0.1)), T(100));
        }
        const vec3<T> v = phong::view_vector(phong::eye_from_projection(M), Q);
        RC_ASSERT(near(v, phong::detail::view_perspective(Q), 16, T(1)));
    });
    // glm::ortho and an oblique orthographic matrix (ortho times a shear): view_orthographic's
    // formula normalize(-M02/M00, -M12/M11, 1) is the definition.
    check_property("ortho, oblique ortho: v = normalize(-M02/M00, -M12/M11, 1)", [] {
        const vec3<T> Q = gen_point<T>();
        const T l = *grid<T>(-40, -1, T(0.25)), r = *grid<T>(1, 40, T(0.25));
        const T b = *grid<T>(-40, -1, T(0.25)), t = *grid<T>(1, 40, T(0.25));
        mat4<T> M = glm::ortho(l, r, b, t, *grid<T>(-10, 10, T(0.1)), T(50));
        mat4<T> S(T(1));
        S[2][0] = *grid<T>(-16, 16, T(1) / T(16)); // x += a z
        S[2][1] = *grid<T>(-16, 16, T(1) / T(16)); // y += b z
        M = M * S;
        const vec3<T> v = phong::view_vector(phong::eye_from_projection(M), Q);
        RC_ASSERT(near(v, phong::detail::view_orthographic(M), 16, T(1)));
        // And the shear itself: v = normalize(-a, -b, 1) (M02/M00 = a, M12/M11 = b by construction).
        RC_ASSERT(near(v, phong::detail::normalize(vec3<T>(-S[2][0], -S[2][1], T(1))), 16, T(1)));
    });
}

TEST_CASE_TEMPLATE("properties: the constexpr path equals the run-time path within constexpr_tolerance_ulp", T, float, double)
{
    const auto tol = std::uint64_t(phong::detail::constexpr_tolerance_ulp);
    check_property("ce::sqrt, exp, log, log1p, pow vs std::", [tol] {
        // x = mantissa * 2^e on grids: covers the exponent range of T.
        const int max_e = std::is_same_v<T, float> ? 100 : 800;
        const T x = std::ldexp(*grid<T>(1 << 10, 1 << 11, T(1) / T(1 << 10)), *rc::gen::inRange(-max_e, max_e));
        namespace ce = phong::detail::ce;
        RC_ASSERT(ulp_distance(T(ce::sqrt(x)), std::sqrt(x)) <= tol);
        RC_ASSERT(ulp_distance(T(ce::log(x)), std::log(x)) <= tol);
        const T xe = *grid<T>(-8000, 8000, std::is_same_v<T, float> ? T(0.01) : T(0.08));
        RC_ASSERT(ulp_distance(T(ce::exp(xe)), std::exp(xe)) <= tol);
        const T x1 = *grid<T>(-999, 100000, T(1) / T(1000));
        RC_ASSERT(ulp_distance(T(ce::log1p(x1)), std::log1p(x1)) <= tol);
        const T base = *grid<T>(1, 1024, T(1) / T(1024)), m = *grid<T>(0, 2000, T(0.25));
        const T p = std::pow(base, m);
        if (std::isnormal(p)) RC_ASSERT(ulp_distance(T(ce::pow(base, m)), p) <= tol);
    });
}
