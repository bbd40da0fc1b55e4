// shade_batch with a material_table (issue 13, item 4: a renderer's materials and each hit's id)
// equals the per-point-materials overload bit for bit, in every layout, with light masks and
// per-point views; split from tests/batch_inputs.test.cpp (which checks that overload against
// shade<F>) so that the two compile in parallel.
#include "support/batch_case.hpp"
#include "support/generators.hpp"

#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

using namespace phong;
using namespace phong_test;

namespace {

/// Material ids for `count` points, step by step (W points a step) in the patterns a renderer
/// produces: one id for the whole step (coherent primary hits), one id but a single other lane
/// (an object's edge), and random ids (mixed); the tail gets one of them too.
std::vector<std::uint32_t> step_patterned_ids(scene_gen<float>& gen, std::size_t count, std::size_t W, int table_size)
{
    std::vector<std::uint32_t> ids(count);
    for (std::size_t step = 0; step < count; step += W) {
        const int pattern = gen.integer(0, 2);
        const auto id = std::uint32_t(gen.integer(0, table_size - 1));
        const std::size_t odd_lane = std::size_t(gen.integer(0, int(W) - 1));
        for (std::size_t k = step; k < std::min(count, step + W); ++k) {
            if (pattern == 0) ids[k] = id;
            else if (pattern == 1) ids[k] = k - step == odd_lane ? std::uint32_t(table_size - 1) - id : id;
            else ids[k] = std::uint32_t(gen.integer(0, table_size - 1));
        }
    }
    return ids;
}

/// shade_batch with a material_table equals the per-point overload given materials[ids[i]],
/// bit for bit (the same lane values, so the same compiled kernel gives the same bits): every
/// layout pair, light masks on, every tail length, ids in uniform, nearly uniform and mixed
/// steps. The per-point overload is itself checked against shade<F> above. table_size: 5 (a table
/// of at most batch_width entries: float lanes take mixed steps by in-register permutes) or more
/// than batch_width (gathers).
template <class T, features F> void check_material_table(std::uint64_t seed, int table_size = 5)
{
    constexpr bool given = F.view == view_model::given;
    constexpr std::size_t W = batch_width<T>;
    constexpr int channels = F.alpha ? 4 : 3;
    scene_gen<T> gen(seed);
    scene_gen<float> id_gen(seed + 1);
    std::size_t uniform_steps = 0, mixed_steps = 0;
    for (std::size_t count : {std::size_t(0), std::size_t(1), W - 1, W, W + 1, 3 * W + 5, std::size_t(61), 9 * W + 2}) {
        const batch_case<T> c(gen, F, count, 1 + gen.integer(0, 4));
        std::vector<material<T>> table;
        for (int j = 0; j < table_size; ++j) {
            material<T> m = gen.material(1, 100);
            m.emission = glm::vec<3, T>(T(0.01) * T(j), T(0.02) * T(j), T(0.03)); // every field differs between entries
            m.alpha = T(0.5) + T(0.5) * T(j) / T(table_size); // in [0.5, 1)
            table.push_back(m);
        }
        const std::vector<std::uint32_t> ids = step_patterned_ids(id_gen, count, W, int(table.size()));
        std::vector<material<T>> per_point;
        for (std::uint32_t id : ids) per_point.push_back(table[id]);
        for (std::size_t step = 0; step + W <= count; step += W)
            ++(std::all_of(ids.begin() + std::ptrdiff_t(step), ids.begin() + std::ptrdiff_t(step + W), [&](std::uint32_t id) { return id == ids[step]; })
                   ? uniform_steps
                   : mixed_steps);
        CAPTURE(count);
        const std::span<const light<T>> lights(c.base.lights);
        const material_table<T> by_id{.materials = table, .ids = ids};
        std::vector<color<F, T>> want(count, color<F, T>(T(-1))), aos_out(count, color<F, T>(T(-2))), soa_out(count, color<F, T>(T(-3)));
        shade_batch<F>(c.aos(given, true), std::span<const material<T>>(per_point), lights, std::span<color<F, T>>(want), c.base.env);
        shade_batch<F>(c.aos(given, true), by_id, lights, std::span<color<F, T>>(aos_out), c.base.env);
        shade_batch<F>(c.soa(given, true), by_id, lights, std::span<color<F, T>>(soa_out), c.base.env);
        std::vector<T> r(count), g(count), b(count), a(count);
        shade_batch<F>(c.aos(given, true), by_id, lights, soa_rgba<T>{r, g, b, a}, c.base.env);
        for (std::size_t i = 0; i < count; ++i) {
            CAPTURE(i);
            CAPTURE(ids[i]);
            CHECK(aos_out[i] == want[i]);
            CHECK(soa_out[i] == want[i]);
            const glm::vec<4, T> channel(r[i], g[i], b[i], a[i]);
            for (int k = 0; k < channels; ++k) CHECK(channel[k] == want[i][k]);
        }
    }
    CHECK(uniform_steps > 3); // both kinds of full step did occur
    CHECK(mixed_steps > 3);
}

/// A long call with a material table (several calls of several steps each in the exact mode,
/// more steps of mixed ids than a call keeps material lanes for: detail::step_material_slots)
/// gives each point the bits it gets shaded alone (a tail of one point: one step, one call).
/// Lanes are independent and a step's material is its own, so neither the position of a step in
/// its call nor its neighbours' materials may matter; AoS and SoA points, interleaved and SoA
/// colours, masks on and off.
template <class T, features F> void check_long_table_call_equals_points_alone(std::uint64_t seed)
{
    constexpr bool given = F.view == view_model::given;
    constexpr std::size_t W = batch_width<T>;
    constexpr int channels = F.alpha ? 4 : 3;
    scene_gen<T> gen(seed);
    scene_gen<float> id_gen(seed + 1);
    const std::size_t count = (2 * detail::steps_per_call + 3) * W + 5; // three calls or more, and a tail
    const batch_case<T> c(gen, F, count, 3);
    std::vector<material<T>> table;
    for (int j = 0; j < 5; ++j) table.push_back(gen.material(1, 100));
    table[1].shininess = T(0); // a step of shininess 0 (pow(0, 0) = 1) beside steps without
    const std::vector<std::uint32_t> ids = step_patterned_ids(id_gen, count, W, int(table.size()));
    std::size_t mixed_steps = 0;
    for (std::size_t step = 0; step + W <= count; step += W)
        mixed_steps += !std::all_of(ids.begin() + std::ptrdiff_t(step), ids.begin() + std::ptrdiff_t(step + W),
                                    [&](std::uint32_t id) { return id == ids[step]; });
    CHECK(mixed_steps > 2 * detail::step_material_slots); // calls do run out of material lanes
    const material_table<T> by_id{.materials = table, .ids = ids};
    for (bool masked : {false, true}) {
        std::vector<color<F, T>> aos_out(count), soa_out(count);
        shade_batch<F>(c.aos(given, masked), by_id, c.base.lights, std::span<color<F, T>>(aos_out), c.base.env);
        std::vector<T> channel[4];
        for (std::vector<T>& ch : channel) ch.assign(count, T(-1));
        shade_batch<F>(c.soa(given, masked), by_id, c.base.lights, soa_rgba<T>{channel[0], channel[1], channel[2], channel[3]}, c.base.env);
        std::size_t same = 0;
        for (std::size_t i = 0; i < count; ++i) {
            std::vector<color<F, T>> alone(1);
            shade_batch<F>(c.point_alone(i, given, masked), material_table<T>{.materials = table, .ids = std::span(&ids[i], 1)}, c.base.lights,
                           std::span<color<F, T>>(alone), c.base.env);
            color<F, T> soa_i;
            for (int k = 0; k < channels; ++k) soa_i[k] = channel[k][i];
            same += aos_out[i] == alone[0] && soa_i == alone[0];
        }
        CAPTURE(masked);
        CHECK(same == count);
    }
}

} // namespace

TEST_CASE_TEMPLATE("shade_batch: a material table with per-point ids equals per-point materials bit for bit", T, float, double)
{
    check_material_table<T, presets::raytracer_phong>(9001);
    check_material_table<T, given_view_stable_blinn_all_terms>(9002);
    check_material_table<T, presets::classic_phong>(9003);
    check_material_table<T, presets::glsl_ads>(9004);
    check_material_table<T, presets::raytracer_phong>(9005, int(batch_width<T>) + 3); // past the permutable size: gathers
}

TEST_CASE_TEMPLATE("shade_batch: material_table on hand-made points", T, float, double)
{
    // Diffuse only, one white directional light along the unit normal +z: the colour is kd of the
    // point's material (n.l = 1), so each point shows which entry it was given.
    constexpr features F{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::directional};
    const std::vector<light<T>> lights{light<T>::with_strength({T(0), T(0), T(1), T(0)}, glm::vec<3, T>(T(1)))};
    std::vector<material<T>> table(3);
    for (std::size_t j = 0; j < table.size(); ++j) table[j].kd = glm::vec<3, T>(T(j + 1) / T(4), T(0.5), T(j) / T(8));
    const std::size_t count = 2 * batch_width<T> + 3;
    std::vector<glm::vec<3, T>> p(count, glm::vec<3, T>(T(0), T(0), T(-2))), n(count, glm::vec<3, T>(T(0), T(0), T(1)));
    std::vector<std::uint32_t> ids(count, 1); // step 0: all id 1 (uniform)
    for (std::size_t i = batch_width<T>; i < count; ++i) ids[i] = std::uint32_t(i % 3); // then mixed, and the tail
    std::vector<glm::vec<3, T>> out(count);
    shade_batch<F>(aos_points<T>{.positions = p, .normals = n}, material_table<T>{.materials = table, .ids = ids}, lights, out);
    for (std::size_t i = 0; i < count; ++i) {
        CAPTURE(i);
        CHECK(out[i] == table[ids[i]].kd); // kd * 1 * 1: exact
    }
}

TEST_CASE_TEMPLATE("shade_batch: a long call with a material table equals each point shaded alone, bit for bit", T, float, double)
{
    check_long_table_call_equals_points_alone<T, presets::raytracer_phong>(9101);
    check_long_table_call_equals_points_alone<T, presets::classic_phong>(9102);
    check_long_table_call_equals_points_alone<T, presets::glsl_ads>(9103);
    check_long_table_call_equals_points_alone<T, presets::with_mode(presets::raytracer_phong, evaluation::fast)>(9104);
    check_long_table_call_equals_points_alone<T, presets::with_mode(presets::raytracer_phong, evaluation::stable)>(9105);
}
