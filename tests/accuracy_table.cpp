// phong_accuracy_table: measures every input class of phong/accuracy.hpp in both evaluation modes,
// float and double, Phong and Blinn specular, against the __float128 reference, and prints the
// Markdown table of README.md's "Accuracy" section. Not run by ctest (it takes a while).
//
//   phong_accuracy_table [samples per class = 20000] [seed = 1] [--bounds] [--code] [--twofold] [--fast]
//
// --fast: the second group of columns is the fast mode (features::mode = evaluation::fast)
// instead of the stable mode; with --code it prints the fast table's p99 candidates.
// --twofold: the stable columns use features::precision = twofold (float's other route, and the
// SIMD batches'); by default float's stable mode is evaluated in double (precision = wider).
// --bounds also prints, per mode, type and class, the worst figures over both specular models
// next to the published bound (phong::accuracy::bounds), and flags any figure above it (exit 1).
// --code prints candidate bounds (twice the worst figures, rounded up to one digit) as C++, for
// the stable mode only: the exact mode's max_rel and max_ulp are derived (accuracy::exact_bound at
// each class's limits), and only its p99 column is a statistic (printed as a comment).
#include "support/stiff_classes.hpp"

#include <phong/accuracy.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#if defined(__SSE__)
#  include <xmmintrin.h>
#endif

namespace {

using phong::evaluation;
using phong::specular_model;
using phong::accuracy::input_class;
using phong_test::error_stats;

struct row {
    error_stats exact, stable;
};

bool twofold_columns = false; // --twofold
bool fast_columns = false;    // --fast

// Built with -ffast-math (-fassociative-math): the stable mode's twofold route refuses to compile
// (phong/core/ieee.hpp, docs/compilers.md), so the second columns of double, and of float with
// --twofold, are the fast mode's; float's stable columns (precision = wider) stay.
template <class T> bool second_is_fast()
{
    return fast_columns || (!phong::detail::ieee::twofold_allowed<T> && (sizeof(T) == 8 || twofold_columns));
}

template <class T, specular_model S>
row measure_row(const std::vector<phong_test::stiff_scene<T>>& scenes)
{
    constexpr phong::features exact = phong::accuracy::measured_features(evaluation::exact, S);
    constexpr phong::features stable = phong::accuracy::measured_features(evaluation::stable, S);
    constexpr phong::features twofold = phong::accuracy::measured_features(evaluation::stable, S, phong::stable_precision::twofold);
    constexpr phong::features fast = phong::accuracy::measured_features(evaluation::fast, S);
    const std::vector<phong_test::wcolor> refs = phong_test::references(exact, scenes);
    if constexpr (!phong::detail::ieee::twofold_allowed<T>) {
        if (second_is_fast<T>()) return {phong_test::measure<exact>(scenes, refs), phong_test::measure<fast>(scenes, refs)};
        if constexpr (sizeof(T) == 4) return {phong_test::measure<exact>(scenes, refs), phong_test::measure<stable>(scenes, refs)};
        return {};
    } else {
        return {phong_test::measure<exact>(scenes, refs),
                fast_columns      ? phong_test::measure<fast>(scenes, refs)
                : twofold_columns ? phong_test::measure<twofold>(scenes, refs)
                                  : phong_test::measure<stable>(scenes, refs)};
    }
}

std::string fmt(double x)
{
    char buf[32];
    if (x == 0) return "0";
    if (x >= 1e6 || x < 1e-2) std::snprintf(buf, sizeof buf, "%.1e", x);
    else if (x >= 100) std::snprintf(buf, sizeof buf, "%.0f", x);
    else std::snprintf(buf, sizeof buf, "%.2g", x);
    return buf;
}

std::string cells(const error_stats& e)
{
    return fmt(e.p50_ulp) + " | " + fmt(e.p99_ulp) + " | " + fmt(e.max_ulp) + " | " + fmt(e.max_rel) + " | " +
           std::to_string(e.non_finite);
}

struct worst {
    double p99 = 0, max_ulp = 0, max_rel = 0;
    std::size_t non_finite = 0, channels = 0;
    void add(const error_stats& e)
    {
        p99 = std::max(p99, e.p99_ulp);
        max_ulp = std::max(max_ulp, e.max_ulp);
        max_rel = std::max(max_rel, e.max_rel);
        non_finite += e.non_finite;
        channels += e.channels;
    }
};

/// Whether subnormal numbers are flushed (x86 MXCSR FTZ or DAZ): set at start-up by a program
/// linked with -ffast-math (crtfastmath.o) or -mdaz-ftz.
bool flushes_subnormals()
{
#if defined(__SSE__)
    return (_mm_getcsr() & 0x8040u) != 0;
#else
    return false;
#endif
}

template <evaluation M, class T>
bool print_bound(input_class c, const worst& w)
{
    const phong::accuracy::bound b = twofold_columns && M == evaluation::stable ? phong::accuracy::of<M, T, phong::stable_precision::twofold>(c)
                                                     : phong::accuracy::of<M, T>(c);
    const bool nan_policy = c == input_class::non_finite;
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
    // -ffinite-math-only: NaN and inf inputs give unspecified values (docs/compilers.md), the
    // documented exception to the NaN policy; only finite inputs are checked.
    if (nan_policy) return true;
#endif
    const bool ok = nan_policy ? w.non_finite == w.channels
                               : (w.non_finite == 0 && w.p99 <= b.p99_ulp && w.max_ulp <= b.max_ulp && w.max_rel <= b.max_rel);
    std::printf("%-7s %-6s %-20s measured p99 %-8s max %-8s rel %-8s nonfinite %zu/%zu | bound %s %s %s %s\n",
                M == evaluation::exact ? "exact" : M == evaluation::fast ? "fast" : "stable", sizeof(T) == 4 ? "float" : "double", phong::accuracy::name(c),
                fmt(w.p99).c_str(), fmt(w.max_ulp).c_str(), fmt(w.max_rel).c_str(), w.non_finite, w.channels,
                fmt(b.p99_ulp).c_str(), fmt(b.max_ulp).c_str(), fmt(b.max_rel).c_str(), ok ? "" : "  <-- ABOVE BOUND");
    // Flushed subnormals (FTZ/DAZ, set by the -ffast-math link): a light within 1e-19 of the point
    // in float (1e-154 in double) leaves bounds derived for IEEE gradual underflow
    // (docs/compilers.md): the one class exempted there, as long as it stays finite.
    if (!ok && c == input_class::attenuation_c0_zero && flushes_subnormals() && w.non_finite == 0) {
        std::printf("        (attenuation_c0_zero with subnormals flushed, FTZ/DAZ: the documented exception, not a failure)\n");
        return true;
    }
    return ok;
}

// Twice x rounded up to one significant digit (the margin of the published bounds).
double margin(double x)
{
    if (x <= 0) return 0;
    const double y = 2 * x;
    const double p = std::pow(10.0, std::floor(std::log10(y)));
    return std::ceil(y / p * (1 - 1e-12)) * p;
}

std::vector<std::string> code[2][2]; // [mode][type]

template <class T>
bool run_type(input_class c, std::size_t n, std::uint64_t seed, bool bounds)
{
    const auto scenes = phong_test::make_class<T>(c, n, seed);
    const row p = measure_row<T, specular_model::phong>(scenes);
    const row b = measure_row<T, specular_model::blinn>(scenes);
    const char* type = sizeof(T) == 4 ? "float" : "double";
    std::printf("| %s | %s | phong | %s | %s |\n", phong::accuracy::name(c), type, cells(p.exact).c_str(), cells(p.stable).c_str());
    std::printf("| %s | %s | blinn | %s | %s |\n", phong::accuracy::name(c), type, cells(b.exact).c_str(), cells(b.stable).c_str());
    std::fflush(stdout);
    worst we, ws;
    we.add(p.exact), we.add(b.exact), ws.add(p.stable), ws.add(b.stable);
    const worst* ws_[2] = {&we, &ws};
    for (int m = 0; m < 2; ++m) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "    /* %-19s */ {%g, %g, %g},", phong::accuracy::name(c), margin(ws_[m]->p99),
                      margin(ws_[m]->max_ulp), margin(ws_[m]->max_rel));
        code[m][sizeof(T) == 4 ? 0 : 1].push_back(buf);
    }
    if (!bounds) return true;
    const bool ok_e = print_bound<evaluation::exact, T>(c, we);
    const bool ok_s = second_is_fast<T>() ? print_bound<evaluation::fast, T>(c, ws) : print_bound<evaluation::stable, T>(c, ws);
    return ok_e && ok_s;
}

} // namespace

int main(int argc, char** argv)
{
    std::size_t n = 20000;
    std::uint64_t seed = 1;
    bool bounds = false, print_code = false;
    int positional = 0;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--bounds") == 0) bounds = true;
        else if (std::strcmp(argv[i], "--code") == 0) print_code = true;
        else if (std::strcmp(argv[i], "--twofold") == 0) twofold_columns = true;
        else if (std::strcmp(argv[i], "--fast") == 0) fast_columns = true;
        else if (positional++ == 0) n = std::strtoull(argv[i], nullptr, 10);
        else seed = std::strtoull(argv[i], nullptr, 10);
    }
    if (fast_columns) std::printf("Second columns: the fast mode (evaluation::fast).\n");
    else std::printf("Stable columns: %s.\n", twofold_columns ? "precision = twofold (float arithmetic, twofold unit vectors)"
                                                             : "precision = wider (float evaluated in double; double twofold)");
    std::printf("Scenes per class: %zu, seed %llu; 3 channels per scene. Errors per channel against %s.\n"
                "ulp: of the exact value in the type; rel: max |computed - exact| / |exact|; NaN/Inf: channels.\n\n",
                n, static_cast<unsigned long long>(seed),
                phong_test::wide_digits >= 113 ? "__float128"
                                               : "long double (64 bits: too few for double at m >= 1e4; build with g++)");
    std::printf("| class | type | specular | exact p50 | p99 | max ulp | max rel | NaN/Inf | %s p50 | p99 | max ulp | max rel | NaN/Inf |\n",
                fast_columns ? "fast" : "stable");
    std::printf("|---|---|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|\n");
    bool ok = true;
    for (std::size_t k = 0; k < phong::accuracy::input_class_count; ++k) {
        const auto c = static_cast<input_class>(k);
        ok = run_type<float>(c, n, seed, bounds) && ok;
        ok = run_type<double>(c, n, seed, bounds) && ok;
    }
    if (print_code) {
        for (int t = 0; t < 2; ++t) {
            std::printf("// exact %s p99 candidates (max_rel, max_ulp: derived, not from this run):\n", t == 0 ? "float" : "double");
            for (const std::string& line : code[0][t]) std::printf("//%s\n", line.c_str());
        }
        for (int t = 0; fast_columns && t < 2; ++t) {
            std::printf("// fast %s p99 candidates (max_rel, max_ulp: derived, not from this run):\n", t == 0 ? "float" : "double");
            for (const std::string& line : code[1][t]) std::printf("//%s\n", line.c_str());
        }
        for (int m = 1; m < 2 && !fast_columns; ++m)
            for (int t = 0; t < 2; ++t) {
                std::printf("template <> inline constexpr detail::table bounds<evaluation::%s, %s%s>{{\n", m == 0 ? "exact" : "stable",
                            t == 0 ? "float" : "double", m == 1 && twofold_columns ? ", stable_precision::twofold" : "");
                for (const std::string& line : code[m][t]) std::printf("%s\n", line.c_str());
                std::printf("}};\n");
            }
    }
    return ok ? 0 : 1;
}
