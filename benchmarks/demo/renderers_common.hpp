// phong end-to-end renderers (issue 13, item 7): what whitted.cpp and raster.cpp share, none of
// it lighting: images, PNG output, image comparison in 8-bit levels, median timing, the command
// line and the report (stdout and <dir>/<name>.txt).
// SPDX-License-Identifier: MIT
#pragma once

#include <glm/vec3.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <time.h> // clock_gettime, CLOCK_THREAD_CPUTIME_ID (POSIX)

#ifndef PHONG_RENDERERS_DEFAULT_DIR
#define PHONG_RENDERERS_DEFAULT_DIR "."
#endif

namespace renderers {

/// A linear-light RGB image in T (float, or double for the reference), row 0 at the top.
template <class T> struct image {
    int width = 0, height = 0;
    std::vector<glm::vec<3, T>> pixels;
    image() = default;
    image(int w, int h, glm::vec<3, T> fill = glm::vec<3, T>(T(0)))
        : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), fill) {}
};

/// Linear light to 8-bit sRGB (the exact sRGB curve, evaluated in double), clamped to [0, 1].
inline int to_srgb8(double linear)
{
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return int(std::lround(s * 255.0));
}

template <class T> std::vector<unsigned char> to_rgb8(const image<T>& img)
{
    std::vector<unsigned char> out(img.pixels.size() * 3);
    for (std::size_t i = 0; i < img.pixels.size(); ++i)
        for (int c = 0; c < 3; ++c) out[3 * i + std::size_t(c)] = static_cast<unsigned char>(to_srgb8(double(img.pixels[i][c])));
    return out;
}

/// Pixels (of the 8-bit sRGB images) that differ, and the largest difference in levels.
struct image_diff {
    std::size_t differing = 0;
    int max_levels = 0;
};
inline image_diff compare(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
    image_diff d;
    for (std::size_t i = 0; i + 2 < a.size() && i + 2 < b.size(); i += 3) {
        int m = 0;
        for (std::size_t c = 0; c < 3; ++c) m = std::max(m, std::abs(int(a[i + c]) - int(b[i + c])));
        if (m > 0) ++d.differing;
        d.max_levels = std::max(d.max_levels, m);
    }
    return d;
}

inline double median(std::vector<double> t)
{
    std::sort(t.begin(), t.end());
    const std::size_t n = t.size();
    return n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
}

/// The calling thread's CPU time in seconds (POSIX CLOCK_THREAD_CPUTIME_ID, as the demo's
/// raycast.hpp): on a machine shared with other jobs, time spent descheduled is not counted.
inline double thread_seconds()
{
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

/// Medians, in seconds, of each method's time: thread CPU time and steady_clock wall time.
struct timings {
    std::vector<double> cpu, wall;
};

/// Each method timed `reps` times around its whole call; the methods run in turn within a round,
/// so a change of the machine's load falls on all of them alike rather than on one.
inline timings interleaved_medians(int reps, const std::vector<std::function<void()>>& methods)
{
    std::vector<std::vector<double>> cpu(methods.size()), wall(methods.size());
    for (int r = 0; r < reps; ++r)
        for (std::size_t m = 0; m < methods.size(); ++m) {
            const double c0 = thread_seconds();
            const auto t0 = std::chrono::steady_clock::now();
            methods[m]();
            const auto t1 = std::chrono::steady_clock::now();
            const double c1 = thread_seconds();
            wall[m].push_back(std::chrono::duration<double>(t1 - t0).count());
            cpu[m].push_back(c1 - c0);
        }
    timings out;
    for (std::size_t m = 0; m < methods.size(); ++m) {
        out.cpu.push_back(median(cpu[m]));
        out.wall.push_back(median(wall[m]));
    }
    return out;
}

/// Command line: [output_dir] [--size WxH] [--reps N]; the environment variable
/// PHONG_RENDERERS_SIZE=WxH overrides the default size (CI: a small run through the CMake target).
struct options {
    std::filesystem::path dir = PHONG_RENDERERS_DEFAULT_DIR;
    int width, height, reps = 9;
};
inline bool parse(int argc, char** argv, options& o, const char* name)
{
    if (const char* s = std::getenv("PHONG_RENDERERS_SIZE"))
        if (std::sscanf(s, "%dx%d", &o.width, &o.height) != 2) return false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--size" && i + 1 < argc) {
            if (std::sscanf(argv[++i], "%dx%d", &o.width, &o.height) != 2) return false;
        } else if (a == "--reps" && i + 1 < argc) {
            o.reps = std::max(1, std::atoi(argv[++i]));
        } else if (a == "-h" || a == "--help" || a.starts_with("-")) {
            std::printf("usage: %s [output_dir] [--size WxH] [--reps N]\n", name);
            return false;
        } else {
            o.dir = a;
        }
    }
    if (o.width < 8 || o.height < 8) return false;
    std::error_code ec;
    std::filesystem::create_directories(o.dir, ec);
    return true;
}

/// The report: printed, and written to <dir>/<name>.txt.
class report {
public:
    explicit report(const std::filesystem::path& path) : file_(std::fopen(path.string().c_str(), "w")) {}
    ~report()
    {
        if (file_) std::fclose(file_);
    }
    report(const report&) = delete;
    report& operator=(const report&) = delete;
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    void operator()(const char* fmt, ...)
    {
        std::va_list a;
        va_start(a, fmt);
        std::vprintf(fmt, a);
        va_end(a);
        if (file_) {
            va_start(a, fmt);
            std::vfprintf(file_, fmt, a);
            va_end(a);
        }
        std::fflush(stdout);
    }

private:
    std::FILE* file_;
};

/// Writes an image as PNG (stb_image_write, defined by the including .cpp); false on failure.
template <class T> bool write_png(const std::filesystem::path& path, const image<T>& img, int (*writer)(const char*, int, int, int, const void*, int))
{
    const std::vector<unsigned char> rgb = to_rgb8(img);
    if (writer(path.string().c_str(), img.width, img.height, 3, rgb.data(), img.width * 3) == 0) {
        std::fprintf(stderr, "cannot write %s\n", path.string().c_str());
        return false;
    }
    return true;
}

/// The check an image target makes: "PASS" or "FAIL", and the running verdict.
inline const char* verdict(bool ok, bool& all_ok)
{
    all_ok = all_ok && ok;
    return ok ? "PASS" : "FAIL";
}

} // namespace renderers
