// phong: the published accuracy of each evaluation mode, per input class and number type.
// SPDX-License-Identifier: MIT
//
// One constant per (mode, type): `accuracy::bounds<M, T>`, indexed by `input_class`. The doc
// comments, the tests (tests/accuracy.test.cpp asserts every class stays within its bound) and the
// benchmark counters all read these constants; nothing else states a bound.
//
// How they are measured: per colour channel, against the whole model evaluated in __float128 from
// the exact input values (tests/support/reference.hpp), over the seeded scene generators of
// tests/support/stiff_classes.hpp, with the feature set `accuracy::measured_features(M, S)` for
// both specular models S (the bound is the larger of the two). Reproduce the table with
//   cmake --preset gcc-release && cmake --build build/gcc-release --target phong_accuracy_table
//   build/gcc-release/tests/phong_accuracy_table 200000 7 --bounds
// The constants are upper bounds with a margin over that run (see README.md, "Accuracy"); CI
// step 35 checks them on other seeds, with and without FMA instructions.
// Summary, stable mode: float (evaluated in double) correctly rounded but for near-ties, within
// 1 ulp in every class; with twofold precision (double, SIMD batches, or float on request) every
// class within a few ulp (p99 <= 5, max <= 12 measured), m up to 1e5 near the peak and n.l ~ 1e-6
// included. Exact mode: the formulas as written;
// ~m eps near a sharp highlight, ~eps / (n.l) at grazing incidence, and a light, normal or view
// whose squared length is not a normal number is dropped (relative error 1, never NaN).
#pragma once

#include "features.hpp"

#include <array>
#include <cstddef>
#include <limits>

namespace phong::accuracy {

/// The input classes the bounds are stated for. The generators (tests/support/stiff_classes.hpp)
/// define each one precisely; in short:
enum class input_class : unsigned char {
    well_conditioned,    ///< random scene: Q in a box in front of the eye, 1-3 lights (positional or directional), m in [1, 200]
    shininess_1e3,       ///< m = 1e3 near the highlight peak: angle(r, v) < 3 / sqrt(m), so (r.v)^m > exp(-4.5); specular only
    shininess_1e4,       ///< the same with m = 1e4
    shininess_1e5,       ///< the same with m = 1e5
    grazing,             ///< n.l in [2.5e-7, 4e-6]: light nearly in the tangent plane, diffuse only
    near_light_1e20,     ///< a positional light at |L - Q| ~ 1e-20 (coordinates ~ 1e-17)
    near_light_1e40,     ///< a positional light at |L - Q| ~ 1e-40 (float: a subnormal distance, coordinates ~ 1e-37)
    huge_1e20,           ///< a well-conditioned scene with every coordinate (points, normal, lights) scaled by 1e20
    huge_1e30,           ///< the same scaled by 1e30
    tiny_directional,    ///< a directional light with |xyz| ~ 1e-30
    attenuation_c0_zero, ///< polynomial attenuation with c0 = 0 and d from 1e-1 down to 1e-30 (double: 1e-200)
    blinn_opposite,      ///< l = -v exactly (light behind the surface, on the line from the eye through Q)
    denormal,            ///< subnormal normal vector, subnormal directional light xyz, subnormal c1 and c2
    shininess_zero,      ///< a well-conditioned scene with m = 0 (pow(0, 0) = 1)
    non_finite,          ///< NaN or +-inf in one component of Q or the normal: every channel must be NaN
    count
};

inline constexpr std::size_t input_class_count = static_cast<std::size_t>(input_class::count);

/// The class's name as the tables print it.
PHONG_HD constexpr const char* name(input_class c)
{
    constexpr const char* names[] = {"well_conditioned", "shininess_1e3",   "shininess_1e4",      "shininess_1e5",
                                     "grazing",          "near_light_1e20", "near_light_1e40",    "huge_1e20",
                                     "huge_1e30",        "tiny_directional", "attenuation_c0_zero", "blinn_opposite",
                                     "denormal",         "shininess_zero",  "non_finite"};
    static_assert(sizeof(names) / sizeof(names[0]) == input_class_count);
    return names[static_cast<std::size_t>(c)];
}

/// The error bound of one class, per colour channel against the exact model:
/// p99_ulp: 99th percentile of the error in ulp of the exact value; max_ulp: its maximum;
/// max_rel: the largest |computed - exact| / |exact| (absolute where exact = 0).
/// Finite input never gives NaN or inf (except non_finite, whose policy is NaN in every channel;
/// its bound is +inf).
struct bound {
    double p99_ulp;
    double max_ulp;
    double max_rel;
};

/// The feature set the bounds are measured with: scene ambient, diffuse, the specular model S
/// gated on n.l > 0, lights of any kind (w read at run time), polynomial attenuation, perspective
/// view, evaluation mode M. Other feature sets run the same kernels for the terms they keep.
constexpr features measured_features(evaluation M, specular_model S, stable_precision P = stable_precision::wider)
{
    features f{};
    f.scene_ambient = true;
    f.light_ambient = false;
    f.diffuse = true;
    f.specular = S;
    f.specular_gate = true;
    f.lights = light_kind::any;
    f.attenuation = attenuation_model::polynomial;
    f.view = view_model::perspective;
    f.mode = M;
    f.precision = P;
    return f;
}

namespace detail {
inline constexpr double inf = std::numeric_limits<double>::infinity();
using table = std::array<bound, input_class_count>;
} // namespace detail

/// The published bounds, indexed by input_class (use accuracy::of<M, T>(c)). P, the stable mode's
/// precision (features::precision), matters for float only: double always runs twofold, and so
/// do SIMD batches (their bound is bounds<stable, T, twofold>).
template <evaluation M, class T, stable_precision P = stable_precision::wider> inline constexpr detail::table bounds{};

// clang-format off
// Measured: build/gcc-release/tests/phong_accuracy_table 200000 7 --code (200000 scenes per
// class, 600000 channels, both specular models), then twice the worst figure rounded up to one
// digit. Where the exact mode drops a light, normal or view (a squared length that is not a
// normal number: float |L - Q| ~ 1e-20, 1e-40, coordinates 1e20, 1e30, |xyz| = 1e-30, c0 = 0
// with d -> 0, subnormal normals; double: the last two), the computed channel keeps only the
// terms it still has, so it lies in [0, exact] (up to rounding): relative error <= 1, hence
// < 2^24 ulp in float (2^53 in double); those entries state that bound.
template <stable_precision P> inline constexpr detail::table bounds<evaluation::exact, float, P>{{
    /* well_conditioned    */ {40, 5000, 0.0003},
    /* shininess_1e3       */ {10000, 30000, 0.002},
    /* shininess_1e4       */ {100000, 300000, 0.02},
    /* shininess_1e5       */ {1e+06, 3e+06, 0.2},
    /* grazing             */ {2e+06, 7e+06, 0.5},
    /* near_light_1e20     */ {0x1p24, 0x1p24, 1},
    /* near_light_1e40     */ {0x1p24, 0x1p24, 1},
    /* huge_1e20           */ {0x1p24, 0x1p24, 1},
    /* huge_1e30           */ {0x1p24, 0x1p24, 1},
    /* tiny_directional    */ {0x1p24, 0x1p24, 1},
    /* attenuation_c0_zero */ {0x1p24, 0x1p24, 1},
    /* blinn_opposite      */ {30, 700, 6e-05},
    /* denormal            */ {0x1p24, 0x1p24, 1},
    /* shininess_zero      */ {4, 50, 3e-06},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
template <stable_precision P> inline constexpr detail::table bounds<evaluation::exact, double, P>{{
    /* well_conditioned    */ {40, 2000, 4e-13},
    /* shininess_1e3       */ {10000, 30000, 3e-12},
    /* shininess_1e4       */ {100000, 300000, 3e-11},
    /* shininess_1e5       */ {1e+06, 3e+06, 3e-10},
    /* grazing             */ {2e+06, 6e+06, 7e-10},
    /* near_light_1e20     */ {60, 2000, 2e-13},
    /* near_light_1e40     */ {60, 2000, 2e-13},
    /* huge_1e20           */ {40, 2000, 2e-13},
    /* huge_1e30           */ {40, 2000, 3e-13},
    /* tiny_directional    */ {60, 2000, 3e-13},
    /* attenuation_c0_zero */ {0x1p53, 0x1p53, 1},
    /* blinn_opposite      */ {30, 500, 8e-14},
    /* denormal            */ {0x1p53, 0x1p53, 1},
    /* shininess_zero      */ {4, 50, 6e-15},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// Stable float, wider precision: evaluated in double and rounded once, so every finite class is
// float's correct rounding of the model but for near-ties (measured: max 0.5 ulp, 5.9e-8 in every
// class); published as 1 ulp.
template <> inline constexpr detail::table bounds<evaluation::stable, float, stable_precision::wider>{{
    /* well_conditioned    */ {1, 1, 1.2e-07},
    /* shininess_1e3       */ {1, 1, 1.2e-07},
    /* shininess_1e4       */ {1, 1, 1.2e-07},
    /* shininess_1e5       */ {1, 1, 1.2e-07},
    /* grazing             */ {1, 1, 1.2e-07},
    /* near_light_1e20     */ {1, 1, 1.2e-07},
    /* near_light_1e40     */ {1, 1, 1.2e-07},
    /* huge_1e20           */ {1, 1, 1.2e-07},
    /* huge_1e30           */ {1, 1, 1.2e-07},
    /* tiny_directional    */ {1, 1, 1.2e-07},
    /* attenuation_c0_zero */ {1, 1, 1.2e-07},
    /* blinn_opposite      */ {1, 1, 1.2e-07},
    /* denormal            */ {1, 1, 1.2e-07},
    /* shininess_zero      */ {1, 1, 1.2e-07},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// Stable, twofold precision (float with features::precision = twofold, SIMD batches, and double).
template <> inline constexpr detail::table bounds<evaluation::stable, float, stable_precision::twofold>{{
    /* well_conditioned    */ {3, 20, 2e-06},
    /* shininess_1e3       */ {10, 30, 2e-06},
    /* shininess_1e4       */ {9, 30, 2e-06},
    /* shininess_1e5       */ {10, 30, 2e-06},
    /* grazing             */ {5, 20, 7e-07},
    /* near_light_1e20     */ {4, 20, 8e-07},
    /* near_light_1e40     */ {4, 20, 8e-07},
    /* huge_1e20           */ {4, 10, 7e-07},
    /* huge_1e30           */ {4, 8, 6e-07},
    /* tiny_directional    */ {3, 9, 2e-06},
    /* attenuation_c0_zero */ {5, 20, 2e-06},
    /* blinn_opposite      */ {4, 10, 7e-07},
    /* denormal            */ {4, 10, 1e-06},
    /* shininess_zero      */ {4, 10, 9e-07},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
template <stable_precision P> inline constexpr detail::table bounds<evaluation::stable, double, P>{{
    /* well_conditioned    */ {4, 20, 2e-15},
    /* shininess_1e3       */ {10, 30, 3e-15},
    /* shininess_1e4       */ {9, 30, 3e-15},
    /* shininess_1e5       */ {10, 20, 3e-15},
    /* grazing             */ {5, 20, 2e-15},
    /* near_light_1e20     */ {4, 20, 2e-15},
    /* near_light_1e40     */ {4, 20, 2e-15},
    /* huge_1e20           */ {4, 9, 2e-15},
    /* huge_1e30           */ {4, 20, 2e-15},
    /* tiny_directional    */ {3, 20, 2e-15},
    /* attenuation_c0_zero */ {5, 20, 3e-15},
    /* blinn_opposite      */ {4, 10, 2e-15},
    /* denormal            */ {4, 10, 3e-15},
    /* shininess_zero      */ {4, 9, 2e-15},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// clang-format on

/// The bound of class c for mode M, scalar type T (float or double) and stable precision P.
template <evaluation M, class T, stable_precision P = stable_precision::wider>
PHONG_HD constexpr bound of(input_class c)
{
    return bounds<M, T, P>[static_cast<std::size_t>(c)];
}

} // namespace phong::accuracy
