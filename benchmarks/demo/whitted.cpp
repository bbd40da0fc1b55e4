// phong end-to-end benchmark and test 1: a small Whitted ray tracer (issue 13, item 7).
// Spheres and a checkered floor, 1, 2 or 4 point lights, hard shadows, mirror reflection and
// refraction to a fixed depth, Phong lighting at every hit, done four ways over the same hits:
//   inline  the ten lines a ray tracer's author writes (no guards, n and v taken as unit);
//   phong   phong::shade<F>, exact mode, v = -ray.dir given, unit inputs, masked(lights, visible),
//           the tracer's own point_light read through its phong::light_traits specialization;
//   stable  the same in evaluation::stable;
//   batch   primary hits only: phong::shade_batch<F> on the hit arrays as kept (aos_points, material_table);
// plus the inline formula in double as the reference image.
// The frame is traced once and every hit recorded (position, unit normal, view direction, shadow
// mask, material, path weight, pixel); each method is then timed over the recorded hits (median
// of --reps runs) and composed into an image (sum of weight * local colour per pixel, which is
// Whitted's recursion with constant reflection and transmission coefficients).
// Image targets (exit 1 if missed): phong exact vs inline and phong stable vs double, each
// within 1 level of 8-bit sRGB at every pixel.
//
// Usage: phong_whitted [output_dir] [--size WxH] [--reps N]
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

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <bit>
#include <cmath>
#include <limits>

namespace {

using glm::vec3;
using renderers::image;

struct sphere {
    vec3 centre;
    float radius;
    int material;
};
struct tracer_material {
    vec3 ka, kd, ks;
    float shininess;
    float kr = 0.0f, kt = 0.0f, ior = 1.0f; ///< reflected, transmitted weight; refractive index
};
struct point_light {
    vec3 position, colour;
};
} // namespace

/// How phong reads the tracer's lights: a positional light whose colour is its diffuse and
/// specular strength (no ambient term, no falloff: light_traits' defaults).
template <> struct phong::light_traits<point_light> {
    static glm::vec4 position(const point_light& L) { return glm::vec4(L.position, 1.0f); }
    static const vec3& diffuse(const point_light& L) { return L.colour; }
    static const vec3& specular(const point_light& L) { return L.colour; }
};

namespace {

struct scene {
    std::vector<sphere> spheres;
    float floor_half_size = 6.0f; ///< the floor: y = 0, |x|, |z| < this, checkered materials 0 and 1
    std::vector<tracer_material> materials;
    std::vector<point_light> lights;
    vec3 ambient{0.1f}, background{0.05f, 0.07f, 0.12f};
    vec3 eye{0.0f, 1.7f, 6.2f}, target{0.0f, 0.7f, 0.0f};
    float fov_degrees = 45.0f;
    int max_depth = 4;
};

scene make_scene(int light_count)
{
    scene sc;
    sc.materials = {
        {vec3(0.08f), vec3(0.75f), vec3(0.2f), 20.0f, 0.1f},                                      // 0 floor light
        {vec3(0.02f), vec3(0.18f), vec3(0.2f), 20.0f, 0.1f},                                      // 1 floor dark
        {vec3(0.1f, 0.02f, 0.02f), vec3(0.7f, 0.12f, 0.1f), vec3(0.6f), 60.0f},                   // 2 red plastic
        {vec3(0.01f), vec3(0.05f), vec3(0.8f), 200.0f, 0.85f},                                    // 3 mirror
        {vec3(0.0f), vec3(0.02f), vec3(0.9f), 120.0f, 0.08f, 0.88f, 1.5f},                        // 4 glass
        {vec3(0.02f, 0.04f, 0.1f), vec3(0.15f, 0.3f, 0.8f), vec3(0.5f), 35.0f, 0.15f},            // 5 blue
        {vec3(0.08f, 0.07f, 0.02f), vec3(0.8f, 0.65f, 0.15f), vec3(0.3f), 8.0f},                  // 6 gold, broad
    };
    sc.spheres = {{{-1.7f, 0.8f, -0.2f}, 0.8f, 2}, {{0.3f, 1.05f, -1.4f}, 1.05f, 3}, {{1.35f, 0.62f, 0.9f}, 0.62f, 4},
                  {{-0.35f, 0.35f, 1.5f}, 0.35f, 5}, {{2.6f, 0.5f, -1.2f}, 0.5f, 6}};
    const point_light all[4] = {{{4.0f, 6.0f, 5.0f}, {1.0f, 0.95f, 0.85f}},
                                {{-5.0f, 4.0f, 3.0f}, {0.55f, 0.6f, 0.8f}},
                                {{0.5f, 7.0f, -4.0f}, {0.7f, 0.7f, 0.7f}},
                                {{-1.0f, 1.5f, 4.5f}, {0.4f, 0.35f, 0.3f}}};
    const float scale = 1.0f / std::sqrt(float(light_count));
    for (int i = 0; i < light_count; ++i) sc.lights.push_back({all[i].position, all[i].colour * scale});
    return sc;
}

struct ray {
    vec3 origin, dir; ///< dir unit
};

struct intersection {
    float t = std::numeric_limits<float>::infinity();
    int object = -1; ///< sphere index, or -2 for the floor
};

intersection intersect(const scene& sc, const ray& r, float t_min)
{
    intersection best;
    for (std::size_t i = 0; i < sc.spheres.size(); ++i) {
        const sphere& s = sc.spheres[i];
        const vec3 oc = r.origin - s.centre;
        const float b = glm::dot(oc, r.dir), c = glm::dot(oc, oc) - s.radius * s.radius, disc = b * b - c;
        if (disc < 0.0f) continue;
        const float q = std::sqrt(disc);
        const float t = -b - q > t_min ? -b - q : -b + q;
        if (t > t_min && t < best.t) best = {t, int(i)};
    }
    if (r.dir.y != 0.0f) {
        const float t = -r.origin.y / r.dir.y;
        const vec3 p = r.origin + t * r.dir;
        if (t > t_min && t < best.t && std::abs(p.x) < sc.floor_half_size && std::abs(p.z) < sc.floor_half_size) best = {t, -2};
    }
    return best;
}

/// One recorded hit: what the shading step reads, and where its colour goes.
struct hit_record {
    vec3 position, normal, view; ///< normal and view unit, view = -ray.dir, normal facing the ray
    unsigned visible;            ///< bit i: lights[i] not in shadow
    phong::incident<float> shadow[phong_calls::max_lights]; ///< the shadow rays: unit direction toward lights[i] and its distance
    int material;
    vec3 weight; ///< product of kr / kt along the path
    int pixel;
};

struct frame {
    std::vector<hit_record> hits;    ///< every hit, primary and secondary
    std::vector<hit_record> primary; ///< the primary hits (the batch method's input)
    image<double> missed;            ///< sum of weight * background of the rays that hit nothing
};

frame trace_frame(const scene& sc, int width, int height)
{
    frame f;
    f.missed = image<double>(width, height);
    const vec3 forward = glm::normalize(sc.target - sc.eye), right = glm::normalize(glm::cross(forward, vec3(0, 1, 0)));
    const vec3 up = glm::cross(right, forward);
    const float half_h = std::tan(glm::radians(sc.fov_degrees) * 0.5f), half_w = half_h * float(width) / float(height);
    struct task {
        ray r;
        vec3 weight;
        int depth;
    };
    std::vector<task> stack;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const int pixel = y * width + x;
            const float u = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * half_w;
            const float w = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * half_h;
            stack.push_back({{sc.eye, glm::normalize(forward + u * right + w * up)}, vec3(1.0f), 0});
            while (!stack.empty()) {
                const task tk = stack.back();
                stack.pop_back();
                const intersection is = intersect(sc, tk.r, 1e-4f);
                if (is.object == -1) {
                    f.missed.pixels[std::size_t(pixel)] += glm::dvec3(tk.weight * sc.background);
                    continue;
                }
                hit_record h;
                h.position = tk.r.origin + is.t * tk.r.dir;
                if (is.object >= 0) {
                    const sphere& s = sc.spheres[std::size_t(is.object)];
                    h.normal = glm::normalize(h.position - s.centre);
                    h.material = s.material;
                } else {
                    h.normal = vec3(0.0f, 1.0f, 0.0f);
                    h.material = (int(std::floor(h.position.x)) + int(std::floor(h.position.z))) & 1;
                }
                const bool inside = glm::dot(h.normal, tk.r.dir) > 0.0f;
                if (inside) h.normal = -h.normal;
                h.view = -tk.r.dir;
                h.visible = 0;
                for (std::size_t i = 0; i < sc.lights.size(); ++i) {
                    const vec3 to_light = sc.lights[i].position - h.position;
                    const float dist = glm::length(to_light);
                    const vec3 dir = to_light / dist;
                    h.shadow[i] = {dir, dist};
                    const intersection sh = intersect(sc, {h.position + 1e-3f * h.normal, dir}, 1e-4f);
                    if (!(sh.t < dist)) h.visible |= 1u << i;
                }
                h.weight = tk.weight;
                h.pixel = pixel;
                f.hits.push_back(h);
                if (tk.depth == 0) f.primary.push_back(h);
                if (tk.depth >= sc.max_depth) continue;
                const tracer_material& m = sc.materials[std::size_t(h.material)];
                const vec3 reflected = glm::normalize(glm::reflect(tk.r.dir, h.normal));
                if (m.kr > 0.0f) stack.push_back({{h.position + 1e-3f * h.normal, reflected}, tk.weight * m.kr, tk.depth + 1});
                if (m.kt > 0.0f) {
                    const vec3 refracted = glm::refract(tk.r.dir, h.normal, inside ? m.ior : 1.0f / m.ior);
                    if (glm::dot(refracted, refracted) == 0.0f) // total internal reflection
                        stack.push_back({{h.position + 1e-3f * h.normal, reflected}, tk.weight * m.kt, tk.depth + 1});
                    else
                        stack.push_back({{h.position - 1e-3f * h.normal, glm::normalize(refracted)}, tk.weight * m.kt, tk.depth + 1});
                }
            }
        }
    return f;
}

/// The lighting a ray tracer's author writes inline, in T (float: the `inline` method; double:
/// the reference). n and v are unit already; no guards.
template <class T>
glm::vec<3, T> shade_inline(const hit_record& h, const scene& sc)
{
    using V = glm::vec<3, T>;
    const tracer_material& m = sc.materials[std::size_t(h.material)];
    const V P(h.position), n(h.normal), v(h.view), kd(m.kd), ks(m.ks);
    const T shininess = T(m.shininess);
    V colour = V(m.ka) * V(sc.ambient);
    for (std::size_t i = 0; i < sc.lights.size(); ++i) {
        if (!(h.visible & (1u << i))) continue;
        const V l = glm::normalize(V(sc.lights[i].position) - P);
        const T lambert = std::max(T(0), glm::dot(l, n));
        const V r = glm::reflect(-l, n);
        const T spec = std::pow(std::max(T(0), glm::dot(r, v)), shininess);
        colour += V(sc.lights[i].colour) * (kd * lambert + ks * spec);
    }
    return colour;
}

/// The same lighting as an expert writes it: the shadow rays' unit directions reused (nothing
/// of L - P recomputed), r.v as 2 (n.l)(n.v) - l.v. The baseline of issue 27's table.
template <class T>
glm::vec<3, T> shade_inline_reuse(const hit_record& h, const scene& sc)
{
    using V = glm::vec<3, T>;
    const tracer_material& m = sc.materials[std::size_t(h.material)];
    const V n(h.normal), v(h.view), kd(m.kd), ks(m.ks);
    const T shininess = T(m.shininess), nv = glm::dot(n, v);
    V colour = V(m.ka) * V(sc.ambient);
    for (std::size_t i = 0; i < sc.lights.size(); ++i) {
        if (!(h.visible & (1u << i))) continue;
        const V l(h.shadow[i].direction);
        const T nl = glm::dot(l, n);
        const T lambert = std::max(T(0), nl);
        const T spec = std::pow(std::max(T(0), T(2) * nl * nv - glm::dot(l, v)), shininess);
        colour += V(sc.lights[i].colour) * (kd * lambert + ks * spec);
    }
    return colour;
}

/// The materials as phong takes them, converted once (not timed); lights as phong::light<float>
/// for the kernel reference only (the phong methods read the tracer's own lights).
struct phong_scene {
    std::vector<phong::light<float>> lights;
    std::vector<phong::material<float>> materials;
};
phong_scene to_phong(const scene& sc)
{
    phong_scene p;
    for (const point_light& L : sc.lights) p.lights.push_back(phong_calls::make_light(L.position, L.colour));
    for (const tracer_material& m : sc.materials) p.materials.push_back(phong_calls::make_material(m.ka, m.kd, m.ks, m.shininess));
    return p;
}

void shade_all_inline(const std::vector<hit_record>& hits, const scene& sc, std::vector<vec3>& out)
{
    for (std::size_t i = 0; i < hits.size(); ++i) out[i] = shade_inline<float>(hits[i], sc);
}

template <phong::features F>
void shade_all_phong(const std::vector<hit_record>& hits, const scene& sc, const phong_scene& ps, std::vector<vec3>& out)
{
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const hit_record& h = hits[i];
        out[i] = phong_calls::shade_phong_scalar<F>(h.position, h.normal, h.view, h.visible, std::span<const point_light>(sc.lights),
                                                   ps.materials[std::size_t(h.material)], sc.ambient);
    }
}

void shade_all_inline_reuse(const std::vector<hit_record>& hits, const scene& sc, std::vector<vec3>& out)
{
    for (std::size_t i = 0; i < hits.size(); ++i) out[i] = shade_inline_reuse<float>(hits[i], sc);
}

/// phong with what the tracer has: the shadow rays' directions and distances (shade_incident).
template <phong::features F>
void shade_all_incident(const std::vector<hit_record>& hits, const scene& sc, const phong_scene& ps, std::vector<vec3>& out)
{
    for (std::size_t i = 0; i < hits.size(); ++i) {
        const hit_record& h = hits[i];
        out[i] = phong_calls::shade_phong_incident<F>(h.normal, h.view, h.visible, std::span<const point_light>(sc.lights), h.shadow,
                                                     ps.materials[std::size_t(h.material)], sc.ambient);
    }
}

/// The batch method's input, as a user would keep it (timed from here: grouping, packing, shading).
struct primary_arrays {
    std::vector<vec3> P, n, v;             ///< hit position, unit normal, unit view vector -ray.dir
    std::vector<std::uint64_t> visible;   ///< bit i: lights[i] not in shadow
    std::vector<std::uint32_t> material;  ///< index into the scene's materials
};

void shade_all_batch(const primary_arrays& a, const scene& sc, const phong_scene& ps, std::vector<vec3>& out)
{
    phong_calls::shade_phong_batch<phong_calls::whitted_exact>(a.P, a.n, a.v, a.visible, a.material, ps.materials,
                                                               std::span<const point_light>(sc.lights),
                                                               sc.ambient, out);
}

/// The batch kernel's floor, for the overhead figure (not a renderer's call): the same hits
/// already in SoA arrays and one material for all (material 0), with the same views and masks, so
/// no AoS transpose and no per-point material; batch minus this is the per-point overhead of the
/// AoS loads, the material lookup and the colour stores.
struct kernel_reference_input {
    std::vector<float> px, py, pz, nx, ny, nz, vx, vy, vz;
    std::vector<std::uint64_t> visible;
    std::vector<float> r, g, b;
};
kernel_reference_input make_kernel_reference_input(const primary_arrays& a)
{
    kernel_reference_input k;
    for (std::size_t i = 0; i < a.P.size(); ++i) {
        k.px.push_back(a.P[i].x), k.py.push_back(a.P[i].y), k.pz.push_back(a.P[i].z);
        k.nx.push_back(a.n[i].x), k.ny.push_back(a.n[i].y), k.nz.push_back(a.n[i].z);
        k.vx.push_back(a.v[i].x), k.vy.push_back(a.v[i].y), k.vz.push_back(a.v[i].z);
    }
    k.visible = a.visible;
    k.r.resize(a.P.size()), k.g.resize(a.P.size()), k.b.resize(a.P.size());
    return k;
}
void shade_kernel_reference(kernel_reference_input& k, const phong_scene& ps, const scene& sc, std::vector<vec3>& out)
{
    const phong::soa_points<float> points{.positions = {k.px, k.py, k.pz}, .normals = {k.nx, k.ny, k.nz},
                                          .views = {k.vx, k.vy, k.vz}, .light_masks = k.visible};
    phong::shade_batch<phong_calls::whitted_exact>(points, ps.materials[0], ps.lights, phong::soa_rgba<float>{k.r, k.g, k.b, {}},
                                                   phong::environment<float>{.ambient = sc.ambient});
    out[0] = vec3(k.r[0], k.g[0], k.b[0]); // keep the result observable
}

/// How the primary hits fall into shade_batch's steps (batch_width<float> consecutive hits): per
/// (step, light), whether no hit, every hit or only some hits of the step see the light (some: the
/// step shades the light in every lane and keeps the result where it is seen), and the share of
/// steps whose hits all have one material (else the step gathers its materials).
struct coherence_stats {
    int lights;
    double none, every, some, one_material;
};
coherence_stats step_coherence(const primary_arrays& a, int light_count)
{
    constexpr std::size_t W = phong::batch_width<float>;
    std::size_t steps = 0, none = 0, every = 0, some = 0, one_material = 0;
    for (std::size_t i = 0; i + W <= a.visible.size(); i += W, ++steps) {
        std::uint64_t seen_by_any = 0, seen_by_all = ~std::uint64_t(0);
        bool uniform = true;
        for (std::size_t k = i; k < i + W; ++k) {
            seen_by_any |= a.visible[k];
            seen_by_all &= a.visible[k];
            uniform = uniform && a.material[k] == a.material[i];
        }
        for (int j = 0; j < light_count; ++j) {
            if (!(seen_by_any >> j & 1u)) ++none;
            else if (seen_by_all >> j & 1u) ++every;
            else ++some;
        }
        one_material += uniform;
    }
    const double pairs = double(steps) * light_count;
    return {light_count, double(none) / pairs, double(every) / pairs, double(some) / pairs, double(one_material) / double(steps)};
}

/// The memory floor of the batch method: the same bytes read and written (positions, normals,
/// views, masks, material ids in; one colour out per hit) with no shading, as a lower bound on
/// the batch method's time in this loop, where the other methods evict the hit arrays from the
/// caches between its runs.
void stream_floor(const primary_arrays& a, std::vector<vec3>& out)
{
    for (std::size_t i = 0; i < a.P.size(); ++i) out[i] = a.P[i] + a.n[i] * a.v[i] + float(a.visible[i] + a.material[i]);
}

/// Whitted's sum: the missed rays' background plus weight * local colour of every hit.
template <class T, class C>
image<T> compose(const frame& f, const std::vector<C>& local, int width, int height)
{
    image<T> img(width, height);
    for (std::size_t i = 0; i < img.pixels.size(); ++i) img.pixels[i] = glm::vec<3, T>(f.missed.pixels[i]);
    for (std::size_t i = 0; i < f.hits.size(); ++i)
        img.pixels[std::size_t(f.hits[i].pixel)] += glm::vec<3, T>(f.hits[i].weight) * glm::vec<3, T>(local[i]);
    return img;
}

/// The primary hits' local colours as an image (for the batch comparison; background elsewhere).
image<float> primary_image(const frame& f, const std::vector<vec3>& local, int width, int height, const vec3& background)
{
    image<float> img(width, height, background);
    for (std::size_t i = 0; i < f.primary.size(); ++i) img.pixels[std::size_t(f.primary[i].pixel)] = local[i];
    return img;
}

} // namespace

int main(int argc, char** argv)
{
    renderers::options opt{.width = 640, .height = 480};
    if (!renderers::parse(argc, argv, opt, "phong_whitted")) return 2;
    const int W = opt.width, H = opt.height;
    renderers::report out(opt.dir / "whitted.txt");
    out("phong_whitted: %dx%d, Whitted ray tracer (5 spheres, floor, depth 4), shading step only, median of %d reps, one thread\n",
        W, H, opt.reps);
    struct checks {
        int lights;
        renderers::image_diff exact_inline, stable_double, exact_double, batch_inline, incident_reuse, incident_stable_double;
    };
    std::vector<checks> results;
    std::vector<std::string> rows_cpu, rows_wall; // the timing tables, one row per light count
    std::vector<std::string> rows_given, rows_machine; // issue 27: phong with the shadow rays' l and distance against the expert inline
    std::vector<std::pair<int, double>> speedups; // scalar phong / batch on the primary hits (CPU time), per light count
    std::vector<coherence_stats> coherence;       // the primary hits' steps, per light count
    std::vector<std::pair<double, double>> floors; // ns per primary hit: stream_floor, and scalar phong / 4 (the batch target)
    for (const int light_count : {1, 2, 4}) {
        const scene sc = make_scene(light_count);
        const phong_scene ps = to_phong(sc);
        const frame f = trace_frame(sc, W, H);
        const std::size_t N = f.hits.size(), NP = f.primary.size();
        double visible = 0.0;
        for (const hit_record& h : f.hits) visible += double(std::popcount(h.visible));

        std::vector<vec3> c_reuse(N), c_incident(N), c_incident_stable(N);
        std::vector<vec3> c_inline(N), c_exact(N), c_stable(N), p_inline(NP), p_exact(NP), p_batch(NP), p_kernel(NP), p_floor(NP);
        std::vector<glm::dvec3> c_double(N);
        primary_arrays pa;
        for (const hit_record& h : f.primary) {
            pa.P.push_back(h.position);
            pa.n.push_back(h.normal);
            pa.v.push_back(h.view);
            pa.visible.push_back(h.visible);
            pa.material.push_back(std::uint32_t(h.material));
        }
        kernel_reference_input kernel_in = make_kernel_reference_input(pa);
        coherence.push_back(step_coherence(pa, light_count));
        const renderers::timings t = renderers::interleaved_medians(opt.reps, {
            [&] { shade_all_inline(f.hits, sc, c_inline); },
            [&] { shade_all_phong<phong_calls::whitted_exact>(f.hits, sc, ps, c_exact); },
            [&] { shade_all_phong<phong_calls::whitted_stable>(f.hits, sc, ps, c_stable); },
            [&] { shade_all_inline(f.primary, sc, p_inline); },
            [&] { shade_all_phong<phong_calls::whitted_exact>(f.primary, sc, ps, p_exact); },
            [&] { shade_all_batch(pa, sc, ps, p_batch); },
            [&] { shade_kernel_reference(kernel_in, ps, sc, p_kernel); },
            [&] { stream_floor(pa, p_floor); },
            [&] { shade_all_inline_reuse(f.hits, sc, c_reuse); },
            [&] { shade_all_incident<phong_calls::whitted_exact>(f.hits, sc, ps, c_incident); },
            [&] { shade_all_incident<phong_calls::whitted_stable>(f.hits, sc, ps, c_incident_stable); },
        });
        for (std::size_t i = 0; i < N; ++i) c_double[i] = shade_inline<double>(f.hits[i], sc);

        const double ns = 1e9 / double(N), pns = 1e9 / double(NP);
        for (const auto& [times, rows] : {std::pair{&t.cpu, &rows_cpu}, std::pair{&t.wall, &rows_wall}}) {
            const std::vector<double>& x = *times;
            char row[300];
            std::snprintf(row, sizeof row,
                          "%-6d %9zu %6.2f | %8.1f %8.1f (%.2f) %8.1f (%.2f) | %9zu %8.1f %8.1f (%.2f) %8.1f (%.2f) %8.1f %8.1f | %6.2fx\n",
                          light_count, N, visible / double(N), x[0] * ns, x[1] * ns, x[1] / x[0], x[2] * ns, x[2] / x[0], NP,
                          x[3] * pns, x[4] * pns, x[4] / x[3], x[5] * pns, x[5] / x[3], x[6] * pns, (x[5] - x[6]) * pns, x[4] / x[5]);
            rows->push_back(row);
        }
        speedups.push_back({light_count, t.cpu[4] / t.cpu[5]});
        {
            const std::vector<double>& x = t.cpu;
            char row[300];
            std::snprintf(row, sizeof row, "%-6d %9zu | %8.2f %8.2f | %8.2f (%.2f) %8.2f (%.2f) | %8.2f (%.2f)\n", light_count, N, x[0] * ns,
                          x[8] * ns, x[9] * ns, x[9] / x[8], x[10] * ns, x[10] / x[8], x[1] * ns, x[1] / x[8]);
            rows_given.push_back(row);
            std::snprintf(row, sizeof row, "TABLE27 whitted %d %.3f %.3f\n", light_count, x[9] / x[8], x[10] / x[8]);
            rows_machine.push_back(row);
        }
        floors.push_back({t.cpu[7] * pns, t.cpu[4] * pns / 4});

        const image<float> i_inline = compose<float>(f, c_inline, W, H), i_exact = compose<float>(f, c_exact, W, H),
                           i_stable = compose<float>(f, c_stable, W, H);
        const image<double> i_double = compose<double>(f, c_double, W, H);
        const std::string stem = "whitted_" + std::to_string(light_count) + "lights_";
        bool written = true;
        written &= renderers::write_png(opt.dir / (stem + "inline.png"), i_inline, stbi_write_png);
        written &= renderers::write_png(opt.dir / (stem + "phong.png"), i_exact, stbi_write_png);
        written &= renderers::write_png(opt.dir / (stem + "stable.png"), i_stable, stbi_write_png);
        written &= renderers::write_png(opt.dir / (stem + "double.png"), i_double, stbi_write_png);
        if (!written) return 1;
        using renderers::compare, renderers::to_rgb8;
        results.push_back({light_count, compare(to_rgb8(i_exact), to_rgb8(i_inline)), compare(to_rgb8(i_stable), to_rgb8(i_double)),
                           compare(to_rgb8(i_exact), to_rgb8(i_double)),
                           compare(to_rgb8(primary_image(f, p_batch, W, H, sc.background)),
                                   to_rgb8(primary_image(f, p_inline, W, H, sc.background))),
                           compare(to_rgb8(compose<float>(f, c_incident, W, H)), to_rgb8(compose<float>(f, c_reuse, W, H))),
                           compare(to_rgb8(compose<float>(f, c_incident_stable, W, H)), to_rgb8(i_double))});
    }
    for (const auto& [clock, rows] : {std::pair{"thread CPU time", &rows_cpu}, std::pair{"wall clock, steady_clock", &rows_wall}}) {
        out("\nns per shaded point, %s; (x) = ratio to inline; right: primary hits only, against inline over the same hits;\n"
            "kernel = shade_batch on the same hits pre-packed to SoA with one material; overhead = batch - kernel; "
            "speed-up = phong exact / batch\n", clock);
        out("%-6s %9s %6s | %8s %14s %14s | %9s %8s %14s %14s %8s %8s | %7s\n", "lights", "points", "vis/pt", "inline", "phong exact",
            "phong stable", "primary", "inline", "phong exact", "batch", "kernel", "overhead", "speed-up");
        for (const std::string& r : *rows) out("%s", r.c_str());
    }
    out("\nwith what the tracer has (issue 27): ns per shaded point, thread CPU time; expert inline = the shadow rays' l reused;\n"
        "phong exact / stable = shade_incident (l and distance given, unit n and v), (x) = ratio to the expert inline;\n"
        "phong shade<F> = the position-based call (recomputes L - P), for reference\n");
    out("%-6s %9s | %8s %8s | %15s %15s | %15s\n", "lights", "points", "inline", "expert", "phong exact", "phong stable", "phong shade<F>");
    for (const std::string& r : rows_given) out("%s", r.c_str());
    for (const std::string& r : rows_machine) out("%s", r.c_str());
    bool fast = true;
    out("\nbatch target (issue 13: shade_batch on the primary hits, packing included, >= 4x faster than scalar phong exact over the "
        "same hits, thread CPU time):");
    for (const auto& [lights, speedup] : speedups) out(" %d light%s %.2fx %s;", lights, lights == 1 ? "" : "s", speedup, renderers::verdict(speedup >= 4.0, fast));
    out(" %s\n", fast ? "PASS" : "FAIL");
    out("memory floor of the batch method (its %zu bytes per hit streamed, no shading; thread CPU time) against the 4x budget, "
        "ns per hit:", 3 * sizeof(vec3) + sizeof(std::uint64_t) + sizeof(std::uint32_t) + sizeof(vec3));
    for (std::size_t k = 0; k < floors.size(); ++k)
        out(" %d light%s %.2f / %.2f;", speedups[k].first, speedups[k].first == 1 ? "" : "s", floors[k].first, floors[k].second);
    out("\n");
    out("primary hits in steps of %zu: share of (step, light) pairs where no hit / every hit / some hits see the light "
        "(binning by mask could only move the last); steps with one material\n", phong::batch_width<float>);
    for (const coherence_stats& c : coherence)
        out("  %d light%s: %5.1f %% / %5.1f %% / %5.1f %%; %5.1f %%\n", c.lights, c.lights == 1 ? " " : "s", 100 * c.none, 100 * c.every,
            100 * c.some, 100 * c.one_material);
    out("\nimages (8-bit sRGB, %d pixels): pixels differing / max difference in levels\n", W * H);
    out("%-6s %-26s %-26s %-22s %-22s\n", "lights", "phong exact vs inline", "phong stable vs double", "(exact vs double)",
        "(batch vs inline, primary)");
    bool ok = true;
    for (const checks& c : results) {
        const bool a = c.exact_inline.max_levels <= 1, b = c.stable_double.max_levels <= 1;
        out("%-6d %7zu / %d %-12s %7zu / %d %-12s %7zu / %-12d %7zu / %d\n", c.lights, c.exact_inline.differing, c.exact_inline.max_levels,
            renderers::verdict(a, ok), c.stable_double.differing, c.stable_double.max_levels, renderers::verdict(b, ok),
            c.exact_double.differing, c.exact_double.max_levels, c.batch_inline.differing, c.batch_inline.max_levels);
    }
    out("shade_incident images: exact vs expert inline, stable vs double (pixels differing / max levels):");
    for (const checks& c : results) {
        const bool a = c.incident_reuse.max_levels <= 1, b = c.incident_stable_double.max_levels <= 1;
        out(" %d light%s %zu / %d %s, %zu / %d %s;", c.lights, c.lights == 1 ? "" : "s", c.incident_reuse.differing, c.incident_reuse.max_levels,
            renderers::verdict(a, ok), c.incident_stable_double.differing, c.incident_stable_double.max_levels, renderers::verdict(b, ok));
    }
    out("\n");
    out("image targets (max 1 level: phong exact vs inline, phong stable vs double): %s\n", ok ? "PASS" : "FAIL");
    return ok ? 0 : 1;
}
