// The GPU benchmark (docs/cuda.md): phong::shade<glsl_ads> in each mode beside the kernel a CUDA
// author writes for the same formula (glm::normalize, fmaxf, glm::reflect, powf or __powf), one
// thread per point, N points (positions and non-unit normals as glm::vec3), K = 1, 4 and 16
// positional lights in __constant__ memory. One process, the kernels' launches interleaved,
// medians of the repetitions, the device named in the output; accuracy against a long double
// evaluation of the formula written out on the host (every 8th point), NaN and inf counted over
// every point. Then the SFU bounds of phong/core/fast_sfu.hpp checked on the GPU against long double:
// fast::pow_unit over dense sweeps of x for several m, fast::rsqrt over every float in [1, 4).
// Exit status 1 if a bound fails or a kernel gives NaN or inf.
//
// Build and run (one GPU):
//   nvcc -std=c++20 --expt-relaxed-constexpr -O3 -arch=sm_90 -I include benchmarks/cuda/shade.cu -o shade_bench
//   ./shade_bench [repetitions = 21] [points = 4194304]
// CI compiles it (.ci/steps/50-cuda.sh) and counts the PTX instructions per light of the kernels
// count_* below (benchmarks/cuda/ptx_per_light.awk), with and without --use_fast_math.
#include <phong/accuracy.hpp> // fast::pow_unit_sfu_max_rel, rsqrt_sfu_max_rel
#include <phong/phong.hpp>

#include <cuda_runtime.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace {

constexpr int max_lights = 16;
__constant__ phong::light<float> lights_f[max_lights];
__constant__ phong::light<double> lights_d[max_lights];

using phong::evaluation;
using phong::stable_precision;
constexpr phong::features ads = phong::presets::glsl_ads; // La Ka + Ld Kd max(s.n, 0) + [s.n > 0] Ls Ks max(r.v, 0)^m
constexpr phong::features ads_fast = phong::presets::with_mode(ads, evaluation::fast);
constexpr phong::features ads_stable = phong::presets::with_mode(ads, evaluation::stable);
constexpr phong::features ads_twofold = [] {
    phong::features f = ads_stable;
    f.precision = stable_precision::twofold;
    return f;
}();

/// phong::shade in mode Set::value, scalar type T. K > 0: K lights known at compile time (the
/// timed kernels); K = 0: the count k at run time (the PTX count's kernels: one loop trip per light).
template <class Set, class T, int K>
__device__ __forceinline__ void phong_point(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                            const phong::material<T>& mat, int count, int k)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= count) return;
    const phong::light<T>* lights;
    if constexpr (std::is_same_v<T, float>) lights = lights_f;
    else lights = lights_d;
    const glm::vec<3, T> p(positions[i]), n(normals[i]);
    glm::vec<3, T> c;
    if constexpr (K > 0) c = phong::shade<Set::value>(p, n, mat, std::span<const phong::light<T>, K>(lights, K));
    else c = phong::shade<Set::value>(p, n, mat, std::span<const phong::light<T>>(lights, static_cast<std::size_t>(k)));
    out[i] = glm::vec3(c);
}

/// The feature set as a type (phong::feature_set): nvcc cannot take template <phong::features F> __global__.
template <class Set, class T, int K>
__global__ void phong_kernel(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out, phong::material<T> mat, int count, int k)
{
    phong_point<Set, T, K>(positions, normals, out, mat, count, k);
}

/// One light of the hand-written kernel: the GLSL ADS formula with glm and CUDA's own functions.
template <bool Fast>
__device__ __forceinline__ void hand_light(glm::vec3& c, const phong::light<float>& L, const glm::vec3& p, const glm::vec3& n,
                                           const glm::vec3& v, const phong::material<float>& mat)
{
    const glm::vec3 s = glm::normalize(glm::vec3(L.position) - p);
    const float sn = fmaxf(glm::dot(s, n), 0.0f);
    c += L.ambient * mat.ka + L.diffuse * mat.kd * sn;
    if (sn > 0.0f) {
        const float rv = fmaxf(glm::dot(glm::reflect(-s, n), v), 0.0f);
        c += L.specular * mat.ks * (Fast ? __powf(rv, mat.shininess) : powf(rv, mat.shininess));
    }
}

/// The hand-written kernel (powf, or __powf where Fast). K as in phong_point; K = 0 keeps the loop.
template <bool Fast, int K>
__device__ __forceinline__ void hand_point(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                           const phong::material<float>& mat, int count, int k)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i >= count) return;
    const glm::vec3 p = positions[i];
    const glm::vec3 n = glm::normalize(normals[i]);
    const glm::vec3 v = glm::normalize(-p);
    glm::vec3 c(0.0f);
    if constexpr (K > 0) {
#pragma unroll
        for (int j = 0; j < K; ++j) hand_light<Fast>(c, lights_f[j], p, n, v, mat);
    } else {
#pragma unroll 1
        for (int j = 0; j < k; ++j) hand_light<Fast>(c, lights_f[j], p, n, v, mat);
    }
    out[i] = c;
}

template <bool Fast, int K>
__global__ void hand_kernel(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out, phong::material<float> mat, int count, int k)
{
    hand_point<Fast, K>(positions, normals, out, mat, count, k);
}

/// fast::pow_unit and fast::rsqrt on the device, for the bound checks.
__global__ void pow_unit_kernel(const float* x, float m, float* out, int count)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i < count) out[i] = phong::fast::pow_unit(x[i], m);
}
__global__ void rsqrt_kernel(const float* x, float* out, int count)
{
    const int i = static_cast<int>(blockIdx.x * blockDim.x + threadIdx.x);
    if (i < count) out[i] = phong::fast::rsqrt(x[i]);
}

} // namespace

// The PTX count's kernels (.ci/steps/50-cuda.sh, benchmarks/cuda/ptx_per_light.awk): the light count
// at run time, one loop trip per light; phong's fast mode against the __powf kernel, the exact mode
// against the powf kernel. extern "C": plain names in the PTX, and emitted by -ptx alone.
extern "C" __global__ void count_phong_exact(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                             phong::material<float> mat, int count, int k)
{
    phong_point<phong::feature_set<ads>, float, 0>(positions, normals, out, mat, count, k);
}
extern "C" __global__ void count_phong_fast(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                            phong::material<float> mat, int count, int k)
{
    phong_point<phong::feature_set<ads_fast>, float, 0>(positions, normals, out, mat, count, k);
}
extern "C" __global__ void count_hand_powf(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                           phong::material<float> mat, int count, int k)
{
    hand_point<false, 0>(positions, normals, out, mat, count, k);
}
extern "C" __global__ void count_hand_fast_powf(const glm::vec3* positions, const glm::vec3* normals, glm::vec3* out,
                                                phong::material<float> mat, int count, int k)
{
    hand_point<true, 0>(positions, normals, out, mat, count, k);
}

namespace {

void check(cudaError_t e, const char* what)
{
    if (e != cudaSuccess) {
        std::fprintf(stderr, "shade_bench: %s: %s\n", what, cudaGetErrorString(e));
        std::exit(2);
    }
}

struct variant {
    std::string name;
    void (*launch)(const glm::vec3*, const glm::vec3*, glm::vec3*, float m, int count, int k, int blocks);
};

template <class Set, class T, int K>
void launch_phong(const glm::vec3* p, const glm::vec3* n, glm::vec3* o, float m, int count, int k, int blocks)
{
    // the float material's values in every T: the same scene, and the reference's inputs
    phong::material<T> mat{.ka = glm::vec<3, T>(T(0.2f)), .kd = glm::vec<3, T>(T(0.7f)), .ks = glm::vec<3, T>(T(0.5f)), .shininess = T(m)};
    phong_kernel<Set, T, K><<<blocks, 256>>>(p, n, o, mat, count, k);
}
template <bool Fast, int K>
void launch_hand(const glm::vec3* p, const glm::vec3* n, glm::vec3* o, float m, int count, int k, int blocks)
{
    phong::material<float> mat{.ka = glm::vec3(0.2f), .kd = glm::vec3(0.7f), .ks = glm::vec3(0.5f), .shininess = m};
    hand_kernel<Fast, K><<<blocks, 256>>>(p, n, o, mat, count, k);
}

template <int K>
std::vector<variant> variants_of()
{
    return {{"hand, powf", &launch_hand<false, K>},
            {"hand, __powf", &launch_hand<true, K>},
            {"phong exact", &launch_phong<phong::feature_set<ads>, float, K>},
            {"phong fast", &launch_phong<phong::feature_set<ads_fast>, float, K>},
            {"phong stable (wider)", &launch_phong<phong::feature_set<ads_stable>, float, K>},
            {"phong stable twofold", &launch_phong<phong::feature_set<ads_twofold>, float, K>},
            {"phong exact, double", &launch_phong<phong::feature_set<ads>, double, K>}};
}

/// The formula written out in long double (n, s, v normalized, r = 2 (s.n) n - s).
struct ref_light {
    long double p[3], la[3], ld[3], ls[3];
};
void reference(const glm::vec3& P, const glm::vec3& N, const std::vector<ref_light>& lights, int k, long double m, long double out[3])
{
    const long double ka = 0.2f, kd = 0.7f, ks = 0.5f; // the kernels' float material, exactly
    long double n[3] = {N.x, N.y, N.z}, v[3] = {-(long double)P.x, -(long double)P.y, -(long double)P.z};
    const auto unit = [](long double a[3]) {
        const long double l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        for (int c = 0; c < 3; ++c) a[c] /= l;
    };
    unit(n);
    unit(v);
    for (int c = 0; c < 3; ++c) out[c] = 0;
    for (int j = 0; j < k; ++j) {
        const ref_light& L = lights[j];
        long double s[3] = {L.p[0] - P.x, L.p[1] - P.y, L.p[2] - P.z};
        unit(s);
        const long double sn = s[0] * n[0] + s[1] * n[1] + s[2] * n[2];
        long double spec = 0;
        if (sn > 0) {
            long double rv = 0;
            for (int c = 0; c < 3; ++c) rv += (2 * sn * n[c] - s[c]) * v[c];
            spec = rv > 0 ? std::pow(rv, m) : 0;
        }
        for (int c = 0; c < 3; ++c) out[c] += L.la[c] * ka + L.ld[c] * kd * std::max(sn, 0.0L) + L.ls[c] * ks * spec;
    }
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

/// fast::pow_unit and fast::rsqrt on the device against long double, within phong/core/fast_sfu.hpp's bounds.
bool check_sfu_bounds()
{
    bool ok = true;
    std::vector<float> xs;
    for (int e = 1; e <= 40; ++e) // 2^14 points per binade [2^-e, 2^(1-e)), and 1
        for (int j = 0; j < (1 << 14); ++j) xs.push_back(std::ldexp(1.0f + float(j) / float(1 << 14), -e));
    xs.push_back(1.0f);
    const int count = static_cast<int>(xs.size());
    float *dx, *dout;
    check(cudaMalloc(&dx, sizeof(float) * xs.size()), "cudaMalloc");
    check(cudaMalloc(&dout, sizeof(float) * xs.size()), "cudaMalloc");
    check(cudaMemcpy(dx, xs.data(), sizeof(float) * xs.size(), cudaMemcpyHostToDevice), "cudaMemcpy");
    std::vector<float> got(xs.size());
    for (float m : {0.5f, 1.0f, 2.0f, 8.0f, 24.0f, 32.0f, 40.0f, 100.0f, 1000.0f, 10000.0f}) {
        pow_unit_kernel<<<(count + 255) / 256, 256>>>(dx, m, dout, count);
        check(cudaMemcpy(got.data(), dout, sizeof(float) * xs.size(), cudaMemcpyDeviceToHost), "pow_unit_kernel");
        const double bound = phong::fast::pow_unit_sfu_max_rel(m);
        double max_rel = 0, max_abs = 0;
        for (std::size_t i = 0; i < xs.size(); ++i) {
            const long double r = std::pow((long double)xs[i], (long double)m);
            const double err = double(std::fabs((long double)got[i] - r));
            if (!std::isfinite(got[i])) max_rel = max_abs = INFINITY;
            else if (r >= 0x1p-24L) max_rel = std::max(max_rel, double(err / r));
            else max_abs = std::max(max_abs, err);
        }
        const bool pass = max_rel <= bound && max_abs <= 0x1p-24 * bound;
        ok = ok && pass;
        std::printf("fast::pow_unit m = %-6g max_rel %.3g (bound %.3g), max_abs below 2^-24 %.3g (bound %.3g)  %s\n", m, max_rel,
                    bound, max_abs, 0x1p-24 * bound, pass ? "ok" : "FAIL");
    }
    check(cudaFree(dx), "cudaFree");
    check(cudaFree(dout), "cudaFree");
    // rsqrt: every float in [1, 4) (the relative error repeats every factor 4)
    const int n = 3 << 23;
    std::vector<float> rx(n);
    rx[0] = 1.0f;
    for (int i = 1; i < n; ++i) rx[i] = std::nextafter(rx[i - 1], 8.0f);
    check(cudaMalloc(&dx, sizeof(float) * n), "cudaMalloc");
    check(cudaMalloc(&dout, sizeof(float) * n), "cudaMalloc");
    check(cudaMemcpy(dx, rx.data(), sizeof(float) * n, cudaMemcpyHostToDevice), "cudaMemcpy");
    rsqrt_kernel<<<(n + 255) / 256, 256>>>(dx, dout, n);
    std::vector<float> rg(n);
    check(cudaMemcpy(rg.data(), dout, sizeof(float) * n, cudaMemcpyDeviceToHost), "rsqrt_kernel");
    double max_rel = 0;
    for (int i = 0; i < n; ++i) {
        const long double r = 1.0L / std::sqrt((long double)rx[i]);
        max_rel = std::max(max_rel, std::isfinite(rg[i]) ? double(std::fabs(rg[i] - r) / r) : INFINITY);
    }
    const bool pass = max_rel <= phong::fast::rsqrt_sfu_max_rel;
    ok = ok && pass;
    std::printf("fast::rsqrt over [1, 4): max_rel %.3g (bound %.3g)  %s\n", max_rel, phong::fast::rsqrt_sfu_max_rel, pass ? "ok" : "FAIL");
    check(cudaFree(dx), "cudaFree");
    check(cudaFree(dout), "cudaFree");
    return ok;
}

} // namespace

int main(int argc, char** argv)
{
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 21;
    const int count = argc > 2 ? std::max(1024, std::atoi(argv[2])) : 4194304;
    const int blocks = (count + 255) / 256;
    cudaDeviceProp prop{};
    check(cudaGetDeviceProperties(&prop, 0), "cudaGetDeviceProperties");
    int runtime = 0;
    cudaRuntimeGetVersion(&runtime);
    std::printf("device: %s (sm_%d%d), CUDA runtime %d, N = %d points, %d repetitions, median\n", prop.name, prop.major, prop.minor,
                runtime, count, reps);

    // A sphere of radius 1 at (0, 0, -4) in eye coordinates, normals of lengths 0.5 to 2.
    std::mt19937 rng(20261127);
    std::uniform_real_distribution<float> uni(-1.0f, 1.0f), len(0.5f, 2.0f);
    std::vector<glm::vec3> pos(count), nrm(count);
    for (int i = 0; i < count; ++i) {
        glm::vec3 d;
        do d = glm::vec3(uni(rng), uni(rng), uni(rng));
        while (glm::dot(d, d) < 0.01f || glm::dot(d, d) > 1.0f);
        d = glm::normalize(d);
        pos[i] = glm::vec3(0.0f, 0.0f, -4.0f) + d;
        nrm[i] = d * len(rng);
    }
    std::vector<phong::light<float>> lf(max_lights);
    std::vector<phong::light<double>> ld(max_lights);
    std::vector<ref_light> lr(max_lights);
    for (int j = 0; j < max_lights; ++j) {
        const float a = 6.2831853f * float(j) / max_lights;
        const glm::vec3 p(3.0f * std::cos(a), 2.0f * std::sin(3.0f * a), -4.0f + 3.0f * std::sin(a));
        const glm::vec3 colour(0.3f + 0.04f * float(j), 0.9f - 0.03f * float(j), 0.6f);
        lf[j].position = glm::vec4(p, 1.0f);
        lf[j].ambient = glm::vec3(0.05f);
        lf[j].diffuse = colour;
        lf[j].specular = colour;
        ld[j].position = glm::dvec4(lf[j].position);
        ld[j].ambient = glm::dvec3(lf[j].ambient);
        ld[j].diffuse = glm::dvec3(colour);
        ld[j].specular = glm::dvec3(colour);
        lr[j] = ref_light{{p.x, p.y, p.z}, {0.05f, 0.05f, 0.05f}, {colour.x, colour.y, colour.z}, {colour.x, colour.y, colour.z}};
    }
    check(cudaMemcpyToSymbol(lights_f, lf.data(), sizeof(phong::light<float>) * max_lights), "lights_f");
    check(cudaMemcpyToSymbol(lights_d, ld.data(), sizeof(phong::light<double>) * max_lights), "lights_d");
    glm::vec3 *dp, *dn, *dout;
    check(cudaMalloc(&dp, sizeof(glm::vec3) * count), "cudaMalloc");
    check(cudaMalloc(&dn, sizeof(glm::vec3) * count), "cudaMalloc");
    check(cudaMalloc(&dout, sizeof(glm::vec3) * count), "cudaMalloc");
    check(cudaMemcpy(dp, pos.data(), sizeof(glm::vec3) * count, cudaMemcpyHostToDevice), "cudaMemcpy");
    check(cudaMemcpy(dn, nrm.data(), sizeof(glm::vec3) * count, cudaMemcpyHostToDevice), "cudaMemcpy");
    cudaEvent_t start, stop;
    check(cudaEventCreate(&start), "cudaEventCreate");
    check(cudaEventCreate(&stop), "cudaEventCreate");

    bool ok = true;
    std::vector<glm::vec3> got(count);
    const float m_speed = 32.0f;
    for (int k : {1, 4, 16}) {
        const std::vector<variant> vs = k == 1 ? variants_of<1>() : k == 4 ? variants_of<4>() : variants_of<16>();
        std::vector<std::vector<double>> ms(vs.size());
        for (int r = -1; r < reps; ++r) // r = -1: warm-up, not kept
            for (std::size_t v = 0; v < vs.size(); ++v) {
                check(cudaEventRecord(start), "cudaEventRecord");
                vs[v].launch(dp, dn, dout, m_speed, count, k, blocks);
                check(cudaEventRecord(stop), "cudaEventRecord");
                check(cudaEventSynchronize(stop), "launch");
                float msec = 0;
                check(cudaEventElapsedTime(&msec, start, stop), "cudaEventElapsedTime");
                if (r >= 0) ms[v].push_back(msec);
            }
        std::printf("\nK = %d lights, m = %g: ps per (point, light), ratio to hand powf; accuracy against long double (every 8th point)\n",
                    k, m_speed);
        const float accuracy_m[2] = {32.0f, 1e4f};
        std::vector<double> refs[2]; // the reference of every 8th point, 3 channels, per m (rounded to double: 1e-16)
        for (int a = 0; a < 2; ++a) {
            refs[a].resize(3 * std::size_t((count + 7) / 8));
            for (int i = 0; i < count; i += 8) {
                long double ref[3];
                reference(pos[i], nrm[i], lr, k, accuracy_m[a], ref);
                for (int c = 0; c < 3; ++c) refs[a][3 * std::size_t(i / 8) + c] = double(ref[c]);
            }
        }
        const double base = median(ms[0]);
        for (std::size_t v = 0; v < vs.size(); ++v) {
            const double med = median(ms[v]);
            std::string acc;
            for (int a = 0; a < 2; ++a) {
                const float m = accuracy_m[a];
                vs[v].launch(dp, dn, dout, m, count, k, blocks);
                check(cudaMemcpy(got.data(), dout, sizeof(glm::vec3) * count, cudaMemcpyDeviceToHost), "result");
                long bad = 0;
                double max_rel = 0;
                for (int i = 0; i < count; ++i) {
                    for (int c = 0; c < 3; ++c) bad += std::isfinite(got[i][c]) ? 0 : 1;
                    if (i % 8 != 0) continue;
                    const double* ref = &refs[a][3 * std::size_t(i / 8)];
                    for (int c = 0; c < 3; ++c) max_rel = std::max(max_rel, std::fabs(double(got[i][c]) - ref[c]) / ref[c]);
                }
                if (bad > 0) ok = false;
                char buf[96];
                std::snprintf(buf, sizeof buf, "  m = %g: max_rel %.2e, NaN/inf %ld", m, max_rel, bad);
                acc += buf;
            }
            std::printf("  %-22s %8.3f (%.2f)%s\n", vs[v].name.c_str(), med * 1e9 / (double(count) * k), med / base, acc.c_str());
        }
    }
    std::printf("\n");
    ok = check_sfu_bounds() && ok;
    std::printf("%s\n", ok ? "shade_bench: every check passed" : "shade_bench: FAILED");
    return ok ? 0 : 1;
}
