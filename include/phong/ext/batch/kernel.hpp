// phong: shade_lanes, the one compiled kernel of shade_batch: prepare, every (visible) light,
// finish, for a run of steps of one call.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
#include "../simd/math_traits.hpp"
#include "../simd/fast_lanes.hpp"
#include "../simd/stable_lanes.hpp"
#include "folding.hpp"
#include "layout.hpp"
#include "materials.hpp"
#include "visibility.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

/// Whether shade_batch runs F on lanes V through detail/simd/stable_lanes.hpp (the stable mode on
/// float lanes of x86 and aarch64).
template <features F, class V> inline constexpr bool stable_lanes_route =
#if PHONG_STABLE_LANES
    F.mode == evaluation::stable && stable_lanes::applies<V>;
#else
    false;
#endif

#if defined(__GNUC__) || defined(__clang__)
#  define PHONG_BATCH_NOINLINE __attribute__((noinline, flatten))
#else
#  define PHONG_BATCH_NOINLINE
#endif

/// Steps per call of shade_lanes: the per-call work (entry, the hoisted constants, the return) is
/// shared by that many steps, and the out-of-order core overlaps one step's long dependent chain
/// (normalizations, the power's polynomial) and its loads from memory with the next step's, which
/// a call per step kept apart. Steps read and written in place (SoA points or AoS points with
/// the transposes in registers; SoA colours or interleaved rgb likewise) take 128 per call, steps
/// through the call's blocks 8 (a block of 32 steps would be 26 KiB); the choice of those numbers
/// is measured in docs/batch.md. The arrays per step of a call (per-step material pointers,
/// facing masks) exist only where they are used.
inline constexpr std::size_t steps_per_call = 128;
inline constexpr std::size_t block_steps_per_call = 8;
/// Whether full steps of these points are read in place, and full steps' colours written in place.
template <class Points, class V, class T, glm::qualifier Q>
inline constexpr bool points_in_place =
    std::is_same_v<Points, soa_points<T>> || (std::is_same_v<Points, aos_points<T, Q>> && aos_in_registers<V, T, Q>);
template <features F, class Output, class V, class T, glm::qualifier Q>
inline constexpr bool colours_in_place = std::is_same_v<Output, soa_rgba<T>> || (!F.alpha && aos_in_registers<V, T, Q>);
template <features F, class Points, class Output, class V, class T, glm::qualifier Q>
inline constexpr bool in_place_steps = points_in_place<Points, V, T, Q> && colours_in_place<F, Output, V, T, Q>;
/// The most steps of one call for these points and this output.
template <features F, class Points, class Output, class V, class T, glm::qualifier Q>
inline constexpr std::size_t call_steps = in_place_steps<F, Points, Output, V, T, Q> ? steps_per_call : block_steps_per_call;

#if PHONG_STABLE_LANES
/// The stable mode's steps on float lanes (detail/simd/stable_lanes.hpp): the geometry of every
/// pair in double lanes (wide_lights: the lights in double), the power and the sums in float;
/// arguments as shade_lanes'.
template <features F, class V, class T, glm::qualifier Q, bool Folded>
PHONG_LANES_INLINE void shade_stable_steps(const step_stream<V, T>& io, std::size_t first, std::size_t steps, const material<V, Q>& mat,
                                           std::span<const light<V, Q>> lights, std::span<const light<double, Q>> wide_lights,
                                           const environment<V, Q>& env, const std::uint64_t* bits, std::size_t count)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    using Sums = std::conditional_t<Folded, folded_sums<V, Q>, light_sums<V, Q>>;
    for (std::size_t k = 0; k < steps; ++k) {
        const std::uint64_t* step_bits = bits ? bits + k * W : nullptr;
        const step_lanes<V, Q> in = io.template lanes<F, Q>(first + k);
        const stable_lanes::surface_frame<V, Q> s = stable_lanes::prepare<F>(in.position, in.normal, in.view, env, in.front);
        Sums sums{};
        if constexpr (Folded) sums.total = env.ambient + s.poison; // finish(folded_sums): the poison is in the start
        const auto shade_step = [&]<features G>() {
            each_visible_light<V, T>(sums, lights.size(), step_bits, count, [&](Sums& step_sums, std::size_t j) {
                stable_lanes::add_light<G>(step_sums, s, lights[j], wide_lights[j], mat.shininess);
            });
            io.template put<G, Q>(first + k, finish<G>(sums, s, mat, env));
        };
        if constexpr (Folded && ambient_hoistable<F>) {
            if (!step_bits) {
                shade_step.template operator()<ambient_hoisted<F>>();
                continue;
            }
        }
        shade_step.template operator()<F>();
    }
}
#endif

/// The lanes' colours, step by step: prepare, every (visible) light, finish, for each of `steps`
/// steps from step `first` of the stream (its step first + k in, its colour first + k out). The
/// caller passes the stream it built, unchanged (a copy per call, offset to the step, costs time:
/// docs/batch.md). Not inlined, on purpose: every layout (soa3, soa_points, aos_points; either
/// output) calls this one compiled function, so the compiler's choices (FMA contraction above
/// all) are the same for all of them and the layouts agree bit for bit (inlined, AoS and SoA
/// differed by an ulp at -march=native). Flattened: every call inside (the light loop's
/// add_light, the power, xsimd's kernels) is inlined into it, so the point's frame and sums stay
/// in registers across the light loop.
/// bits: W light masks per step (the k-th step from `first`: bits + k W; 0 past the tail), or
/// null; count: the live lanes of each step (W, or a tail's count with steps = 1). Folded: the
/// lights carry the material's ka, kd and ks (one material for all points, shade_points_impl):
/// folded_sums, else light_sums. Folded, env.ambient is not the scene's ambient but the colour's
/// point-independent part, emission + ka La, + ka sum_i La_i when hoisted (ambient_hoisted:
/// without masks, the loop runs without the lights' ambient terms); the sums start from it.
/// step_materials: null (mat for every step), or, not folded and in the exact mode only, the
/// material lanes of each step (step k: *step_materials[k]; per-point materials or a table's
/// tail). table: null, or (exact mode, not folded, full steps) a material table whose step k
/// takes the ids of points table_first + k W .. + W - 1, looked up in the step loop
/// (table_lanes::step; step_materials null). The fast mode's integer exponent and the stable
/// mode's route are decided per call from mat: those modes take one step per call with
/// per-step materials.
template <features F, class V, class T, glm::qualifier Q, bool Folded>
PHONG_BATCH_NOINLINE void shade_lanes(const step_stream<V, T>& stream, std::size_t first, std::size_t steps, const material<V, Q>& mat,
                                      std::span<const light<V, Q>> lights, std::span<const light<double, Q>> wide_lights,
                                      const environment<V, Q>& env, const std::uint64_t* bits, std::size_t count,
                                      const material<V, Q>* const* step_materials, const table_lanes<V, T, Q>* table = nullptr,
                                      std::size_t table_first = 0)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    const step_stream<V, T> io = stream; // a copy the colour stores cannot alias: its pointers stay in registers
    using Sums = std::conditional_t<Folded, folded_sums<V, Q>, light_sums<V, Q>>;
#if PHONG_STABLE_LANES
    if constexpr (stable_lanes_route<F, V>) {
        // The stable mode's geometry in double lanes, unless a lane's shininess is above that
        // route's limit: then the twofold route below.
        if (!xsimd::any(mat.shininess > V(stable_lanes::max_shininess)))
            return shade_stable_steps<F, V, T, Q, Folded>(io, first, steps, mat, lights, wide_lights, env, bits, count);
    }
#else
    (void)wide_lights;
#endif
    // The steps with masks or without: two loops, so that a call without masks tests nothing per step.
    // Flags: the loop that tests io's layout flags per step (a loop of its own, so that SoA steps
    // test nothing).
    const auto run_steps = [&]<bool Masks, bool Flags>(const auto& call_m) {
        // Step k's colour is stored after step k + 1's lanes are loaded: stored before, it held up
        // those loads where the spans share their offset in a page (docs/batch.md).
        color<F, V, Q> pending;
        for (std::size_t k = 0; k < steps; ++k) {
            const std::uint64_t* step_bits = Masks ? bits + k * W : nullptr;
            const step_lanes<V, Q> in = io.template lanes<F, Q, Flags>(first + k);
            if (k > 0) io.template put<F, Q, Flags>(first + k - 1, pending);
            const frame_t<F, V, Q> s = prepare<F>(in.position, in.normal, in.view, env, in.front);
            Sums sums{};
            if constexpr (Folded) sums.total = env.ambient + s.poison; // finish(folded_sums): the poison is in the start
            if constexpr (Folded && ambient_hoistable<F> && !Masks) {
                constexpr features G = ambient_hoisted<F>;
                add_masked_lights<G, V, T, Q>(sums, s, lights, call_m, step_bits, count);
                pending = finish<G>(sums, s, mat, env);
            } else if constexpr (!Folded && std::is_same_v<std::decay_t<decltype(call_m)>, exact::lane_shininess<V>>) {
                // Per-step materials: the step's shininess tested for 0 here, as once per call otherwise.
                // A table's step looks its ids up here, in the loop: their loads and, for mixed
                // ids, the lanes' permutes overlap the shading of the steps around them.
                material_slot<V, Q> looked_up;
                const material<V, Q>& step_mat = table            ? *table->step(table_first + k * W, W, looked_up.lanes)
                                                 : step_materials ? *step_materials[k]
                                                                  : mat;
                exact::lane_shininess<V> m = call_m;
                if (table || step_materials) m = shininess_lanes(step_mat.shininess);
                add_masked_lights<F, V, T, Q>(sums, s, lights, m, step_bits, count);
                pending = finish<F>(sums, s, step_mat, env);
            } else {
                add_masked_lights<F, V, T, Q>(sums, s, lights, call_m, step_bits, count);
                pending = finish<F>(sums, s, mat, env);
            }
        }
        if (steps > 0) io.template put<F, Q, Flags>(first + steps - 1, pending);
    };
    const auto run = [&](const auto& m) { // m: the shininess (V, exact::lane_shininess<V> or exact::integer_exponent<V>)
        if constexpr (aos_in_registers<V, T, Q>) {
            if (io.aos_in || io.interleaved_out) {
                if (bits) run_steps.template operator()<true, true>(m);
                else run_steps.template operator()<false, true>(m);
                return;
            }
        }
        if (bits) run_steps.template operator()<true, false>(m);
        else run_steps.template operator()<false, false>(m);
    };
    if constexpr (F.mode == evaluation::fast && !std::is_same_v<V, T>) {
        if (const unsigned n = shared_integer_exponent<V, T>(mat)) return run(exact::integer_exponent<V>::of(n));
    }
    if constexpr (F.mode != evaluation::stable && !std::is_same_v<V, T>) {
        run(shininess_lanes(mat.shininess)); // m == 0 tested once
    } else {
        run(mat.shininess);
    }
}

#undef PHONG_BATCH_NOINLINE

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
