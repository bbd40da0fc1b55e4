// phong: shade_batch's preconditions (span lengths, aliasing, valid materials, lights and
// environment), checked in debug builds through the precondition handler.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../shade.hpp"
#include "../../batch_types.hpp"
#include "../simd/math_traits.hpp"

#include <array>
#include <cstdio>
#include <functional>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "../simd/diagnostics_push.hpp"

namespace phong::detail {

/// The bytes [p, p + bytes) and [q, q + bytes_q) share at least one byte (std::less: a total
/// order on pointers, also between unrelated objects).
inline bool bytes_overlap(const void* p, std::size_t bytes, const void* q, std::size_t bytes_q)
{
    if (bytes == 0 || bytes_q == 0) return false;
    const auto* a = static_cast<const unsigned char*>(p);
    const auto* b = static_cast<const unsigned char*>(q);
    const std::less<const unsigned char*> before;
    return before(a, b + bytes_q) && before(b, a + bytes);
}

/// Memory that shade_batch reads while it writes: none for one shared material (copied into
/// lanes first), the N materials when per point, a table's entries (gathered per step) and its N ids.
struct byte_range {
    const void* p = nullptr;
    std::size_t bytes = 0;
};
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material<T, Q>&, std::size_t) { return {}; }
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(std::span<const material<T, Q>> m, std::size_t n)
{
    return {byte_range{m.data(), n * sizeof(material<T, Q>)}, byte_range{}};
}
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material_table<T, Q>& t, std::size_t n)
{
    return {byte_range{t.materials.data(), t.materials.size() * sizeof(material<T, Q>)}, byte_range{t.ids.data(), n * sizeof(std::uint32_t)}};
}

/// shade_batch's aliasing rule, checked in debug builds: the memory it writes (the first n
/// elements of each output channel, or of the interleaved colours) overlaps no memory it reads
/// point by point (the first n coordinates, materials when per point, front_facing flags), nor
/// another output channel. One exception: an SoA output channel may be exactly an input
/// coordinate span (same data(), whole length n), i.e. shading in place. That is safe because
/// each step reads its points' coordinates (into lanes, or padded copies for the tail) before it
/// stores their colours, and never stores to an element a later step reads. Lights, a shared
/// material and the environment are copied into lanes before the first store: no constraint.
template <int channels, class T, glm::qualifier Q, class Materials, class Output>
bool output_overlaps_input(const soa3<T>& positions, const soa3<T>& normals, const Materials& materials,
                           const Output& out, std::span<const bool> front_facing, std::size_t n)
{
    struct range {
        const void* p;
        std::size_t bytes;
    };
    constexpr bool soa = std::is_same_v<Output, soa_rgba<T>>;
    range writes[4]{};
    int write_count = 0;
    if constexpr (soa) {
        const std::span<T> channel[4] = {out.r, out.g, out.b, out.a};
        for (int k = 0; k < channels; ++k) writes[write_count++] = {channel[k].data(), n * sizeof(T)};
    } else {
        writes[write_count++] = {out.data(), n * sizeof(typename Output::value_type)};
    }
    const std::span<const T> coords[6] = {positions.x, positions.y, positions.z, normals.x, normals.y, normals.z};
    for (int w = 0; w < write_count; ++w) {
        for (const std::span<const T>& c : coords)
            if (bytes_overlap(writes[w].p, writes[w].bytes, c.data(), n * sizeof(T)) &&
                !(soa && writes[w].p == static_cast<const void*>(c.data())))
                return true;
        for (const byte_range& m : material_reads(materials, n))
            if (bytes_overlap(writes[w].p, writes[w].bytes, m.p, m.bytes)) return true;
        if (!front_facing.empty() && bytes_overlap(writes[w].p, writes[w].bytes, front_facing.data(), n * sizeof(bool)))
            return true;
        for (int other = 0; other < w; ++other)
            if (bytes_overlap(writes[w].p, writes[w].bytes, writes[other].p, writes[other].bytes)) return true;
    }
    return false;
}

/// Number of vectors in an SoA or AoS input (SoA: the three spans' common length, or a length
/// no valid input has when they differ).
template <class T> std::size_t vec3_count(const soa3<T>& v)
{
    return v.y.size() == v.x.size() && v.z.size() == v.x.size() ? v.x.size() : std::size_t(-1);
}
template <class T, glm::qualifier Q> std::size_t vec3_count(std::span<const glm::vec<3, T, Q>> v) { return v.size(); }

/// "shade_batch: <span>[<index>]: <message>", formatted into a per-thread buffer: the message of
/// a failed precondition on one entry of a span names the entry (debug builds, on failure only;
/// valid until the thread's next call).
inline const char* entry_message(const char* span, std::size_t index, const char* message) noexcept
{
    thread_local char buffer[256];
    std::snprintf(buffer, sizeof buffer, "shade_batch: %s[%zu]: %s", span, index, message);
    return buffer;
}

/// shade_batch's preconditions, checked in debug builds through the precondition handler (span
/// lengths, each message naming the span; no aliasing; valid materials, lights and environment, a
/// span's entry named by its index). Returns whether to shade: not when a length
/// is off (a handler that returns must not lead to reads or writes past a span), nor, in every
/// build, with an empty material table (nothing to read).
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
bool check_batch_inputs(const Points& points, const Materials& materials, [[maybe_unused]] std::span<const light<T, Q>> lights,
                        const Output& out, [[maybe_unused]] const environment<T, Q>& env, std::size_t n)
{
    constexpr bool shared_material = std::is_same_v<Materials, material<T, Q>>;
    constexpr bool table = std::is_same_v<Materials, material_table<T, Q>>;
    [[maybe_unused]] std::size_t out_size = 0;
    if constexpr (std::is_same_v<Output, soa_rgba<T>>)
        out_size = std::min({out.r.size(), out.g.size(), out.b.size(), F.alpha ? out.a.size() : out.r.size()});
    else
        out_size = out.size();
    const bool positions_ok = vec3_count(points.positions) != std::size_t(-1); // else n is no count: one report
    PHONG_ASSERT(positions_ok, "shade_batch: .positions: x, y and z of different lengths");
    PHONG_ASSERT(!positions_ok || vec3_count(points.normals) == n, "shade_batch: .normals: not one normal per point");
    PHONG_ASSERT(!positions_ok || out_size >= n, "shade_batch: the output is shorter than the points (N entries per channel)");
    [[maybe_unused]] bool lengths_ok = positions_ok && vec3_count(points.normals) == n && out_size >= n;
    if constexpr (F.view == view_model::given) {
        PHONG_ASSERT(vec3_count(points.views) == n, "shade_batch: view_model::given needs one view vector per point (.views)");
        lengths_ok = lengths_ok && vec3_count(points.views) == n;
    } else {
        PHONG_ASSERT(vec3_count(points.views) == 0, "shade_batch: .views is read only with features::view = view_model::given");
    }
    PHONG_ASSERT(points.front_facing.empty() || points.front_facing.size() == n, "shade_batch: front_facing length");
    PHONG_ASSERT(points.light_masks.empty() || points.light_masks.size() == n, "shade_batch: light_masks length");
    lengths_ok = lengths_ok && (points.front_facing.empty() || points.front_facing.size() == n) &&
                 (points.light_masks.empty() || points.light_masks.size() == n);
    if constexpr (table) {
        PHONG_ASSERT(materials.ids.size() == n, "shade_batch: material_table needs one id per point (.ids)");
        PHONG_ASSERT(n == 0 || !materials.materials.empty(), "shade_batch: material_table without materials");
        lengths_ok = lengths_ok && materials.ids.size() == n;
        // Checked in every build: with no entry there is nothing to read (an id is clamped to the last entry).
        if (n != 0 && materials.materials.empty()) return false;
    } else if constexpr (!shared_material) {
        PHONG_ASSERT(materials.size() == n, "shade_batch: one material per point");
        lengths_ok = lengths_ok && materials.size() == n;
    }
#if !defined(NDEBUG)
    if (!lengths_ok) return false;
    if constexpr (std::is_same_v<Points, soa_points<T>>) {
        PHONG_ASSERT((!output_overlaps_input<F.alpha ? 4 : 3, T, Q>(points.positions, points.normals, materials, out, points.front_facing, n)),
                     "shade_batch: an output span overlaps an input span (only an output channel equal to an input "
                     "coordinate span, the same data() and size(), may alias it)");
    } else { // AoS: the output overlaps none of the point arrays nor the materials
        const void* out_data = nullptr;
        std::size_t out_bytes = 0;
        if constexpr (std::is_same_v<Output, soa_rgba<T>>) out_data = out.r.data(), out_bytes = n * sizeof(T);
        else out_data = out.data(), out_bytes = n * sizeof(typename Output::value_type);
        bool overlap = false;
        const std::span<const glm::vec<3, T, Q>> arrays[3] = {points.positions, points.normals, points.views};
        for (const auto& a : arrays) overlap = overlap || bytes_overlap(out_data, out_bytes, a.data(), a.size() * sizeof(glm::vec<3, T, Q>));
        for (const byte_range& m : material_reads(materials, n)) overlap = overlap || bytes_overlap(out_data, out_bytes, m.p, m.bytes);
        PHONG_ASSERT(!overlap, "shade_batch: the output overlaps the input points");
    }
    if constexpr (table) {
        for (std::size_t j = 0; j < materials.materials.size(); ++j) {
            const validation valid = validate(materials.materials[j]);
            PHONG_ASSERT(static_cast<bool>(valid), entry_message("material_table.materials", j, valid.message()));
        }
        for (std::size_t i = 0; i < n; ++i)
            PHONG_ASSERT(materials.ids[i] < materials.materials.size(), entry_message("material_table.ids", i, "a material id past the table"));
    } else if constexpr (!shared_material) {
        for (std::size_t i = 0; i < n; ++i) {
            const validation valid = validate(materials[i]);
            PHONG_ASSERT(static_cast<bool>(valid), entry_message("materials", i, valid.message()));
        }
    } else {
        PHONG_ASSERT(static_cast<bool>(validate(materials)), validate(materials).message());
    }
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const validation valid = validate(lights[k]);
        PHONG_ASSERT(static_cast<bool>(valid), entry_message("lights", k, valid.message()));
    }
    PHONG_ASSERT(static_cast<bool>(validate(env)), validate(env).message());
#endif
    return true;
}

} // namespace phong::detail

#include "../simd/diagnostics_pop.hpp"
