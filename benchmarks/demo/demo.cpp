// phong demo renderer: seed 001's primitives ray cast and shaded with phong::shade<F>, with
// reflection-based (phong) and halfway-based (blinn) specular, through a perspective and an
// orthographic camera. Writes one PNG per combination and an overview (demo.png, the four at
// half size), and prints the median frame time and the share of it spent in shading.
//
// Usage: phong_demo [output_dir] [--frames N] [--size WxH]
// SPDX-License-Identifier: MIT
#include "raycast.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#ifndef PHONG_DEMO_DEFAULT_DIR
#define PHONG_DEMO_DEFAULT_DIR "."
#endif

namespace {

using namespace phong_demo;

std::vector<unsigned char> to_rgb8(const image& img)
{
    std::vector<unsigned char> out(img.pixels.size() * 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) out[3 * i + std::size_t(c)] = to_srgb8(img.pixels[i][c]);
    return out;
}

bool write_png(const std::filesystem::path& path, int width, int height, const std::vector<unsigned char>& rgb)
{
    if (stbi_write_png(path.string().c_str(), width, height, 3, rgb.data(), width * 3) == 0) {
        std::fprintf(stderr, "phong_demo: cannot write %s\n", path.string().c_str());
        return false;
    }
    return true;
}

/// The image at half size (2x2 box filter in linear light) pasted into `sheet` at (x0, y0).
void paste_half(const image& img, image& sheet, int x0, int y0)
{
    for (int y = 0; y + 1 < img.height; y += 2)
        for (int x = 0; x + 1 < img.width; x += 2)
            sheet.at(x0 + x / 2, y0 + y / 2) =
                0.25f * (img.at(x, y) + img.at(x + 1, y) + img.at(x, y + 1) + img.at(x + 1, y + 1));
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

struct run_result {
    double frame_ms, frame_cpu_ms, shade_cpu_ms, shade_share;
};

/// Renders `frames` frames with features F, keeps the last image, and returns the medians.
template <phong::features F>
run_result run(const scene& sc, const camera& cam, int frames, image& img)
{
    std::vector<hit_record> gbuffer;
    std::vector<double> wall, cpu, shade, share;
    for (int i = 0; i < frames; ++i) {
        const frame_time t = render<F>(sc, cam, img, gbuffer);
        wall.push_back(t.total() * 1e3);
        cpu.push_back(t.total_cpu() * 1e3);
        shade.push_back(t.shade_cpu * 1e3);
        share.push_back(t.shade_cpu / t.total_cpu());
    }
    return {median(wall), median(cpu), median(shade), median(share)};
}

} // namespace

int main(int argc, char** argv)
{
    std::filesystem::path dir = PHONG_DEMO_DEFAULT_DIR;
    int frames = 7, width = 512, height = 384;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--frames" && i + 1 < argc) frames = std::max(1, std::atoi(argv[++i]));
        else if (a == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &width, &height) != 2 || width < 2 || height < 2) {
                std::fprintf(stderr, "phong_demo: --size WxH, e.g. 512x384\n");
                return 2;
            }
        } else if (a == "-h" || a == "--help") {
            std::printf("usage: phong_demo [output_dir] [--frames N] [--size WxH]\n");
            return 0;
        } else dir = a;
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);

    const scene sc = demo_scene();
    image sheet;
    sheet.width = width / 2 * 2;
    sheet.height = height / 2 * 2;
    sheet.pixels.assign(std::size_t(sheet.width) * std::size_t(sheet.height), sc.background);

    std::printf("phong demo: %dx%d, %zu objects, %zu lights, median of %d frames, one thread\n", width, height,
                sc.objects.size(), sc.lights.size(), frames);
    std::printf("(wall: elapsed time; cpu: the thread's CPU time; shading: share of the CPU time in the shading pass)\n");
    std::printf("%-26s %10s %10s %10s %8s\n", "image", "wall ms", "cpu ms", "shade ms", "shading");
    bool ok = true;
    int tile = 0;
    for (const bool perspective : {true, false}) {
        const camera cam = demo_camera(perspective, width, height);
        for (const bool blinn : {false, true}) {
            image img;
            const run_result r = blinn ? run<blinn_lighting>(sc, cam, frames, img) : run<phong_lighting>(sc, cam, frames, img);
            const std::string name =
                std::string(blinn ? "blinn" : "phong") + (perspective ? "_perspective" : "_orthographic") + ".png";
            std::printf("%-26s %10.2f %10.2f %10.2f %7.1f%%\n", name.c_str(), r.frame_ms, r.frame_cpu_ms, r.shade_cpu_ms,
                        100.0 * r.shade_share);
            ok = write_png(dir / name, width, height, to_rgb8(img)) && ok;
            paste_half(img, sheet, (tile % 2) * (width / 2), (tile / 2) * (height / 2));
            ++tile;
        }
    }
    ok = write_png(dir / "demo.png", sheet.width, sheet.height, to_rgb8(sheet)) && ok;
    std::printf("wrote phong_perspective.png, blinn_perspective.png, phong_orthographic.png, "
                "blinn_orthographic.png and demo.png (top: perspective, bottom: orthographic; left: phong, "
                "right: blinn) to %s\n",
                dir.string().c_str());
    return ok ? 0 : 1;
}
