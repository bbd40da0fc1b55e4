// phong: the data layouts of shade_batch: broadcasting (splat), loads and stores of lanes, the
// AoS <-> SoA transposes in registers (AVX-512, AVX2), and the step stream through which every
// layout reaches the one compiled kernel.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
#include "../simd/math_traits.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

template <class V, class T, glm::qualifier Q>
glm::vec<3, V, Q> splat(const glm::vec<3, T, Q>& v) { return {V(v.x), V(v.y), V(v.z)}; }
template <class V, class T, glm::qualifier Q>
glm::vec<4, V, Q> splat(const glm::vec<4, T, Q>& v) { return {V(v.x), V(v.y), V(v.z), V(v.w)}; }

template <class V, class T, glm::qualifier Q>
light<V, Q> splat(const light<T, Q>& L)
{
    light<V, Q> b;
    b.position = splat<V>(L.position);
    b.ambient = splat<V>(L.ambient);
    b.diffuse = splat<V>(L.diffuse);
    b.specular = splat<V>(L.specular);
    b.attenuation = {V(L.attenuation.constant), V(L.attenuation.linear), V(L.attenuation.quadratic), V(L.attenuation.range)};
    b.spot.direction = splat<V>(L.spot.direction);
    b.spot.exponent = V(L.spot.exponent);
    b.spot.cos_cutoff = V(L.spot.cos_cutoff);
    b.spot.cos_inner = V(L.spot.cos_inner);
    b.spot.cos_outer = V(L.spot.cos_outer);
    return b;
}
template <class V, class T, glm::qualifier Q>
material<V, Q> splat(const material<T, Q>& m)
{
    return {splat<V>(m.ka), splat<V>(m.kd), splat<V>(m.ks), splat<V>(m.emission), V(m.shininess), V(m.alpha)};
}

template <class V, class T> V load(const T* p)
{
    if constexpr (std::is_same_v<V, T>) return *p;
    else return V::load_unaligned(p);
}
template <class V, class T> void store(const V& v, T* p)
{
    if constexpr (std::is_same_v<V, T>) *p = v;
    else v.store_unaligned(p);
}

/// True where the AVX-512 paths below apply: 512-bit lanes of float or double (16 or 8 points).
template <class V, class T> inline constexpr bool avx512_lanes =
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    !std::is_same_v<V, T> && sizeof(V) == 64 && (std::is_same_v<T, float> || std::is_same_v<T, double>);
#else
    false;
#endif

/// True where the AVX2 paths below apply: 256-bit lanes of float (8 points).
template <class V, class T> inline constexpr bool avx2_float_lanes =
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    !std::is_same_v<V, T> && sizeof(V) == 32 && std::is_same_v<T, float>;
#else
    false;
#endif

#if PHONG_HAS_XSIMD && defined(__AVX2__)
/// The 8 x 3 transpose with AVX2 (8 interleaved vec3 in registers a, b, c): component o of lane k
/// is float 3k + o; as 3 is coprime to 8, two blends gather a component's 8 floats and one permute
/// orders them. Back: block b's float j is component (8b + j) % 3 of point (8b + j) / 3.
constexpr int aos8_blend(int o, int reg)
{
    int bits = 0;
    for (int k = 0; k < 8; ++k)
        if ((3 * k + o) / 8 == reg) bits |= 1 << ((3 * k + o) % 8);
    return bits;
}
constexpr int interleave8_blend(int b, int component)
{
    int bits = 0;
    for (int j = 0; j < 8; ++j)
        if ((8 * b + j) % 3 == component) bits |= 1 << j;
    return bits;
}
struct aos8_permutes {
    alignas(32) std::int32_t gather[3][8]{}, scatter[3][8]{};
    constexpr aos8_permutes()
    {
        for (int o = 0; o < 3; ++o)
            for (int k = 0; k < 8; ++k) {
                gather[o][k] = (3 * k + o) % 8;
                scatter[o][k] = (8 * o + k) / 3;
            }
    }
};
inline constexpr aos8_permutes aos8_permute_table{};
template <int o> __m256 aos8_component(__m256 a, __m256 b, __m256 c)
{
    const __m256 t = _mm256_blend_ps(_mm256_blend_ps(a, b, aos8_blend(o, 1)), c, aos8_blend(o, 2));
    return _mm256_permutevar8x32_ps(t, _mm256_load_si256(reinterpret_cast<const __m256i*>(aos8_permute_table.gather[o])));
}
template <int b> __m256 interleave8_block(__m256 x, __m256 y, __m256 z)
{
    const __m256i point = _mm256_load_si256(reinterpret_cast<const __m256i*>(aos8_permute_table.scatter[b]));
    const __m256 px = _mm256_permutevar8x32_ps(x, point), py = _mm256_permutevar8x32_ps(y, point), pz = _mm256_permutevar8x32_ps(z, point);
    return _mm256_blend_ps(_mm256_blend_ps(px, py, interleave8_blend(b, 1)), pz, interleave8_blend(b, 2));
}
#endif

/// Lanes [0, W) of a vector input for points i .. i + count - 1 (count <= W): SoA straight from
/// the three spans when the step is full, else through a padded copy (lanes past count: pad).
template <class V, glm::qualifier Q, class T>
glm::vec<3, V, Q> load_vec3(const soa3<T>& in, std::size_t i, std::size_t count, const glm::vec<3, T, Q>& pad)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if (count == W) return {load<V>(in.x.data() + i), load<V>(in.y.data() + i), load<V>(in.z.data() + i)};
    alignas(64) T buf[3][W];
    for (std::size_t k = 0; k < W; ++k) {
        buf[0][k] = k < count ? in.x[i + k] : pad.x;
        buf[1][k] = k < count ? in.y[i + k] : pad.y;
        buf[2][k] = k < count ? in.z[i + k] : pad.z;
    }
    return {load<V>(buf[0]), load<V>(buf[1]), load<V>(buf[2])};
}

#if PHONG_HAS_XSIMD && defined(__AVX512F__)
/// The 3 x W transpose of W interleaved vec3 into x, y, z lanes: two permutex2var per component
/// (component o of lane k is scalar 3k + o: in (a, b) below 2W, else c's 3k + o - 2W).
template <std::size_t W> struct aos_permutes {
    alignas(64) std::int32_t ab[3][W]{}, with_c[3][W]{};  // 32-bit: the float table
    alignas(64) std::int64_t ab64[3][W]{}, with_c64[3][W]{}; // 64-bit: the double table
    /// and back: block b of the interleaved output (scalars bW .. bW + W - 1) from x, y (first
    /// permute), then z.
    alignas(64) std::int32_t xy[3][W]{}, with_z[3][W]{};
    alignas(64) std::int64_t xy64[3][W]{}, with_z64[3][W]{};
    constexpr aos_permutes()
    {
        for (std::size_t o = 0; o < 3; ++o)
            for (std::size_t k = 0; k < W; ++k) {
                const std::size_t s = 3 * k + o;
                const std::size_t first = s < 2 * W ? s : 0, second = s < 2 * W ? k : W + s - 2 * W;
                ab[o][k] = std::int32_t(first), with_c[o][k] = std::int32_t(second);
                ab64[o][k] = std::int64_t(first), with_c64[o][k] = std::int64_t(second);
            }
        for (std::size_t b = 0; b < 3; ++b)
            for (std::size_t j = 0; j < W; ++j) {
                const std::size_t s = b * W + j, point = s / 3, component = s % 3;
                const std::size_t first = component == 0 ? point : component == 1 ? W + point : 0;
                const std::size_t second = component == 2 ? W + point : j;
                xy[b][j] = std::int32_t(first), with_z[b][j] = std::int32_t(second);
                xy64[b][j] = std::int64_t(first), with_z64[b][j] = std::int64_t(second);
            }
    }
};
template <std::size_t W> inline constexpr aos_permutes<W> aos_permute_table{};
#endif

/// Whether full steps of W interleaved vec3 are transposed in registers (aos_lanes,
/// interleave_lanes): AVX-512 (float, double), AVX2 (float), unpadded vec3; else via a buffer.
template <class V, class T, glm::qualifier Q> inline constexpr bool aos_in_registers =
    sizeof(glm::vec<3, T, Q>) == 3 * sizeof(T) && (avx512_lanes<V, T> || avx2_float_lanes<V, T>);

/// The x, y, z lanes of W interleaved vec3 at s, transposed in registers (aos_in_registers only):
/// AVX-512, three loads and six two-source permutes; AVX2, three loads, six blends, three permutes.
template <class V, glm::qualifier Q, class T>
inline glm::vec<3, V, Q> aos_lanes([[maybe_unused]] const T* s)
{
    static_assert(aos_in_registers<V, T, Q>);
    [[maybe_unused]] constexpr std::size_t W = sizeof(V) / sizeof(T);
    glm::vec<3, V, Q> r;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (avx512_lanes<V, T>) {
        constexpr const aos_permutes<W>& P = aos_permute_table<W>;
        for (glm::length_t o = 0; o < 3; ++o) {
            if constexpr (std::is_same_v<T, float>) {
                const __m512 t = _mm512_permutex2var_ps(_mm512_loadu_ps(s), _mm512_load_si512(P.ab[o]), _mm512_loadu_ps(s + W));
                r[o] = V(_mm512_permutex2var_ps(t, _mm512_load_si512(P.with_c[o]), _mm512_loadu_ps(s + 2 * W)));
            } else {
                const __m512d t = _mm512_permutex2var_pd(_mm512_loadu_pd(s), _mm512_load_si512(P.ab64[o]), _mm512_loadu_pd(s + W));
                r[o] = V(_mm512_permutex2var_pd(t, _mm512_load_si512(P.with_c64[o]), _mm512_loadu_pd(s + 2 * W)));
            }
        }
        return r;
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (avx2_float_lanes<V, T>) {
        const __m256 a = _mm256_loadu_ps(s), b = _mm256_loadu_ps(s + 8), c = _mm256_loadu_ps(s + 16);
        r = {V(aos8_component<0>(a, b, c)), V(aos8_component<1>(a, b, c)), V(aos8_component<2>(a, b, c))};
    }
#endif
    return r;
}

/// The same from an array of glm vectors (AoS): aos_lanes for a full step where aos_in_registers,
/// else a small buffer; the same values as from SoA spans, so the same bits.
template <class V, glm::qualifier Q, class T>
glm::vec<3, V, Q> load_vec3(std::span<const glm::vec<3, T, Q>> in, std::size_t i, std::size_t count, const glm::vec<3, T, Q>& pad)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if constexpr (aos_in_registers<V, T, Q>)
        if (count == W) return aos_lanes<V, Q>(&in[i].x);
    alignas(64) T buf[3][W];
    for (std::size_t k = 0; k < W; ++k) {
        const glm::vec<3, T, Q>& p = k < count ? in[i + k] : pad;
        buf[0][k] = p.x;
        buf[1][k] = p.y;
        buf[2][k] = p.z;
    }
    return {load<V>(buf[0]), load<V>(buf[1]), load<V>(buf[2])};
}

/// Stores the r, g, b lanes of a colour as W interleaved rgb at d (3W scalars; aos_in_registers
/// only): AVX-512, six permutes and three stores; AVX2, nine permutes, six blends, three stores.
template <class V, class T, glm::qualifier Q>
inline void interleave_lanes([[maybe_unused]] const glm::vec<3, V, Q>& c, [[maybe_unused]] T* d)
{
    static_assert(aos_in_registers<V, T, Q>);
    [[maybe_unused]] constexpr std::size_t W = sizeof(V) / sizeof(T);
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (avx512_lanes<V, T>) {
        constexpr const aos_permutes<W>& P = aos_permute_table<W>;
        for (std::size_t b = 0; b < 3; ++b) {
            if constexpr (std::is_same_v<T, float>) {
                const __m512 t = _mm512_permutex2var_ps(c[0], _mm512_load_si512(P.xy[b]), c[1]);
                _mm512_storeu_ps(d + b * W, _mm512_permutex2var_ps(t, _mm512_load_si512(P.with_z[b]), c[2]));
            } else {
                const __m512d t = _mm512_permutex2var_pd(c[0], _mm512_load_si512(P.xy64[b]), c[1]);
                _mm512_storeu_pd(d + b * W, _mm512_permutex2var_pd(t, _mm512_load_si512(P.with_z64[b]), c[2]));
            }
        }
        return;
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (avx2_float_lanes<V, T>) {
        _mm256_storeu_ps(d, interleave8_block<0>(c[0], c[1], c[2]));
        _mm256_storeu_ps(d + 8, interleave8_block<1>(c[0], c[1], c[2]));
        _mm256_storeu_ps(d + 16, interleave8_block<2>(c[0], c[1], c[2]));
    }
#endif
}

/// Stores a colour's lanes into count interleaved rgb at out (interleave_lanes or a small buffer).
template <class V, class T, glm::length_t N, glm::qualifier Q>
void store_interleaved(const glm::vec<N, V, Q>& c, glm::vec<N, T, Q>* out, std::size_t count)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if constexpr (N == 3 && aos_in_registers<V, T, Q>) {
        if (count == W) return interleave_lanes<V, T, Q>(c, &out->x);
    }
    alignas(64) T buf[4][W];
    for (glm::length_t ch = 0; ch < N; ++ch) store(c[ch], buf[ch]);
    for (std::size_t k = 0; k < count; ++k)
        for (glm::length_t ch = 0; ch < N; ++ch) out[k][ch] = buf[ch][k];
}

/// The lanes of one batch step: position, normal, view (view_model::given only), front-facing flags.
template <class V, glm::qualifier Q> struct step_lanes {
    glm::vec<3, V, Q> position;
    glm::vec<3, V, Q> normal;
    glm::vec<3, V, Q> view;
    mask_t<V> front;
};

/// Where shade_lanes reads its steps' lanes and writes their colours: a pointer per component and
/// the stride from one step to the next. Full SoA steps point into the caller's spans (stride W),
/// full AoS steps and interleaved rgb into the caller's arrays (transposed in registers, stride 3W),
/// the rest into a block of the call. The layout is a run-time flag, not a template parameter, so
/// every layout runs the same compiled shade_lanes and their colours agree bit for bit.
template <class V, class T> struct step_stream {
    const T* in[9];          ///< view x y z: read only with view_model::given; aos_in: in[0], in[3], in[6] only
    std::size_t in_stride;
    const mask_t<V>* front;  ///< front-facing lanes, one mask per step; null: every lane
    T* out[4];               ///< a: written only with F.alpha; interleaved_out: out[0] only
    std::size_t out_stride;
    bool aos_in;             ///< in[0], in[3], in[6]: W interleaved vec3 per step
    bool interleaved_out;    ///< out[0]: W interleaved rgb per step
    /// Step k's lanes (the view only with view_model::given). Flags: false where the caller knows
    /// that neither aos_in nor interleaved_out is set (SoA in and out, blocks): no test per step.
    template <features F, glm::qualifier Q, bool Flags = true> step_lanes<V, Q> lanes(std::size_t k) const
    {
        const std::size_t o = k * in_stride;
        step_lanes<V, Q> s;
        s.front = front ? front[k] : mask_t<V>(true);
        if constexpr (Flags && aos_in_registers<V, T, Q>) {
            if (aos_in) {
                s.position = aos_lanes<V, Q>(in[0] + o);
                s.normal = aos_lanes<V, Q>(in[3] + o);
                if constexpr (F.view == view_model::given) s.view = aos_lanes<V, Q>(in[6] + o);
                return s;
            }
        }
        s.position = {load<V>(in[0] + o), load<V>(in[1] + o), load<V>(in[2] + o)};
        s.normal = {load<V>(in[3] + o), load<V>(in[4] + o), load<V>(in[5] + o)};
        if constexpr (F.view == view_model::given) s.view = {load<V>(in[6] + o), load<V>(in[7] + o), load<V>(in[8] + o)};
        return s;
    }
    /// Stores step k's colour (Flags as lanes).
    template <features F, glm::qualifier Q, bool Flags = true> void put(std::size_t k, const color<F, V, Q>& c) const
    {
        if constexpr (Flags && !F.alpha && aos_in_registers<V, T, Q>) {
            if (interleaved_out) return interleave_lanes<V, T, Q>(c, out[0] + k * out_stride);
        }
        constexpr glm::length_t channels = F.alpha ? 4 : 3;
        for (glm::length_t ch = 0; ch < channels; ++ch) store(c[ch], out[ch] + k * out_stride);
    }
};

/// The front-facing lanes of one step (count <= W flags from index i; lanes past count: front).
template <class V, class T> mask_t<V> front_lanes(std::span<const bool> front_facing, std::size_t i, std::size_t count)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    alignas(64) T buf[W];
    for (std::size_t k = 0; k < W; ++k) buf[k] = k < count && !front_facing[i + k] ? T(0) : T(1);
    return load<V>(buf) > V(T(0));
}

/// Loads one step's position, normal and view lanes (count <= W points from i; soa_points or
/// aos_points): full steps straight or through a transpose, tails through padded copies (pad:
/// Q = (0, 0, -1), n = v = (0, 0, 1), facing the eye).
template <features F, class V, class Points, class T, glm::qualifier Q>
void load_step(std::size_t i, std::size_t count, const Points& points, step_lanes<V, Q>& lanes)
{
    using vec3 = glm::vec<3, T, Q>;
    lanes.position = load_vec3<V, Q>(points.positions, i, count, vec3(T(0), T(0), T(-1)));
    lanes.normal = load_vec3<V, Q>(points.normals, i, count, vec3(T(0), T(0), T(1)));
    if constexpr (F.view == view_model::given) lanes.view = load_vec3<V, Q>(points.views, i, count, vec3(T(0), T(0), T(1)));
}

/// Stores the colours of one batch step (count <= W points from index i).
template <features F, class V, class T, glm::qualifier Q, class Output>
void store_step(const color<F, V, Q>& c, std::size_t i, std::size_t count, const Output& out)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    constexpr glm::length_t channels = F.alpha ? 4 : 3;
    if constexpr (std::is_same_v<Output, soa_rgba<T>>) {
        T* dst[4] = {out.r.data(), out.g.data(), out.b.data(), F.alpha ? out.a.data() : nullptr};
        for (glm::length_t ch = 0; ch < channels; ++ch) {
            if (count == W) {
                store(c[ch], dst[ch] + i);
            } else {
                alignas(64) T buf[W];
                store(c[ch], buf);
                for (std::size_t k = 0; k < count; ++k) dst[ch][i + k] = buf[k];
            }
        }
    } else {
        store_interleaved<V, T>(c, out.data() + i, count);
    }
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
