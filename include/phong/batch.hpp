// phong: batch shading. The same templates as the scalar path (detail::prepare, add_lights in
// detail/route.hpp, finish in shade.hpp), instantiated on a SIMD batch type, over structure-of-
// arrays or array-of-structures points.
// SPDX-License-Identifier: MIT
//
// SIMD layer: xsimd (Debian libxsimd-dev, header-only) when it is available, else a plain scalar
// loop over the same kernel. Why xsimd and not std::experimental::simd: the kernel needs
// vectorized exp and log1p (the specular power), and libstdc++ 12's <experimental/simd> computes
// those with a scalar loop per lane; measured with this kernel, see README "Batch shading".
// Define PHONG_NO_XSIMD to force the scalar fallback.
#pragma once

#include "shade.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <array>
#include <cstddef>
#include <cstdio>
#include <functional>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#if !defined(PHONG_NO_XSIMD) && !defined(__CUDACC__) && __has_include(<xsimd/xsimd.hpp>)
// g++ 12 reports the _mm512_undefined_* placeholders inside its own AVX-512 intrinsics (which
// xsimd calls) as (maybe) uninitialized once they are inlined; they are not, by design. g++
// decides by the source position of each function in the inlining chain, innermost first, not
// by where a template is instantiated: so the region opens *before* xsimd (and through it
// <immintrin.h>) is included, and every chain that runs through xsimd's code is covered, also
// from phong's templates instantiated in a user's file (tests/consumer/batch_user.cpp). Include
// phong/batch.hpp before <xsimd/xsimd.hpp> for this to hold.
#  if defined(__GNUC__) && !defined(__clang__)
#    pragma GCC diagnostic push
#    pragma GCC diagnostic ignored "-Wuninitialized"
#    pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#    define PHONG_BATCH_POP_DIAGNOSTICS 1
#  endif
#  include <xsimd/xsimd.hpp>
#  include "detail/lanes_power.hpp"
#  define PHONG_HAS_XSIMD 1
#  include "detail/stable_lanes.hpp"
#else
#  define PHONG_HAS_XSIMD 0
#endif

namespace phong {

#if PHONG_HAS_XSIMD
// The lane kernels are small and hot: inline them into the shading loop.
#if defined(__GNUC__)
#  define PHONG_LANES_INLINE inline __attribute__((always_inline))
#else
#  define PHONG_LANES_INLINE inline
#endif



/// math_traits for xsimd batches: every kernel of math.hpp, lane-wise. exp, log and log1p are
/// xsimd's (vectorized, within a few ulp); float rsqrt is the hardware estimate refined by one
/// Newton step; fma is the fused instruction. pow is exp(y log x) restricted to x >= 0 with IEEE's
/// pow(0, 0) = 1 (xsimd's own pow returns 0 there). Domain-specific cephes-style exp/log kernels
/// were tried: fewer instructions, but twice the time in the shading loop on this CPU.
template <class T, class A>
struct math_traits<xsimd::batch<T, A>> {
    using V = xsimd::batch<T, A>;
    using scalar = T;
    using mask = xsimd::batch_bool<T, A>;
    static constexpr bool float_lanes = std::is_same_v<T, float>;

    PHONG_LANES_INLINE static V sqrt(const V& x) { return xsimd::sqrt(x); }
    /// 1/sqrt(x). Float lanes with AVX-512 or AVX: hardware estimate + one Newton step
    /// (< 2 ulp); elsewhere 1/sqrt(x). rsqrt(0) = inf, rsqrt(inf) = 0.
    PHONG_LANES_INLINE static V rsqrt(const V& x)
    {
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>) {
            return newton_rsqrt(x, V(_mm512_rsqrt14_ps(x)));
        } else if constexpr (float_lanes && std::is_base_of_v<xsimd::avx, A>) {
            return newton_rsqrt(x, V(_mm256_rsqrt_ps(x)));
        } else {
            return V(T(1)) / xsimd::sqrt(x);
        }
    }
    /// 1/sqrt(x) for x a positive normal number (detail::rsqrt_normal): rsqrt without the guards
    /// for 0 and inf (other x: unspecified, maybe NaN).
    PHONG_LANES_INLINE static V rsqrt_normal(const V& x)
    {
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>) {
            return newton_step(x, V(_mm512_rsqrt14_ps(x)));
        } else if constexpr (float_lanes && std::is_base_of_v<xsimd::avx, A>) {
            return newton_step(x, V(_mm256_rsqrt_ps(x)));
        } else {
            return V(T(1)) / xsimd::sqrt(x);
        }
    }
    /// x >= min and x <= max of T (x a positive normal number: the exact mode's test of a squared
    /// length). AVX-512DQ: one vfpclass for every other class (zeros, subnormals, negatives,
    /// infinities, NaN) in place of two compares.
    PHONG_LANES_INLINE static mask positive_normal(const V& x)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_knot_mask16(_mm512_fpclass_ps_mask(x, 0xff))));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_knot_mask8(_mm512_fpclass_pd_mask(x, 0xff))));
#endif
        return (x >= V(std::numeric_limits<T>::min())) && (x <= V(std::numeric_limits<T>::max()));
    }
    /// m && positive_normal(x) (AVX-512DQ: vfpclass and one kandn).
    PHONG_LANES_INLINE static mask both_positive_normal(const mask& m, const V& x)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_kandn_mask16(_mm512_fpclass_ps_mask(x, 0xff), m)));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return mask(typename mask::register_type(_kandn_mask8(_mm512_fpclass_pd_mask(x, 0xff), m)));
#endif
        return m && positive_normal(x);
    }
    /// all(a && b) (AVX-512: one kortest of the complements).
    PHONG_LANES_INLINE static bool all_both(const mask& a, const mask& b)
    {
#if defined(__AVX512DQ__)
        if constexpr (float_lanes && std::is_base_of_v<xsimd::avx512f, A>)
            return _kortestz_mask16_u8(_knot_mask16(a), _knot_mask16(b));
        else if constexpr (std::is_same_v<T, double> && std::is_base_of_v<xsimd::avx512f, A>)
            return _kortestz_mask8_u8(_knot_mask8(a), _knot_mask8(b));
#endif
        return xsimd::all(a && b);
    }
    /// e^x, lane-wise: xsimd::exp on the argument clamped to [minlog, maxlog] (xsimd's own
    /// thresholds: -88.38 / 88.38 in float, -708.40 / 709.78 in double), NaN passed through.
    /// Why: xsimd 8.1's exp converts round(x / ln 2) to an integer before it looks at the range,
    /// and where the ISA has no vector conversion (double below AVX-512DQ: SSE2, AVX, AVX2) that
    /// is a scalar static_cast, undefined (UBSan: float-cast-overflow) for |x| beyond 2^63 and for
    /// NaN. Such x are in the model's domain: the stable mode's exp(m log1p(-x)) with m = 1e30 in
    /// double, or pow(x, y) with y = 1e38 in float. The clamp cannot change a result: xsimd's exp
    /// returns exactly 0 for every x <= minlog and +inf for every x >= maxlog (its final selects),
    /// so exp(clamp(x)) == exp(x) for every non-NaN x; and exp(NaN) = NaN here as before.
    PHONG_LANES_INLINE static V exp(const V& x)
    {
        const V lo = xsimd::constants::minlog<V>(), hi = xsimd::constants::maxlog<V>();
        const V clamped = xsimd::select(x > lo, xsimd::select(x < hi, x, hi), lo); // NaN: lo
        return xsimd::select(x == x, xsimd::exp(clamped), x);
    }
    /// log and log1p: xsimd's (no integer conversion of the argument: defined for every input).
    PHONG_LANES_INLINE static V log(const V& x) { return xsimd::log(x); }
    PHONG_LANES_INLINE static V log1p(const V& x) { return xsimd::log1p(x); }
    /// x^y for x in [0, 1], y >= 0 (the lighting model's domain): exp(y log x) with xsimd's
    /// kernels (exp clamped as above: y log x is -inf or below -1e300 for large y), pow(0, 0) = 1,
    /// pow(0, y > 0) = 0 (xsimd's own pow returns 0 for pow(0, 0)).
    PHONG_LANES_INLINE static V pow(const V& x, const V& y)
    {
        const V p = exp(y * xsimd::log(xsimd::select(x > V(T(0)), x, V(T(1)))));
        return xsimd::select(x > V(T(0)), p, xsimd::select(y == V(T(0)), V(T(1)), V(T(0))));
    }
    /// x^m for x in [0, 1], m >= 0 (the specular and spot powers of the exact mode). Float lanes:
    /// detail/lanes_power.hpp's polynomial kernel, relative error <= (3.5 |m log2 x| + 2.5) u
    /// (detail::lanes::pow_unit_lanes_error); double lanes: pow above.
    PHONG_LANES_INLINE static V pow_unit(const V& x, const V& m)
    {
        if constexpr (float_lanes) return detail::lanes::pow_unit(x, m);
        else return pow(x, m);
    }
    /// pow_unit with m_is_zero = (m == 0) given (computed once per call by shade_batch). Both
    /// kinds of lanes give x <= 0 and NaN the power of 0 (0, or 1 for m = 0).
    PHONG_LANES_INLINE static V pow_unit(const V& x, const V& m, const mask& m_is_zero)
    {
        if constexpr (float_lanes) return detail::lanes::pow_unit(x, m, m_is_zero);
        else return pow(x, m);
    }
    /// Float lanes: x^m for x in [0, 1] and 0 <= m <= 2^100 where x > 0 or m = 0; other lanes
    /// unspecified (finite), for the caller to select away (detail/lanes_power.hpp's pow_unit_positive).
    template <class U = T, std::enable_if_t<std::is_same_v<U, float>, int> = 0>
    PHONG_LANES_INLINE static V pow_unit_positive(const V& x, const V& m) { return detail::lanes::pow_unit_positive(x, m); }
    /// (1 - x)^m for x >= 0, m >= 0 (specular.hpp's pow_one_minus): exp(m log1p(-x)) with
    /// xsimd's kernels (exp clamped as above: m log1p(-x) reaches -1e30 and below for the
    /// shininess validate accepts); x >= 1 gives 0, and 1 for m = 0.
    /// Float lanes: detail/lanes_power.hpp's polynomial kernel (log2(1 - x) from t = -x itself near
    /// x = 0), relative error <= (6.5 |m log2(1 - x)| + 2.5) u (pow_one_minus_lanes_error).
    PHONG_LANES_INLINE static V pow_one_minus(const V& x, const V& m)
    {
        if constexpr (float_lanes) return detail::lanes::pow_one_minus(xsimd::max(x, V(T(0))), m);
        const V xc = xsimd::min(x, V(T(1)));
        const auto inside = xc < V(T(1));
        const V lg = xsimd::log1p(-xsimd::select(inside, xc, V(T(0))));
        const V r = exp(m * lg);
        return xsimd::select(inside, r, xsimd::select(m == V(T(0)), V(T(1)), V(T(0))));
    }
    /// a * b + c rounded once. xsimd 8.1's fma is a separate multiply and add on AVX-512 and on
    /// targets without FMA (found by the stable mode's error-free products losing their error
    /// term), so the fused instructions are called directly, and without FMA hardware the exact
    /// product comes from Dekker's split (`split_fma` below).
    PHONG_LANES_INLINE static V fma(const V& a, const V& b, const V& c)
    {
#  if defined(__AVX512F__)
        if constexpr (sizeof(V) == 64) {
            if constexpr (float_lanes) return V(_mm512_fmadd_ps(a, b, c));
            else return V(_mm512_fmadd_pd(a, b, c));
        }
#  endif
#  if defined(__FMA__)
        if constexpr (sizeof(V) == 32) {
            if constexpr (float_lanes) return V(_mm256_fmadd_ps(a, b, c));
            else return V(_mm256_fmadd_pd(a, b, c));
        } else if constexpr (sizeof(V) == 16) {
            if constexpr (float_lanes) return V(_mm_fmadd_ps(a, b, c));
            else return V(_mm_fmadd_pd(a, b, c));
        }
#  endif
        return split_fma(a, b, c);
    }
    /// Dekker's product a * b = p + e exactly, then (p + c) + e: exact whenever c = -fl(a * b)
    /// (the error-free products of the stable mode), else within 1 ulp. Veltkamp's split forms
    /// (2^h + 1) x (h = 12 for float, 27 for double), which overflows for |x| above
    /// max / 2^(h + 1) (8.3e34 in float, 1.1e300 in double): the error term became inf - inf = NaN
    /// and the stable mode lost the view vector of a point at |Q| = 1e38 in float (found by
    /// tests/fuzz/fuzz_batch.cpp at the baseline ISA, where the scalar path's std::fma is exact).
    /// So e is computed for a 2^-(h+1) (and b 2^-(h+1)) where those are that large, and scaled
    /// back by the same powers of two: exact, since e of such a product (|a b| >= 8.3e34 * 1.4e-45
    /// in float) is far from the subnormal range.
    PHONG_LANES_INLINE static V split_fma(const V& a, const V& b, const V& c)
    {
        constexpr int h = (std::numeric_limits<T>::digits + 1) / 2;
        const V limit(std::numeric_limits<T>::max() / T(1ull << (h + 1)));
        const V down(T(1) / T(1ull << (h + 1))), up(T(1ull << (h + 1))), one(T(1)), splitter(T((1ull << h) + 1));
        const auto big_a = xsimd::abs(a) > limit, big_b = xsimd::abs(b) > limit;
        const V as = xsimd::select(big_a, a * down, a), bs = xsimd::select(big_b, b * down, b);
        const V scale = xsimd::select(big_a, up, one) * xsimd::select(big_b, up, one);
        const V ca = detail::ieee::opaque(splitter * as), ah = detail::ieee::opaque(ca - detail::ieee::opaque(ca - as)), al = as - ah;
        const V cb = detail::ieee::opaque(splitter * bs), bh = detail::ieee::opaque(cb - detail::ieee::opaque(cb - bs)), bl = bs - bh;
        const V ps = as * bs;
        const V es = detail::ieee::ordered_sum(ah * bh - ps, ah * bl, al * bh, al * bl);
        return detail::ieee::opaque(a * b + c) + es * scale;
    }
    static V select(const mask& m, const V& a, const V& b) { return xsimd::select(m, a, b); }
    static bool any(const mask& m) { return xsimd::any(m); }
    static bool all(const mask& m) { return xsimd::all(m); }
    static mask both(const mask& a, const mask& b) { return a && b; }
    static V abs(const V& x) { return xsimd::abs(x); }
    static V min(const V& a, const V& b) { return xsimd::min(a, b); }
    static V max(const V& a, const V& b) { return xsimd::max(a, b); }

    /// The power of two of math_traits<T>::inverse_pow2_scale, lane-wise: 2^(bias - e) has the
    /// exponent field (2 bias) - (x's exponent field), one integer subtraction; x's above 2^bias
    /// (where that would underflow) take 2^(1 - bias). Integer selects are avoided on purpose
    /// (xsimd 8.1 does not compile them for AVX-512BW at -O0).
    static V inverse_pow2_scale(const V& x)
    {
        using I = xsimd::as_integer_t<T>;
        using IV = xsimd::batch<I, A>;
        constexpr int mant = std::numeric_limits<T>::digits - 1;
        constexpr I one = I(1) << mant;                                       // exponent field 1: 2^(1 - bias)
        constexpr I exponent_mask = ((I(1) << (sizeof(T) * 8 - 1 - mant)) - 1) << mant; // all exponent bits
        constexpr I two_bias = exponent_mask - one;                           // field 2 bias: 2^bias
        const IV scale_bits = IV(two_bias) - (xsimd::bitwise_cast<IV>(x) & IV(exponent_mask));
        const V two_pow_bias = xsimd::bitwise_cast<V>(IV(two_bias));
        return xsimd::select(x >= two_pow_bias, xsimd::bitwise_cast<V>(IV(one)), xsimd::bitwise_cast<V>(scale_bits));
    }

private:
    /// One Newton step for 1/sqrt(x) from an estimate.
    /// Correction form y0 + (y0 / 2)(1 - (x y0) y0) with fused multiply-adds: the step squares the
    /// estimate's error (1.5 e0^2), and the roundings add about 1.5 u (x y0 rounded, halved by
    /// y0 / 2; the last fma): 1.6 u with AVX-512's 2^-14 estimate, 4.9 u with AVX's 1.5 2^-12.
    PHONG_LANES_INLINE static V newton_step(const V& x, const V& estimate)
    {
        const V residual = fma(-(x * estimate), estimate, V(T(1))); // 1 - x y0^2
        return fma(estimate * V(T(0.5)), residual, estimate);
    }
    static V newton_rsqrt(const V& x, const V& estimate)
    {
        const V refined = newton_step(x, estimate);
        const auto finite_nonzero = phong::detail::ieee::positive_finite(estimate);
        return xsimd::select(finite_nonzero, refined, estimate);
    }
};

#  if defined(__GNUC__) && !defined(__clang__) && !defined(__OPTIMIZE__) && XSIMD_WITH_AVX512BW
/// g++ 12 at -O0 cannot compile xsimd 8.1's AVX-512BW integer select (used inside xsimd::log):
/// unoptimized builds use AVX-512DQ, the same 512-bit float arithmetic.
using simd_arch = xsimd::avx512dq;
#  else
using simd_arch = xsimd::default_arch;
#  endif
/// The SIMD batch used by shade_batch for T: xsimd's widest for the compile flags (16 floats with
/// AVX-512, 8 with AVX2, 4 with SSE2).
template <class T> using simd_batch = xsimd::batch<T, simd_arch>;
#else
template <class T> using simd_batch = T;
#endif

/// Lanes per step of shade_batch for T.
template <class T> inline constexpr std::size_t batch_width = sizeof(simd_batch<T>) / sizeof(T);

/// Three parallel arrays x, y, z of the same length (structure of arrays).
template <class T> struct soa3 {
    std::span<const T> x, y, z;
};
/// Output colour channels, structure of arrays. a is written only when F.alpha.
template <class T> struct soa_rgba {
    std::span<T> r, g, b, a;
};

/// The points of one shade_batch call, structure of arrays: a renderer's per-point inputs in
/// one argument (designated initializers name the ones used). N = positions.x.size().
///   positions, normals: N points and their normals (any length; as shade<F> takes them);
///   views: N view vectors (from each point toward its viewer, e.g. -ray.dir), read only and
///          required with features::view = view_model::given; leave empty otherwise;
///   front_facing: N flags, read only for facing::flag; empty: all front-facing;
///   light_masks: N masks, bit j set: light j is visible at that point (a shadow ray's result);
///          a light whose bit is clear is skipped there exactly as if it were not in the list;
///          empty: every light visible everywhere. Lights past the 64th are seen by no point
///          when masks are given (as phong::masked).
template <class T> struct soa_points {
    soa3<T> positions;
    soa3<T> normals;
    soa3<T> views{};
    std::span<const bool> front_facing{};
    std::span<const std::uint64_t> light_masks{};
};

/// The same, array of structures: a ray tracer's hit records as glm vectors
/// (std::vector<glm::vec3> converts), loaded into lanes per step with a small transpose, so
/// nothing needs repacking. Fields as soa_points; N = positions.size().
template <class T, glm::qualifier Q = glm::defaultp> struct aos_points {
    std::span<const glm::vec<3, T, Q>> positions;
    std::span<const glm::vec<3, T, Q>> normals;
    std::span<const glm::vec<3, T, Q>> views{};
    std::span<const bool> front_facing{};
    std::span<const std::uint64_t> light_masks{};
};

/// Materials as a renderer keeps them: a table (a scene's materials) and one index into it per
/// point (each hit's material id). shade_batch with a material_table shades point i with
/// materials[ids[i]], bit for bit as the overloads that take one material per point would with
/// that material, without copying a material per point: the table goes to SIMD lanes once per
/// call; a step whose points all have one id (coherent primary hits: most steps) uses those
/// lanes as they are, and a step of mixed ids takes each field from the table: with float lanes
/// and at most batch_width<float> entries (16 with AVX-512, 8 with AVX2), one in-register
/// permute per field; else one gather instruction per field (AVX-512 and AVX2).
///   materials: the table, validate() for each entry; not empty when there are points;
///   ids: N indices (N = the number of points), each < materials.size().
/// Pre (debug assertions through the precondition handler): ids N long, every id in the
/// table. Edge: an id past the table takes its last entry (memory-safe in release builds);
/// an empty table shades nothing (every build).
template <class T, glm::qualifier Q = glm::defaultp> struct material_table {
    std::span<const material<T, Q>> materials;
    std::span<const std::uint32_t> ids;
};

namespace detail {

template <class V, class T, glm::qualifier Q>
glm::vec<3, V, Q> splat(const glm::vec<3, T, Q>& v) { return {V(v.x), V(v.y), V(v.z)}; }
template <class V, class T, glm::qualifier Q>
glm::vec<4, V, Q> splat(const glm::vec<4, T, Q>& v) { return {V(v.x), V(v.y), V(v.z), V(v.w)}; }

template <class V, class T, glm::qualifier Q>
light<V, Q> splat(const light<T, Q>& L)
{
    light<V, Q> b;
    b.position = splat<V>(L.position);
    b.ambient = splat<V>(L.ambient);
    b.diffuse = splat<V>(L.diffuse);
    b.specular = splat<V>(L.specular);
    b.attenuation = {V(L.attenuation.constant), V(L.attenuation.linear), V(L.attenuation.quadratic), V(L.attenuation.range)};
    b.spot.direction = splat<V>(L.spot.direction);
    b.spot.exponent = V(L.spot.exponent);
    b.spot.cos_cutoff = V(L.spot.cos_cutoff);
    b.spot.cos_inner = V(L.spot.cos_inner);
    b.spot.cos_outer = V(L.spot.cos_outer);
    return b;
}
template <class V, class T, glm::qualifier Q>
material<V, Q> splat(const material<T, Q>& m)
{
    return {splat<V>(m.ka), splat<V>(m.kd), splat<V>(m.ks), splat<V>(m.emission), V(m.shininess), V(m.alpha)};
}

template <class V, class T> V load(const T* p)
{
    if constexpr (std::is_same_v<V, T>) return *p;
    else return V::load_unaligned(p);
}
template <class V, class T> void store(const V& v, T* p)
{
    if constexpr (std::is_same_v<V, T>) *p = v;
    else v.store_unaligned(p);
}

/// True where the AVX-512 paths below apply: 512-bit lanes of float or double (16 or 8 points).
template <class V, class T> inline constexpr bool avx512_lanes =
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    !std::is_same_v<V, T> && sizeof(V) == 64 && (std::is_same_v<T, float> || std::is_same_v<T, double>);
#else
    false;
#endif

/// True where the AVX2 paths below apply: 256-bit lanes of float (8 points).
template <class V, class T> inline constexpr bool avx2_float_lanes =
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    !std::is_same_v<V, T> && sizeof(V) == 32 && std::is_same_v<T, float>;
#else
    false;
#endif

#if PHONG_HAS_XSIMD && defined(__AVX2__)
/// The 8 x 3 transpose with AVX2 (8 interleaved vec3 in three registers a, b, c of 8 floats).
/// Component o of lane k is float s = 3k + o, in register s / 8 at position s % 8; for each o
/// those positions are a permutation of 0..7 (3 is coprime to 8), so two blends gather the
/// component's 8 floats into one register (position p from the register holding it) and one
/// permute puts lane k at its place. Back (a colour to 8 interleaved vec3): block b's float j is
/// component (8b + j) % 3 of point (8b + j) / 3: x, y, z permuted by point, blended by component.
constexpr int aos8_blend(int o, int reg)
{
    int bits = 0;
    for (int k = 0; k < 8; ++k)
        if ((3 * k + o) / 8 == reg) bits |= 1 << ((3 * k + o) % 8);
    return bits;
}
constexpr int interleave8_blend(int b, int component)
{
    int bits = 0;
    for (int j = 0; j < 8; ++j)
        if ((8 * b + j) % 3 == component) bits |= 1 << j;
    return bits;
}
struct aos8_permutes {
    alignas(32) std::int32_t gather[3][8]{}, scatter[3][8]{};
    constexpr aos8_permutes()
    {
        for (int o = 0; o < 3; ++o)
            for (int k = 0; k < 8; ++k) gather[o][k] = (3 * k + o) % 8, scatter[o][k] = (8 * o + k) / 3;
    }
};
inline constexpr aos8_permutes aos8_permute_table{};
template <int o> __m256 aos8_component(__m256 a, __m256 b, __m256 c)
{
    const __m256 t = _mm256_blend_ps(_mm256_blend_ps(a, b, aos8_blend(o, 1)), c, aos8_blend(o, 2));
    return _mm256_permutevar8x32_ps(t, _mm256_load_si256(reinterpret_cast<const __m256i*>(aos8_permute_table.gather[o])));
}
template <int b> __m256 interleave8_block(__m256 x, __m256 y, __m256 z)
{
    const __m256i point = _mm256_load_si256(reinterpret_cast<const __m256i*>(aos8_permute_table.scatter[b]));
    const __m256 px = _mm256_permutevar8x32_ps(x, point), py = _mm256_permutevar8x32_ps(y, point), pz = _mm256_permutevar8x32_ps(z, point);
    return _mm256_blend_ps(_mm256_blend_ps(px, py, interleave8_blend(b, 1)), pz, interleave8_blend(b, 2));
}
#endif

/// A material is 14 scalars in a row (ka, kd, ks, emission, shininess, alpha) when glm's vec3 is
/// unpadded (every qualifier but the aligned ones): then its fields can be gathered by offset.
template <class T, glm::qualifier Q> inline constexpr bool material_is_14_scalars =
    sizeof(glm::vec<3, T, Q>) == 3 * sizeof(T) && sizeof(material<T, Q>) == 14 * sizeof(T) && std::is_standard_layout_v<material<T, Q>>;

/// The material whose 14 fields, in material's order (ka, kd, ks, emission, shininess, alpha),
/// are field[0..13].
template <class V, glm::qualifier Q> material<V, Q> material_of_fields(const V (&field)[14])
{
    return {{field[0], field[1], field[2]}, {field[3], field[4], field[5]}, {field[6], field[7], field[8]},
            {field[9], field[10], field[11]}, field[12], field[13]};
}

/// Material m's 14 fields, in the same order, into column k of lane (lane[f][k]): the scalar
/// transpose of a step's (or a table's) materials into field lanes.
template <class T, glm::qualifier Q, std::size_t W> void put_fields(T (&lane)[14][W], std::size_t k, const material<T, Q>& m)
{
    for (int c = 0; c < 3; ++c) {
        lane[c][k] = m.ka[c];
        lane[3 + c][k] = m.kd[c];
        lane[6 + c][k] = m.ks[c];
        lane[9 + c][k] = m.emission[c];
    }
    lane[12][k] = m.shininess;
    lane[13][k] = m.alpha;
}

/// One material of lanes: lane k takes base[element[k]] (k < W). The same values as splatting
/// each material, so the same bits downstream. With gather_instructions (a material table: small,
/// in cache) and AVX-512 or AVX2: one gather instruction per field (14); otherwise a scalar
/// transpose through a small buffer. Per-point materials take the scalar transpose: they stream
/// from memory, and there 14 gathers over the same 14 cache lines took 1.5x the time of the
/// sequential reads (262144 points, AVX-512, this machine).
template <class V, bool gather_instructions, class T, glm::qualifier Q>
material<V, Q> gather(const material<T, Q>* base, const std::uint32_t* element)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (gather_instructions && avx512_lanes<V, T> && material_is_14_scalars<T, Q>) {
        const T* scalars = &base->ka.x; // the 14 fields of base[e] are scalars[14 e + f]
        V field[14];
        if constexpr (std::is_same_v<T, float>) {
            const __m512i index = _mm512_mullo_epi32(_mm512_loadu_si512(element), _mm512_set1_epi32(14));
            for (int f = 0; f < 14; ++f) field[f] = V(_mm512_i32gather_ps(index, scalars + f, sizeof(T)));
        } else {
            const __m256i index = _mm256_mullo_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(element)), _mm256_set1_epi32(14));
            for (int f = 0; f < 14; ++f) field[f] = V(_mm512_i32gather_pd(index, scalars + f, sizeof(T)));
        }
        return material_of_fields<V, Q>(field);
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (gather_instructions && avx2_float_lanes<V, T> && material_is_14_scalars<T, Q>) {
        const T* scalars = &base->ka.x;
        const __m256i index = _mm256_mullo_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(element)), _mm256_set1_epi32(14));
        V field[14];
        for (int f = 0; f < 14; ++f) field[f] = V(_mm256_i32gather_ps(scalars + f, index, sizeof(T)));
        return material_of_fields<V, Q>(field);
    }
#endif
    alignas(64) T lane[14][W];
    for (std::size_t k = 0; k < W; ++k) put_fields(lane, k, base[element[k]]);
    V field[14];
    for (int f = 0; f < 14; ++f) field[f] = load<V>(lane[f]);
    return material_of_fields<V, Q>(field);
}

/// The element indices 0, 1, ..., count - 1, then count - 1 repeated (a tail's pad lanes take
/// the last point's material): the per-point materials of one step.
template <std::size_t W> struct consecutive_elements {
    alignas(64) std::uint32_t index[W]{};
    constexpr explicit consecutive_elements(std::size_t count)
    {
        for (std::size_t k = 0; k < W; ++k) index[k] = std::uint32_t(k < count ? k : count - 1);
    }
};
template <std::size_t W> inline constexpr consecutive_elements<W> full_step_elements{W};

/// Storage for one step's material lanes, left uninitialized (material's default member
/// initializers would fill 14 vectors per slot per call: 8 KiB of stores per call of 32 steps);
/// the step functions construct the lanes in it (std::construct_at) before any read.
template <class V, glm::qualifier Q> union material_slot {
    material<V, Q> lanes;
    material_slot() {}
};

/// The lane material of one step from a material table: the table's lanes (splatted once per
/// call) when every point of the step has the same id, else a gather of the table's entries.
/// An id past the table takes its last entry (a debug build reports it before: shade_batch's
/// precondition); pad lanes of a tail take the last point's id.
template <class V, class T, glm::qualifier Q> struct table_lanes {
    std::span<const material<T, Q>> table;
    std::span<const std::uint32_t> ids;
    std::vector<material<V, Q>> splatted; ///< table[j] in every lane
    /// A table of at most W entries (float lanes, AVX-512 or AVX2; empty otherwise): field f of
    /// entry j in lane j (the last entry repeated past the table). A step of mixed ids then takes
    /// each field with one in-register permute by id instead of a gather from memory (a scene's
    /// few materials: 14 permutes against 14 gathers, the same values).
    std::vector<V> columns;

    /// The lanes of field f of table[id[k]] in lane k, from columns (ids: W clamped ids in a register).
    template <class Ids> material<V, Q> permuted([[maybe_unused]] const Ids& id) const
    {
        V field[14];
        for (int f = 0; f < 14; ++f) {
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
            if constexpr (avx512_lanes<V, T> && std::is_same_v<T, float>) field[f] = V(_mm512_permutexvar_ps(id, columns[std::size_t(f)]));
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__) && !defined(__AVX512F__)
            if constexpr (avx2_float_lanes<V, T>) field[f] = V(_mm256_permutevar8x32_ps(columns[std::size_t(f)], id));
#endif
        }
        return material_of_fields<V, Q>(field);
    }
    /// Fills columns when the table is small enough and the lanes have the permute (see columns).
    void make_columns()
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        constexpr bool permutable =
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
            avx512_lanes<V, T> && std::is_same_v<T, float>;
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
            avx2_float_lanes<V, T>;
#else
            false;
#endif
        if constexpr (permutable) {
            if (table.empty() || table.size() > W) return;
            alignas(64) T lane[14][W];
            for (std::size_t k = 0; k < W; ++k) put_fields(lane, k, table[std::min(k, table.size() - 1)]);
            for (int f = 0; f < 14; ++f) columns.push_back(load<V>(lane[f]));
        }
    }

    /// The lanes of points i .. i + count - 1: the table's lanes of their id when they share one
    /// (nothing copied), else `scratch`, filled with each point's entry.
    const material<V, Q>* step(std::size_t i, std::size_t count, material<V, Q>& scratch) const
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        const std::uint32_t last = std::uint32_t(table.size() - 1);
        const std::uint32_t* id = ids.data() + i;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T> && std::is_same_v<T, float>) {
            if (count == W) { // 16 ids in one register: clamp, compare with lane 0
                const std::uint32_t first = std::min(id[0], last);
                const __m512i clamped = _mm512_min_epu32(_mm512_loadu_si512(id), _mm512_set1_epi32(int(last)));
                if (_mm512_cmpneq_epi32_mask(clamped, _mm512_set1_epi32(int(first))) == 0) return &splatted[first];
                if (!columns.empty()) return std::construct_at(&scratch, permuted(clamped));
                alignas(64) std::uint32_t element[W];
                _mm512_store_si512(element, clamped);
                return std::construct_at(&scratch, gather<V, true>(table.data(), element));
            }
        }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) {
            if (count == W) { // 8 ids in one register: clamp, compare with lane 0
                const std::uint32_t first = std::min(id[0], last);
                const __m256i clamped = _mm256_min_epu32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(id)), _mm256_set1_epi32(int(last)));
                if (_mm256_movemask_epi8(_mm256_cmpeq_epi32(clamped, _mm256_set1_epi32(int(first)))) == -1) return &splatted[first];
                if (!columns.empty()) return std::construct_at(&scratch, permuted(clamped));
                alignas(32) std::uint32_t element[W];
                _mm256_store_si256(reinterpret_cast<__m256i*>(element), clamped);
                return std::construct_at(&scratch, gather<V, true>(table.data(), element));
            }
        }
#endif
        alignas(64) std::uint32_t element[W];
        bool uniform = true;
        for (std::size_t k = 0; k < W; ++k) {
            element[k] = std::min(id[k < count ? k : count - 1], last);
            uniform = uniform && element[k] == element[0];
        }
        if (uniform) return &splatted[element[0]];
        return std::construct_at(&scratch, gather<V, true>(table.data(), element));
    }
};

/// Lanes [0, W) of a vector input for points i .. i + count - 1 (count <= W): SoA straight from
/// the three spans when the step is full, else through a padded copy (lanes past count: pad).
template <class V, glm::qualifier Q, class T>
glm::vec<3, V, Q> load_vec3(const soa3<T>& in, std::size_t i, std::size_t count, const glm::vec<3, T, Q>& pad)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if (count == W) return {load<V>(in.x.data() + i), load<V>(in.y.data() + i), load<V>(in.z.data() + i)};
    alignas(64) T buf[3][W];
    for (std::size_t k = 0; k < W; ++k) {
        buf[0][k] = k < count ? in.x[i + k] : pad.x;
        buf[1][k] = k < count ? in.y[i + k] : pad.y;
        buf[2][k] = k < count ? in.z[i + k] : pad.z;
    }
    return {load<V>(buf[0]), load<V>(buf[1]), load<V>(buf[2])};
}

#if PHONG_HAS_XSIMD && defined(__AVX512F__)
/// The 3 x W transpose of W interleaved vec3 (3 registers a, b, c of W scalars: x0 y0 z0 x1 ...)
/// into x, y, z lanes, two two-source permutes per component: t = lanes from (a, b), then the
/// lanes that come from c. The tables are the indices of permutex2var: component o of lane k is
/// scalar 3k + o; below 2W it is in (a, b), else c's scalar 3k + o - 2W.
template <std::size_t W> struct aos_permutes {
    alignas(64) std::int32_t ab[3][W]{}, with_c[3][W]{};  // 32-bit: the float table
    alignas(64) std::int64_t ab64[3][W]{}, with_c64[3][W]{}; // 64-bit: the double table
    /// and back: block b of the interleaved output (scalars bW .. bW + W - 1) from x, y (first
    /// permute), then z.
    alignas(64) std::int32_t xy[3][W]{}, with_z[3][W]{};
    alignas(64) std::int64_t xy64[3][W]{}, with_z64[3][W]{};
    constexpr aos_permutes()
    {
        for (std::size_t o = 0; o < 3; ++o)
            for (std::size_t k = 0; k < W; ++k) {
                const std::size_t s = 3 * k + o;
                const std::size_t first = s < 2 * W ? s : 0, second = s < 2 * W ? k : W + s - 2 * W;
                ab[o][k] = std::int32_t(first), with_c[o][k] = std::int32_t(second);
                ab64[o][k] = std::int64_t(first), with_c64[o][k] = std::int64_t(second);
            }
        for (std::size_t b = 0; b < 3; ++b)
            for (std::size_t j = 0; j < W; ++j) {
                const std::size_t s = b * W + j, point = s / 3, component = s % 3;
                const std::size_t first = component == 0 ? point : component == 1 ? W + point : 0;
                const std::size_t second = component == 2 ? W + point : j;
                xy[b][j] = std::int32_t(first), with_z[b][j] = std::int32_t(second);
                xy64[b][j] = std::int64_t(first), with_z64[b][j] = std::int64_t(second);
            }
    }
};
template <std::size_t W> inline constexpr aos_permutes<W> aos_permute_table{};
#endif

/// Whether full steps of W interleaved glm::vec3 (3W scalars in a row) are transposed to and
/// from x, y, z lanes in registers (aos_lanes, interleave_lanes): AVX-512 (float or double) and
/// AVX2 (float) with an unpadded vec3. Elsewhere they go through a small buffer.
template <class V, class T, glm::qualifier Q> inline constexpr bool aos_in_registers =
    sizeof(glm::vec<3, T, Q>) == 3 * sizeof(T) && (avx512_lanes<V, T> || avx2_float_lanes<V, T>);

/// The x, y, z lanes of W interleaved vec3 at s (3W scalars: x0 y0 z0 x1 ...), transposed in
/// registers (aos_in_registers only): AVX-512, three loads and six two-source permutes; AVX2,
/// three loads, six blends and three permutes.
template <class V, glm::qualifier Q, class T>
inline glm::vec<3, V, Q> aos_lanes([[maybe_unused]] const T* s)
{
    static_assert(aos_in_registers<V, T, Q>);
    [[maybe_unused]] constexpr std::size_t W = sizeof(V) / sizeof(T);
    glm::vec<3, V, Q> r;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (avx512_lanes<V, T>) {
        constexpr const aos_permutes<W>& P = aos_permute_table<W>;
        for (int o = 0; o < 3; ++o) {
            if constexpr (std::is_same_v<T, float>) {
                const __m512 t = _mm512_permutex2var_ps(_mm512_loadu_ps(s), _mm512_load_si512(P.ab[o]), _mm512_loadu_ps(s + W));
                r[o] = V(_mm512_permutex2var_ps(t, _mm512_load_si512(P.with_c[o]), _mm512_loadu_ps(s + 2 * W)));
            } else {
                const __m512d t = _mm512_permutex2var_pd(_mm512_loadu_pd(s), _mm512_load_si512(P.ab64[o]), _mm512_loadu_pd(s + W));
                r[o] = V(_mm512_permutex2var_pd(t, _mm512_load_si512(P.with_c64[o]), _mm512_loadu_pd(s + 2 * W)));
            }
        }
        return r;
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (avx2_float_lanes<V, T>) {
        const __m256 a = _mm256_loadu_ps(s), b = _mm256_loadu_ps(s + 8), c = _mm256_loadu_ps(s + 16);
        r = {V(aos8_component<0>(a, b, c)), V(aos8_component<1>(a, b, c)), V(aos8_component<2>(a, b, c))};
    }
#endif
    return r;
}

/// The same from an array of glm vectors (AoS): a W x 3 transpose (aos_lanes for a full step
/// where aos_in_registers; else through a small buffer). The lanes are the same values as from
/// SoA spans, so both layouts give the same bits.
template <class V, glm::qualifier Q, class T>
glm::vec<3, V, Q> load_vec3(std::span<const glm::vec<3, T, Q>> in, std::size_t i, std::size_t count, const glm::vec<3, T, Q>& pad)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if constexpr (aos_in_registers<V, T, Q>)
        if (count == W) return aos_lanes<V, Q>(&in[i].x);
    alignas(64) T buf[3][W];
    for (std::size_t k = 0; k < W; ++k) {
        const glm::vec<3, T, Q>& p = k < count ? in[i + k] : pad;
        buf[0][k] = p.x;
        buf[1][k] = p.y;
        buf[2][k] = p.z;
    }
    return {load<V>(buf[0]), load<V>(buf[1]), load<V>(buf[2])};
}

/// Stores the r, g, b lanes of a colour as W interleaved rgb at d (3W scalars; aos_in_registers
/// only): AVX-512, six permutes and three stores; AVX2, nine permutes, six blends, three stores.
template <class V, class T, glm::qualifier Q>
inline void interleave_lanes([[maybe_unused]] const glm::vec<3, V, Q>& c, [[maybe_unused]] T* d)
{
    static_assert(aos_in_registers<V, T, Q>);
    [[maybe_unused]] constexpr std::size_t W = sizeof(V) / sizeof(T);
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    if constexpr (avx512_lanes<V, T>) {
        constexpr const aos_permutes<W>& P = aos_permute_table<W>;
        for (int b = 0; b < 3; ++b) {
            if constexpr (std::is_same_v<T, float>) {
                const __m512 t = _mm512_permutex2var_ps(c[0], _mm512_load_si512(P.xy[b]), c[1]);
                _mm512_storeu_ps(d + b * W, _mm512_permutex2var_ps(t, _mm512_load_si512(P.with_z[b]), c[2]));
            } else {
                const __m512d t = _mm512_permutex2var_pd(c[0], _mm512_load_si512(P.xy64[b]), c[1]);
                _mm512_storeu_pd(d + b * W, _mm512_permutex2var_pd(t, _mm512_load_si512(P.with_z64[b]), c[2]));
            }
        }
        return;
    }
#endif
#if PHONG_HAS_XSIMD && defined(__AVX2__)
    if constexpr (avx2_float_lanes<V, T>) {
        _mm256_storeu_ps(d, interleave8_block<0>(c[0], c[1], c[2]));
        _mm256_storeu_ps(d + 8, interleave8_block<1>(c[0], c[1], c[2]));
        _mm256_storeu_ps(d + 16, interleave8_block<2>(c[0], c[1], c[2]));
    }
#endif
}

/// Stores the lanes of a colour into count interleaved colours at out (rgb, a full step:
/// interleave_lanes where aos_in_registers; else through a small buffer).
template <class V, class T, int N, glm::qualifier Q>
void store_interleaved(const glm::vec<N, V, Q>& c, glm::vec<N, T, Q>* out, std::size_t count)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    if constexpr (N == 3 && aos_in_registers<V, T, Q>) {
        if (count == W) return interleave_lanes<V, T, Q>(c, &out->x);
    }
    alignas(64) T buf[4][W];
    for (int ch = 0; ch < N; ++ch) store(c[ch], buf[ch]);
    for (std::size_t k = 0; k < count; ++k)
        for (int ch = 0; ch < N; ++ch) out[k][ch] = buf[ch][k];
}

/// sums where `lanes` is set, else `before`: the lanes that do not see a light keep exactly the
/// sums they had without it.
template <class V, glm::qualifier Q>
folded_sums<V, Q> select_sums(const mask_t<V>& lanes, const folded_sums<V, Q>& sums, const folded_sums<V, Q>& before)
{
    folded_sums<V, Q> r;
    for (int c = 0; c < 3; ++c) r.total[c] = phong::select(lanes, sums.total[c], before.total[c]);
    return r;
}
template <class V, glm::qualifier Q>
light_sums<V, Q> select_sums(const mask_t<V>& lanes, const light_sums<V, Q>& sums, const light_sums<V, Q>& before)
{
    light_sums<V, Q> r;
    for (int c = 0; c < 3; ++c) {
        r.ambient[c] = phong::select(lanes, sums.ambient[c], before.ambient[c]);
        r.diffuse[c] = phong::select(lanes, sums.diffuse[c], before.diffuse[c]);
        r.specular[c] = phong::select(lanes, sums.specular[c], before.specular[c]);
    }
    return r;
}

/// Which lanes see light j: bit k set when lane k's mask has bit j (lanes past count have no
/// bits). AVX-512: two (float) or one (double) 64-bit lane tests of the W masks, as a k-mask.
template <class V, class T> struct lane_visibility {
    static constexpr std::size_t W = sizeof(V) / sizeof(T);
    const std::uint64_t* bits;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
    __m512i low{}, high{}; // the masks of lanes 0..7 and 8..15 (float)
    explicit lane_visibility(const std::uint64_t* b) : bits(b)
    {
        if (!b) return;
        if constexpr (avx512_lanes<V, T>) {
            low = _mm512_loadu_si512(b);
            if constexpr (W == 16) high = _mm512_loadu_si512(b + 8);
        }
    }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
    __m256i low{}, high{}; // the masks of lanes 0..3 and 4..7 (float)
    explicit lane_visibility(const std::uint64_t* b) : bits(b)
    {
        if (!b) return;
        if constexpr (avx2_float_lanes<V, T>) {
            low = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b));
            high = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + 4));
        }
    }
#else
    explicit lane_visibility(const std::uint64_t* b) : bits(b) {}
#endif
    std::uint32_t lanes_seeing(std::size_t j) const
    {
        const std::uint64_t bit = std::uint64_t(1) << j;
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T>) {
            const __m512i b = _mm512_set1_epi64(std::int64_t(bit));
            std::uint32_t m = _mm512_test_epi64_mask(low, b);
            if constexpr (W == 16) m |= std::uint32_t(_mm512_test_epi64_mask(high, b)) << 8;
            return m;
        }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) { // bit j of each 64-bit mask to its sign bit, then movemask
            const __m256i up = _mm256_set1_epi64x(std::int64_t(63 - j));
            const int m_low = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_sllv_epi64(low, up)));
            const int m_high = _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_sllv_epi64(high, up)));
            return std::uint32_t(m_low) | std::uint32_t(m_high) << 4;
        }
#endif
        std::uint32_t m = 0;
        for (std::size_t k = 0; k < W; ++k) m |= std::uint32_t((bits[k] & bit) != 0) << k;
        return m;
    }
    /// The lane mask of bit set k <=> lane k (partial visibility: a select).
    static mask_t<V> mask(std::uint32_t lanes)
    {
#if PHONG_HAS_XSIMD && defined(__AVX512F__)
        if constexpr (avx512_lanes<V, T>) {
            if constexpr (W == 16) return mask_t<V>(typename mask_t<V>::register_type(__mmask16(lanes)));
            else return mask_t<V>(typename mask_t<V>::register_type(__mmask8(lanes)));
        }
#elif PHONG_HAS_XSIMD && defined(__AVX2__)
        if constexpr (avx2_float_lanes<V, T>) { // lane k: all ones where bit k of lanes is set
            const __m256i lane_bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
            const __m256i set = _mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(lanes)), lane_bit), lane_bit);
            return mask_t<V>(_mm256_castsi256_ps(set));
        }
#endif
        alignas(64) T seen[W];
        for (std::size_t k = 0; k < W; ++k) seen[k] = (lanes >> k & 1u) ? T(1) : T(0);
        return load<V>(seen) > V(T(0));
    }
};

/// The qualifier of a sums type (light_sums<V, Q> or folded_sums<V, Q>).
template <class Sums> struct sums_qualifier;
template <template <class, glm::qualifier> class S, class V, glm::qualifier Q> struct sums_qualifier<S<V, Q>> {
    static constexpr glm::qualifier value = Q;
};
template <class Sums> inline constexpr glm::qualifier Q_of = sums_qualifier<Sums>::value;

#if defined(__GNUC__) || defined(__clang__)
#  define PHONG_BATCH_ALWAYS_INLINE inline __attribute__((always_inline))
#else
#  define PHONG_BATCH_ALWAYS_INLINE inline
#endif
/// Every light's terms added to the sums of one step, light j only in the lanes whose mask has
/// bit j (bits: one mask per lane, 0 past the tail; null: every light in every lane). A light no
/// lane sees is skipped; one that every point of the step sees is added as without masks; else
/// it is added and the lanes that do not see it get their sums back (select: exactly nothing
/// from it, its ambient term included). Lights past the 64th are seen by no point. One call site
/// of add_light for every case, masks or none: a masked light, a removed one (the same call with
/// the light left out) and a call without masks run the same compiled code (but for the fast
/// mode's Phong with a power-of-two shininess without masks, add_masked_lights: the same bits).
/// Which lanes see a light: one bit test of the W masks per light (AVX-512: two vector tests, the
/// result a k-mask used as is; AVX2: a shift and a movemask per four lanes).
/// each_visible_light calls add_light(sums, j) for every light j (light_count of them) by these
/// rules; the frame and the route are the caller's (add_masked_lights: detail::add_light).
template <class V, class T, class Sums, class AddLight>
PHONG_BATCH_ALWAYS_INLINE void each_visible_light(Sums& sums, std::size_t light_count, const std::uint64_t* bits, std::size_t count,
                                                  AddLight&& add_light)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    // Without masks every lane sees every light: the same loop (one call site of add_light, which
    // the compiler then inlines; with a second loop for this case g++ 12 kept add_light out of
    // line: 9 % more instructions in shade_lanes with masks, AVX2, 1 light).
    const std::uint32_t live = count >= W ? std::uint32_t((std::uint64_t(1) << W) - 1) : std::uint32_t((1u << count) - 1);
    const lane_visibility<V, T> visibility(bits);
    const std::size_t n = bits ? std::min<std::size_t>(light_count, 64) : light_count;
    for (std::size_t j = 0; j < n; ++j) {
        const std::uint32_t seeing = bits ? visibility.lanes_seeing(j) : live;
        if (bits && !seeing) continue; // live != 0: a step has at least one point
        const bool partial = seeing != live;
        const Sums before = sums;
        add_light(sums, j);
        if (partial) sums = select_sums<V, Q_of<Sums>>(lane_visibility<V, T>::mask(seeing), sums, before);
    }
}

template <features F, class V, class T, glm::qualifier Q, class Sums, class Exponent>
PHONG_BATCH_ALWAYS_INLINE void add_masked_lights(Sums& sums, const frame_t<F, V, Q>& s, std::span<const light<V, Q>> lights,
                       const Exponent& m, const std::uint64_t* bits, std::size_t count)
{
    if constexpr (std::is_same_v<V, T>) { // scalar lanes (no xsimd): shade<F>'s own light loop
        if (!bits) add_lights<F>(sums, s, lights, m);
        else add_lights<F>(sums, s, masked(lights, bits[0]), m);
        return;
    } else {
        // Float lanes: the step's specular constants (exact::step_specular), made once per step; a
        // pair's specular mask is then one compare. Else m as given.
        const auto step_m = [&] {
            if constexpr (std::is_same_v<Exponent, exact::lane_shininess<V>> && std::is_same_v<T, float> && exact::step_specular_route<F>)
                return exact::step_specular_of(m, s.sees_viewer);
            else return m;
        }();
        if constexpr (std::is_same_v<Exponent, exact::integer_exponent<V>> && F.specular == specular_model::phong) {
            // The fast mode's integer shininess n = 2^K (plan.chain = K + 1, K <= 6), no masks: the
            // light loop with K known, its power K squarings with no jump per pair; the same bits.
            // Measured (phong_batch_ratio fast, AVX-512): Phong 2 % faster at 16 lights, 6 % at 1;
            // Blinn 1 to 8 % slower, so it keeps the jump.
            if (!bits) {
                const auto each_light = [&](const auto& fixed) {
                    for (std::size_t j = 0; j < lights.size(); ++j) detail::add_light<F>(sums, s, lights[j], fixed);
                };
                switch (m.plan.chain) {
                case 1: return each_light(m.template with_squarings<0>());
                case 2: return each_light(m.template with_squarings<1>());
                case 3: return each_light(m.template with_squarings<2>());
                case 4: return each_light(m.template with_squarings<3>());
                case 5: return each_light(m.template with_squarings<4>());
                case 6: return each_light(m.template with_squarings<5>());
                case 7: return each_light(m.template with_squarings<6>());
                default: break;
                }
            }
        }
        each_visible_light<V, T>(sums, lights.size(), bits, count,
                                 [&](Sums& step_sums, std::size_t j) { detail::add_light<F>(step_sums, s, lights[j], step_m); });
    }
}

/// The lights' ambient terms La_i f_i do not depend on the point (f_i = 1, or ambient not
/// attenuated): shade_batch with one material and no masks adds their sum once per call (a
/// per-light constant hoisted), not once per light per step.
template <features F>
inline constexpr bool ambient_hoistable = F.light_ambient && (!F.attenuate_ambient || ((F.attenuation == attenuation_model::none ||
                                                                                       F.lights == light_kind::directional) &&
                                                                                      F.spot == spot_model::none));
/// F as shade_lanes runs it with the ambient hoisted: the loop has no light ambient term (the
/// folded sums start at ka (La + sum_i La_i), shade_points_impl).
template <features F>
inline constexpr features ambient_hoisted = [] {
    features g = F;
    g.light_ambient = false;
    return g;
}();

/// Whether shade_batch runs F on lanes V through detail/stable_lanes.hpp (the stable mode on
/// float lanes of x86).
template <features F, class V> inline constexpr bool stable_lanes_route =
#if PHONG_STABLE_LANES
    F.mode == evaluation::stable && stable_lanes::applies<V>;
#else
    false;
#endif

#if defined(__GNUC__) || defined(__clang__)
#  define PHONG_BATCH_NOINLINE __attribute__((noinline, flatten))
#else
#  define PHONG_BATCH_NOINLINE
#endif

/// The lanes of one batch step: W points' position, normal, view vector (set and read only with
/// view_model::given) and front-facing flags.
template <class V, glm::qualifier Q> struct step_lanes {
    glm::vec<3, V, Q> position;
    glm::vec<3, V, Q> normal;
    glm::vec<3, V, Q> view;
    mask_t<V> front;
};

/// Where shade_lanes reads its steps' lanes and writes their colours: one pointer per component
/// (in: position x y z, normal x y z, view x y z; out: r g b a) and the elements from one step to
/// the next. Full SoA steps point into the caller's spans (stride W: nothing copied); full AoS
/// steps (aos_in) and interleaved rgb colours (interleaved_out) point into the caller's arrays
/// too, transposed in registers (aos_in_registers; stride 3W); tails, and AoS or interleaved
/// layouts without those transposes, point into a block of the call (stride: one block step).
/// Every layout runs the same compiled shade_lanes through it (the layout is a run-time flag, not
/// a template parameter), so their colours agree bit for bit.
template <class V, class T> struct step_stream {
    const T* in[9];          ///< view x y z: read only with view_model::given; aos_in: in[0], in[3], in[6] only
    std::size_t in_stride;
    const mask_t<V>* front;  ///< front-facing lanes, one mask per step; null: every lane
    T* out[4];               ///< a: written only with F.alpha; interleaved_out: out[0] only
    std::size_t out_stride;
    bool aos_in;             ///< in[0], in[3], in[6]: W interleaved vec3 per step
    bool interleaved_out;    ///< out[0]: W interleaved rgb per step
    /// Step k's lanes (the view only with view_model::given). Flags: false where the caller knows
    /// that neither aos_in nor interleaved_out is set (SoA in and out, blocks): no test per step.
    template <features F, glm::qualifier Q, bool Flags = true> step_lanes<V, Q> lanes(std::size_t k) const
    {
        const std::size_t o = k * in_stride;
        step_lanes<V, Q> s;
        s.front = front ? front[k] : mask_t<V>(true);
        if constexpr (Flags && aos_in_registers<V, T, Q>) {
            if (aos_in) {
                s.position = aos_lanes<V, Q>(in[0] + o);
                s.normal = aos_lanes<V, Q>(in[3] + o);
                if constexpr (F.view == view_model::given) s.view = aos_lanes<V, Q>(in[6] + o);
                return s;
            }
        }
        s.position = {load<V>(in[0] + o), load<V>(in[1] + o), load<V>(in[2] + o)};
        s.normal = {load<V>(in[3] + o), load<V>(in[4] + o), load<V>(in[5] + o)};
        if constexpr (F.view == view_model::given) s.view = {load<V>(in[6] + o), load<V>(in[7] + o), load<V>(in[8] + o)};
        return s;
    }
    /// Stores step k's colour (Flags as lanes).
    template <features F, glm::qualifier Q, bool Flags = true> void put(std::size_t k, const color<F, V, Q>& c) const
    {
        if constexpr (Flags && !F.alpha && aos_in_registers<V, T, Q>) {
            if (interleaved_out) return interleave_lanes<V, T, Q>(c, out[0] + k * out_stride);
        }
        constexpr int channels = F.alpha ? 4 : 3;
        for (int ch = 0; ch < channels; ++ch) store(c[ch], out[ch] + k * out_stride);
    }
};

/// Steps per call of shade_lanes: the per-call work (entry, the hoisted constants, the return) is
/// shared by that many steps, and the out-of-order core overlaps one step's long dependent chain
/// (normalizations, the power's polynomial) and its loads from memory with the next step's, which
/// a call per step kept apart (batch exact at K = 1: 1.4x the hand-written kernel's time with a
/// call per step; docs/batch.md). Steps read and written in place (SoA points or AoS points with
/// the transposes in registers; SoA colours or interleaved rgb likewise) take 128 per call (K = 1:
/// Phong 0.94x to 0.95x, Blinn 0.95x to 0.97x the hand-written kernel's time against 0.97x and 0.99x
/// with 32, 0.99x with 8; 512 gained at most 1 % more), steps through the call's blocks 8 (a block
/// of 32 steps would be 26 KiB). The arrays per step of a call (per-step material pointers, facing
/// masks) exist only where they are used.
inline constexpr std::size_t steps_per_call = 128;
inline constexpr std::size_t block_steps_per_call = 8;
/// Whether full steps of these points are read in place, and full steps' colours written in place.
template <class Points, class V, class T, glm::qualifier Q>
inline constexpr bool points_in_place =
    std::is_same_v<Points, soa_points<T>> || (std::is_same_v<Points, aos_points<T, Q>> && aos_in_registers<V, T, Q>);
template <features F, class Output, class V, class T, glm::qualifier Q>
inline constexpr bool colours_in_place = std::is_same_v<Output, soa_rgba<T>> || (!F.alpha && aos_in_registers<V, T, Q>);
template <features F, class Points, class Output, class V, class T, glm::qualifier Q>
inline constexpr bool in_place_steps = points_in_place<Points, V, T, Q> && colours_in_place<F, Output, V, T, Q>;
/// The most steps of one call for these points and this output.
template <features F, class Points, class Output, class V, class T, glm::qualifier Q>
inline constexpr std::size_t call_steps = in_place_steps<F, Points, Output, V, T, Q> ? steps_per_call : block_steps_per_call;

/// The shininess lanes with m == 0 tested (exact::lane_shininess): once per call, or once per
/// step with per-step materials.
template <class V> exact::lane_shininess<V> shininess_lanes(const V& m)
{
    using S = typename math_traits<V>::scalar;
    const mask_t<V> zero = m == V(S(0));
    return {m, zero, math_traits<V>::any(zero), phong::select(zero, V(-std::numeric_limits<S>::infinity()), V(S(0))),
            phong::min(m, V(S(0x1p100)))};
}

/// The lanes' colours, step by step: prepare, every (visible) light, finish, for each of `steps`
/// steps from step `first` of the stream (its step first + k in, its colour first + k out). The
/// caller passes the stream it built, unchanged: a copy per call, offset to the step (one call per
/// step with a material table), cost the ray tracer's AoS table path about 0.5 ns per hit
/// (benchmarks/demo/whitted.cpp, batch column). Not inlined, on purpose: every layout (soa3, soa_points, aos_points; either
/// output) calls this one compiled function, so the compiler's choices (FMA
/// contraction above all) are the same for all of them and the layouts agree bit for bit
/// (inlined, AoS and SoA differed by an ulp at -march=native). Flattened: every call inside
/// (the light loop's add_light, the power, xsimd's kernels) is inlined into it, so the point's
/// frame and sums stay in registers across the light loop (before, add_light was a call per
/// light per step with its operands in memory: batch exact took 1.5x to 2.6x the hand-written
/// kernel's time; benchmarks/hand_simd.bench.cpp).
/// bits: W light masks per step (the k-th step from `first`: bits + k W; 0 past the tail), or
/// null; count: the live lanes of each step (W, or a tail's count with steps = 1). Folded: the lights carry the
/// material's ka, kd and ks (one material for all points, shade_points_impl): folded_sums, else
/// light_sums. Folded, env.ambient is not the scene's ambient but the colour's point-independent
/// part, emission + ka La, + ka sum_i La_i when hoisted (ambient_hoisted: without masks, the
/// loop runs without the lights' ambient terms); the sums start from it.
/// step_materials: null (mat for every step), or, not folded and in the exact mode only, the
/// material lanes of each step (step k: *step_materials[k]; per-point materials or a table's
/// tail). table: null, or (exact mode, not folded, full steps) a material table whose step k
/// takes the ids of points table_first + k W .. + W - 1, looked up in the step loop
/// (table_lanes::step; step_materials null). The fast mode's integer exponent and the stable
/// mode's route are decided per call from mat: those modes take one step per call with
/// per-step materials.
template <features F, class V, class T, glm::qualifier Q, bool Folded>
PHONG_BATCH_NOINLINE void shade_lanes(const step_stream<V, T>& stream, std::size_t first, std::size_t steps, const material<V, Q>& mat,
                                      std::span<const light<V, Q>> lights, std::span<const light<double, Q>> wide_lights,
                                      const environment<V, Q>& env, const std::uint64_t* bits, std::size_t count,
                                      const material<V, Q>* const* step_materials, const table_lanes<V, T, Q>* table = nullptr,
                                      std::size_t table_first = 0)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    const step_stream<V, T> io = stream; // a copy the colour stores cannot alias: its pointers stay in registers
    using Sums = std::conditional_t<Folded, folded_sums<V, Q>, light_sums<V, Q>>;
#if PHONG_STABLE_LANES
    if constexpr (stable_lanes_route<F, V>) {
        // The stable mode's geometry in double lanes (detail/stable_lanes.hpp), unless a lane's
        // shininess is above that route's limit: then the twofold route below.
        if (!xsimd::any(mat.shininess > V(stable_lanes::max_shininess))) {
            for (std::size_t k = 0; k < steps; ++k) {
                const std::uint64_t* step_bits = bits ? bits + k * W : nullptr;
                const step_lanes<V, Q> in = io.template lanes<F, Q>(first + k);
                const stable_lanes::surface_frame<V, Q> s = stable_lanes::prepare<F>(in.position, in.normal, in.view, env, in.front);
                Sums sums{};
                if constexpr (Folded) sums.total = env.ambient + s.poison; // finish(folded_sums): the poison is in the start
                const auto shade_step = [&]<features G>() {
                    each_visible_light<V, T>(sums, lights.size(), step_bits, count, [&](Sums& step_sums, std::size_t j) {
                        stable_lanes::add_light<G>(step_sums, s, lights[j], wide_lights[j], mat.shininess);
                    });
                    io.template put<G, Q>(first + k, finish<G>(sums, s, mat, env));
                };
                if constexpr (Folded && ambient_hoistable<F>) {
                    if (!step_bits) {
                        shade_step.template operator()<ambient_hoisted<F>>();
                        continue;
                    }
                }
                shade_step.template operator()<F>();
            }
            return;
        }
    }
#else
    (void)wide_lights;
#endif
    // The steps with masks or without: two loops, so that a call without masks tests nothing per step.
    // Flags: the loop that tests io's layout flags per step (a loop of its own, so that SoA steps
    // test nothing: the test per step cost Blinn K = 1 3 % against the hand-written kernel).
    const auto run_steps = [&]<bool Masks, bool Flags>(const auto& call_m) {
        // Step k's colour is stored after step k + 1's lanes are loaded: stored before, it held up
        // those loads where the spans share their offset in a 4 KiB page (batch exact, Blinn, K = 1,
        // the benchmark's std::vectors: 1.07x the hand-written kernel's time against 0.78x).
        color<F, V, Q> pending;
        for (std::size_t k = 0; k < steps; ++k) {
            const std::uint64_t* step_bits = Masks ? bits + k * W : nullptr;
            const step_lanes<V, Q> in = io.template lanes<F, Q, Flags>(first + k);
            if (k > 0) io.template put<F, Q, Flags>(first + k - 1, pending);
            const frame_t<F, V, Q> s = prepare<F>(in.position, in.normal, in.view, env, in.front);
            Sums sums{};
            if constexpr (Folded) sums.total = env.ambient + s.poison; // finish(folded_sums): the poison is in the start
            if constexpr (Folded && ambient_hoistable<F> && !Masks) {
                constexpr features G = ambient_hoisted<F>;
                add_masked_lights<G, V, T, Q>(sums, s, lights, call_m, step_bits, count);
                pending = finish<G>(sums, s, mat, env);
            } else if constexpr (!Folded && std::is_same_v<std::decay_t<decltype(call_m)>, exact::lane_shininess<V>>) {
                // Per-step materials: the step's shininess tested for 0 here, as once per call otherwise.
                // A table's step looks its ids up here, in the loop: their loads and, for mixed
                // ids, the lanes' permutes overlap the shading of the steps around them.
                material_slot<V, Q> looked_up;
                const material<V, Q>& step_mat = table            ? *table->step(table_first + k * W, W, looked_up.lanes)
                                                 : step_materials ? *step_materials[k]
                                                                  : mat;
                exact::lane_shininess<V> m = call_m;
                if (table || step_materials) m = shininess_lanes(step_mat.shininess);
                add_masked_lights<F, V, T, Q>(sums, s, lights, m, step_bits, count);
                pending = finish<F>(sums, s, step_mat, env);
            } else {
                add_masked_lights<F, V, T, Q>(sums, s, lights, call_m, step_bits, count);
                pending = finish<F>(sums, s, mat, env);
            }
        }
        if (steps > 0) io.template put<F, Q, Flags>(first + steps - 1, pending);
    };
    const auto run = [&](const auto& m) { // m: the shininess (V, exact::lane_shininess<V> or exact::integer_exponent<V>)
        if constexpr (aos_in_registers<V, T, Q>) {
            if (io.aos_in || io.interleaved_out) {
                if (bits) run_steps.template operator()<true, true>(m);
                else run_steps.template operator()<false, true>(m);
                return;
            }
        }
        if (bits) run_steps.template operator()<true, false>(m);
        else run_steps.template operator()<false, false>(m);
    };
    if constexpr (F.mode == evaluation::fast && !std::is_same_v<V, T>) {
        // One integer shininess in every lane (a shared material, or a step of equal ones):
        // the fast power by binary powering, its schedule made here once rather than per pair
        // (n >= 1; m = 0, pow(0, 0) = 1 on every lane that is on, takes lane_shininess below).
        const T m0 = mat.shininess.get(0);
        if (m0 >= T(1) && m0 <= T(fast::pow_integer_max_exponent) && m0 == T(unsigned(m0)) &&
            math_traits<V>::all(mat.shininess == V(m0)))
            return run(exact::integer_exponent<V>::of(unsigned(m0)));
    }
    if constexpr (F.mode != evaluation::stable && !std::is_same_v<V, T>) {
        run(shininess_lanes(mat.shininess)); // m == 0 tested once
    } else {
        run(mat.shininess);
    }
}

/// One material for every point: its lanes, splatted once per call (folded into the lights).
template <class V, glm::qualifier Q> struct shared_lanes {
    material<V, Q> lanes;
};
/// The same where folding would lose a product to underflow or overflow (foldable below): the
/// material multiplies the sums at the end, as per point.
template <class V, glm::qualifier Q> struct unfolded_shared_lanes {
    material<V, Q> lanes;
};

/// One material per point: the step's materials gathered into lanes (the tail's pad lanes take
/// the last point's material).
template <class V, class T, glm::qualifier Q> struct per_point_lanes {
    std::span<const material<T, Q>> materials;
    /// The lanes of points i .. i + count - 1, in `scratch`.
    const material<V, Q>* step(std::size_t i, std::size_t count, material<V, Q>& scratch) const
    {
        constexpr std::size_t W = sizeof(V) / sizeof(T);
        if (count == W) {
            std::construct_at(&scratch, gather<V, false>(materials.data() + i, full_step_elements<W>.index));
        } else {
            const consecutive_elements<W> tail(count);
            std::construct_at(&scratch, gather<V, false>(materials.data() + i, tail.index));
        }
        return &scratch;
    }
};

/// The front-facing lanes of one step (count <= W flags from index i; lanes past count: front).
template <class V, class T> mask_t<V> front_lanes(std::span<const bool> front_facing, std::size_t i, std::size_t count)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    alignas(64) T buf[W];
    for (std::size_t k = 0; k < W; ++k) buf[k] = k < count && !front_facing[i + k] ? T(0) : T(1);
    return load<V>(buf) > V(T(0));
}

/// Loads the position, normal and view lanes of one batch step over points of any layout
/// (soa_points, aos_points): `count` <= W points starting at index i. Full steps load SoA spans
/// directly and AoS through a transpose; tails go through padded copies (the pad: Q = (0, 0, -1),
/// n = v = (0, 0, 1), facing the eye).
template <features F, class V, class Points, class T, glm::qualifier Q>
void load_step(std::size_t i, std::size_t count, const Points& points, step_lanes<V, Q>& lanes)
{
    using vec3 = glm::vec<3, T, Q>;
    lanes.position = load_vec3<V, Q>(points.positions, i, count, vec3(T(0), T(0), T(-1)));
    lanes.normal = load_vec3<V, Q>(points.normals, i, count, vec3(T(0), T(0), T(1)));
    if constexpr (F.view == view_model::given) lanes.view = load_vec3<V, Q>(points.views, i, count, vec3(T(0), T(0), T(1)));
}

/// Stores the colours of one batch step (count <= W points from index i).
template <features F, class V, class T, glm::qualifier Q, class Output>
void store_step(const color<F, V, Q>& c, std::size_t i, std::size_t count, const Output& out)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    constexpr int channels = F.alpha ? 4 : 3;
    if constexpr (std::is_same_v<Output, soa_rgba<T>>) {
        T* dst[4] = {out.r.data(), out.g.data(), out.b.data(), F.alpha ? out.a.data() : nullptr};
        for (int ch = 0; ch < channels; ++ch) {
            if (count == W) {
                store(c[ch], dst[ch] + i);
            } else {
                alignas(64) T buf[W];
                store(c[ch], buf);
                for (std::size_t k = 0; k < count; ++k) dst[ch][i + k] = buf[k];
            }
        }
    } else {
        store_interleaved<V, T>(c, out.data() + i, count);
    }
}

// g++ -O1 reports `in` below as maybe uninitialized when it passes the array to shade_lanes, which
// reads in[k] only for k < steps, all loaded first: a false positive (found by CI's consumer build
// with PHONG_NO_XSIMD -O1 -march=native). Silenced for this function only; with xsimd the region
// opened before <xsimd/xsimd.hpp> covers it already.
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic push
#  pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
/// Material lanes kept per call of shade_lanes for steps of mixed materials (per-point
/// materials; a table's full steps are looked up in shade_lanes): a call ends at the step that
/// would need one more.
inline constexpr std::size_t step_material_slots = 8;

/// Up to call_steps batch steps from point i (steps full steps of W points, or one step of
/// count < W points: a tail), through one call of shade_lanes; returns the steps shaded (fewer
/// than `steps` when the call ran out of step_material_slots). Full SoA steps, full AoS steps
/// (aos_in_registers) and light masks of full steps are read in place, full steps' SoA or
/// interleaved rgb colours written in place. `materials` gives each step's material lanes
/// (shared_lanes, per_point_lanes or table_lanes); materials that differ per step go in one call
/// of several steps in the exact mode (a table's full steps: looked up by shade_lanes in its step
/// loop; per-point materials and a table's tail: a pointer per step, to a table's lanes as they
/// are or to a slot), one step per call in the others.
template <features F, class V, class Points, class T, glm::qualifier Q, class MaterialLanes, class Output>
std::size_t shade_points_steps(std::size_t i, std::size_t steps, std::size_t count, const Points& points,
                               const MaterialLanes& materials, std::span<const light<V, Q>> lights,
                               std::span<const light<double, Q>> wide_lights, const environment<V, Q>& env, const Output& out)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    // One material for all points: shade_points_impl folded it into the lights.
    constexpr bool folded = std::is_same_v<MaterialLanes, shared_lanes<V, Q>>;
    constexpr bool shared = folded || std::is_same_v<MaterialLanes, unfolded_shared_lanes<V, Q>>;
    constexpr int channels = F.alpha ? 4 : 3;
    constexpr std::size_t max_steps = call_steps<F, Points, Output, V, T, Q>;
    steps = std::min(steps, max_steps); // callers pass at most max_steps; said here for g++'s -Wstringop-overflow
    // Per-step materials first: they may end the call early. A table's full steps look their
    // materials up inside shade_lanes instead, where the ids' loads and a mixed step's permutes
    // overlap the shading of the steps around them and no slot can run out (before, here, for
    // all of a call's steps ahead of its shading: the ray tracer's batch, 2 lights, took ~1 ns
    // per hit more; benchmarks/demo/whitted.cpp).
    constexpr bool materials_per_step = !shared && F.mode == evaluation::exact && !std::is_same_v<V, T>;
    constexpr bool table_in_loop = materials_per_step && std::is_same_v<MaterialLanes, table_lanes<V, T, Q>>;
    const bool look_up_in_loop = table_in_loop && count == W;
    const material<V, Q>* step_material[materials_per_step ? max_steps : 1] = {}; // zeroed: g++ -O3 cannot see that steps >= 1
    material_slot<V, Q> slots[materials_per_step ? step_material_slots : 1];
    [[maybe_unused]] const auto slot = [&](std::size_t k) -> material<V, Q>& { return slots[k].lanes; };
    if constexpr (materials_per_step) {
        if (!look_up_in_loop) {
            std::size_t used = 0, k = 0;
            for (; k < steps && used < step_material_slots; ++k) {
                step_material[k] = materials.step(i + k * W, count, slot(used));
                used += step_material[k] == &slot(used);
            }
            if (k < steps && used == step_material_slots) steps = k; // the next step may need a slot
        }
    }
    // Full steps in place are read and written where they are; the rest goes through these
    // blocks (in place: only a tail, one step).
    constexpr bool in_place = in_place_steps<F, Points, Output, V, T, Q>;
    constexpr std::size_t block_steps = in_place ? 1 : block_steps_per_call;
    alignas(64) T in_block[block_steps][9][W];
    alignas(64) T out_block[block_steps][4][W];
    mask_t<V> front[F.two_sided == facing::flag ? max_steps : 1];
    step_stream<V, T> io{};
    constexpr bool soa_in = std::is_same_v<Points, soa_points<T>>;
    if (points_in_place<Points, V, T, Q> && count == W) {
        if constexpr (soa_in) {
            const soa3<T>* from[3] = {&points.positions, &points.normals, &points.views};
            for (int v = 0; v < (F.view == view_model::given ? 3 : 2); ++v)
                for (int c = 0; c < 3; ++c) io.in[3 * v + c] = (c == 0 ? from[v]->x : c == 1 ? from[v]->y : from[v]->z).data() + i;
            io.in_stride = W;
        } else if constexpr (points_in_place<Points, V, T, Q>) {
            io.in[0] = &points.positions[i].x;
            io.in[3] = &points.normals[i].x;
            if constexpr (F.view == view_model::given) io.in[6] = &points.views[i].x;
            io.in_stride = 3 * W;
            io.aos_in = true;
        }
    } else {
        for (std::size_t k = 0; k < steps && k < block_steps; ++k) { // steps <= block_steps here
            step_lanes<V, Q> lanes;
            load_step<F, V, Points, T, Q>(i + k * W, count, points, lanes);
            for (int c = 0; c < 3; ++c) {
                store(lanes.position[c], in_block[k][c]);
                store(lanes.normal[c], in_block[k][3 + c]);
                if constexpr (F.view == view_model::given) store(lanes.view[c], in_block[k][6 + c]);
            }
        }
        for (int c = 0; c < 9; ++c) io.in[c] = in_block[0][c];
        io.in_stride = 9 * W;
    }
    if constexpr (F.two_sided == facing::flag) {
        if (!points.front_facing.empty()) {
            for (std::size_t k = 0; k < steps; ++k) front[k] = front_lanes<V, T>(points.front_facing, i + k * W, count);
            io.front = front;
        }
    }
    constexpr bool soa_out = std::is_same_v<Output, soa_rgba<T>>;
    if (colours_in_place<F, Output, V, T, Q> && count == W) {
        if constexpr (soa_out) {
            T* dst[4] = {out.r.data(), out.g.data(), out.b.data(), F.alpha ? out.a.data() : nullptr};
            for (int ch = 0; ch < channels; ++ch) io.out[ch] = dst[ch] + i;
            io.out_stride = W;
        } else if constexpr (colours_in_place<F, Output, V, T, Q>) {
            io.out[0] = &out[i].x;
            io.out_stride = 3 * W;
            io.interleaved_out = true;
        }
    } else {
        for (int ch = 0; ch < channels; ++ch) io.out[ch] = out_block[0][ch];
        io.out_stride = 4 * W;
    }

    alignas(64) std::uint64_t tail_bits[W]; // a tail's masks, 0 past count (full steps read them in place)
    const std::uint64_t* bits = nullptr;
    if (!points.light_masks.empty()) {
        if (count == W) {
            bits = points.light_masks.data() + i;
        } else {
            for (std::size_t k = 0; k < W; ++k) tail_bits[k] = k < count ? points.light_masks[i + k] : 0;
            bits = tail_bits;
        }
    }
    if constexpr (shared) {
        shade_lanes<F, V, T, Q, folded>(io, 0, steps, materials.lanes, lights, wide_lights, env, bits, count, nullptr);
    } else if constexpr (materials_per_step) {
        const table_lanes<V, T, Q>* table = nullptr; // a table's full steps: looked up in shade_lanes
        if constexpr (table_in_loop) table = look_up_in_loop ? &materials : nullptr;
        shade_lanes<F, V, T, Q, folded>(io, 0, steps, table ? table->splatted[0] : *step_material[0], lights, wide_lights, env, bits,
                                        count, table ? nullptr : step_material, table, i);
    } else {
        for (std::size_t k = 0; k < steps; ++k)
            shade_lanes<F, V, T, Q, folded>(io, k, 1, *materials.step(i + k * W, count, slot(0)), lights, wide_lights, env,
                                            bits ? bits + k * W : nullptr, count, nullptr);
    }
    if (io.out[0] == out_block[0][0]) {
        for (std::size_t k = 0; k < steps && k < block_steps; ++k) {
            color<F, V, Q> c;
            for (int ch = 0; ch < channels; ++ch) c[ch] = load<V>(out_block[k][ch]);
            store_step<F, V, T, Q>(c, i + k * W, count, out);
        }
    }
    return steps;
}
#if defined(__GNUC__) && !defined(__clang__)
#  pragma GCC diagnostic pop
#endif

/// The bytes [p, p + bytes) and [q, q + bytes_q) share at least one byte (std::less: a total
/// order on pointers, also between unrelated objects).
inline bool bytes_overlap(const void* p, std::size_t bytes, const void* q, std::size_t bytes_q)
{
    if (bytes == 0 || bytes_q == 0) return false;
    const auto* a = static_cast<const unsigned char*>(p);
    const auto* b = static_cast<const unsigned char*>(q);
    const std::less<const unsigned char*> before;
    return before(a, b + bytes_q) && before(b, a + bytes);
}

/// Memory that shade_batch reads while it writes, with the span's name: none for one shared
/// material (copied into lanes first), the N materials when per point, a table's entries
/// (gathered per step) and its N ids.
struct byte_range {
    const void* p = nullptr;
    std::size_t bytes = 0;
    const char* name = "";
};
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material<T, Q>&, std::size_t) { return {}; }
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(std::span<const material<T, Q>> m, std::size_t n)
{
    return {byte_range{m.data(), n * sizeof(material<T, Q>), "materials"}, byte_range{}};
}
template <class T, glm::qualifier Q> std::array<byte_range, 2> material_reads(const material_table<T, Q>& t, std::size_t n)
{
    return {byte_range{t.materials.data(), t.materials.size() * sizeof(material<T, Q>), "material_table.materials"},
            byte_range{t.ids.data(), n * sizeof(std::uint32_t), "material_table.ids"}};
}

/// "shade_batch: an output span overlaps <an input span | another output span>: <written> over
/// <read>", formatted into a per-thread buffer (on failure only; valid until the thread's next call).
inline const char* overlap_message(const char* written, const char* read, bool input, bool coordinate) noexcept
{
    thread_local char buffer[256];
    std::snprintf(buffer, sizeof buffer, "shade_batch: an output span overlaps %s: %s over %s%s",
                  input ? "an input span" : "another output span", written, read,
                  coordinate ? " (only an output channel equal to an input coordinate span, the same data() and size(), may alias it)" : "");
    return buffer;
}

/// shade_batch's aliasing rule, checked in every build (O(1): at most 4 written and 16 read
/// ranges): the memory it writes (the first n elements of each output channel, or of the
/// interleaved colours) overlaps no memory it reads point by point (the first n coordinates of
/// positions, normals and views, materials when per point, a table and its ids, front_facing
/// flags, light masks), nor another output channel. Returns nullptr, or the message naming both
/// spans. One exception: an SoA output channel may be exactly an SoA input coordinate span (same
/// data(), whole length n), i.e. shading in place. That is safe because each step reads its
/// points' coordinates (into lanes, or padded copies for the tail) before it stores their colours,
/// and never stores to an element a later step reads. Lights, a shared material and the
/// environment are copied into lanes before the first store: no constraint.
template <int channels, class T, glm::qualifier Q, class Points, class Materials, class Output>
const char* output_overlap(const Points& points, const Materials& materials, const Output& out, std::size_t n)
{
    constexpr bool soa_out = std::is_same_v<Output, soa_rgba<T>>;
    constexpr bool soa_in = std::is_same_v<Points, soa_points<T>>;
    byte_range writes[4]{};
    int write_count = 0;
    if constexpr (soa_out) {
        const std::span<T> channel[4] = {out.r, out.g, out.b, out.a};
        constexpr const char* names[4] = {"out.r", "out.g", "out.b", "out.a"};
        for (int k = 0; k < channels; ++k) writes[write_count++] = {channel[k].data(), n * sizeof(T), names[k]};
    } else {
        writes[write_count++] = {out.data(), n * sizeof(typename Output::value_type), "the output"};
    }
    byte_range reads[16]{};
    int read_count = 0;
    int coordinate_reads = 0; // reads[0, coordinate_reads): SoA coordinates, which an output channel may equal
    if constexpr (soa_in) {
        const soa3<T>* vectors[3] = {&points.positions, &points.normals, &points.views};
        constexpr const char* names[9] = {".positions.x", ".positions.y", ".positions.z", ".normals.x", ".normals.y",
                                          ".normals.z",   ".views.x",     ".views.y",     ".views.z"};
        for (int a = 0; a < 3; ++a) {
            const std::span<const T> c[3] = {vectors[a]->x, vectors[a]->y, vectors[a]->z};
            for (int k = 0; k < 3; ++k) reads[read_count++] = {c[k].data(), std::min(n, c[k].size()) * sizeof(T), names[3 * a + k]};
        }
        coordinate_reads = read_count;
    } else {
        reads[read_count++] = {points.positions.data(), points.positions.size() * sizeof(glm::vec<3, T, Q>), ".positions"};
        reads[read_count++] = {points.normals.data(), points.normals.size() * sizeof(glm::vec<3, T, Q>), ".normals"};
        reads[read_count++] = {points.views.data(), points.views.size() * sizeof(glm::vec<3, T, Q>), ".views"};
    }
    for (const byte_range& m : material_reads(materials, n)) reads[read_count++] = m;
    reads[read_count++] = {points.front_facing.data(), points.front_facing.size() * sizeof(bool), ".front_facing"};
    reads[read_count++] = {points.light_masks.data(), points.light_masks.size() * sizeof(std::uint64_t), ".light_masks"};
    for (int w = 0; w < write_count; ++w) {
        for (int r = 0; r < read_count; ++r) {
            const bool in_place = soa_out && r < coordinate_reads && writes[w].p == reads[r].p && reads[r].bytes == writes[w].bytes;
            if (!in_place && bytes_overlap(writes[w].p, writes[w].bytes, reads[r].p, reads[r].bytes))
                return overlap_message(writes[w].name, reads[r].name, true, soa_out && r < coordinate_reads);
        }
        for (int other = 0; other < w; ++other)
            if (bytes_overlap(writes[w].p, writes[w].bytes, writes[other].p, writes[other].bytes))
                return overlap_message(writes[w].name, writes[other].name, false, false);
    }
    return nullptr;
}

/// A memory-safety precondition of shade_batch (span lengths, overlap): O(1), checked in every
/// build, NDEBUG included (as hardened standard libraries check std::span), through the
/// precondition handler (default: print the message and abort). Returns ok: when a handler
/// returns, shade_batch writes nothing.
inline bool memory_safe(bool ok, const char* message, const char* file = PHONG_DETAIL_CALLER_FILE,
                        int line = PHONG_DETAIL_CALLER_LINE) noexcept
{
#if !defined(__CUDA_ARCH__) // shade_batch is host code; nvcc's device pass still parses this body
    if (!ok) precondition_failed(message, file, line);
#else
    (void)message;
    (void)file;
    (void)line;
#endif
    return ok;
}

/// Number of vectors in an SoA or AoS input (SoA: the three spans' common length, or a length
/// no valid input has when they differ).
template <class T> std::size_t vec3_count(const soa3<T>& v)
{
    return v.y.size() == v.x.size() && v.z.size() == v.x.size() ? v.x.size() : std::size_t(-1);
}
template <class T, glm::qualifier Q> std::size_t vec3_count(std::span<const glm::vec<3, T, Q>> v) { return v.size(); }

/// "shade_batch: <span>[<index>]: <message>", formatted into a per-thread buffer: the message of
/// a failed precondition on one entry of a span names the entry (debug builds, on failure only;
/// valid until the thread's next call).
inline const char* entry_message(const char* span, std::size_t index, const char* message) noexcept
{
    thread_local char buffer[256];
    std::snprintf(buffer, sizeof buffer, "shade_batch: %s[%zu]: %s", span, index, message);
    return buffer;
}

/// shade_batch's preconditions, through the precondition handler. In every build: the span
/// lengths (each message naming the span) and the aliasing rule (naming both spans), O(1) checks
/// that keep memory safe; shade nothing when one fails (a handler that returns leads to no read or
/// write past a span). Debug builds only: valid materials, lights and environment, a span's entry
/// named by its index. Returns whether to shade: not after a failed memory check, nor, in every
/// build, with an empty material table (nothing to read).
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
bool check_batch_inputs(const Points& points, const Materials& materials, [[maybe_unused]] std::span<const light<T, Q>> lights,
                        const Output& out, [[maybe_unused]] const environment<T, Q>& env, std::size_t n)
{
    constexpr bool shared_material = std::is_same_v<Materials, material<T, Q>>;
    constexpr bool table = std::is_same_v<Materials, material_table<T, Q>>;
    std::size_t out_size = 0;
    if constexpr (std::is_same_v<Output, soa_rgba<T>>)
        out_size = std::min({out.r.size(), out.g.size(), out.b.size(), F.alpha ? out.a.size() : out.r.size()});
    else
        out_size = out.size();
    // n is no count when x, y and z differ: one report then.
    if (!memory_safe(vec3_count(points.positions) != std::size_t(-1), "shade_batch: .positions: x, y and z of different lengths")) return false;
    bool lengths_ok = memory_safe(vec3_count(points.normals) == n, "shade_batch: .normals: not one normal per point");
    lengths_ok = memory_safe(out_size >= n, "shade_batch: the output is shorter than the points (N entries per channel)") && lengths_ok;
    if constexpr (F.view == view_model::given)
        lengths_ok = memory_safe(vec3_count(points.views) == n, "shade_batch: view_model::given needs one view vector per point (.views)") && lengths_ok;
    else
        lengths_ok = memory_safe(vec3_count(points.views) == 0, "shade_batch: .views is read only with features::view = view_model::given") && lengths_ok;
    lengths_ok = memory_safe(points.front_facing.empty() || points.front_facing.size() == n, "shade_batch: front_facing length") && lengths_ok;
    lengths_ok = memory_safe(points.light_masks.empty() || points.light_masks.size() == n, "shade_batch: light_masks length") && lengths_ok;
    if constexpr (table) {
        lengths_ok = memory_safe(materials.ids.size() == n, "shade_batch: material_table needs one id per point (.ids)") && lengths_ok;
        // With no entry there is nothing to read (an id is clamped to the last entry).
        lengths_ok = memory_safe(n == 0 || !materials.materials.empty(), "shade_batch: material_table without materials") && lengths_ok;
    } else if constexpr (!shared_material) {
        lengths_ok = memory_safe(materials.size() == n, "shade_batch: one material per point") && lengths_ok;
    }
    if (!lengths_ok) return false;
    const char* overlap = output_overlap<F.alpha ? 4 : 3, T, Q>(points, materials, out, n);
    if (!memory_safe(overlap == nullptr, overlap)) return false;
#if !defined(NDEBUG)
    if constexpr (table) {
        for (std::size_t j = 0; j < materials.materials.size(); ++j) {
            const validation valid = validate(materials.materials[j]);
            PHONG_ASSERT(static_cast<bool>(valid), entry_message("material_table.materials", j, valid.message()));
        }
        for (std::size_t i = 0; i < n; ++i)
            PHONG_ASSERT(materials.ids[i] < materials.materials.size(), entry_message("material_table.ids", i, "a material id past the table"));
    } else if constexpr (!shared_material) {
        for (std::size_t i = 0; i < n; ++i) {
            const validation valid = validate(materials[i]);
            PHONG_ASSERT(static_cast<bool>(valid), entry_message("materials", i, valid.message()));
        }
    } else {
        PHONG_ASSERT(static_cast<bool>(validate(materials)), validate(materials).message());
    }
    for (std::size_t k = 0; k < lights.size(); ++k) {
        const validation valid = validate(lights[k]);
        PHONG_ASSERT(static_cast<bool>(valid), entry_message("lights", k, valid.message()));
    }
    PHONG_ASSERT(static_cast<bool>(validate(env)), validate(env).message());
#endif
    return true;
}

/// Whether one material can be folded into the lights: every product La_i ka, Ld_i kd, Ls_i ks is
/// 0 exactly (a zero factor) or a normal number. A product lost to underflow would drop a term
/// that f_i (up to the attenuation cap, ~1e38 in float) may scale back to a visible size (found by
/// tests/fuzz/fuzz_batch.cpp: kd 2e-19, Ld 1e-30, f 3e28); one that overflows would turn a
/// finite colour into inf.
template <class T, glm::qualifier Q>
bool foldable(const material<T, Q>& m, std::span<const light<T, Q>> lights)
{
    const auto fine = [](T a, T b) {
        const T p = a * b;
        return a == T(0) || b == T(0) || (std::abs(p) >= std::numeric_limits<T>::min() && std::abs(p) <= std::numeric_limits<T>::max());
    };
    for (const light<T, Q>& L : lights)
        for (int c = 0; c < 3; ++c)
            if (!fine(m.ka[c], L.ambient[c]) || !fine(m.kd[c], L.diffuse[c]) || !fine(m.ks[c], L.specular[c])) return false;
    return true;
}

/// The lights in lanes, splatted once per call; with one material for all points and fold, the
/// material folded into them (La_i ka, Ld_i kd, Ls_i ks: shade_lanes' folded_sums).
template <class V, class T, glm::qualifier Q, class Materials>
std::vector<light<V, Q>> lane_lights_of(std::span<const light<T, Q>> lights, const Materials& materials, [[maybe_unused]] bool fold)
{
    std::vector<light<V, Q>> lanes;
    lanes.reserve(lights.size());
    for (light<T, Q> L : lights) {
        if constexpr (std::is_same_v<Materials, material<T, Q>>)
            if (fold) L.ambient *= materials.ka, L.diffuse *= materials.kd, L.specular *= materials.ks;
        lanes.push_back(splat<V>(L));
    }
    return lanes;
}

/// The environment in lanes. With one material for all points, its ambient is the folded sums'
/// start (shade_lanes): emission + ka La, and + ka sum_i La_i where the lights' ambient terms are
/// hoisted (ambient_hoistable, no masks).
template <features F, class V, class T, glm::qualifier Q, class Materials>
environment<V, Q> lane_environment(const environment<T, Q>& env, const Materials& materials, std::span<const light<T, Q>> lights,
                                   [[maybe_unused]] bool masks, [[maybe_unused]] bool fold)
{
    environment<T, Q> e = env;
    if constexpr (std::is_same_v<Materials, material<T, Q>>) {
        if (!fold) return {splat<V>(e.ambient), splat<V>(e.eye)};
        glm::vec<3, T, Q> ambient(T(0));
        if constexpr (F.scene_ambient) ambient = env.ambient;
        if constexpr (ambient_hoistable<F>) {
            if (!masks) {
                glm::vec<3, T, Q> sum(T(0));
                for (const light<T, Q>& L : lights) sum += L.ambient;
                ambient = F.scene_ambient ? env.ambient + sum : sum;
            }
        }
        glm::vec<3, T, Q> start = materials.ka * ambient;
        if constexpr (F.emission) start = materials.emission + start;
        e.ambient = start;
    }
    return {splat<V>(e.ambient), splat<V>(e.eye)};
}

/// shade_batch over soa_points or aos_points: preconditions checked (debug builds), lights,
/// shared material (or a material table) and environment broadcast once, then
/// shade_points_steps per call_steps W points. Materials: material<T, Q> (one for all), a span of N
/// materials (one per point) or material_table<T, Q> (a table and N ids).
template <features F, class T, glm::qualifier Q, class Points, class Materials, class Output>
void shade_points_impl(const Points& points, const Materials& materials, std::span<const light<T, Q>> lights,
                       const Output& out, const environment<T, Q>& env)
{
    using V = simd_batch<T>;
    constexpr std::size_t W = batch_width<T>;
    const std::size_t n = vec3_count(points.positions);
    if (!check_batch_inputs<F>(points, materials, lights, out, env, n)) return;

    bool fold = false; // one material: folded into the lights where no product is lost
    if constexpr (std::is_same_v<Materials, material<T, Q>>) fold = foldable(materials, lights);
    const std::vector<light<V, Q>> lane_lights = lane_lights_of<V>(lights, materials, fold);
    const std::span<const light<V, Q>> lane_span(lane_lights);
    std::vector<light<double, Q>> wide_lights; // the lights in double, for stable_lanes_route
    if constexpr (stable_lanes_route<F, V>) {
        wide_lights.reserve(lights.size());
        for (const light<T, Q>& L : lights) wide_lights.push_back(splat<double>(L));
    }
    const std::span<const light<double, Q>> wide_span(wide_lights);
    const environment<V, Q> lane_env = lane_environment<F, V>(env, materials, lights, !points.light_masks.empty(), fold);
    const auto run = [&](const auto& material_lanes) {
        std::size_t i = 0;
        while (i + W <= n) {
            const std::size_t steps = std::min(call_steps<F, Points, Output, V, T, Q>, (n - i) / W);
            i += W * shade_points_steps<F, V, Points, T, Q>(i, steps, W, points, material_lanes, lane_span, wide_span, lane_env, out);
        }
        if (i < n) shade_points_steps<F, V, Points, T, Q>(i, 1, n - i, points, material_lanes, lane_span, wide_span, lane_env, out);
    };
    if constexpr (std::is_same_v<Materials, material<T, Q>>) {
        if (fold) run(shared_lanes<V, Q>{splat<V>(materials)});
        else run(unfolded_shared_lanes<V, Q>{splat<V>(materials)});
    } else if constexpr (std::is_same_v<Materials, material_table<T, Q>>) {
        table_lanes<V, T, Q> lanes{materials.materials, materials.ids, {}, {}};
        lanes.splatted.reserve(materials.materials.size());
        for (const material<T, Q>& m : materials.materials) lanes.splatted.push_back(splat<V>(m));
        lanes.make_columns();
        run(lanes);
    } else {
        run(per_point_lanes<V, T, Q>{materials});
    }
}

/// The soa3 overloads: shade_points_impl on soa_points without views or masks.
template <features F, class T, glm::qualifier Q, class Materials, class Output>
void shade_batch_impl(const soa3<T>& positions, const soa3<T>& normals, const Materials& materials,
                      std::span<const light<T, Q>> lights, const Output& out, const environment<T, Q>& env,
                      std::span<const bool> front_facing)
{
    static_assert(F.view != view_model::given,
                  "shade_batch: view_model::given needs a view vector per point: pass soa_points/aos_points with .views");
    shade_points_impl<F>(soa_points<T>{positions, normals, {}, front_facing, {}}, materials, lights, out, env);
}

} // namespace detail

/// Shades N points at once: out[i] = shade<F>(position[i], normal[i], mat, lights, env,
/// front_facing[i]) for every i. The kernels are shade<F>'s own templates (detail::prepare,
/// add_light, finish) run on simd_batch<T>, batch_width<T> points per step; a tail shorter than
/// the width goes through padded copies. Lights, material and environment are broadcast to the
/// lanes once per call.
///   positions, normals: structure of arrays (x, y, z spans of length N), as shade<F> takes them;
///   mat: one material for all points, or a span of N materials (one per point);
///   out: SoA channels (soa_rgba: r, g, b, and a when F.alpha), or a span of N interleaved
///        colours (std::span<color<F, T>>: glm::vec3, or glm::vec4 when F.alpha);
///   front_facing: N flags, read only for facing::flag; empty means all front-facing.
/// Per-point view vectors (view_model::given: a compile error here), per-point light masks and
/// AoS glm::vec3 inputs: the soa_points / aos_points overloads below.
/// Pre (checked through the precondition handler, detail/config.hpp; the span lengths and the
/// aliasing rule in every build, NDEBUG included, and nothing is shaded when one fails; the values
/// in debug builds): spans of length N (out may be longer; only its first N elements are
/// written); validate(material) and validate(L); no aliasing: the N output elements overlap
/// neither the inputs read per point (the N coordinates and views, the N materials when per point
/// or a table and its ids, front_facing, light masks) nor each other, except that
/// an SoA output channel may be exactly one of the coordinate spans (same data(), in-place
/// shading: each point is read before its colour is stored). An output shifted against an input
/// would otherwise overwrite points before they are read. Lights, a shared material and env are
/// copied before the first store and may alias anything.
/// Edges and NaN policy: those of shade<F>, point by point.
/// Lights: a span of light<T> (they go to SIMD lanes once per call). A renderer's own light type
/// (light_traits, light.hpp): convert the list once per call with to_light, not per point.
/// Accuracy: within the published bound of F.mode (phong/accuracy.hpp), tested against the
/// __float128 reference; against the scalar shade<F> the results differ by the SIMD rsqrt
/// estimate (< 2 ulp, float lanes) and the exp/log implementations, amplified by the exponent m in
/// exact mode (by about sqrt(m) in stable mode).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const material<T, Q>& mat,
                 std::span<const light<T, Q>> lights, const soa_rgba<T>& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, mat, lights, out, env, front_facing);
}

/// shade_batch with one material per point (materials.size() == N).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, std::span<const material<T, Q>> materials,
                 std::span<const light<T, Q>> lights, const soa_rgba<T>& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, materials, lights, out, env, front_facing);
}

/// shade_batch writing interleaved colours (rgb, or rgba when F.alpha), one material for all.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const material<T, Q>& mat,
                 std::span<const light<T, Q>> lights, std::span<color<F, T, Q>> out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, mat, lights, out, env, front_facing);
}

/// shade_batch writing interleaved colours, one material per point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, std::span<const material<T, Q>> materials,
                 std::span<const light<T, Q>> lights, std::span<color<F, T, Q>> out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    detail::shade_batch_impl<F>(positions, normals, materials, lights, out, env, front_facing);
}

/// Shades N points given as soa_points (or aos_points, below): for every i,
///   out[i] = shade<F>(p[i], n[i], [v[i],] mat, masked(lights, light_masks[i]), env, front_facing[i]),
/// with v[i] = points.views (view_model::given only: secondary rays each with their own view
/// vector), masked() only when light_masks is given (shadows: each point its own set of lights;
/// a light whose bit is clear gives that point nothing, its ambient term included, exactly as if
/// it were removed), front_facing only for facing::flag. Every other argument, the kernels,
/// edges, NaN policy and accuracy are those of the shade_batch overloads above; masks and views
/// change no other lane's result (but the stable mode picks its route per step from every lane:
/// the twofold route where any lane's shininess is above 2^20 on float lanes, and its depth with
/// features::stable_twofold_above > 0).
/// lights, materials and out are spans (a std::vector converts); N = the number of positions.
/// Pre (debug assertions): normals, and views with view_model::given, N long (views empty
/// otherwise); front_facing and light_masks empty or N long; out at least N long; per-point
/// materials N long; validate(material) and validate(L). Masks with more than 64 lights: lights
/// past the 64th are seen by no point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 const soa_rgba<T>& out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over soa_points, one material per point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points writing interleaved colours (glm::vec3, or vec4 when F.alpha).
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 std::type_identity_t<std::span<color<F, T, Q>>> out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over soa_points, one material per point, interleaved colours.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points (positions, normals and views as glm vectors): the same lanes as
/// the SoA overloads, so the same results bit for bit. Everything else as above.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 const soa_rgba<T>& out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over aos_points, one material per point.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points writing interleaved colours: hit records in, colours out.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material<T, Q>& mat, std::type_identity_t<std::span<const light<T, Q>>> lights,
                 std::type_identity_t<std::span<color<F, T, Q>>> out, const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, mat, lights, out, env);
}

/// shade_batch over aos_points, one material per point, interleaved colours.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, std::type_identity_t<std::span<const material<T, Q>>> materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points with a material table: point i takes materials.materials[
/// materials.ids[i]] (see material_table); the same bits as the per-point overload given those
/// materials. Everything else as above.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over soa_points with a material table, interleaved colours.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa_points<T>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points with a material table: a ray tracer's hit arrays (positions,
/// normals, views -ray.dir, shadow masks) and its material ids, as it keeps them.
///   shade_batch<F>(aos_points<float>{.positions = P, .normals = N, .views = V, .light_masks = visible},
///                  material_table<float>{.materials = scene_materials, .ids = hit_material}, lights, out, env);
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, const soa_rgba<T>& out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

/// shade_batch over aos_points with a material table, interleaved colours.
template <features F, class T, glm::qualifier Q>
void shade_batch(const aos_points<T, Q>& points, const material_table<T, Q>& materials,
                 std::type_identity_t<std::span<const light<T, Q>>> lights, std::type_identity_t<std::span<color<F, T, Q>>> out,
                 const environment<T, Q>& env = {})
{
    detail::shade_points_impl<F>(points, materials, lights, out, env);
}

} // namespace phong

#include "detail/fast_lanes.hpp" // fast::lanes for the batches (the fast mode's kernels)

#if defined(PHONG_BATCH_POP_DIAGNOSTICS)
#  pragma GCC diagnostic pop
#  undef PHONG_BATCH_POP_DIAGNOSTICS
#endif
#undef PHONG_BATCH_NOINLINE
#undef PHONG_BATCH_ALWAYS_INLINE
