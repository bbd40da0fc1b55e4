// phong: the published accuracy of each evaluation mode, per input class and number type.
// SPDX-License-Identifier: MIT
//
// accuracy::of<M, T, P>(c) reads one table per (mode, type). Exact and fast modes: the error
// analysis's bound at each class's limits, a promise for every scene of the class. Stable mode:
// measured against the model in __float128, with a margin. Derivation and reproduction: docs/accuracy.md.
#pragma once

#include "inputs/features.hpp"

#include <array>
#include <cstddef>
#include <limits>

namespace phong::accuracy {

/// The input classes the bounds are stated for (each defined precisely in docs/accuracy.md):
enum class input_class : unsigned char {
    well_conditioned,    ///< random scene: Q in a box in front of the eye, 1-3 lights (positional or directional), m in [1, 200]
    shininess_1e3,       ///< m = 1e3 near the highlight peak: angle(r, v) < 3 / sqrt(m), n.v >= 0.5, n.l > 0.05;
                         ///< one light, specular only
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
    grazing_specular,    ///< 1-4 lights at n.l in [2.5e-7, 3e-5], diffuse and specular, no ambient: a specular term
                         ///< far from its peak may outweigh the diffuse one
    non_finite,          ///< NaN or +-inf in one component of Q or the normal: every channel must be NaN
    count
};

inline constexpr std::size_t input_class_count = static_cast<std::size_t>(input_class::count);

/// The class's name as the tables print it ("count" for input_class::count, "?" past it).
PHONG_HD constexpr const char* name(input_class c)
{
    constexpr const char* names[] = {"well_conditioned", "shininess_1e3",   "shininess_1e4",      "shininess_1e5",
                                     "grazing",          "near_light_1e20", "near_light_1e40",    "huge_1e20",
                                     "huge_1e30",        "tiny_directional", "attenuation_c0_zero", "blinn_opposite",
                                     "denormal",         "shininess_zero",  "grazing_specular",   "non_finite"};
    static_assert(sizeof(names) / sizeof(names[0]) == input_class_count);
    if (static_cast<std::size_t>(c) >= input_class_count) return c == input_class::count ? "count" : "?";
    return names[static_cast<std::size_t>(c)];
}

/// The error bound of one class, per colour channel against the exact model. Finite input never
/// gives NaN or inf; non_finite's policy is NaN in every channel (bound +inf).
struct bound {
    double p99_ulp; ///< 99th percentile of the error, in ulp of the exact value
    double max_ulp; ///< the largest error in ulp
    double max_rel; ///< the largest relative error (absolute where exact = 0)
};

/// The feature set the bounds hold for: scene ambient, diffuse, specular model S gated on n.l > 0,
/// any light kind, polynomial attenuation, perspective view, mode M, stable precision P.
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
    f.view = view_model::eye_at_origin;
    f.mode = M;
    f.precision = P;
    return f;
}

namespace detail {
inline constexpr double inf = std::numeric_limits<double>::infinity();
using table = std::array<bound, input_class_count>;
} // namespace detail

/// The published bounds, indexed by input_class (read through of<M, T, P>(c)). P matters for float
/// only: double always runs twofold, and SIMD batches are held to bounds<stable, T, twofold>.
template <evaluation M, class T, stable_precision P = stable_precision::wider> inline constexpr detail::table bounds{};

// clang-format off
// Exact mode: max_rel is the error analysis at the class's worst-case conditioning (docs/accuracy.md),
// max_ulp = max_rel / u; p99_ulp is measured. Classes that may drop a vector (a squared length that
// is not a normal number) state relative error 1.
// BEGIN exact: generated by tests/tools/print_tables.cpp (phong_print_tables accuracy)
template <stable_precision P> inline constexpr detail::table bounds<evaluation::exact, float, P>{{
    /* well_conditioned    */ {40, 0x1.4569d2fbec9f2p+17, 0x1.4569d2fbec9f2p-7},
    /* shininess_1e3       */ {10000, 0x1.76c7112d1caf5p+16, 0x1.76c7112d1caf5p-8},
    /* shininess_1e4       */ {100000, 0x1.df4d034d4cbafp+19, 0x1.df4d034d4cbafp-5},
    /* shininess_1e5       */ {1e+06, 0x1.87f2373f6802cp+23, 0x1.87f2373f6802cp-1},
    /* grazing             */ {2e+06, 0x1.5005bfaebf358p+25, 0x1.5005bfaebf358p+1},
    /* near_light_1e20     */ {0x1p+24, 0x1p+24, 1},
    /* near_light_1e40     */ {0x1p+24, 0x1p+24, 1},
    /* huge_1e20           */ {0x1p+24, 0x1p+24, 1},
    /* huge_1e30           */ {0x1p+24, 0x1p+24, 1},
    /* tiny_directional    */ {0x1p+24, 0x1p+24, 1},
    /* attenuation_c0_zero */ {0x1p+24, 0x1p+24, 1},
    /* blinn_opposite      */ {30, 0x1.bcf08ce19c4e8p+14, 0x1.bcf08ce19c4e8p-10},
    /* denormal            */ {0x1p+24, 0x1p+24, 1},
    /* shininess_zero      */ {4, 0x1.f87e65add13f9p+7, 0x1.f87e65add13f9p-17},
    /* grazing_specular    */ {2e+06, 0x1.5005c5202cfb7p+25, 0x1.5005c5202cfb7p+1},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
template <stable_precision P> inline constexpr detail::table bounds<evaluation::exact, double, P>{{
    /* well_conditioned    */ {40, 0x1.462b5f201e803p+17, 0x1.462b5f201e803p-36},
    /* shininess_1e3       */ {10000, 0x1.818bcbf3ff0fbp+16, 0x1.818bcbf3ff0fbp-37},
    /* shininess_1e4       */ {100000, 0x1.e076d75e51366p+19, 0x1.e076d75e51366p-34},
    /* shininess_1e5       */ {1e+06, 0x1.2c32db5b25618p+23, 0x1.2c32db5b25618p-30},
    /* grazing             */ {2e+06, 0x1.50057b63c0023p+25, 0x1.50057b63c0023p-28},
    /* near_light_1e20     */ {60, 0x1.b694b06acb4c4p+16, 0x1.b694b06acb4c4p-37},
    /* near_light_1e40     */ {60, 0x1.b694b06acb4c4p+16, 0x1.b694b06acb4c4p-37},
    /* huge_1e20           */ {40, 0x1.462b5f201e803p+17, 0x1.462b5f201e803p-36},
    /* huge_1e30           */ {40, 0x1.462b5f201e803p+17, 0x1.462b5f201e803p-36},
    /* tiny_directional    */ {60, 0x1.b694b06acb4c4p+16, 0x1.b694b06acb4c4p-37},
    /* attenuation_c0_zero */ {0x1p+53, 0x1p+53, 1},
    /* blinn_opposite      */ {30, 0x1.cf7b07002bd05p+14, 0x1.cf7b07002bd05p-39},
    /* denormal            */ {0x1p+53, 0x1p+53, 1},
    /* shininess_zero      */ {4, 0x1.f87e000000034p+7, 0x1.f87e000000034p-46},
    /* grazing_specular    */ {2e+06, 0x1.50057ce420025p+25, 0x1.50057ce420025p-28},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// END exact
// Stable float, wider precision: evaluated in double and rounded once, so correctly rounded but for
// near-ties; published as 1 ulp.
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
    /* grazing_specular    */ {1, 1, 1.2e-07},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// Stable, twofold precision (float with precision = twofold, SIMD batches, double): twice the worst
// measured, rounded up. grazing_specular carries the power's own error, ~|m log2 c| u; the shininess
// classes' p99 holds for any distribution of the inputs within the class (docs/accuracy.md).
template <> inline constexpr detail::table bounds<evaluation::stable, float, stable_precision::twofold>{{
    /* well_conditioned    */ {3, 20, 2e-06},
    /* shininess_1e3       */ {20, 30, 2e-06},
    /* shininess_1e4       */ {20, 30, 2e-06},
    /* shininess_1e5       */ {20, 30, 2e-06},
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
    /* grazing_specular    */ {20, 90, 6e-06},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
template <stable_precision P> inline constexpr detail::table bounds<evaluation::stable, double, P>{{
    /* well_conditioned    */ {4, 20, 2e-15},
    /* shininess_1e3       */ {20, 30, 3e-15},
    /* shininess_1e4       */ {20, 30, 3e-15},
    /* shininess_1e5       */ {20, 20, 3e-15},
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
    /* grazing_specular    */ {20, 70, 9e-15},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// clang-format on

// The fast mode's bounds, derived like the exact mode's with the published errors of fast::rsqrt
// and fast::pow_unit (docs/accuracy.md, "Fast mode"). Double's p99 is ~1e9 ulp: the fast power is
// float-accurate in double too.
// clang-format off
// clang-format off
// BEGIN fast: generated by tests/tools/print_tables.cpp (phong_print_tables accuracy)
template <stable_precision P> inline constexpr detail::table bounds<evaluation::fast, float, P>{{
    /* well_conditioned    */ {50, 0x1.62d38104a6ed5p+17, 0x1.62d38104a6ed5p-7},
    /* shininess_1e3       */ {20000, 0x1.c1a594d8d2f8ap+16, 0x1.c1a594d8d2f8ap-8},
    /* shininess_1e4       */ {200000, 0x1.20d62c345a82fp+20, 0x1.20d62c345a82fp-4},
    /* shininess_1e5       */ {2e+06, 0x1.f3d1afde2de3fp+23, 0x1.f3d1afde2de3fp-1},
    /* grazing             */ {2e+06, 0x1.5005cbd8bfb7ep+25, 0x1.5005cbd8bfb7ep+1},
    /* near_light_1e20     */ {0x1p+24, 0x1p+24, 1},
    /* near_light_1e40     */ {0x1p+24, 0x1p+24, 1},
    /* huge_1e20           */ {0x1p+24, 0x1p+24, 1},
    /* huge_1e30           */ {0x1p+24, 0x1p+24, 1},
    /* tiny_directional    */ {0x1p+24, 0x1p+24, 1},
    /* attenuation_c0_zero */ {0x1p+24, 0x1p+24, 1},
    /* blinn_opposite      */ {30, 0x1.d40ca0904a78cp+14, 0x1.d40ca0904a78cp-10},
    /* denormal            */ {0x1p+24, 0x1p+24, 1},
    /* shininess_zero      */ {4, 0x1.02f5361a649e1p+8, 0x1.02f5361a649e1p-16},
    /* grazing_specular    */ {2e+06, 0x1.50ce749d9f21p+25, 0x1.50ce749d9f21p+1},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
template <stable_precision P> inline constexpr detail::table bounds<evaluation::fast, double, P>{{
    /* well_conditioned    */ {2e+09, 0x1.0c6fa4c0467e5p+36, 0x1.0c6fa4c0467e5p-17},
    /* shininess_1e3       */ {3e+09, 0x1.0c6f949ec2a5fp+36, 0x1.0c6f949ec2a5fp-17},
    /* shininess_1e4       */ {3e+09, 0x1.0c70831150b09p+36, 0x1.0c70831150b09p-17},
    /* shininess_1e5       */ {3e+09, 0x1.0c79d38b76ea5p+36, 0x1.0c79d38b76ea5p-17},
    /* grazing             */ {2e+06, 0x1.50057d30eb2bdp+25, 0x1.50057d30eb2bdp-28},
    /* near_light_1e20     */ {2e+09, 0x1.0c6f96cdff99ap+36, 0x1.0c6f96cdff99ap-17},
    /* near_light_1e40     */ {2e+09, 0x1.0c6f96cdff99ap+36, 0x1.0c6f96cdff99ap-17},
    /* huge_1e20           */ {2e+09, 0x1.0c6fa4c0467e5p+36, 0x1.0c6fa4c0467e5p-17},
    /* huge_1e30           */ {2e+09, 0x1.0c6fa4c0467e5p+36, 0x1.0c6fa4c0467e5p-17},
    /* tiny_directional    */ {2e+09, 0x1.0c6f96cdff99ap+36, 0x1.0c6f96cdff99ap-17},
    /* attenuation_c0_zero */ {0x1p+53, 0x1p+53, 1},
    /* blinn_opposite      */ {2e+09, 0x1.0c6f8176580f8p+36, 0x1.0c6f8176580f8p-17},
    /* denormal            */ {0x1p+53, 0x1p+53, 1},
    /* shininess_zero      */ {4, 0x1.ffb2aca5f625fp+7, 0x1.ffb2aca5f625fp-46},
    /* grazing_specular    */ {2e+10, 0x1.0c997e82c32bp+36, 0x1.0c997e82c32bp-17},
    /* non_finite          */ {detail::inf, detail::inf, detail::inf},
}};
// END fast
// clang-format on

/// The bound of class c for mode M, scalar type T (float or double) and stable precision P.
/// c = input_class::count or past it: every field +inf (no promise), never a read past the table.
template <evaluation M, class T, stable_precision P = stable_precision::wider>
PHONG_HD constexpr bound of(input_class c)
{
    if (static_cast<std::size_t>(c) >= input_class_count) return {detail::inf, detail::inf, detail::inf};
    return bounds<M, T, P>[static_cast<std::size_t>(c)];
}

} // namespace phong::accuracy
