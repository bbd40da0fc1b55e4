// batch.hpp: shade_batch runs shade<F>'s own templates on SIMD batches. Checked against the
// scalar path point by point (every feature set of the list, float and double, every tail length)
// and against the __float128 reference; degenerate points and the NaN policy lane by lane.
#include "support/generators.hpp"
#include "support/numeric.hpp"
#include "support/reference.hpp"

#include <phong/accuracy.hpp>
#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

using namespace phong;
using namespace phong_test;

namespace {

/// SoA copies of a list of points, and the output channels.
template <class T> struct soa_scene {
    std::vector<T> px, py, pz, nx, ny, nz, r, g, b, a;
    std::vector<char> front_storage;
    std::vector<bool> front_values;

    void add(const glm::vec<3, T>& p, const glm::vec<3, T>& n)
    {
        px.push_back(p.x), py.push_back(p.y), pz.push_back(p.z);
        nx.push_back(n.x), ny.push_back(n.y), nz.push_back(n.z);
    }
    std::size_t size() const { return px.size(); }
    template <features F>
    void shade(const material<T>& mat, std::span<const light<T>> lights, const environment<T>& env,
               const bool* front = nullptr)
    {
        const std::size_t n = size();
        r.assign(n, T(-1)), g.assign(n, T(-1)), b.assign(n, T(-1)), a.assign(n, T(-1));
        shade_batch<F>(soa3<T>{px, py, pz}, soa3<T>{nx, ny, nz}, mat, lights, soa_rgba<T>{r, g, b, a}, env,
                       front ? std::span<const bool>(front, n) : std::span<const bool>());
    }
    glm::vec<4, T> color(std::size_t i) const { return {r[i], g[i], b[i], a[i]}; }
};

// Feature sets the batch path is checked on: every optional term on and off at least once.
constexpr features batch_feature_sets[] = {
    features{.mode = evaluation::exact},
    features{.mode = evaluation::stable},
    features{.specular = specular_model::blinn, .mode = evaluation::stable},
    features{.specular = specular_model::blinn, .mode = evaluation::exact},
    features{.light_ambient = true, .lights = light_kind::positional, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::opengl, .mode = evaluation::stable},
    features{.light_ambient = true, .lights = light_kind::any, .attenuation = attenuation_model::windowed,
             .spot = spot_model::smooth, .attenuate_ambient = false, .mode = evaluation::exact},
    features{.specular = specular_model::none, .lights = light_kind::directional, .two_sided = facing::view,
             .view = view_model::fixed_direction, .mode = evaluation::stable},
    features{.specular = specular_model::blinn, .specular_gate = false, .two_sided = facing::flag,
             .view = view_model::eye_point, .emission = true, .alpha = true, .mode = evaluation::stable},
    presets::classic_phong,
    presets::with_mode(presets::classic_phong, evaluation::stable),
    presets::blinn_phong_per_light_ambient,
    presets::glsl_ads,
    presets::diffuse_only,
};

/// Relative difference of two colours, per channel, against the largest channel of the reference.
template <class T> double channel_difference(const glm::vec<4, T>& a, const glm::vec<4, T>& b, int channels)
{
    double scale = 0, diff = 0;
    for (int k = 0; k < channels; ++k) {
        scale = std::max(scale, double(std::abs(b[k])));
        diff = std::max(diff, double(std::abs(a[k] - b[k])));
    }
    return diff / std::max(scale, 1e-30);
}

/// Tolerance of batch against scalar: both are within the mode's bound of the reference, but the
/// SIMD rsqrt estimate (float lanes, < 2 ulp) and contraction into FMA shift the rounding; the
/// exact mode's power amplifies that by up to m, the stable mode's by about sqrt(m).
template <class T> double batch_tolerance(const features& F, double m)
{
    const double eps = std::numeric_limits<T>::epsilon();
    const double amplification = F.mode == evaluation::exact ? 1 + m : 1 + 4 * std::sqrt(m);
    return 64 * eps * amplification;
}

template <class T, features F> void check_against_scalar(std::uint64_t seed)
{
    scene_gen<T> gen(seed);
    constexpr std::size_t W = batch_width<T>;
    for (std::size_t n : {std::size_t(0), std::size_t(1), W - 1, W, W + 1, 3 * W + 5, std::size_t(257)}) {
        const scene<T> base = gen.make(F, 1 + gen.integer(0, 3));
        soa_scene<T> batch;
        std::vector<char> front_chars;
        std::vector<scene<T>> points;
        for (std::size_t i = 0; i < n; ++i) {
            scene<T> s = base; // same material, lights and eye; each point its own Q, n and facing
            s.position = gen.point();
            s.normal = gen.direction() * gen.uniform(0.5, 2);
            s.front_facing = gen.coin();
            points.push_back(s);
            batch.add(s.position, s.normal);
            front_chars.push_back(s.front_facing);
        }
        std::unique_ptr<bool[]> front(new bool[n + 1]);
        for (std::size_t i = 0; i < n; ++i) front[i] = front_chars[i] != 0;
        batch.template shade<F>(base.mat, base.lights, base.env, front.get());
        const int channels = F.alpha ? 4 : 3;
        int checked = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const scene<T>& s = points[i];
            const auto c = shade<F>(s.position, s.normal, s.mat, s.lights, s.env, s.front_facing);
            glm::vec<4, T> scalar(T(0), T(0), T(0), T(-1));
            for (int k = 0; k < channels; ++k) scalar[k] = c[k];
            const glm::vec<4, T> got = batch.color(i);
            for (int k = 0; k < channels; ++k) REQUIRE(std::isfinite(got[k]));
            if (!well_conditioned(F, s, 1e-3)) continue; // a rounding may flip a gate or a cone edge
            ++checked;
            const double diff = channel_difference(got, scalar, channels);
            const double tol = batch_tolerance<T>(F, double(s.mat.shininess));
            if (diff > tol) {
                MESSAGE("point " << i << " of " << n << ": batch vs scalar relative difference " << diff << " > " << tol);
            }
            CHECK(diff <= tol);
        }
        // Lanes beyond n untouched: the output spans are exactly n long, so nothing to check
        // there; but a tail must have been written: no -1 left in the first n.
        for (std::size_t i = 0; i < n; ++i) CHECK(batch.r[i] != T(-1));
        (void)checked;
    }
}

template <class T, std::size_t... I> void check_all_feature_sets(std::index_sequence<I...>)
{
    (check_against_scalar<T, batch_feature_sets[I]>(1000 + I), ...);
}

} // namespace

TEST_CASE_TEMPLATE("shade_batch equals shade point by point, every feature set, every tail length", T, float, double)
{
    check_all_feature_sets<T>(std::make_index_sequence<std::size(batch_feature_sets)>{});
}

TEST_CASE_TEMPLATE("shade_batch stable mode is within the stable bound of the __float128 reference", T, float, double)
{
    // Well-conditioned random scenes; the bound is the scalar stable path's target for
    // well-conditioned inputs (max 64 ulp of the largest channel), widened by the SIMD rsqrt.
    constexpr features F{.light_ambient = true, .specular = specular_model::phong, .lights = light_kind::any,
                         .attenuation = attenuation_model::polynomial, .emission = true, .mode = evaluation::stable};
    constexpr features G{.specular = specular_model::blinn, .lights = light_kind::positional, .mode = evaluation::stable};
    scene_gen<T> gen(77);
    double worst = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const scene<T> base = gen.make(F, 3, 1, 200);
        soa_scene<T> batch;
        std::vector<scene<T>> points;
        for (int i = 0; i < 37; ++i) {
            scene<T> s = base;
            s.position = gen.point();
            s.normal = gen.direction();
            points.push_back(s);
            batch.add(s.position, s.normal);
        }
        batch.template shade<F>(base.mat, base.lights, base.env);
        soa_scene<T> blinn = batch;
        blinn.template shade<G>(base.mat, base.lights, base.env);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const scene<T>& s = points[i];
            const wcolor ref = reference_shade<T>(F, s.position, s.normal, s.mat, s.lights, s.env);
            const wcolor ref_b = reference_shade<T>(G, s.position, s.normal, s.mat, s.lights, s.env);
            const wide scale = wmax(wmax(ref.r, ref.g), ref.b), scale_b = wmax(wmax(ref_b.r, ref_b.g), ref_b.b);
            const bool ok_f = well_conditioned(F, s, 1e-3), ok_g = well_conditioned(G, s, 1e-3);
            for (int k = 0; k < 3; ++k) {
                const T got = k == 0 ? batch.r[i] : k == 1 ? batch.g[i] : batch.b[i];
                const T got_b = k == 0 ? blinn.r[i] : k == 1 ? blinn.g[i] : blinn.b[i];
                if (ok_f) worst = std::max(worst, double(wabs(wide(got) - ref[k]) / ulp_of<T>(scale)));
                if (ok_g) worst = std::max(worst, double(wabs(wide(got_b) - ref_b[k]) / ulp_of<T>(scale_b)));
            }
        }
    }
    MESSAGE("batch stable: worst error " << worst << " ulp of the largest channel");
    CHECK(worst <= 64);
}

TEST_CASE_TEMPLATE("shade_batch degenerate lanes: documented finite values, NaN policy", T, float, double)
{
    // One batch mixing: a normal point, a zero normal, a light at Q, Blinn l = -v, NaN and inf inputs.
    constexpr features F{.light_ambient = true, .specular = specular_model::blinn, .lights = light_kind::positional,
                         .mode = evaluation::stable};
    constexpr features E = presets::with_mode(F, evaluation::exact);
    material<T> mat{.ka = glm::vec<3, T>(T(0.5)), .kd = glm::vec<3, T>(T(0.25)), .ks = glm::vec<3, T>(T(1)), .shininess = T(0)};
    std::array<light<T>, 1> lights{};
    lights[0].position = {T(0), T(0), T(-2), T(1)};
    lights[0].ambient = glm::vec<3, T>(T(0.5));
    environment<T> env{.ambient = glm::vec<3, T>(T(1))};
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    soa_scene<T> s;
    s.add({T(0), T(0), T(-1)}, {T(0), T(0), T(1)});   // 0: lit from behind the eye's line: light at z=-2 is behind Q (n.l < 0)
    s.add({T(0), T(0), T(-3)}, {T(0), T(0), T(1)});   // 1: lit head-on: n.l = 1, l = v, m = 0 -> specular 1
    s.add({T(0), T(0), T(-3)}, {T(0), T(0), T(0)});   // 2: zero normal: ambient only
    s.add({T(0), T(0), T(-2)}, {T(0), T(0), T(1)});   // 3: light at Q: ambient only
    s.add({nan, T(0), T(-3)}, {T(0), T(0), T(1)});    // 4: NaN position -> NaN
    s.add({T(0), T(0), T(-3)}, {T(0), inf, T(1)});    // 5: inf normal -> NaN
    for (int rep = 0; rep < int(batch_width<T>); ++rep) s.add({T(0), T(0), T(-3)}, {T(0), T(0), T(1)}); // fill a full batch
    const T ambient_only = T(0.5) * (T(1) + T(0.5)); // ka (La + La_i)
    for (int mode = 0; mode < 2; ++mode) {
        if (mode == 0) s.template shade<F>(mat, lights, env);
        else s.template shade<E>(mat, lights, env);
        CAPTURE(mode);
        CHECK(s.r[0] == ambient_only);                                  // n.l = -1: gated
        CHECK(s.r[1] == doctest::Approx(double(ambient_only + T(0.25) + T(1))).epsilon(1e-6)); // + kd + ks * 1 (m = 0)
        CHECK(s.r[2] == ambient_only);
        CHECK(s.r[3] == ambient_only);
        CHECK(std::isnan(s.r[4]));
        CHECK(std::isnan(s.g[4]));
        CHECK(std::isnan(s.b[5]));
    }
    // Blinn with l = -v exactly: eye at the origin, Q = (0, 0, -1), light at (0, 0, -2): l = (0, 0, -1), v = (0, 0, 1).
    // n = (0, 0, -1) faces the light: n.l = 1 > 0, h undefined -> n.h = 0: specular 0 for m > 0, 1 for m = 0.
    // Both modes: the exact lanes form h = d (1/|d|) + v fused and take |h| < u as this case. A full
    // step too (the kernel's in-place loop), and near-opposite points (light a few ulp off the eye
    // ray: |l + v| at the rounding level) give finite colours within [diffuse only, + ks].
    material<T> shiny = mat;
    shiny.shininess = T(8);
    for (int mode = 0; mode < 2; ++mode) {
        CAPTURE(mode);
        soa_scene<T> opp;
        for (std::size_t i = 0; i < batch_width<T> + 3; ++i) opp.add({T(0), T(0), T(-1)}, {T(0), T(0), T(-1)});
        if (mode == 0) opp.template shade<F>(shiny, lights, env);
        else opp.template shade<E>(shiny, lights, env);
        for (std::size_t i = 0; i < opp.r.size(); ++i)
            CHECK(opp.r[i] == doctest::Approx(double(ambient_only + T(0.25))).epsilon(1e-6)); // diffuse only
        if (mode == 0) opp.template shade<F>(mat, lights, env);
        else opp.template shade<E>(mat, lights, env);
        CHECK(opp.r[2] == doctest::Approx(double(ambient_only + T(0.25) + T(1))).epsilon(1e-6)); // m = 0: 0^0 = 1
        soa_scene<T> near;
        const T e = std::numeric_limits<T>::epsilon();
        for (int k = 1; k <= int(batch_width<T>) + 3; ++k) near.add({T(k) * e, T(0), T(-1)}, {T(0), T(0), T(-1)});
        if (mode == 0) near.template shade<F>(shiny, lights, env);
        else near.template shade<E>(shiny, lights, env);
        for (std::size_t i = 0; i < near.r.size(); ++i) {
            CAPTURE(i);
            CHECK(std::isfinite(near.r[i]));
            CHECK(near.r[i] >= T(0.99) * (ambient_only + T(0.25)));
            CHECK(near.r[i] <= T(1.01) * (ambient_only + T(0.25) + T(1)));
        }
    }
}

// A light nearer than sqrt(smallest normal T): the floor bounds d^2 *before* the window multiplies,
// f = window^2 / max(d^2, floor), in every mode and on every route. Float lights on double lanes
// (the stable mode's wider route) used to cap the quotient instead, min(window^2 / d^2, 1 / floor):
// 1 / window^2 too large (a fuzzer finding, 2026-11-24).
template <class T, features F> void check_light_below_floor()
{
    // d = 2^-62 (float: d^2 = 2^-124 is normal but below the floor 2^-63), range = 2 d: window = (15/16)^2.
    const T d = std::ldexp(T(1), -62);
    material<T> mat{.ka = glm::vec<3, T>(T(1)), .kd = glm::vec<3, T>(T(0)), .ks = glm::vec<3, T>(T(0))};
    std::array<light<T>, 1> lights{};
    lights[0].position = {T(0), d, T(-1), T(1)};
    lights[0].ambient = glm::vec<3, T>(T(1));
    lights[0].attenuation.range = 2 * d;
    const environment<T> env{};
    // The formula written literally, in long double, with the documented floors (2^-63 float, 2^-511 double).
    const long double floor = std::is_same_v<T, float> ? std::ldexp(1.0L, -63) : std::ldexp(1.0L, -511);
    const long double dd = std::ldexp(1.0L, -124), window = 1 - std::pow(0.5L, 4);
    const double expected = double(window * window / std::max(dd, floor));
    soa_scene<T> s;
    for (std::size_t i = 0; i < batch_width<T> + 1; ++i) s.add({T(0), T(0), T(-1)}, {T(0), T(0), T(1)});
    s.template shade<F>(mat, lights, env);
    const auto scalar = shade<F>(glm::vec<3, T>(T(0), T(0), T(-1)), glm::vec<3, T>(T(0), T(0), T(1)), mat, lights, env);
    CHECK(double(scalar.r) == doctest::Approx(expected).epsilon(1e-6));
    for (std::size_t i = 0; i < s.size(); ++i) CHECK(double(s.r[i]) == doctest::Approx(expected).epsilon(1e-6));
}

TEST_CASE("shade_batch and shade: a light nearer than the attenuation floor gets the window, every mode")
{
    constexpr features F{.scene_ambient = false, .light_ambient = true, .diffuse = false, .specular = specular_model::none,
                         .lights = light_kind::positional, .attenuation = attenuation_model::windowed};
    constexpr features twofold{.scene_ambient = false, .light_ambient = true, .diffuse = false, .specular = specular_model::none,
                               .lights = light_kind::positional, .attenuation = attenuation_model::windowed,
                               .mode = evaluation::stable, .precision = stable_precision::twofold};
    check_light_below_floor<float, presets::with_mode(F, evaluation::exact)>();
    check_light_below_floor<float, presets::with_mode(F, evaluation::stable)>();
    check_light_below_floor<float, twofold>();
    check_light_below_floor<float, presets::with_mode(F, evaluation::fast)>();
    check_light_below_floor<double, presets::with_mode(F, evaluation::stable)>();
}

// The stable mode's view vector normalize(E.xyz - E.w Q) does not change when the eye point E is
// scaled by a power of two. A tiny E (components 3e-319 and 2.5e-322, subnormal) and the same E
// times 2^1000 (exact) must give the same colours, bit for bit, scalar and batch: the tiny one's
// products E.w Q are subnormal, where the twofold product error is not exact (a fuzzer finding,
// 2026-11-25: 1.4e-6 between the scalar path and SSE2 lanes).
TEST_CASE("stable mode: a tiny eye point gives the colours of the same eye scaled by 2^1000")
{
    constexpr features F{.specular_gate = false, .lights = light_kind::any, .two_sided = facing::view,
                         .view = view_model::eye_point, .mode = evaluation::stable};
    const material<double> mat{.ka = glm::dvec3(0.5), .kd = glm::dvec3(0.75), .ks = glm::dvec3(0.25), .shininess = 10.4375};
    std::array<light<double>, 1> lights{};
    lights[0].position = {-1.0, -1.0, -11.75, 0.0};
    environment<double> tiny{}, scaled{};
    tiny.eye = {0.0, 0.0, 3.2379086165851934e-319, 2.4703282292062327e-322};
    scaled.eye = tiny.eye * 0x1p1000;
    soa_scene<double> a, b;
    for (int k = 0; k < 9; ++k) {
        const glm::dvec3 q(-5.75 + 0.5 * k, -10.0, -10.0 + 0.25 * k), n(-1.0, -1.0, 0.125 * k);
        a.add(q, n), b.add(q, n);
        const auto c1 = shade<F>(q, n, mat, lights, tiny), c2 = shade<F>(q, n, mat, lights, scaled);
        CAPTURE(k);
        CHECK(c1 == c2);
    }
    a.template shade<F>(mat, lights, tiny);
    b.template shade<F>(mat, lights, scaled);
    for (std::size_t i = 0; i < a.size(); ++i) {
        CAPTURE(i);
        CHECK(a.color(i) == b.color(i));
    }
}

TEST_CASE_TEMPLATE("stable mode: an eye point whose products E.w Q are subnormal or overflow gives the colours of the model",
                   T, float, double)
{
    // v = normalize(E.xyz - E.w Q) where the products E.w Q are subnormal (double: Q ~ 1e-315,
    // float: 1e-40), so that their twofold error terms are not exact; where E.xyz cancels E.w Q in
    // one component and the others are subnormal; where E.xyz and Q are subnormal and E.w is not
    // (a scaling of E by E.w first lost E.xyz's bits); and where |E.w Q| is beyond T's range although
    // the direction is finite. Phong at m = 1000 with l mirroring v about n, so that an error of
    // the view moves the colour m-fold. Expected: the reference model (tests/support/reference.hpp,
    // in a wide type); scalar and batch within 8 eps (before: 1e-8 to 2e-3 in double; no specular
    // at all where E.w Q overflowed). Float takes the twofold route (the wider one, double, has
    // none of these).
    constexpr features F{.specular_gate = false, .lights = light_kind::any, .two_sided = facing::view,
                         .view = view_model::eye_point, .mode = evaluation::stable, .precision = stable_precision::twofold};
    constexpr bool is_double = std::is_same_v<T, double>;
    using vec3 = glm::vec<3, T>;
    const material<T> mat{.ka = vec3(0), .kd = vec3(0.25), .ks = vec3(0.5), .shininess = T(1000)};
    struct eye_case {
        glm::vec<4, T> eye;
        vec3 point;      ///< points: point + (k dx, k dy, 0) times scale, k = 0..5 (x, y: the scaled part)
        T scale;
        bool cancel_x;   ///< point.x is not scaled: E.x - E.w Q.x = 0 exactly
    };
    const T tiny = is_double ? T(1e-315) : T(1e-40), huge_w = is_double ? T(0x1p600) : T(0x1p100),
            huge_q = is_double ? T(0x1p500) : T(0x1p60), huge_x = is_double ? T(0x1p1000) : T(0x1p120),
            big_q = is_double ? T(0x1p420) : T(0x1p40), sub = is_double ? T(1e-320) : T(1e-42);
    const vec3 mirror(T(0.31), T(0.17), T(-1)); // v along -mirror: l = (0.32, 0.16, 1) mirrors it about n
    const eye_case cases[] = {
        {{T(0), T(0), T(0), T(0.3)}, mirror, tiny, false},
        {{T(0), T(0), T(0), T(1e-5)}, mirror, tiny, false},
        {{tiny / 10, T(0), T(0), T(0.7)}, mirror, tiny, false},
        {{T(1), T(0), T(0), T(0.5)}, vec3(T(2), T(0.17), T(-1)), tiny / 100, true},
        {{sub / 4, -sub / 4, sub / 4, T(50.0943)}, mirror, sub, false}, // E.xyz and Q subnormal, E.w not tiny
        {{T(0), T(0), T(0), huge_w}, mirror, huge_q, false},
        {{huge_x, T(0), T(0), huge_w / 3}, mirror, big_q, false},
    };
    const wide tolerance = 8 * wide(std::numeric_limits<T>::epsilon());
    const vec3 n(T(0), T(0), T(1));
    for (const eye_case& c : cases) {
        std::array<light<T>, 1> lights{};
        lights[0].position = {c.cancel_x ? T(0) : T(0.32), T(0.16), T(1), T(0)};
        environment<T> env{};
        env.eye = c.eye;
        soa_scene<T> pts;
        std::vector<wcolor> expected;
        for (int k = 0; k < 6; ++k) {
            const vec3 base = c.point + vec3(T(0.013 * k), T(-0.007 * k), T(0));
            vec3 q = base * (c.scale * T(1 + k));
            if (c.cancel_x) q.x = c.point.x;
            pts.add(q, n);
            expected.push_back(reference_shade(F, q, n, mat, std::span<const light<T>>(lights), env));
        }
        pts.template shade<F>(mat, lights, env);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            CAPTURE(c.eye.x);
            CAPTURE(c.eye.w);
            CAPTURE(c.scale);
            CAPTURE(i);
            const vec3 q(pts.px[i], pts.py[i], pts.pz[i]);
            const auto scalar = shade<F>(q, n, mat, lights, env);
            CHECK(expected[i].r > 1e-3); // the specular term is on: the test reads the view vector
            for (int ch = 0; ch < 3; ++ch) {
                CAPTURE(ch);
                CHECK(std::abs(wide(scalar[ch]) - expected[i][ch]) <= tolerance * expected[i][ch]);
                CHECK(std::abs(wide(pts.color(i)[ch]) - expected[i][ch]) <= tolerance * expected[i][ch]);
            }
        }
    }
}

TEST_CASE_TEMPLATE("stable mode: eye points and positions at every scale stay within the well-conditioned bound", T, float, double)
{
    // Inputs no bound was fitted to: eye, point and light position scaled together by 2^k, k drawn
    // over T's whole exponent range (subnormal to near max), the eye's w at any scale of its own,
    // against the reference model. Scene ambient and ka keep every channel away from 0, and points
    // within 1e-6 of the two-sided flip n.v = 0 are left out (the model's discontinuity). Held to
    // the published well_conditioned max_rel, scalar and batch. Before 2026-11-25: up to 1.98
    // relative in double (E.xyz and Q subnormal, E.w normal).
    constexpr features F{.specular_gate = false, .lights = light_kind::any, .two_sided = facing::view,
                         .view = view_model::eye_point, .mode = evaluation::stable, .precision = stable_precision::twofold};
    constexpr bool is_double = std::is_same_v<T, double>;
    using vec3 = glm::vec<3, T>;
    const double bound = accuracy::of<evaluation::stable, T, stable_precision::twofold>(accuracy::input_class::well_conditioned).max_rel;
    std::mt19937_64 rng(20261125);
    std::uniform_real_distribution<double> u(-1, 1);
    std::uniform_int_distribution<int> exponent(is_double ? -1074 : -149, is_double ? 1000 : 110), w_exponent(-40, 40);
    const material<T> mat{.ka = vec3(T(0.25)), .kd = vec3(T(0.5)), .ks = vec3(T(0.5)), .shininess = T(50)};
    environment<T> env{};
    env.ambient = vec3(T(1));
    std::array<light<T>, 1> lights{};
    const auto scaled = [](double x, int k) { return T(std::ldexp(x, k)); }; // x rounded to T at 2^k
    int compared = 0;
    for (int round = 0; round < 300; ++round) {
        const int k = exponent(rng);
        env.eye = {scaled(u(rng), k), scaled(u(rng), k), scaled(u(rng), k), scaled(std::abs(u(rng)), w_exponent(rng) / (is_double ? 1 : 2))};
        lights[0].position = {T(u(rng)), T(u(rng)), T(1 + u(rng)), T(0)};
        soa_scene<T> pts;
        std::vector<wcolor> expected;
        std::vector<bool> keep;
        for (int i = 0; i < 20; ++i) {
            const vec3 q(scaled(u(rng), k), scaled(u(rng), k), scaled(u(rng) - 1.5, k)), n(T(u(rng)), T(u(rng)), T(1));
            pts.add(q, n);
            expected.push_back(reference_shade(F, q, n, mat, std::span<const light<T>>(lights), env));
            const wvec3 v = wvec3{wide(env.eye.x), wide(env.eye.y), wide(env.eye.z)} - widen(q) * wide(env.eye.w);
            const wide nv = wdot(v, widen(n)), lengths = wsqrt(wdot(v, v) * wdot(widen(n), widen(n)));
            keep.push_back(lengths > 0 && wabs(nv) > wide(1e-6) * lengths);
        }
        pts.template shade<F>(mat, lights, env);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            if (!keep[i]) continue;
            ++compared;
            const vec3 q(pts.px[i], pts.py[i], pts.pz[i]), n(pts.nx[i], pts.ny[i], pts.nz[i]);
            const auto scalar = shade<F>(q, n, mat, lights, env);
            CAPTURE(k);
            CAPTURE(env.eye.w);
            CAPTURE(i);
            for (int ch = 0; ch < 3; ++ch) {
                CHECK(wabs(wide(scalar[ch]) - expected[i][ch]) <= wide(bound) * expected[i][ch]);
                CHECK(wabs(wide(pts.color(i)[ch]) - expected[i][ch]) <= wide(bound) * expected[i][ch]);
            }
        }
    }
    CHECK(compared > 5000); // the flip's band leaves out few points
}

TEST_CASE_TEMPLATE("stable mode: an eye point that is zero, subnormal, huge or mixed gives finite colours, scalar and batch", T,
                   float, double)
{
    // Finite input never gives NaN or inf (shade.hpp): E = 0 (no view vector: no specular term),
    // E.w = the least subnormal, every component at the largest finite T (|E.w Q| far beyond the
    // range), E.x huge with E.w subnormal, a direction (w = 0); points at 0, subnormal, near max.
    constexpr features F{.specular_gate = false, .lights = light_kind::any, .two_sided = facing::view,
                         .view = view_model::eye_point, .mode = evaluation::stable, .precision = stable_precision::twofold};
    using vec3 = glm::vec<3, T>;
    using vec4 = glm::vec<4, T>;
    const T big = std::numeric_limits<T>::max(), den = std::numeric_limits<T>::denorm_min();
    const material<T> mat{.ka = vec3(T(0.25)), .kd = vec3(T(0.5)), .ks = vec3(T(0.5)), .shininess = T(10)};
    std::array<light<T>, 1> lights{};
    lights[0].position = {T(1), T(2), T(3), T(1)};
    const vec4 eyes[] = {vec4(0), vec4(T(0), T(0), T(0), den), vec4(den, T(0), T(0), T(0)), vec4(big, big, -big, big),
                         vec4(T(0), T(0), T(0), big), vec4(big, T(0), T(0), den), vec4(T(1), T(2), T(3), T(0))};
    const vec3 points[] = {vec3(0), vec3(den, den, -den), vec3(big / 4, -big / 4, big / 4), vec3(big), vec3(T(0.5), T(0.25), T(-3))};
    const vec3 n(T(0.25), T(0.125), T(1));
    for (const vec4& eye : eyes) {
        environment<T> env{};
        env.eye = eye;
        soa_scene<T> pts;
        for (const vec3& q : points) pts.add(q, n);
        pts.template shade<F>(mat, lights, env);
        for (std::size_t i = 0; i < pts.size(); ++i) {
            CAPTURE(eye.x);
            CAPTURE(eye.w);
            CAPTURE(i);
            const auto scalar = shade<F>(points[i], n, mat, lights, env);
            for (int ch = 0; ch < 3; ++ch) {
                CHECK(std::isfinite(scalar[ch]));
                CHECK(scalar[ch] >= T(0));
                CHECK(std::isfinite(pts.color(i)[ch]));
                CHECK(pts.color(i)[ch] >= T(0));
            }
        }
    }
}

TEST_CASE_TEMPLATE("stable mode: scaling every position and normal by 2^k leaves the colours unchanged, bit for bit", T, float, double)
{
    // Without attenuation the model reads only directions, and 2^k (Q, L.xyz, E.xyz, n) has the
    // directions of (Q, L.xyz, E.xyz, n) for every k, subnormal and huge values included: the
    // stable mode's rescaling by powers of two must then give the same bits (the twofold route
    // relies on exact error terms, which a subnormal intermediate loses). Positions are on a grid
    // of 10-bit values, so that 2^k of them is exact; E.w is not (0.3, 1e-5, ...), so that E.w Q is
    // an inexact product whose scaled copy may be subnormal. Float takes the twofold route.
    constexpr bool is_double = std::is_same_v<T, double>;
    using vec3 = glm::vec<3, T>;
    std::mt19937 rng(20261125);
    std::uniform_int_distribution<int> grid(-512, 511);
    const auto coordinate = [&] { return T(grid(rng)) / T(64); }; // [-8, 8), lowest bit 2^-6
    const auto point = [&] { return vec3(coordinate(), coordinate(), coordinate() - T(9)); };
    const std::vector<int> ks = is_double ? std::vector<int>{-1066, -1040, -1000, -960, -500, 0, 500, 1000}
                                          : std::vector<int>{-140, -130, -110, -100, -60, 0, 60, 110};
    const T eye_ws[] = {T(1), T(0.3), T(1e-5), T(3.7), T(0)};
    const auto run = [&]<features F>() {
        const material<T> mat{.ka = vec3(T(0.25)), .kd = vec3(T(0.5)), .ks = vec3(T(0.75)), .shininess = T(37.5)};
        for (int trial = 0; trial < 8; ++trial) {
            std::array<light<T>, 3> lights{};
            for (std::size_t j = 0; j < lights.size(); ++j) {
                const vec3 p = point();
                lights[j].position = glm::vec<4, T>(p, T(j == 2 ? 0 : 1)); // two positional, one directional
                lights[j].ambient = vec3(T(0.125));
            }
            environment<T> env{};
            const vec3 e = point() + vec3(T(0), T(0), T(9));
            env.eye = glm::vec<4, T>(e, eye_ws[trial % 5]);
            std::vector<vec3> qs, ns;
            for (int i = 0; i < 11; ++i) qs.push_back(point()), ns.push_back(vec3(coordinate(), coordinate(), coordinate() + T(8)));
            std::vector<glm::vec<4, T>> base_scalar, base_batch;
            for (int k : ks) {
                const T f = std::ldexp(T(1), k);
                std::array<light<T>, 3> scaled_lights = lights;
                for (std::size_t j = 0; j < 3; ++j) scaled_lights[j].position = glm::vec<4, T>(vec3(lights[j].position) * f, lights[j].position.w);
                environment<T> scaled_env = env;
                scaled_env.eye = glm::vec<4, T>(e * f, env.eye.w);
                soa_scene<T> pts;
                for (std::size_t i = 0; i < qs.size(); ++i) pts.add(qs[i] * f, ns[i] * f);
                pts.template shade<F>(mat, scaled_lights, scaled_env);
                for (std::size_t i = 0; i < qs.size(); ++i) {
                    const auto c = shade<F>(qs[i] * f, ns[i] * f, mat, scaled_lights, scaled_env);
                    const glm::vec<4, T> scalar(c[0], c[1], c[2], T(0)), batch = pts.color(i);
                    if (k == ks.front()) {
                        base_scalar.push_back(scalar), base_batch.push_back(batch);
                        continue;
                    }
                    CAPTURE(trial);
                    CAPTURE(k);
                    CAPTURE(i);
                    CHECK(glm::vec<3, T>(scalar) == glm::vec<3, T>(base_scalar[i]));
                    CHECK(batch == base_batch[i]);
                }
            }
        }
    };
    static constexpr features phong_eye{.light_ambient = true, .lights = light_kind::any, .two_sided = facing::view,
                                        .view = view_model::eye_point, .mode = evaluation::stable, .precision = stable_precision::twofold};
    static constexpr features blinn_eye = [] {
        features f = phong_eye;
        f.specular = specular_model::blinn;
        f.specular_gate = false;
        return f;
    }();
    static constexpr features phong_origin = [] {
        features f = phong_eye;
        f.view = view_model::eye_at_origin;
        return f;
    }();
    run.template operator()<phong_eye>();
    run.template operator()<blinn_eye>();
    run.template operator()<phong_origin>();
}

TEST_CASE_TEMPLATE("shade_batch: per-point materials and interleaved output equal the SoA path", T, float, double)
{
    constexpr features F{.light_ambient = true, .specular = specular_model::blinn, .lights = light_kind::any,
                         .attenuation = attenuation_model::polynomial, .emission = true, .alpha = true,
                         .mode = evaluation::stable};
    scene_gen<T> gen(4242);
    const scene<T> base = gen.make(F, 3);
    const std::size_t n = 2 * batch_width<T> + 3;
    soa_scene<T> pts;
    std::vector<material<T>> mats;
    for (std::size_t i = 0; i < n; ++i) {
        pts.add(gen.point(), gen.direction());
        mats.push_back(gen.material(1, 100));
    }
    const soa3<T> P{pts.px, pts.py, pts.pz}, N{pts.nx, pts.ny, pts.nz};
    std::vector<T> r(n), g(n), b(n), a(n);
    shade_batch<F>(P, N, std::span<const material<T>>(mats), std::span<const light<T>>(base.lights),
                   soa_rgba<T>{r, g, b, a}, base.env);
    std::vector<glm::vec<4, T>> interleaved(n);
    shade_batch<F>(P, N, std::span<const material<T>>(mats), std::span<const light<T>>(base.lights),
                   std::span<glm::vec<4, T>>(interleaved), base.env);
    // One material for all points is folded into the lights (ka La_i, kd Ld_i, ks Ls_i, once per
    // call), per-point materials multiply the sums at the end: the same terms with the material
    // product rounded before instead of after the sum over K lights. Every term is non-negative, so
    // each channel differs by at most 2 (K + 4) roundings relative to it.
    const double tolerance = 2 * (double(base.lights.size()) + 4) * std::numeric_limits<T>::epsilon() / 2;
    const auto close = [&](T x, T y) { return std::abs(double(x) - double(y)) <= tolerance * std::abs(double(y)); };
    for (std::size_t i = 0; i < n; ++i) {
        // Per-point material: each lane equals the same point shaded alone with its own material.
        soa_scene<T> one;
        one.add({pts.px[i], pts.py[i], pts.pz[i]}, {pts.nx[i], pts.ny[i], pts.nz[i]});
        one.template shade<F>(mats[i], base.lights, base.env);
        CHECK(close(r[i], one.r[0]));
        CHECK(close(g[i], one.g[0]));
        CHECK(close(b[i], one.b[0]));
        CHECK(a[i] == mats[i].alpha);
        CHECK(interleaved[i] == glm::vec<4, T>(r[i], g[i], b[i], a[i]));
    }
}

TEST_CASE("shade_batch: width and layer")
{
    // The batch type is a real SIMD type when xsimd has lanes for the target (at least SSE2's or
    // NEON's 4 float lanes, doubles half as many); else one point at a time (RISC-V, POWER).
    if (PHONG_HAS_XSIMD) {
        CHECK(batch_width<float> >= 4);
        CHECK(batch_width<double> * 2 == batch_width<float>);
    } else {
        CHECK(batch_width<float> == 1);
        CHECK(batch_width<double> == 1);
    }
    MESSAGE("batch width: " << batch_width<float> << " floats, " << batch_width<double> << " doubles");
}



#if PHONG_HAS_XSIMD
TEST_CASE_TEMPLATE("shade_batch lanes: normal_square is exactly 'min <= dd <= max', lane by lane", T, float, double)
{
    // The exact mode's range test of a squared length (one vfpclass on AVX-512DQ) against the
    // definition evaluated in scalars, on every class of number: zeros, subnormals, the normal
    // range's ends, negatives, infinities, NaN.
    using V = simd_batch<T>;
    constexpr std::size_t W = batch_width<T>;
    using lim = std::numeric_limits<T>;
    const std::vector<T> values{T(0), -T(0), lim::denorm_min(), std::nextafter(lim::min(), T(0)), lim::min(),
                                std::nextafter(lim::min(), T(1)), T(0.5), T(1), T(3e7), std::nextafter(lim::max(), T(0)),
                                lim::max(), lim::infinity(), -lim::infinity(), lim::quiet_NaN(), -lim::quiet_NaN(), -lim::min(),
                                -T(1), -lim::max(), -lim::denorm_min()};
    for (std::size_t start = 0; start < values.size(); start += W) {
        alignas(64) T x[W];
        alignas(64) T on_values[W];
        for (std::size_t k = 0; k < W; ++k) {
            x[k] = values[(start + k) % values.size()];
            on_values[k] = k % 3 == 1 ? T(0) : T(1); // a mask with some lanes off
        }
        const V lanes = V::load_aligned(x);
        const auto on = V::load_aligned(on_values) > V(T(0));
        alignas(64) T got[W], got_and[W];
        phong::detail::select(detail::normal_square(lanes), V(T(1)), V(T(0))).store_aligned(got);
        phong::detail::select(detail::both_normal_square(on, lanes), V(T(1)), V(T(0))).store_aligned(got_and);
        for (std::size_t k = 0; k < W; ++k) {
            CAPTURE(x[k]);
            const bool expected = x[k] >= lim::min() && x[k] <= lim::max();
            CHECK((got[k] == T(1)) == expected);
            CHECK((got_and[k] == T(1)) == (expected && on_values[k] == T(1)));
        }
    }
}
#endif

#if PHONG_LANES_WITHOUT_FMA
namespace {
/// shade_batch on aos_points with per-point views, light masks and a material table, against
/// shade<F> point by point: equal bit for bit (x86 without FMA instructions: shade_batch shades
/// point by point there, PHONG_LANES_WITHOUT_FMA).
template <features F, class T>
void one_by_one_equals_shade()
{
    std::mt19937 rng(2711);
    std::uniform_real_distribution<T> u(T(-1), T(1));
    const std::size_t n = 37;
    std::vector<glm::vec<3, T>> p(n), nrm(n), v(n), out(n);
    std::vector<std::uint64_t> masks(n);
    std::vector<std::uint32_t> ids(n);
    for (std::size_t i = 0; i < n; ++i) {
        p[i] = {u(rng), u(rng), u(rng) - T(3)};
        nrm[i] = {u(rng), u(rng), u(rng) + T(1.5)};
        v[i] = -p[i];
        masks[i] = rng() & 7u;
        ids[i] = std::uint32_t(rng() % 2);
    }
    std::vector<material<T>> table(2);
    table[1].shininess = T(64);
    table[1].ks = glm::vec<3, T>(T(0.7));
    std::vector<light<T>> lights{light<T>::with_strength({1, 2, 1, 1}, glm::vec<3, T>(1)),
                                 light<T>::with_strength({-1, 0, 1, 0}, glm::vec<3, T>(T(0.5))),
                                 light<T>::with_strength({0, -2, 0, 1}, glm::vec<3, T>(T(0.3)))};
    const environment<T> env{.ambient = glm::vec<3, T>(T(0.1))};
    shade_batch<F>(aos_points<T>{.positions = p, .normals = nrm, .views = v, .light_masks = masks},
                   material_table<T>{.materials = table, .ids = ids}, std::span<const light<T>>(lights),
                   std::span<glm::vec<3, T>>(out), env);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec<3, T> expected = shade<F>(p[i], nrm[i], v[i], table[ids[i]], masked(lights, masks[i]), env);
        CAPTURE(i);
        CHECK(std::memcmp(&expected, &out[i], sizeof expected) == 0);
    }
}
} // namespace

TEST_CASE_TEMPLATE("shade_batch without FMA instructions: shade<F> point by point, bit for bit", T, float, double)
{
    constexpr features given = [] {
        features f = presets::blinn_phong_per_light_ambient;
        f.view = view_model::given;
        return f;
    }();
    one_by_one_equals_shade<given, T>();
    one_by_one_equals_shade<presets::with_mode(given, evaluation::stable), T>();
    one_by_one_equals_shade<presets::with_mode(given, evaluation::fast), T>();
}
#endif
