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

/// Whether shade_batch runs F on lanes V through ext/simd/stable_lanes.hpp (float stable lanes).
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

/// Steps per call of shade_lanes: the per-call work is shared, and the core overlaps one step's
/// long chains and loads with the next step's. 128 for steps read and written in place, 8 for
/// steps through the call's blocks (docs/batch.md). The per-step arrays exist only where used.
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
/// The stable mode's steps on float lanes (ext/simd/stable_lanes.hpp; wide_lights: the lights in
/// double); arguments as shade_lanes'.
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
            each_visible_light_in_pairs<V, T>(
                sums, lights.size(), step_bits, count, [&](std::size_t j) { return stable_lanes::terms_of<G>(s, wide_lights[j]); },
                [&](Sums& step_sums, std::size_t j, const auto& t) { stable_lanes::add_terms<G>(step_sums, t, lights[j], mat.shininess); });
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

/// The lanes' colours: prepare, every (visible) light, finish, for `steps` steps from step `first`
/// of the caller's stream (passed unchanged: docs/batch.md). Not inlined, on purpose: every layout
/// calls this one compiled function, so the compiler's choices (FMA contraction) are the same and
/// the layouts agree bit for bit. Flattened, so the frame and sums stay in registers.
/// bits: W light masks per step (bits + k W; 0 past the tail), or null; count: the live lanes of
/// each step. Folded: the lights carry ka, kd, ks (one material, folded_sums); env.ambient is then
/// the colour's point-independent part (emission + ka La, + ka sum_i La_i when ambient_hoisted),
/// from which the sums start. step_materials: null (mat for every step) or, exact mode not folded,
/// each step's material lanes. table: null, or (exact, not folded, full steps) a material table
/// looked up per step (table_lanes::step). The fast and stable modes decide per call from mat: one
/// step per call with per-step materials.
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
    // Two loops, so a call without masks tests nothing per step; Flags: a loop of its own that tests
    // io's layout flags per step, so SoA steps test nothing.
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
                // Per-step materials: the shininess tested for 0 here. A table's ids are looked up
                // here, so their loads and permutes overlap the neighbouring steps' shading.
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
