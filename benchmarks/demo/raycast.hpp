// phong demo: a small ray caster for seed 001's generic primitives, shaded with phong::shade<F>.
// Header-only so that the demo (demo.cpp) and the tests (tests/render.test.cpp) run the same code.
//
// Pipeline per frame (deferred, so the time spent in shading can be measured on its own):
//   1. intersect: for each pixel the primary ray S + t c from the camera (unprojected through
//      inverse(projection * view), so perspective and orthographic cameras are the same code);
//      each object's inverse transform gives the generic ray S' + t c', the nearest generic hit
//      gives t, P = S + t c and the generic normal m' (phong/primitives.hpp), carried to world
//      space by the object's normal matrix (M^{-1})^T (phong/terms/normal.hpp), and a shadow ray toward
//      each light marks which lights reach P: a G-buffer;
//   2. shade: phong::shade<F>(P, m, material, lights, environment) on every G-buffer entry, with
//      only the lights that reach P (a point no light reaches gets exactly the ambient term), and
//      the eye of the environment = inverse(view) * eye_from_projection(projection): the camera
//      position (w = 1) for a perspective camera, the direction toward the viewer (w = 0) for an
//      orthographic one (seed 001's e = ray.start - P, or e = -ray direction).
// SPDX-License-Identifier: MIT
#pragma once

#include <phong/phong.hpp>
#include <phong/primitives.hpp>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <cstddef>
#include <limits>
#include <span>
#include <time.h> // clock_gettime, CLOCK_THREAD_CPUTIME_ID (POSIX)
#include <vector>

namespace phong_demo {

/// Linear light to 8-bit sRGB (the exact sRGB curve, in float), clamped to [0, 1] first: the
/// demo's and the path tracer's pictures.
inline unsigned char to_srgb8(float linear)
{
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(s * 255.0f));
}

/// Seed 001's generic primitives (and a cube).
enum class shape : unsigned char { sphere, plane, square, tapered_cylinder, cube };

/// One object: a generic primitive placed by `transform` (generic -> world coordinates).
struct object {
    shape kind = shape::sphere;
    glm::mat4 transform{1.0f};       ///< M: generic -> world
    glm::mat4 inverse{1.0f};         ///< M^{-1}: world -> generic (the ray's transform)
    glm::mat3 normal_matrix{1.0f};   ///< (M^{-1})^T of the upper 3x3: m = N m'
    float taper = 1.0f;              ///< tapered cylinder: small radius s (radius at z = 1)
    phong::material<float> material{};
};

/// An object with its inverse and normal matrix computed once.
inline object make_object(shape kind, const glm::mat4& transform, const phong::material<float>& mat, float taper = 1.0f)
{
    object o;
    o.kind = kind;
    o.transform = transform;
    o.inverse = glm::inverse(transform);
    o.normal_matrix = phong::normal_matrix(transform);
    o.taper = taper;
    o.material = mat;
    return o;
}

/// Lights in world coordinates, the scene's ambient light, and the colour where no object is hit.
struct scene {
    std::vector<object> objects;
    std::vector<phong::light<float>> lights;
    glm::vec3 ambient{0.0f};
    glm::vec3 background{0.0f};
    bool shadows = true; ///< cast a shadow ray toward each light; occluded lights are left out
};

/// At most this many lights reach shade<F> per point (the visibility mask is a bit field).
inline constexpr std::size_t max_lights = 16;

/// A camera: view (world -> eye) and projection (eye -> clip) matrices and the image size.
struct camera {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    int width = 64;
    int height = 48;
};

/// A ray S + t c (c need not be unit).
struct ray {
    glm::vec3 origin;
    glm::vec3 direction;
};

/// What the intersection pass leaves for the shading pass, per pixel.
struct hit_record {
    int object = -1;          ///< index into scene::objects, -1 for no hit
    float t = 0.0f;           ///< ray time
    glm::vec3 position{0.0f}; ///< P = S + t c, world coordinates
    glm::vec3 normal{0.0f};   ///< m = N m', world coordinates, normalized
    glm::vec3 generic{0.0f};  ///< P' in the object's generic coordinates
    unsigned visible = 0;     ///< bit i set: light i is not occluded (all set without shadows)
};

/// The homogeneous eye in world coordinates: inverse(view) applied to eye_from_projection
/// (w = 1: the camera position; w = 0: the unit direction toward the viewer, orthographic).
inline glm::vec4 world_eye(const camera& cam)
{
    glm::vec4 e = glm::inverse(cam.view) * phong::eye_from_projection(cam.projection);
    if (e.w == 0.0f) {
        const glm::vec3 d = phong::detail::normalize(glm::vec3(e));
        e = glm::vec4(d, 0.0f);
    }
    return e;
}

/// The primary ray through the centre of pixel (x, y) (y = 0 the top row): the points at clip
/// depth -1 (near plane) and +1 (far plane) unprojected, S = near point, c = far - near.
inline ray primary_ray(const camera& cam, const glm::mat4& inverse_view_projection, int x, int y)
{
    const float ndc_x = (2.0f * (float(x) + 0.5f)) / float(cam.width) - 1.0f;
    const float ndc_y = 1.0f - (2.0f * (float(y) + 0.5f)) / float(cam.height);
    const glm::vec4 near = inverse_view_projection * glm::vec4(ndc_x, ndc_y, -1.0f, 1.0f);
    const glm::vec4 far = inverse_view_projection * glm::vec4(ndc_x, ndc_y, 1.0f, 1.0f);
    const glm::vec3 n = glm::vec3(near) / near.w, f = glm::vec3(far) / far.w;
    return {n, f - n};
}

/// The pixel (column, row; row 0 at the top) a world point projects to, as real coordinates
/// whose integer parts name the pixel (the inverse of primary_ray's pixel centres).
inline glm::vec2 project_to_pixel(const camera& cam, const glm::vec3& world)
{
    const glm::vec4 clip = cam.projection * cam.view * glm::vec4(world, 1.0f);
    const float ndc_x = clip.x / clip.w, ndc_y = clip.y / clip.w;
    return {(ndc_x + 1.0f) * 0.5f * float(cam.width), (1.0f - ndc_y) * 0.5f * float(cam.height)};
}

/// The nearest hit of the ray with the scene's objects after t_min (object -1 for none).
inline hit_record trace(const scene& sc, const ray& r, float t_min = 1e-4f)
{
    hit_record best;
    float best_t = std::numeric_limits<float>::infinity();
    for (std::size_t i = 0; i < sc.objects.size(); ++i) {
        const object& o = sc.objects[i];
        // The generic ray: S' = M^{-1} S (a point), c' = M^{-1} c (a direction); same t.
        const glm::vec3 S(o.inverse * glm::vec4(r.origin, 1.0f));
        const glm::vec3 c(o.inverse * glm::vec4(r.direction, 0.0f));
        phong::ray_hit<float> h;
        switch (o.kind) {
        case shape::sphere: h = phong::ray_sphere(S, c, t_min); break;
        case shape::plane: h = phong::ray_plane(S, c, t_min); break;
        case shape::square: h = phong::ray_square(S, c, t_min); break;
        case shape::tapered_cylinder: h = phong::ray_tapered_cylinder(S, c, o.taper, t_min); break;
        case shape::cube: h = phong::ray_cube(S, c, t_min); break;
        }
        if (!h || !(h.t < best_t)) continue;
        best_t = h.t;
        const glm::vec3 Pg = S + h.t * c; // P' = it_ray(hit_time)
        glm::vec3 mg(0.0f);               // m', the generic normal
        switch (o.kind) {
        case shape::sphere: mg = phong::sphere_normal(Pg); break;
        case shape::plane: mg = phong::plane_normal(Pg); break;
        case shape::square: mg = phong::square_normal(Pg); break;
        case shape::tapered_cylinder: mg = phong::tapered_cylinder_normal(Pg, o.taper, h.part); break;
        case shape::cube: mg = phong::cube_normal(Pg); break;
        }
        best.object = int(i);
        best.t = h.t;
        best.position = r.origin + h.t * r.direction; // P = ray(hit_time)
        best.normal = phong::transform_normal(o.normal_matrix, mg); // m = (M^{-1})^T m', normalized
        best.generic = Pg;
    }
    return best;
}

/// Whether an object blocks the segment S + t c, t_min < t < t_max.
inline bool occluded(const scene& sc, const ray& r, float t_min, float t_max)
{
    const hit_record h = trace(sc, r, t_min);
    return h.object >= 0 && h.t < t_max;
}

/// Which lights reach P: a shadow ray toward each, P + t (L.xyz - L.w P), blocked when an object
/// lies at 1e-3 < t < 1 (positional: up to the light) or t > 1e-3 (directional, w = 0).
inline unsigned visible_lights(const scene& sc, const glm::vec3& P)
{
    unsigned mask = 0;
    for (std::size_t i = 0; i < sc.lights.size() && i < max_lights; ++i) {
        const glm::vec4& L = sc.lights[i].position;
        const ray shadow{P, glm::vec3(L) - L.w * P};
        const float t_max = L.w > 0.0f ? 1.0f : std::numeric_limits<float>::infinity();
        if (!sc.shadows || !occluded(sc, shadow, 1e-3f, t_max)) mask |= 1u << i;
    }
    return mask;
}

/// A linear-light RGB image, row 0 at the top.
struct image {
    int width = 0, height = 0;
    std::vector<glm::vec3> pixels;
    glm::vec3& at(int x, int y) { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    const glm::vec3& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

/// The intersection pass: one hit record per pixel, with its shadow rays.
inline void intersect(const scene& sc, const camera& cam, std::vector<hit_record>& gbuffer)
{
    gbuffer.resize(std::size_t(cam.width) * std::size_t(cam.height));
    const glm::mat4 inverse_view_projection = glm::inverse(cam.projection * cam.view);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            hit_record h = trace(sc, primary_ray(cam, inverse_view_projection, x, y));
            if (h.object >= 0) h.visible = visible_lights(sc, h.position);
            gbuffer[std::size_t(y) * std::size_t(cam.width) + std::size_t(x)] = h;
        }
}

/// The frame's environment: the scene's ambient light and the eye (world_eye).
inline phong::environment<float> frame_environment(const scene& sc, const camera& cam)
{
    return {.ambient = sc.ambient, .eye = world_eye(cam)};
}

/// The shading pass: phong::shade<F> at every hit with the lights that reach it, the background
/// elsewhere; env: frame_environment(sc, cam).
template <phong::features F>
void shade_pass(const scene& sc, const camera& cam, const phong::environment<float>& env, const std::vector<hit_record>& gbuffer,
                image& out)
{
    out.width = cam.width;
    out.height = cam.height;
    out.pixels.resize(gbuffer.size());
    const std::size_t count = std::min(sc.lights.size(), max_lights);
    const unsigned all = (1u << count) - 1u; // count <= max_lights = 16
    std::array<phong::light<float>, max_lights> subset{};
    for (std::size_t i = 0; i < gbuffer.size(); ++i) {
        const hit_record& h = gbuffer[i];
        if (h.object < 0) {
            out.pixels[i] = sc.background;
            continue;
        }
        std::span<const phong::light<float>> lights(sc.lights.data(), count);
        if (h.visible != all) { // some lights are in shadow: shade with the others
            std::size_t n = 0;
            for (std::size_t k = 0; k < count; ++k)
                if (h.visible & (1u << k)) subset[n++] = sc.lights[k];
            lights = std::span<const phong::light<float>>(subset.data(), n);
        }
        const auto c = phong::shade<F>(h.position, h.normal, sc.objects[std::size_t(h.object)].material, lights, env);
        out.pixels[i] = glm::vec3(c.x, c.y, c.z);
    }
}
template <phong::features F>
void shade_pass(const scene& sc, const camera& cam, const std::vector<hit_record>& gbuffer, image& out)
{
    shade_pass<F>(sc, cam, frame_environment(sc, cam), gbuffer, out);
}

/// Seconds spent in each pass of one frame: wall-clock time, and the CPU time of the rendering
/// thread (the renderer is single-threaded; on a machine shared with other jobs the CPU time is
/// the steadier figure, as time spent descheduled is not counted).
struct frame_time {
    double intersect = 0.0, shade = 0.0;         ///< wall clock
    double intersect_cpu = 0.0, shade_cpu = 0.0; ///< thread CPU time (= wall clock where unavailable)
    double total() const { return intersect + shade; }
    double total_cpu() const { return intersect_cpu + shade_cpu; }
};

/// The calling thread's CPU time in seconds (POSIX CLOCK_THREAD_CPUTIME_ID), or the steady clock
/// where that clock does not exist.
inline double thread_seconds()
{
#if defined(CLOCK_THREAD_CPUTIME_ID)
    timespec ts{};
    if (clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts) == 0) return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
#endif
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

/// Renders one frame: the intersection pass, then shading with features F.
template <phong::features F>
frame_time render(const scene& sc, const camera& cam, image& out, std::vector<hit_record>& gbuffer)
{
    using clock = std::chrono::steady_clock;
    const auto t0 = clock::now();
    const double c0 = thread_seconds();
    intersect(sc, cam, gbuffer);
    const auto t1 = clock::now();
    const double c1 = thread_seconds();
    shade_pass<F>(sc, cam, gbuffer, out);
    const auto t2 = clock::now();
    const double c2 = thread_seconds();
    return {std::chrono::duration<double>(t1 - t0).count(), std::chrono::duration<double>(t2 - t1).count(), c1 - c0, c2 - c1};
}

/// The demo's lighting: ambient, diffuse, specular (reflection- or halfway-based, gated on n.l > 0
/// as in seed 003), any light kind (w = 1 positional, w = 0 directional), OpenGL polynomial
/// attenuation and spot cones, two-sided by the view vector (a square or plane seen from behind
/// is lit as its front), the eye as a homogeneous point (perspective or orthographic).
inline constexpr phong::features lighting(phong::specular_model specular)
{
    return phong::features{.scene_ambient = true, .light_ambient = false, .diffuse = true, .specular = specular,
                           .specular_gate = true, .lights = phong::light_kind::any,
                           .attenuation = phong::attenuation_model::polynomial, .spot = phong::spot_model::opengl,
                           .attenuate_ambient = true, .two_sided = phong::facing::view,
                           .view = phong::view_model::eye_point, .emission = false, .alpha = false,
                           .mode = phong::evaluation::exact};
}

inline constexpr phong::features phong_lighting = lighting(phong::specular_model::phong);
inline constexpr phong::features blinn_lighting = lighting(phong::specular_model::blinn);

/// The demo's scene, world coordinates with y up: a floor (the generic plane), an ellipsoid (the
/// generic sphere under a non-uniform scale and a tilt), a tapered cylinder with base and cap, a
/// two-sided square seen from its back, and a cube; lit by a positional light, a directional
/// light and a spot light, the positional ones attenuated.
inline scene demo_scene()
{
    using glm::mat4;
    using glm::vec3;
    const auto translate = [](vec3 t) { return glm::translate(mat4(1.0f), t); };
    const auto rotate = [](float degrees, vec3 axis) { return glm::rotate(mat4(1.0f), glm::radians(degrees), axis); };
    const auto scale = [](vec3 s) { return glm::scale(mat4(1.0f), s); };
    const mat4 z_up_to_y_up = rotate(-90.0f, {1, 0, 0}); // generic z axis -> world y axis

    const auto mat = [](vec3 kd, vec3 ks, float m) {
        return phong::material<float>{.ka = kd, .kd = kd, .ks = ks, .emission = vec3(0.0f), .shininess = m, .alpha = 1.0f};
    };
    scene sc;
    sc.objects.push_back(make_object(shape::plane, z_up_to_y_up, mat({0.32f, 0.33f, 0.36f}, vec3(0.1f), 8.0f)));
    sc.objects.push_back(make_object(shape::sphere,
                                     translate({-1.35f, 0.95f, 0.2f}) * rotate(-25.0f, {0, 0, 1}) * scale({0.62f, 0.95f, 0.62f}),
                                     mat({0.7f, 0.1f, 0.08f}, vec3(0.9f), 50.0f)));
    sc.objects.push_back(make_object(shape::tapered_cylinder,
                                     translate({1.25f, 0.0f, 0.35f}) * z_up_to_y_up * scale({0.65f, 0.65f, 1.7f}),
                                     mat({0.8f, 0.6f, 0.15f}, vec3(0.6f), 25.0f), 0.4f));
    sc.objects.push_back(make_object(shape::square,
                                     translate({0.0f, 1.25f, -1.8f}) * rotate(200.0f, {0, 1, 0}) * scale({1.3f, 1.0f, 1.0f}),
                                     mat({0.15f, 0.6f, 0.25f}, vec3(0.5f), 60.0f)));
    sc.objects.push_back(make_object(shape::cube,
                                     translate({0.05f, 0.33f, 1.35f}) * rotate(35.0f, {0, 1, 0}) * scale(vec3(0.33f)),
                                     mat({0.2f, 0.3f, 0.8f}, vec3(0.6f), 80.0f)));

    phong::light<float> key; // positional, warm, attenuated
    key.position = {3.0f, 4.0f, 3.5f, 1.0f};
    key.diffuse = key.specular = {1.7f, 1.55f, 1.35f};
    key.attenuation = {.constant = 1.0f, .linear = 0.05f, .quadratic = 0.02f};
    phong::light<float> sky; // directional, cool and dim (w = 0: no attenuation)
    sky.position = {-1.0f, 0.8f, 0.5f, 0.0f};
    sky.diffuse = sky.specular = {0.22f, 0.27f, 0.4f};
    phong::light<float> spot; // a spot from above onto the ellipsoid
    spot.position = {-1.0f, 5.0f, 2.5f, 1.0f};
    spot.diffuse = spot.specular = {1.2f, 1.2f, 1.3f};
    spot.attenuation = {.constant = 1.0f, .linear = 0.0f, .quadratic = 0.01f};
    spot.spot = phong::spot_cone<float>::opengl(vec3(-1.4f, 0.0f, 0.2f) - vec3(-1.0f, 5.0f, 2.5f), 4.0f, 16.0f);
    sc.lights = {key, sky, spot};
    sc.ambient = vec3(0.12f);
    sc.background = {0.02f, 0.02f, 0.03f};
    return sc;
}

/// The demo's view (world -> eye), looking at the scene from the front and above.
inline glm::mat4 demo_view()
{
    return glm::lookAt(glm::vec3(0.0f, 2.8f, 6.5f), glm::vec3(0.0f, 0.75f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

/// Perspective (40 degree vertical field of view) or orthographic camera of the same view,
/// framing about the same part of the scene.
inline camera demo_camera(bool perspective, int width, int height)
{
    const float aspect = float(width) / float(height);
    camera cam;
    cam.view = demo_view();
    cam.width = width;
    cam.height = height;
    if (perspective) cam.projection = glm::perspective(glm::radians(40.0f), aspect, 0.1f, 50.0f);
    else cam.projection = glm::ortho(-2.7f * aspect, 2.7f * aspect, -2.7f, 2.7f, 0.1f, 50.0f);
    return cam;
}

} // namespace phong_demo
