// Benchmark harness: cached inputs, the high-precision reference on a sample of points, and the
// accuracy counters every row reports (computed outside the timed loop, from the very outputs the
// timed loop wrote).
#pragma once

#include "inputs.hpp"

#include "support/numeric.hpp"   // tests/support: error_ulp, error_rel (sign-aware ulp distance)
#include "support/reference.hpp" // tests/support: reference_shade, __float128 with libquadmath

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace phong_bench {

/// Points on which the reference is evaluated: all of a small set, else an evenly strided sample
/// of this many (the __float128 reference costs a few microseconds per (point, light)).
inline constexpr std::size_t reference_sample = 4096;

/// Points are generated once per (set, N, T) and reused by every row and repetition. The points
/// of the typical and grazing sets do not depend on K, so they are shared across K.
template <class T>
const points<T>& cached_points(input_set set, std::size_t N, std::size_t K)
{
    static std::map<std::tuple<int, std::size_t, std::size_t>, std::unique_ptr<points<T>>> cache;
    const std::size_t points_key = set == input_set::highlight ? K : 0;
    auto& slot = cache[{static_cast<int>(set), N, points_key}];
    if (!slot) slot = std::make_unique<points<T>>(make_points<T>(set, N, K));
    return *slot;
}

inline std::vector<std::size_t> sample_indices(std::size_t N)
{
    std::vector<std::size_t> idx;
    const std::size_t stride = N <= reference_sample ? 1 : N / reference_sample;
    for (std::size_t i = 0; i < N && idx.size() < reference_sample; i += stride) idx.push_back(i);
    return idx;
}

/// The reference colours of the sampled points of (set, N, K) under the features F (given as a
/// run-time value; phong's features is a plain aggregate). Inputs are the double ones, which equal
/// the float ones exactly, so float and double rows share it.
inline const std::vector<phong_test::wcolor>& cached_reference(phong::features F, input_set set, std::size_t N,
                                                               std::size_t K, light_style style = light_style::plain)
{
    F.mode = phong::evaluation::exact; // the reference is the model itself, whatever the mode
    using key_t = std::tuple<std::string, int, std::size_t, std::size_t, int>;
    static std::map<key_t, std::vector<phong_test::wcolor>> cache;
    // features has no operator<; its bytes are a fine key (a structural aggregate of enums and bools).
    const std::string fkey(reinterpret_cast<const char*>(&F), sizeof F);
    const key_t key{fkey, static_cast<int>(set), N, K, static_cast<int>(style)};
    auto it = cache.find(key);
    if (it != cache.end()) return it->second;

    const scene sc = make_scene(set, K);
    const std::vector<phong::light<double>> lights = lights_of<double>(sc, style);
    const phong::material<double> mat = material_of<double>(sc);
    const phong::environment<double> env = environment_of<double>(sc);
    std::vector<phong_test::wcolor> ref;
    for (std::size_t i : sample_indices(N)) {
        dvec3 q, n;
        make_point(sc, set, i, q, n);
        ref.push_back(phong_test::reference_shade<double>(F, q, n, mat, std::span<const phong::light<double>>(lights), env));
    }
    return cache.emplace(key, std::move(ref)).first->second;
}

/// Accuracy of one row: over every rgb channel of the sampled points, against the reference.
struct error_stats {
    double max_rel = 0, p99_ulp = 0, max_ulp = 0;
    double nan_count = 0; // over all N outputs, not only the sample
};

template <class T, int L>
error_stats measure(const std::vector<glm::vec<L, T>>& out, const std::vector<phong_test::wcolor>& ref)
{
    error_stats e;
    for (const auto& c : out)
        for (int k = 0; k < 3; ++k)
            if (!std::isfinite(c[k])) e.nan_count += 1;
    const std::vector<std::size_t> idx = sample_indices(out.size());
    std::vector<double> ulps;
    ulps.reserve(idx.size() * 3);
    for (std::size_t s = 0; s < idx.size(); ++s)
        for (int k = 0; k < 3; ++k) {
            const T c = out[idx[s]][k];
            const double rel = phong_test::error_rel(c, ref[s][k]);
            const double ulp = phong_test::error_ulp(c, ref[s][k]);
            e.max_rel = std::max(e.max_rel, rel);
            e.max_ulp = std::max(e.max_ulp, ulp);
            ulps.push_back(ulp);
        }
    if (!ulps.empty()) {
        const std::size_t k99 = std::min(ulps.size() - 1, (ulps.size() * 99) / 100);
        std::nth_element(ulps.begin(), ulps.begin() + std::ptrdiff_t(k99), ulps.end());
        e.p99_ulp = ulps[k99];
    }
    return e;
}

/// Reports time per (point, light) and the accuracy counters of a finished row.
/// ns_per_pair: CPU time / (iterations N K), in ns (a rate counter, inverted).
/// bound: the variant's published relative error bound for this input class, -1 when none is published.
template <class T, int L>
void report(benchmark::State& state, std::size_t N, std::size_t K, const std::vector<glm::vec<L, T>>& out,
            const std::vector<phong_test::wcolor>& ref, double bound)
{
    const double pairs = double(N) * double(K);
    state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(pairs));
    state.counters["ns_per_pair"] = benchmark::Counter(double(state.iterations()) * pairs * 1e-9,
                                                       benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
    const error_stats e = phong_bench::measure(out, ref);
    state.counters["max_rel_err"] = e.max_rel;
    state.counters["p99_ulp"] = e.p99_ulp;
    state.counters["max_ulp"] = e.max_ulp;
    state.counters["nan_count"] = e.nan_count;
    state.counters["bound"] = bound;
    state.counters["K"] = double(K);
    state.counters["N"] = double(N);
}

} // namespace phong_bench
