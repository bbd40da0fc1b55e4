// Tests for the demo renderer (benchmarks/demo/raycast.hpp): small images rendered through the same
// code as the demo, checked for what a person would see.
//  * The highlight of a sphere (and of an ellipsoid: non-uniform scale, so the normal matrix
//    matters) lies where r = v, equivalently n = h, predicts: computed analytically here.
//  * Points no light reaches (outside a spot cone, facing away, in shadow) get exactly the
//    ambient term ka La.
//  * The back of a two-sided square is lit as its front when the scene is mirrored through the
//    square's plane; without two-sided lighting it gets only the ambient term.
#include "support/numeric.hpp"

#include "raycast.hpp"

#include <doctest/doctest.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <cmath>
#include <set>

namespace {

using namespace phong_demo;
using glm::mat4;
using glm::vec3;
using glm::vec4;

constexpr float eps = std::numeric_limits<float>::epsilon();

/// The pixel with the largest red value (first one on ties).
glm::ivec2 brightest(const image& img)
{
    glm::ivec2 best(0);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            if (img.at(x, y).r > img.at(best.x, best.y).r) best = {x, y};
    return best;
}

/// Chebyshev distance between the centre of pixel p and the real pixel coordinates q.
float pixel_distance(glm::ivec2 p, glm::vec2 q)
{
    return std::max(std::abs(float(p.x) + 0.5f - q.x), std::abs(float(p.y) + 0.5f - q.y));
}

/// A specular-only material (ka = kd = 0), so the image is the highlight alone.
phong::material<float> specular_only(float m)
{
    return {.ka = vec3(0.0f), .kd = vec3(0.0f), .ks = vec3(1.0f), .emission = vec3(0.0f), .shininess = m, .alpha = 1.0f};
}

template <phong::features F> image render_image(const scene& sc, const camera& cam, std::vector<hit_record>& gbuffer)
{
    image img;
    render<F>(sc, cam, img, gbuffer);
    return img;
}

template <phong::features F> image render_image(const scene& sc, const camera& cam)
{
    std::vector<hit_record> gbuffer;
    return render_image<F>(sc, cam, gbuffer);
}

} // namespace

TEST_CASE("render: the eye comes from the projection matrix (perspective: a point, orthographic: a direction)")
{
    camera cam;
    cam.view = glm::lookAt(vec3(1, 2, 6), vec3(0, 0.5f, 0), vec3(0, 1, 0));
    cam.projection = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 100.0f);
    const vec4 e = world_eye(cam);
    CHECK(e.w == 1.0f);
    CHECK(phong_test::approx_equal(vec3(e), vec3(1, 2, 6), 64 * eps));
    cam.projection = glm::ortho(-2.0f, 2.0f, -1.5f, 1.5f, 0.1f, 100.0f);
    const vec4 d = world_eye(cam);
    CHECK(d.w == 0.0f);
    CHECK(phong_test::approx_equal(vec3(d), glm::normalize(vec3(1, 1.5f, 6)), 64 * eps));
    // Every primary ray of the orthographic camera runs along -d (seed 001: e = -ray direction).
    const ray r = primary_ray(cam, glm::inverse(cam.projection * cam.view), 3, 7);
    CHECK(phong_test::approx_equal(-glm::normalize(r.direction), vec3(d), 64 * eps));
}

TEST_CASE("render: the highlight of an ellipsoid lies where n = h (orthographic camera, directional light)")
{
    // Ellipsoid X = C + A p', |p'| = 1, A = rotation * diag(1.3, 0.7, 0.9). Its normal at X is
    // A^{-T} p'; it equals h where p' is along A^T h. With a directional light l and an
    // orthographic eye direction v, h = normalize(l + v) is the same at every point, so the peak
    // of max(n.h, 0)^m is at X* = C + A (A^T h / |A^T h|). Phong's r = v holds at the same point
    // (r = v iff n is along l + v), so both models must peak there.
    const mat4 A = glm::rotate(mat4(1.0f), glm::radians(30.0f), glm::normalize(vec3(1, 2, 0.5f))) *
                   glm::scale(mat4(1.0f), vec3(1.3f, 0.7f, 0.9f));
    const vec3 C(0.2f, -0.1f, 0.0f);
    scene sc;
    sc.objects.push_back(make_object(shape::sphere, glm::translate(mat4(1.0f), C) * A, specular_only(400.0f)));
    phong::light<float> sun;
    sun.position = vec4(glm::normalize(vec3(0.6f, 0.8f, 1.0f)), 0.0f);
    sc.lights = {sun};
    sc.shadows = false;

    camera cam;
    cam.view = glm::lookAt(vec3(0.5f, 0.3f, 8), vec3(0), vec3(0, 1, 0));
    cam.projection = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, 0.1f, 100.0f);
    cam.width = cam.height = 160;

    const vec3 v = vec3(world_eye(cam));
    const vec3 h = glm::normalize(vec3(sun.position) + v);
    const glm::mat3 A3(A);
    const vec3 X = C + A3 * glm::normalize(glm::transpose(A3) * h);
    const glm::vec2 predicted = project_to_pixel(cam, X);
    REQUIRE(predicted.x > 10);
    REQUIRE(predicted.x < 150);

    const image phong_img = render_image<phong_lighting>(sc, cam);
    const image blinn_img = render_image<blinn_lighting>(sc, cam);
    CHECK(pixel_distance(brightest(phong_img), predicted) <= 1.0f);
    CHECK(pixel_distance(brightest(blinn_img), predicted) <= 1.0f);
    // The peak is the full highlight ks Ls = 1 (up to the pixel's offset from X*).
    const glm::ivec2 b = brightest(blinn_img);
    CHECK(blinn_img.at(b.x, b.y).r > 0.9f);
    CHECK(blinn_img.at(b.x, b.y).r <= 1.0f + 8 * eps);

    // The normal matrix matters: carrying the normal by A itself (seed 001's m = M m' taken
    // literally) would put the peak where A p' is along h, visibly elsewhere.
    const vec3 wrong = C + A3 * glm::normalize(glm::inverse(A3) * h);
    CHECK(pixel_distance(brightest(blinn_img), project_to_pixel(cam, wrong)) > 4.0f);
}

TEST_CASE("render: the highlight of a sphere lit from the eye faces the eye (perspective camera)")
{
    // A positional light at the eye E: l = v at every point, so r = v and n = h both mean n = v:
    // the peak is the sphere point nearest the eye, X* = C + R normalize(E - C).
    const vec3 E(1.5f, 1.0f, 5.0f), C(-0.4f, 0.3f, 0.0f);
    const float R = 0.9f;
    scene sc;
    sc.objects.push_back(make_object(shape::sphere, glm::translate(mat4(1.0f), C) * glm::scale(mat4(1.0f), vec3(R)),
                                     specular_only(300.0f)));
    phong::light<float> lamp;
    lamp.position = vec4(E, 1.0f);
    sc.lights = {lamp};
    sc.shadows = false;
    camera cam;
    cam.view = glm::lookAt(E, vec3(0), vec3(0, 1, 0));
    cam.projection = glm::perspective(glm::radians(35.0f), 1.0f, 0.1f, 100.0f);
    cam.width = cam.height = 160;

    const glm::vec2 predicted = project_to_pixel(cam, C + R * glm::normalize(E - C));
    CHECK(pixel_distance(brightest(render_image<phong_lighting>(sc, cam)), predicted) <= 1.0f);
    CHECK(pixel_distance(brightest(render_image<blinn_lighting>(sc, cam)), predicted) <= 1.0f);
}

TEST_CASE("render: points no light reaches get exactly the ambient term")
{
    // A floor lit by one spot from above (cutoff 20 degrees) and a directional light from below
    // (the floor faces the camera above it, so that light is behind it everywhere), with a sphere
    // in the cone casting a shadow. Outside the cone or in the shadow: exactly ka La. Inside the
    // cone and not shadowed: more, in every channel.
    const vec3 ka(0.2f, 0.3f, 0.4f), La(0.5f, 0.25f, 0.125f);
    const phong::material<float> floor_mat{.ka = ka, .kd = vec3(0.6f), .ks = vec3(0.3f), .emission = vec3(0.0f),
                                           .shininess = 20.0f, .alpha = 1.0f};
    const vec3 S(0.0f, 0.0f, 0.0f), sphere_c(0.0f, 1.5f, 0.2f);
    const float sphere_r = 0.4f;
    scene sc;
    sc.objects.push_back(make_object(shape::plane, glm::rotate(mat4(1.0f), glm::radians(-90.0f), vec3(1, 0, 0)), floor_mat));
    sc.objects.push_back(make_object(shape::sphere, glm::translate(mat4(1.0f), sphere_c) * glm::scale(mat4(1.0f), vec3(sphere_r)),
                                     floor_mat));
    const vec3 spot_pos(0.0f, 4.0f, 0.5f);
    const float cutoff = 20.0f;
    phong::light<float> spot;
    spot.position = vec4(spot_pos, 1.0f);
    spot.attenuation = {.constant = 1.0f, .linear = 0.1f, .quadratic = 0.02f};
    spot.spot = phong::spot_cone<float>::opengl(S - spot_pos, 2.0f, cutoff);
    phong::light<float> under;
    under.position = vec4(0.3f, -1.0f, 0.2f, 0.0f);
    sc.lights = {spot, under};
    sc.ambient = La;
    sc.background = vec3(-1.0f); // no hit: recognisable

    camera cam;
    cam.view = glm::lookAt(vec3(0.0f, 6.0f, 6.0f), vec3(0.0f, 0.0f, 0.0f), vec3(0, 1, 0));
    cam.projection = glm::perspective(glm::radians(50.0f), 1.0f, 0.1f, 100.0f);
    cam.width = cam.height = 96;

    std::vector<hit_record> gbuffer;
    const image img = render_image<blinn_lighting>(sc, cam, gbuffer);
    const vec3 ambient = ka * La;
    const glm::dvec3 axis = glm::normalize(glm::dvec3(S - spot_pos));
    const double cos_cut = std::cos(glm::radians(double(cutoff)));
    int outside = 0, shadowed = 0, lit = 0;
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            const hit_record& h = gbuffer[std::size_t(y * cam.width + x)];
            if (h.object != 0) continue; // the floor only
            const glm::dvec3 P(h.position), L(spot_pos);
            const glm::dvec3 to_point = glm::normalize(P - L);
            const double c = glm::dot(to_point, axis);
            // Shadow: the segment P -> L passes through the sphere (distance from its centre < r).
            const glm::dvec3 Cd(sphere_c), d = L - P;
            const double t = std::clamp(glm::dot(Cd - P, d) / glm::dot(d, d), 0.0, 1.0);
            const double dist = glm::length(P + t * d - Cd);
            const vec3 px = img.at(x, y);
            if (c < cos_cut - 0.01) {
                ++outside;
                CHECK(px == ambient);
            } else if (dist < double(sphere_r) - 0.02) {
                ++shadowed;
                CHECK(px == ambient);
            } else if (c > cos_cut + 0.01 && dist > double(sphere_r) + 0.02) {
                ++lit;
                CHECK(px.r > ambient.r);
                CHECK(px.g > ambient.g);
                CHECK(px.b > ambient.b);
            }
        }
    // The scene really has all three kinds of floor point.
    CHECK(outside > 500);
    CHECK(shadowed > 20);
    CHECK(lit > 200);
}

TEST_CASE("render: the back of a two-sided square is lit as its front when mirrored")
{
    // Scene A: the square in z = 0 (scaled and turned about z, which commutes with the mirror
    // S = diag(1, 1, -1)), camera and lights on its front (+z) side. Scene B: the lights mirrored
    // by S and the camera too (view_B = view_A S), so the camera sees the square's back, where the
    // generic normal (0, 0, 1) points away from it. Every vector of B is S times A's, so with
    // two-sided lighting (the normal negated toward the viewer) every dot product, and so every
    // pixel, is the same up to rounding.
    const mat4 square_m = glm::rotate(mat4(1.0f), glm::radians(20.0f), vec3(0, 0, 1)) * glm::scale(mat4(1.0f), vec3(1.5f, 1.0f, 1.0f));
    const mat4 S = glm::scale(mat4(1.0f), vec3(1.0f, 1.0f, -1.0f));
    const phong::material<float> mat{.ka = vec3(0.2f, 0.25f, 0.3f), .kd = vec3(0.7f, 0.5f, 0.3f), .ks = vec3(0.5f),
                                     .emission = vec3(0.0f), .shininess = 30.0f, .alpha = 1.0f};
    phong::light<float> lamp;
    lamp.position = vec4(1.0f, 1.5f, 2.5f, 1.0f);
    lamp.attenuation = {.constant = 1.0f, .linear = 0.1f, .quadratic = 0.05f};
    phong::light<float> sun;
    sun.position = vec4(-0.5f, 0.3f, 1.0f, 0.0f);
    sun.diffuse = sun.specular = vec3(0.4f);

    scene a;
    a.objects.push_back(make_object(shape::square, square_m, mat));
    a.lights = {lamp, sun};
    a.ambient = vec3(0.3f);
    scene b = a;
    for (phong::light<float>& L : b.lights) L.position = S * L.position;

    camera cam_a;
    cam_a.view = glm::lookAt(vec3(0.6f, 0.9f, 4.0f), vec3(0), vec3(0, 1, 0));
    cam_a.projection = glm::perspective(glm::radians(45.0f), 4.0f / 3.0f, 0.1f, 100.0f);
    cam_a.width = 64;
    cam_a.height = 48;
    camera cam_b = cam_a;
    cam_b.view = cam_a.view * S;

    REQUIRE(world_eye(cam_a).z > 0.0f);
    REQUIRE(world_eye(cam_b).z < 0.0f);
    std::vector<hit_record> ga, gb;
    const image front = render_image<phong_lighting>(a, cam_a, ga);
    const image back = render_image<phong_lighting>(b, cam_b, gb);
    const vec3 ambient = mat.ka * a.ambient;
    int square_pixels = 0, brighter = 0, edge = 0;
    for (std::size_t i = 0; i < front.pixels.size(); ++i) {
        if (ga[i].object != gb[i].object) { // the same silhouette, but for a ray grazing an edge
            ++edge;
            continue;
        }
        if (ga[i].object < 0) continue;
        ++square_pixels;
        CHECK(ga[i].normal.z > 0.0f); // the same square, normal +z in both scenes: A's camera (z > 0)
        CHECK(gb[i].normal.z > 0.0f); // sees its front, B's (z < 0) its back
        // Rounding only: the mirrored rays come from a different inverse matrix; the shading
        // amplifies their few-ulp differences by at most about m (pow). (Observed with GLM 0.9.9.8:
        // bit-identical, as negating z negates every product exactly.)
        const float tol = 8 * eps * (1.0f + mat.shininess);
        for (int k = 0; k < 3; ++k) CHECK(std::abs(front.pixels[i][k] - back.pixels[i][k]) <= tol * std::max(1.0f, front.pixels[i][k]));
        if (front.pixels[i].r > ambient.r + 0.05f) ++brighter;
    }
    CHECK(edge <= 2);
    CHECK(square_pixels > 300);
    CHECK(brighter > square_pixels / 2); // the front is really lit, not just ambient

    // One-sided: the back keeps its generic normal (0, 0, 1), away from the lights: ambient only.
    constexpr phong::features one_sided = [] {
        phong::features f = phong_lighting;
        f.two_sided = phong::facing::none;
        return f;
    }();
    const image unlit = render_image<one_sided>(b, cam_b);
    for (std::size_t i = 0; i < unlit.pixels.size(); ++i)
        if (gb[i].object >= 0) CHECK(unlit.pixels[i] == ambient);
}

TEST_CASE("render: the demo scene renders finite, non-negative, with every object visible")
{
    const scene sc = demo_scene();
    for (const bool perspective : {true, false}) {
        const camera cam = demo_camera(perspective, 128, 96);
        std::vector<hit_record> gbuffer;
        for (const image& img : {render_image<phong_lighting>(sc, cam, gbuffer), render_image<blinn_lighting>(sc, cam, gbuffer)}) {
            int bad = 0;
            for (const vec3& p : img.pixels)
                for (int k = 0; k < 3; ++k) bad += !(std::isfinite(p[k]) && p[k] >= 0.0f);
            CHECK(bad == 0);
        }
        std::set<int> seen;
        for (const hit_record& h : gbuffer) seen.insert(h.object);
        for (int i = 0; i < int(sc.objects.size()); ++i) CHECK(seen.count(i) == 1);
    }
}
