// phong_stable_p99: the stable mode's published figures for the shininess classes (p99_ulp,
// max_ulp, max_rel of phong/accuracy.hpp, bounds<stable, ...>) on a second, independently written
// generator family of the same classes, against the independent __float128 reference of
// tests/support/independent_generators.hpp (the seed formula written literally).
//
//   phong_stable_p99 [scenes per class and type = 20000] [seed = 1]
//
// The classes (accuracy.hpp): m = 1e3, 1e4, 1e5 near the highlight peak, angle(r, v) < 3 / sqrt(m)
// (so (r.v)^m > exp(-4.5)), specular only. The project's generator (tests/support/stiff_classes.hpp)
// draws that angle uniformly; this family draws y = m ln(r.v) uniformly in [-4.5, 0] instead (more
// scenes far from the peak, where the power's error grows like |y|), with its own generator
// (xoshiro256**), log-uniform distances and normal lengths, directional and attenuated positional
// lights. Scalar float (precision = twofold), scalar double, and shade_batch in float and double
// (their published bounds: bounds<stable, T, twofold>). Exit 1 when a figure is above its bound.
#include "support/independent_generators.hpp"

#include "support/accuracy_analysis.hpp"
#include <phong/batch.hpp>
#include <phong/sum/shade.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

using independent::l3;

using independent::xoshiro;
using phong::evaluation;
using phong::specular_model;
using phong::accuracy::input_class;

/// One scene of class shininess_1e<k> (m = 10^k), drawn by this family.
template <class T> independent::scene<T> near_peak(xoshiro& g, long double m, bool edge)
{
    for (;;) {
        independent::scene<T> s;
        const l3 v = independent::sphere(g);
        const long double distance = g.log_range(0.5L, 100);
        const l3 Q = v * -distance;
        constexpr phong::accuracy::near_peak_limits k = phong::accuracy::near_peak; // the class's limits
        const l3 n = independent::at_cosine(g, v, g.range(k.min_nv, 1));
        const long double y = edge ? -g.range(4.4L, 4.5L) : -g.range(0, 4.5L); // m ln(r.v), uniform
        const long double theta = std::acos(std::exp(y / m));     // angle(r, v) < 3 / sqrt(m) = max_angle_sqrt_m / sqrt(m)
        if (!(theta * std::sqrt(m) < k.max_angle_sqrt_m)) continue;
        const l3 r = independent::at_angle(g, v, theta);
        const l3 l = n * (2 * independent::ldot(n, r)) - r;       // reflect(-r, n)
        if (!(independent::ldot(n, l) > k.min_nl)) continue;
        s.position = independent::to_t<T>(Q);
        s.normal = independent::to_t<T>(n * g.log_range(0.1L, 10));
        s.material.shininess = T(m);
        for (int ch = 0; ch < 3; ++ch) {
            s.material.ka[ch] = s.material.kd[ch] = T(0);
            s.material.ks[ch] = T(g.range(0.05L, 1));
            s.environment.ambient[ch] = T(0);
        }
        phong::light<T> L;
        if (g.chance(0.5)) {
            L.position = glm::vec<4, T>(independent::to_t<T>(l * g.log_range(1e-2L, 1e2L)), T(0));
        } else {
            const long double reach = g.log_range(1, 1000) * distance;
            L.position = glm::vec<4, T>(independent::to_t<T>(Q + l * reach), T(1));
            L.attenuation.constant = T(g.range(0.5L, 2));
            L.attenuation.linear = T(g.chance(0.5) ? 0 : g.unit() / reach);
            L.attenuation.quadratic = T(g.chance(0.5) ? 0 : g.unit() / (reach * reach));
        }
        for (int ch = 0; ch < 3; ++ch) {
            L.ambient[ch] = T(0);
            L.diffuse[ch] = T(g.range(0.05L, 1));
            L.specular[ch] = T(g.range(0.05L, 1));
        }
        s.lights.push_back(L);
        return s;
    }
}

/// |computed - exact| in ulp of the exact value in T (the spacing of T's numbers at |exact|).
template <class T> double error_ulp(T computed, quad exact)
{
    const long double e = (long double)(exact < 0 ? -exact : exact);
    int k = 0;
    std::frexp(e, &k); // e = f 2^k, f in [0.5, 1)
    const int lowest = std::numeric_limits<T>::min_exponent - std::numeric_limits<T>::digits;
    const long double ulp = std::ldexp(1.0L, std::max(k - std::numeric_limits<T>::digits, lowest));
    return double((long double)independent::qabs(static_cast<quad>(computed) - exact) / ulp);
}

struct stats {
    std::vector<double> ulp;
    double max_rel = 0;
    std::size_t non_finite = 0;
    void add(double u, double rel, bool finite)
    {
        if (!finite) {
            ++non_finite;
            return;
        }
        ulp.push_back(u);
        max_rel = std::max(max_rel, rel);
    }
    double p99() { return ulp.empty() ? 0 : (std::sort(ulp.begin(), ulp.end()), ulp[std::size_t(0.99 * double(ulp.size() - 1))]); }
    double max() const { return ulp.empty() ? 0 : *std::max_element(ulp.begin(), ulp.end()); }
};

template <phong::features F, class T> glm::vec<3, T> batch_color(const independent::scene<T>& s)
{
    const std::size_t n = phong::batch_width<T> + 1; // a full step and a tail
    std::vector<T> px(n, s.position.x), py(n, s.position.y), pz(n, s.position.z), nx(n, s.normal.x), ny(n, s.normal.y),
        nz(n, s.normal.z), r(n), g(n), b(n);
    phong::shade_batch<F>(phong::soa3<T>{px, py, pz}, phong::soa3<T>{nx, ny, nz}, s.material, std::span<const phong::light<T>>(s.lights),
                          phong::soa_rgba<T>{r, g, b, {}}, s.environment);
    return {r[n - 1], g[n - 1], b[n - 1]}; // the tail's lane
}

template <class T, bool Batch> bool run(input_class c, long double m, std::size_t count, std::uint64_t seed, bool edge)
{
    constexpr auto precision = phong::stable_precision::twofold;
    stats st;
    xoshiro g(seed * 0x9e3779b97f4a7c15ull + (sizeof(T) == 4 ? 3 : 5) + (Batch ? 17 : 0) + std::uint64_t(std::log10(m)));
    for (std::size_t i = 0; i < count; ++i) {
        const independent::scene<T> s = near_peak<T>(g, m, edge);
        const independent::evaluation<T> e = independent::evaluate<T>(s);
        for (const specular_model S : {specular_model::phong, specular_model::blinn}) {
            glm::vec<3, T> col;
            if (S == specular_model::phong) {
                constexpr phong::features F = phong::accuracy::measured_features(evaluation::stable, specular_model::phong, precision);
                if constexpr (Batch) col = batch_color<F>(s);
                else col = phong::shade<F>(s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
            } else {
                constexpr phong::features F = phong::accuracy::measured_features(evaluation::stable, specular_model::blinn, precision);
                if constexpr (Batch) col = batch_color<F>(s);
                else col = phong::shade<F>(s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
            }
            for (int ch = 0; ch < 3; ++ch) {
                const quad exact = S == specular_model::phong ? e.phong[ch] : e.blinn[ch];
                const double rel = exact > 0 ? double(independent::qabs(static_cast<quad>(col[ch]) - exact) / exact) : 0;
                st.add(error_ulp<T>(col[ch], exact), rel, std::isfinite(col[ch]));
            }
        }
    }
    const phong::accuracy::bound b = phong::accuracy::of<evaluation::stable, T, precision>(c);
    const double p99 = st.p99(), mx = st.max();
    const bool ok = st.non_finite == 0 && p99 <= b.p99_ulp && mx <= b.max_ulp && st.max_rel <= b.max_rel;
    std::printf("%-14s %-5s %-6s %-6s p99 %6.2f  max %6.2f ulp  rel %.2e  non-finite %zu | bound %g %g %.0e%s\n", phong::accuracy::name(c), edge ? "edge" : "all",
                sizeof(T) == 4 ? "float" : "double", Batch ? "batch" : "scalar", p99, mx, st.max_rel, st.non_finite, b.p99_ulp, b.max_ulp,
                b.max_rel, ok ? "" : "  <-- ABOVE BOUND");
    return ok;
}

} // namespace

int main(int argc, char** argv)
{
    const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 20000;
    const std::uint64_t seed = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
    std::printf("stable mode, second generator family (y = m ln(r.v) uniform in [-4.5, 0]), %zu scenes per row, seed %llu, "
                "both specular models\n",
                n, static_cast<unsigned long long>(seed));
    bool ok = true;
    const std::pair<input_class, long double> classes[] = {
        {input_class::shininess_1e3, 1e3L}, {input_class::shininess_1e4, 1e4L}, {input_class::shininess_1e5, 1e5L}};
    for (const bool edge : {false, true})
        for (const auto& [c, m] : classes) {
            ok = run<float, false>(c, m, n, seed, edge) && ok;
            ok = run<double, false>(c, m, n, seed, edge) && ok;
            ok = run<float, true>(c, m, n, seed, edge) && ok;
            ok = run<double, true>(c, m, n, seed, edge) && ok;
        }
    return ok ? 0 : 1;
}
