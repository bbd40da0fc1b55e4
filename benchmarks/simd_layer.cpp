// Why batch.hpp uses xsimd: the same shade kernels (detail::prepare, add_light, finish) run on
// xsimd batches and on libstdc++'s std::experimental::simd, exact mode, float, Phong with
// attenuation, N = 65536 points, K = 1 / 4 / 16 lights, median of 7 runs, ns per (point, light).
// libstdc++ 12's <experimental/simd> computes exp, log and pow one lane at a time.
// Run: build/bench/benchmarks/phong_simd_layer
// g++ 12 reports the _mm512_undefined_* placeholders inside its AVX-512 intrinsics (used by both
// SIMD libraries) as uninitialized once inlined; batch.hpp silences this for its own code.
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic ignored "-Wuninitialized"
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <experimental/simd>
#include <phong/batch.hpp>
#include <chrono>
#include <cstdio>
#include <random>
#include <algorithm>
namespace stdx = std::experimental;
using SV = stdx::native_simd<float>;
namespace phong {
template <> struct phong::detail::math_traits<SV> {
    using V = SV; using scalar = float; using mask = typename SV::mask_type;
    static V sqrt(const V& x) { return stdx::sqrt(x); }
    static V rsqrt(const V& x) { return V(1.f) / stdx::sqrt(x); }
    static V exp(const V& x) { return stdx::exp(x); }
    static V log(const V& x) { return stdx::log(x); }
    static V log1p(const V& x) { return stdx::log1p(x); }
    static V pow(const V& x, const V& y) { return stdx::pow(x, y); }
    static V fma(const V& a, const V& b, const V& c) { return stdx::fma(a, b, c); }
    static V madd(const V& a, const V& b, const V& c) { return a * b + c; } // the dot's sums: contracted by the compiler
    static V select(const mask& m, const V& a, const V& b) { V r = b; stdx::where(m, r) = a; return r; }
    static bool any(const mask& m) { return stdx::any_of(m); }
    static bool all(const mask& m) { return stdx::all_of(m); }
    static mask both(const mask& a, const mask& b) { return a && b; }
    static V abs(const V& x) { return stdx::abs(x); }
    static V min(const V& a, const V& b) { return stdx::min(a, b); }
    static V max(const V& a, const V& b) { return stdx::max(a, b); }
    static V inverse_pow2_scale(const V& x) { return V([&](auto i) { return phong::detail::math_traits<float>::inverse_pow2_scale(x[i]); }); }
};
}
using namespace phong;
constexpr features F{.specular = specular_model::phong, .lights = light_kind::positional, .attenuation = attenuation_model::polynomial, .mode = evaluation::exact};
template <class V> double run(int K, const std::vector<float>* p, const std::vector<float>* n, std::vector<float>* out, const std::vector<light<float>>& L) {
    constexpr std::size_t W = sizeof(V) / sizeof(float);
    std::vector<light<V>> lv; for (auto& l : L) lv.push_back(detail::splat<V>(l));
    material<float> m0; m0.shininess = 50; material<V> m = detail::splat<V>(m0);
    environment<V> env{glm::vec<3, V>(V(0.1f)), glm::vec<4, V>(V(0.f), V(0.f), V(0.f), V(1.f))};
    const std::size_t N = p[0].size();
    std::vector<double> t;
    for (int rep = 0; rep < 7; ++rep) {
        auto t0 = std::chrono::steady_clock::now();
        for (std::size_t i = 0; i < N; i += W) {
            auto ld = [&](const std::vector<float>& a) { if constexpr (std::is_same_v<V, SV>) return V(&a[i], stdx::element_aligned); else return V::load_unaligned(&a[i]); };
            auto s = detail::prepare<F>(glm::vec<3, V>(ld(p[0]), ld(p[1]), ld(p[2])), glm::vec<3, V>(ld(n[0]), ld(n[1]), ld(n[2])), glm::vec<3, V>(V(0.f)), env, phong::detail::mask_t<V>(true));
            detail::light_sums<V, glm::defaultp> sums{};
            for (auto& l : lv) detail::add_light<F>(sums, s, l, m.shininess);
            auto c = detail::finish<F>(sums, s, m, env);
            if constexpr (std::is_same_v<V, SV>) c.x.copy_to(&out[0][i], stdx::element_aligned); else c.x.store_unaligned(&out[0][i]);
        }
        t.push_back(std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count() / (N * K));
    }
    std::sort(t.begin(), t.end()); return t[3];
}
int main() {
    const std::size_t N = 65536;
    std::mt19937 rng(1); std::uniform_real_distribution<float> u(-1, 1);
    std::vector<float> p[3], n[3], out[1];
    for (int c = 0; c < 3; ++c) { p[c].resize(N); n[c].resize(N); }
    out[0].resize(N);
    for (std::size_t i = 0; i < N; ++i) { p[0][i]=u(rng); p[1][i]=u(rng); p[2][i]=u(rng)-4; n[0][i]=u(rng); n[1][i]=u(rng); n[2][i]=u(rng)+1.5f; }
    for (int K : {1, 4, 16}) {
        std::vector<light<float>> L(K);
        for (int k = 0; k < K; ++k) { L[k].position = {u(rng)*3, u(rng)*3, u(rng), 1}; L[k].attenuation = {1, 0.1f, 0.01f}; }
        double a = run<simd_batch<float>>(K, p, n, out, L), b = run<SV>(K, p, n, out, L);
        std::printf("K=%2d  xsimd (%zu lanes) %.2f ns/pair   std::experimental::simd (%zu lanes) %.2f ns/pair   ratio %.1fx\n", K, batch_width<float>, a, SV::size(), b, b / a);
    }
}
