// phong: the types of shade_batch's arguments: points and colours as structure of arrays or array
// of structures, and a material table. Included by phong/batch.hpp.
// SPDX-License-Identifier: MIT
#pragma once

#include "../../inputs/material.hpp"
#include "../simd/backend.hpp"

#include <cstdint>
#include <span>

namespace phong {


/// Three parallel arrays x, y, z of the same length (structure of arrays).
template <class T> struct soa3 {
    std::span<const T> x; ///< the x components
    std::span<const T> y; ///< the y components
    std::span<const T> z; ///< the z components
};
/// Output colour channels, structure of arrays. a is written only when F.alpha.
template <class T> struct soa_rgba {
    std::span<T> r; ///< red
    std::span<T> g; ///< green
    std::span<T> b; ///< blue
    std::span<T> a; ///< alpha (F.alpha only; else may be empty)
};

/// The points of one shade_batch call, structure of arrays (designated initializers name the ones
/// used); N = positions.x.size().
///   positions, normals: N points and their normals (any length; as shade<F> takes them);
///   views: N view vectors (toward the viewer, e.g. -ray.dir), read only and required with
///          view_model::given; empty otherwise;
///   front_facing: N flags, read only for facing::flag; empty: all front-facing;
///   light_masks: N masks, bit j set: light j visible there (else skipped exactly as if absent);
///          empty: every light visible. Lights past the 64th are seen by no point with masks.
template <class T> struct soa_points {
    soa3<T> positions;                            ///< N points
    soa3<T> normals;                              ///< their N normals
    soa3<T> views{};                              ///< N view vectors (view_model::given only)
    std::span<const bool> front_facing{};         ///< N flags (facing::flag only); empty: all front-facing
    std::span<const std::uint64_t> light_masks{}; ///< N light masks; empty: every light visible
};

/// The same, array of structures (a ray tracer's hit records as glm vectors, transposed into lanes
/// per step: nothing repacked). Fields as soa_points; N = positions.size().
template <class T, glm::qualifier Q = glm::defaultp> struct aos_points {
    std::span<const glm::vec<3, T, Q>> positions; ///< N points
    std::span<const glm::vec<3, T, Q>> normals;   ///< their N normals
    std::span<const glm::vec<3, T, Q>> views{};   ///< N view vectors (view_model::given only)
    std::span<const bool> front_facing{};         ///< N flags (facing::flag only); empty: all front-facing
    std::span<const std::uint64_t> light_masks{}; ///< N light masks; empty: every light visible
};

/// Materials as a renderer keeps them: a table and one index per point. shade_batch shades point i
/// with materials[ids[i]], bit for bit as with one material per point, without copying one per
/// point: the table goes to lanes once per call; a step whose points share one id uses those lanes,
/// a step of mixed ids takes each field from the table (one permute per field for float lanes and
/// at most batch_width<float> entries, else one gather per field).
///   materials: the table, validate() for each entry; not empty when there are points;
///   ids: N indices, each < materials.size().
/// Pre (debug assertions): ids N long, every id in the table. Edge: an id past the table takes its
/// last entry (memory-safe in release builds); an empty table shades nothing (every build).
template <class T, glm::qualifier Q = glm::defaultp> struct material_table {
    std::span<const material<T, Q>> materials; ///< the table
    std::span<const std::uint32_t> ids;        ///< one index into the table per point
};

} // namespace phong
