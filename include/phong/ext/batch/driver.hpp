// phong: the driver of shade_batch: the call's set-up (lights, material and environment in lanes)
// and the runs of steps handed to shade_lanes (in place, or through blocks).
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
#include "../simd/math_traits.hpp"
#include "checks.hpp"
#include "folding.hpp"
#include "kernel.hpp"
#include "layout.hpp"
#include "materials.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

// g++ -O1 reports `in` below as maybe uninitialized (shade_lanes reads in[k] only for k < steps,
// all loaded first): silenced here (with xsimd, backend.hpp's region covers it already).
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
/// Material lanes kept per call of shade_lanes for steps of mixed materials (per-point materials, a
/// table's tail): a call ends at the step that would need one more.
inline constexpr std::size_t step_material_slots = 8;

/// Points io's inputs at steps i, i + W, ...: full steps of points_in_place layouts where they are
/// (stride W SoA, 3W AoS), else copies in in_block (at most B steps).
template <features F, class V, class Points, class T, glm::qualifier Q, std::size_t B, std::size_t W>
void stream_inputs(step_stream<V, T>& io, std::size_t i, std::size_t steps, std::size_t count, const Points& points,
                   T (&in_block)[B][9][W])
{
    if (points_in_place<Points, V, T, Q> && count == W) {
        if constexpr (std::is_same_v<Points, soa_points<T>>) {
            const soa3<T>* from[3] = {&points.positions, &points.normals, &points.views};
            for (int v = 0; v < (F.view == view_model::given ? 3 : 2); ++v)
                for (int c = 0; c < 3; ++c) io.in[3 * v + c] = (c == 0 ? from[v]->x : c == 1 ? from[v]->y : from[v]->z).data() + i;
            io.in_stride = W;
        } else if constexpr (points_in_place<Points, V, T, Q>) {
            io.in[0] = &points.positions[i].x;
            io.in[3] = &points.normals[i].x;
            if constexpr (F.view == view_model::given) io.in[6] = &points.views[i].x;
            io.in_stride = 3 * W;
            io.aos_in = true;
        }
        return;
    }
    for (std::size_t k = 0; k < steps && k < B; ++k) {
        step_lanes<V, Q> lanes;
        load_step<F, V, Points, T, Q>(i + k * W, count, points, lanes);
        for (glm::length_t c = 0; c < 3; ++c) {
            store(lanes.position[c], in_block[k][c]);
            store(lanes.normal[c], in_block[k][3 + c]);
            if constexpr (F.view == view_model::given) store(lanes.view[c], in_block[k][6 + c]);
        }
    }
    for (int c = 0; c < 9; ++c) io.in[c] = in_block[0][c];
    io.in_stride = 9 * W;
}

/// Points io's outputs at point i: full steps' colours where colours_in_place (SoA channels,
/// stride W; interleaved rgb, stride 3W), else out_block (store_blocks copies them out).
template <features F, class V, class T, glm::qualifier Q, class Output, std::size_t B, std::size_t W>
void stream_outputs(step_stream<V, T>& io, std::size_t i, std::size_t count, const Output& out, T (&out_block)[B][4][W])
{
    constexpr int channels = F.alpha ? 4 : 3;
    if (colours_in_place<F, Output, V, T, Q> && count == W) {
        if constexpr (std::is_same_v<Output, soa_rgba<T>>) {
            T* dst[4] = {out.r.data(), out.g.data(), out.b.data(), F.alpha ? out.a.data() : nullptr};
            for (int ch = 0; ch < channels; ++ch) io.out[ch] = dst[ch] + i;
            io.out_stride = W;
        } else if constexpr (colours_in_place<F, Output, V, T, Q>) {
            io.out[0] = &out[i].x;
            io.out_stride = 3 * W;
            io.interleaved_out = true;
        }
        return;
    }
    for (int ch = 0; ch < channels; ++ch) io.out[ch] = out_block[0][ch];
    io.out_stride = 4 * W;
}

/// The colours of steps i, i + W, ... from out_block to the output (where stream_outputs put them).
template <features F, class V, class T, glm::qualifier Q, class Output, std::size_t B, std::size_t W>
void store_blocks(const step_stream<V, T>& io, std::size_t i, std::size_t steps, std::size_t count, const Output& out,
                  const T (&out_block)[B][4][W])
{
    if (io.out[0] != out_block[0][0]) return;
    for (std::size_t k = 0; k < steps && k < B; ++k) {
        color<F, V, Q> c;
        for (glm::length_t ch = 0; ch < (F.alpha ? 4 : 3); ++ch) c[ch] = load<V>(out_block[k][ch]);
        store_step<F, V, T, Q>(c, i + k * W, count, out);
    }
}

/// The light masks of steps from point i: null without masks, in place for full steps, else a
/// tail's count masks copied to tail_bits (0 past count).
template <class Points, std::size_t W>
const std::uint64_t* step_masks(const Points& points, std::size_t i, std::size_t count, std::uint64_t (&tail_bits)[W])
{
    if (points.light_masks.empty()) return nullptr;
    if (count == W) return points.light_masks.data() + i;
    for (std::size_t k = 0; k < W; ++k) tail_bits[k] = k < count ? points.light_masks[i + k] : 0;
    return tail_bits;
}

/// The material lanes of steps i, i + W, ... (per-point materials, or a table's tail), a pointer per
/// step; returns the steps that got one (fewer than `steps` when the slots ran out).
template <class V, glm::qualifier Q, class MaterialLanes, std::size_t Slots, std::size_t MaxSteps>
std::size_t point_step_materials(const MaterialLanes& materials, std::size_t i, std::size_t steps, std::size_t count,
                                 const material<V, Q>* (&step_material)[MaxSteps], material_slot<V, Q> (&slots)[Slots])
{
    constexpr std::size_t W = sizeof(V) / sizeof(typename math_traits<V>::scalar);
    std::size_t used = 0, k = 0;
    for (; k < steps && used < Slots; ++k) {
        step_material[k] = materials.step(i + k * W, count, slots[used].lanes);
        used += step_material[k] == &slots[used].lanes;
    }
    return k < steps && used == Slots ? k : steps;
}

/// Up to call_steps steps from point i (full steps, or one tail step) through one call of
/// shade_lanes; returns the steps shaded (fewer when step_material_slots ran out). Per-step
/// materials go several steps per call in the exact mode, one step per call otherwise.
template <features F, class V, class Points, class T, glm::qualifier Q, class MaterialLanes, class Output>
std::size_t shade_points_steps(std::size_t i, std::size_t steps, std::size_t count, const Points& points,
                               const MaterialLanes& materials, std::span<const light<V, Q>> lights,
                               std::span<const light<double, Q>> wide_lights, const environment<V, Q>& env, const Output& out)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    // One material for all points: shade_points_impl folded it into the lights.
    constexpr bool folded = std::is_same_v<MaterialLanes, shared_lanes<V, Q>>;
    constexpr bool shared = folded || std::is_same_v<MaterialLanes, unfolded_shared_lanes<V, Q>>;
    constexpr std::size_t max_steps = call_steps<F, Points, Output, V, T, Q>;
    steps = std::min(steps, max_steps); // callers pass at most max_steps; said here for g++'s -Wstringop-overflow
    // Per-step materials first: they may end the call early. A table's full steps look their
    // materials up inside shade_lanes instead (docs/batch.md), where no slot can run out.
    constexpr bool materials_per_step = !shared && F.mode == evaluation::exact && !std::is_same_v<V, T>;
    constexpr bool table_in_loop = materials_per_step && std::is_same_v<MaterialLanes, table_lanes<V, T, Q>>;
    const bool look_up_in_loop = table_in_loop && count == W;
    const material<V, Q>* step_material[materials_per_step ? max_steps : 1] = {}; // zeroed: g++ -O3 cannot see that steps >= 1
    material_slot<V, Q> slots[materials_per_step ? step_material_slots : 1];
    if constexpr (materials_per_step)
        if (!look_up_in_loop) steps = point_step_materials(materials, i, steps, count, step_material, slots);
    // Full steps in place are read and written where they are; the rest goes through these blocks.
    constexpr std::size_t block_steps = in_place_steps<F, Points, Output, V, T, Q> ? 1 : block_steps_per_call;
    alignas(64) T in_block[block_steps][9][W];
    alignas(64) T out_block[block_steps][4][W];
    mask_t<V> front[F.two_sided == facing::flag ? max_steps : 1];
    step_stream<V, T> io{};
    stream_inputs<F, V, Points, T, Q>(io, i, steps, count, points, in_block);
    if constexpr (F.two_sided == facing::flag) {
        if (!points.front_facing.empty()) {
            for (std::size_t k = 0; k < steps; ++k) front[k] = front_lanes<V, T>(points.front_facing, i + k * W, count);
            io.front = front;
        }
    }
    stream_outputs<F, V, T, Q>(io, i, count, out, out_block);
    alignas(64) std::uint64_t tail_bits[W]; // a tail's masks, 0 past count (full steps read them in place)
    const std::uint64_t* bits = step_masks(points, i, count, tail_bits);
    if constexpr (shared) {
        shade_lanes<F, V, T, Q, folded>(io, 0, steps, materials.lanes, lights, wide_lights, env, bits, count, nullptr);
    } else if constexpr (materials_per_step) {
        const table_lanes<V, T, Q>* table = nullptr; // a table's full steps: looked up in shade_lanes
        if constexpr (table_in_loop) table = look_up_in_loop ? &materials : nullptr;
        shade_lanes<F, V, T, Q, folded>(io, 0, steps, table ? table->splatted[0] : *step_material[0], lights, wide_lights, env, bits,
                                        count, table ? nullptr : step_material, table, i);
    } else {
        for (std::size_t k = 0; k < steps; ++k)
            shade_lanes<F, V, T, Q, folded>(io, k, 1, *materials.step(i + k * W, count, slots[0].lanes), lights, wide_lights, env,
                                            bits ? bits + k * W : nullptr, count, nullptr);
    }
    store_blocks<F, V, T, Q>(io, i, steps, count, out, out_block);
    return steps;
}
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic pop
#endif

/// shade_batch point by point through shade<F>'s route (PHONG_LANES_WITHOUT_FMA: x86 without FMA
/// instructions), after check_batch_inputs: no check per point. A table's id past the table takes
/// the last entry, as the lanes do.
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
void shade_points_one_by_one(const Points& points, const Materials& materials, std::span<const light<T, Q>> lights,
                             const Output& out, const environment<T, Q>& env, std::size_t n)
{
    using vec3 = glm::vec<3, T, Q>;
    const auto at = [](const auto& xyz, std::size_t i) -> vec3 {
        if constexpr (requires { xyz.x; }) return vec3(xyz.x[i], xyz.y[i], xyz.z[i]);
        else return vec3(xyz[i]);
    };
    const auto material_at = [&materials](std::size_t i) -> const material<T, Q>& {
        if constexpr (std::is_same_v<Materials, material<T, Q>>) return materials;
        else if constexpr (std::is_same_v<Materials, material_table<T, Q>>)
            return materials.materials[std::min<std::size_t>(materials.ids[i], materials.materials.size() - 1)];
        else return materials[i];
    };
    const auto run = [&]<bool Masks>() { // the loop twice: a call without masks tests nothing per point
        for (std::size_t i = 0; i < n; ++i) {
            const vec3 position = at(points.positions, i), normal = at(points.normals, i);
            vec3 view(T(0));
            if constexpr (F.view == view_model::given) view = at(points.views, i);
            bool front_facing = true;
            if constexpr (F.two_sided == facing::flag) front_facing = points.front_facing.empty() || points.front_facing[i];
            const material<T, Q>& mat = material_at(i);
            color<F, T, Q> c;
            if constexpr (Masks)
                c = color<F, T, Q>(total_of<F>(shade_at<F, false>(position, normal, view, mat, masked(lights, points.light_masks[i]), env, front_facing)));
            else c = color<F, T, Q>(total_of<F>(shade_at<F, false>(position, normal, view, mat, lights, env, front_facing)));
            if constexpr (std::is_same_v<Output, soa_rgba<T>>) {
                out.r[i] = c.r;
                out.g[i] = c.g;
                out.b[i] = c.b;
                if constexpr (F.alpha) out.a[i] = c.a;
            } else {
                out[i] = c;
            }
        }
    };
    if (points.light_masks.empty()) run.template operator()<false>();
    else run.template operator()<true>();
}

/// shade_points_impl's shading on the lanes of simd_batch<T>: lights, shared material (or a
/// material table) and environment broadcast once, then shade_points_steps per call_steps W points.
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
void shade_points_lanes(const Points& points, const Materials& materials, std::span<const light<T, Q>> lights,
                        const Output& out, const environment<T, Q>& env, std::size_t n)
{
    using V = simd_batch<T>;
    constexpr std::size_t W = batch_width<T>;

    bool fold = false; // one material: folded into the lights where no product is lost
    if constexpr (std::is_same_v<Materials, material<T, Q>>) fold = foldable(materials, lights);
    const std::vector<light<V, Q>> lane_lights = lane_lights_of<V>(lights, materials, fold);
    const std::span<const light<V, Q>> lane_span(lane_lights);
    std::vector<light<double, Q>> wide_lights; // the lights in double, for stable_lanes_route
    if constexpr (stable_lanes_route<F, V>) {
        wide_lights.reserve(lights.size());
        for (const light<T, Q>& L : lights) wide_lights.push_back(splat<double>(L));
    }
    const std::span<const light<double, Q>> wide_span(wide_lights);
    const environment<V, Q> lane_env = lane_environment<F, V>(env, materials, lights, !points.light_masks.empty(), fold);
    const auto run = [&](const auto& material_lanes) {
        std::size_t i = 0;
        while (i + W <= n) {
            const std::size_t steps = std::min(call_steps<F, Points, Output, V, T, Q>, (n - i) / W);
            i += W * shade_points_steps<F, V, Points, T, Q>(i, steps, W, points, material_lanes, lane_span, wide_span, lane_env, out);
        }
        if (i < n) shade_points_steps<F, V, Points, T, Q>(i, 1, n - i, points, material_lanes, lane_span, wide_span, lane_env, out);
    };
    if constexpr (std::is_same_v<Materials, material<T, Q>>) {
        if (fold) run(shared_lanes<V, Q>{splat<V>(materials)});
        else run(unfolded_shared_lanes<V, Q>{splat<V>(materials)});
    } else if constexpr (std::is_same_v<Materials, material_table<T, Q>>) {
        table_lanes<V, T, Q> lanes{materials.materials, materials.ids, {}, {}};
        lanes.splatted.reserve(materials.materials.size());
        for (const material<T, Q>& m : materials.materials) lanes.splatted.push_back(splat<V>(m));
        lanes.make_columns();
        run(lanes);
    } else {
        run(per_point_lanes<V, T, Q>{materials});
    }
}

/// shade_batch over soa_points or aos_points: check_batch_inputs, then the lanes, or point by point
/// without fused multiply-add (PHONG_LANES_WITHOUT_FMA). Materials: material<T, Q> (one for all), a
/// span of N materials (one per point) or material_table<T, Q> (a table and N ids).
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
void shade_points_impl(const Points& points, const Materials& materials, std::span<const light<T, Q>> lights,
                       const Output& out, const environment<T, Q>& env)
{
    const std::size_t n = vec3_count(points.positions);
    if (!check_batch_inputs<F>(points, materials, lights, out, env, n)) return;
    if constexpr (PHONG_LANES_WITHOUT_FMA) shade_points_one_by_one<F>(points, materials, lights, out, env, n);
    else shade_points_lanes<F>(points, materials, lights, out, env, n);
}

/// The soa3 overloads: shade_points_impl on soa_points without views or masks.
template <features F, class T, glm::qualifier Q, class Materials, class Output>
void shade_batch_impl(const soa3<T>& positions, const soa3<T>& normals, const Materials& materials,
                      std::span<const light<T, Q>> lights, const Output& out, const environment<T, Q>& env,
                      std::span<const bool> front_facing)
{
    static_assert(F.view != view_model::given,
                  "shade_batch: view_model::given needs a view vector per point: pass soa_points/aos_points with .views");
    shade_points_impl<F>(soa_points<T>{positions, normals, {}, front_facing, {}}, materials, lights, out, env);
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
