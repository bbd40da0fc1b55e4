// phong: batch shading, shade_batch<F>. The same templates as the scalar path (detail::prepare,
// add_lights in detail/route.hpp, finish in shading_terms.hpp), instantiated on a SIMD batch type,
// over structure-of-arrays or array-of-structures points.
// SPDX-License-Identifier: MIT
//
// The layers, each including only the ones below it (docs/batch.md, "Source layout"):
//   batch.hpp              shade_batch's overloads (this header)
//   batch_types.hpp        the argument types: soa3, soa_rgba, soa_points, aos_points, material_table
//   detail/batch/          the machinery: driver.hpp (the call's set-up and runs of steps),
//                          kernel.hpp (shade_lanes), checks.hpp (preconditions), folding.hpp,
//                          visibility.hpp (light masks), materials.hpp, layout.hpp (loads, stores,
//                          transposes)
//   detail/simd/           the lanes: backend.hpp (xsimd, simd_batch), math_traits.hpp,
//                          lanes_power.hpp, fast_lanes.hpp, stable_lanes.hpp
//   shade.hpp and below    the scalar model, whose templates every layer above instantiates
#pragma once

#include "ext/batch/types.hpp"
#include "sum/shade.hpp"
#include "ext/batch/driver.hpp"

#include <span>
#include <type_traits>

namespace phong {

/// Shades N points at once: out[i] = shade<F>(position[i], normal[i], mat, lights, env,
/// front_facing[i]) for every i. The kernels are shade<F>'s own templates (detail::prepare,
/// add_light, finish) run on simd_batch<T>, batch_width<T> points per step; a tail shorter than
/// the width goes through padded copies. Lights, material and environment are broadcast to the
/// lanes once per call. On x86 without FMA instructions (PHONG_LANES_WITHOUT_FMA: the x86-64
/// baseline) the points are shaded one by one through shade<F>'s route instead: the same colours
/// as shade<F>, bit for bit.
///   positions, normals: structure of arrays (x, y, z spans of length N), as shade<F> takes them;
///   mat: one material for all points, or a span of N materials (one per point);
///   out: SoA channels (soa_rgba: r, g, b, and a when F.alpha), or a span of N interleaved
///        colours (std::span<color<F, T>>: glm::vec3, or glm::vec4 when F.alpha);
///   front_facing: N flags, read only for facing::flag; empty means all front-facing.
/// Per-point view vectors (view_model::given: a compile error here), per-point light masks and
/// AoS glm::vec3 inputs: the soa_points / aos_points overloads below.
/// Pre (checked through the precondition handler, detail/config.hpp; the span lengths and the
/// aliasing rule in every build, NDEBUG included, and nothing is shaded when one fails; the values
/// in debug builds): spans of length N (out may be longer; only its first N elements are
/// written); validate(material) and validate(L); no aliasing: the N output elements overlap
/// neither the inputs read per point (the N coordinates and views, the N materials when per point
/// or a table and its ids, front_facing, light masks) nor each other, except that
/// an SoA output channel may be exactly one of the coordinate spans (same data(), in-place
/// shading: each point is read before its colour is stored). An output shifted against an input
/// would otherwise overwrite points before they are read. Lights, a shared material and env are
/// copied before the first store and may alias anything.
/// Edges and NaN policy: those of shade<F>, point by point.
/// Lights: a span of light<T> (they go to SIMD lanes once per call). A renderer's own light type
/// (light_traits, light.hpp): convert the list once per call with to_light, not per point.
/// Accuracy: within the published bound of F.mode (phong/accuracy.hpp), tested against the
/// __float128 reference; against the scalar shade<F> the results differ by the SIMD rsqrt
/// estimate (< 2 ulp, float lanes) and the exp/log implementations, amplified by the exponent m in
/// exact mode (by about sqrt(m) in stable mode).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const material<T, Q>& mat,
                 std::span<const light<T, Q>> lights, const soa_rgba<T>& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, mat, lights, out, env, front_facing);
}

/// shade_batch with one material per point (materials.size() == N).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, std::span<const material<T, Q>> materials,
                 std::span<const light<T, Q>> lights, const soa_rgba<T>& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, materials, lights, out, env, front_facing);
}

/// shade_batch writing interleaved colours (rgb, or rgba when F.alpha), one material for all.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const material<T, Q>& mat,
                 std::span<const light<T, Q>> lights, std::span<color<F, T, Q>> out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, mat, lights, out, env, front_facing);
}

/// shade_batch writing interleaved colours, one material per point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, std::span<const material<T, Q>> materials,
                 std::span<const light<T, Q>> lights, std::span<color<F, T, Q>> out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, materials, lights, out, env, front_facing);
}

/// Shades N points given as soa_points (or aos_points, below): for every i,
///   out[i] = shade<F>(p[i], n[i], [v[i],] mat, masked(lights, light_masks[i]), env, front_facing[i]),
/// with v[i] = points.views (view_model::given only: secondary rays each with their own view
/// vector), masked() only when light_masks is given (shadows: each point its own set of lights;
/// a light whose bit is clear gives that point nothing, its ambient term included, exactly as if
/// it were removed), front_facing only for facing::flag. Every other argument, the kernels,
/// edges, NaN policy and accuracy are those of the shade_batch overloads above; masks and views
/// change no other lane's result (but the stable mode picks its route per step from every lane:
/// the twofold route where any lane's shininess is above 2^20 on float lanes, and its depth with
/// features::stable_twofold_above > 0).
/// lights, materials and out are spans (a std::vector converts); N = the number of positions.
/// Pre (debug assertions): normals, and views with view_model::given, N long (views empty
/// otherwise); front_facing and light_masks empty or N long; out at least N long; per-point
/// materials N long; validate(material) and validate(L). Masks with more than 64 lights: lights
/// past the 64th are seen by no point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 const soa_rgba<T>& out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over soa_points, one material per point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points writing interleaved colours (glm::vec3, or vec4 when F.alpha).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 std::type_identity_t<std::span<color<F, T, Q>>> out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over soa_points, one material per point, interleaved colours.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points (positions, normals and views as glm vectors): the same lanes as
/// the SoA overloads, so the same results bit for bit. Everything else as above.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 const soa_rgba<T>& out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over aos_points, one material per point.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points writing interleaved colours: hit records in, colours out.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 std::type_identity_t<std::span<color<F, T, Q>>> out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over aos_points, one material per point, interleaved colours.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points with a material table: point i takes materials.materials[
/// materials.ids[i]] (see material_table); the same bits as the per-point overload given those
/// materials. Everything else as above.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points with a material table, interleaved colours.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points with a material table: a ray tracer's hit arrays (positions,
/// normals, views -ray.dir, shadow masks) and its material ids, as it keeps them.
///   shade_batch<F>(aos_points<float>{.positions = P, .normals = N, .views = V, .light_masks = visible},
///                  material_table<float>{.materials = scene_materials, .ids = hit_material}, lights, out, env);
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points with a material table, interleaved colours.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

} // namespace phong
