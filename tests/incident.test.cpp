// shade_incident (phong/sum/incident.hpp, issue 27): the model from the light directions and
// distances a renderer already has, with no position. Expected values: worked by hand (3-4-5
// directions, where every cosine is exact), the formulas written literally in long double, and
// properties: shade<F> on the position the incidents come from; surface and material the same
// bits; masked() the same as the visible lights alone; fixed_direction the same as the given v.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/property.hpp"

#include <phong/sum/incident.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <span>
#include <vector>

using namespace phong;
using namespace phong_test;

namespace {

template <class T> using vec3 = glm::vec<3, T>;

template <glm::length_t L, class T> bool same_bits(const glm::vec<L, T>& a, const glm::vec<L, T>& b)
{
    return std::memcmp(&a, &b, sizeof(a)) == 0;
}

template <class T> bool near(const vec3<T>& a, const vec3<T>& b, T tol)
{
    for (int k = 0; k < 3; ++k)
        if (!(std::abs(double(a[k]) - double(b[k])) <= double(tol) * (1.0 + std::abs(double(b[k]))))) return false;
    return true;
}

constexpr features given_phong = [] {
    features f = presets::raytracer_phong;
    f.unit_inputs = true;
    return f;
}();
constexpr features given_ungated = [] {
    features f = given_phong;
    f.specular_gate = false;
    return f;
}();
constexpr features given_blinn = [] {
    features f = given_phong;
    f.specular = specular_model::blinn;
    return f;
}();
/// The screen-space rasterizer's model: directional light, view along +z, unit inputs.
constexpr features screen = [] {
    features f = presets::glsl_ads;
    f.scene_ambient = true;
    f.light_ambient = false;
    f.lights = light_kind::directional;
    f.view = view_model::fixed_direction;
    f.unit_inputs = true;
    return f;
}();

/// The hand-worked point: n = v = (0, 0, 1), l = (0, 3/5, 4/5), one light of colour 1, La = 1/5,
/// ka = 1/10, kd = 1/2, ks = 1/4, m = 2:
///   ambient  ka La = 1/50;  diffuse kd (n.l) = 1/2 * 4/5 = 2/5;
///   Phong:   r = reflect(-l, n) = (0, -3/5, 4/5), r.v = 4/5, ks (r.v)^2 = 1/4 * 16/25 = 4/25;
///   Blinn:   n.h = (4/5 + 1) / |l + v| = (9/5) / sqrt(9/25 + 81/25) = 9 / sqrt(90),
///            (n.h)^2 = 81/90 = 9/10, ks 9/10 = 9/40.
template <class T> constexpr light<T> hand_light()
{
    light<T> L;
    L.position = glm::vec<4, T>(T(0), T(3), T(4), T(1)); // 5 away from the origin along l
    L.ambient = vec3<T>(T(0));
    L.diffuse = vec3<T>(T(1));
    L.specular = vec3<T>(T(1));
    return L;
}
template <class T> constexpr material<T> hand_material()
{
    return {vec3<T>(T(0.1)), vec3<T>(T(0.5)), vec3<T>(T(0.25)), vec3<T>(T(0)), T(2), T(1)};
}
template <class T> constexpr incident<T> hand_incident() { return {vec3<T>(T(0), T(0.6), T(0.8)), T(5)}; }

template <features F, class T> constexpr T hand_value()
{
    const std::array<light<T>, 1> lights{hand_light<T>()};
    const std::array<incident<T>, 1> in{hand_incident<T>()};
    const environment<T> env{.ambient = vec3<T>(T(0.2))};
    return shade_incident<F>(vec3<T>(T(0), T(0), T(1)), vec3<T>(T(0), T(0), T(1)), hand_material<T>(), lights, in, env).x;
}

// constant evaluation: the hand values within a few ulp of double
static_assert(std::abs(hand_value<given_phong, double>() - (0.02 + 0.4 + 0.16)) < 1e-15);
static_assert(std::abs(hand_value<given_blinn, double>() - (0.02 + 0.4 + 0.225)) < 1e-15);

} // namespace

TEST_CASE_TEMPLATE("shade_incident: hand-worked values (Phong, Blinn, attenuation, fixed direction)", T, float, double)
{
    const T tol = tolerance<T>::rel(8);
    const std::array<light<T>, 1> lights{hand_light<T>()};
    const std::array<incident<T>, 1> in{hand_incident<T>()};
    const environment<T> env{.ambient = vec3<T>(T(0.2))};
    const vec3<T> n(T(0), T(0), T(1)), v = n;
    const material<T> mat = hand_material<T>();
    CHECK(near(shade_incident<given_phong>(n, v, mat, lights, in, env), vec3<T>(T(0.02 + 0.4 + 0.16)), tol));
    CHECK(near(shade_incident<given_blinn>(n, v, mat, lights, in, env), vec3<T>(T(0.02 + 0.4 + 0.225)), tol));
    // polynomial attenuation at the given distance 5: f = 1 / (1 + 0.2 * 5 + 0.04 * 25) = 1/3
    constexpr features att = [] {
        features f = given_phong;
        f.attenuation = attenuation_model::polynomial;
        return f;
    }();
    std::array<light<T>, 1> attenuated = lights;
    attenuated[0].attenuation = falloff<T>{T(1), T(0.2), T(0.04)};
    CHECK(near(shade_incident<att>(n, v, mat, attenuated, in, env), vec3<T>(T(0.02 + (0.4 + 0.16) / 3)), tol));
    // the screen-space model: the same point with v = environment::eye.xyz = +z, a directional light
    std::array<light<T>, 1> directional = lights;
    directional[0].position = glm::vec<4, T>(T(0), T(3), T(4), T(0));
    const environment<T> screen_env{.ambient = vec3<T>(T(0.2)), .eye = glm::vec<4, T>(T(0), T(0), T(1), T(0))};
    CHECK(near(shade_incident<screen>(n, mat, directional, in, screen_env), vec3<T>(T(0.2 * 0.1 + 0.4 + 0.16)), tol));
}

TEST_CASE_TEMPLATE("shade_incident: the formulas written literally (long double), random unit inputs", T, float, double)
{
    std::mt19937 rng(27);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const auto unit = [&] {
        glm::dvec3 d;
        do d = glm::dvec3(u(rng), u(rng), u(rng));
        while (glm::dot(d, d) < 0.01);
        return glm::normalize(d);
    };
    int checked = 0;
    for (int i = 0; i < 2000; ++i) {
        const vec3<T> n(unit()), v(unit()), l(unit());
        const T m = T(1 + 63 * (0.5 + 0.5 * u(rng)));
        const material<T> mat{vec3<T>(T(0.1)), vec3<T>(T(0.6)), vec3<T>(T(0.3)), vec3<T>(T(0)), m, T(1)};
        light<T> L = light<T>::with_strength(glm::vec<4, T>(T(1), T(2), T(3), T(1)), vec3<T>(T(0.8)));
        const std::array<light<T>, 1> lights{L};
        const std::array<incident<T>, 1> in{incident<T>{l, T(3)}};
        const T got = shade_incident<given_ungated>(n, v, mat, lights, in, environment<T>{.ambient = vec3<T>(T(0.5))}).x;
        // literally: ka La + Ld kd max(n.l, 0) + Ls ks max(r.v, 0)^m, r = 2 (n.l) n - l, from T's inputs
        using W = long double;
        const W nl = W(n.x) * l.x + W(n.y) * l.y + W(n.z) * l.z;
        const W rv = 2 * nl * (W(n.x) * v.x + W(n.y) * v.y + W(n.z) * v.z) - (W(l.x) * v.x + W(l.y) * v.y + W(l.z) * v.z);
        const W expected = W(T(0.1)) * W(T(0.5)) + W(T(0.8)) * W(T(0.6)) * std::max(nl, W(0)) +
                           W(T(0.8)) * W(T(0.3)) * std::pow(std::max(std::min(rv, W(1)), W(0)), W(m));
        // the bound: a few roundings of unit inputs, amplified by m in the power
        const W bound = W(tolerance<T>::eps) * (16 + 4 * W(m));
        if (!(std::abs(W(got) - expected) <= bound)) {
            CAPTURE(i);
            CAPTURE(double(got));
            CAPTURE(double(expected));
            CHECK(false);
        }
        ++checked;
    }
    CHECK(checked == 2000);
}

TEST_CASE_TEMPLATE("shade_incident: properties", T, float, double)
{
    check_property("shade_incident = shade<F> at the position the incidents come from", [] {
        const vec3<T> P = *gen_vec3<T>(-16, 16, T(0.25));
        const vec3<T> n0 = *gen_nonzero_vec3<T>(-8, 8, T(1));
        const vec3<T> v0 = *gen_nonzero_vec3<T>(-8, 8, T(1));
        const material<T> mat = *gen_material<T>(64);
        std::vector<light<T>> lights;
        std::vector<incident<T>> in;
        for (int i = 0; i < 3; ++i) {
            light<T> L = *gen_light<T>(false);
            const vec3<T> d = vec3<T>(L.position) - P;
            RC_PRE(glm::dot(d, d) > T(0.01));
            L.attenuation = falloff<T>{T(1), T(0.125), T(0.0625)};
            lights.push_back(L);
            in.push_back({glm::normalize(d), glm::length(d)});
        }
        const unsigned visible = *rc::gen::inRange(0u, 8u);
        const vec3<T> n = glm::normalize(n0), v = glm::normalize(v0);
        // The specular gate n.l > 0 is a discontinuity: where n.l is within rounding of 0, the
        // given l and normalize(L - P) may fall on its two sides (a legitimate jump of ks L (r.v)^m).
        for (const incident<T>& i : in) RC_PRE(std::abs(glm::dot(n, i.direction)) > T(1e-3));
        constexpr features F = [] {
            features f = given_phong;
            f.attenuation = attenuation_model::polynomial;
            f.light_ambient = true;
            return f;
        }();
        const environment<T> env{.ambient = vec3<T>(T(0.25))};
        const vec3<T> a = shade_incident<F>(n, v, mat, masked(std::span<const light<T>>(lights), visible), in, env);
        const vec3<T> b = shade<F>(P, n, v, mat, masked(std::span<const light<T>>(lights), visible), env);
        // l rounded differently (given vs normalize(L - P)): a few ulp, amplified by m in the power
        RC_ASSERT(near(a, b, tolerance<T>::rel(64 + 8 * int(mat.shininess))));
    });
    check_property("surface and material give the same bits; masked() = the visible lights alone", [] {
        const vec3<T> n = glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1)));
        const vec3<T> v = glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1)));
        const material<T> mat = *gen_material<T>(64);
        const surface<T> surf{mat.ka, mat.kd, mat.ks, mat.shininess};
        const material<T> plain{mat.ka, mat.kd, mat.ks, vec3<T>(T(0)), mat.shininess, T(1)};
        const std::array<light<T>, 2> lights{*gen_light<T>(false), *gen_light<T>(false)};
        const std::array<incident<T>, 2> in{incident<T>{glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1))), T(2)},
                                            incident<T>{glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1))), T(3)}};
        RC_ASSERT(same_bits(shade_incident<given_blinn>(n, v, surf, lights, in), shade_incident<given_blinn>(n, v, plain, lights, in)));
        const std::array<light<T>, 1> second{lights[1]};
        const std::array<incident<T>, 1> second_in{in[1]};
        RC_ASSERT(same_bits(shade_incident<given_phong>(n, v, mat, masked(lights, 2u), in),
                            shade_incident<given_phong>(n, v, mat, second, second_in)));
    });
    check_property("fixed_direction (eye.xyz used as given) = the same v given per call", [] {
        const vec3<T> n = glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1)));
        const vec3<T> v = glm::normalize(*gen_nonzero_vec3<T>(-8, 8, T(1)));
        const material<T> mat = *gen_material<T>(64);
        light<T> L = *gen_light<T>(true);
        const std::array<light<T>, 1> lights{L};
        const std::array<incident<T>, 1> in{incident<T>{glm::normalize(vec3<T>(L.position)), T(0)}};
        constexpr features G = [] {
            features f = screen;
            f.view = view_model::given;
            return f;
        }();
        const environment<T> env{.ambient = vec3<T>(T(0.25)), .eye = glm::vec<4, T>(v, T(0))};
        RC_ASSERT(same_bits(shade_incident<screen>(n, mat, lights, in, env), shade_incident<G>(n, v, mat, lights, in, env)));
        // shade<F> with fixed_direction and unit_inputs also takes eye.xyz as given
        RC_ASSERT(same_bits(shade<screen>(vec3<T>(T(0)), n, mat, lights, env), shade<G>(vec3<T>(T(0)), n, v, mat, lights, env)));
    });
}

TEST_CASE_TEMPLATE("shade_incident: edges and modes", T, float, double)
{
    const std::array<light<T>, 1> lights{hand_light<T>()};
    const std::array<incident<T>, 1> in{hand_incident<T>()};
    const environment<T> env{.ambient = vec3<T>(T(0.2))};
    const material<T> mat = hand_material<T>();
    const vec3<T> z(T(0), T(0), T(1));
    constexpr features normalizing = [] {
        features f = presets::raytracer_phong;
        f.specular_gate = false;
        return f;
    }();
    // a zero normal: ambient only; a zero view vector: no specular term; NaN: NaN in every channel
    CHECK(near(shade_incident<normalizing>(vec3<T>(T(0)), z, mat, lights, in, env), vec3<T>(T(0.02)), tolerance<T>::rel(4)));
    CHECK(near(shade_incident<normalizing>(z, vec3<T>(T(0)), mat, lights, in, env), vec3<T>(T(0.02 + 0.4)), tolerance<T>::rel(8)));
    const vec3<T> nan = shade_incident<normalizing>(vec3<T>(std::numeric_limits<T>::quiet_NaN(), T(0), T(1)), z, mat, lights, in, env);
    CHECK((std::isnan(nan.x) && std::isnan(nan.y) && std::isnan(nan.z)));
    // not normalized inputs are normalized without unit_inputs: 3 z is z
    CHECK(near(shade_incident<normalizing>(T(3) * z, T(7) * z, mat, lights, in, env), vec3<T>(T(0.02 + 0.4 + 0.16)), tolerance<T>::rel(8)));
    // a light below the surface: gated, ambient only
    const std::array<incident<T>, 1> below{incident<T>{vec3<T>(T(0), T(0.6), T(-0.8)), T(5)}};
    CHECK(near(shade_incident<given_phong>(z, z, mat, lights, below, env), vec3<T>(T(0.02)), tolerance<T>::rel(4)));
    // stable and fast modes: the same hand value within their bounds
    CHECK(near(shade_incident<presets::with_mode(given_phong, evaluation::stable)>(z, z, mat, lights, in, env), vec3<T>(T(0.58)),
               tolerance<T>::rel(4)));
    CHECK(near(shade_incident<presets::with_mode(given_blinn, evaluation::fast)>(z, z, mat, lights, in, env), vec3<T>(T(0.645)), T(1e-4)));
    // m = 0: the specular base^0 = 1 where the term is on (lit, sees the viewer)
    material<T> m0 = mat;
    m0.shininess = T(0);
    CHECK(near(shade_incident<given_phong>(z, z, m0, lights, in, env), vec3<T>(T(0.02 + 0.4 + 0.25)), tolerance<T>::rel(8)));
}

TEST_CASE_TEMPLATE("shade_incident: the first light outside the loop (masks, indices, the sign of a zero colour)", T, float, double)
{
    // The light loop adds the first light before the others, to sums that start at -0. Checked:
    // every mask of three lights gives the bits of the visible lights passed alone (each with its
    // own incident: the indices stay aligned when the first is off), and a point that nothing
    // lights, without ambient, is +0 in every channel, as from sums that start at +0.
    constexpr features no_ambient = [] {
        features f = given_phong;
        f.scene_ambient = false;
        f.light_ambient = false;
        return f;
    }();
    const vec3<T> z(T(0), T(0), T(1));
    const material<T> mat = hand_material<T>();
    std::array<light<T>, 3> lights{hand_light<T>(), hand_light<T>(), hand_light<T>()};
    lights[1].diffuse = vec3<T>(T(0.5), T(0.25), T(1));
    lights[2].specular = vec3<T>(T(0.75));
    const std::array<incident<T>, 3> in{hand_incident<T>(), incident<T>{vec3<T>(T(0.6), T(0), T(0.8)), T(2)},
                                        incident<T>{vec3<T>(T(0), T(-0.28), T(0.96)), T(1)}};
    for (unsigned bits = 0; bits < 8; ++bits) {
        CAPTURE(bits);
        std::vector<light<T>> alone;
        std::vector<incident<T>> alone_in;
        for (unsigned i = 0; i < 3; ++i)
            if (bits >> i & 1u) alone.push_back(lights[i]), alone_in.push_back(in[i]);
        const vec3<T> a = shade_incident<given_phong>(z, z, mat, masked(lights, bits), in);
        const vec3<T> b = shade_incident<given_phong>(z, z, mat, std::span<const light<T>>(alone), alone_in);
        CHECK(same_bits(a, b));
        if (bits == 0) CHECK(same_bits(a, vec3<T>(T(0))));
    }
    // nothing lit, no ambient: +0, not -0 (an empty list, a light below the surface, a masked one)
    const std::array<incident<T>, 1> below{incident<T>{vec3<T>(T(0), T(0.6), T(-0.8)), T(5)}};
    const std::array<light<T>, 1> one{hand_light<T>()};
    CHECK(same_bits(shade_incident<no_ambient>(z, z, mat, std::span<const light<T>>(), std::span<const incident<T>>()), vec3<T>(T(0))));
    CHECK(same_bits(shade_incident<no_ambient>(z, z, mat, one, below), vec3<T>(T(0))));
    CHECK(same_bits(shade_incident<no_ambient>(z, z, mat, masked(one, 0u), below), vec3<T>(T(0))));
    CHECK(same_bits(shade_incident<no_ambient>(z, z, mat, masked(lights, 0u), in), vec3<T>(T(0))));
    // and the hand value with the light first, second or last of three (the others below)
    const std::array<incident<T>, 3> first{hand_incident<T>(), below[0], below[0]}, last{below[0], below[0], hand_incident<T>()};
    const std::array<light<T>, 3> same{hand_light<T>(), hand_light<T>(), hand_light<T>()};
    const T expected = T(0.4) + T(0.16); // kd n.l + ks (r.v)^2 of the hand-worked point, no ambient
    CHECK(near(shade_incident<no_ambient>(z, z, mat, same, first), vec3<T>(expected), tolerance<T>::rel(8)));
    CHECK(near(shade_incident<no_ambient>(z, z, mat, same, last), vec3<T>(expected), tolerance<T>::rel(8)));
}

namespace {
/// A renderer's light that only shade_incident reads: colours, no position (the incident carries
/// the direction).
template <class T> struct colour_only_light {
    vec3<T> colour;
};
} // namespace

template <class T> struct phong::light_traits<colour_only_light<T>> {
    static const vec3<T>& diffuse(const colour_only_light<T>& L) { return L.colour; }
    static const vec3<T>& specular(const colour_only_light<T>& L) { return L.colour; }
};

static_assert(phong::detail::incident_light_source<colour_only_light<float>> && !light_source<colour_only_light<float>>,
              "a light_traits without position is a light for shade_incident only");
static_assert(std::is_same_v<phong::detail::light_scalar_t<colour_only_light<double>>, double>);

TEST_CASE_TEMPLATE("shade_incident: a light_traits without position, the same bits as light<T> with that colour", T, float, double)
{
    // The position is never read by shade_incident with positional lights: a light<T> anywhere,
    // with the same colours, gives the same bits.
    const std::array<colour_only_light<T>, 2> mine{{{vec3<T>(T(0.9), T(0.5), T(0.25))}, {vec3<T>(T(0.125), T(1), T(0.5))}}};
    std::array<light<T>, 2> theirs{};
    for (int k = 0; k < 2; ++k) {
        theirs[k].position = glm::vec<4, T>(T(100 + k), T(-7), T(3), T(1)); // arbitrary: not read
        theirs[k].diffuse = theirs[k].specular = mine[k].colour;
    }
    const std::array<incident<T>, 2> in{{{vec3<T>(T(0), T(0.6), T(0.8)), T(2)}, {vec3<T>(T(0.8), T(0), T(0.6)), T(5)}}};
    const vec3<T> n(T(0), T(0), T(1)), v(T(0.6), T(0), T(0.8));
    const material<T> m{};
    const vec3<T> a = shade_incident<given_phong>(n, v, m, mine, in);
    const vec3<T> b = shade_incident<given_phong>(n, v, m, theirs, in);
    CHECK(same_bits(a, b));
    // by hand: kd * (0.8 L0 + 0.6 L1) + ks * ((r.v)^32 ...) > kd * n.l terms alone
    CHECK(a.x > T(0.7) * (T(0.8) * T(0.9) + T(0.6) * T(0.125)) * T(0.999));
    const vec3<T> masked_only = shade_incident<given_phong>(n, v, m, masked(mine, 0b10), in);
    CHECK(same_bits(masked_only, shade_incident<given_phong>(n, v, m, masked(theirs, 0b10), in)));
}
