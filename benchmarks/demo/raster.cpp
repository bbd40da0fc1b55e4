// phong end-to-end benchmark and test 2: a small software rasterizer (issue 13, item 7).
// A generated torus (96 x 48 quads, 9216 triangles), model-view and projection matrices, back-face
// culling, a z-buffer with perspective-correct barycentrics, two lights in eye coordinates and
// seed 003's GLSL ADS lighting (reflect(-s, n), specular only where s.n > 0), done
//   per vertex (Gouraud): inline GLSL ADS, phong::shade_vertex<F> exact and stable, with
//     normal_matrix(model_view); colours interpolated;
//   per pixel: the interpolated eye-space position and normal lit by the inline formula,
//     phong::shade<F> exact and stable, and phong::shade_batch<F> over all fragments (SoA, packing
//     timed); plus the inline formula in double as the reference.
// Deferred: the frame is rasterized once (the z-buffer keeps the nearest triangle and its
// barycentrics per pixel), then each shading method is timed alone (median of --reps runs).
// Image targets (exit 1 if missed), 8-bit sRGB, max 1 level at every pixel: Gouraud phong exact vs
// inline, per-pixel phong exact vs inline, per-pixel phong stable vs double.
//
// Usage: phong_raster [output_dir] [--size WxH] [--reps N]
// SPDX-License-Identifier: MIT

// g++ 12 flags the _mm512_undefined_* placeholders inside its own AVX-512 intrinsics as
// uninitialized once xsimd's kernels are inlined (shade_batch); as in benchmarks/shade.bench.cpp,
// silenced for the whole file before any include.
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include "phong_calls.hpp"
#include "renderers_common.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>
#include <limits>

namespace {

using glm::vec3;
using glm::vec4;
using renderers::image;

struct mesh {
    std::vector<vec3> positions, normals; ///< object space, unit normals
    std::vector<glm::vec2> uvs;           ///< texture coordinates in [0, 1)^2
    std::vector<glm::uvec3> triangles;
};

/// A torus around the z axis: major radius R, minor radius r, u x v quads, two triangles each.
mesh make_torus(float R, float r, unsigned u_segments, unsigned v_segments)
{
    mesh m;
    const float two_pi = 6.28318530718f;
    for (unsigned i = 0; i < u_segments; ++i)
        for (unsigned j = 0; j < v_segments; ++j) {
            const float u = two_pi * float(i) / float(u_segments), v = two_pi * float(j) / float(v_segments);
            const vec3 ring(std::cos(u), std::sin(u), 0.0f);
            const vec3 n = std::cos(v) * ring + vec3(0.0f, 0.0f, std::sin(v));
            m.positions.push_back(R * ring + r * n);
            m.normals.push_back(glm::normalize(n));
            m.uvs.push_back(glm::vec2(float(i) / float(u_segments), float(j) / float(v_segments)));
        }
    for (unsigned i = 0; i < u_segments; ++i)
        for (unsigned j = 0; j < v_segments; ++j) {
            const unsigned a = i * v_segments + j, b = ((i + 1) % u_segments) * v_segments + j;
            const unsigned c = ((i + 1) % u_segments) * v_segments + (j + 1) % v_segments, d = i * v_segments + (j + 1) % v_segments;
            m.triangles.push_back({a, b, c});
            m.triangles.push_back({a, c, d});
        }
    return m;
}

/// Seed 003's light and material, in eye coordinates.
struct ads_light {
    vec3 position, La, Ld, Ls;
};
struct ads_material {
    vec3 Ka, Kd, Ks;
    float shininess;
};

struct setup {
    mesh torus = make_torus(1.0f, 0.42f, 96, 48);
    glm::mat4 model_view{1.0f}, projection{1.0f};
    std::vector<ads_light> lights;
    ads_material material{{0.9f, 0.5f, 0.3f}, {0.9f, 0.5f, 0.3f}, {0.8f, 0.8f, 0.8f}, 40.0f};
    vec3 background{0.03f, 0.03f, 0.05f};
};

setup make_setup(int width, int height)
{
    setup s;
    const glm::mat4 model = glm::rotate(glm::rotate(glm::mat4(1.0f), glm::radians(-60.0f), vec3(1, 0, 0)), glm::radians(20.0f), vec3(0, 1, 0));
    const glm::mat4 view = glm::lookAt(vec3(0.0f, 0.3f, 3.6f), vec3(0.0f), vec3(0.0f, 1.0f, 0.0f));
    s.model_view = view * model;
    s.projection = glm::perspective(glm::radians(45.0f), float(width) / float(height), 0.1f, 20.0f);
    s.lights = {{{3.0f, 4.0f, 2.0f}, vec3(0.08f), vec3(0.8f, 0.78f, 0.72f), vec3(0.9f)},
                {{-4.0f, -1.0f, 1.0f}, vec3(0.04f), vec3(0.25f, 0.3f, 0.45f), vec3(0.4f)}};
    return s;
}

/// Seed 003's GLSL ADS as its author writes it, in T (float: the `inline` method; double: the
/// reference): n = normalize(normal), v = normalize(-p), s = normalize(L - p), specular where s.n > 0.
template <class T>
glm::vec<3, T> ads_inline(const vec3& eye_position, const vec3& normal, const setup& s)
{
    using V = glm::vec<3, T>;
    const V p(eye_position), n = glm::normalize(V(normal)), v = glm::normalize(-p);
    const ads_material& m = s.material;
    V colour(T(0));
    for (const ads_light& L : s.lights) {
        const V sv = glm::normalize(V(L.position) - p);
        const T sn = std::max(glm::dot(sv, n), T(0));
        T spec = T(0);
        if (sn > T(0)) spec = std::pow(std::max(glm::dot(glm::reflect(-sv, n), v), T(0)), T(m.shininess));
        colour += V(L.La) * V(m.Ka) + V(L.Ld) * V(m.Kd) * sn + V(L.Ls) * V(m.Ks) * spec;
    }
    return colour;
}

/// The vertex shader, inline: eyeCoords = ModelView * p, tnorm = normalize(NormalMatrix * n), ADS.
vec3 vertex_inline(const vec3& p, const vec3& n, const glm::mat3& normal_mat, const setup& s)
{
    const vec3 eye(s.model_view * vec4(p, 1.0f));
    return ads_inline<float>(eye, normal_mat * n, s);
}

/// What the z-buffer pass leaves per covered pixel: the winning triangle's interpolated inputs.
struct fragment {
    int pixel;
    unsigned triangle;
    vec3 bary;                    ///< perspective-correct barycentrics
    vec3 eye_position, eye_normal; ///< interpolated (normal not unit)
};

std::vector<fragment> rasterize(const setup& s, int width, int height)
{
    const mesh& m = s.torus;
    const glm::mat3 normal_mat = glm::transpose(glm::inverse(glm::mat3(s.model_view)));
    std::vector<vec3> eye(m.positions.size()), eye_n(m.positions.size());
    std::vector<vec4> screen(m.positions.size()); // x, y in pixels, z NDC depth, w = 1/w_clip
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
        eye[i] = vec3(s.model_view * vec4(m.positions[i], 1.0f));
        eye_n[i] = glm::normalize(normal_mat * m.normals[i]); // the vertex shader's Normal output
        const vec4 clip = s.projection * vec4(eye[i], 1.0f);
        const float iw = 1.0f / clip.w;
        screen[i] = {(clip.x * iw + 1.0f) * 0.5f * float(width), (1.0f - clip.y * iw) * 0.5f * float(height), clip.z * iw, iw};
    }
    std::vector<float> depth(std::size_t(width) * std::size_t(height), std::numeric_limits<float>::infinity());
    std::vector<int> winner(depth.size(), -1);
    std::vector<vec3> bary(depth.size());
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const glm::uvec3 tri = m.triangles[t];
        const vec4 a = screen[tri.x], b = screen[tri.y], c = screen[tri.z];
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area >= 0.0f) continue; // back-facing (y down: counter-clockwise triangles have area < 0)
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x})))), x1 = std::min(width - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y})))), y1 = std::min(height - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const float px = float(x) + 0.5f, py = float(y) + 0.5f;
                const float w0 = ((c.x - b.x) * (py - b.y) - (c.y - b.y) * (px - b.x)) / area;
                const float w1 = ((a.x - c.x) * (py - c.y) - (a.y - c.y) * (px - c.x)) / area;
                const float w2 = 1.0f - w0 - w1;
                if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f) continue;
                const float z = w0 * a.z + w1 * b.z + w2 * c.z;
                const std::size_t i = std::size_t(y) * std::size_t(width) + std::size_t(x);
                if (!(z < depth[i]) || z < -1.0f) continue;
                depth[i] = z;
                winner[i] = int(t);
                const vec3 pc(w0 * a.w, w1 * b.w, w2 * c.w); // perspective correction
                bary[i] = pc / (pc.x + pc.y + pc.z);
            }
    }
    std::vector<fragment> frags;
    for (std::size_t i = 0; i < winner.size(); ++i) {
        if (winner[i] < 0) continue;
        const glm::uvec3 tri = m.triangles[std::size_t(winner[i])];
        const vec3 w = bary[i];
        frags.push_back({int(i), unsigned(winner[i]), w, w.x * eye[tri.x] + w.y * eye[tri.y] + w.z * eye[tri.z],
                         w.x * eye_n[tri.x] + w.y * eye_n[tri.y] + w.z * eye_n[tri.z]});
    }
    return frags;
}

// ---- Screen-space case (issue 27): texture-mapped kd and ks, a specular map's per-pixel
// exponent, a normal map, directional lights, the view along +z; as a software rasterizer in the
// style of tinyrenderer writes it. The texture lookups are done once (not timed); the lighting
// is timed per fragment.

/// What the textures give one fragment: the mapped unit normal, kd, ks and the exponent.
struct textured_fragment {
    vec3 normal; ///< unit, screen (eye) space
    vec3 kd, ks;
    float exponent;
};

/// Procedural maps on the torus's (u, v) in [0, 1)^2: a striped diffuse map, a specular map (grey
/// level and exponent), and a normal map's bumps added to the interpolated normal.
std::vector<textured_fragment> texture_fragments(const std::vector<fragment>& frags, const mesh& m)
{
    std::vector<textured_fragment> out;
    out.reserve(frags.size());
    for (const fragment& f : frags) {
        const glm::uvec3 tri = m.triangles[f.triangle];
        const glm::vec2 uv = f.bary.x * m.uvs[tri.x] + f.bary.y * m.uvs[tri.y] + f.bary.z * m.uvs[tri.z];
        const float stripe = 0.5f + 0.5f * std::sin(40.0f * uv.x), ring = 0.5f + 0.5f * std::cos(24.0f * uv.y);
        const vec3 kd = glm::mix(vec3(0.75f, 0.35f, 0.15f), vec3(0.2f, 0.45f, 0.7f), stripe * ring);
        const float gloss = 0.5f + 0.5f * std::sin(17.0f * uv.x + 9.0f * uv.y);
        const vec3 bump(0.25f * std::cos(60.0f * uv.x), 0.25f * std::sin(36.0f * uv.y), 0.0f);
        out.push_back({glm::normalize(glm::normalize(f.eye_normal) + bump), kd, vec3(0.15f + 0.6f * gloss), 4.0f + 60.0f * gloss});
    }
    return out;
}

/// A directional light in screen space: unit direction toward the light, colour.
struct screen_light {
    vec3 direction, colour;
};
std::vector<screen_light> screen_lights(int count)
{
    const screen_light all[4] = {{glm::normalize(vec3(0.4f, 0.6f, 1.0f)), vec3(0.9f, 0.85f, 0.8f)},
                                 {glm::normalize(vec3(-0.8f, -0.2f, 0.6f)), vec3(0.3f, 0.35f, 0.5f)},
                                 {glm::normalize(vec3(0.1f, -0.9f, 0.5f)), vec3(0.35f, 0.3f, 0.25f)},
                                 {glm::normalize(vec3(-0.3f, 0.7f, 0.4f)), vec3(0.25f, 0.3f, 0.3f)}};
    std::vector<screen_light> out(all, all + count);
    const float scale = 1.0f / std::sqrt(float(count));
    for (screen_light& L : out) L.colour *= scale;
    return out;
}
constexpr float screen_ambient = 0.08f;

/// The inline lighting (T = float, or double for the reference): ambient kd + sum over lights of
/// colour (kd max(n.l, 0) + ks max(r.z, 0)^e), r = reflect(-l, n), r.z = 2 (n.l) n.z - l.z.
template <class T>
glm::vec<3, T> screen_inline(const textured_fragment& f, const std::vector<screen_light>& lights)
{
    using V = glm::vec<3, T>;
    const V n(f.normal), kd(f.kd), ks(f.ks);
    V colour = T(screen_ambient) * kd;
    for (const screen_light& L : lights) {
        const V l(L.direction);
        const T nl = glm::dot(n, l);
        const T spec = std::pow(std::max(T(2) * nl * n.z - l.z, T(0)), T(f.exponent));
        colour += V(L.colour) * (kd * std::max(nl, T(0)) + ks * spec);
    }
    return colour;
}

/// Everything the phong methods need, converted once (not timed).
struct phong_setup {
    std::vector<phong::light<float>> lights;
    phong::material<float> material;
    glm::mat3 normal_mat;
};
phong_setup to_phong(const setup& s)
{
    phong_setup p;
    for (const ads_light& L : s.lights) p.lights.push_back(phong_calls::make_ads_light(L.position, L.La, L.Ld, L.Ls));
    p.material = phong_calls::make_material(s.material.Ka, s.material.Kd, s.material.Ks, s.material.shininess);
    p.normal_mat = phong_calls::normal_matrix(s.model_view);
    return p;
}

template <class T, class C>
image<T> gouraud_image(const setup& s, const std::vector<fragment>& frags, const std::vector<C>& vertex_colour, int width, int height)
{
    image<T> img(width, height, glm::vec<3, T>(s.background));
    for (const fragment& f : frags) {
        const glm::uvec3 tri = s.torus.triangles[f.triangle];
        img.pixels[std::size_t(f.pixel)] = glm::vec<3, T>(f.bary.x * vertex_colour[tri.x] + f.bary.y * vertex_colour[tri.y] +
                                                          f.bary.z * vertex_colour[tri.z]);
    }
    return img;
}

template <class T, class C>
image<T> pixel_image(const setup& s, const std::vector<fragment>& frags, const std::vector<C>& colour, int width, int height)
{
    image<T> img(width, height, glm::vec<3, T>(s.background));
    for (std::size_t i = 0; i < frags.size(); ++i) img.pixels[std::size_t(frags[i].pixel)] = glm::vec<3, T>(colour[i]);
    return img;
}

} // namespace

int main(int argc, char** argv)
{
    renderers::options opt{.width = 640, .height = 480};
    if (!renderers::parse(argc, argv, opt, "phong_raster")) return 2;
    const int W = opt.width, H = opt.height;
    const setup s = make_setup(W, H);
    const phong_setup ps = to_phong(s);
    const std::vector<fragment> frags = rasterize(s, W, H);
    const mesh& m = s.torus;
    const std::size_t NV = m.positions.size(), NF = frags.size();
    const glm::mat3 inline_normal_mat = glm::transpose(glm::inverse(glm::mat3(s.model_view)));

    // Vertex stage: repeated `inner` times per timed run (a few thousand vertices is a short run).
    constexpr int inner = 16;
    std::vector<vec3> v_inline(NV), v_exact(NV), v_stable(NV);
    const auto vertex_pass = [&](std::vector<vec3>& out, auto&& shade_one) {
        for (int k = 0; k < inner; ++k)
            for (std::size_t i = 0; i < NV; ++i) out[i] = shade_one(m.positions[i], m.normals[i]);
    };
    const auto vertex_exact = [&](const vec3& p, const vec3& n) {
        return phong_calls::shade_phong_vertex<phong_calls::raster_exact>(p, n, s.model_view, ps.normal_mat, ps.material, ps.lights);
    };
    const auto vertex_stable = [&](const vec3& p, const vec3& n) {
        return phong_calls::shade_phong_vertex<phong_calls::raster_stable>(p, n, s.model_view, ps.normal_mat, ps.material, ps.lights);
    };
    // Fragment stage.
    std::vector<vec3> f_inline(NF), f_exact(NF), f_stable(NF), f_batch(NF), f_P(NF), f_n(NF);
    for (std::size_t i = 0; i < NF; ++i) f_P[i] = frags[i].eye_position, f_n[i] = frags[i].eye_normal;
    std::vector<glm::dvec3> f_double(NF);
    phong_calls::batch_scratch scratch;
    const renderers::timings t = renderers::interleaved_medians(opt.reps, {
        [&] { vertex_pass(v_inline, [&](const vec3& p, const vec3& n) { return vertex_inline(p, n, inline_normal_mat, s); }); },
        [&] { vertex_pass(v_exact, vertex_exact); },
        [&] { vertex_pass(v_stable, vertex_stable); },
        [&] {
            for (std::size_t i = 0; i < NF; ++i) f_inline[i] = ads_inline<float>(f_P[i], f_n[i], s);
        },
        [&] {
            for (std::size_t i = 0; i < NF; ++i)
                f_exact[i] = phong_calls::shade_phong_fragment<phong_calls::raster_exact>(f_P[i], f_n[i], ps.material, ps.lights);
        },
        [&] {
            for (std::size_t i = 0; i < NF; ++i)
                f_stable[i] = phong_calls::shade_phong_fragment<phong_calls::raster_stable>(f_P[i], f_n[i], ps.material, ps.lights);
        },
        [&] { phong_calls::shade_phong_fragments_batch<phong_calls::raster_exact>(f_P, f_n, ps.material, ps.lights, f_batch, scratch); },
    });
    for (std::size_t i = 0; i < NF; ++i) f_double[i] = ads_inline<double>(f_P[i], f_n[i], s);

    renderers::report out(opt.dir / "raster.txt");
    out("phong_raster: %dx%d, torus %zu vertices %zu triangles, %zu lights, GLSL ADS, shading step only, median of %d reps, one thread\n",
        W, H, NV, m.triangles.size(), s.lights.size(), opt.reps);
    const double nv = 1e9 / double(NV * inner), nf = 1e9 / double(NF);
    for (const auto& [clock, x] : {std::pair{"thread CPU time", &t.cpu}, std::pair{"wall clock, steady_clock", &t.wall}}) {
        const std::vector<double>& u = *x;
        out("\nns per shaded vertex / fragment, %s; (x) = ratio to inline\n", clock);
        out("%-9s %8s | %8s %14s %14s %14s\n", "stage", "points", "inline", "phong exact", "phong stable", "batch (SoA)");
        out("%-9s %8zu | %8.1f %8.1f (%.2f) %8.1f (%.2f) %14s\n", "vertex", NV, u[0] * nv, u[1] * nv, u[1] / u[0], u[2] * nv, u[2] / u[0], "-");
        out("%-9s %8zu | %8.1f %8.1f (%.2f) %8.1f (%.2f) %8.1f (%.2f)\n", "fragment", NF, u[3] * nf, u[4] * nf, u[4] / u[3], u[5] * nf,
            u[5] / u[3], u[6] * nf, u[6] / u[3]);
    }

    const image<float> g_inline = gouraud_image<float>(s, frags, v_inline, W, H), g_exact = gouraud_image<float>(s, frags, v_exact, W, H),
                       g_stable = gouraud_image<float>(s, frags, v_stable, W, H);
    const image<float> p_inline = pixel_image<float>(s, frags, f_inline, W, H), p_exact = pixel_image<float>(s, frags, f_exact, W, H),
                       p_stable = pixel_image<float>(s, frags, f_stable, W, H), p_batch = pixel_image<float>(s, frags, f_batch, W, H);
    const image<double> p_double = pixel_image<double>(s, frags, f_double, W, H);
    bool written = true;
    written &= renderers::write_png(opt.dir / "raster_gouraud_inline.png", g_inline, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_gouraud_phong.png", g_exact, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_gouraud_stable.png", g_stable, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_pixel_inline.png", p_inline, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_pixel_phong.png", p_exact, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_pixel_stable.png", p_stable, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_pixel_batch.png", p_batch, stbi_write_png);
    written &= renderers::write_png(opt.dir / "raster_pixel_double.png", p_double, stbi_write_png);
    if (!written) return 1;

    using renderers::compare, renderers::to_rgb8;
    const renderers::image_diff d_gouraud = compare(to_rgb8(g_exact), to_rgb8(g_inline)), d_pixel = compare(to_rgb8(p_exact), to_rgb8(p_inline)),
                                d_stable = compare(to_rgb8(p_stable), to_rgb8(p_double)), d_batch = compare(to_rgb8(p_batch), to_rgb8(p_inline)),
                                d_exact_double = compare(to_rgb8(p_exact), to_rgb8(p_double));
    bool ok = true;
    out("\nimages (8-bit sRGB, %d pixels, %zu covered): pixels differing / max difference in levels\n", W * H, NF);
    out("  Gouraud phong exact vs inline:     %7zu / %d  %s\n", d_gouraud.differing, d_gouraud.max_levels, renderers::verdict(d_gouraud.max_levels <= 1, ok));
    out("  per-pixel phong exact vs inline:   %7zu / %d  %s\n", d_pixel.differing, d_pixel.max_levels, renderers::verdict(d_pixel.max_levels <= 1, ok));
    out("  per-pixel phong stable vs double:  %7zu / %d  %s\n", d_stable.differing, d_stable.max_levels, renderers::verdict(d_stable.max_levels <= 1, ok));
    out("  (per-pixel phong exact vs double:  %7zu / %d)\n", d_exact_double.differing, d_exact_double.max_levels);
    out("  (per-pixel batch vs inline:        %7zu / %d)\n", d_batch.differing, d_batch.max_levels);

    // Screen-space case (issue 27), 1, 2 and 4 directional lights.
    const std::vector<textured_fragment> tex = texture_fragments(frags, m);
    out("\nscreen space (issue 27): normal-mapped, texture-mapped kd / ks, per-pixel exponent, directional lights, view +z;\n"
        "ns per fragment, thread CPU time, (x) = ratio to the inline lighting; phong = shade_incident (no position, surface per fragment)\n");
    out("%-6s %8s | %8s | %15s %15s | images exact vs inline, stable vs double\n", "lights", "points", "inline", "phong exact", "phong stable");
    std::vector<std::string> machine;
    for (const int count : {1, 2, 4}) {
        const std::vector<screen_light> lights = screen_lights(count);
        std::vector<phong::light<float>> plights;
        std::vector<phong::incident<float>> incidents;
        for (const screen_light& L : lights) {
            plights.push_back(phong_calls::make_light_directional(L.direction, L.colour));
            incidents.push_back({L.direction, 0.0f});
        }
        std::vector<vec3> s_inline(NF), s_exact(NF), s_stable(NF);
        std::vector<glm::dvec3> s_double(NF);
        const renderers::timings st = renderers::interleaved_medians(opt.reps, {
            [&] {
                for (std::size_t i = 0; i < NF; ++i) s_inline[i] = screen_inline<float>(tex[i], lights);
            },
            [&] {
                for (std::size_t i = 0; i < NF; ++i)
                    s_exact[i] = phong_calls::shade_phong_screen<phong_calls::screen_exact>(tex[i].normal, tex[i].kd, tex[i].ks, tex[i].exponent,
                                                                                           plights, incidents, screen_ambient);
            },
            [&] {
                for (std::size_t i = 0; i < NF; ++i)
                    s_stable[i] = phong_calls::shade_phong_screen<phong_calls::screen_stable>(tex[i].normal, tex[i].kd, tex[i].ks, tex[i].exponent,
                                                                                             plights, incidents, screen_ambient);
            },
        });
        for (std::size_t i = 0; i < NF; ++i) s_double[i] = screen_inline<double>(tex[i], lights);
        const image<float> a = pixel_image<float>(s, frags, s_inline, W, H), b = pixel_image<float>(s, frags, s_exact, W, H),
                           c = pixel_image<float>(s, frags, s_stable, W, H);
        const image<double> d = pixel_image<double>(s, frags, s_double, W, H);
        const std::string stem = "raster_screen_" + std::to_string(count) + "lights_";
        written &= renderers::write_png(opt.dir / (stem + "inline.png"), a, stbi_write_png);
        written &= renderers::write_png(opt.dir / (stem + "phong.png"), b, stbi_write_png);
        const renderers::image_diff de = compare(to_rgb8(b), to_rgb8(a)), ds = compare(to_rgb8(c), to_rgb8(d));
        const std::vector<double>& x = st.cpu;
        out("%-6d %8zu | %8.2f | %8.2f (%.2f) %8.2f (%.2f) | %zu / %d %s, %zu / %d %s\n", count, NF, x[0] * nf, x[1] * nf, x[1] / x[0],
            x[2] * nf, x[2] / x[0], de.differing, de.max_levels, renderers::verdict(de.max_levels <= 1, ok), ds.differing, ds.max_levels,
            renderers::verdict(ds.max_levels <= 1, ok));
        char row[120];
        std::snprintf(row, sizeof row, "TABLE27 raster %d %.3f %.3f\n", count, x[1] / x[0], x[2] / x[0]);
        machine.push_back(row);
    }
    for (const std::string& r : machine) out("%s", r.c_str());
    if (!written) return 1;
    out("image targets (max 1 level): %s\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
