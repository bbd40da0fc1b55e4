// phong_exact_bound: the exact mode's derived error bound (phong::accuracy::exact_bound,
// docs/accuracy.md) against measurement, channel by channel, on two generator families:
//  * independent: tests/support/independent_generators.hpp (another generator, other
//    distributions, the reference written literally in __float128 there);
//  * classes: the project's input classes (tests/support/stiff_classes.hpp), with the same
//    independent reference; scenes within a class's limits (accuracy::exact_class_limits) must also
//    stay within the class's published constant (accuracy::bounds<exact, T>).
// Every channel must satisfy |computed - exact| <= exact_bound(conditioning) |exact| + allowance
// (channels with a term that has no relative bound, +inf, are counted, not checked). Prints the
// largest measured / bound ratio; exits 1 on any channel above its bound or any NaN/inf.
//
//   phong_exact_bound [--batch] [scenes per family and type = 20000] [seed = 1]
// --batch: the colours come from shade_batch (SIMD lanes, each scene's point in a step of its own
// padded lanes), held to the same derivation with the lanes' power (power_kernel::lanes).
// Run in 12 builds by tests/bounds_matrix.sh (g++/clang++, -O1/-O2/-O3, with/without -march=native).
#include "support/independent_generators.hpp"
#include "support/stiff_classes.hpp"

#include "support/accuracy_analysis.hpp"
#include <phong/batch.hpp>
#include <phong/sum/shade.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string>
#include <vector>

namespace {

using phong::evaluation;
using phong::specular_model;
using phong::accuracy::input_class;

struct tally {
    std::size_t scenes = 0, channels = 0, unbounded = 0, no_relative = 0, failures = 0, non_finite = 0;
    double max_ratio = 0;          ///< measured / bound over channels whose relative bound is < 1
    double max_ratio_any = 0;      ///< the same over every checked channel
    std::vector<double> ratios;    ///< channels with relative bound < 1 and a nonzero error
    // class constants (project classes only)
    std::size_t within = 0;
    double max_class_ratio = 0;    ///< measured / (published constant |I| + allowance), within the limits
    double max_rel = 0;            ///< the largest measured relative error (channels with I > 0)
};

bool verbose = false;
bool batch = false; ///< --batch: shade_batch's lanes instead of shade<F>

/// One point's colour through shade_batch<F> (one point: the other lanes are the batch's padding).
template <phong::features F, class Scene>
auto batch_color(const Scene& s)
{
    using T = std::remove_cvref_t<decltype(s.position.x)>;
    const T px[1] = {s.position.x}, py[1] = {s.position.y}, pz[1] = {s.position.z};
    const T nx[1] = {s.normal.x}, ny[1] = {s.normal.y}, nz[1] = {s.normal.z};
    glm::vec<3, T> out[1];
    phong::shade_batch<F>(phong::soa3<T>{px, py, pz}, phong::soa3<T>{nx, ny, nz}, s.material,
                          std::span<const phong::light<T>>(s.lights), std::span<glm::vec<3, T>>(out), s.environment);
    return out[0];
}

template <class T, specular_model S, class Scene>
bool within_limits(const Scene& s, const independent::evaluation<T>& e, const phong::accuracy::exact_limits& k)
{
    if (int(s.lights.size()) > k.lights || double(s.material.shininess) > k.m) return false;
    for (int ch = 0; ch < 3; ++ch) {
        if (!k.diffuse && s.material.kd[ch] != T(0)) return false;
        if (!k.specular && s.material.ks[ch] != T(0)) return false;
    }
    for (const independent::pair_info& p : e.pairs) {
        const phong::accuracy::pair_conditioning& c = S == specular_model::phong ? p.phong_k : p.blinn_k;
        if (!c.in_range && !k.drops) return false;
        if (c.w_ratio != 0) return false;
        if (!p.lit) continue;
        if (std::fabs(c.nl) < k.nl || std::fabs(c.nv) < k.nv) return false;
        if (S == specular_model::blinn && !k.blinn_cancels && c.nl > 0 && c.blinn_sum < k.nl + k.nv) return false;
        if (k.specular && c.m != 0 && c.nl > 0) {
            if (S == specular_model::blinn && k.blinn_cancels) {
                if (c.blinn_sum != 0) return false;
            } else if (!(c.c >= k.c || c.c <= -k.c / 100)) {
                return false;
            }
        }
    }
    return true;
}

template <class T, specular_model S, class Scene>
void check_scene(const Scene& s, tally& t, const char* what, const phong::accuracy::exact_limits* limits = nullptr, double constant = 0)
{
    constexpr phong::features F = phong::accuracy::measured_features(evaluation::exact, S);
    const independent::evaluation<T> e = independent::evaluate<T>(s);
    const auto c = batch ? batch_color<F>(s)
                         : phong::shade<F>(s.position, s.normal, s.material, std::span<const phong::light<T>>(s.lights), s.environment);
    const bool within = limits && within_limits<T, S>(s, e, *limits);
    ++t.scenes;
    t.within += within;
    for (int ch = 0; ch < 3; ++ch) {
        ++t.channels;
        const quad exact = S == specular_model::phong ? e.phong[ch] : e.blinn[ch];
        if (!std::isfinite(c[ch])) {
            ++t.non_finite;
            ++t.failures;
            std::printf("FAIL %s: non-finite channel\n", what);
            continue;
        }
        const double err = double(independent::qabs(quad(c[ch]) - exact));
        const double I = double(exact);
        if (I > 0) t.max_rel = std::max(t.max_rel, err / I);
        const double allowance = phong::accuracy::exact_absolute_allowance<T>(int(s.lights.size()), e.f_max, e.k_max);
        if (within) {
            const double b = constant * std::fabs(I) + allowance;
            const double r = err == 0 ? 0 : err / b;
            t.max_class_ratio = std::max(t.max_class_ratio, r);
            if (r > 1) {
                ++t.failures;
                std::printf("FAIL %s (%s): channel %d error %.3g rel %.3g above the class constant %.3g\n", what,
                            S == specular_model::phong ? "phong" : "blinn", ch, err, err / I, constant);
            }
        }
        using phong::accuracy::power_kernel;
        const double b = batch ? independent::channel_bound<T, Scene, power_kernel::lanes>(s, e, S, ch, I)
                               : independent::channel_bound<T>(s, e, S, ch, I);
        if (!(b < std::numeric_limits<double>::infinity())) {
            ++t.unbounded;
            continue;
        }
        const double r = err == 0 ? 0 : err / b;
        const bool relative = b < std::fabs(I); // a relative bound below 1
        if (!relative) ++t.no_relative;
        t.max_ratio_any = std::max(t.max_ratio_any, r);
        if (relative) {
            t.max_ratio = std::max(t.max_ratio, r);
            if (err > 0) t.ratios.push_back(r);
        }
        if (r > 1 || (verbose && r > 0.25 && relative)) {
            if (r > 1) ++t.failures;
            std::printf("%s %s (%s, %s): channel %d computed %.17g exact %.17g error %.3g bound %.3g (ratio %.3g), m %.6g, K %zu\n",
                        r > 1 ? "FAIL" : "note", what, sizeof(T) == 4 ? "float" : "double",
                        S == specular_model::phong ? "phong" : "blinn", ch, double(c[ch]), I, err, b, r,
                        double(s.material.shininess), s.lights.size());
            for (const independent::pair_info& p : e.pairs) {
                const auto& k = S == specular_model::phong ? p.phong_k : p.blinn_k;
                std::printf("    pair: lit %d nl %.6g nv %.6g c %.17g sigma %.6g w_ratio %.3g in_range %d f %.6g | diffuse %.3g specular %.3g\n",
                            int(p.lit), k.nl, k.nv, k.c, k.blinn_sum, k.w_ratio, int(k.in_range), double(p.f),
                            phong::accuracy::exact_diffuse_bound<T>(k), phong::accuracy::exact_specular_bound<T>(k));
            }
        }
    }
}

void print(const char* family, const char* type, const char* model, tally& t, bool classes)
{
    double p50 = 0, p999 = 0;
    if (!t.ratios.empty()) {
        std::sort(t.ratios.begin(), t.ratios.end());
        p50 = t.ratios[t.ratios.size() / 2];
        p999 = t.ratios[std::size_t(0.999 * double(t.ratios.size() - 1))];
    }
    std::printf("%-26s %-6s %-5s scenes %6zu channels %6zu | measured/bound: max %.3g (p50 %.2g, p99.9 %.2g; any %.3g) | "
                "unbounded %zu, bound >= 1: %zu | max rel %.3g",
                family, type, model, t.scenes, t.channels, t.max_ratio, p50, p999, t.max_ratio_any, t.unbounded, t.no_relative,
                t.max_rel);
    if (classes) std::printf(" | within limits %zu, measured/constant max %.3g", t.within, t.max_class_ratio);
    std::printf("%s\n", t.failures ? "  <-- FAIL" : "");
}

struct summary {
    std::size_t failures = 0;
    double max_ratio = 0;
    void add(const tally& t)
    {
        failures += t.failures;
        max_ratio = std::max(max_ratio, t.max_ratio);
    }
};

template <class T, specular_model S>
void run_independent(std::size_t n, std::uint64_t seed, summary& sum)
{
    independent::xoshiro g(seed * 0x9e3779b97f4a7c15ull + (sizeof(T) == 4 ? 11 : 23) + (S == specular_model::phong ? 0 : 7));
    tally t;
    for (std::size_t i = 0; i < n; ++i) check_scene<T, S>(independent::make_scene<T>(g), t, "independent");
    print("independent", sizeof(T) == 4 ? "float" : "double", S == specular_model::phong ? "phong" : "blinn", t, false);
    sum.add(t);
}

template <class T>
void run_class(input_class c, std::size_t n, std::uint64_t seed, summary& sum)
{
    const auto scenes = phong_test::make_class<T>(c, n, seed);
    const phong::accuracy::exact_limits limits = phong::accuracy::exact_class_limits<T>(c);
    const double constant = phong::accuracy::of<evaluation::exact, T>(c).max_rel;
    tally p, b;
    for (const auto& s : scenes) {
        // The class constants are shade<F>'s (scalar power): checked without --batch only.
        const phong::accuracy::exact_limits* lim = batch ? nullptr : &limits;
        check_scene<T, specular_model::phong>(s, p, phong::accuracy::name(c), lim, constant);
        check_scene<T, specular_model::blinn>(s, b, phong::accuracy::name(c), lim, constant);
    }
    print(phong::accuracy::name(c), sizeof(T) == 4 ? "float" : "double", "phong", p, true);
    print(phong::accuracy::name(c), sizeof(T) == 4 ? "float" : "double", "blinn", b, true);
    sum.add(p);
    sum.add(b);
}

} // namespace

int main(int argc, char** argv)
{
    std::size_t n = 20000;
    std::uint64_t seed = 1;
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::string(argv[i]) == "--verbose") verbose = true;
        else if (std::string(argv[i]) == "--batch") batch = true;
        else if (positional++ == 0) n = std::strtoull(argv[i], nullptr, 10);
        else seed = std::strtoull(argv[i], nullptr, 10);
    }
    std::printf("Exact mode (%s) against its derived bound: %zu scenes per family, type and model, seed %llu.\n",
                batch ? "shade_batch lanes" : "shade<F>", n, static_cast<unsigned long long>(seed));
    summary sum;
    run_independent<float, specular_model::phong>(n, seed, sum);
    run_independent<float, specular_model::blinn>(n, seed, sum);
    run_independent<double, specular_model::phong>(n, seed, sum);
    run_independent<double, specular_model::blinn>(n, seed, sum);
    const std::size_t per_class = std::max<std::size_t>(n / 10, 1);
    for (std::size_t k = 0; k < phong::accuracy::input_class_count; ++k) {
        const auto c = static_cast<input_class>(k);
        if (c == input_class::non_finite) continue;
        run_class<float>(c, per_class, seed, sum);
        run_class<double>(c, per_class, seed, sum);
    }
    std::printf("max measured/bound %.3g; %zu channels above their bound\n", sum.max_ratio, sum.failures);
    return sum.failures == 0 ? 0 : 1;
}
