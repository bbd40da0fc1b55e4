// phong end-to-end renderers: EVERY call into phong made by whitted.cpp and raster.cpp, in a few
// small functions, so that they can be switched to new API options in one place. The renderers
// themselves only see glm types, their own light and material structs, and these functions.
//
// How the ray tracer calls phong (the renderer-facing API):
//  * shade<F> with view_model::given takes v = -ray.dir itself, right for primary, reflected and
//    refracted rays; features::unit_inputs says that n and v are unit already (no normalization);
//  * the tracer's own light type goes to phong as it is, through a phong::light_traits
//    specialization (whitted.cpp, next to the type): no phong::light<float> built per hit;
//  * the per-hit shadow mask is passed with the whole light list, masked(lights, visible): no
//    per-hit copy of the visible lights;
//  * shade_batch<F> takes the hit arrays as they are (aos_points: glm::vec3 positions, normals and
//    view vectors -ray.dir, one shadow mask per point) and the material ids with the scene's
//    material table (material_table): one call for all primary hits.
// The rasterizer's per-pixel normal is interpolated, not unit: it keeps the normalizing path.
// The per-point wrappers below are PHONG_INLINE, as phong's own functions: a renderer's shading
// loop then holds the whole lighting computation. Left to clang++ 14, shade_phong_screen stayed
// out of line and cost a constant 15 to 19 ns more per fragment (docs/demo.md).
// SPDX-License-Identifier: MIT
#pragma once

#include <phong/batch.hpp>
#include <phong/phong.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace phong_calls {

// ---- Whitted ray tracer ---------------------------------------------------------------------

/// The ray tracer's lighting: ka La + sum over visible lights of L (kd max(n.l, 0) + ks max(r.v, 0)^m),
/// r = reflect(-l, n), positional lights, no gate (as the inline code), no attenuation, v given
/// per call and, with n, unit already: presets::raytracer_phong without its gate, unit inputs.
inline constexpr phong::features whitted_exact = [] {
    phong::features f = phong::presets::raytracer_phong;
    f.specular_gate = false;
    f.unit_inputs = true;
    return f;
}();
inline constexpr phong::features whitted_stable = phong::presets::with_mode(whitted_exact, phong::evaluation::stable);


inline constexpr std::size_t max_lights = 4;

/// A light for phong: positional, one colour for diffuse and specular, no ambient.
inline phong::light<float> make_light(const glm::vec3& position, const glm::vec3& colour)
{
    phong::light<float> L;
    L.position = glm::vec4(position, 1.0f);
    L.ambient = glm::vec3(0.0f);
    L.diffuse = colour;
    L.specular = colour;
    return L;
}

inline phong::material<float> make_material(const glm::vec3& ka, const glm::vec3& kd, const glm::vec3& ks, float shininess)
{
    return {.ka = ka, .kd = kd, .ks = ks, .emission = glm::vec3(0.0f), .shininess = shininess, .alpha = 1.0f};
}

/// One hit, scalar shade<F>: v = -ray.dir given, the lights seen from the hit by the bits of
/// `visible` (bit i: lights[i] not in shadow), nothing copied per hit. Light: the renderer's own
/// light type (with a phong::light_traits specialization) or phong::light<float>.
template <phong::features F, phong::light_source Light>
PHONG_INLINE glm::vec3 shade_phong_scalar(const glm::vec3& P, const glm::vec3& n, const glm::vec3& v, unsigned visible,
                                    std::span<const Light> lights, const phong::material<float>& mat,
                                    const glm::vec3& ambient)
{
    const phong::environment<float> env{.ambient = ambient};
    return phong::shade<F>(P, n, v, mat, phong::masked(lights, visible), env);
}

/// One hit with what the tracer has already (shade_incident): the shadow rays' unit directions
/// and distances (shadow[i] for lights[i]), unit n and v = -ray.dir; no position.
template <phong::features F, phong::light_source Light>
PHONG_INLINE glm::vec3 shade_phong_incident(const glm::vec3& n, const glm::vec3& v, unsigned visible, std::span<const Light> lights,
                                      const phong::incident<float>* shadow, const phong::material<float>& mat, const glm::vec3& ambient)
{
    const phong::environment<float> env{.ambient = ambient};
    return phong::shade_incident<F>(n, v, mat, phong::masked(lights, visible), std::span<const phong::incident<float>>(shadow, lights.size()),
                                    env);
}

/// Scratch arrays of shade_phong_fragments_batch, kept between calls.
struct batch_scratch {
    std::vector<float> px, py, pz, nx, ny, nz; ///< SoA positions and normals (rasterizer)
    std::vector<float> r, g, b;                ///< SoA colours (rasterizer)
};

/// Primary hits, shade_batch<F> on the hit arrays as the tracer keeps them (AoS glm::vec3), each
/// point with its own view vector (-ray.dir), shadow mask and material id into the scene's
/// material table (material_table): one call, no point copied or repacked (all of it timed).
/// shade_batch takes phong::light<float>: the renderer's lights are converted once per call
/// (phong::to_light, through their light_traits), not per hit.
template <phong::features F, phong::light_source Light>
inline void shade_phong_batch(std::span<const glm::vec3> P, std::span<const glm::vec3> n, std::span<const glm::vec3> v,
                              std::span<const std::uint64_t> visible, std::span<const std::uint32_t> material_id,
                              std::span<const phong::material<float>> materials, std::span<const Light> lights,
                              const glm::vec3& ambient, std::span<glm::vec3> out)
{
    const phong::environment<float> env{.ambient = ambient};
    std::array<phong::light<float>, max_lights> converted;
    for (std::size_t i = 0; i < lights.size() && i < max_lights; ++i) converted[i] = phong::to_light(lights[i]);
    phong::shade_batch<F>(phong::aos_points<float>{.positions = P, .normals = n, .views = v, .light_masks = visible},
                          phong::material_table<float>{.materials = materials, .ids = material_id},
                          std::span<const phong::light<float>>(converted.data(), std::min(lights.size(), max_lights)), out, env);
}

// ---- Software rasterizer --------------------------------------------------------------------

/// Seed 003's GLSL ADS (phong.vert): La Ka + Ld Kd max(s.n, 0) + [s.n > 0] Ls Ks max(r.v, 0)^f,
/// eye coordinates, v = normalize(-eyeCoords).
inline constexpr phong::features raster_exact = phong::presets::glsl_ads;
inline constexpr phong::features raster_stable = phong::presets::with_mode(raster_exact, phong::evaluation::stable);

/// A seed 003 light in eye coordinates (La, Ld, Ls).
inline phong::light<float> make_ads_light(const glm::vec3& eye_position, const glm::vec3& La, const glm::vec3& Ld, const glm::vec3& Ls)
{
    phong::light<float> L;
    L.position = glm::vec4(eye_position, 1.0f);
    L.ambient = La;
    L.diffuse = Ld;
    L.specular = Ls;
    return L;
}

/// NormalMatrix of seed 003.
inline glm::mat3 normal_matrix(const glm::mat4& model_view) { return phong::normal_matrix(model_view); }

/// One vertex through seed 003's pipeline: shade_vertex<F> (object-space position and normal).
template <phong::features F>
PHONG_INLINE glm::vec3 shade_phong_vertex(const glm::vec3& p, const glm::vec3& n, const glm::mat4& model_view, const glm::mat3& normal_mat,
                                    const phong::material<float>& mat, std::span<const phong::light<float>> lights)
{
    return phong::shade_vertex<F>(p, n, model_view, normal_mat, mat, lights);
}

/// One fragment: shade<F> on the interpolated eye-space position and (not unit) normal.
template <phong::features F>
PHONG_INLINE glm::vec3 shade_phong_fragment(const glm::vec3& eye_position, const glm::vec3& normal, const phong::material<float>& mat,
                                      std::span<const phong::light<float>> lights)
{
    return phong::shade<F>(eye_position, normal, mat, lights);
}

/// Every fragment at once: packed into SoA arrays, shade_batch<F>, colours scattered back (timed).
template <phong::features F>
inline void shade_phong_fragments_batch(std::span<const glm::vec3> P, std::span<const glm::vec3> n, const phong::material<float>& mat,
                                        std::span<const phong::light<float>> lights, std::span<glm::vec3> out, batch_scratch& s)
{
    const std::size_t N = P.size();
    for (auto* v : {&s.px, &s.py, &s.pz, &s.nx, &s.ny, &s.nz, &s.r, &s.g, &s.b}) v->resize(N);
    for (std::size_t i = 0; i < N; ++i) {
        s.px[i] = P[i].x, s.py[i] = P[i].y, s.pz[i] = P[i].z;
        s.nx[i] = n[i].x, s.ny[i] = n[i].y, s.nz[i] = n[i].z;
    }
    const auto in = [](const std::vector<float>& v) { return std::span<const float>(v); };
    phong::shade_batch<F>(phong::soa3<float>{in(s.px), in(s.py), in(s.pz)}, phong::soa3<float>{in(s.nx), in(s.ny), in(s.nz)}, mat, lights,
                          phong::soa_rgba<float>{std::span<float>(s.r), std::span<float>(s.g), std::span<float>(s.b), {}});
    for (std::size_t i = 0; i < N; ++i) out[i] = glm::vec3(s.r[i], s.g[i], s.b[i]);
}

// ---- Screen-space rasterizer (issue 27) ------------------------------------------------------

/// The screen-space model of a software rasterizer: ambient kd + sum over directional lights of
/// colour (kd max(n.l, 0) + ks max(r.v, 0)^e), the view along +z (fixed_direction, environment::eye
/// = (0, 0, 1, 0), used as given: unit_inputs), no specular gate (as the inline code), n unit.
inline constexpr phong::features screen_exact{
    .scene_ambient = true, .light_ambient = false, .diffuse = true, .specular = phong::specular_model::phong,
    .specular_gate = false, .lights = phong::light_kind::directional, .view = phong::view_model::fixed_direction,
    .unit_inputs = true};
inline constexpr phong::features screen_stable = phong::presets::with_mode(screen_exact, phong::evaluation::stable);

/// A directional light for phong: w = 0, one colour for diffuse and specular, no ambient.
inline phong::light<float> make_light_directional(const glm::vec3& direction, const glm::vec3& colour)
{
    phong::light<float> L = make_light(direction, colour);
    L.position.w = 0.0f;
    return L;
}

/// One fragment in screen space: the texture maps' kd, ks and exponent as a phong::surface (ka = kd:
/// the scene ambient times kd), the lights' directions given (incidents, the same for every fragment),
/// no position.
template <phong::features F>
PHONG_INLINE glm::vec3 shade_phong_screen(const glm::vec3& n, const glm::vec3& kd, const glm::vec3& ks, float exponent,
                                    std::span<const phong::light<float>> lights, std::span<const phong::incident<float>> incidents,
                                    float ambient)
{
    const phong::environment<float> env{.ambient = glm::vec3(ambient), .eye = glm::vec4(0.0f, 0.0f, 1.0f, 0.0f)};
    return phong::shade_incident<F>(n, phong::surface<float>{.ka = kd, .kd = kd, .ks = ks, .shininess = exponent}, lights, incidents, env);
}

} // namespace phong_calls
