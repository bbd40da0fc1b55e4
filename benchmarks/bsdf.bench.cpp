// The BSDFs (phong/bsdf.hpp) against the same functions written as Mitsuba 0.6 writes them
// (src/bsdfs/phong.cpp: std::pow for the lobe, cos a = pow(u, 1/(m+1)), sin a = sqrt(1 -
// pow(u, 2/(m+1))), Frame(R) by its coordinateSystem with a branch and a normalization), modified
// Phong, float and double, m = 1 .. 1e5. One item = sample(wo, u) (which evaluates pdf and f at
// the sampled direction, in both) + f(wo, wi) cos + pdf(wo, wi) at a second, prepared direction.
// Error counters, outside the timed loop, over the specular samples of the same inputs against a
// long double evaluation of the same u: dir_p99 / dir_max, the relative error of the sampled
// direction's offset from the mirror direction |wi - wi*| / sin a*; pdf_p99 / pdf_max, the relative
// error of the returned pdf against the exact pdf of the exact direction.
//
// Rows: bsdf.<phong|mitsuba>.<float|double>/m:<m>. Ratios: benchmarks/bsdf_ratio.sh (interleaved
// repetitions, medians; docs/bsdf.md).
#include <phong/bsdf.hpp>

#include <benchmark/benchmark.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace {

// ---- Mitsuba 0.6's phong, transcribed (scalar T, local frame, n = +z) ----
template <class T> struct mitsuba_phong {
    using vec3 = glm::vec<3, T>;
    vec3 kd, ks;
    T exponent, spec_weight;
    static constexpr T inv_pi = T(0.31830988618379067154), inv_two_pi = T(0.15915494309189533577), pi = T(3.14159265358979323846);

    static vec3 reflect(const vec3& w) { return {-w.x, -w.y, w.z}; }
    // Mitsuba's coordinateSystem(a, b, c).
    static void coordinate_system(const vec3& a, vec3& b, vec3& c)
    {
        if (std::abs(a.x) > std::abs(a.y)) {
            const T inv_len = T(1) / std::sqrt(a.x * a.x + a.z * a.z);
            c = vec3(a.z * inv_len, T(0), -a.x * inv_len);
        } else {
            const T inv_len = T(1) / std::sqrt(a.y * a.y + a.z * a.z);
            c = vec3(T(0), a.z * inv_len, -a.y * inv_len);
        }
        b = vec3(c.y * a.z - c.z * a.y, c.z * a.x - c.x * a.z, c.x * a.y - c.y * a.x);
    }
    vec3 eval(const vec3& wi, const vec3& wo) const // Mitsuba: bRec.wi = ours wo, bRec.wo = ours wi
    {
        if (wi.z <= 0 || wo.z <= 0) return vec3(0);
        vec3 result(0);
        const T alpha = glm::dot(wo, reflect(wi));
        if (alpha > 0) result += ks * ((exponent + 2) * inv_two_pi * std::pow(alpha, exponent));
        result += kd * inv_pi;
        return result * wo.z;
    }
    T pdf(const vec3& wi, const vec3& wo) const
    {
        if (wi.z <= 0 || wo.z <= 0) return 0;
        const T alpha = glm::dot(wo, reflect(wi));
        T spec = 0;
        if (alpha > 0) spec = std::pow(alpha, exponent) * (exponent + 1) / (2 * pi);
        const T diff = wo.z * inv_pi;
        return spec_weight * spec + (1 - spec_weight) * diff;
    }
    struct result { vec3 wo; T pdf; vec3 weight; };
    result sample(const vec3& wi, glm::vec<2, T> u) const
    {
        if (wi.z <= 0) return {vec3(0), 0, vec3(0)};
        vec3 wo;
        if (u.x <= spec_weight) {
            u.x /= spec_weight;
            const vec3 R = reflect(wi);
            const T sin_alpha = std::sqrt(1 - std::pow(u.y, 2 / (exponent + 1)));
            const T cos_alpha = std::pow(u.y, 1 / (exponent + 1));
            const T phi = 2 * pi * u.x;
            vec3 s, t;
            coordinate_system(R, s, t);
            wo = s * (sin_alpha * std::cos(phi)) + t * (sin_alpha * std::sin(phi)) + R * cos_alpha;
            if (wo.z <= 0) return {wo, 0, vec3(0)};
        } else {
            u.x = (u.x - spec_weight) / (1 - spec_weight);
            const T r = std::sqrt(u.y), phi = 2 * pi * u.x; // squareToCosineHemisphere (polar form)
            wo = vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(T(0), 1 - u.y)));
        }
        const T p = pdf(wi, wo);
        if (p == 0) return {wo, 0, vec3(0)};
        return {wo, p, eval(wi, wo) / p};
    }
};

template <class T> struct item { glm::vec<3, T> wo, wi; glm::vec<2, T> u; };

template <class T> std::vector<item<T>> make_items(std::size_t n)
{
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> U(0, 1);
    std::vector<item<T>> v;
    for (std::size_t i = 0; i < n; ++i) {
        const double c = 0.05 + 0.95 * U(rng), phi = 6.283185307179586 * U(rng), s = std::sqrt(1 - c * c);
        const double c2 = 0.05 + 0.95 * U(rng), phi2 = 6.283185307179586 * U(rng), s2 = std::sqrt(1 - c2 * c2);
        v.push_back({{T(s * std::cos(phi)), T(s * std::sin(phi)), T(c)},
                     {T(s2 * std::cos(phi2)), T(s2 * std::sin(phi2)), T(c2)},
                     {T(U(rng)), T(U(rng))}});
    }
    return v;
}

constexpr std::size_t n_items = 4096;

template <class T> phong::material<T> bench_material(double m)
{
    phong::material<T> mat;
    mat.kd = glm::vec<3, T>(T(0.3));
    mat.ks = glm::vec<3, T>(T(0.6));
    mat.shininess = T(m);
    return mat;
}

// Error counters: specular samples only, against long double (the same u, the same lobe choice).
template <class T, class Sample>
void error_counters(benchmark::State& state, double m, double p_spec, Sample sample)
{
    using ld = long double;
    const auto items = make_items<T>(n_items * 4);
    std::vector<double> dir, pdf;
    for (const auto& it : items) {
        if (!(double(it.u.x) < p_spec)) continue;
        const auto [wi, p] = sample(it.wo, it.u);
        if (!(p > 0)) continue;
        // Exact: the same u, in long double (the library's own stable form; -expm1(log u / (m+1))).
        const ld omc = -std::expm1(std::log(ld(it.u.y)) / (ld(T(m)) + 1));
        const ld ca = 1 - omc, sa = std::sqrt(omc * (2 - omc));
        const ld r[3] = {-ld(it.wo.x), -ld(it.wo.y), ld(it.wo.z)};
        // Any frame about r gives the same distribution but not the same direction: measure the
        // angle a of wi from r (the part of the error the sampling controls) and the pdf there.
        const ld cx = ld(wi.y) * r[2] - ld(wi.z) * r[1], cy = ld(wi.z) * r[0] - ld(wi.x) * r[2], cz = ld(wi.x) * r[1] - ld(wi.y) * r[0];
        const ld s = std::sqrt(cx * cx + cy * cy + cz * cz);
        dir.push_back(double(std::abs(s - sa) / sa));
        const ld pdf_exact = ld(T(p_spec)) * (ld(T(m)) + 1) / (2 * 3.14159265358979323846264L) * std::pow(ca, ld(T(m)));
        // The diffuse part of the mixture at wi, as the library computes it (not the error measured).
        const ld diffuse = (1 - ld(T(p_spec))) * ld(wi.z) / 3.14159265358979323846264L;
        pdf.push_back(double(std::abs(ld(p) - (pdf_exact + diffuse)) / (pdf_exact + diffuse)));
    }
    const auto pct = [](std::vector<double> v, double q) {
        if (v.empty()) return 0.0;
        std::sort(v.begin(), v.end());
        return v[std::min(v.size() - 1, std::size_t(q * double(v.size())))];
    };
    state.counters["dir_p99"] = pct(dir, 0.99);
    state.counters["dir_max"] = pct(dir, 1.0);
    state.counters["pdf_p99"] = pct(pdf, 0.99);
    state.counters["pdf_max"] = pct(pdf, 1.0);
}

template <class T> void bm_phong(benchmark::State& state)
{
    const double m = std::pow(10.0, double(state.range(0)));
    const phong::modified_phong_bsdf<T> b(bench_material<T>(m));
    const auto items = make_items<T>(n_items);
    for (auto _ : state) {
        T acc = 0;
        for (const auto& it : items) {
            const auto s = b.sample(it.wo, it.u);
            acc += s.weight.x + s.wi.x + b.eval_cos(it.wo, it.wi).x + b.pdf(it.wo, it.wi);
        }
        benchmark::DoNotOptimize(acc);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n_items));
    error_counters<T>(state, m, double(b.specular_probability), [&](const glm::vec<3, T>& wo, const glm::vec<2, T>& u) {
        const auto s = b.sample(wo, u);
        return std::pair{s.wi, s.pdf};
    });
}

template <class T> void bm_mitsuba(benchmark::State& state)
{
    const double m = std::pow(10.0, double(state.range(0)));
    const phong::material<T> mat = bench_material<T>(m);
    const T p = phong::detail::bsdf::luminance_probability(mat.kd, mat.ks);
    const mitsuba_phong<T> b{mat.kd, mat.ks, mat.shininess, p};
    const auto items = make_items<T>(n_items);
    for (auto _ : state) {
        T acc = 0;
        for (const auto& it : items) {
            const auto s = b.sample(it.wo, it.u);
            acc += s.weight.x + s.wo.x + b.eval(it.wo, it.wi).x + b.pdf(it.wo, it.wi);
        }
        benchmark::DoNotOptimize(acc);
    }
    state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(n_items));
    error_counters<T>(state, m, double(p), [&](const glm::vec<3, T>& wo, const glm::vec<2, T>& u) {
        const auto s = b.sample(wo, u);
        return std::pair{s.wo, s.pdf};
    });
}

} // namespace

BENCHMARK(bm_phong<float>)->Name("bsdf.phong.float")->ArgName("log10m")->DenseRange(0, 5);
BENCHMARK(bm_mitsuba<float>)->Name("bsdf.mitsuba.float")->ArgName("log10m")->DenseRange(0, 5);
BENCHMARK(bm_phong<double>)->Name("bsdf.phong.double")->ArgName("log10m")->DenseRange(0, 5);
BENCHMARK(bm_mitsuba<double>)->Name("bsdf.mitsuba.double")->ArgName("log10m")->DenseRange(0, 5);
