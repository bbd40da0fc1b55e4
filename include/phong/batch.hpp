// phong: batch shading, shade_batch<F>: shade<F>'s own templates instantiated on SIMD batch types,
// over structure-of-arrays or array-of-structures points (types in ext/batch/types.hpp, machinery in
// ext/batch/, lanes in ext/simd/; docs/batch.md, "Source layout").
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
/// front_facing[i]), shade<F>'s own templates run on simd_batch<T>, batch_width<T> points per step (a
/// short tail through padded copies). On x86 without FMA instructions (PHONG_LANES_WITHOUT_FMA) the
/// points go one by one through shade<F>'s route instead: shade<F>'s bits.
///   positions, normals: structure of arrays (x, y, z spans of length N);
///   materials: one material<T, Q>; N materials (anything that converts to std::span<const material<T, Q>>);
///        or a material_table<T, Q> (point i takes materials[ids[i]]: the per-point form's bits);
///   lights: a span of light<T, Q>, put in lanes once per call (a renderer's own light type: to_light
///        once per call, not per point);
///   out: soa_rgba<T> (r, g, b, and a when F.alpha) or N interleaved colours (std::span<color<F, T, Q>>
///        or a std::vector of them);
///   front_facing: N flags, read only for facing::flag; empty means all front-facing.
/// Per-point views (view_model::given does not compile here), light masks, AoS input: the form below.
/// Pre (checked through the precondition handler, core/config.hpp: lengths and aliasing in every build,
/// and then nothing is shaded; values in debug builds): spans N long (out may be longer);
/// validate(material), validate(L); the N outputs overlap neither each other nor the inputs read per
/// point, except that an SoA output channel may be exactly one coordinate span (in place: each point
/// is read before its store). Lights, a shared material and env are copied first and may alias
/// anything. A table: ids N long, each in the table (past it: the last entry; empty table: nothing shaded).
/// Edges and NaN policy: shade<F>'s, point by point.
/// Accuracy: F.mode's published bound (phong/accuracy.hpp). Against the scalar shade<F> the bits differ
/// by the lanes' rsqrt estimate (< 2 ulp, float) and exp/log, amplified by m in exact mode (by about
/// sqrt(m) in stable mode).
template <features F, class T, class Materials, glm::qualifier Q = detail::materials_qualifier_v<Materials>, class Output = soa_rgba<T>>
    requires detail::batch_materials<Materials, T, Q> && detail::batch_output<Output, F, T, Q>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const Materials& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, Output&& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, detail::batch_materials_arg<T, Q>(materials), lights,
                                detail::batch_output_arg<F, T, Q>(static_cast<Output&&>(out)), env, front_facing);
}

/// Shades N points given as soa_points<T> or aos_points<T, Q> (glm vectors, e.g. a ray tracer's hit
/// records, transposed into the same lanes: the same bits as soa_points): for every i,
///   out[i] = shade<F>(p[i], n[i], [v[i],] materials(i), masked(lights, light_masks[i]), env, front_facing[i]),
/// v[i] = points.views with view_model::given only; masked() only when light_masks is given (a clear
/// bit: that light gives that point nothing, ambient included, as if removed); front_facing only for
/// facing::flag. materials, lights, out, kernels, edges, NaN policy and accuracy: as above. Masks and
/// views change no other lane's result, but the stable mode picks its route per step from every lane
/// (twofold where any lane's shininess is above 2^20 on float lanes, or per stable_twofold_above).
///   shade_batch<F>(aos_points<float>{.positions = P, .normals = N, .views = V, .light_masks = visible},
///                  material_table<float>{.materials = scene_materials, .ids = hit_material}, lights, out, env);
/// Pre (as above): N = the number of positions; normals N long, views N long with view_model::given
/// (else empty); front_facing and light_masks empty or N long. Lights past the 64th are seen by no
/// point when masks are given.
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
