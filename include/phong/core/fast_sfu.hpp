// phong: the fast mode on a CUDA GPU's special-function units: in device code, float's
// fast::pow_unit and fast::rsqrt take lg2/ex2/rsqrt.approx.f32, with bounds derived from the errors
// NVIDIA documents (CUDA C++ Programming Guide, "Mathematical Functions"; docs/cuda.md).
// SPDX-License-Identifier: MIT
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
/// Relative error bound of fast::pow_unit in float CUDA device code where x^m >= 2^-24 (below:
/// absolute, 2^-24 times it): 2^-22 + (1 + 2^-22)(t + t^2), t = ln 2 ((1 + u) 2^-22 max(m, 24) + 24 u);
/// +inf where t > 1 (m beyond ~6e6). Grows with m (lg2.approx's error is absolute near 1): within
/// pow_unit_max_rel up to m = 40, 1.7e-3 at m = 1e4. Derivation: docs/cuda.md.
PHONG_INLINE constexpr double pow_unit_sfu_max_rel(double m)
{
    const double u = 0x1p-24;
    const double ln2 = 0.6931471805599453;
    const double D = (1 + u) * sfu_log2_abs * (m > 24 ? m : 24.0) + 24 * u;
    const double t = D * ln2;
    if (!(t <= 1)) return std::numeric_limits<double>::infinity();
    return sfu_exp2_rel + (1 + sfu_exp2_rel) * (t + t * t);
}

/// fast::rsqrt's bound in float CUDA device code: rsqrtf's 2^-22, within rsqrt_max_rel<float>.
inline constexpr double rsqrt_sfu_max_rel = sfu_rsqrt_rel;

} // namespace detail

#if defined(__CUDA_ARCH__)
namespace detail {

/// fast::pow_unit on the SFU: 2^min(m lg2(x), 0), with fast::pow_unit's edges (m = 0 gives 1;
/// x >= 1 gives exactly 1; x = 0 or NaN gives 0 for m > 0). Bound: pow_unit_sfu_max_rel(m).
__device__ inline float pow_unit_sfu(float x, float m)
{
    const float p = exp2f(fminf(m * __log2f(x), 0.0f));
    return (m == 0.0f || x >= 1.0f) ? 1.0f : (x > 0.0f ? p : 0.0f);
}

} // namespace detail
#endif

} // namespace phong::fast
