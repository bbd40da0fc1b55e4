// phong: per-point light masks on lanes (shadow rays' results): which lanes see a light, and the
// masked light loop of one step.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
#include "../simd/math_traits.hpp"
#include "layout.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

/// sums where `lanes` is set, else `before`: the lanes that do not see a light keep exactly the
/// sums they had without it.
template <class V, glm::qualifier Q>
folded_sums<V, Q> select_sums(const mask_t<V>& lanes, const folded_sums<V, Q>& sums, const folded_sums<V, Q>& before)
{
    folded_sums<V, Q> r;
    for (glm::length_t c = 0; c < 3; ++c) r.total[c] = detail::select(lanes, sums.total[c], before.total[c]);
    return r;
}
template <class V, glm::qualifier Q>
light_sums<V, Q> select_sums(const mask_t<V>& lanes, const light_sums<V, Q>& sums, const light_sums<V, Q>& before)
{
    light_sums<V, Q> r;
    for (glm::length_t c = 0; c < 3; ++c) {
        r.ambient[c] = detail::select(lanes, sums.ambient[c], before.ambient[c]);
        r.diffuse[c] = detail::select(lanes, sums.diffuse[c], before.diffuse[c]);
        r.specular[c] = detail::select(lanes, sums.specular[c], before.specular[c]);
    }
    return r;
}

/// Which lanes see light j: bit k set when lane k's mask has bit j (lanes past count have no
/// bits). AVX-512: two (float) or one (double) 64-bit lane tests of the W masks, as a k-mask.
template <class V, class T> struct lane_visibility {
    static constexpr std::size_t W = sizeof(V) / sizeof(T);
    const std::uint64_t* bits;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    __m512i low{}, high{}; // the masks of lanes 0..7 and 8..15 (float)
    explicit lane_visibility(const std::uint64_t* b) : bits(b)
    {
        if (!b) return;
        if constexpr (avx512_lanes<V, T>) {
            low = _mm512_loadu_si512(b);
            if constexpr (W == 16) high = _mm512_loadu_si512(b + 8);
        }
    }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
    __m256i low{}, high{}; // the masks of lanes 0..3 and 4..7 (float)
    explicit lane_visibility(const std::uint64_t* b) : bits(b)
    {
        if (!b) return;
        if constexpr (avx2_float_lanes<V, T>) {
            low = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b));
            high = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + 4));
        }
    }
#else
    explicit lane_visibility(const std::uint64_t* b) : bits(b) {}
#endif
    std::uint32_t lanes_seeing(std::size_t j) const
    {
        const std::uint64_t bit = std::uint64_t(1) << j;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T>) {
            const __m512i b = _mm512_set1_epi64(std::int64_t(bit));
            std::uint32_t m = _mm512_test_epi64_mask(low, b);
            if constexpr (W == 16) m |= std::uint32_t(_mm512_test_epi64_mask(high, b)) << 8;
            return m;
        }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) { // bit j of each 64-bit mask to its sign bit, then movemask
            const __m256i up = _mm256_set1_epi64x(std::int64_t(63 - j));
            const int m_low = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_sllv_epi64(low, up)));
            const int m_high = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_sllv_epi64(high, up)));
            return std::uint32_t(m_low) | std::uint32_t(m_high) << 4;
        }
#endif
        std::uint32_t m = 0;
        for (std::size_t k = 0; k < W; ++k) m |= std::uint32_t((bits[k] & bit) != 0) << k;
        return m;
    }
    /// The lane mask of bit set k <=> lane k (partial visibility: a select).
    static mask_t<V> mask(std::uint32_t lanes)
    {
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T>) {
            if constexpr (W == 16) return mask_t<V>(typename mask_t<V>::register_type(__mmask16(lanes)));
            else return mask_t<V>(typename mask_t<V>::register_type(__mmask8(lanes)));
        }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) { // lane k: all ones where bit k of lanes is set
            const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
            const __m256i set = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), lane_bit), lane_bit);
            return mask_t<V>(_mm256_castsi256_ps(set));
        }
#endif
        alignas(64) T seen[W];
        for (std::size_t k = 0; k < W; ++k) seen[k] = (lanes >> k & 1u) ? T(1) : T(0);
        return load<V>(seen) > V(T(0));
    }
};

/// The qualifier of a sums type (light_sums<V, Q> or folded_sums<V, Q>).
template <class Sums> struct sums_qualifier;
template <template <class, glm::qualifier> class S, class V, glm::qualifier Q> struct sums_qualifier<S<V, Q>> {
    static constexpr glm::qualifier value = Q;
};
template <class Sums> inline constexpr glm::qualifier Q_of = sums_qualifier<Sums>::value;

/// Every light's terms added to the sums of one step, light j only in the lanes whose mask has bit j
/// (bits: one mask per lane, 0 past the tail; null: every light everywhere; lights past the 64th
/// are seen by no point). A light no lane sees is skipped; else the lanes that do not see it get
/// their sums back (exactly nothing from it). One call site of add_light for every case, so masked,
/// removed and unmasked lights run the same compiled code (the same bits).
template <class V, class T, class Sums, class AddLight>
PHONG_LANES_INLINE void each_visible_light(Sums& sums, std::size_t light_count, const std::uint64_t* bits, std::size_t count,
                                                  AddLight&& add_light)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    // Without masks every lane sees every light: the same loop, so add_light has one call site and
    // is inlined (g++ 12 kept it out of line with a second loop).
    const std::uint32_t live = count >= W ? std::uint32_t((std::uint64_t(1) << W) - 1) : std::uint32_t((1u << count) - 1);
    const lane_visibility<V, T> visibility(bits);
    const std::size_t n = bits ? std::min<std::size_t>(light_count, 64) : light_count;
    for (std::size_t j = 0; j < n; ++j) {
        const std::uint32_t seeing = bits ? visibility.lanes_seeing(j) : live;
        if (bits && !seeing) continue; // live != 0: a step has at least one point
        const bool partial = seeing != live;
        const Sums before = sums;
        add_light(sums, j);
        if (partial) sums = select_sums<V, Q_of<Sums>>(lane_visibility<V, T>::mask(seeing), sums, before);
    }
}

/// each_visible_light for a light step in two halves: terms_of(j), light j's geometry, and
/// add_terms(sums, j, terms), its terms added to the sums. A step that sees every light takes them
/// two at a time, the second light's geometry before the first's sums, so that the core overlaps
/// the two lights' dependent chains; the same terms are added in the same order.
template <class V, class T, class Sums, class TermsOf, class AddTerms>
PHONG_LANES_INLINE void each_visible_light_in_pairs(Sums& sums, std::size_t light_count, const std::uint64_t* bits, std::size_t count,
                                                    TermsOf&& terms_of, AddTerms&& add_terms)
{
    if (bits) {
        each_visible_light<V, T>(sums, light_count, bits, count,
                                 [&](Sums& step_sums, std::size_t j) { add_terms(step_sums, j, terms_of(j)); });
        return;
    }
    std::size_t j = 0;
    for (; j + 1 < light_count; j += 2) {
        const auto first = terms_of(j);
        const auto second = terms_of(j + 1);
        add_terms(sums, j, first);
        add_terms(sums, j + 1, second);
    }
    if (j < light_count) add_terms(sums, j, terms_of(j));
}

template <features F, class V, class T, glm::qualifier Q, class Sums, class Exponent>
PHONG_LANES_INLINE void add_masked_lights(Sums& sums, const frame_t<F, V, Q>& s, std::span<const light<V, Q>> lights,
                       const Exponent& m, const std::uint64_t* bits, std::size_t count)
{
    if constexpr (std::is_same_v<V, T>) { // scalar lanes (no xsimd): shade<F>'s own light loop
        if (!bits) add_lights<F>(sums, s, lights, m);
        else add_lights<F>(sums, s, masked(lights, bits[0]), m);
        return;
    } else {
        // Float lanes: the step's specular constants, made once per step (one compare per pair).
        const auto step_m = [&] {
            if constexpr (std::is_same_v<Exponent, exact::lane_shininess<V>> && std::is_same_v<T, float> && exact::step_specular_route<F>)
                return exact::step_specular_of(m, s.sees_viewer);
            else return m;
        }();
        if constexpr (std::is_same_v<Exponent, exact::integer_exponent<V>> && F.specular == specular_model::phong) {
            // The fast mode's integer shininess n = 2^K (K <= 6), no masks: the light loop with K
            // known, K squarings with no jump per pair; the same bits. Phong only (docs/batch.md).
            if (!bits) {
                const auto each_light = [&](const auto& fixed) {
                    for (std::size_t j = 0; j < lights.size(); ++j) detail::add_light<F>(sums, s, lights[j], fixed);
                };
                switch (m.plan.chain) {
                case 1: return each_light(m.template with_squarings<0>());
                case 2: return each_light(m.template with_squarings<1>());
                case 3: return each_light(m.template with_squarings<2>());
                case 4: return each_light(m.template with_squarings<3>());
                case 5: return each_light(m.template with_squarings<4>());
                case 6: return each_light(m.template with_squarings<5>());
                case 7: return each_light(m.template with_squarings<6>());
                default: break;
                }
            }
        }
        if constexpr (F.mode != evaluation::stable && avx512_lanes<V, T>) {
            // In pairs on AVX-512 only: two lights' values need its 32 vector registers (docs/batch.md).
            each_visible_light_in_pairs<V, T>(
                sums, lights.size(), bits, count, [&](std::size_t j) { return exact::light_terms_of<F>(s, lights[j], unweighted{}); },
                [&](Sums& step_sums, std::size_t j, const auto& t) { exact::add_light_terms<F>(step_sums, s, lights[j], step_m, t); });
            return;
        }
        each_visible_light<V, T>(sums, lights.size(), bits, count,
                                 [&](Sums& step_sums, std::size_t j) { detail::add_light<F>(step_sums, s, lights[j], step_m); });
    }
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
