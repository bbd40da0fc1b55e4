// The published error bound of a variant for an input class: phong/accuracy.hpp's max_rel for
// the row's mode and number type (typical -> well_conditioned, the stiff sets -> shininess_1e4 and
// grazing). -1 when the header is absent or its table is not filled in (all zeros).
#pragma once

#include "inputs.hpp"

#include <phong/features.hpp>
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
    const input_class c = set == input_set::highlight ? input_class::shininess_1e4
                        : set == input_set::grazing   ? input_class::grazing
                                                      : input_class::well_conditioned;
    using phong::evaluation;
    using phong::stable_precision;
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
