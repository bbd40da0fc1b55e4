// phong: shade_batch's preconditions, through the precondition handler: span lengths and
// aliasing in every build (memory safety), valid materials, lights and environment in debug builds.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../sum/shade.hpp"
#include "types.hpp"
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

/// Memory that shade_batch reads while it writes, with the span's name: per-point materials, a
/// table's entries and its ids (a shared material is copied into lanes first).
struct byte_range {
    const void* p = nullptr;
    std::size_t bytes = 0;
    const char* name = "";
};
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material<T, Q>&, std::size_t) { return {}; }
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(std::span<const material<T, Q>> m, std::size_t n)
{
    return {byte_range{m.data(), n * sizeof(material<T, Q>), "materials"}, byte_range{}};
}
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material_table<T, Q>& t, std::size_t n)
{
    return {byte_range{t.materials.data(), t.materials.size() * sizeof(material<T, Q>), "material_table.materials"},
            byte_range{t.ids.data(), n * sizeof(std::uint32_t), "material_table.ids"}};
}

/// "shade_batch: an output span overlaps <an input span | another output span>: <written> over
/// <read>", formatted into a per-thread buffer (on failure only; valid until the thread's next call).
inline const char* overlap_message(const char* written, const char* read, bool input, bool coordinate) noexcept
{
    thread_local char buffer[256];
    std::snprintf(buffer, sizeof buffer, "shade_batch: an output span overlaps %s: %s over %s%s",
                  input ? "an input span" : "another output span", written, read,
                  coordinate ? " (only an output channel equal to an input coordinate span, the same data() and size(), may alias it)" : "");
    return buffer;
}

/// shade_batch's aliasing rule, checked in every build (O(1)): what it writes overlaps nothing it
/// reads point by point (coordinates, per-point materials, a table and its ids, flags, masks), nor
/// another output. Exception: an SoA output channel may be exactly an SoA input coordinate span
/// (shading in place: each step reads its points before it stores their colours). Returns nullptr,
/// or the message naming both spans.
template <int channels, class T, glm::qualifier Q, class Points, class Materials, class Output>
const char* output_overlap(const Points& points, const Materials& materials, const Output& out, std::size_t n)
{
    constexpr bool soa_out = std::is_same_v<Output, soa_rgba<T>>;
    constexpr bool soa_in = std::is_same_v<Points, soa_points<T>>;
    byte_range writes[4]{};
    int write_count = 0;
    if constexpr (soa_out) {
        const std::span<T> channel[4] = {out.r, out.g, out.b, out.a};
        constexpr const char* names[4] = {"out.r", "out.g", "out.b", "out.a"};
        for (int k = 0; k < channels; ++k) writes[write_count++] = {channel[k].data(), n * sizeof(T), names[k]};
    } else {
        writes[write_count++] = {out.data(), n * sizeof(typename Output::value_type), "the output"};
    }
    byte_range reads[16]{};
    int read_count = 0;
    int coordinate_reads = 0; // reads[0, coordinate_reads): SoA coordinates, which an output channel may equal
    if constexpr (soa_in) {
        const soa3<T>* vectors[3] = {&points.positions, &points.normals, &points.views};
        constexpr const char* names[9] = {".positions.x", ".positions.y", ".positions.z", ".normals.x", ".normals.y",
                                          ".normals.z",   ".views.x",     ".views.y",     ".views.z"};
        for (int a = 0; a < 3; ++a) {
            const std::span<const T> c[3] = {vectors[a]->x, vectors[a]->y, vectors[a]->z};
            for (int k = 0; k < 3; ++k) reads[read_count++] = {c[k].data(), std::min(n, c[k].size()) * sizeof(T), names[3 * a + k]};
        }
        coordinate_reads = read_count;
    } else {
        reads[read_count++] = {points.positions.data(), points.positions.size() * sizeof(glm::vec<3, T, Q>), ".positions"};
        reads[read_count++] = {points.normals.data(), points.normals.size() * sizeof(glm::vec<3, T, Q>), ".normals"};
        reads[read_count++] = {points.views.data(), points.views.size() * sizeof(glm::vec<3, T, Q>), ".views"};
    }
    for (const byte_range& m : material_reads(materials, n)) reads[read_count++] = m;
    reads[read_count++] = {points.front_facing.data(), points.front_facing.size() * sizeof(bool), ".front_facing"};
    reads[read_count++] = {points.light_masks.data(), points.light_masks.size() * sizeof(std::uint64_t), ".light_masks"};
    for (int w = 0; w < write_count; ++w) {
        for (int r = 0; r < read_count; ++r) {
            const bool in_place = soa_out && r < coordinate_reads && writes[w].p == reads[r].p && reads[r].bytes == writes[w].bytes;
            if (!in_place && bytes_overlap(writes[w].p, writes[w].bytes, reads[r].p, reads[r].bytes))
                return overlap_message(writes[w].name, reads[r].name, true, soa_out && r < coordinate_reads);
        }
        for (int other = 0; other < w; ++other)
            if (bytes_overlap(writes[w].p, writes[w].bytes, writes[other].p, writes[other].bytes))
                return overlap_message(writes[w].name, writes[other].name, false, false);
    }
    return nullptr;
}

/// A memory-safety precondition of shade_batch (span lengths, overlap): O(1), checked in every
/// build (as hardened standard libraries check std::span) through the precondition handler. Returns
/// ok: when a handler returns, shade_batch writes nothing.
inline bool memory_safe(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                        int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
#if !defined(__CUDA_ARCH__) // shade_batch is host code; nvcc's device pass still parses this body
    if (!ok) precondition_failed(message, file, line);
#else
    (void)message;
    (void)file;
    (void)line;
#endif
    return ok;
}

/// Number of vectors in an SoA or AoS input (SoA spans of different lengths: a length no input has).
template <class T> std::size_t vec3_count(const soa3<T>& v)
{
    return v.y.size() == v.x.size() && v.z.size() == v.x.size() ? v.x.size() : std::size_t(-1);
}
template <class T, glm::qualifier Q> std::size_t vec3_count(std::span<const glm::vec<3, T, Q>> v) { return v.size(); }

/// "shade_batch: <span>[<index>]: <message>" in a per-thread buffer (debug builds, on failure only;
/// valid until the thread's next call).
inline const char* entry_message(const char* span, std::size_t index, const char* message) noexcept
{
    thread_local char buffer[256];
    std::snprintf(buffer, sizeof buffer, "shade_batch: %s[%zu]: %s", span, index, message);
    return buffer;
}

/// shade_batch's preconditions through the precondition handler: in every build the span lengths and
/// the aliasing rule (memory safety: a failure shades nothing); in debug builds valid materials,
/// lights and environment (naming the entry). Returns whether to shade: not after a failed memory
/// check, nor with an empty material table.
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
bool check_batch_inputs(const Points& points, const Materials& materials, [[maybe_unused]] std::span<const light<T, Q>> lights,
                        const Output& out, [[maybe_unused]] const environment<T, Q>& env, std::size_t n)
{
    constexpr bool shared_material = std::is_same_v<Materials, material<T, Q>>;
    constexpr bool table = std::is_same_v<Materials, material_table<T, Q>>;
    std::size_t out_size = 0;
    if constexpr (std::is_same_v<Output, soa_rgba<T>>)
        out_size = std::min({out.r.size(), out.g.size(), out.b.size(), F.alpha ? out.a.size() : out.r.size()});
    else
        out_size = out.size();
    // n is no count when x, y and z differ: one report then.
    if (!memory_safe(vec3_count(points.positions) != std::size_t(-1), "shade_batch: .positions: x, y and z of different lengths")) return false;
    bool lengths_ok = memory_safe(vec3_count(points.normals) == n, "shade_batch: .normals: not one normal per point");
    lengths_ok = memory_safe(out_size >= n, "shade_batch: the output is shorter than the points (N entries per channel)") && lengths_ok;
    if constexpr (F.view == view_model::given)
        lengths_ok = memory_safe(vec3_count(points.views) == n, "shade_batch: view_model::given needs one view vector per point (.views)") && lengths_ok;
    else
        lengths_ok = memory_safe(vec3_count(points.views) == 0, "shade_batch: .views is read only with features::view = view_model::given") && lengths_ok;
    lengths_ok = memory_safe(points.front_facing.empty() || points.front_facing.size() == n, "shade_batch: front_facing length") && lengths_ok;
    lengths_ok = memory_safe(points.light_masks.empty() || points.light_masks.size() == n, "shade_batch: light_masks length") && lengths_ok;
    if constexpr (table) {
        lengths_ok = memory_safe(materials.ids.size() == n, "shade_batch: material_table needs one id per point (.ids)") && lengths_ok;
        // With no entry there is nothing to read (an id is clamped to the last entry).
        lengths_ok = memory_safe(n == 0 || !materials.materials.empty(), "shade_batch: material_table without materials") && lengths_ok;
    } else if constexpr (!shared_material) {
        lengths_ok = memory_safe(materials.size() == n, "shade_batch: one material per point") && lengths_ok;
    }
    if (!lengths_ok) return false;
    const char* overlap = output_overlap<F.alpha ? 4 : 3, T, Q>(points, materials, out, n);
    if (!memory_safe(overlap == nullptr, overlap)) return false;
#if !defined(NDEBUG)
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
