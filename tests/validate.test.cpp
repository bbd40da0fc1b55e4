// validate(light), validate(material) and validate(environment) (light.hpp, material.hpp,
// environment.hpp, validate.hpp): every rejection listed in their doc comments, each message
// naming the field the user set (light.attenuation.linear, not "coefficients"), the acceptance of valid and documented-degenerate parameters,
// and the same at compile time.
#include <phong/inputs/environment.hpp>
#include <phong/inputs/light.hpp>
#include <phong/inputs/material.hpp>

#include <doctest/doctest.h>

#include <cstring>
#include <functional>
#include <limits>
#include <string>

namespace {
template <class T> using vec3 = glm::vec<3, T>;
template <class T> using vec4 = glm::vec<4, T>;
template <class T> constexpr T pinf = std::numeric_limits<T>::infinity();
template <class T> constexpr T qnan = std::numeric_limits<T>::quiet_NaN();

// Rejected, with a message that names `field`.
template <class X> bool rejected(const X& x, const char* field)
{
    const phong::validation r = phong::validate(x);
    return !static_cast<bool>(r) && std::string(r.message()).find(field) != std::string::npos;
}
} // namespace

TEST_CASE_TEMPLATE("validate(light): valid lights are accepted", T, float, double)
{
    phong::light<T> L{};
    CHECK(static_cast<bool>(phong::validate(L)));
    CHECK(std::string(phong::validate(L).message()) == "ok");
    CHECK(static_cast<bool>(phong::validate(phong::light<T>::with_strength(vec4<T>(1, 2, 3, 1), vec3<T>(0.5)))));
    L.position = vec4<T>(-4, 5, 6, 1);
    L.ambient = vec3<T>(0.1);
    L.attenuation = {T(0), T(0), T(1), T(10)}; // c0 = 0 allowed when c2 > 0
    L.spot = phong::spot_cone<T>::opengl(vec3<T>(0, -1, 0), T(10), T(45));
    CHECK(static_cast<bool>(phong::validate(L)));
    L.spot = phong::spot_cone<T>::smooth(vec3<T>(0, -1, 0), T(10), T(30));
    CHECK(static_cast<bool>(phong::validate(L)));
    L.spot.cos_inner = L.spot.cos_outer; // equal cones: a hard edge, allowed
    CHECK(static_cast<bool>(phong::validate(L)));
    // Documented: a directional light with xyz = 0 is accepted (contributes its ambient only).
    phong::light<T> zero{};
    zero.position = vec4<T>(0);
    CHECK(static_cast<bool>(phong::validate(zero)));
    // Cutoff 90 degrees (cos 0) and 0 degrees (cos 1) are the ends of the valid range.
    zero.spot.cos_cutoff = T(0);
    CHECK(static_cast<bool>(phong::validate(zero)));
    zero.spot.cos_cutoff = T(1);
    CHECK(static_cast<bool>(phong::validate(zero)));
    // w = -0 is w = 0 (IEEE: -0 == 0): a directional light.
    zero.position = vec4<T>(1, 2, 3, -T(0));
    CHECK(static_cast<bool>(phong::validate(zero)));
}

// Issue 15 item 5: light_kind::any shaded a light with w = 2 at xyz / w, while ::positional and
// ::directional ignore w (xyz and direction xyz). The document's convention, w = 1 positional and
// w = 0 directional, is now the domain: every other w is rejected, with a message naming the field.
TEST_CASE_TEMPLATE("validate(light): w must be exactly 0 or 1", T, float, double)
{
    using L = phong::light<T>;
    const T eps = std::numeric_limits<T>::epsilon();
    const T denorm = std::numeric_limits<T>::denorm_min();
    for (T w : {T(2), T(0.5), T(1) + eps, T(1) - eps / 2, denorm, -denorm, T(-1), std::numeric_limits<T>::max(), T(3)}) {
        CAPTURE(w);
        const L light = L::with_strength(vec4<T>(1, 2, 3, w), vec3<T>(1));
        const phong::validation r = phong::validate(light);
        CHECK_FALSE(static_cast<bool>(r));
        CHECK(std::string(r.message()).find("light.position.w") != std::string::npos);
    }
    for (T w : {T(0), -T(0), T(1)}) {
        CAPTURE(w);
        CHECK(static_cast<bool>(phong::validate(L::with_strength(vec4<T>(1, 2, 3, w), vec3<T>(1)))));
    }
}
static_assert(!phong::validate(phong::light<float>{.position = {1.0f, 2.0f, 3.0f, 2.0f}}));
static_assert(!phong::validate(phong::light<double>{.position = {1.0, 2.0, 3.0, 0.5}}));
static_assert(static_cast<bool>(phong::validate(phong::light<double>{.position = {1.0, 2.0, 3.0, 1.0}})));

TEST_CASE_TEMPLATE("light::seed000: one strength L_i for diffuse and specular, no ambient", T, float, double)
{
    const phong::falloff<T> fall{T(1), T(0.5), T(0.25), T(10)};
    const auto L = phong::light<T>::with_strength(vec4<T>(1, 2, 3, 0), vec3<T>(0.25, 0.5, 0.75), fall);
    CHECK(L.position == vec4<T>(1, 2, 3, 0));
    CHECK(L.diffuse == vec3<T>(0.25, 0.5, 0.75));
    CHECK(L.specular == vec3<T>(0.25, 0.5, 0.75));
    CHECK(L.ambient == vec3<T>(0));
    CHECK(L.attenuation.linear == T(0.5));
    CHECK(L.attenuation.range == T(10));
    // Defaults: no attenuation (f = 1), no spot.
    const phong::light<T> d{};
    CHECK(d.attenuation.constant == T(1));
    CHECK(d.attenuation.linear == T(0));
    CHECK(d.attenuation.quadratic == T(0));
    CHECK(d.spot.cos_cutoff == T(-1));
}

TEST_CASE_TEMPLATE("validate(light): each documented rejection", T, float, double)
{
    using light = phong::light<T>;
    struct bad {
        const char* field;
        std::function<void(light&)> spoil;
    };
    const bad cases[] = {
        {"light.position", [](light& L) { L.position.x = qnan<T>; }},
        {"light.position", [](light& L) { L.position.y = pinf<T>; }},
        {"light.position", [](light& L) { L.position.w = pinf<T>; }},
        {"light.position.w", [](light& L) { L.position.w = T(-1); }},
        {"light.position.w", [](light& L) { L.position.w = T(2); }},
        {"light.position.w", [](light& L) { L.position.w = T(0.5); }},
        {"light.ambient", [](light& L) { L.ambient.r = T(-0.1); }},
        {"light.ambient", [](light& L) { L.ambient.g = qnan<T>; }},
        {"light.ambient", [](light& L) { L.ambient.b = pinf<T>; }},
        {"light.diffuse", [](light& L) { L.diffuse.r = T(-1); }},
        {"light.diffuse", [](light& L) { L.diffuse.b = qnan<T>; }},
        {"light.diffuse", [](light& L) { L.diffuse.g = pinf<T>; }},
        {"light.specular", [](light& L) { L.specular.g = T(-1e-30); }},
        {"light.specular", [](light& L) { L.specular.r = qnan<T>; }},
        {"light.specular", [](light& L) { L.specular.b = pinf<T>; }},
        {"light.attenuation.constant", [](light& L) { L.attenuation.constant = T(-1); }},
        {"light.attenuation.linear", [](light& L) { L.attenuation.linear = T(-0.5); }},
        {"light.attenuation.quadratic", [](light& L) { L.attenuation.quadratic = T(-0.5); }},
        {"light.attenuation.constant", [](light& L) { L.attenuation.constant = qnan<T>; }},
        {"light.attenuation.linear", [](light& L) { L.attenuation.linear = pinf<T>; }},
        {"light.attenuation.quadratic", [](light& L) { L.attenuation.quadratic = pinf<T>; }},
        {"light.attenuation", [](light& L) { L.attenuation = {T(0), T(0), T(0), pinf<T>}; }}, // all zero
        {"constant + linear + quadratic", [](light& L) { L.attenuation = {T(0), T(0), T(0), pinf<T>}; }}, // the user's names, not c0, c1, c2
        {"light.attenuation.range", [](light& L) { L.attenuation.range = T(0); }},
        {"light.attenuation.range", [](light& L) { L.attenuation.range = T(-3); }},
        {"light.attenuation.range", [](light& L) { L.attenuation.range = qnan<T>; }},
        {"light.spot.exponent", [](light& L) { L.spot.exponent = T(-1); }},
        {"light.spot.exponent", [](light& L) { L.spot.exponent = pinf<T>; }},
        {"light.spot.exponent", [](light& L) { L.spot.exponent = qnan<T>; }},
        {"light.spot.cos_cutoff", [](light& L) { L.spot.cos_cutoff = T(-0.5); }}, // 120 degrees
        {"light.spot.cos_cutoff", [](light& L) { L.spot.cos_cutoff = T(1.5); }},
        {"light.spot.cos_cutoff", [](light& L) { L.spot.cos_cutoff = qnan<T>; }},
        {"light.spot.cos_inner", [](light& L) { L.spot.cos_inner = T(1.5); }},
        {"light.spot.cos_outer", [](light& L) { L.spot.cos_outer = T(-1.5); }},
        {"light.spot.cos_inner", [](light& L) { L.spot.cos_inner = qnan<T>; }},
        {"light.spot.cos_outer", [](light& L) { L.spot.cos_outer = qnan<T>; }},
        {"light.spot.cos_outer", [](light& L) { L.spot.cos_inner = T(0.5), L.spot.cos_outer = T(0.9); }}, // outer narrower
        {"light.spot.direction", [](light& L) { L.spot.direction = vec3<T>(0, 0, -2); }},
        {"light.spot.direction", [](light& L) { L.spot.direction = vec3<T>(0, 0, T(-1.01)); }},
        {"light.spot.direction", [](light& L) { L.spot.direction = vec3<T>(qnan<T>, 0, 1); }},
    };
    for (const bad& b : cases) {
        light L = light::with_strength(vec4<T>(1, 2, 3, 1), vec3<T>(1));
        REQUIRE(static_cast<bool>(phong::validate(L)));
        b.spoil(L);
        CAPTURE(b.field);
        CAPTURE(phong::validate(L).message());
        CHECK(rejected(L, b.field));
    }
    // The spot axis tolerance is 1e-3 on the length (documented): 1.0004 passes.
    light L{};
    L.spot.direction = vec3<T>(0, 0, T(-1.0004));
    CHECK(static_cast<bool>(phong::validate(L)));
    // A zero axis is no cone (spot_cone's convention): accepted.
    L.spot.direction = vec3<T>(0);
    CHECK(static_cast<bool>(phong::validate(L)));
    L.spot.direction = vec3<T>(T(-0.0), 0, T(-0.0));
    CHECK(static_cast<bool>(phong::validate(L)));
    // A tiny axis is not zero, though its squared length underflows in T (the wider route would
    // read it as a cone along x): rejected, naming the field.
    L.spot.direction = vec3<T>(std::numeric_limits<T>::denorm_min(), 0, 0);
    CHECK(rejected(L, "light.spot.direction"));
}

TEST_CASE_TEMPLATE("validate(material): valid materials are accepted", T, float, double)
{
    phong::material<T> m{};
    CHECK(static_cast<bool>(phong::validate(m)));
    m.ka = m.kd = m.ks = m.emission = vec3<T>(0);
    m.shininess = T(0);
    m.alpha = T(0);
    CHECK(static_cast<bool>(phong::validate(m)));
    // Shininess above seed 001's 200 is accepted (documented); coefficients above 1 too (the
    // doc rejects only negative, NaN or inf).
    m.shininess = T(1e5);
    m.kd = vec3<T>(2);
    m.alpha = T(1);
    CHECK(static_cast<bool>(phong::validate(m)));
}

TEST_CASE_TEMPLATE("validate(material): each documented rejection", T, float, double)
{
    using material = phong::material<T>;
    struct bad {
        const char* field;
        std::function<void(material&)> spoil;
    };
    const bad cases[] = {
        {"material.ka", [](material& m) { m.ka.r = T(-0.1); }},
        {"material.ka", [](material& m) { m.ka.g = qnan<T>; }},
        {"material.ka", [](material& m) { m.ka.b = pinf<T>; }},
        {"material.kd", [](material& m) { m.kd.r = T(-1); }},
        {"material.kd", [](material& m) { m.kd.g = qnan<T>; }},
        {"material.kd", [](material& m) { m.kd.b = pinf<T>; }},
        {"material.ks", [](material& m) { m.ks.b = T(-1); }},
        {"material.ks", [](material& m) { m.ks.r = qnan<T>; }},
        {"material.ks", [](material& m) { m.ks.g = pinf<T>; }},
        {"material.emission", [](material& m) { m.emission.r = T(-1); }},
        {"material.emission", [](material& m) { m.emission.g = qnan<T>; }},
        {"material.emission", [](material& m) { m.emission.b = pinf<T>; }},
        {"material.shininess", [](material& m) { m.shininess = T(-1); }},
        {"material.shininess", [](material& m) { m.shininess = qnan<T>; }},
        {"material.shininess", [](material& m) { m.shininess = pinf<T>; }},
        {"material.alpha", [](material& m) { m.alpha = T(-0.01); }},
        {"material.alpha", [](material& m) { m.alpha = T(1.01); }},
        {"material.alpha", [](material& m) { m.alpha = qnan<T>; }},
    };
    for (const bad& b : cases) {
        material m{};
        b.spoil(m);
        CAPTURE(b.field);
        CAPTURE(phong::validate(m).message());
        CHECK(rejected(m, b.field));
    }
}

TEST_CASE_TEMPLATE("validate(environment): ambient and the eye's w", T, float, double)
{
    using environment = phong::environment<T>;
    environment e{};
    CHECK(static_cast<bool>(phong::validate(e)));
    e.ambient = vec3<T>(0, 2, 1e30); // no upper bound, as for a light's strengths
    e.eye = vec4<T>(1, 2, 3, 0);     // w = 0: a direction toward the viewer
    CHECK(static_cast<bool>(phong::validate(e)));
    e.eye.w = T(2); // any w > 0 is a point (xyz / w), as toward() reads it
    CHECK(static_cast<bool>(phong::validate(e)));
    // The eye is an input of the NaN policy (NaN in, NaN out; shade.hpp), not a parameter error.
    e.eye = vec4<T>(qnan<T>, 0, 0, 1);
    CHECK(static_cast<bool>(phong::validate(e)));
    e.eye.w = -pinf<T>;
    CHECK(static_cast<bool>(phong::validate(e)));
    struct bad {
        const char* field;
        std::function<void(environment&)> spoil;
    };
    const bad cases[] = {
        {"environment.ambient", [](environment& x) { x.ambient.r = T(-0.25); }},
        {"environment.ambient", [](environment& x) { x.ambient.g = qnan<T>; }},
        {"environment.ambient", [](environment& x) { x.ambient.b = pinf<T>; }},
        {"environment.eye.w", [](environment& x) { x.eye.w = T(-1); }}, // would turn v away from the viewer
    };
    for (const bad& b : cases) {
        environment x{};
        b.spoil(x);
        CAPTURE(b.field);
        CAPTURE(phong::validate(x).message());
        CHECK(rejected(x, b.field));
    }
}
static_assert(!phong::validate(phong::environment<float>{.ambient = glm::vec3(-1.0f)}));
static_assert(static_cast<bool>(phong::validate(phong::environment<double>{})));

// validate is constexpr: the same answers at compile time.
namespace {
constexpr phong::light<float> bad_light()
{
    phong::light<float> L{};
    L.attenuation.range = -1.0f;
    return L;
}
constexpr phong::material<double> bad_material()
{
    phong::material<double> m{};
    m.shininess = -2;
    return m;
}
static_assert(static_cast<bool>(phong::validate(phong::light<float>{})));
static_assert(static_cast<bool>(phong::validate(phong::material<double>{})));
static_assert(!static_cast<bool>(phong::validate(bad_light())));
static_assert(!static_cast<bool>(phong::validate(bad_material())));
} // namespace

TEST_CASE("validate: the compile-time answers name the field")
{
    CHECK(std::strstr(phong::validate(bad_light()).message(), "range") != nullptr);
    CHECK(std::strstr(phong::validate(bad_material()).message(), "shininess") != nullptr);
}
