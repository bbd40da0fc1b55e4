// phong path tracer: the demo scene (raycast.hpp) path traced with phong's BSDFs (phong/bsdf.hpp),
// and a white-furnace check. One command renders everything:
//
//   phong_pathtrace [output_dir] [--spp N] [--size WxH]
//
// Writes pathtrace_phong.png (the modified Phong), pathtrace_blinn.png (the normalized
// Blinn-Phong) and furnace.png, and exits non-zero when the furnace check fails.
//
// The renderer: camera rays from the demo camera; at each hit the local frame of the normal
// (phong::local_frame, the normal turned toward the ray), the point lights and the directional
// light by next-event estimation (shadow ray, f cos L attenuation; the spot's cone is left out),
// the next direction by bsdf.sample (throughput *= weight), Russian roulette from depth 3, the
// background as a constant sky. A material with kd + ks > 1 (the demo's are tuned for the classic
// model) is scaled down to kd + ks = 1 in its brightest channel, as validate() requires.
//
// The furnace: one sphere inside a sky of radiance 1, nothing else. A convex object sees only the
// sky, so a pixel's expected value is the BSDF's directional albedo at that pixel's wo:
// exactly 1 for a white Lambertian sphere (kd = 1), albedo(wo) <= 1 for the glossy ones (their
// energy lost toward grazing). The check: the sample mean of each pixel against
// bsdf.albedo(wo) within 5 standard errors (its own sample variance), in at least 99.9 % of the
// pixels (96 x 96 pixels, 512 samples each), for the three spheres; and the Lambertian sphere's mean over all pixels equal to 1
// within 5 of its standard errors.
// SPDX-License-Identifier: MIT
#include "raycast.hpp"

#include <phong/bsdf.hpp>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#ifndef PHONG_RENDERERS_DEFAULT_DIR
#define PHONG_RENDERERS_DEFAULT_DIR "."
#endif

namespace {

using namespace phong_demo;

bool write_png(const std::filesystem::path& path, const image& img)
{
    std::vector<unsigned char> rgb(img.pixels.size() * 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) rgb[3 * i + std::size_t(c)] = to_srgb8(img.pixels[i][c]);
    if (stbi_write_png(path.string().c_str(), img.width, img.height, 3, rgb.data(), img.width * 3) == 0) {
        std::fprintf(stderr, "phong_pathtrace: cannot write %s\n", path.string().c_str());
        return false;
    }
    return true;
}

/// A material whose kd + ks exceeds 1 in a channel, scaled down so the brightest channel sums to 1.
phong::material<float> conserving(phong::material<float> m)
{
    float worst = 0;
    for (int c = 0; c < 3; ++c) worst = std::max(worst, m.kd[c] + m.ks[c]);
    if (worst > 1) {
        m.kd /= worst;
        m.ks /= worst;
    }
    return m;
}

struct rng_t {
    std::mt19937 gen;
    float next() { return float(gen() >> 8) * 0x1p-24f; } // [0, 1)
};

enum class model { phong, blinn, lambert };

/// One BSDF of either kind, built from the object's material.
struct any_bsdf {
    model kind;
    phong::modified_phong_bsdf<float> p;
    phong::blinn_phong_bsdf<float> b;
    any_bsdf(model k, const phong::material<float>& m) : kind(k), p(m), b(m) {}
    glm::vec3 eval_cos(const glm::vec3& wo, const glm::vec3& wi) const { return kind == model::blinn ? b.eval_cos(wo, wi) : p.eval_cos(wo, wi); }
    phong::bsdf_sample<float> sample(const glm::vec3& wo, glm::vec2 u) const { return kind == model::blinn ? b.sample(wo, u) : p.sample(wo, u); }
    glm::vec3 albedo(const glm::vec3& wo) const { return kind == model::blinn ? b.albedo(wo) : p.albedo(wo); }
};

/// Radiance along r: next-event estimation to the scene's lights, BSDF sampling for the rest.
glm::vec3 radiance(const scene& sc, const std::vector<any_bsdf>& bsdfs, ray r, rng_t& rng, glm::vec3 sky)
{
    glm::vec3 L(0.0f), throughput(1.0f);
    for (int depth = 0; depth < 16; ++depth) {
        const hit_record h = trace(sc, r, 1e-4f);
        if (h.object < 0) return L + throughput * sky;
        const glm::vec3 d = phong::detail::normalize(r.direction);
        const glm::vec3 n = phong::detail::dot(h.normal, d) > 0.0f ? -h.normal : h.normal; // toward the ray
        const phong::shading_frame<float> frame = phong::local_frame(n);
        const glm::vec3 wo = frame.to_local(-d);
        const any_bsdf& bsdf = bsdfs[std::size_t(h.object)];
        const glm::vec3 P = h.position + n * 1e-4f;
        for (const auto& light : sc.lights) {
            const glm::vec3 toward = glm::vec3(light.position) - light.position.w * P;
            const float dist = phong::detail::length(toward);
            const glm::vec3 wi_world = toward / dist;
            const glm::vec3 wi = frame.to_local(wi_world);
            if (!(wi.z > 0.0f)) continue;
            const float t_max = light.position.w > 0.0f ? 1.0f : std::numeric_limits<float>::infinity();
            if (occluded(sc, ray{P, toward}, 1e-4f, t_max)) continue;
            float att = 1.0f;
            if (light.position.w > 0.0f)
                att = 1.0f / (light.attenuation.constant + light.attenuation.linear * dist + light.attenuation.quadratic * dist * dist);
            L += throughput * bsdf.eval_cos(wo, wi) * light.diffuse * att;
        }
        const phong::bsdf_sample<float> s = bsdf.sample(wo, {rng.next(), rng.next()});
        if (!(s.pdf > 0.0f)) break;
        throughput *= s.weight;
        if (depth >= 3) { // Russian roulette
            const float q = std::min(0.95f, std::max({throughput.x, throughput.y, throughput.z}));
            if (rng.next() >= q) break;
            throughput /= q;
        }
        r = ray{P, frame.to_world(s.wi)};
    }
    return L;
}

image render(const scene& sc, const std::vector<any_bsdf>& bsdfs, const camera& cam, int spp, glm::vec3 sky, image* variance = nullptr)
{
    image img{cam.width, cam.height, std::vector<glm::vec3>(std::size_t(cam.width) * std::size_t(cam.height))};
    if (variance) *variance = img;
    const glm::mat4 inv = glm::inverse(cam.projection * cam.view);
    for (int y = 0; y < cam.height; ++y)
        for (int x = 0; x < cam.width; ++x) {
            rng_t rng{std::mt19937(std::uint32_t(y * cam.width + x) * 2654435761u + 12345u)};
            glm::vec3 sum(0.0f), sum2(0.0f);
            const ray r = primary_ray(cam, inv, x, y);
            for (int k = 0; k < spp; ++k) {
                const glm::vec3 v = radiance(sc, bsdfs, r, rng, sky);
                sum += v;
                sum2 += v * v;
            }
            img.at(x, y) = sum / float(spp);
            if (variance) variance->at(x, y) = glm::max(sum2 / float(spp) - img.at(x, y) * img.at(x, y), glm::vec3(0.0f)) / float(spp);
        }
    return img;
}

std::vector<any_bsdf> bsdfs_of(const scene& sc, model kind)
{
    std::vector<any_bsdf> v;
    for (const auto& o : sc.objects) v.emplace_back(kind, conserving(o.material));
    return v;
}

} // namespace

int main(int argc, char** argv)
{
    std::filesystem::path dir = PHONG_RENDERERS_DEFAULT_DIR;
    int spp = 64, width = 320, height = 240;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--spp") == 0 && i + 1 < argc) spp = std::atoi(argv[++i]);
        else if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc) std::sscanf(argv[++i], "%dx%d", &width, &height);
        else dir = argv[i];
    }
    std::filesystem::create_directories(dir);

    // The demo scene, both models.
    const scene sc = demo_scene();
    const camera cam = demo_camera(true, width, height);
    const glm::vec3 sky(0.15f, 0.17f, 0.22f);
    bool ok = true;
    for (const model kind : {model::phong, model::blinn}) {
        const image img = render(sc, bsdfs_of(sc, kind), cam, spp, sky);
        const char* name = kind == model::phong ? "pathtrace_phong.png" : "pathtrace_blinn.png";
        ok = write_png(dir / name, img) && ok;
        std::printf("%s: %dx%d, %d samples per pixel\n", name, width, height, spp);
    }

    // The white furnace: one sphere at a time in a sky of radiance 1.
    // 96 x 96 pixels, 512 samples each: the sample variance of a pixel is then a fair estimate
    // (the glossy weights are heavy-tailed: with a few samples the z-scores below mislead).
    const int fs = 96, fspp = 512;
    struct sphere_case { model kind; phong::material<float> mat; const char* name; };
    phong::material<float> white;
    white.kd = glm::vec3(1.0f);
    white.ks = glm::vec3(0.0f);
    phong::material<float> glossy;
    glossy.kd = glm::vec3(0.3f);
    glossy.ks = glm::vec3(0.7f);
    glossy.shininess = 40.0f;
    const sphere_case cases[] = {{model::lambert, white, "Lambertian kd = 1"},
                                 {model::phong, glossy, "modified Phong kd 0.3 ks 0.7 m 40"},
                                 {model::blinn, glossy, "Blinn-Phong kd 0.3 ks 0.7 m 40"}};
    image sheet{3 * fs, fs, std::vector<glm::vec3>(std::size_t(3 * fs) * std::size_t(fs))};
    camera fcam;
    fcam.view = glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0), glm::vec3(0, 1, 0));
    fcam.projection = glm::perspective(glm::radians(34.0f), 1.0f, 0.1f, 20.0f);
    fcam.width = fcam.height = fs;
    const glm::mat4 inv = glm::inverse(fcam.projection * fcam.view);
    for (int c = 0; c < 3; ++c) {
        scene fsc;
        fsc.objects.push_back(make_object(shape::sphere, glm::mat4(1.0f), cases[c].mat));
        fsc.shadows = false;
        const std::vector<any_bsdf> b{any_bsdf(cases[c].kind, cases[c].mat)};
        image var;
        const image img = render(fsc, b, fcam, fspp, glm::vec3(1.0f), &var);
        int pixels = 0, outliers = 0;
        double sum = 0, sum_var = 0, worst = 0, z_worst = 0;
        for (int y = 0; y < fs; ++y)
            for (int x = 0; x < fs; ++x) {
                sheet.at(c * fs + x, y) = img.at(x, y);
                const ray r = primary_ray(fcam, inv, x, y);
                const hit_record h = trace(fsc, r);
                if (h.object < 0) continue;
                const glm::vec3 d = phong::detail::normalize(r.direction);
                const phong::shading_frame<float> frame = phong::local_frame(h.normal);
                const double expected = double(b[0].albedo(frame.to_local(-d)).x);
                const double v = double(img.at(x, y).x), se = std::sqrt(double(var.at(x, y).x));
                const double z = se > 0 ? (v - expected) / se : (std::abs(v - expected) < 1e-5 ? 0 : 1e9);
                ++pixels;
                sum += v;
                sum_var += double(var.at(x, y).x);
                worst = std::max(worst, v);
                z_worst = std::max(z_worst, std::abs(z));
                if (std::abs(z) > 5) ++outliers;
            }
        const double mean = sum / pixels, mean_se = std::sqrt(sum_var) / pixels;
        bool pass = outliers <= pixels / 1000;
        if (cases[c].kind == model::lambert) pass = pass && std::abs(mean - 1) <= 5 * mean_se + 1e-6;
        std::printf("furnace, %s: %d pixels, mean %.5f (standard error %.5f), largest %.4f, |z| > 5 in %d (largest |z| %.2f): %s\n",
                    cases[c].name, pixels, mean, mean_se, worst, outliers, z_worst, pass ? "pass" : "FAIL");
        ok = ok && pass;
    }
    ok = write_png(dir / "furnace.png", sheet) && ok;
    std::printf("%s\n", ok ? "all checks passed" : "FAILED");
    return ok ? 0 : 1;
}
