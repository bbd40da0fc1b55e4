// phong: the material lanes of shade_batch: one material for all points, one per point, or a
// material table looked up per step (gathers, in-register permutes).
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

/// A material is 14 scalars in a row (ka, kd, ks, emission, shininess, alpha) when glm's vec3 is
/// unpadded (every qualifier but the aligned ones): then its fields can be gathered by offset.
template <class T, glm::qualifier Q> inline constexpr bool material_is_14_scalars =
    sizeof(glm::vec<3, T, Q>) == 3 * sizeof(T) && sizeof(material<T, Q>) == 14 * sizeof(T) && std::is_standard_layout_v<material<T, Q>>;

/// The material whose 14 fields, in material's order, are field[0..13].
template <class V, glm::qualifier Q> material<V, Q> material_of_fields(const V (&field)[14])
{
    return {{field[0], field[1], field[2]}, {field[3], field[4], field[5]}, {field[6], field[7], field[8]},
            {field[9], field[10], field[11]}, field[12], field[13]};
}

/// Material m's 14 fields into column k of the field lanes (lane[f][k]): a scalar transpose.
template <class T, glm::qualifier Q, std::size_t W> void put_fields(T (&lane)[14][W], std::size_t k, const material<T, Q>& m)
{
    for (glm::length_t c = 0; c < 3; ++c) {
        lane[c][k] = m.ka[c];
        lane[3 + c][k] = m.kd[c];
        lane[6 + c][k] = m.ks[c];
        lane[9 + c][k] = m.emission[c];
    }
    lane[12][k] = m.shininess;
    lane[13][k] = m.alpha;
}

/// One material of lanes: lane k takes base[element[k]] (the same values as splatting each
/// material). With gather_instructions (a small table, in cache) and AVX-512 or AVX2: one gather
/// per field; otherwise a scalar transpose through a small buffer (per-point materials stream from
/// memory, where sequential reads beat the gathers: docs/batch.md).
template <class V, bool gather_instructions, class T, glm::qualifier Q>
material<V, Q> gather(const material<T, Q>* base, const std::uint32_t* element)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (gather_instructions && avx512_lanes<V, T> && material_is_14_scalars<T, Q>) {
        const T* scalars = &base->ka.x; // the 14 fields of base[e] are scalars[14 e + f]
        V field[14];
        if constexpr (std::is_same_v<T, float>) {
            const __m512i index = _mm512_mullo_epi32(_mm512_loadu_si512(element), _mm512_set1_epi32(14));
            for (int f = 0; f < 14; ++f) field[f] = V(_mm512_i32gather_ps(index, scalars + f, sizeof(T)));
        } else {
            const __m256i index = _mm256_mullo_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(element)), _mm256_set1_epi32(14));
            for (int f = 0; f < 14; ++f) field[f] = V(_mm512_i32gather_pd(index, scalars + f, sizeof(T)));
        }
        return material_of_fields<V, Q>(field);
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (gather_instructions && avx2_float_lanes<V, T> && material_is_14_scalars<T, Q>) {
        const T* scalars = &base->ka.x;
        const __m256i index = _mm256_mullo_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(element)), _mm256_set1_epi32(14));
        V field[14];
        for (int f = 0; f < 14; ++f) field[f] = V(_mm256_i32gather_ps(scalars + f, index, sizeof(T)));
        return material_of_fields<V, Q>(field);
    }
#endif
    alignas(64) T lane[14][W];
    for (std::size_t k = 0; k < W; ++k) put_fields(lane, k, base[element[k]]);
    V field[14];
    for (int f = 0; f < 14; ++f) field[f] = load<V>(lane[f]);
    return material_of_fields<V, Q>(field);
}

/// The element indices 0 .. count - 1, then count - 1 repeated (pad lanes: the last point's material).
template <std::size_t W> struct consecutive_elements {
    alignas(64) std::uint32_t index[W]{};
    constexpr explicit consecutive_elements(std::size_t count)
    {
        for (std::size_t k = 0; k < W; ++k) index[k] = std::uint32_t(k < count ? k : count - 1);
    }
};
template <std::size_t W> inline constexpr consecutive_elements<W> full_step_elements{W};

/// Storage for one step's material lanes, left uninitialized (default initializers would cost
/// 8 KiB of stores per call); the step functions construct the lanes (std::construct_at) before any read.
template <class V, glm::qualifier Q> union material_slot {
    material<V, Q> lanes;
    material_slot() {}
};

/// The lane material of one step from a material table: the table's lanes (splatted once per call)
/// when the step's points share one id, else a gather. An id past the table takes its last entry
/// (debug builds report it first); pad lanes of a tail take the last point's id.
template <class V, class T, glm::qualifier Q> struct table_lanes {
    std::span<const material<T, Q>> table;
    std::span<const std::uint32_t> ids;
    std::vector<material<V, Q>> splatted; ///< table[j] in every lane
    /// A table of at most W entries (float lanes, AVX-512 or AVX2; empty otherwise): field f of entry
    /// j in lane j (the last entry repeated). A step of mixed ids then takes each field by one
    /// in-register permute instead of a gather (the same values).
    std::vector<V> columns;

    /// The lanes of field f of table[id[k]] in lane k, from columns (ids: W clamped ids in a register).
    template <class Ids> material<V, Q> permuted([[maybe_unused]] const Ids& id) const
    {
        V field[14];
        for (int f = 0; f < 14; ++f) {
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
            if constexpr (avx512_lanes<V, T> && std::is_same_v<T, float>) field[f] = V(_mm512_permutexvar_ps(id, columns[std::size_t(f)]));
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__) && !defined(__AVX512F__)
            if constexpr (avx2_float_lanes<V, T>) field[f] = V(_mm256_permutevar8x32_ps(columns[std::size_t(f)], id));
#endif
        }
        return material_of_fields<V, Q>(field);
    }
    /// Fills columns when the table is small enough and the lanes have the permute (see columns).
    void make_columns()
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        constexpr bool permutable =
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
            avx512_lanes<V, T> && std::is_same_v<T, float>;
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
            avx2_float_lanes<V, T>;
#else
            false;
#endif
        if constexpr (permutable) {
            if (table.empty() || table.size() > W) return;
            alignas(64) T lane[14][W];
            for (std::size_t k = 0; k < W; ++k) put_fields(lane, k, table[std::min(k, table.size() - 1)]);
            for (int f = 0; f < 14; ++f) columns.push_back(load<V>(lane[f]));
        }
    }

    /// The lanes of points i .. i + count - 1: the table's lanes of their id when they share one
    /// (nothing copied), else `scratch`, filled with each point's entry.
    const material<V, Q>* step(std::size_t i, std::size_t count, material<V, Q>& scratch) const
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        const std::uint32_t last = std::uint32_t(table.size() - 1);
        const std::uint32_t* id = ids.data() + i;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T> && std::is_same_v<T, float>) {
            if (count == W) { // 16 ids in one register: clamp, compare with lane 0
                const std::uint32_t first = std::min(id[0], last);
                const __m512i clamped = _mm512_min_epu32(_mm512_loadu_si512(id), _mm512_set1_epi32(int(last)));
                if (_mm512_cmpneq_epi32_mask(clamped, _mm512_set1_epi32(int(first))) == 0) return &splatted[first];
                if (!columns.empty()) return std::construct_at(&scratch, permuted(clamped));
                alignas(64) std::uint32_t element[W];
                _mm512_store_si512(element, clamped);
                return std::construct_at(&scratch, gather<V, true>(table.data(), element));
            }
        }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) {
            if (count == W) { // 8 ids in one register: clamp, compare with lane 0
                const std::uint32_t first = std::min(id[0], last);
                const __m256i clamped = _mm256_min_epu32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(id)), _mm256_set1_epi32(int(last)));
                if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(clamped, _mm256_set1_epi32(int(first)))) == -1) return &splatted[first];
                if (!columns.empty()) return std::construct_at(&scratch, permuted(clamped));
                alignas(32) std::uint32_t element[W];
                _mm256_store_si256(reinterpret_cast<__m256i*>(element), clamped);
                return std::construct_at(&scratch, gather<V, true>(table.data(), element));
            }
        }
#endif
        alignas(64) std::uint32_t element[W];
        bool uniform = true;
        for (std::size_t k = 0; k < W; ++k) {
            element[k] = std::min(id[k < count ? k : count - 1], last);
            uniform = uniform && element[k] == element[0];
        }
        if (uniform) return &splatted[element[0]];
        return std::construct_at(&scratch, gather<V, true>(table.data(), element));
    }
};

/// One material for every point: its lanes, splatted once per call (folded into the lights).
template <class V, glm::qualifier Q> struct shared_lanes {
    material<V, Q> lanes;
};
/// The same where folding would lose a product to underflow or overflow (foldable below): the
/// material multiplies the sums at the end, as per point.
template <class V, glm::qualifier Q> struct unfolded_shared_lanes {
    material<V, Q> lanes;
};

/// One material per point: the step's materials gathered into lanes (pad lanes: the last point's).
template <class V, class T, glm::qualifier Q> struct per_point_lanes {
    std::span<const material<T, Q>> materials;
    /// The lanes of points i .. i + count - 1, in `scratch`.
    const material<V, Q>* step(std::size_t i, std::size_t count, material<V, Q>& scratch) const
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        if (count == W) {
            std::construct_at(&scratch, gather<V, false>(materials.data() + i, full_step_elements<W>.index));
        } else {
            const consecutive_elements<W> tail(count);
            std::construct_at(&scratch, gather<V, false>(materials.data() + i, tail.index));
        }
        return &scratch;
    }
};

/// The shininess lanes with m == 0 tested (exact::lane_shininess): once per call, or once per
/// step with per-step materials.
template <class V> exact::lane_shininess<V> shininess_lanes(const V& m)
{
    using S = typename math_traits<V>::scalar;
    const mask_t<V> zero = m == V(S(0));
    // Float lanes: cosines above least_base(m) have a power of at least the power floor, the others
    // get 0 (exact::add_specular's step_specular route).
    V least(S(0));
    if constexpr (std::is_same_v<S, float>) least = math_traits<V>::least_base(detail::select(zero, V(S(1)), m));
    return {m, zero, math_traits<V>::any(zero), detail::select(zero, V(-std::numeric_limits<S>::infinity()), least),
            detail::min(m, V(S(0x1p100)))};
}

/// The fast mode's shared integer exponent: n when every lane's shininess is the same integer n in
/// [1, fast::detail::pow_integer_max_exponent] (binary powering, its schedule made once per call),
/// else 0 (m = 0, pow(0, 0) = 1 on every lane that is on, and other m take lane_shininess).
template <class V, class T, glm::qualifier Q> unsigned shared_integer_exponent(const material<V, Q>& mat)
{
    const T m0 = mat.shininess.get(0);
    const bool shared = m0 >= T(1) && m0 <= T(fast::detail::pow_integer_max_exponent) && m0 == T(unsigned(m0)) &&
                        math_traits<V>::all(mat.shininess == V(m0));
    return shared ? unsigned(m0) : 0u;
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
