// batch.hpp's inputs beyond G-buffers (issue 13, item 4): per-point view vectors
// (view_model::given), per-point light masks, and AoS (glm::vec3) hit arrays, through
// soa_points / aos_points. The oracle is the scalar shade<F> with the same view vector and
// phong::masked(lights, mask) per point; AoS against SoA and a masked light against a removed
// one are compared bit for bit (the lanes are the same values and the kernels lane-wise).
#include "support/batch_case.hpp"
#include "support/generators.hpp"

#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

using namespace phong;
using namespace phong_test;

namespace {

/// Tolerance of batch against scalar (as tests/batch.test.cpp, same reasons): both are within
/// the mode's bound of the reference, but the SIMD rsqrt estimate (float lanes, < 2 ulp),
/// xsimd's exp/log and FMA contraction shift the rounding; the exact mode's power amplifies
/// that by up to m, the stable mode's by about sqrt(m).
template <class T> double batch_tolerance(const features& F, double m)
{
    const double eps = std::numeric_limits<T>::epsilon();
    const double amplification = F.mode == evaluation::exact ? 1 + m : 1 + 4 * std::sqrt(m);
    return 64 * eps * amplification;
}

/// Relative difference of two colours, per channel, against the largest channel of the reference.
template <class T, glm::length_t N> double channel_difference(const glm::vec<N, T>& a, const glm::vec<N, T>& b)
{
    double scale = 0, diff = 0;
    for (glm::length_t k = 0; k < N; ++k) {
        scale = std::max(scale, double(std::abs(b[k])));
        diff = std::max(diff, double(std::abs(a[k] - b[k])));
    }
    return diff / std::max(scale, 1e-30);
}

template <features F> constexpr features conditioning_features()
{
    features G = F;
    if (G.view == view_model::given) G.view = view_model::eye_point;
    return G;
}

/// The scalar oracle for point i: shade<F>(Q, n, [v,] mat, masked(lights, mask) or lights, env, front).
template <features F, class T>
color<F, T> scalar_shade(const batch_case<T>& c, std::size_t i, const material<T>& mat, bool masked_lights)
{
    const std::span<const light<T>> lights(c.base.lights);
    const std::uint64_t mask = masked_lights ? c.masks[i] : ~std::uint64_t(0);
    if constexpr (F.view == view_model::given)
        return shade<F>(c.p[i], c.n[i], c.v[i], mat, masked(lights, mask), c.base.env, c.front[i]);
    else
        return shade<F>(c.p[i], c.n[i], mat, masked(lights, mask), c.base.env, c.front[i]);
}

/// Every layout and variant of the call for one feature set, against the scalar oracle, for
/// every tail length; AoS against SoA bit for bit.
template <class T, features F> void check_inputs(std::uint64_t seed)
{
    constexpr bool given = F.view == view_model::given;
    constexpr std::size_t W = batch_width<T>;
    constexpr int channels = F.alpha ? 4 : 3;
    scene_gen<T> gen(seed);
    int checked = 0;
    for (std::size_t count : {std::size_t(0), std::size_t(1), W - 1, W, W + 1, 3 * W + 5, std::size_t(61)}) {
        for (int masked_lights = 0; masked_lights < 2; ++masked_lights) {
            for (int per_point_material = 0; per_point_material < 2; ++per_point_material) {
                const batch_case<T> c(gen, F, count, 1 + gen.integer(0, 4));
                CAPTURE(count);
                CAPTURE(masked_lights);
                CAPTURE(per_point_material);
                const std::span<const light<T>> lights(c.base.lights);
                const std::span<const material<T>> mats(c.mats);
                std::vector<T> r(count, T(-1)), g(count, T(-1)), b(count, T(-1)), a(count, T(-1));
                std::vector<color<F, T>> interleaved(count, color<F, T>(T(-2)));
                const soa_rgba<T> out{r, g, b, a};
                if (per_point_material) {
                    shade_batch<F>(c.soa(given, masked_lights), mats, lights, out, c.base.env);
                    shade_batch<F>(c.aos(given, masked_lights), mats, lights, std::span<color<F, T>>(interleaved), c.base.env);
                } else {
                    shade_batch<F>(c.soa(given, masked_lights), c.base.mat, lights, out, c.base.env);
                    shade_batch<F>(c.aos(given, masked_lights), c.base.mat, lights, std::span<color<F, T>>(interleaved), c.base.env);
                }
                // The other two layout pairs (SoA in with interleaved out, AoS in with SoA out).
                std::vector<color<F, T>> soa_interleaved(count, color<F, T>(T(-3)));
                std::vector<T> r2(count), g2(count), b2(count), a2(count);
                if (per_point_material) {
                    shade_batch<F>(c.soa(given, masked_lights), mats, lights, std::span<color<F, T>>(soa_interleaved), c.base.env);
                    shade_batch<F>(c.aos(given, masked_lights), mats, lights, soa_rgba<T>{r2, g2, b2, a2}, c.base.env);
                } else {
                    shade_batch<F>(c.soa(given, masked_lights), c.base.mat, lights, std::span<color<F, T>>(soa_interleaved), c.base.env);
                    shade_batch<F>(c.aos(given, masked_lights), c.base.mat, lights, soa_rgba<T>{r2, g2, b2, a2}, c.base.env);
                }
                for (std::size_t i = 0; i < count; ++i) {
                    const glm::vec<4, T> soa_rgba_i(r[i], g[i], b[i], a[i]);
                    const glm::vec<4, T> aos_rgba_i(r2[i], g2[i], b2[i], a2[i]);
                    color<F, T> got;
                    for (int k = 0; k < channels; ++k) got[k] = soa_rgba_i[k];
                    // Bit for bit: every layout loads the same lanes.
                    CHECK(interleaved[i] == got);
                    CHECK(soa_interleaved[i] == got);
                    for (int k = 0; k < channels; ++k) CHECK(aos_rgba_i[k] == got[k]);
                    for (int k = 0; k < channels; ++k) REQUIRE(std::isfinite(got[k]));

                    const material<T>& mat = per_point_material ? c.mats[i] : c.base.mat;
                    const color<F, T> scalar = scalar_shade<F>(c, i, mat, masked_lights != 0);
                    if (!well_conditioned(conditioning_features<F>(), c.point_scene(i, F, per_point_material), 1e-3))
                        continue; // a rounding may flip a gate or a cone edge
                    ++checked;
                    const double diff = channel_difference(got, scalar);
                    const double tol = batch_tolerance<T>(F, double(mat.shininess));
                    if (diff > tol) MESSAGE("point " << i << ": batch vs scalar relative difference " << diff << " > " << tol);
                    CHECK(diff <= tol);
                }
            }
        }
    }
    CHECK(checked > 100); // the comparison did run on most points
}

/// A light whose mask bit is clear equals that light removed, bit for bit: each point of a
/// masked batch against the same point alone in a batch whose light list holds only the lights
/// its mask lets through, all marked visible (lanes are independent, so the lane position does
/// not matter; masks given to both, so both run the same compiled code also in the scalar build
/// without xsimd, where a call without masks runs shade<F>'s loop over the plain span instead).
template <class T, features F> void check_masked_equals_removed(std::uint64_t seed)
{
    constexpr bool given = F.view == view_model::given;
    constexpr std::size_t W = batch_width<T>;
    scene_gen<T> gen(seed);
    const std::size_t count = 2 * W + 3;
    const batch_case<T> c(gen, F, count, 5);
    std::vector<color<F, T>> got(count);
    shade_batch<F>(c.aos(given, true), c.base.mat, c.base.lights, std::span<color<F, T>>(got), c.base.env);
    for (std::size_t i = 0; i < count; ++i) {
        std::vector<light<T>> kept;
        for (std::size_t j = 0; j < c.base.lights.size(); ++j)
            if (c.masks[i] >> j & 1u) kept.push_back(c.base.lights[j]);
        std::vector<color<F, T>> alone(1);
        const bool front = c.front[i];
        const std::uint64_t all_visible = ~std::uint64_t(0);
        aos_points<T> one{std::span(&c.p[i], 1), std::span(&c.n[i], 1), {}, std::span(&front, 1), std::span(&all_visible, 1)};
        if (given) one.views = std::span(&c.v[i], 1);
        shade_batch<F>(one, c.base.mat, kept, std::span<color<F, T>>(alone), c.base.env);
        CAPTURE(i);
        CAPTURE(c.masks[i]);
        CHECK(got[i] == alone[0]);
    }
}

/// shade_lanes takes up to steps_per_call steps per call: a long call (several calls of several
/// steps, masked or not, SoA and AoS) gives each point the bits that point gets shaded alone (a
/// tail of one point: a call of one step). Lanes are independent, so the position of a point in
/// its step and of a step in its call must not matter.
template <class T, features F> void check_long_call_equals_points_alone(std::uint64_t seed, bool integer_shininess = false)
{
    constexpr bool given = F.view == view_model::given;
    constexpr std::size_t W = batch_width<T>;
    scene_gen<T> gen(seed);
    const std::size_t count = (2 * detail::steps_per_call + 3) * W + 5; // three calls, the last one short, and a tail
    batch_case<T> c(gen, F, count, 3);
    // An integer shininess: the fast mode's lanes then take fast::detail::pow_integer.
    if (integer_shininess) c.base.mat.shininess = std::round(std::min(c.base.mat.shininess, T(64)));
    for (bool masked : {false, true}) {
        std::vector<color<F, T>> soa_out(count), aos_out(count);
        shade_batch<F>(c.soa(given, masked), c.base.mat, c.base.lights, std::span<color<F, T>>(soa_out), c.base.env);
        shade_batch<F>(c.aos(given, masked), c.base.mat, c.base.lights, std::span<color<F, T>>(aos_out), c.base.env);
        // SoA in and out: full steps read and written in place (detail::steps_per_call per call).
        std::vector<T> channel[4];
        for (std::vector<T>& ch : channel) ch.assign(count, T(-1));
        shade_batch<F>(c.soa(given, masked), c.base.mat, c.base.lights, soa_rgba<T>{channel[0], channel[1], channel[2], channel[3]},
                       c.base.env);
        std::vector<color<F, T>> in_place_out(count);
        for (std::size_t i = 0; i < count; ++i)
            for (int k = 0; k < (F.alpha ? 4 : 3); ++k) in_place_out[i][k] = channel[k][i];
        std::size_t same = 0;
        for (std::size_t i = 0; i < count; ++i) {
            std::vector<color<F, T>> alone(1);
            shade_batch<F>(c.point_alone(i, given, masked), c.base.mat, c.base.lights, std::span<color<F, T>>(alone), c.base.env);
            same += soa_out[i] == alone[0] && aos_out[i] == alone[0] && in_place_out[i] == alone[0];
        }
        CAPTURE(masked);
        CHECK(same == count);
    }
}

/// shade_batch of c's points without masks against the same call with every light mask set, bit for
/// bit (NaN included: the bytes). Returns at how many points the call without a specular term
/// differs (the callers check that the power was compared at all). c's masks are all set and its
/// lights have no ambient term: a call without masks adds the sum of those once per call, a masked
/// one per light (different roundings, about 2e-7 relative in float).
template <class T, features F> std::size_t check_unmasked_equals_masked(const batch_case<T>& c, const material<T>& mat)
{
    constexpr bool given = F.view == view_model::given;
    const std::size_t count = c.p.size();
    material<T> dull = mat; // no specular term: the difference below is the specular term
    dull.ks = glm::vec<3, T>(0);
    std::vector<color<F, T>> unmasked(count), masked_call(count), diffuse_only(count);
    shade_batch<F>(c.soa(given, false), mat, c.base.lights, std::span<color<F, T>>(unmasked), c.base.env);
    shade_batch<F>(c.soa(given, true), mat, c.base.lights, std::span<color<F, T>>(masked_call), c.base.env);
    shade_batch<F>(c.soa(given, false), dull, c.base.lights, std::span<color<F, T>>(diffuse_only), c.base.env);
    std::size_t same = 0, highlighted = 0;
    for (std::size_t i = 0; i < count; ++i) {
        same += std::memcmp(&unmasked[i], &masked_call[i], sizeof(unmasked[i])) == 0;
        highlighted += std::memcmp(&unmasked[i], &diffuse_only[i], sizeof(unmasked[i])) != 0;
    }
    CHECK(same == count);
    return highlighted;
}

/// `lights` lights at 3 W + 5 points, every mask set and no light ambient (check_unmasked_equals_masked).
template <class T, features F> batch_case<T> all_visible_case(std::uint64_t seed, std::size_t lights)
{
    scene_gen<T> gen(seed);
    batch_case<T> c(gen, F, 3 * batch_width<T> + 5, int(lights));
    for (std::uint64_t& bits : c.masks) bits = ~std::uint64_t(0);
    for (light<T>& L : c.base.lights) L.ambient = glm::vec<3, T>(0);
    return c;
}

/// The fast mode's light loop with a power-of-two shininess n = 2^K known at compile time
/// (add_masked_lights without masks: K squarings in a row) against the same call with every light
/// mask set (each_visible_light: fast::detail::pow_integer's chain entered by a jump), for n = 1 to
/// 64 and odd n (which both calls shade alike).
template <class T, features F> void check_power_of_two_shininess(std::uint64_t seed)
{
    const batch_case<T> c = all_visible_case<T, F>(seed, 4);
    for (const T n : {T(1), T(2), T(4), T(8), T(16), T(32), T(64), T(3), T(33)}) {
        material<T> mat = c.base.mat;
        mat.shininess = n;
        CAPTURE(n);
        CHECK(check_unmasked_equals_masked<T, F>(c, mat) > 0);
    }
}

/// The light loop without masks (two lights at a time: the stable mode's float lanes, the exact and
/// fast modes' AVX-512 lanes; the second light's geometry before the first's power) against the
/// same call with every light mask set (one light at a time), for 1 to 5 lights (pairs and a last
/// odd one). A highlight somewhere among the five calls (one light may light no highlight).
template <class T, features F> void check_light_pairs(std::uint64_t seed)
{
    std::size_t highlighted = 0;
    for (std::size_t lights = 1; lights <= 5; ++lights) {
        const batch_case<T> c = all_visible_case<T, F>(seed + lights, lights);
        CAPTURE(lights);
        highlighted += check_unmasked_equals_masked<T, F>(c, c.base.mat);
    }
    CHECK(highlighted > 0);
}

/// Bad and extreme geometry through the fast mode's integer powers (n = 32: the loop with the
/// squarings known; n = 33: pow_integer's loop): a zero normal, NaN and infinite coordinates, huge
/// and tiny positions, a point at a light. Non-finite geometry gives NaN in every channel, the rest
/// finite non-negative colours, and the unmasked call the bytes of the masked one.
template <class T> void check_fast_integer_power_edges()
{
    constexpr features F = presets::with_mode(presets::glsl_ads, evaluation::fast);
    const T inf = std::numeric_limits<T>::infinity(), nan = std::numeric_limits<T>::quiet_NaN();
    const T huge = std::numeric_limits<T>::max() / 4, tiny = std::numeric_limits<T>::min();
    std::vector<light<T>> lights(2);
    lights[0].position = glm::vec<4, T>(1, 2, 3, 1);
    lights[1].position = glm::vec<4, T>(-2, 1, 1, 1);
    using v3 = glm::vec<3, T>;
    const std::vector<v3> P = {v3(0, 0, -2), v3(0, 0, -2), v3(nan, 0, -2), v3(0, inf, -2), v3(huge, huge, -huge),
                               v3(tiny, tiny, -tiny), v3(1, 2, 3),          v3(0, 0, -1e-30f), v3(1e30f, 0, -1e30f)};
    const std::vector<v3> N = {v3(0, 0, 1), v3(0, 0, 0),  v3(0, 0, 1), v3(0, 0, 1), v3(0, 0, 1),
                               v3(0, 0, 1), v3(0, 0, 1), v3(0, 1, 1),  v3(1, 0, 1)};
    const std::vector<std::uint64_t> all(P.size(), ~std::uint64_t(0));
    for (const T n : {T(32), T(33)}) {
        material<T> mat;
        mat.shininess = n;
        std::vector<v3> fixed(P.size()), chained(P.size());
        shade_batch<F>(aos_points<T>{.positions = P, .normals = N}, mat, lights, std::span<v3>(fixed));
        shade_batch<F>(aos_points<T>{.positions = P, .normals = N, .light_masks = all}, mat, lights, std::span<v3>(chained));
        for (std::size_t i = 0; i < P.size(); ++i) {
            CAPTURE(n);
            CAPTURE(i);
            CHECK(std::memcmp(&fixed[i], &chained[i], sizeof(v3)) == 0);
            const bool finite = std::isfinite(P[i].x) && std::isfinite(P[i].y) && std::isfinite(P[i].z);
            for (int c = 0; c < 3; ++c) {
                if (finite) CHECK((std::isfinite(fixed[i][c]) && fixed[i][c] >= 0));
                else CHECK(std::isnan(fixed[i][c]));
            }
        }
    }
}

// Per-point views (view_model::given) in both modes, Phong and Blinn, diffuse only, per-light
// ambient not attenuated (a masked light must not leave its ambient term), unit inputs, facing
// flags with alpha; and the other view models with masks.
constexpr features input_feature_sets[] = {
    presets::raytracer_phong,
    presets::with_mode(presets::raytracer_phong, evaluation::stable),
    features{.specular = specular_model::blinn, .view = view_model::given},
    features{.light_ambient = true, .specular = specular_model::blinn, .lights = light_kind::any,
             .attenuation = attenuation_model::polynomial, .attenuate_ambient = false, .view = view_model::given,
             .mode = evaluation::stable},
    features{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::positional, .view = view_model::given},
    features{.scene_ambient = false, .specular = specular_model::none, .view = view_model::given, .mode = evaluation::stable},
    features{.view = view_model::given, .unit_inputs = true},
    given_view_stable_blinn_all_terms,
    features{.light_ambient = true, .specular = specular_model::phong, .two_sided = facing::view, .view = view_model::given},
    presets::classic_phong,
    presets::with_mode(presets::classic_phong, evaluation::stable),
    presets::blinn_phong_per_light_ambient,
    presets::glsl_ads,
    presets::diffuse_only,
    features{.specular = specular_model::blinn, .lights = light_kind::directional, .view = view_model::fixed_direction,
             .mode = evaluation::stable},
};

template <class T, std::size_t... I> void check_all_inputs(std::index_sequence<I...>)
{
    (check_inputs<T, input_feature_sets[I]>(7000 + I), ...);
}
template <class T, std::size_t... I> void check_all_masked(std::index_sequence<I...>)
{
    (check_masked_equals_removed<T, input_feature_sets[I]>(8000 + I), ...);
}

} // namespace

TEST_CASE_TEMPLATE("shade_batch with per-point views and light masks equals shade<F> with masked(), AoS = SoA", T, float, double)
{
    check_all_inputs<T>(std::make_index_sequence<std::size(input_feature_sets)>{});
}

TEST_CASE_TEMPLATE("shade_batch: a long call equals each point shaded alone, bit for bit", T, float, double)
{
    check_long_call_equals_points_alone<T, presets::classic_phong>(9001);
    check_long_call_equals_points_alone<T, presets::blinn_phong_per_light_ambient>(9002);
    check_long_call_equals_points_alone<T, presets::with_mode(presets::classic_phong, evaluation::fast)>(9003);
    check_long_call_equals_points_alone<T, presets::with_mode(presets::classic_phong, evaluation::fast)>(9006, true);
    check_long_call_equals_points_alone<T, presets::with_mode(presets::raytracer_phong, evaluation::stable)>(9004);
    check_long_call_equals_points_alone<T, input_feature_sets[2]>(9005); // Blinn, given views
}

TEST_CASE_TEMPLATE("shade_batch fast: a power-of-two shininess without masks gives the bits of the masked call", T, float, double)
{
    check_power_of_two_shininess<T, presets::with_mode(presets::classic_phong, evaluation::fast)>(9101);
    check_power_of_two_shininess<T, presets::with_mode(presets::raytracer_phong, evaluation::fast)>(9102);
    check_power_of_two_shininess<T, presets::with_mode(presets::glsl_ads, evaluation::fast)>(9104); // the benchmark's model
    check_power_of_two_shininess<T, presets::with_mode(presets::blinn_phong_per_light_ambient, evaluation::fast)>(9103);
}

TEST_CASE_TEMPLATE("shade_batch: the light loop without masks gives the bits of the masked call", T, float, double)
{
    // Feature sets the other tests instantiate already (shade_batch's compile time).
    check_light_pairs<T, presets::glsl_ads>(9201); // the benchmark's model
    check_light_pairs<T, presets::blinn_phong_per_light_ambient>(9202);
    check_light_pairs<T, input_feature_sets[2]>(9203); // Blinn, given views
    check_light_pairs<T, presets::with_mode(presets::raytracer_phong, evaluation::stable)>(9211);
    check_light_pairs<T, presets::with_mode(presets::classic_phong, evaluation::stable)>(9212); // attenuation, any light
    check_light_pairs<T, input_feature_sets[3]>(9213); // Blinn, attenuation, light ambient not attenuated
    check_light_pairs<T, given_view_stable_blinn_all_terms>(9214); // Blinn, spot, facing flags
    check_light_pairs<T, presets::with_mode(presets::glsl_ads, evaluation::fast)>(9221);
    check_light_pairs<T, presets::with_mode(presets::blinn_phong_per_light_ambient, evaluation::fast)>(9222);
}

TEST_CASE_TEMPLATE("shade_batch fast, integer shininess: bad and extreme geometry", T, float, double)
{
    check_fast_integer_power_edges<T>();
}

TEST_CASE_TEMPLATE("shade_batch: a masked light equals a removed light, bit for bit", T, float, double)
{
    check_all_masked<T>(std::make_index_sequence<std::size(input_feature_sets)>{});
}

TEST_CASE_TEMPLATE("shade_batch: soa_points without views or masks equals the soa3 overloads bit for bit", T, float, double)
{
    constexpr features F = presets::with_mode(presets::classic_phong, evaluation::stable);
    scene_gen<T> gen(31);
    const std::size_t count = 3 * batch_width<T> + 1;
    const batch_case<T> c(gen, F, count, 3);
    std::vector<T> r(count), g(count), b(count), a(count), r2(count), g2(count), b2(count), a2(count);
    shade_batch<F>(soa3<T>{c.px, c.py, c.pz}, soa3<T>{c.nx, c.ny, c.nz}, c.base.mat, std::span<const light<T>>(c.base.lights),
                   soa_rgba<T>{r, g, b, a}, c.base.env);
    shade_batch<F>(soa_points<T>{.positions = {c.px, c.py, c.pz}, .normals = {c.nx, c.ny, c.nz}}, c.base.mat, c.base.lights,
                   soa_rgba<T>{r2, g2, b2, a2}, c.base.env);
    CHECK(r == r2);
    CHECK(g == g2);
    CHECK(b == b2);
    CHECK(a == a2);
}

TEST_CASE_TEMPLATE("shade_batch: light masks on hand-made points", T, float, double)
{
    // Two white directional lights along +z and +x, diffuse only, unit normal +z at every point:
    // light 0 gives n.l = 1, light 1 gives n.l = 0. A third light along +z with strength 0.5.
    // Expected per point: kd (1 [bit 0] + 0.5 [bit 2]); bit 1 adds 0; bits past the list nothing.
    constexpr features F{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::directional};
    std::vector<light<T>> lights(3);
    lights[0].position = {T(0), T(0), T(1), T(0)};
    lights[1].position = {T(1), T(0), T(0), T(0)};
    lights[2].position = {T(0), T(0), T(3), T(0)};
    lights[2].diffuse = glm::vec<3, T>(T(0.5));
    const std::size_t count = 2 * batch_width<T> + 1;
    std::vector<glm::vec<3, T>> p(count, glm::vec<3, T>(T(0), T(0), T(-2))), n(count, glm::vec<3, T>(T(0), T(0), T(1)));
    std::vector<std::uint64_t> masks(count);
    for (std::size_t i = 0; i < count; ++i) masks[i] = (i % 8) | (i % 3 == 0 ? std::uint64_t(1) << 40 : 0);
    const material<T> mat{.kd = glm::vec<3, T>(T(1))};
    std::vector<glm::vec<3, T>> out(count);
    shade_batch<F>(aos_points<T>{.positions = p, .normals = n, .light_masks = masks}, mat, lights, out);
    for (std::size_t i = 0; i < count; ++i) {
        const T expected = T((masks[i] & 1) ? 1 : 0) + T((masks[i] & 4) ? 0.5 : 0);
        CAPTURE(i);
        CHECK(out[i].r == doctest::Approx(double(expected)).epsilon(1e-6));
        CHECK(out[i].g == out[i].r);
    }
}
