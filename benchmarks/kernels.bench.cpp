// The scalar kernels behind the model, each beside what a user would call instead: phong::detail::pow_unit
// (the specular and spot power, inline, detail/power.hpp) against std::pow, float and double; the
// fast mode's approximations (phong/core/fast_math.hpp) beside their exact twins: fast::pow_unit against
// phong::detail::pow_unit, fast::detail::pow_integer likewise (exponents 1..64 in turn), fast::rsqrt against
// phong::detail::rsqrt (bound counter: their published constants; the fast power's error over results
// >= 2^-24, where its relative bound holds); on this build's widest SIMD lanes, fast::rsqrt and
// fast::detail::reciprocal_normal against 1 / sqrt(x) and 1 / x on the same lanes (rows kernel.lanes_*).
// Time per call over 65536 (x, m) pairs of the lighting model's range (x in (0, 1], a third of them
// within 1e-3 of 1 as near a highlight; m in [1, 200] and up to 1e4), and the error of every result
// in T's normal range against pow in the __float128 reference type (tests/support/wide.hpp).
//
// Row names: kernel.<function>.<type>/typical/K:1/N:65536 (the report's naming; K = 1: one call per item).
#include "support/inputs.hpp" // uniform(): counter-based, reproducible

#include "support/numeric.hpp"
#include "support/wide.hpp"

#include <phong/batch.hpp> // first: its pragmas cover the intrinsics headers (the SIMD rows)
#include <phong/accuracy.hpp> // the fast kernels' bounds
#include <phong/core/fast_math.hpp>
#include <phong/core/math.hpp>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace phong_bench {
namespace {

constexpr std::size_t n_pairs = 65536;

template <class T>
struct power_inputs {
    std::vector<T> x, m;
};

template <class T>
const power_inputs<T>& inputs()
{
    static const power_inputs<T> in = [] {
        power_inputs<T> p;
        for (std::size_t i = 0; i < n_pairs; ++i) {
            const double u = uniform(3000, i, 0);
            const double x = i % 3 == 0 ? 1 - 1e-3 * u : std::max(u, 1e-6); // near the peak, or anywhere
            const double m = i % 7 == 0 ? std::pow(10.0, 2 + 2 * uniform(3000, i, 1)) : 1 + 199 * uniform(3000, i, 1);
            p.x.push_back(T(x));
            p.m.push_back(T(m));
        }
        return p;
    }();
    return in;
}

enum class power_kernel { phong, std_pow, fast, fast_integer };

/// The exponent of pair i: the inputs' m, or for fast::detail::pow_integer the integers 1..64 in turn (an
/// n that changes every call mispredicts the squaring loop's branches: this row is pow_integer's
/// error, and its time's worst case; shade_batch calls it with one n for a whole call).
template <class T, power_kernel Kernel> T exponent_of(const power_inputs<T>& in, std::size_t i)
{
    return Kernel == power_kernel::fast_integer ? T(1 + i % phong::fast::detail::pow_integer_max_exponent) : in.m[i];
}

template <class T, power_kernel Kernel>
void power_row(benchmark::State& state)
{
    const power_inputs<T>& in = inputs<T>();
    std::vector<T> out(n_pairs);
    for (auto _ : state) {
        for (std::size_t i = 0; i < n_pairs; ++i) {
            if constexpr (Kernel == power_kernel::phong) out[i] = phong::detail::pow_unit(in.x[i], in.m[i]);
            else if constexpr (Kernel == power_kernel::fast) out[i] = phong::fast::pow_unit(in.x[i], in.m[i]);
            else if constexpr (Kernel == power_kernel::fast_integer)
                out[i] = phong::fast::detail::pow_integer(in.x[i], unsigned(exponent_of<T, Kernel>(in, i)));
            else out[i] = T(std::pow(in.x[i], in.m[i]));
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    // Errors against pow in the wide type (outside the timed loop), over the results in T's normal
    // range: below it both functions lose bits to underflow (pow_unit flushes below 2^-1022).
    double max_rel = 0, max_ulp = 0, nan = 0;
    std::vector<double> ulps;
    for (std::size_t i = 0; i < n_pairs; ++i) {
        if (!std::isfinite(out[i])) nan += 1;
        const phong_test::wide ref = phong_test::wpow(phong_test::wide(in.x[i]), phong_test::wide(exponent_of<T, Kernel>(in, i)));
        if (ref < phong_test::wide(Kernel == power_kernel::fast ? T(0x1p-24) : std::numeric_limits<T>::min())) continue;
        max_rel = std::max(max_rel, phong_test::error_rel(out[i], ref));
        ulps.push_back(phong_test::error_ulp(out[i], ref));
    }
    std::nth_element(ulps.begin(), ulps.begin() + std::ptrdiff_t(ulps.size() * 99 / 100), ulps.end());
    const double p99 = ulps[ulps.size() * 99 / 100];
    max_ulp = *std::max_element(ulps.begin(), ulps.end());
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n_pairs));
    state.counters["ns_per_pair"] = benchmark::Counter(double(state.iterations()) * double(n_pairs) * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["max_rel_err"] = max_rel;
    state.counters["p99_ulp"] = p99;
    state.counters["max_ulp"] = max_ulp;
    state.counters["nan_count"] = nan;
    state.counters["bound"] = Kernel == power_kernel::fast           ? phong::fast::pow_unit_max_rel
                              : Kernel == power_kernel::fast_integer ? phong::fast::detail::pow_integer_max_rel<T>
                                                                     : -1;
    state.counters["K"] = 1;
    state.counters["N"] = double(n_pairs);
}

/// 1/sqrt(x) over squared distances of a scene's range (x in [1e-4, 1e4], log-uniform), one call
/// per item: phong::detail::rsqrt (1 / sqrt) or fast::rsqrt (estimate + Newton).
template <class T, bool Fast>
void rsqrt_row(benchmark::State& state)
{
    std::vector<T> x(n_pairs), out(n_pairs);
    for (std::size_t i = 0; i < n_pairs; ++i) x[i] = T(std::pow(10.0, -4 + 8 * uniform(3001, i, 0)));
    for (auto _ : state) {
        for (std::size_t i = 0; i < n_pairs; ++i) out[i] = Fast ? phong::fast::rsqrt(x[i]) : phong::detail::rsqrt(x[i]);
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    double max_rel = 0;
    for (std::size_t i = 0; i < n_pairs; ++i) {
        const phong_test::wide ref = 1 / phong_test::wsqrt(phong_test::wide(x[i]));
        max_rel = std::max(max_rel, phong_test::error_rel(out[i], ref));
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n_pairs));
    state.counters["ns_per_pair"] = benchmark::Counter(double(state.iterations()) * double(n_pairs) * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["max_rel_err"] = max_rel;
    state.counters["bound"] = Fast ? phong::fast::rsqrt_max_rel<T> : -1;
    state.counters["K"] = 1;
    state.counters["N"] = double(n_pairs);
}

#if PHONG_HAS_XSIMD
/// 1/sqrt(x) or 1/x over the rsqrt rows' x, on SIMD lanes (phong::simd_batch<T>: AVX-512 with
/// -march=native here), one call per lane batch; ns per item. Fast: fast::rsqrt /
/// fast::detail::reciprocal_normal (estimate + Newton); else the exact twin, 1 / sqrt(x) or 1 / x.
template <class T, bool Reciprocal, bool Fast>
void lanes_row(benchmark::State& state)
{
    using V = phong::simd_batch<T>;
    std::vector<T> x(n_pairs), out(n_pairs);
    for (std::size_t i = 0; i < n_pairs; ++i) x[i] = T(std::pow(10.0, -4 + 8 * uniform(3001, i, 0)));
    for (auto _ : state) {
        for (std::size_t i = 0; i + V::size <= n_pairs; i += V::size) {
            const V v = V::load_unaligned(x.data() + i);
            V r;
            if constexpr (Reciprocal) r = Fast ? phong::fast::detail::reciprocal_normal(v) : V(T(1)) / v;
            else r = Fast ? phong::fast::rsqrt(v) : V(T(1)) / xsimd::sqrt(v);
            r.store_unaligned(out.data() + i);
        }
        benchmark::DoNotOptimize(out.data());
        benchmark::ClobberMemory();
    }
    double max_rel = 0;
    for (std::size_t i = 0; i < n_pairs; ++i) {
        const phong_test::wide xi(x[i]);
        const phong_test::wide ref = Reciprocal ? 1 / xi : 1 / phong_test::wsqrt(xi);
        max_rel = std::max(max_rel, phong_test::error_rel(out[i], ref));
    }
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(n_pairs));
    state.counters["ns_per_pair"] = benchmark::Counter(double(state.iterations()) * double(n_pairs) * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    state.counters["max_rel_err"] = max_rel;
    state.counters["bound"] = !Fast ? -1 : Reciprocal ? phong::fast::detail::reciprocal_max_rel<T> : phong::fast::rsqrt_max_rel<T>;
    state.counters["K"] = 1;
    state.counters["N"] = double(n_pairs);
}
#endif

const bool registered = [] {
    const std::string tail = "/typical/K:1/N:" + std::to_string(n_pairs);
    benchmark::RegisterBenchmark(("kernel.pow_unit.float" + tail).c_str(), power_row<float, power_kernel::phong>);
    benchmark::RegisterBenchmark(("kernel.std_pow.float" + tail).c_str(), power_row<float, power_kernel::std_pow>);
    benchmark::RegisterBenchmark(("kernel.fast_pow_unit.float" + tail).c_str(), power_row<float, power_kernel::fast>);
    benchmark::RegisterBenchmark(("kernel.pow_unit.double" + tail).c_str(), power_row<double, power_kernel::phong>);
    benchmark::RegisterBenchmark(("kernel.std_pow.double" + tail).c_str(), power_row<double, power_kernel::std_pow>);
    benchmark::RegisterBenchmark(("kernel.fast_pow_unit.double" + tail).c_str(), power_row<double, power_kernel::fast>);
    benchmark::RegisterBenchmark(("kernel.rsqrt.float" + tail).c_str(), rsqrt_row<float, false>);
    benchmark::RegisterBenchmark(("kernel.fast_pow_integer.float" + tail).c_str(), power_row<float, power_kernel::fast_integer>);
    benchmark::RegisterBenchmark(("kernel.fast_pow_integer.double" + tail).c_str(), power_row<double, power_kernel::fast_integer>);
    benchmark::RegisterBenchmark(("kernel.fast_rsqrt.float" + tail).c_str(), rsqrt_row<float, true>);
    benchmark::RegisterBenchmark(("kernel.rsqrt.double" + tail).c_str(), rsqrt_row<double, false>);
    benchmark::RegisterBenchmark(("kernel.fast_rsqrt.double" + tail).c_str(), rsqrt_row<double, true>);
#if PHONG_HAS_XSIMD
    benchmark::RegisterBenchmark(("kernel.lanes_rsqrt.float" + tail).c_str(), lanes_row<float, false, false>);
    benchmark::RegisterBenchmark(("kernel.lanes_fast_rsqrt.float" + tail).c_str(), lanes_row<float, false, true>);
    benchmark::RegisterBenchmark(("kernel.lanes_reciprocal.float" + tail).c_str(), lanes_row<float, true, false>);
    benchmark::RegisterBenchmark(("kernel.lanes_fast_reciprocal_normal.float" + tail).c_str(), lanes_row<float, true, true>);
#endif
    return true;
}();

} // namespace
} // namespace phong_bench
