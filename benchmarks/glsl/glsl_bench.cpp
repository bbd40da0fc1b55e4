// Throughput of the GLSL twin against seed 003's phong.vert on Mesa llvmpipe (headless EGL, OpenGL
// 4.1 core, GLSL 410 for both): the same model (presets::glsl_ads, one positional light), the same
// vertex buffers and uniforms, per-vertex shading captured by transform feedback (rasterizer off).
// The draws alternate (their order rotates each round); each draw is timed to its read-back (the
// map waits for the draw), in this thread's CPU time (see `now` below). The report: the median time of each, the ratio of the medians twin /
// seed and the median of the per-round ratios; and, for the shading alone, the same with a third
// program's median subtracted first: a pass-through shader with the same inputs and output (the
// vertex fetch and the transform feedback, which every program pays).
// Usage: phong_glsl_bench [vertices = 1048576] [rounds = 21]
#include "../../tests/glsl/seed003.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

namespace {
double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}
} // namespace

int main(int argc, char** argv)
{
    const int vertices = argc > 1 ? std::atoi(argv[1]) : 1 << 20;
    const int rounds = argc > 2 ? std::atoi(argv[2]) : 21;
    if (vertices < 1 || rounds < 1) {
        std::fprintf(stderr, "usage: phong_glsl_bench [vertices >= 1] [rounds >= 1]\n");
        return 2;
    }
    try {
        glt::context c(glt::api::gl41_core);
        std::printf("%s: %s (EGL %s)\n", c.renderer().c_str(), c.version().c_str(), c.platform().c_str());
        glt::feedback_program seed(c, glt::seed003_source(PHONG_SEED003_VERT), "LightIntensity");
        glt::feedback_program twin(c, glt::twin_ads_source(), "LightIntensity");
        glt::feedback_program pass(c, R"(#version 410
layout (location = 0) in vec3 VertexPosition;
layout (location = 1) in vec3 VertexNormal;
out vec3 LightIntensity;
uniform mat4 MVP;
void main() { LightIntensity = VertexNormal; gl_Position = MVP * vec4(VertexPosition, 1.0); }
)", "LightIntensity");
        std::mt19937 rng(11);
        std::uniform_real_distribution<float> box(-1.5f, 1.5f);
        std::vector<glm::vec3> positions(static_cast<std::size_t>(vertices)), normals(static_cast<std::size_t>(vertices));
        for (int i = 0; i < vertices; ++i) {
            positions[std::size_t(i)] = glm::vec3{box(rng), box(rng), box(rng)}; // braces: drawn in order
            normals[std::size_t(i)] = glm::normalize(glm::vec3{box(rng), box(rng), box(rng)} + glm::vec3(0, 0, 0.01f));
        }
        glt::vertex_buffers vb(c, positions, normals);
        glt::ads_uniforms u;
        u.model_view = glm::translate(glm::mat4(1), glm::vec3(0, 0, -6)) * glm::rotate(glm::mat4(1), 0.7f, glm::vec3(0.3f, 1, 0.2f));
        u.normal_matrix = phong::normal_matrix(u.model_view);
        u.projection = glm::perspective(0.8f, 1.3f, 0.1f, 100.0f);
        u.light.position = glm::vec4(2, 3, -2, 1);
        u.light.ambient = glm::vec3(0.1f);
        u.light.diffuse = glm::vec3(0.9f);
        u.light.specular = glm::vec3(0.7f);
        u.material = {glm::vec3(0.2f), glm::vec3(0.6f, 0.3f, 0.3f), glm::vec3(0.5f), glm::vec3(0), 40, 1};
        std::vector<double> t_seed, t_twin, t_pass, ratio;
        // This thread's CPU time: llvmpipe runs the vertex shader of a transform feedback draw with
        // the rasterizer off on the calling thread, and on a shared machine the wall time mostly
        // measures the other processes (ratios of wall-clock medians ranged 1.0 to 1.6 for one build).
        const auto now = [] {
            timespec t{};
            clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
            return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
        };
        const auto time = [&](const glt::feedback_program& p, bool is_seed) {
            const double start = now();
            p.run(vertices, 3, [&] {
                vb.attach();
                glt::set_ads_uniforms(c, p, u, is_seed);
            }); // the map of the feedback buffer waits for the draw
            return now() - start;
        };
        time(seed, true), time(twin, false), time(pass, true); // warm-up: shader compilation on first draw
        for (int r = 0; r < rounds; ++r) {
            double a = 0, b = 0, e = 0;
            for (int k = 0; k < 3; ++k) { // the order rotates: seed, twin, pass; twin, pass, seed; pass, seed, twin
                switch ((r + k) % 3) {
                case 0: a = time(seed, true); break;
                case 1: b = time(twin, false); break;
                default: e = time(pass, true); break;
                }
            }
            t_seed.push_back(a), t_twin.push_back(b), t_pass.push_back(e), ratio.push_back(b / a);
        }
        const double ms = median(t_seed), mt = median(t_twin), me = median(t_pass);
        const auto ns = [&](double t) { return t * 1e9 / vertices; };
        std::printf("vertices %d, rounds %d (interleaved), median thread CPU ns per vertex: seed 003 phong.vert %.2f, twin %.2f, "
                    "pass-through %.2f\n", vertices, rounds, ns(ms), ns(mt), ns(me));
        std::printf("twin / seed: ratio of medians %.3f, median of per-round ratios %.3f (min %.3f, max %.3f)\n", mt / ms,
                    median(ratio), *std::min_element(ratio.begin(), ratio.end()), *std::max_element(ratio.begin(), ratio.end()));
        std::printf("shading alone (pass-through subtracted): seed %.2f ns, twin %.2f ns per vertex, ratio %.3f\n", ns(ms - me),
                    ns(mt - me), (mt - me) / (ms - me));
    } catch (const std::exception& e) {
        std::fprintf(stderr, "phong_glsl_bench: %s\n", e.what());
        return 1;
    }
    return 0;
}
