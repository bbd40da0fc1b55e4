// Kernels for benchmarks/mode_cost.sh: what each evaluation mode and number type costs against
// the lighting a renderer writes inline (docs/models.md, 'What each mode costs'). Every kernel
// shades the same 1024 points x 4 positional lights with document 003's model (ambient, Lambert,
// Phong specular gated on n.l > 0, the eye at the origin), in float or double:
//   mc_inline_<T>              the lighting written inline on GLM (normalize, reflect, std::pow)
//   mc_inline_incident_<T>     the same, with each light's unit direction given (a ray tracer's
//                              shadow rays have it)
//   mc_shade_<mode>_<T>        phong::shade<presets::glsl_ads with that mode>
//   mc_incident_<mode>_<T>     phong::shade_incident<...> with the same directions given
// extern "C" noipa functions, so `valgrind --tool=callgrind --toggle-collect=<kernel>` counts one
// kernel with the libm calls it makes, repeatably; with --time it times them instead, interleaved.
//
// Usage: phong_mode_cost <kernel>    runs <kernel> once
//        phong_mode_cost --list      the kernels
//        phong_mode_cost --time [R]  thread CPU time per (point, light), median of R rounds (default
//                                    31), every kernel once per round, in turn
#include "inputs.hpp"

#include <phong/phong.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

constexpr std::size_t N = 1024, K = 4;

template <class T> struct data {
    std::vector<glm::vec<3, T>> position, normal, out;
    std::vector<phong::light<T>> lights;
    std::vector<phong::incident<T>> incidents; // N x K: each point's light directions and distances
    phong::material<T> mat;
    phong::environment<T> env;
};

template <class T> data<T>& the_data()
{
    static data<T> d = [] {
        data<T> d;
        const phong_bench::scene sc = phong_bench::make_scene(phong_bench::input_set::typical, K);
        const phong_bench::points<T> pts = phong_bench::make_points<T>(phong_bench::input_set::typical, N, K);
        d.position = pts.position;
        d.normal = pts.normal;
        for (auto& n : d.normal) n = n / std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z); // unit, as a renderer's
        d.out.assign(N, glm::vec<3, T>(0));
        d.lights = phong_bench::lights_of<T>(sc);
        d.mat = phong_bench::material_of<T>(sc);
        d.mat.emission = glm::vec<3, T>(0);
        d.env = phong_bench::environment_of<T>(sc);
        for (std::size_t i = 0; i < N; ++i)
            for (const auto& L : d.lights) {
                const glm::vec<3, T> v = glm::vec<3, T>(L.position) - d.position[i];
                const T len = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
                d.incidents.push_back({v / len, len});
            }
        return d;
    }();
    return d;
}

template <class T> T dot3(const glm::vec<3, T>& a, const glm::vec<3, T>& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// Document 003's shader in C++, as a renderer writes it inline: s = normalize(L - Q), r = reflect(-s, n),
// v = normalize(-Q), specular only where s.n > 0.
template <class T, bool Given>
void inline_lighting(data<T>& d)
{
    using vec3 = glm::vec<3, T>;
    for (std::size_t i = 0; i < N; ++i) {
        const vec3 q = d.position[i], n = d.normal[i];
        const vec3 v = -q / std::sqrt(dot3(q, q));
        vec3 c = d.mat.ka * d.env.ambient;
        for (std::size_t k = 0; k < K; ++k) {
            const auto& L = d.lights[k];
            vec3 s;
            if constexpr (Given) s = d.incidents[i * K + k].direction;
            else {
                const vec3 to = vec3(L.position) - q;
                s = to / std::sqrt(dot3(to, to));
            }
            const T sn = std::max(dot3(s, n), T(0));
            c += L.ambient * d.mat.ka + L.diffuse * d.mat.kd * sn;
            if (sn > T(0)) {
                const vec3 r = T(2) * dot3(n, s) * n - s;
                c += L.specular * d.mat.ks * std::pow(std::max(dot3(r, v), T(0)), d.mat.shininess);
            }
        }
        d.out[i] = c;
    }
}

template <phong::evaluation M> constexpr phong::features ads = [] {
    phong::features f = phong::presets::glsl_ads;
    f.mode = M;
    return f;
}();
template <phong::evaluation M> constexpr phong::features ads_unit = [] {
    phong::features f = ads<M>;
    f.unit_inputs = true; // the normals are unit and the directions given: what shade_incident is for
    f.view = phong::view_model::given; // v = -Q / |Q|, passed
    return f;
}();

template <class T, phong::evaluation M> void shade_all(data<T>& d)
{
    for (std::size_t i = 0; i < N; ++i) d.out[i] = phong::shade<ads<M>>(d.position[i], d.normal[i], d.mat, d.lights, d.env);
}
template <class T, phong::evaluation M> void incident_all(data<T>& d)
{
    for (std::size_t i = 0; i < N; ++i) {
        const glm::vec<3, T> q = d.position[i];
        const glm::vec<3, T> v = -q / std::sqrt(dot3(q, q));
        d.out[i] = phong::shade_incident<ads_unit<M>>(d.normal[i], v, d.mat, d.lights,
                                                     std::span(d.incidents).subspan(i * K, K), d.env);
    }
}

} // namespace

#if defined(__clang__)
#define MC_NOIPA __attribute__((noinline))
#else
#define MC_NOIPA __attribute__((noipa)) // no inlining, cloning or constant propagation
#endif
#define MC_KERNEL(name, call) extern "C" MC_NOIPA void name() { call; }
MC_KERNEL(mc_inline_float, (inline_lighting<float, false>(the_data<float>())))
MC_KERNEL(mc_inline_double, (inline_lighting<double, false>(the_data<double>())))
MC_KERNEL(mc_inline_incident_float, (inline_lighting<float, true>(the_data<float>())))
MC_KERNEL(mc_inline_incident_double, (inline_lighting<double, true>(the_data<double>())))
MC_KERNEL(mc_shade_exact_float, (shade_all<float, phong::evaluation::exact>(the_data<float>())))
MC_KERNEL(mc_shade_stable_float, (shade_all<float, phong::evaluation::stable>(the_data<float>())))
MC_KERNEL(mc_shade_fast_float, (shade_all<float, phong::evaluation::fast>(the_data<float>())))
MC_KERNEL(mc_shade_exact_double, (shade_all<double, phong::evaluation::exact>(the_data<double>())))
MC_KERNEL(mc_shade_stable_double, (shade_all<double, phong::evaluation::stable>(the_data<double>())))
MC_KERNEL(mc_shade_fast_double, (shade_all<double, phong::evaluation::fast>(the_data<double>())))
MC_KERNEL(mc_incident_exact_float, (incident_all<float, phong::evaluation::exact>(the_data<float>())))
MC_KERNEL(mc_incident_stable_float, (incident_all<float, phong::evaluation::stable>(the_data<float>())))
MC_KERNEL(mc_incident_fast_float, (incident_all<float, phong::evaluation::fast>(the_data<float>())))
MC_KERNEL(mc_incident_exact_double, (incident_all<double, phong::evaluation::exact>(the_data<double>())))
MC_KERNEL(mc_incident_stable_double, (incident_all<double, phong::evaluation::stable>(the_data<double>())))
MC_KERNEL(mc_incident_fast_double, (incident_all<double, phong::evaluation::fast>(the_data<double>())))

namespace {
struct kernel { const char* name; void (*run)(); };
constexpr kernel kernels[] = {
    {"mc_inline_float", mc_inline_float}, {"mc_inline_double", mc_inline_double},
    {"mc_inline_incident_float", mc_inline_incident_float}, {"mc_inline_incident_double", mc_inline_incident_double},
    {"mc_shade_exact_float", mc_shade_exact_float}, {"mc_shade_stable_float", mc_shade_stable_float},
    {"mc_shade_fast_float", mc_shade_fast_float}, {"mc_shade_exact_double", mc_shade_exact_double},
    {"mc_shade_stable_double", mc_shade_stable_double}, {"mc_shade_fast_double", mc_shade_fast_double},
    {"mc_incident_exact_float", mc_incident_exact_float}, {"mc_incident_stable_float", mc_incident_stable_float},
    {"mc_incident_fast_float", mc_incident_fast_float}, {"mc_incident_exact_double", mc_incident_exact_double},
    {"mc_incident_stable_double", mc_incident_stable_double}, {"mc_incident_fast_double", mc_incident_fast_double},
};
double thread_seconds()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
} // namespace

int main(int argc, char** argv)
{
    (void)the_data<float>(), (void)the_data<double>(); // made before any count or timing
    const std::string arg = argc > 1 ? argv[1] : "--list";
    if (arg == "--list") {
        for (const auto& k : kernels) std::printf("%s\n", k.name);
        return 0;
    }
    if (arg == "--time") {
        const int rounds = argc > 2 ? std::atoi(argv[2]) : 31;
        std::vector<std::vector<double>> t(std::size(kernels));
        for (int r = 0; r < rounds; ++r)
            for (std::size_t k = 0; k < std::size(kernels); ++k) {
                const double t0 = thread_seconds();
                for (int rep = 0; rep < 8; ++rep) kernels[k].run();
                t[k].push_back((thread_seconds() - t0) / (8.0 * N * K) * 1e9);
            }
        for (std::size_t k = 0; k < std::size(kernels); ++k) {
            std::nth_element(t[k].begin(), t[k].begin() + rounds / 2, t[k].end());
            std::printf("%s\t%.3f\n", kernels[k].name, t[k][rounds / 2]);
        }
        return 0;
    }
    for (const auto& k : kernels)
        if (arg == k.name) {
            k.run();
            return 0;
        }
    std::fprintf(stderr, "phong_mode_cost: no kernel %s (--list)\n", arg.c_str());
    return 2;
}
