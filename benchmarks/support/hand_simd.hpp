// A hand-written SIMD baseline: what an expert writes with intrinsics for exactly the model of
// shade.bench.cpp's rows (phong's batch rows are compared with it in the report).
//
// Model (presets::glsl_ads, exact mode, positional lights, eye at the origin, float):
//   rgb = ka sum_i La_i + sum_i [n.l_i > 0] ( kd Ld_i (n.l_i) + ks Ls_i max(c_i, 0)^m ),
//   n = N / |N|, v = -Q / |Q|, d_i = L_i - Q, l_i = d_i / |d_i|,
//   Phong: c_i = r_i.v = (2 (n.d_i)(n.v) - d_i.v) / |d_i|          (r_i = reflect(-l_i, n))
//   Blinn: c_i = n.h_i = (n.l_i + n.v) / |l_i + v|                  (h_i = normalize(l_i + v))
// with c_i clamped to 1. These are the terms of shade.bench.cpp's model(), the model of the
// naive_glm / scalar / batch rows, so every row's error is measured against the same reference.
// It is not accuracy::measured_features (scene ambient, any light kind, polynomial attenuation):
// that set is the one of classes.bench.cpp's class.* rows, which have no batch rows to compare.
//
// Layout: SoA float input (x, y, z arrays of positions and normals), SoA rgb output, W = 16 points
// per step (AVX-512, __m512), 8 (AVX2 + FMA, __m256) or 4 (AArch64 NEON, float32x4_t). Per call,
// hoisted: per light L_i, kd Ld_i and ks Ls_i (the material folded into the light), and
// ka sum_i La_i; per W points, in registers: n, v, n.v; the light loop runs over broadcast
// constants with every pair's work inline.
//
// Approximations (u = 2^-24, the unit roundoff of float):
//  * 1/sqrt(x): hardware estimate y0 (AVX-512 rsqrt14: |e0| < 2^-14; AVX2 rsqrt: |e0| <= 1.5 2^-12)
//    and one Newton step in correction form, y1 = y0 + (y0 / 2)(1 - (x y0) y0) with fused
//    multiply-adds. The step squares the estimate's error: 1.5 e0^2 (0.1 u; AVX2 3.4 u), plus the
//    rounding of x y0 (u, halved by the factor y0 / 2) and of the last fma (u) (NEON: vrsqrte's
//    |e0| < 2^-8 takes two steps, 1.5 (1.5 e0^2)^2 < 2^-30 plus the same roundings):
//      |rel err| <= 1.6 u (AVX-512; measured 1.25 u; NEON the same),  <= 4.9 u (AVX2).
//  * x^m for x in [0, 1], m >= 0 as 2^(m log2 x):
//    log2: x = 2^e f with f in [sqrt(1/2), sqrt(2)) by integer arithmetic on the bits (exact),
//      log2 f = t P(t), t = f - 1 (exact), P of degree 8 (Chebyshev fit of log2(1 + t) / t; fit error
//      3.0e-8 = 0.5 u relative); log2 x = fma(t, P, e). Horner with |t| <= 0.415 and alternating
//      coefficients adds about 2.5 u: the computed L = log2 x (1 + dL), |dL| <= 4 u (for e != 0,
//      |t P| <= 1/2 <= |log2 x|, so the relative bound holds there too).
//    y = m L rounded: |y_computed - m log2 x| <= 5 u |y|.
//    exp2: k = round(y), r = y - k in [-1/2, 1/2] (exact), 2^r = 1 + r Q(r), Q of degree 5 (fit
//      error 5e-9 = 0.1 u relative), Horner about 2 u; 2^k applied exactly (AVX-512 scalef, masked;
//      AVX2 exponent-field arithmetic on y clamped to >= -101, and a mask), and results below
//      2^-100 (y < -100, e^-69.3) flushed to 0, as an expert does: no subnormal number is made or
//      read (each costs a microcode assist on Intel cores without FTZ/DAZ), and no product of the
//      power by a colour coefficient of at least 2^-26 is subnormal either. phong's shading flushes
//      at the same floor (detail::ieee::power_floor_log2), so the two compute the same values.
//    Total, to first order: |rel err of x^m| <= ln 2 * 5 u |y| + 2.5 u <= (3.5 |y| + 2.5) u,
//    y = m log2 x: 2.5 u at the highlight peak, 38 u at x^m = 2^-10, 86 u at 2^-24 (where the term
//    is below float resolution of the other terms anyway). hand_simd_check.cpp measures it.
//    Edges: x = 0 gives 0 for m > 0 and 1 for m = 0 (pow(0, 0) = 1); 0 < x < 2^-126 is taken as
//    2^-126 (absolute error <= 2^(-126 m)); x^m < 2^-100 gives 0 (absolute error < 2^-100).
//  * Not handled (the benchmark's inputs have none): a light at Q, Q at the eye, a zero normal, or
//    any squared length that is not a normal float (NaN or inf there). Blinn's l = -v gives a
//    finite c (|l + v|^2 is raised to 2^-126 first).
// The error of the whole colour is the model's conditioning (about m times the few-u error of c
// near a highlight, u / (n.l) at the terminator, as in every exact row) plus the above. Measured on
// the typical rows (m = 32): max_rel_err 6.7e-6 at K = 1, and the same with libm's pow in place of
// the polynomial power, so there it is the conditioning at n.l -> 0; the report's counters measure it
// against the __float128 reference, and check_against_scalar() (used by the benchmark rows and by
// phong_hand_simd_check) asserts agreement with phong's scalar shade<F> within check_tolerance.
#pragma once

#include <phong/phong.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#if defined(__AVX512F__) || (defined(__AVX2__) && defined(__FMA__))
#  include <immintrin.h>
#  define PHONG_HAND_SIMD 1
#elif defined(__aarch64__)
#  include <arm_neon.h>
#  define PHONG_HAND_SIMD 1
#else
#  define PHONG_HAND_SIMD 0
#endif

namespace phong_bench::hand_simd {

/// Per-call constants, hoisted out of the point loop.
struct light_constants {
    float x, y, z;    ///< light position (w = 1)
    float dr, dg, db; ///< kd * Ld
    float sr, sg, sb; ///< ks * Ls
};
struct constants {
    std::vector<light_constants> lights;
    float ambient[3]; ///< ka * sum_i La_i
    float m;          ///< shininess
};

inline constants make_constants(std::span<const phong::light<float>> lights, const phong::material<float>& mat)
{
    constants c{};
    glm::vec3 la(0);
    for (const phong::light<float>& L : lights) {
        la += L.ambient;
        c.lights.push_back({L.position.x, L.position.y, L.position.z, mat.kd.x * L.diffuse.x, mat.kd.y * L.diffuse.y,
                            mat.kd.z * L.diffuse.z, mat.ks.x * L.specular.x, mat.ks.y * L.specular.y, mat.ks.z * L.specular.z});
    }
    for (int k = 0; k < 3; ++k) c.ambient[k] = mat.ka[k] * la[k];
    c.m = mat.shininess;
    return c;
}

// Polynomial coefficients, highest degree first (Chebyshev fits in mpmath, rounded to float).
// log2(1 + t) = t P(t) on t in [sqrt(1/2) - 1, sqrt(2) - 1]
inline constexpr float log2_coef[9] = {0.1231096846719146f,  -0.20586188051276055f, 0.21607822552243777f,
                                       -0.2391698814010418f, 0.28790326092450147f,  -0.36069326813533614f,
                                       0.48091075345941253f, -0.7213474682495624f,  1.4426950035679822f};
// 2^r = 1 + r Q(r) on r in [-1/2, 1/2]
inline constexpr float exp2_coef[6] = {0.0001545316294512069f, 0.0013390863364671234f, 0.009618082557277852f,
                                       0.05550357114219078f,   0.24022650760568126f,   0.6931471880262288f};

#if PHONG_HAND_SIMD
#  define PHONG_HAND_INLINE inline __attribute__((always_inline))

#  if defined(__aarch64__)
/// AArch64 NEON (Advanced SIMD): 4 float lanes, masks as all-ones / all-zeros lanes. Every
/// aarch64 has fused multiply-adds (vfmaq_f32). NEON's 1/sqrt estimate (vrsqrteq_f32) has only
/// about 8 correct bits, so rsqrt below takes two Newton steps (rsqrt_steps) to reach AVX-512's
/// 1.6 u (the first step leaves about 2^-16, the second the roundings).
struct isa {
    using V = float32x4_t;
    using M = uint32x4_t;
    static constexpr std::size_t W = 4;
    static constexpr const char* name = "neon";
    static constexpr int rsqrt_steps = 2;
    static constexpr bool clamp_y = true; // y >= -101: 2^k a normal float
    static PHONG_HAND_INLINE V load(const float* p) { return vld1q_f32(p); }
    static PHONG_HAND_INLINE void store(float* p, V v) { vst1q_f32(p, v); }
    static PHONG_HAND_INLINE V set1(float x) { return vdupq_n_f32(x); }
    static PHONG_HAND_INLINE V add(V a, V b) { return vaddq_f32(a, b); }
    static PHONG_HAND_INLINE V sub(V a, V b) { return vsubq_f32(a, b); }
    static PHONG_HAND_INLINE V mul(V a, V b) { return vmulq_f32(a, b); }
    static PHONG_HAND_INLINE V fma(V a, V b, V c) { return vfmaq_f32(c, a, b); }              // a b + c
    static PHONG_HAND_INLINE V fms(V a, V b, V c) { return vfmaq_f32(vnegq_f32(c), a, b); }   // a b - c
    static PHONG_HAND_INLINE V fnma(V a, V b, V c) { return vfmsq_f32(c, a, b); }             // c - a b
    static PHONG_HAND_INLINE V min(V a, V b) { return vminq_f32(a, b); }
    static PHONG_HAND_INLINE V max(V a, V b) { return vmaxq_f32(a, b); }
    static PHONG_HAND_INLINE V rsqrt_estimate(V x) { return vrsqrteq_f32(x); }
    static PHONG_HAND_INLINE M gt(V a, V b) { return vcgtq_f32(a, b); }
    static PHONG_HAND_INLINE M both(M a, M b) { return vandq_u32(a, b); }
    static PHONG_HAND_INLINE M either(M a, M b) { return vorrq_u32(a, b); }
    static PHONG_HAND_INLINE M all_if(bool b) { return vdupq_n_u32(b ? ~0u : 0u); }
    static PHONG_HAND_INLINE V zero_unless(M m, V v) { return vreinterpretq_f32_u32(vandq_u32(m, vreinterpretq_u32_f32(v))); }
    static PHONG_HAND_INLINE V round(V y) { return vrndnq_f32(y); }
    /// p 2^k for integral k in [-101, 0] (2^k built in the exponent field) where y >= y_floor, else 0.
    static PHONG_HAND_INLINE V ldexp_above(V p, V k, V y, V y_floor)
    {
        const int32x4_t field = vaddq_s32(vcvtq_s32_f32(k), vdupq_n_s32(127));
        return zero_unless(vcgeq_f32(y, y_floor), mul(p, vreinterpretq_f32_s32(vshlq_n_s32(field, 23))));
    }
    static PHONG_HAND_INLINE V split(V x, V& e)
    {
        const int32x4_t bits = vreinterpretq_s32_f32(x);
        const int32x4_t ei = vshrq_n_s32(vsubq_s32(bits, vdupq_n_s32(0x3f3504f3)), 23);
        e = vcvtq_f32_s32(ei);
        return sub(vreinterpretq_f32_s32(vsubq_s32(bits, vshlq_n_s32(ei, 23))), set1(1));
    }
};
#  elif defined(__AVX512F__)
/// AVX-512F: 16 float lanes, k-register masks.
struct isa {
    using V = __m512;
    using M = __mmask16;
    static constexpr std::size_t W = 16;
    static constexpr const char* name = "avx512";
    static constexpr bool clamp_y = false; // the masked scalef leaves the lanes below the floor alone
    static constexpr int rsqrt_steps = 1;
    static PHONG_HAND_INLINE V load(const float* p) { return _mm512_loadu_ps(p); }
    static PHONG_HAND_INLINE void store(float* p, V v) { _mm512_storeu_ps(p, v); }
    static PHONG_HAND_INLINE V set1(float x) { return _mm512_set1_ps(x); }
    static PHONG_HAND_INLINE V add(V a, V b) { return _mm512_add_ps(a, b); }
    static PHONG_HAND_INLINE V sub(V a, V b) { return _mm512_sub_ps(a, b); }
    static PHONG_HAND_INLINE V mul(V a, V b) { return _mm512_mul_ps(a, b); }
    static PHONG_HAND_INLINE V fma(V a, V b, V c) { return _mm512_fmadd_ps(a, b, c); }   // a b + c
    static PHONG_HAND_INLINE V fms(V a, V b, V c) { return _mm512_fmsub_ps(a, b, c); }   // a b - c
    static PHONG_HAND_INLINE V fnma(V a, V b, V c) { return _mm512_fnmadd_ps(a, b, c); } // c - a b
    static PHONG_HAND_INLINE V min(V a, V b) { return _mm512_min_ps(a, b); }
    static PHONG_HAND_INLINE V max(V a, V b) { return _mm512_max_ps(a, b); }
    static PHONG_HAND_INLINE V rsqrt_estimate(V x) { return _mm512_rsqrt14_ps(x); }
    static PHONG_HAND_INLINE M gt(V a, V b) { return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ); }
    static PHONG_HAND_INLINE M both(M a, M b) { return static_cast<M>(a & b); }
    static PHONG_HAND_INLINE M either(M a, M b) { return static_cast<M>(a | b); }
    static PHONG_HAND_INLINE M all_if(bool b) { return b ? M(0xffff) : M(0); }
    static PHONG_HAND_INLINE V zero_unless(M m, V v) { return _mm512_maskz_mov_ps(m, v); }
    static PHONG_HAND_INLINE V round(V y) { return _mm512_roundscale_ps(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC); }
    /// p 2^k for integral k where y >= y_floor, else 0 (masked: no result, no exception).
    static PHONG_HAND_INLINE V ldexp_above(V p, V k, V y, V y_floor)
    {
        return _mm512_maskz_scalef_ps(_mm512_cmp_ps_mask(y, y_floor, _CMP_GE_OQ), p, k);
    }
    /// x = 2^e f, f in [sqrt(1/2), sqrt(2)): returns f - 1 and e (as float). x normal, positive.
    static PHONG_HAND_INLINE V split(V x, V& e)
    {
        const __m512i bits = _mm512_castps_si512(x);
        const __m512i ei = _mm512_srai_epi32(_mm512_sub_epi32(bits, _mm512_set1_epi32(0x3f3504f3)), 23);
        e = _mm512_cvtepi32_ps(ei);
        return sub(_mm512_castsi512_ps(_mm512_sub_epi32(bits, _mm512_slli_epi32(ei, 23))), set1(1));
    }
};
#  else
/// AVX2 + FMA: 8 float lanes, masks as all-ones / all-zeros lanes.
struct isa {
    using V = __m256;
    using M = __m256;
    static constexpr std::size_t W = 8;
    static constexpr const char* name = "avx2";
    static constexpr bool clamp_y = true; // y >= -101: 2^k a normal float
    static constexpr int rsqrt_steps = 1;
    static PHONG_HAND_INLINE V load(const float* p) { return _mm256_loadu_ps(p); }
    static PHONG_HAND_INLINE void store(float* p, V v) { _mm256_storeu_ps(p, v); }
    static PHONG_HAND_INLINE V set1(float x) { return _mm256_set1_ps(x); }
    static PHONG_HAND_INLINE V add(V a, V b) { return _mm256_add_ps(a, b); }
    static PHONG_HAND_INLINE V sub(V a, V b) { return _mm256_sub_ps(a, b); }
    static PHONG_HAND_INLINE V mul(V a, V b) { return _mm256_mul_ps(a, b); }
    static PHONG_HAND_INLINE V fma(V a, V b, V c) { return _mm256_fmadd_ps(a, b, c); }
    static PHONG_HAND_INLINE V fms(V a, V b, V c) { return _mm256_fmsub_ps(a, b, c); }
    static PHONG_HAND_INLINE V fnma(V a, V b, V c) { return _mm256_fnmadd_ps(a, b, c); }
    static PHONG_HAND_INLINE V min(V a, V b) { return _mm256_min_ps(a, b); }
    static PHONG_HAND_INLINE V max(V a, V b) { return _mm256_max_ps(a, b); }
    static PHONG_HAND_INLINE V rsqrt_estimate(V x) { return _mm256_rsqrt_ps(x); }
    static PHONG_HAND_INLINE M gt(V a, V b) { return _mm256_cmp_ps(a, b, _CMP_GT_OQ); }
    static PHONG_HAND_INLINE M both(M a, M b) { return _mm256_and_ps(a, b); }
    static PHONG_HAND_INLINE M either(M a, M b) { return _mm256_or_ps(a, b); }
    static PHONG_HAND_INLINE M all_if(bool b) { return _mm256_castsi256_ps(_mm256_set1_epi32(b ? -1 : 0)); }
    static PHONG_HAND_INLINE V zero_unless(M m, V v) { return _mm256_and_ps(m, v); }
    static PHONG_HAND_INLINE V round(V y) { return _mm256_round_ps(y, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC); }
    /// p 2^k for integral k in [-101, 0] (2^k built in the exponent field) where y >= y_floor, else 0.
    static PHONG_HAND_INLINE V ldexp_above(V p, V k, V y, V y_floor)
    {
        const __m256i field = _mm256_add_epi32(_mm256_cvtps_epi32(k), _mm256_set1_epi32(127));
        return _mm256_and_ps(_mm256_cmp_ps(y, y_floor, _CMP_GE_OQ), mul(p, _mm256_castsi256_ps(_mm256_slli_epi32(field, 23))));
    }
    static PHONG_HAND_INLINE V split(V x, V& e)
    {
        const __m256i bits = _mm256_castps_si256(x);
        const __m256i ei = _mm256_srai_epi32(_mm256_sub_epi32(bits, _mm256_set1_epi32(0x3f3504f3)), 23);
        e = _mm256_cvtepi32_ps(ei);
        return sub(_mm256_castsi256_ps(_mm256_sub_epi32(bits, _mm256_slli_epi32(ei, 23))), set1(1));
    }
};
#  endif

using V = isa::V;
using M = isa::M;
inline constexpr std::size_t width = isa::W;
inline constexpr const char* isa_name = isa::name;

/// 1/sqrt(x): estimate + one Newton step in correction form (error in the header comment).
PHONG_HAND_INLINE V rsqrt(V x)
{
    V y = isa::rsqrt_estimate(x);
    for (int step = 0; step < isa::rsqrt_steps; ++step) {
        const V e = isa::fnma(isa::mul(x, y), y, isa::set1(1)); // 1 - x y^2
        y = isa::fma(isa::mul(y, isa::set1(0.5f)), e, y);
    }
    return y;
}

/// log2(x) for normal positive x.
PHONG_HAND_INLINE V log2(V x)
{
    V e;
    const V t = isa::split(x, e);
    V p = isa::set1(log2_coef[0]);
    for (int k = 1; k < 9; ++k) p = isa::fma(p, t, isa::set1(log2_coef[k]));
    return isa::fma(t, p, e);
}

/// The least 2^y kept: below 2^-100 the power is flushed to 0 (see the header comment).
inline constexpr float y_floor = -100;

/// 2^y for finite y <= 0; 0 for y < y_floor.
PHONG_HAND_INLINE V exp2(V y_in)
{
    const V y = isa::clamp_y ? isa::max(y_in, isa::set1(y_floor - 1)) : y_in;
    const V k = isa::round(y);
    const V r = isa::sub(y, k);
    V q = isa::set1(exp2_coef[0]);
    for (int j = 1; j < 6; ++j) q = isa::fma(q, r, isa::set1(exp2_coef[j]));
    return isa::ldexp_above(isa::fma(r, q, isa::set1(1)), k, y_in, isa::set1(y_floor));
}

/// x^m for x in (0, 1] (x below 2^-126 taken as 2^-126); the caller zeroes x = 0 for m > 0.
PHONG_HAND_INLINE V pow_unit(V x, V m)
{
    return exp2(isa::mul(m, log2(isa::max(x, isa::set1(std::numeric_limits<float>::min())))));
}

/// The inputs of W points (position q, normal u) and their W colours.
struct step_in {
    V qx, qy, qz, ux, uy, uz;
};
struct step_out {
    V r, g, b;
};
PHONG_HAND_INLINE step_in load_step(const float* px, const float* py, const float* pz, const float* nx, const float* ny, const float* nz)
{
    return {isa::load(px), isa::load(py), isa::load(pz), isa::load(nx), isa::load(ny), isa::load(nz)};
}
PHONG_HAND_INLINE void store_step(const step_out& o, float* r, float* g, float* b) { isa::store(r, o.r), isa::store(g, o.g), isa::store(b, o.b); }

/// The colours of W points.
template <bool Blinn>
PHONG_HAND_INLINE step_out shade_step(const step_in& in, const constants& c)
{
    // Per-point frame: n, v = -Q / |Q|, n.v, kept in registers across the light loop.
    const V qx = in.qx, qy = in.qy, qz = in.qz;
    V ux = in.ux, uy = in.uy, uz = in.uz;
    const V inv_n = rsqrt(isa::fma(ux, ux, isa::fma(uy, uy, isa::mul(uz, uz))));
    ux = isa::mul(ux, inv_n), uy = isa::mul(uy, inv_n), uz = isa::mul(uz, inv_n);
    const V minus_inv_q = isa::sub(isa::set1(0), rsqrt(isa::fma(qx, qx, isa::fma(qy, qy, isa::mul(qz, qz)))));
    const V vx = isa::mul(qx, minus_inv_q), vy = isa::mul(qy, minus_inv_q), vz = isa::mul(qz, minus_inv_q);
    const V nv = isa::fma(ux, vx, isa::fma(uy, vy, isa::mul(uz, vz)));
    const V two_nv = isa::add(nv, nv);
    const V m = isa::set1(c.m);
    const V zero = isa::set1(0), one = isa::set1(1);
    const M m_is_zero = isa::all_if(c.m == 0.0f); // pow(0, 0) = 1: the power is on wherever the gate is
    V cr = isa::set1(c.ambient[0]), cg = isa::set1(c.ambient[1]), cb = isa::set1(c.ambient[2]);
    for (const light_constants& L : c.lights) {
        const V dx = isa::sub(isa::set1(L.x), qx), dy = isa::sub(isa::set1(L.y), qy), dz = isa::sub(isa::set1(L.z), qz);
        const V dd = isa::fma(dx, dx, isa::fma(dy, dy, isa::mul(dz, dz)));
        const V nd = isa::fma(ux, dx, isa::fma(uy, dy, isa::mul(uz, dz)));
        const V inv = rsqrt(dd);
        const V nl = isa::mul(nd, inv);
        const M lit = isa::gt(nd, zero); // the gate n.l > 0
        V cosine;
        if constexpr (Blinn) {
            // n.h = (n.l + n.v) / |l + v|
            const V hx = isa::fma(dx, inv, vx), hy = isa::fma(dy, inv, vy), hz = isa::fma(dz, inv, vz);
            const V hh = isa::max(isa::fma(hx, hx, isa::fma(hy, hy, isa::mul(hz, hz))), isa::set1(std::numeric_limits<float>::min()));
            cosine = isa::mul(isa::add(nl, nv), rsqrt(hh));
        } else {
            // r.v = (2 (n.d)(n.v) - d.v) / |d|
            const V dv = isa::fma(dx, vx, isa::fma(dy, vy, isa::mul(dz, vz)));
            cosine = isa::mul(isa::fms(nd, two_nv, dv), inv);
        }
        cosine = isa::min(cosine, one);
        const M spec_on = isa::both(lit, isa::either(isa::gt(cosine, zero), m_is_zero));
        const V spec = isa::zero_unless(spec_on, pow_unit(cosine, m));
        const V diff = isa::max(nl, zero); // = [n.l > 0] n.l
        cr = isa::fma(isa::set1(L.dr), diff, isa::fma(isa::set1(L.sr), spec, cr));
        cg = isa::fma(isa::set1(L.dg), diff, isa::fma(isa::set1(L.sg), spec, cg));
        cb = isa::fma(isa::set1(L.db), diff, isa::fma(isa::set1(L.sb), spec, cb));
    }
    return {cr, cg, cb};
}

/// n points (SoA in, SoA rgb out). A tail shorter than the width goes through padded copies
/// (pad: Q = (0, 0, -1), n = (0, 0, 1), a point facing the eye).
template <bool Blinn>
void shade(const float* px, const float* py, const float* pz, const float* nx, const float* ny, const float* nz,
           std::size_t n, const constants& c, float* r, float* g, float* b)
{
    constexpr std::size_t W = width;
    std::size_t i = 0;
    // Step k's colours are stored after step k + 1's inputs are loaded (software pipelining): stored
    // before, they held up those loads where the arrays share their offset in a 4 KiB page (the
    // benchmark's std::vectors: Blinn, K = 1, 3.1 ns per pair against 2.6 ns, 2026-11-24; phong's
    // shade_batch does the same).
    step_out pending{};
    for (; i + W <= n; i += W) {
        const step_in in = load_step(px + i, py + i, pz + i, nx + i, ny + i, nz + i);
        if (i > 0) store_step(pending, r + i - W, g + i - W, b + i - W);
        pending = shade_step<Blinn>(in, c);
    }
    if (i > 0) store_step(pending, r + i - W, g + i - W, b + i - W);
    if (i < n) {
        alignas(64) float in[6][W], out[3][W];
        const float* src[6] = {px, py, pz, nx, ny, nz};
        for (int k = 0; k < 6; ++k)
            for (std::size_t j = 0; j < W; ++j) in[k][j] = i + j < n ? src[k][i + j] : (k == 2 ? -1.0f : k == 5 ? 1.0f : 0.0f);
        store_step(shade_step<Blinn>(load_step(in[0], in[1], in[2], in[3], in[4], in[5]), c), out[0], out[1], out[2]);
        for (std::size_t j = 0; i + j < n; ++j) r[i + j] = out[0][j], g[i + j] = out[1][j], b[i + j] = out[2][j];
    }
}
#  undef PHONG_HAND_INLINE
#endif // PHONG_HAND_SIMD

/// The model the kernel computes, as phong features (shade.bench.cpp's model(), exact mode).
constexpr phong::features model(bool blinn)
{
    phong::features f = phong::presets::glsl_ads;
    f.specular = blinn ? phong::specular_model::blinn : phong::specular_model::phong;
    f.mode = phong::evaluation::exact;
    return f;
}

/// Tolerance of check_against_scalar, per channel, relative: both kernels evaluate the same exact
/// formulas with different roundings (rsqrt estimate + Newton against 1/sqrt, polynomial against
/// an accurate pow, the material folded into the lights). The cosine c carries a relative error of
/// a few u in each (here three rsqrt estimates refined to 1.6 u: n, v and 1/|d|), which c^m
/// amplifies by m near a highlight; the tolerance allows 16 u per unit of m: 16 (m + 16) u, 4.6e-5
/// at the benchmark's m = 32, where the largest difference measured is 1.2e-5 (K = 1, Phong;
/// phong_hand_simd_check prints every case). A different model is far outside it: one light's
/// ambient term alone is ka La = 4e-3 of a colour of at most ~10 (K = 16), >= 4e-4 relative
/// (measured: 0.25 at an unlit point), the other specular model 0.4; a missing gate or attenuation
/// changes colours by O(1). phong_hand_simd_check asserts that these are caught.
inline double check_tolerance(float m) { return 16.0 * (double(m) + 16.0) * 0x1p-24; }

/// Largest relative difference per channel between the hand kernel's colours (SoA r, g, b) and
/// phong's scalar shade<model(blinn)> at every point.
template <bool Blinn>
double max_difference_to_scalar(std::span<const glm::vec3> position, std::span<const glm::vec3> normal,
                                std::span<const phong::light<float>> lights, const phong::material<float>& mat,
                                std::span<const float> r, std::span<const float> g, std::span<const float> b)
{
    constexpr phong::features F = model(Blinn);
    double worst = 0;
    for (std::size_t i = 0; i < position.size(); ++i) {
        const glm::vec3 s = phong::shade<F>(position[i], normal[i], mat, lights);
        const float h[3] = {r[i], g[i], b[i]};
        for (int k = 0; k < 3; ++k) {
            const double diff = std::abs(double(h[k]) - double(s[k]));
            const double rel = s[k] != 0 ? diff / std::abs(double(s[k])) : diff;
            worst = std::max(worst, std::isnan(rel) ? std::numeric_limits<double>::infinity() : rel);
        }
    }
    return worst;
}

} // namespace phong_bench::hand_simd
