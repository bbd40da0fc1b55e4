// The published error bound of a variant for an input set: phong/accuracy.hpp's max_rel for the
// row's mode and number type, for the input class whose preconditions the set satisfies; -1 where
// no class contains the set (or the header is absent, or its table is not filled in: all zeros).
//
// Which class holds which set (support/inputs.hpp against tests/support/stiff_classes.hpp):
//   stiff_grazing_nl1e-6 -> grazing_specular: K = 4 positional lights, every one at n.l in
//     [8.6e-7, 9.0e-6] (measured over the 65536 points; the class allows [2.5e-7, 3e-5] and 1-4
//     lights), diffuse and Phong or Blinn specular with m = 32 (class: [1, 200]), kd, ks and the
//     light strengths in [0.24, 1] (class: kd, ks in [0.2, 1], strengths [0.1, 1]), no ambient
//     (the set's per-light ambient is 0), n.v ~ 0.64. Not `grazing`, which is diffuse only.
//     The exact and fast modes' constants hold within the class's exact limits (specular cosines
//     >= 0.05 or <= -5e-4); the set's r.v sweeps through 0, where exact_bound is +inf.
//   stiff_highlight_m1e4 -> none: shininess_1e4 is one light, specular only; the set has four
//     lights with diffuse terms at any n.l (down to grazing) beside the one near its peak.
//   typical -> none: well_conditioned has 1-3 lights with n.l, n.v >= 0.05; the set has K = 4 or
//     16 lights around a sphere, with n.l and n.v down to 0 at the terminator and the silhouette.
#pragma once

#include "inputs.hpp"

#include <phong/inputs/features.hpp>
#if __has_include(<phong/accuracy.hpp>)
#  include <phong/accuracy.hpp>
#  define PHONG_BENCH_HAVE_ACCURACY 1
#endif

namespace phong_bench {

/// batch_row: SIMD batches run the stable mode twofold whatever features::precision says.
template <class T>
double published_bound([[maybe_unused]] const phong::features& F, [[maybe_unused]] input_set set, [[maybe_unused]] bool batch_row = false)
{
#if defined(PHONG_BENCH_HAVE_ACCURACY)
    using phong::accuracy::input_class;
    using phong::evaluation;
    using phong::stable_precision;
    if (set != input_set::grazing) return -1; // inside no class (see above)
    const input_class c = input_class::grazing_specular;
    // The exact and fast constants are stated within the class's exact limits, which the set leaves.
    if (F.mode != evaluation::stable) return -1;
    // stable_twofold_above rounds components once below its threshold: no published table (its
    // measured figures are in features.hpp's doc and README.md).
    if (F.mode == evaluation::stable && F.stable_twofold_above > 0) return -1;
    const bool twofold = F.precision == stable_precision::twofold || batch_row;
    const phong::accuracy::bound b = F.mode == evaluation::exact ? phong::accuracy::of<evaluation::exact, T>(c)
                                   : F.mode == evaluation::fast  ? phong::accuracy::of<evaluation::fast, T>(c)
                                   : twofold ? phong::accuracy::of<evaluation::stable, T, stable_precision::twofold>(c)
                                             : phong::accuracy::of<evaluation::stable, T>(c);
    if (b.max_rel == 0 && b.p99_ulp == 0 && b.max_ulp == 0) return -1; // not published yet
    return b.max_rel;
#else
    return -1;
#endif
}

} // namespace phong_bench
