// The NaN and bad-input policy stated in README.md ("Supported compilers, NaN and bad input") and in
// shade.hpp's doc comment, one check per statement:
//  1. NaN or inf in the position, the normal or (view_model::eye_point) the eye: every channel NaN,
//     alpha included; the eye is not read by the perspective view, so a NaN there changes nothing.
//  2. Finite, in-domain input never gives NaN or inf, degenerate cases included.
//  3. validate(material) / validate(light) reject NaN, inf and out-of-range parameters, naming the
//     field, and accept the ends of the domain.
//  4. shade() asserts validate() in debug builds and rejects invalid parameters in constant
//     evaluation: those two need a process that aborts and a program that does not compile, so
//     they are ctests of their own (tests/nan_policy/, registered by tests/nan_policy/checks.cmake).
#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <type_traits>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using namespace phong;

template <class T> constexpr T nan_v = std::numeric_limits<T>::quiet_NaN();
template <class T> constexpr T inf_v = std::numeric_limits<T>::infinity();

template <class T> std::array<T, 3> bad_values() { return {nan_v<T>, inf_v<T>, -inf_v<T>}; }

// Feature sets covering both evaluation modes, both specular models, every view model, alpha.
constexpr features plain{};
constexpr features classic = presets::classic_phong; // eye_point, alpha, polynomial, two-sided
constexpr features raytracer_stable = presets::with_mode(presets::blinn_phong_per_light_ambient, evaluation::stable);
constexpr features spot_windowed{.light_ambient = true, .specular = specular_model::blinn,
                                 .attenuation = attenuation_model::windowed, .spot = spot_model::smooth,
                                 .two_sided = facing::flag, .view = view_model::fixed_direction, .emission = true,
                                 .alpha = true, .mode = evaluation::stable};

template <class T> struct scene {
    glm::vec<3, T> position{T(0.5), T(-0.25), T(-4)};
    glm::vec<3, T> normal{T(0.125), T(0.25), T(1)};
    material<T> mat{.ka = glm::vec<3, T>(T(0.25)), .kd = glm::vec<3, T>(T(0.5)), .ks = glm::vec<3, T>(T(0.5)),
                    .emission = glm::vec<3, T>(T(0.0625)), .shininess = T(20), .alpha = T(0.75)};
    std::vector<light<T>> lights;
    environment<T> env{.ambient = glm::vec<3, T>(T(0.125)), .eye = glm::vec<4, T>(T(0), T(0), T(0), T(1))};

    scene()
    {
        light<T> a = light<T>::with_strength({T(2), T(3), T(1), T(1)}, glm::vec<3, T>(T(1)), {T(1), T(0.125), T(0.0625), T(50)});
        a.ambient = glm::vec<3, T>(T(0.25));
        light<T> b = light<T>::with_strength({T(0), T(1), T(1), T(0)}, glm::vec<3, T>(T(0.5)));
        lights = {a, b};
    }
};

// By the bits (exponent all ones), not std::isnan / std::isfinite, which -ffinite-math-only folds
// to constants: these checks also run in .ci/steps/36-fast-math.sh.
template <class T> bool exponent_all_ones(T x)
{
    using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const U e = sizeof(T) == 4 ? U(0x7f800000u) : U(0x7ff0000000000000ull);
    return (std::bit_cast<U>(x) & e) == e;
}
template <class T> bool bits_nan(T x)
{
    using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const U mantissa = sizeof(T) == 4 ? U(0x007fffffu) : U(0x000fffffffffffffull);
    return exponent_all_ones(x) && (std::bit_cast<U>(x) & mantissa) != 0;
}
template <class V> int nan_channels(const V& c)
{
    int n = 0;
    for (glm::length_t k = 0; k < V::length(); ++k) n += bits_nan(c[k]) ? 1 : 0;
    return n;
}
template <class V> bool all_finite(const V& c)
{
    for (glm::length_t k = 0; k < V::length(); ++k)
        if (exponent_all_ones(c[k])) return false;
    return true;
}

// A ray tracer's view vector given per call (view_model::given), plain and with unit inputs (the
// normal and view are unit by precondition; the position is not covered by it).
constexpr features given_view = [] {
    features f = presets::raytracer_phong;
    f.view = view_model::given;
    return f;
}();
constexpr features given_unit = [] {
    features f = given_view;
    f.unit_inputs = true;
    return f;
}();

template <features F, class T> auto shade_scene(const scene<T>& s)
{
    if constexpr (F.view == view_model::given) {
        const glm::vec<3, T> v = F.unit_inputs ? glm::vec<3, T>(T(0), T(0.6), T(0.8)) : glm::vec<3, T>(T(0), T(1.5), T(2));
        const glm::vec<3, T> n = F.unit_inputs ? glm::vec<3, T>(T(0.6), T(0), T(0.8)) : s.normal;
        return shade<F>(s.position, n, v, s.mat, s.lights, s.env, true);
    } else {
        return shade<F>(s.position, s.normal, s.mat, s.lights, s.env, true);
    }
}

/// The position-only checks also run the given-view feature sets (their normal comes from
/// shade_scene, unit where unit_inputs asks for it).
template <class T, class Mutate, class Check> void for_each_given_view_set(Mutate mutate, Check check)
{
    scene<T> s;
    mutate(s);
    check(shade_scene<given_view>(s), 3, "given view");
    check(shade_scene<given_unit>(s), 3, "given view, unit inputs");
}

/// Runs `check(shade<F>(...), channel count)` for each of the four feature sets.
template <class T, class Mutate, class Check> void for_each_feature_set(Mutate mutate, Check check)
{
    scene<T> s;
    mutate(s);
    check(shade_scene<plain>(s), 3, "plain");
    check(shade_scene<classic>(s), 4, "classic_phong");
    // -ffast-math: double's stable mode (twofold) refuses the build (docs/compilers.md).
    if constexpr (phong::detail::ieee::twofold_allowed<T> || sizeof(T) == 4) check(shade_scene<raytracer_stable>(s), 3, "seed001 stable");
    if constexpr (phong::detail::ieee::twofold_allowed<T> || sizeof(T) == 4) check(shade_scene<spot_windowed>(s), 4, "spot_windowed");
}

} // namespace

TEST_CASE_TEMPLATE("NaN policy: NaN or inf in the position gives NaN in every channel", T, float, double)
{
    for (T bad : bad_values<T>()) {
        for (int k = 0; k < 3; ++k) {
            for_each_feature_set<T>([&](scene<T>& s) { s.position[k] = bad; },
                                    [&](const auto& c, int channels, const char* name) {
                                        INFO(name, ", position[", k, "] = ", bad);
                                        CHECK(nan_channels(c) == channels);
                                    });
            for_each_given_view_set<T>([&](scene<T>& s) { s.position[k] = bad; },
                                       [&](const auto& c, int channels, const char* name) {
                                           INFO(name, ", position[", k, "] = ", bad);
                                           CHECK(nan_channels(c) == channels);
                                       });
        }
    }
}

TEST_CASE_TEMPLATE("NaN policy: NaN or inf in the normal gives NaN in every channel", T, float, double)
{
    for (T bad : bad_values<T>()) {
        for (int k = 0; k < 3; ++k) {
            for_each_feature_set<T>([&](scene<T>& s) { s.normal[k] = bad; },
                                    [&](const auto& c, int channels, const char* name) {
                                        INFO(name, ", normal[", k, "] = ", bad);
                                        CHECK(nan_channels(c) == channels);
                                    });
        }
    }
}

TEST_CASE_TEMPLATE("NaN policy: NaN or inf in the eye gives NaN for view_model::eye_point only", T, float, double)
{
    for (T bad : bad_values<T>()) {
        for (int k = 0; k < 4; ++k) {
            scene<T> s;
            const auto reference = shade_scene<plain>(s);
            s.env.eye[k] = bad;
            INFO("eye[", k, "] = ", bad);
            CHECK(nan_channels(shade_scene<classic>(s)) == 4); // eye_point: every channel, alpha too
            const auto perspective = shade_scene<plain>(s);     // perspective: the eye is not read
            for (int c = 0; c < 3; ++c) CHECK(perspective[c] == reference[c]);
        }
    }
}

TEST_CASE_TEMPLATE("NaN policy: finite degenerate input gives finite output", T, float, double)
{
    const auto check_finite = [](const auto& c, int, const char* name) {
        INFO(name);
        CHECK(all_finite(c));
    };
    // Zero normal; point at the eye (v = 0); light at the point (no direction).
    for_each_feature_set<T>([](scene<T>& s) { s.normal = glm::vec<3, T>(T(0)); }, check_finite);
    for_each_feature_set<T>([](scene<T>& s) { s.position = glm::vec<3, T>(T(0)); }, check_finite);
    for_each_feature_set<T>([](scene<T>& s) { s.lights[0].position = glm::vec<4, T>(s.position, T(1)); }, check_finite);
    // c0 = 0 with the light at the point: f is capped, not inf.
    for_each_feature_set<T>([](scene<T>& s) {
        s.lights[0].position = glm::vec<4, T>(s.position, T(1));
        s.lights[0].attenuation = {T(0), T(0), T(1), inf_v<T>};
    }, check_finite);
    // A directional light with xyz = 0; m = 0; Blinn with l = -v (light behind the eye's direction).
    for_each_feature_set<T>([](scene<T>& s) { s.lights[1].position = glm::vec<4, T>(T(0)); }, check_finite);
    for_each_feature_set<T>([](scene<T>& s) { s.mat.shininess = T(0); }, check_finite);
    for_each_feature_set<T>([](scene<T>& s) { s.lights[1].position = glm::vec<4, T>(s.position, T(0)); }, check_finite);
    // Huge and tiny (subnormal) finite coordinates.
    const T huge = std::numeric_limits<T>::max() / T(8), tiny = std::numeric_limits<T>::denorm_min();
    for_each_feature_set<T>([&](scene<T>& s) { s.position = glm::vec<3, T>(huge, -huge, tiny); }, check_finite);
    for_each_feature_set<T>([&](scene<T>& s) { s.normal = glm::vec<3, T>(tiny, 0, tiny); }, check_finite);
    for_each_feature_set<T>([&](scene<T>& s) { s.normal = glm::vec<3, T>(huge, huge, huge); }, check_finite);
    // L.xyz - w Q and E.xyz - E.w Q overflow although every input is finite (|w Q| > max, or
    // |L.xyz - Q| > max with w = 1; a light's w is 0 or 1, validate(light)): that light (or the
    // view) has no direction, never NaN (the smooth spot used to turn inf * 0 into NaN).
    const T top = std::numeric_limits<T>::max();
    for_each_feature_set<T>([&](scene<T>& s) { s.env.eye.w = top; }, check_finite);
    for_each_feature_set<T>([&](scene<T>& s) { s.lights[0].position = glm::vec<4, T>(top, -top, top, T(1)); s.position = glm::vec<3, T>(-top, top, -top); }, check_finite);
    // A far light exactly opposite the viewer (l = -v in the high parts, l + v carried only by the
    // rounding errors): the stable Blinn halfway vector used to overflow its low part (NaN).
    for_each_feature_set<T>([&](scene<T>& s) {
        s.position = glm::vec<3, T>(T(11.875));
        s.env.eye = glm::vec<4, T>(T(0), T(1), T(0), T(0));
        s.lights[0].position = glm::vec<4, T>(T(1), -top, T(1), T(1));
    }, check_finite);
}

TEST_CASE_TEMPLATE("NaN policy: an OpenGL spot aimed at the point with a huge exponent stays finite, spot <= 1", T, float, double)
{
#if PHONG_FP_REASSOCIATION && !defined(PHONG_ALLOW_REASSOCIATED_TWOFOLD)
    if constexpr (sizeof(T) == 8) return; // -ffast-math: double's stable mode refuses the build (docs/compilers.md)
    else
#endif
    {
    // The axis is exactly -l as rounded, so c = -l.s is 1 up to rounding (1 + eps for some of these
    // directions); mathematically c <= 1, so spot = c^e <= 1 for every finite e >= 0.
    constexpr features F{.spot = spot_model::opengl, .mode = evaluation::stable};
    int above_one = 0;
    for (int i = 1; i <= 40; ++i) {
        for (int j = 1; j <= 40; ++j) {
            const glm::vec<3, T> d(T(i), T(j), T(3));
            const glm::vec<3, T> l = phong::detail::normalize(d);
            above_one += -phong::detail::dot(l, -l) > T(1) ? 1 : 0;
            for (T e : {T(1e4), T(1e30), std::numeric_limits<T>::max()}) {
                INFO("d = (", i, ", ", j, ", 3), e = ", e);
                const T spot = spot_opengl(l, glm::vec<3, T>(-l), e, T(0.5));
                CHECK(spot >= T(0));
                CHECK(spot <= T(1));
                scene<T> s;
                s.lights.resize(1);
                s.lights[0].position = glm::vec<4, T>(s.position + d, T(1));
                s.lights[0].spot.direction = -l;
                s.lights[0].spot.exponent = e;
                s.lights[0].spot.cos_cutoff = T(0.5);
                REQUIRE(static_cast<bool>(validate(s.lights[0])));
                CHECK(all_finite(shade_scene<F>(s)));
            }
        }
    }
    CHECK(above_one > 0); // the grid does reach c > 1 (else this test would prove nothing)
    }
}

namespace {

/// Expects validate(x) to fail with a message containing `field`.
template <class X> void expect_rejected(const X& x, const char* field)
{
    const validation v = validate(x);
    INFO("expected rejection naming ", field, ", got: ", v.message());
    CHECK_FALSE(static_cast<bool>(v));
    CHECK(std::string(v.message()).find(field) != std::string::npos);
}

} // namespace

// README's overflow example: c0 = 1e-3 at distance 1 (f = 1000), Ld = 1e36, kd = (0, 0.5, 0.5).
// The light sum f Ld = 1e39 overflows float: the exact mode gives inf, and 0 * inf = NaN in the
// channel whose coefficient is 0; the stable mode sums in double, where nothing overflows, and only
// the final rounding to float is inf: (0, inf, inf).
TEST_CASE("NaN policy: an overflowing light sum, exact against stable float")
{
    constexpr features exact{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::positional,
                             .attenuation = attenuation_model::polynomial};
    constexpr features stable = presets::with_mode(exact, evaluation::stable);
    light<float> L = light<float>::with_strength({0, 0, -3, 1}, glm::vec3(1e36f), {1e-3f, 0, 0, std::numeric_limits<float>::infinity()});
    const std::array<light<float>, 1> lights{L};
    const material<float> mat{.ka = glm::vec3(0), .kd = glm::vec3(0, 0.5f, 0.5f), .ks = glm::vec3(0)};
    const glm::vec3 q(0, 0, -4), n(0, 0, 1); // the light 1 above Q: n.l = 1, f = 1 / 1e-3
    REQUIRE(validate(L));
    const glm::vec3 e = shade<exact>(q, n, mat, lights), s = shade<stable>(q, n, mat, lights);
    CHECK(std::isnan(e.x));
    CHECK(std::isinf(e.y));
    CHECK(std::isinf(e.z));
    CHECK(s.x == 0.0f);
    CHECK(std::isinf(s.y));
    CHECK(std::isinf(s.z));
    // Just below float's range the stable mode is finite and correctly rounded: 1e35 * 1000 * 0.5.
    L.diffuse = glm::vec3(1e35f);
    const std::array<light<float>, 1> smaller{L};
    const glm::vec3 f = shade<stable>(q, n, mat, smaller);
    CHECK(f.x == 0.0f);
    CHECK(f.y == float(double(1e35f) * (1.0 / double(1e-3f)) * 0.5));
}

TEST_CASE_TEMPLATE("NaN policy: validate(material) rejects NaN, inf and out-of-range parameters", T, float, double)
{
    const material<T> ok{};
    REQUIRE(static_cast<bool>(validate(ok)));
    for (T bad : {nan_v<T>, inf_v<T>, -inf_v<T>, T(-1), -std::numeric_limits<T>::denorm_min()}) {
        INFO("bad value ", bad);
        for (int k = 0; k < 3; ++k) {
            material<T> m = ok;
            m.ka[k] = bad;
            expect_rejected(m, "material.ka");
            m = ok;
            m.kd[k] = bad;
            expect_rejected(m, "material.kd");
            m = ok;
            m.ks[k] = bad;
            expect_rejected(m, "material.ks");
            m = ok;
            m.emission[k] = bad;
            expect_rejected(m, "material.emission");
        }
        material<T> m = ok;
        m.shininess = bad;
        expect_rejected(m, "material.shininess");
        m = ok;
        m.alpha = bad;
        expect_rejected(m, "material.alpha");
    }
    material<T> m = ok;
    m.alpha = T(1) + std::numeric_limits<T>::epsilon();
    expect_rejected(m, "material.alpha");
    // The ends of the domain are accepted: zero coefficients (also -0), m = 0, alpha 0 and 1, huge m.
    m = ok;
    m.ka = glm::vec<3, T>(-T(0));
    m.shininess = T(0);
    m.alpha = T(0);
    CHECK(static_cast<bool>(validate(m)));
    m.alpha = T(1);
    m.shininess = std::numeric_limits<T>::max();
    CHECK(static_cast<bool>(validate(m)));
}

TEST_CASE_TEMPLATE("NaN policy: validate(light) rejects NaN, inf and out-of-range parameters", T, float, double)
{
    const light<T> ok{};
    REQUIRE(static_cast<bool>(validate(ok)));
    for (T bad : {nan_v<T>, inf_v<T>, -inf_v<T>}) {
        INFO("bad value ", bad);
        for (int k = 0; k < 4; ++k) {
            light<T> L = ok;
            L.position[k] = bad;
            expect_rejected(L, "light.position");
        }
        light<T> L = ok;
        L.spot.exponent = bad;
        expect_rejected(L, "light.spot.exponent");
        L = ok;
        L.spot.direction.x = bad;
        expect_rejected(L, "light.spot.direction");
        L = ok;
        L.spot.cos_cutoff = bad;
        expect_rejected(L, "light.spot.cos_cutoff");
        L = ok;
        L.spot.cos_inner = bad;
        expect_rejected(L, "light.spot");
    }
    for (T bad : {nan_v<T>, inf_v<T>, -inf_v<T>, T(-0.5)}) {
        INFO("bad value ", bad);
        for (int k = 0; k < 3; ++k) {
            light<T> L = ok;
            L.ambient[k] = bad;
            expect_rejected(L, "light.ambient");
            L = ok;
            L.diffuse[k] = bad;
            expect_rejected(L, "light.diffuse");
            L = ok;
            L.specular[k] = bad;
            expect_rejected(L, "light.specular");
        }
        light<T> L = ok;
        L.attenuation.constant = bad;
        expect_rejected(L, "light.attenuation");
        L = ok;
        L.attenuation.linear = bad;
        expect_rejected(L, "light.attenuation");
        L = ok;
        L.attenuation.quadratic = bad;
        expect_rejected(L, "light.attenuation");
    }
    light<T> L = ok;
    L.position.w = T(-1);
    expect_rejected(L, "light.position.w");
    L = ok;
    L.attenuation = {T(0), T(0), T(0), inf_v<T>};
    expect_rejected(L, "light.attenuation");
    for (T range : {T(0), T(-1), nan_v<T>}) {
        L = ok;
        L.attenuation.range = range;
        expect_rejected(L, "light.attenuation.range");
    }
    for (T c : {T(-0.5), T(1.5), T(-1) - std::numeric_limits<T>::epsilon()}) {
        L = ok;
        L.spot.cos_cutoff = c;
        expect_rejected(L, "light.spot.cos_cutoff");
    }
    L = ok;
    L.spot.cos_inner = T(0.5);
    L.spot.cos_outer = T(0.75); // outer narrower than inner
    expect_rejected(L, "light.spot");
    L = ok;
    L.spot.direction = glm::vec<3, T>(T(0), T(0), T(-1.01));
    expect_rejected(L, "light.spot.direction");
    L.spot.direction = glm::vec<3, T>(T(0), T(0), T(-0.5));
    expect_rejected(L, "light.spot.direction");
    // The ends of the domain are accepted.
    L = ok;
    L.position = glm::vec<4, T>(T(0)); // directional with no direction: accepted (ambient only)
    L.attenuation = {T(0), T(0), std::numeric_limits<T>::denorm_min(), std::numeric_limits<T>::denorm_min()};
    L.spot.cos_cutoff = T(0);
    L.spot.cos_inner = T(1);
    L.spot.cos_outer = T(-1);
    CHECK(static_cast<bool>(validate(L)));
    L.spot.cos_cutoff = T(1);
    L.position.w = T(1);
    CHECK(static_cast<bool>(validate(L)));
    L.position.w = T(0.5); // only w = 0 and w = 1 (light.hpp)
    expect_rejected(L, "light.position.w");
}

// validate() is constexpr: the same answers in constant evaluation.
static_assert(static_cast<bool>(validate(material<float>{})));
static_assert(!validate(material<float>{.shininess = -1.0f}));
static_assert(!validate(material<double>{.alpha = std::numeric_limits<double>::quiet_NaN()}));
static_assert(!validate(light<float>{.position = {0.0f, 0.0f, 1.0f, -1.0f}}));
// ... infinite parameters included (validate once computed inf - inf, not a constant expression).
static_assert(!validate(material<float>{.ks = glm::vec3(std::numeric_limits<float>::infinity())}));
static_assert(!validate(light<double>{.diffuse = glm::dvec3(1.0, -std::numeric_limits<double>::infinity(), 1.0)}));
static_assert(!validate(light<double>{.position = {0.0, std::numeric_limits<double>::infinity(), 1.0, 1.0}}));
// A valid whole shade in constant evaluation compiles (the invalid counterpart must not: see
// tests/nan_policy/constexpr_reject.cpp).
static_assert([] {
    const std::array<light<float>, 1> lights{light<float>::with_strength({0, 0, 1, 0}, {1, 1, 1})};
    const glm::vec3 c = shade<features{}>(glm::vec3(0, 0, -2), glm::vec3(0, 0, 1), material<float>{}, lights,
                                          environment<float>{});
    return c.x > 0.0f && c.x == c.y && c.y == c.z; // .x, not .r: GLM's unions allow only the member written
}());
