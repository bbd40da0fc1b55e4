// batch.hpp on the stiff and extreme input classes of phong/accuracy.hpp: shade_batch in stable
// (and fast) mode stays within that mode's published bounds (the same constants the scalar path is held
// to), produces no NaN/inf for finite input, and NaN in every channel for non-finite geometry.
#include "support/numeric.hpp"
#include "support/reference.hpp"
#include "support/stiff_classes.hpp"

#include <phong/accuracy.hpp>
#include <phong/batch.hpp>

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace phong;
using namespace phong_test;

namespace {

/// shade_batch on W + 1 copies of each scene (a full step and a tail), every lane compared with
/// lane 0, lane 0 against the reference: the batch path's error statistics over one class.
template <features F, class T>
error_stats measure_batch(const std::vector<phong_test::stiff_scene<T>>& scenes, std::size_t& lanes_disagree)
{
    error_accumulator acc;
    const std::size_t n = batch_width<T> + 1;
    std::vector<T> px, py, pz, nx, ny, nz, r(n), g(n), b(n);
    for (const phong_test::stiff_scene<T>& s : scenes) {
        px.assign(n, s.position.x), py.assign(n, s.position.y), pz.assign(n, s.position.z);
        nx.assign(n, s.normal.x), ny.assign(n, s.normal.y), nz.assign(n, s.normal.z);
        shade_batch<F>(soa3<T>{px, py, pz}, soa3<T>{nx, ny, nz}, s.material, std::span<const light<T>>(s.lights),
                       soa_rgba<T>{r, g, b, {}}, s.environment);
        const wcolor ref = reference_scene(F, s);
        for (std::size_t i = 1; i < n; ++i)
            if (std::memcmp(&r[i], &r[0], sizeof(T)) != 0 || std::memcmp(&b[i], &b[0], sizeof(T)) != 0) ++lanes_disagree;
        acc.add<T>(r[0], ref.r);
        acc.add<T>(g[0], ref.g);
        acc.add<T>(b[0], ref.b);
    }
    return acc.summary();
}

/// Shininess in [1, 64] rounded to an integer (the others kept): the fast mode's lanes then take
/// fast::detail::pow_integer (one integer shininess for all points) instead of fast::pow_unit's kernels.
template <class T> void round_small_shininess(std::vector<phong_test::stiff_scene<T>>& scenes)
{
    for (phong_test::stiff_scene<T>& s : scenes)
        if (s.material.shininess >= T(1) && s.material.shininess <= T(64)) s.material.shininess = std::round(s.material.shininess);
}

template <class T, specular_model S, evaluation M = evaluation::stable, bool integer_shininess = false> void check_batch_classes()
{
    using phong::accuracy::input_class;
    constexpr features F = phong::accuracy::measured_features(M, S);
    for (std::size_t c = 0; c < phong::accuracy::input_class_count; ++c) {
        const auto cls = static_cast<input_class>(c);
        // Without __float128 (clang: no quadmath.h) the reference is long double, whose own error
        // exceeds these double bounds (see tests/accuracy.test.cpp): checked by the g++ build only.
        if (wide_digits < 113 && sizeof(T) == 8 &&
            (cls == input_class::shininess_1e4 || cls == input_class::shininess_1e5 || cls == input_class::grazing ||
             cls == input_class::grazing_specular))
            continue;
        auto scenes = make_class<T>(cls, 300, 500 + c);
        if constexpr (integer_shininess) round_small_shininess(scenes);
        std::size_t disagree = 0;
        const error_stats e = measure_batch<F>(scenes, disagree);
        const phong::accuracy::bound bound = M == evaluation::fast    ? phong::accuracy::of<evaluation::fast, T>(cls)
                                             : M == evaluation::exact ? phong::accuracy::of<evaluation::exact, T>(cls)
                                                                      : phong::accuracy::of<M, T, phong::stable_precision::twofold>(cls);
        CAPTURE(std::string(phong::accuracy::name(cls)));
        CAPTURE(e.p99_ulp);
        CAPTURE(e.max_ulp);
        CAPTURE(e.max_rel);
        MESSAGE((std::string(M == evaluation::fast ? "fast " : M == evaluation::exact ? "exact " : "stable ") + (integer_shininess ? "(integer m) " : "") + phong::accuracy::name(cls) + (sizeof(T) == 4 ? " float " : " double ") + (S == specular_model::phong ? "phong" : "blinn"))
                << ": p99 " << e.p99_ulp << " max " << e.max_ulp << " ulp, max rel " << e.max_rel << ", non-finite " << e.non_finite);
        CHECK(disagree == 0);
        if (cls == input_class::non_finite) {
#if defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
            continue; // -ffinite-math-only: NaN and inf inputs give unspecified values (docs/compilers.md)
#endif
            CHECK(e.non_finite == e.channels); // NaN in every channel
            continue;
        }
        CHECK(e.non_finite == 0);
#if defined(__GNUC__) && !defined(__clang__) && PHONG_FP_REASSOCIATION && !defined(__FMA__)
        // g++ -ffast-math without FMA instructions: the exact double lanes' p99 in tiny_directional
        // (measured with the SSE2 lanes, PHONG_SIMD_WITHOUT_FMA; shade_batch now shades point by
        // point there) over these 300 scenes was 69 ulp against the published 60; a p99 of 300 scenes is a noisy
        // statistic (12 to 69 across seeds and builds, IEEE 16 to 50), and over 6000 scenes it is 35
        // (IEEE 33). So there the p99 is checked on 3000 scenes (docs/compilers.md, "-ffast-math").
        if (M == evaluation::exact && sizeof(T) == 8 && cls == input_class::tiny_directional) {
            auto more = make_class<T>(cls, 3000, 500 + c);
            std::size_t more_disagree = 0;
            CHECK(measure_batch<F>(more, more_disagree).p99_ulp <= bound.p99_ulp);
        } else {
            CHECK(e.p99_ulp <= bound.p99_ulp);
        }
#else
        CHECK(e.p99_ulp <= bound.p99_ulp);
#endif
        CHECK(e.max_ulp <= bound.max_ulp);
        CHECK(e.max_rel <= bound.max_rel);
    }
}

} // namespace

TEST_CASE_TEMPLATE("shade_batch stable: every stiff and extreme class within the published stable bound", T, float, double)
{
    if constexpr (phong::detail::ieee::twofold_allowed<T>) { // -ffast-math: refused at compile time (docs/compilers.md)
        check_batch_classes<T, specular_model::phong>();
        check_batch_classes<T, specular_model::blinn>();
    }
}

// The exact mode's lanes (xsimd's exp and log for double, detail/lanes_power.hpp for float) within
// the exact bounds; with tests/support's scenes also in the -ffast-math build of .ci/steps/36-fast-math.sh.
TEST_CASE_TEMPLATE("shade_batch exact: every stiff and extreme class within the published exact bound", T, float, double)
{
    check_batch_classes<T, specular_model::phong, evaluation::exact>();
    check_batch_classes<T, specular_model::blinn, evaluation::exact>();
}

TEST_CASE_TEMPLATE("shade_batch fast: every stiff and extreme class within the published fast bound", T, float, double)
{
    check_batch_classes<T, specular_model::phong, evaluation::fast>();
    check_batch_classes<T, specular_model::blinn, evaluation::fast>();
}

TEST_CASE_TEMPLATE("shade_batch fast, integer shininess (binary powering): every class within the published fast bound", T, float, double)
{
    check_batch_classes<T, specular_model::phong, evaluation::fast, true>();
    check_batch_classes<T, specular_model::blinn, evaluation::fast, true>();
}

#if !PHONG_FP_REASSOCIATION || defined(PHONG_ALLOW_REASSOCIATED_TWOFOLD) // the batch stable mode refuses -ffast-math builds
TEST_CASE("shade_batch stable, float: both sides of the double-lane route's shininess limit stay within the m = 1e5 bound")
{
    // Float lanes run the geometry in double up to m = 2^20 (detail/simd/stable_lanes.hpp) and the
    // twofold route above. The near-peak scenes of the shininess classes at m = 1e6 (double lanes,
    // at the limit's edge: the double x's error, about m 10 2^-53, is largest there) and at m = 2e6 and
    // 1e8 (twofold route) meet the published bound of the largest published class, shininess_1e5.
    using phong::accuracy::input_class;
    const phong::accuracy::bound bound = phong::accuracy::of<evaluation::stable, float, phong::stable_precision::twofold>(input_class::shininess_1e5);
    for (const double m : {1e6, 2e6, 1e8}) {
        phong_test::splitmix g{0x5eed ^ std::uint64_t(m)};
        std::vector<phong_test::stiff_scene<float>> scenes;
        for (int i = 0; i < 300; ++i) scenes.push_back(phong_test::detail::near_peak<float>(g, m));
        for (const specular_model S : {specular_model::phong, specular_model::blinn}) {
            std::size_t disagree = 0;
            const error_stats e = S == specular_model::phong
                                      ? measure_batch<phong::accuracy::measured_features(evaluation::stable, specular_model::phong), float>(scenes, disagree)
                                      : measure_batch<phong::accuracy::measured_features(evaluation::stable, specular_model::blinn), float>(scenes, disagree);
            CAPTURE(m);
            CAPTURE(std::string(S == specular_model::phong ? "phong" : "blinn"));
            MESSAGE("stable float m = " << m << std::string(S == specular_model::phong ? " phong" : " blinn") << ": p99 " << e.p99_ulp << " max "
                                        << e.max_ulp << " ulp, max rel " << e.max_rel);
            CHECK(disagree == 0);
            CHECK(e.non_finite == 0);
            CHECK(e.p99_ulp <= bound.p99_ulp);
            CHECK(e.max_ulp <= bound.max_ulp);
            CHECK(e.max_rel <= bound.max_rel);
        }
    }
}

TEST_CASE_TEMPLATE("shade_batch stable: a grazing light's specular cosine near 0, within grazing_specular's bound", T, float, double)
{
    // Scenes outside the class generator's exact-mode limits (detail::grazing_cosine_near_zero): the
    // float lanes (detail/simd/stable_lanes.hpp) and double lanes (twofold route) read the cosine itself
    // there; 1 - x rounded to float was 8e4 ulp off at c = 1e-6, m = 1.
    using phong::accuracy::input_class;
    if (wide_digits < 113 && sizeof(T) == 8) return; // a long double reference cannot resolve n.l ~ 1e-6 in double
    const phong::accuracy::bound bound = phong::accuracy::of<evaluation::stable, T, phong::stable_precision::twofold>(input_class::grazing_specular);
    for (const specular_model S : {specular_model::phong, specular_model::blinn}) {
        phong_test::splitmix g{0xba7c ^ std::uint64_t(S)};
        std::vector<phong_test::stiff_scene<T>> scenes;
        for (int i = 0; i < 1000; ++i) scenes.push_back(phong_test::detail::grazing_cosine_near_zero<T>(g, S));
        std::size_t disagree = 0;
        const error_stats e = S == specular_model::phong
                                  ? measure_batch<phong::accuracy::measured_features(evaluation::stable, specular_model::phong), T>(scenes, disagree)
                                  : measure_batch<phong::accuracy::measured_features(evaluation::stable, specular_model::blinn), T>(scenes, disagree);
        CAPTURE(std::string(S == specular_model::phong ? "phong" : "blinn"));
        MESSAGE((std::string("stable cosine near 0 ") + (sizeof(T) == 4 ? "float " : "double ") + (S == specular_model::phong ? "phong" : "blinn"))
                << ": p99 " << e.p99_ulp << " max " << e.max_ulp << " ulp, max rel " << e.max_rel);
        CHECK(disagree == 0);
        CHECK(e.non_finite == 0);
        CHECK(e.p99_ulp <= bound.p99_ulp);
        CHECK(e.max_ulp <= bound.max_ulp);
        CHECK(e.max_rel <= bound.max_rel);
    }
}
#endif
