// phong: the fast mode on a CUDA GPU's special-function units (SFU): in device code, float's
// fast::pow_unit and fast::rsqrt (phong/fast_math.hpp) take the hardware approximations, and their
// bounds, derived from the documented error of those instructions, are published here.
// SPDX-License-Identifier: MIT
//
// The documented errors (CUDA C++ Programming Guide, appendix "Mathematical Functions": the
// single-precision standard functions and intrinsics; NVIDIA states them as generated from
// extensive but not exhaustive tests). nvcc lowers each to one PTX instruction:
//   __log2f(x): lg2.approx.f32. Absolute error at most 2^-22 for x in [0.5, 2], else 2 ulp, and
//               2 ulp of log2 x is at most 2^-22 |log2 x| (an ulp of y is at most 2^-23 |y|):
//               |error| <= 2^-22 max(1, |log2 x|) for every positive normal x.
//   exp2f(y):   ex2.approx.f32. 2 ulp over the full range: relative error at most 2^-22 for a
//               normal result.
//   rsqrtf(x):  rsqrt.approx.f32. 2 ulp over the full range: relative error at most 2^-22.
// Under -ftz=true (implied by --use_fast_math) the three read subnormal inputs as 0 and flush
// subnormal results to 0; the bounds below are for normal numbers either way.
// tests/fast_sfu.test.cpp checks the derivation on the CPU by emulating the two instructions at
// their documented worst errors in both directions; benchmarks/cuda/shade.cu checks the bounds on
// a GPU against long double over dense sweeps.
#pragma once

#include "config.hpp"

#include <limits>

namespace phong::fast {

namespace detail {
/// The documented error of lg2.approx.f32 (__log2f): absolute, at most sfu_log2_abs max(1, |log2 x|).
inline constexpr double sfu_log2_abs = 0x1p-22;
/// The documented relative error of ex2.approx.f32 (exp2f) for a normal result: 2 ulp, at most 2^-22.
inline constexpr double sfu_exp2_rel = 0x1p-22;
/// The documented relative error of rsqrt.approx.f32 (rsqrtf): 2 ulp, at most 2^-22.
inline constexpr double sfu_rsqrt_rel = 0x1p-22;
/// Relative error bound of fast::pow_unit in float CUDA device code, x^m = 2^(m lg2(x)), where the
/// exact x^m >= 2^-24 (|m log2 x| <= 24); below that its absolute error is at most 2^-24 times it.
/// Derived: y = fl(m lg2(x)) differs from m log2 x by
///   D <= m sfu_log2_abs max(1, |log2 x|) + u |m lg2(x)|   (u = 2^-24, the product's rounding).
/// With |m log2 x| <= 24: x >= 1/2 gives m 2^-22; x < 1/2 has |log2 x| > 1, so m < 24 and the term
/// is 2^-22 |m log2 x| <= 24 2^-22. Hence D <= (1 + u) 2^-22 max(m, 24) + 24 u, and
///   2^y (1 + e), |e| <= sfu_exp2_rel:  relative error <= 2^-22 + (1 + 2^-22)(t + t^2),  t = D ln 2
/// (e^t - 1 <= t + t^2 for t <= 1; m beyond about 6e6 gives t > 1: no bound, +inf). Clamping y to
/// <= 0 only moves it toward the exact exponent (x <= 1). Unlike the CPU kernels' (relative error
/// of log2 x, pow_unit_max_rel whatever m), lg2.approx's error is absolute near x = 1, so this bound
/// grows with m: 5.2e-6 for m <= 24, 6.6e-6 at m = 32, within pow_unit_max_rel up to m = 40
/// (phong/accuracy.hpp's fast bounds hold unchanged there), 1.7e-5 at m = 100, 1.7e-3 at m = 1e4
/// (where the exact mode's own conditioning, m times the cosine's few-ulp error, is of that order).
PHONG_INLINE constexpr double pow_unit_sfu_max_rel(double m)
{
    const double u = 0x1p-24;
    const double ln2 = 0.6931471805599453;
    const double D = (1 + u) * sfu_log2_abs * (m > 24 ? m : 24.0) + 24 * u;
    const double t = D * ln2;
    if (!(t <= 1)) return std::numeric_limits<double>::infinity();
    return sfu_exp2_rel + (1 + sfu_exp2_rel) * (t + t * t);
}

/// fast::rsqrt's bound in float CUDA device code: rsqrtf's sfu_rsqrt_rel, within the CPU's
/// rsqrt_max_rel<float> (4e-7), so the fast mode's 1/|d| terms of phong/accuracy.hpp hold unchanged.
inline constexpr double rsqrt_sfu_max_rel = sfu_rsqrt_rel;

} // namespace detail

#if defined(__CUDA_ARCH__)
namespace detail {

/// fast::pow_unit on the SFU: 2^min(m lg2(x), 0), with fast::pow_unit's edges (m = 0 gives 1 for
/// every x, detail::power_of_zero's convention, here folded into one select; x >= 1 gives exactly
/// 1, which lg2.approx's documented error alone would not promise; x = 0 or NaN gives 0 for m > 0).
/// Bound: pow_unit_sfu_max_rel(m).
__device__ inline float pow_unit_sfu(float x, float m)
{
    const float p = exp2f(fminf(m * __log2f(x), 0.0f));
    return (m == 0.0f || x >= 1.0f) ? 1.0f : (x > 0.0f ? p : 0.0f);
}

} // namespace detail
#endif

} // namespace phong::fast
