// phong: batch shading, shade_batch<F>: shade<F>'s own templates instantiated on SIMD batches, over
// structure-of-arrays or array-of-structures points. The machinery is in ext/batch/ (set-up, the
// kernel, checks, loads and stores) and ext/simd/ (the lanes); docs/batch.md draws it.
// SPDX-License-Identifier: MIT
#pragma once

#include "ext/batch/types.hpp"
#include "sum/shade.hpp"
#include "ext/batch/driver.hpp"

#include <iterator>
#include <span>
#include <type_traits>
#include <utility>

namespace phong {

namespace detail {

/// What shade_batch takes as materials: one material<T, Q> for all points, a material_table<T, Q>,
/// or N materials (anything that converts to std::span<const material<T, Q>>: a span, a std::vector).
template <class M, class T, glm::qualifier Q>
concept batch_materials = std::is_same_v<M, material<T, Q>> || std::is_same_v<M, material_table<T, Q>> ||
                          std::is_convertible_v<const M&, std::span<const material<T, Q>>>;

/// What shade_batch writes: SoA channels (soa_rgba<T>), or N interleaved colours (anything that
/// converts to std::span<color<F, T, Q>>: a span, a std::vector lvalue).
template <class O, features F, class T, glm::qualifier Q>
concept batch_output = std::is_same_v<std::remove_cvref_t<O>, soa_rgba<T>> || std::is_convertible_v<O, std::span<color<F, T, Q>>>;

/// The qualifier of a batch_materials type (glm::defaultp where it names none).
template <class M> inline constexpr glm::qualifier materials_qualifier_v = glm::defaultp;
template <class T, glm::qualifier Q> inline constexpr glm::qualifier materials_qualifier_v<material<T, Q>> = Q;
template <class T, glm::qualifier Q> inline constexpr glm::qualifier materials_qualifier_v<material_table<T, Q>> = Q;
template <class M>
    requires requires { typename std::remove_cvref_t<decltype(*std::begin(std::declval<const M&>()))>; }
inline constexpr glm::qualifier materials_qualifier_v<M> = materials_qualifier_v<std::remove_cvref_t<decltype(*std::begin(std::declval<const M&>()))>>;

/// The scalar type and qualifier of soa_points<T> (the materials' qualifier) and aos_points<T, Q>.
template <class P, class Materials> struct batch_points_of {};
template <class T, class Materials> struct batch_points_of<soa_points<T>, Materials> {
    using scalar = T;
    static constexpr glm::qualifier qualifier = materials_qualifier_v<Materials>;
};
template <class T, glm::qualifier Q, class Materials> struct batch_points_of<aos_points<T, Q>, Materials> {
    using scalar = T;
    static constexpr glm::qualifier qualifier = Q;
};

/// The materials as shade_points_impl takes them: a material or a table by reference, N
/// materials as a std::span (so the same instantiations whatever container the caller holds).
template <class T, glm::qualifier Q, class M>
decltype(auto) batch_materials_arg(const M& materials)
{
    if constexpr (std::is_same_v<M, material<T, Q>> || std::is_same_v<M, material_table<T, Q>>) return (materials);
    else return std::span<const material<T, Q>>(materials);
}
/// The output as shade_points_impl takes it: soa_rgba<T>, or a std::span of colours.
template <features F, class T, glm::qualifier Q, class O>
decltype(auto) batch_output_arg(O&& out)
{
    if constexpr (std::is_same_v<std::remove_cvref_t<O>, soa_rgba<T>>) return static_cast<const soa_rgba<T>&>(out);
    else return std::span<color<F, T, Q>>(out);
}

} // namespace detail

/// Shades N points at once: out[i] = shade<F>(position[i], normal[i], materials(i), lights, env,
/// front_facing[i]) for every i. The kernels are shade<F>'s own templates (detail::prepare,
/// add_light, finish) run on simd_batch<T>, batch_width<T> points per step; a tail shorter than
/// the width goes through padded copies. Lights, material and environment are broadcast to the
/// lanes once per call. On x86 without FMA instructions (PHONG_LANES_WITHOUT_FMA: the x86-64
/// baseline) the points are shaded one by one through shade<F>'s route instead: the same colours
/// as shade<F>, bit for bit.
///   positions, normals: structure of arrays (x, y, z spans of length N), as shade<F> takes them;
///   materials: one material<T, Q> for all points; N materials, one per point (a
///        std::span<const material<T, Q>>, or anything that converts to one, e.g. a std::vector);
///        or a material_table<T, Q> (point i takes materials.materials[materials.ids[i]]; the same
///        bits as the per-point form given those materials);
///   lights: a span of light<T, Q> (a std::vector converts);
///   out: SoA channels (soa_rgba<T>: r, g, b, and a when F.alpha; a braced {r, g, b, a} is one),
///        or N interleaved colours (std::span<color<F, T, Q>>, or a std::vector of them:
///        glm::vec3, or glm::vec4 when F.alpha);
///   front_facing: N flags, read only for facing::flag; empty means all front-facing.
/// Per-point view vectors (view_model::given: a compile error here), per-point light masks and
/// AoS glm::vec3 inputs: the soa_points / aos_points form below.
/// Pre (checked through the precondition handler, core/config.hpp; the span lengths and the
/// aliasing rule in every build, NDEBUG included, and nothing is shaded when one fails; the values
/// in debug builds): spans of length N (out may be longer; only its first N elements are
/// written); validate(material) and validate(L); no aliasing: the N output elements overlap
/// neither the inputs read per point (the N coordinates and views, the N materials when per point
/// or a table and its ids, front_facing, light masks) nor each other, except that
/// an SoA output channel may be exactly one of the coordinate spans (same data(), in-place
/// shading: each point is read before its colour is stored). Lights, a shared material and env
/// are copied before the first store and may alias anything. A table: ids N long, every id in the
/// table (an id past the table takes its last entry, memory-safe in release builds; an empty
/// table shades nothing, every build).
/// Edges and NaN policy: those of shade<F>, point by point. A renderer's own light type: convert
/// the list once per call with to_light. Accuracy: the published bound of F.mode
/// (phong/accuracy.hpp); against shade<F>, differences of the lanes' rsqrt and exp/log (< 2 ulp in
/// float lanes) amplified by m in exact mode (by about sqrt(m) in stable mode).
template <features F, class T, class Materials, glm::qualifier Q = detail::materials_qualifier_v<Materials>, class Output = soa_rgba<T>>
    requires detail::batch_materials<Materials, T, Q> && detail::batch_output<Output, F, T, Q>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const Materials& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, Output&& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, detail::batch_materials_arg<T, Q>(materials), lights,
                                detail::batch_output_arg<F, T, Q>(static_cast<Output&&>(out)), env, front_facing);
}

/// Shades N points given as soa_points<T> (structure of arrays) or aos_points<T, Q> (positions,
/// normals and views as glm vectors: a ray tracer's hit records, loaded into lanes with a small
/// transpose; the same lanes as soa_points, so the same results bit for bit): for every i,
///   out[i] = shade<F>(p[i], n[i], [v[i],] materials(i), masked(lights, light_masks[i]), env, front_facing[i]),
/// with v[i] = points.views (view_model::given only: secondary rays each with their own view
/// vector), masked() only when light_masks is given (shadows: each point its own set of lights;
/// a light whose bit is clear gives that point nothing, its ambient term included, exactly as if
/// it were removed), front_facing only for facing::flag. materials, lights and out as above (one
/// material, N materials, or a material_table: a ray tracer's scene materials and per-hit ids);
/// the kernels, edges, NaN policy and accuracy are those of the form above; masks and views
/// change no other lane's result (but the stable mode picks its route per step from every lane:
/// the twofold route where any lane's shininess is above 2^20 on float lanes, and its depth with
/// features::stable_twofold_above > 0). N = the number of positions.
///   shade_batch<F>(aos_points<float>{.positions = P, .normals = N, .views = V, .light_masks = visible},
///                  material_table<float>{.materials = scene_materials, .ids = hit_material}, lights, out, env);
/// Pre (debug assertions): normals, and views with view_model::given, N long (views empty
/// otherwise); front_facing and light_masks empty or N long; out at least N long; per-point
/// materials N long; validate(material) and validate(L). Masks with more than 64 lights: lights
/// past the 64th are seen by no point.
template <features F, class Points, class Materials, class T = typename detail::batch_points_of<Points, Materials>::scalar,
          glm::qualifier Q = detail::batch_points_of<Points, Materials>::qualifier, class Output = soa_rgba<T>>
    requires detail::batch_materials<Materials, T, Q> && detail::batch_output<Output, F, T, Q>
void shade_batch(const Points& points, const Materials& materials, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 Output&& out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, detail::batch_materials_arg<T, Q>(materials), lights,
                                 detail::batch_output_arg<F, T, Q>(static_cast<Output&&>(out)), env);
}

} // namespace phong
