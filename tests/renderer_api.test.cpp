// The renderer-facing API (issue 13): the view vector given per call, unit inputs, light lists as
// renderers hold them (any range, views, masks, weights, a renderer's own light type through a
// transform), and the terms returned separately. Each property compares two ways of asking for
// the same model, so the expected value is the library's own result on the equivalent input
// (the formulas themselves are checked against the __float128 reference elsewhere).
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/phong.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <ranges>
#include <span>
#include <vector>

using namespace phong;
using namespace phong_test;

// clang++ before 16 cannot compile libstdc++'s range views (llvm/llvm-project#44178): the view
// checks run with g++ (and newer clang); masked(), weighted() and every other check run everywhere.
#if defined(__clang__) && __clang_major__ < 16 && defined(__GLIBCXX__)
#  define PHONG_TEST_RANGE_VIEWS 0
#else
#  define PHONG_TEST_RANGE_VIEWS 1
#endif

namespace {

template <class T> using vec3 = glm::vec<3, T>;

/// Bitwise equality of two colours (NaN == NaN with the same bits, -0 != +0).
template <glm::length_t L, class T> bool same_bits(const glm::vec<L, T>& a, const glm::vec<L, T>& b)
{
    return std::memcmp(&a, &b, sizeof(a)) == 0;
}

/// The feature sets the properties run on: the ray tracer's preset, Blinn, diffuse only, with
/// attenuation and a spot, and each in exact and stable mode.
template <view_model View> constexpr std::array<features, 8> feature_sets()
{
    features base = presets::raytracer_phong;
    base.view = View;
    features blinn = base;
    blinn.specular = specular_model::blinn;
    blinn.light_ambient = true;
    features diffuse = presets::diffuse_only;
    diffuse.view = View;
    features spot = base;
    spot.attenuation = attenuation_model::polynomial;
    spot.spot = spot_model::smooth;
    spot.lights = light_kind::any;
    spot.emission = true;
    spot.alpha = true;
    return {base, blinn, diffuse, spot, presets::with_mode(base, evaluation::stable), presets::with_mode(blinn, evaluation::stable),
            presets::with_mode(diffuse, evaluation::stable), presets::with_mode(spot, evaluation::stable)};
}

/// Runs f.template operator()<F>() for every feature set of feature_sets<View>().
template <view_model View, class Fn> void for_each_feature_set(Fn&& fn)
{
    constexpr auto sets = feature_sets<View>();
    [&]<std::size_t... I>(std::index_sequence<I...>) { (fn.template operator()<sets[I]>(), ...); }(std::make_index_sequence<sets.size()>{});
}

constexpr features with_view(features f, view_model v)
{
    f.view = v;
    return f;
}
constexpr features with_unit_inputs(features f)
{
    f.unit_inputs = true;
    return f;
}
constexpr features blinn_given = [] {
    features f = presets::raytracer_phong;
    f.specular = specular_model::blinn;
    return f;
}();

/// A renderer's own light type: what a ray tracer keeps per light.
template <class T> struct my_light {
    vec3<T> position;
    vec3<T> color;
};

/// A renderer's light in a layout of its own, with every field the model reads: shaded through
/// the light_traits specialization below, never copied into a light<T>.
template <class T> struct renderer_light {
    T where[3];
    bool directional;
    vec3<T> glow, colour, highlight; // ambient, diffuse, specular
    T c0, c1, c2;
    spot_cone<T> cone;
};

/// The same light as a light<T>, field by field (what the traits must be equivalent to).
template <class T> light<T> as_light(const renderer_light<T>& r)
{
    light<T> L;
    L.position = glm::vec<4, T>(r.where[0], r.where[1], r.where[2], r.directional ? T(0) : T(1));
    L.ambient = r.glow;
    L.diffuse = r.colour;
    L.specular = r.highlight;
    L.attenuation = {r.c0, r.c1, r.c2, std::numeric_limits<T>::infinity()};
    L.spot = r.cone;
    return L;
}

} // namespace

template <class T> struct phong::light_traits<renderer_light<T>> {
    static glm::vec<4, T> position(const renderer_light<T>& r)
    {
        return {r.where[0], r.where[1], r.where[2], r.directional ? T(0) : T(1)};
    }
    static const vec3<T>& ambient(const renderer_light<T>& r) { return r.glow; }
    static const vec3<T>& diffuse(const renderer_light<T>& r) { return r.colour; }
    static vec3<T> specular(const renderer_light<T>& r) { return r.highlight; } // by value: either works
    static falloff<T> attenuation(const renderer_light<T>& r) { return {r.c0, r.c1, r.c2, std::numeric_limits<T>::infinity()}; }
    static const spot_cone<T>& spot(const renderer_light<T>& r) { return r.cone; }
};

/// The minimal adaptor: a point light with one colour (my_light), the optional fields left out.
template <class T> struct phong::light_traits<my_light<T>> {
    static glm::vec<4, T> position(const my_light<T>& L) { return glm::vec<4, T>(L.position, T(1)); }
    static const vec3<T>& diffuse(const my_light<T>& L) { return L.color; }
    static const vec3<T>& specular(const my_light<T>& L) { return L.color; }
};

static_assert(light_source<light<float>> && light_source<const light<double>&> && light_source<my_light<float>>);
static_assert(!light_source<int> && !light_source<glm::vec4> && !light_source<material<float>>,
              "a type without a light_traits specialization is not a light (tests/nan_policy/light_traits_reject.cpp: the error)");
static_assert(std::is_same_v<phong::detail::light_scalar_t<renderer_light<double>>, double>);

TEST_CASE_TEMPLATE("given view: v = -Q reproduces eye_at_origin, v = E - Q reproduces eye_point, bit for bit", T, float, double)
{
    scene_gen<T> g(101);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
        for_each_feature_set<view_model::given>([&]<features F>() {
            constexpr features at_origin = with_view(F, view_model::eye_at_origin);
            constexpr features at_eye = with_view(F, view_model::eye_point);
            const scene<T> s = g.make(F, 1 + i % 4);
            const vec3<T> Q = s.position;
            // -Q: the view vector eye_at_origin computes (as Q times -1/|Q|; the same bits).
            CHECK(same_bits(shade<F>(Q, s.normal, -Q, s.mat, s.lights, s.env), shade<at_origin>(Q, s.normal, s.mat, s.lights, s.env)));
            // E - Q for an eye point E (w = 1). Exact mode only: the stable mode carries the
            // rounding error of its own E - Q twofold, while a given v is exact input.
            if constexpr (F.mode == evaluation::stable) {
                ++compared;
                return;
            }
            environment<T> env = s.env;
            env.eye = glm::vec<4, T>(g.in_box(-2, 2), T(1));
            const vec3<T> to_eye = vec3<T>(env.eye) - Q;
            CHECK(same_bits(shade<F>(Q, s.normal, to_eye, s.mat, s.lights, env), shade<at_eye>(Q, s.normal, s.mat, s.lights, env)));
            ++compared;
        });
    }
    CHECK(compared == 300 * 8);
}

TEST_CASE_TEMPLATE("unit inputs: on unit normal and view the results equal the normalizing path", T, float, double)
{
    // Exactly unit vectors (|v|^2 rounds to 1, so normalizing multiplies by 1): bit for bit.
    // Random unit vectors (|v|^2 = 1 within a few eps): within the error that a relative change
    // of a few eps in n and v makes, amplified by m in the specular power.
    scene_gen<T> g(202);
    double worst = 0;
    for (int i = 0; i < 400; ++i) {
        constexpr features F = blinn_given, U = with_unit_inputs(blinn_given);
        constexpr features P = presets::raytracer_phong, PU = with_unit_inputs(presets::raytracer_phong);
        const scene<T> s = g.make(F, 1 + i % 4);
        const std::array<vec3<T>, 6> axes{vec3<T>(1, 0, 0), vec3<T>(0, 1, 0), vec3<T>(0, 0, 1),
                                          vec3<T>(T(0.6), T(0.8), 0), vec3<T>(0, T(-0.6), T(0.8)), vec3<T>(T(0.8), 0, T(-0.6))};
        const vec3<T> n_exact = axes[std::size_t(i) % 6], v_exact = axes[std::size_t(i / 6) % 6];
        CHECK(same_bits(shade<U>(s.position, n_exact, v_exact, s.mat, s.lights), shade<F>(s.position, n_exact, v_exact, s.mat, s.lights)));
        CHECK(same_bits(shade<PU>(s.position, n_exact, v_exact, s.mat, s.lights), shade<P>(s.position, n_exact, v_exact, s.mat, s.lights)));
        const vec3<T> n = phong::detail::normalize(s.normal), v = phong::detail::normalize(g.direction());
        const vec3<T> a = shade<U>(s.position, n, v, s.mat, s.lights), b = shade<F>(s.position, n, v, s.mat, s.lights);
        const vec3<T> c = shade<PU>(s.position, n, v, s.mat, s.lights), d = shade<P>(s.position, n, v, s.mat, s.lights);
        const double bound = (16 + 8 * double(s.mat.shininess)) * double(std::numeric_limits<T>::epsilon());
        for (int k = 0; k < 3; ++k) {
            const double scale = std::max(1.0, double(b[k]));
            worst = std::max(worst, std::abs(double(a[k]) - double(b[k])) / scale / bound);
            worst = std::max(worst, std::abs(double(c[k]) - double(d[k])) / std::max(1.0, double(d[k])) / bound);
        }
    }
    CHECK(worst <= 1.0);
}

TEST_CASE_TEMPLATE("terms: emission + ambient + diffuse + specular is shade's colour bit for bit", T, float, double)
{
    scene_gen<T> g(303);
    for (int i = 0; i < 300; ++i) {
        for_each_feature_set<view_model::given>([&]<features F>() {
            const scene<T> s = g.make(F, i % 5); // 0 lights too
            const vec3<T> v = g.direction();
            const auto t = shade_terms<F>(s.position, s.normal, v, s.mat, s.lights, s.env);
            const auto c = shade<F>(s.position, s.normal, v, s.mat, s.lights, s.env);
            // In shade's arithmetic type (double for float's stable mode), rounded once to T.
            const auto sum = t.emission + t.ambient + t.diffuse + t.specular;
            CHECK(same_bits(vec3<T>(sum), vec3<T>(c)));
            CHECK(same_bits(vec3<T>(t.sum()), vec3<T>(c)));
            if constexpr (F.alpha) CHECK(T(t.alpha) == c.w);
            // Terms a feature set leaves out are 0; every term is non-negative.
            if constexpr (!F.emission) CHECK(t.emission == decltype(t.emission)(0));
            if constexpr (F.specular == specular_model::none) CHECK(t.specular == decltype(t.specular)(0));
            for (int k = 0; k < 3; ++k) CHECK((t.ambient[k] >= 0 && t.diffuse[k] >= 0 && t.specular[k] >= 0));
        });
    }
    // The other overload (eye_at_origin), and a NaN point: NaN in every term.
    const std::vector<light<T>> lights{light<T>::with_strength({1, 2, 3, 1}, vec3<T>(1))};
    const material<T> mat{};
    const auto t = shade_terms<presets::glsl_ads>(vec3<T>(0, 0, -2), vec3<T>(0, 0, 1), mat, lights);
    CHECK(same_bits(t.sum(), shade<presets::glsl_ads>(vec3<T>(0, 0, -2), vec3<T>(0, 0, 1), mat, lights)));
    const T nan = std::numeric_limits<T>::quiet_NaN();
    const auto bad = shade_terms<presets::glsl_ads>(vec3<T>(0, nan, -2), vec3<T>(0, 0, 1), mat, lights);
    for (int k = 0; k < 3; ++k) CHECK((std::isnan(bad.emission[k]) && std::isnan(bad.ambient[k]) && std::isnan(bad.diffuse[k]) && std::isnan(bad.specular[k])));
}

TEST_CASE_TEMPLATE("lights: a masked light equals a removed light; weights 0 and 1 equal the mask; a view equals a span", T, float, double)
{
    scene_gen<T> g(404);
    for (int i = 0; i < 200; ++i) {
        for_each_feature_set<view_model::given>([&]<features F>() {
            scene<T> s = g.make(F, 6);
            const vec3<T> v = g.direction();
            const std::uint64_t mask = std::uint64_t(g.integer(0, 63));
            std::vector<light<T>> kept;
            std::vector<T> weights;
            for (std::size_t k = 0; k < s.lights.size(); ++k) {
                if (mask >> k & 1u) kept.push_back(s.lights[k]);
                weights.push_back((mask >> k & 1u) ? T(1) : T(0));
            }
            const auto removed = shade<F>(s.position, s.normal, v, s.mat, kept, s.env);
            CHECK(same_bits(shade<F>(s.position, s.normal, v, s.mat, masked(s.lights, mask), s.env), removed));
            CHECK(same_bits(shade<F>(s.position, s.normal, v, s.mat, weighted(s.lights, std::span<const T>(weights)), s.env), removed));
#if PHONG_TEST_RANGE_VIEWS
            // std::views::filter over the list (the natural way to drop shadowed lights).
            auto visible = s.lights | std::views::filter([&, start = &s.lights[0]](const light<T>& L) { return (mask >> (&L - start) & 1u) != 0; });
            CHECK(same_bits(shade<F>(s.position, s.normal, v, s.mat, visible, s.env), removed));
#endif
            // A span and a std::array of the same lights.
            CHECK(same_bits(shade<F>(s.position, s.normal, v, s.mat, std::span<const light<T>>(s.lights), s.env),
                            shade<F>(s.position, s.normal, v, s.mat, s.lights, s.env)));
        });
    }
}

TEST_CASE_TEMPLATE("lights: a weight scales the light's whole contribution", T, float, double)
{
    // Linearity in f: weight w on light i equals the light's three strengths scaled by w (f is
    // multiplied by w in one place), within the rounding of the extra products.
    scene_gen<T> g(505);
    double worst = 0;
    for (int i = 0; i < 500; ++i) {
        constexpr features F = with_view(presets::blinn_phong_per_light_ambient, view_model::given);
        scene<T> s = g.make(F, 3);
        const vec3<T> v = g.direction();
        const std::array<T, 3> w{g.uniform(0.05, 1), g.uniform(0.05, 1), g.uniform(0.05, 1)};
        std::vector<light<T>> scaled = s.lights;
        for (std::size_t k = 0; k < 3; ++k) {
            scaled[k].ambient *= w[k];
            scaled[k].diffuse *= w[k];
            scaled[k].specular *= w[k];
        }
        const vec3<T> a = shade<F>(s.position, s.normal, v, s.mat, weighted(s.lights, std::span<const T>(w)), s.env);
        const vec3<T> b = shade<F>(s.position, s.normal, v, s.mat, scaled, s.env);
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(double(a[k]) - double(b[k])) / std::max(1e-30, double(b[k])));
    }
    CHECK(worst <= 16 * double(std::numeric_limits<T>::epsilon()));
}

#if PHONG_TEST_RANGE_VIEWS
TEST_CASE("lights: the renderer's own light type through std::views::transform, nothing else to write")
{
    using T = float;
    const std::vector<my_light<T>> mine{{{1, 4, 2}, {1, 0.9f, 0.8f}}, {{-3, 2, 1}, {0.2f, 0.3f, 0.9f}}};
    const auto as_phong = [](const my_light<T>& L) { return light<T>::with_strength(glm::vec<4, T>(L.position, 1), L.color); };
    std::vector<light<T>> copied;
    for (const my_light<T>& L : mine) copied.push_back(as_phong(L));
    constexpr features F = presets::raytracer_phong;
    const vec3<T> Q(0, 0, -3), n(0, 0.6f, 0.8f), v(0, 0, 1);
    const material<T> mat{};
    CHECK(same_bits(shade<F>(Q, n, v, mat, mine | std::views::transform(as_phong)), shade<F>(Q, n, v, mat, copied)));
    CHECK(same_bits(shade<F>(Q, n, v, mat, masked(mine | std::views::transform(as_phong), 0b10)),
                    shade<F>(Q, n, v, mat, std::span<const light<T>>(copied).subspan(1))));
}
#endif

TEST_CASE_TEMPLATE("light_traits: a renderer's own light type gives the colour of the equivalent light<T> bit for bit", T, float, double)
{
    // Every field through the traits (by value and by reference), attenuation and spot included,
    // in every feature set, as a vector, a std::array, a masked and a weighted list; the expected
    // colour is shade<F> on the light<T> built field by field (as_light).
    check_property("shade(renderer_light) == shade(light<T>)", [] {
        const T step = T(1) / T(8);
        const int count = *rc::gen::inRange(1, 5);
        std::vector<renderer_light<T>> mine;
        std::vector<light<T>> reference;
        for (int i = 0; i < count; ++i) {
            const light<T> g = *gen_light<T>(*rc::gen::arbitrary<bool>());
            renderer_light<T> r{{g.position.x, g.position.y, g.position.z}, g.position.w == T(0), g.ambient, g.diffuse, g.specular,
                                *grid<T>(1, 8, T(0.25)), *grid<T>(0, 8, T(0.125)), *grid<T>(0, 8, T(1) / T(16)), spot_cone<T>{}};
            const vec3<T> axis = *gen_nonzero_vec3<T>(-8, 8, T(0.25));
            if (*rc::gen::arbitrary<bool>()) r.cone = spot_cone<T>::smooth(axis, T(*rc::gen::inRange(5, 40)), T(*rc::gen::inRange(45, 80)));
            else r.cone = spot_cone<T>::opengl(axis, T(*rc::gen::inRange(0, 16)), T(*rc::gen::inRange(10, 90)));
            mine.push_back(r);
            reference.push_back(as_light(r));
        }
        const vec3<T> Q(*grid<T>(-32, 32, step), *grid<T>(-32, 32, step), *grid<T>(-64, -8, step));
        const vec3<T> n = *gen_nonzero_vec3<T>(-8, 8, T(0.25)), v = *gen_nonzero_vec3<T>(-8, 8, T(0.25));
        const material<T> mat = *gen_material<T>(128);
        environment<T> env;
        env.ambient = *gen_color<T>();
        const std::uint64_t mask = std::uint64_t(*rc::gen::inRange(0, 32));
        std::vector<T> weights;
        for (int i = 0; i < count; ++i) weights.push_back(T(*rc::gen::inRange(0, 9)) / T(8));
        const std::span<const T> w(weights);
        bool same = true;
        for_each_feature_set<view_model::given>([&]<features F>() {
            same = same && same_bits(shade<F>(Q, n, v, mat, mine, env), shade<F>(Q, n, v, mat, reference, env));
            same = same && same_bits(shade<F>(Q, n, v, mat, masked(mine, mask), env), shade<F>(Q, n, v, mat, masked(reference, mask), env));
            same = same && same_bits(shade<F>(Q, n, v, mat, weighted(mine, w), env), shade<F>(Q, n, v, mat, weighted(reference, w), env));
            const auto t = shade_terms<F>(Q, n, v, mat, mine, env), u = shade_terms<F>(Q, n, v, mat, reference, env);
            same = same && same_bits(t.sum(), u.sum());
        });
        // A std::array (unrolled), in the stable mode's wider route (float lights in double).
        constexpr features S = presets::with_mode(with_view(presets::blinn_phong_per_light_ambient, view_model::given), evaluation::stable);
        const std::array<renderer_light<T>, 1> one{mine[0]};
        const std::array<light<T>, 1> one_reference{reference[0]};
        same = same && same_bits(shade<S>(Q, n, v, mat, one, env), shade<S>(Q, n, v, mat, one_reference, env));
        RC_ASSERT(same);
    });
}

TEST_CASE("light_traits: the minimal adaptor (position, diffuse, specular) takes light<T>'s defaults for the rest")
{
    using T = float;
    const std::vector<my_light<T>> mine{{{1, 4, 2}, {1, 0.9f, 0.8f}}, {{-3, 2, 1}, {0.2f, 0.3f, 0.9f}}};
    std::vector<light<T>> copied;
    for (const my_light<T>& L : mine) copied.push_back(light<T>::with_strength(glm::vec<4, T>(L.position, 1), L.color));
    const light<T> converted = to_light(mine[1]);
    CHECK(std::memcmp(&converted, &copied[1], sizeof(light<T>)) == 0);
    constexpr features F = with_view(presets::blinn_phong_per_light_ambient, view_model::given); // reads ambient: 0 by default
    const vec3<T> Q(0, 0, -3), n(0, 0.6f, 0.8f), v(0, 0, 1);
    material<T> mat{};
    mat.ka = vec3<T>(0.5f);
    CHECK(same_bits(shade<F>(Q, n, v, mat, mine), shade<F>(Q, n, v, mat, copied)));
    CHECK(same_bits(shade<F>(Q, n, v, mat, masked(mine, 0b10)), shade<F>(Q, n, v, mat, std::span<const light<T>>(copied).subspan(1))));
    // By hand: one light at (-3, 2, 1) from Q = (0, 0, -3), the diffuse term alone (ks = 0).
    mat.ks = vec3<T>(0);
    const double nl = (0.6 * 2.0 + 0.8 * 4.0) / std::sqrt(29.0);
    const vec3<T> one = shade<F>(Q, n, v, mat, std::span<const my_light<T>>(mine).subspan(1));
    for (int k = 0; k < 3; ++k) CHECK(double(one[k]) == doctest::Approx(double(mat.kd[k]) * double(mine[1].color[k]) * nl).epsilon(1e-6));
}

TEST_CASE("given view: a zero view vector keeps the diffuse term and has no specular, a NaN one gives NaN in every channel")
{
    using T = double;
    constexpr features F = presets::raytracer_phong;
    const std::vector<light<T>> lights{light<T>::with_strength({1, 2, 3, 1}, vec3<T>(1))};
    material<T> mat{};
    environment<T> env{};
    env.ambient = vec3<T>(0.5);
    const vec3<T> Q(0, 0, -2), n(0, 0, 1);
    const vec3<T> zero_view = shade<F>(Q, n, vec3<T>(0), mat, lights, env);
    // By hand: d = (1, 2, 5), n.l = 5/sqrt(30); ka La + kd Ld n.l, no specular term.
    const vec3<T> expected = mat.ka * env.ambient + mat.kd * (5 / std::sqrt(30.0));
    for (int k = 0; k < 3; ++k) CHECK(zero_view[k] == doctest::Approx(expected[k]).epsilon(1e-14));
    const vec3<T> nan_view = shade<F>(Q, n, vec3<T>(0, std::numeric_limits<T>::quiet_NaN(), 1), mat, lights, env);
    CHECK((std::isnan(nan_view.x) && std::isnan(nan_view.y) && std::isnan(nan_view.z)));
    // Any length: v and 7 v give the same colour (normalized here without unit_inputs).
    CHECK(same_bits(shade<F>(Q, n, vec3<T>(0, 0, 1), mat, lights, env), shade<F>(Q, n, vec3<T>(0, 0, 8), mat, lights, env)));
}

TEST_CASE("constexpr: the renderer API evaluates in constant expressions")
{
    using T = double;
    constexpr features F = with_unit_inputs(presets::raytracer_phong);
    static constexpr std::array<light<T>, 2> lights{light<T>::with_strength({0, 0, 5, 1}, vec3<T>(1)),
                                                    light<T>::with_strength({0, 5, 0, 1}, vec3<T>(1))};
    constexpr material<T> mat{};
    constexpr vec3<T> Q(0, 0, 0), n(0, 0, 1), v(0, 0, 1);
    // Light 0 straight above: n.l = 1, r = v, so kd + ks (ka La = 0); light 1 grazing: n.l = 0.
    constexpr vec3<T> one = shade<F>(Q, n, v, mat, masked(lights, 0b01));
    static_assert(one.x == 0.7 + 0.2);
    constexpr auto terms = shade_terms<F>(Q, n, v, mat, lights);
    static_assert(terms.diffuse.x == 0.7 && terms.specular.x == 0.2);
    static_assert(shade<F>(Q, n, v, mat, masked(lights, 0b00)).x == 0);
    CHECK(one.x == doctest::Approx(0.9));
}
