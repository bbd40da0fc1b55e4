// Kernels for benchmarks/feature_cost.sh: each extern "C" noinline function shades the same
// points with one feature set, so `valgrind --tool=callgrind --toggle-collect=<kernel>` counts
// exactly the instructions of that kernel (and of the libm calls it makes), repeatably.
//
// Pairs checked by the script (a removed feature must cost nothing):
//   fc_phong_diffuse_directional  vs fc_hand_diffuse_directional   (no ambient, no specular, w = 0)
//   fc_phong_ads                  vs fc_hand_ads                   (seed 003: no attenuation, spot,
//                                                                   two-sided, emission, alpha)
// The hand-written kernels implement the same documented model, edge cases included (a zero
// normal or a light at Q gives no diffuse or specular, Q at the eye no specular; NaN/inf geometry gives NaN), the
// leanest direct way, with the same scalar kernels (phong::detail::sqrt, phong::detail::pow_unit) and the same
// formulas (dot products with d = L - Q, scaled by 1/|d| only for pairs that are on; the cheap
// sign test first), so the counts measure what shade<F>'s generic machinery adds; this program
// checks that each pair's outputs agree bit for bit, so the counts compare two computations of
// the same thing.
// The other kernels give the instruction cost of each feature (the script prints the differences).
//
// Usage: phong_feature_cost <kernel> [repeat]   runs <kernel> `repeat` times (default 1)
//        phong_feature_cost --check             runs every pair and compares outputs bit for bit
#include "baseline.hpp"
#include "inputs.hpp"

#include <phong/phong.hpp>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace {

using vec3 = glm::vec3;
using light = phong::light<float>;
using phong::features;

constexpr std::size_t N = 1024, K = 4;

struct data {
    std::vector<vec3> position, normal, out;
    std::vector<light> positional, directional, spot;
    phong::material<float> mat;
    phong::environment<float> env;
};

data& the_data()
{
    static data d = [] {
        data d;
        const phong_bench::scene sc = phong_bench::make_scene(phong_bench::input_set::typical, K);
        const phong_bench::points<float> pts = phong_bench::make_points<float>(phong_bench::input_set::typical, N, K);
        d.position = pts.position;
        d.normal = pts.normal;
        d.out.assign(N, vec3(0));
        d.positional = phong_bench::lights_of<float>(sc);
        d.directional = phong_bench::lights_of<float>(sc, phong_bench::light_style::directional);
        d.spot = d.positional;
        for (std::size_t i = 0; i < K; ++i) {
            d.positional[i].attenuation = {1.0f, 0.09f, 0.032f}; // read only by the attenuation kernels
            d.spot[i] = d.positional[i];
            d.spot[i].spot = phong::spot_cone<float>::opengl(glm::vec3(sc.spot_axis[i]), 8.0f, 60.0f);
        }
        d.mat = phong_bench::material_of<float>(sc);
        d.env = phong_bench::environment_of<float>(sc);
        return d;
    }();
    return d;
}

// The kernels share one shape: shade every point with the lights as a run-time span.
template <features F>
void shade_all(const vec3* position, const vec3* normal, std::size_t n, std::span<const light> lights,
               const phong::material<float>& mat, const phong::environment<float>& env, vec3* out)
{
    for (std::size_t i = 0; i < n; ++i) out[i] = phong::shade<F>(position[i], normal[i], mat, lights, env);
}

constexpr features diffuse_directional{.scene_ambient = false, .light_ambient = false, .diffuse = true,
                                       .specular = phong::specular_model::none, .lights = phong::light_kind::directional};
constexpr features ads = phong::presets::glsl_ads;

// x * 0: 0 for finite x, NaN for NaN or inf (the library's NaN policy, written directly; computed
// only when a squared length is not finite, the one case where an input can be NaN or inf).
inline float nan_poison(const vec3& q, const vec3& n)
{
    return (q.x * 0.0f + q.y * 0.0f + q.z * 0.0f) + (n.x * 0.0f + n.y * 0.0f + n.z * 0.0f);
}
inline float dot3(const vec3& a, const vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
// The exact mode drops a vector whose squared length is below the smallest normal float.
constexpr float tiny = std::numeric_limits<float>::min();

} // namespace

#define FC_KERNEL extern "C" __attribute__((noipa)) void // noipa: no inlining, cloning or constant propagation

FC_KERNEL fc_phong_diffuse_directional(const vec3* q, const vec3* n, std::size_t count, const light* L, std::size_t k,
                                       const phong::material<float>& mat, const phong::environment<float>& env, vec3* out)
{
    shade_all<diffuse_directional>(q, n, count, {L, k}, mat, env, out);
}

/// Hand-written: I = kd sum_i Ld_i max(n.l_i, 0), l_i = normalize(L_i.xyz), with phong's edges.
FC_KERNEL fc_hand_diffuse_directional(const vec3* q, const vec3* n, std::size_t count, const light* L, std::size_t k,
                                      const phong::material<float>& mat, const phong::environment<float>&, vec3* out)
{
    for (std::size_t i = 0; i < count; ++i) {
        const float nn = dot3(n[i], n[i]);
        const float in = nn >= tiny ? 1 / phong::detail::sqrt(nn) : 0.0f;
        const vec3 nh = n[i] * in;
        const float qq = dot3(q[i], q[i]); // only for the NaN test: the diffuse term does not need v
        float poison = 0;
        if (!(nn <= FLT_MAX && qq <= FLT_MAX)) poison = nan_poison(q[i], n[i]);
        const bool defined = in > 0 && poison == 0;
        vec3 sum(0);
        for (std::size_t j = 0; j < k; ++j) {
            const vec3 d(L[j].position.x, L[j].position.y, L[j].position.z);
            const float dd = dot3(d, d);
            const float nd = dot3(nh, d); // |d| (n.l): its sign is known before the square root
            if (defined && nd > 0 && dd >= tiny && dd <= FLT_MAX) sum += L[j].diffuse * (nd / phong::detail::sqrt(dd));
        }
        out[i] = vec3(poison) + mat.kd * sum;
    }
}

FC_KERNEL fc_phong_ads(const vec3* q, const vec3* n, std::size_t count, const light* L, std::size_t k,
                       const phong::material<float>& mat, const phong::environment<float>& env, vec3* out)
{
    shade_all<ads>(q, n, count, {L, k}, mat, env, out);
}

/// Hand-written seed 003 phong.vert summed over positional lights, with phong's edges:
/// I = ka sum La_i + kd sum Ld_i max(n.l, 0) + ks sum [n.l > 0] Ls_i clamp(r.v, 0, 1)^m with
/// |d| r.v = 2 (n.d)(n.v) - d.v (r = reflect(-l, n), n.v once per point, as phong computes it),
/// the power by phong::detail::pow_unit (the scalar kernel a hand-written shader would call instead of pow).
FC_KERNEL fc_hand_ads(const vec3* q, const vec3* n, std::size_t count, const light* L, std::size_t k,
                      const phong::material<float>& mat, const phong::environment<float>&, vec3* out)
{
    for (std::size_t i = 0; i < count; ++i) {
        const float nn = dot3(n[i], n[i]), qq = dot3(q[i], q[i]);
        const float in = nn >= tiny ? 1 / phong::detail::sqrt(nn) : 0.0f;
        const float iv = qq >= tiny ? 1 / phong::detail::sqrt(qq) : 0.0f;
        const vec3 nh = n[i] * in, v = -q[i] * iv;
        float poison = 0;
        if (!(nn <= FLT_MAX && qq <= FLT_MAX)) poison = nan_poison(q[i], n[i]);
        const bool defined = in > 0 && poison == 0; // Q at the eye (iv = 0): diffuse kept, no specular
        const float nv = dot3(nh, v);
        vec3 ambient(0), diffuse(0), specular(0);
        for (std::size_t j = 0; j < k; ++j) {
            ambient += L[j].ambient;
            const vec3 d = vec3(L[j].position.x, L[j].position.y, L[j].position.z) - q[i];
            const float dd = dot3(d, d);
            // Dot products with d, scaled by 1/|d| afterwards: their signs decide the branches
            // before the square root and the division are done.
            const float nd = dot3(nh, d), rvd = 2 * nd * nv - dot3(d, v); // |d| (n.l), |d| (r.v)
            if (defined && nd > 0 && dd >= tiny && dd <= FLT_MAX) {
                const float inv = 1 / phong::detail::sqrt(dd);
                diffuse += L[j].diffuse * (nd * inv);
                if (rvd > 0) specular += L[j].specular * phong::detail::pow_unit(std::min(rvd * inv, 1.0f), mat.shininess);
                else if (mat.shininess == 0 && iv > 0) specular += L[j].specular;
            }
        }
        out[i] = vec3(poison) + mat.ka * ambient + mat.kd * diffuse + mat.ks * specular;
    }
}

/// The naive GLM baseline of the benchmarks (support/baseline.hpp), for reference: seed 003 as a
/// user writes it (no guards, pow only where n.l > 0). Its lights are converted once, outside.
FC_KERNEL fc_naive_ads(const vec3* q, const vec3* n, std::size_t count, const std::vector<phong_bench::naive::LightInfo<float>>& lights,
                       const phong_bench::naive::MaterialInfo<float>& mat, vec3* out)
{
    for (std::size_t i = 0; i < count; ++i) out[i] = phong_bench::naive::ads(q[i], n[i], lights, mat);
}

// Feature costs: the seed 003 model with one feature changed.
#define FC_PHONG(name, F)                                                                                 \
    FC_KERNEL name(const vec3* q, const vec3* n, std::size_t count, const light* L, std::size_t k,          \
                   const phong::material<float>& mat, const phong::environment<float>& env, vec3* out)    \
    {                                                                                                     \
        shade_all<F>(q, n, count, {L, k}, mat, env, out);                                                 \
    }
namespace {
constexpr features phong_ads_spot_unused = [] { features f = ads; f.spot = phong::spot_model::opengl; return f; }();
constexpr features phong_ads_spot = [] { features f = ads; f.spot = phong::spot_model::opengl; return f; }();
constexpr features phong_ads_attenuation = [] { features f = ads; f.attenuation = phong::attenuation_model::polynomial; return f; }();
constexpr features phong_ads_two_sided = [] { features f = ads; f.two_sided = phong::facing::view; return f; }();
constexpr features phong_ads_any_kind = [] { features f = ads; f.lights = phong::light_kind::any; return f; }();
constexpr features phong_ads_blinn = [] { features f = ads; f.specular = phong::specular_model::blinn; return f; }();
constexpr features phong_ads_no_gate = [] { features f = ads; f.specular_gate = false; return f; }();
constexpr features phong_ads_scene_ambient = [] { features f = ads; f.scene_ambient = true; return f; }();
constexpr features phong_ads_stable = [] { features f = ads; f.mode = phong::evaluation::stable; return f; }();
constexpr features phong_ambient_diffuse = [] { features f = ads; f.specular = phong::specular_model::none; return f; }();
} // namespace

FC_PHONG(fc_phong_ads_spot_unused, phong_ads_spot_unused)
FC_PHONG(fc_phong_ads_spot, phong_ads_spot)
FC_PHONG(fc_phong_ads_attenuation, phong_ads_attenuation)
FC_PHONG(fc_phong_ads_two_sided, phong_ads_two_sided)
FC_PHONG(fc_phong_ads_any_kind, phong_ads_any_kind)
FC_PHONG(fc_phong_ads_blinn, phong_ads_blinn)
FC_PHONG(fc_phong_ads_no_gate, phong_ads_no_gate)
FC_PHONG(fc_phong_ads_scene_ambient, phong_ads_scene_ambient)
FC_PHONG(fc_phong_ads_stable, phong_ads_stable)
FC_PHONG(fc_phong_ambient_diffuse, phong_ambient_diffuse)

namespace {

using kernel_fn = void (*)(const vec3*, const vec3*, std::size_t, const light*, std::size_t, const phong::material<float>&,
                           const phong::environment<float>&, vec3*);
enum class lights { positional, directional, spot };
struct kernel {
    const char* name;
    kernel_fn fn;
    lights set;
};
const kernel kernels[] = {
    {"fc_phong_diffuse_directional", fc_phong_diffuse_directional, lights::directional},
    {"fc_hand_diffuse_directional", fc_hand_diffuse_directional, lights::directional},
    {"fc_phong_ads", fc_phong_ads, lights::positional},
    {"fc_hand_ads", fc_hand_ads, lights::positional},
    {"fc_phong_ads_spot_unused", fc_phong_ads_spot_unused, lights::positional},
    {"fc_phong_ads_spot", fc_phong_ads_spot, lights::spot},
    {"fc_phong_ads_attenuation", fc_phong_ads_attenuation, lights::positional},
    {"fc_phong_ads_two_sided", fc_phong_ads_two_sided, lights::positional},
    {"fc_phong_ads_any_kind", fc_phong_ads_any_kind, lights::positional},
    {"fc_phong_ads_blinn", fc_phong_ads_blinn, lights::positional},
    {"fc_phong_ads_no_gate", fc_phong_ads_no_gate, lights::positional},
    {"fc_phong_ads_scene_ambient", fc_phong_ads_scene_ambient, lights::positional},
    {"fc_phong_ads_stable", fc_phong_ads_stable, lights::positional},
    {"fc_phong_ambient_diffuse", fc_phong_ambient_diffuse, lights::positional},
    {"fc_naive_ads", nullptr, lights::positional},
};

std::vector<vec3> run(const kernel& kn, int repeat)
{
    data& d = the_data();
    const std::vector<light>& L = kn.set == lights::directional ? d.directional : kn.set == lights::spot ? d.spot : d.positional;
    if (kn.fn == nullptr) { // the naive baseline: its own light and material structs
        std::vector<phong_bench::naive::LightInfo<float>> L;
        for (const light& l : d.positional) L.push_back({l.position, l.ambient, l.diffuse, l.specular});
        const phong_bench::naive::MaterialInfo<float> mat{d.mat.ka, d.mat.kd, d.mat.ks, d.mat.shininess};
        for (int r = 0; r < repeat; ++r) fc_naive_ads(d.position.data(), d.normal.data(), N, L, mat, d.out.data());
        return d.out;
    }
    for (int r = 0; r < repeat; ++r) kn.fn(d.position.data(), d.normal.data(), N, L.data(), K, d.mat, d.env, d.out.data());
    return d.out;
}

const kernel* find(const char* name)
{
    for (const kernel& k : kernels)
        if (std::strcmp(k.name, name) == 0) return &k;
    return nullptr;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: %s <kernel> [repeat] | --check | --list\n", argv[0]);
        return 2;
    }
    if (std::strcmp(argv[1], "--list") == 0) {
        for (const kernel& k : kernels) std::printf("%s\n", k.name);
        return 0;
    }
    if (std::strcmp(argv[1], "--check") == 0) {
        int bad = 0;
        for (auto [a, b] : {std::pair{"fc_phong_diffuse_directional", "fc_hand_diffuse_directional"},
                            std::pair{"fc_phong_ads", "fc_hand_ads"}}) {
            const std::vector<vec3> x = run(*find(a), 1), y = run(*find(b), 1);
            const bool same = std::memcmp(x.data(), y.data(), x.size() * sizeof(vec3)) == 0;
            std::printf("%-30s %-30s outputs %s\n", a, b, same ? "bitwise equal" : "DIFFER");
            bad += !same;
        }
        return bad;
    }
    const kernel* k = find(argv[1]);
    if (!k) {
        std::fprintf(stderr, "unknown kernel %s (--list)\n", argv[1]);
        return 2;
    }
    const std::vector<vec3> out = run(*k, argc > 2 ? std::atoi(argv[2]) : 1);
    double checksum = 0;
    for (const vec3& c : out) checksum += double(c.x) + double(c.y) + double(c.z);
    std::printf("%s: %zu points x %zu lights, checksum %.9g\n", k->name, N, K, checksum);
    return 0;
}
