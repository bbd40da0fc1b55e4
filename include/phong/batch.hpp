// phong: batch shading. The same templates as the scalar path (detail::prepare, add_light, finish
// in shade.hpp), instantiated on a SIMD batch type, over structure-of-arrays spans of points.
// SPDX-License-Identifier: MIT
//
// SIMD layer: xsimd (Debian libxsimd-dev, header-only) when it is available, else a plain scalar
// loop over the same kernel. Why xsimd and not std::experimental::simd: the kernel needs
// vectorized exp and log1p (the specular power), and libstdc++ 12's <experimental/simd> computes
// those with a scalar loop per lane; measured with this kernel, see README "Batch shading".
// Define PHONG_NO_XSIMD to force the scalar fallback.
#pragma once

#include "shade.hpp"

#include <cstddef>
#include <span>
#include <vector>

#if !defined(PHONG_NO_XSIMD) && !defined(__CUDACC__) && __has_include(<xsimd/xsimd.hpp>)
#  include <xsimd/xsimd.hpp>
#  define PHONG_HAS_XSIMD 1
// g++ 12 reports the _mm512_undefined_* placeholders inside its own AVX-512 intrinsics (which
// xsimd calls) as uninitialized once they are inlined here; they are not, by design.
#  if defined(__GNUC__) && !defined(__clang__)
#    pragma GCC diagnostic push
#    pragma GCC diagnostic ignored "-Wuninitialized"
#    pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#    define PHONG_BATCH_POP_DIAGNOSTICS 1
#  endif
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
/// xsimd's (vectorized, within a few ulp; faster than the cephes-style kernels we measured
/// against them); float rsqrt is the hardware estimate refined by one Newton step. pow is
/// exp(y log x) restricted to x >= 0 with IEEE's pow(0, 0) = 1 (xsimd's own pow returns 0 there).
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
    PHONG_LANES_INLINE static V exp(const V& x) { return xsimd::exp(x); }
    PHONG_LANES_INLINE static V log(const V& x) { return xsimd::log(x); }
    PHONG_LANES_INLINE static V log1p(const V& x) { return xsimd::log1p(x); }
    /// x^y for x >= 0 (the lighting model's domain): exp(y log x), pow(0, 0) = 1, pow(0, y > 0) = 0.
    PHONG_LANES_INLINE static V pow(const V& x, const V& y)
    {
        const V p = exp(y * log(xsimd::select(x > V(T(0)), x, V(T(1)))));
        return xsimd::select(x > V(T(0)), p, xsimd::select(y == V(T(0)), V(T(1)), V(T(0))));
    }
    static V fma(const V& a, const V& b, const V& c) { return xsimd::fma(a, b, c); }
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
    static V newton_rsqrt(const V& x, const V& estimate)
    {
        const V refined = estimate * xsimd::fma(V(T(-0.5)) * x, estimate * estimate, V(T(1.5)));
        const auto finite_nonzero = (estimate > V(T(0))) && (estimate < V(std::numeric_limits<T>::infinity()));
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

/// Shades lanes [i, i + width) of the input: loads, runs the scalar templates on V, stores.
template <features F, class V, class T, glm::qualifier Q>
void shade_lanes(const T* px, const T* py, const T* pz, const T* nx, const T* ny, const T* nz, const bool* front,
                 const material<V, Q>& mat, std::span<const light<V, Q>> lights, const environment<V, Q>& env,
                 T* r, T* g, T* b, T* a)
{
    constexpr std::size_t W = sizeof(V) / sizeof(T);
    const glm::vec<3, V, Q> position(load<V>(px), load<V>(py), load<V>(pz));
    const glm::vec<3, V, Q> normal(load<V>(nx), load<V>(ny), load<V>(nz));
    mask_t<V> front_facing(true);
    if constexpr (F.two_sided == facing::flag) {
        if (front != nullptr) {
            alignas(64) T lanes[W];
            for (std::size_t k = 0; k < W; ++k) lanes[k] = front[k] ? T(1) : T(0);
            front_facing = load<V>(lanes) > V(0);
        }
    }
    const surface_frame<V, Q> s = prepare<F>(position, normal, env, front_facing);
    light_sums<V, Q> sums{};
    for (const light<V, Q>& L : lights) add_light<F>(sums, s, L, mat.shininess);
    const auto c = finish<F>(sums, s, mat, env);
    store(c.x, r);
    store(c.y, g);
    store(c.z, b);
    if constexpr (F.alpha) store(c.w, a);
}

} // namespace detail

/// Shades N points at once: out[i] = shade<F>(position[i], normal[i], mat, lights, env,
/// front_facing[i]) for every i, written to the SoA channels out.r, out.g, out.b (and out.a when
/// F.alpha). The kernels are shade<F>'s own templates run on simd_batch<T> (batch_width<T> points
/// per step); a tail shorter than the width is shaded through a padded copy. Results agree with
/// the scalar shade<F> within the published bound of F.mode (phong/accuracy.hpp; SIMD exp/log1p
/// and the compiler's contraction of a*b+c differ by a few ulp).
/// Pre: every span has the same length N (front_facing: N or empty = all front-facing; read only
/// for facing::flag); validate(mat) and validate(L) for every light (debug assertion).
/// Edges and NaN policy: as shade<F>, point by point.
template <features F, class T, glm::qualifier Q = glm::defaultp>
void shade_batch(const soa3<T>& positions, const soa3<T>& normals, const material<T, Q>& mat,
                 std::span<const light<T, Q>> lights, const soa_rgba<T>& out, const environment<T, Q>& env = {},
                 std::span<const bool> front_facing = {})
{
    using V = simd_batch<T>;
    constexpr std::size_t W = batch_width<T>;
    const std::size_t n = positions.x.size();
    PHONG_ASSERT(positions.y.size() == n && positions.z.size() == n && normals.x.size() == n &&
                     normals.y.size() == n && normals.z.size() == n && out.r.size() >= n && out.g.size() >= n &&
                     out.b.size() >= n && (!F.alpha || out.a.size() >= n),
                 "shade_batch: spans of different lengths");
    PHONG_ASSERT(front_facing.empty() || front_facing.size() == n, "shade_batch: front_facing length");
    PHONG_ASSERT(static_cast<bool>(validate(mat)), validate(mat).message());
    for ([[maybe_unused]] const light<T, Q>& L : lights) PHONG_ASSERT(static_cast<bool>(validate(L)), validate(L).message());

    // Lights, material and environment are the same for every lane: broadcast them once per call.
    std::vector<light<V, Q>> lanes_lights;
    lanes_lights.reserve(lights.size());
    for (const light<T, Q>& L : lights) lanes_lights.push_back(detail::splat<V>(L));
    const material<V, Q> lanes_mat = detail::splat<V>(mat);
    const environment<V, Q> lanes_env{detail::splat<V>(env.ambient), detail::splat<V>(env.eye)};
    const bool* front = front_facing.empty() ? nullptr : front_facing.data();
    T* const a = F.alpha ? out.a.data() : nullptr;

    std::size_t i = 0;
    for (; i + W <= n; i += W)
        detail::shade_lanes<F>(positions.x.data() + i, positions.y.data() + i, positions.z.data() + i,
                               normals.x.data() + i, normals.y.data() + i, normals.z.data() + i,
                               front ? front + i : nullptr, lanes_mat, std::span<const light<V, Q>>(lanes_lights),
                               lanes_env, out.r.data() + i, out.g.data() + i, out.b.data() + i, a ? a + i : nullptr);
    if (i < n) {
        // Tail: copy into full-width buffers padded with a harmless point (Q = (0, 0, -1) facing the eye).
        alignas(64) T buf[10][W];
        bool front_buf[W];
        for (std::size_t k = 0; k < W; ++k) {
            const bool real = i + k < n;
            buf[0][k] = real ? positions.x[i + k] : T(0);
            buf[1][k] = real ? positions.y[i + k] : T(0);
            buf[2][k] = real ? positions.z[i + k] : T(-1);
            buf[3][k] = real ? normals.x[i + k] : T(0);
            buf[4][k] = real ? normals.y[i + k] : T(0);
            buf[5][k] = real ? normals.z[i + k] : T(1);
            front_buf[k] = real && front ? front[i + k] : true;
        }
        detail::shade_lanes<F>(buf[0], buf[1], buf[2], buf[3], buf[4], buf[5], front_buf, lanes_mat,
                               std::span<const light<V, Q>>(lanes_lights), lanes_env, buf[6], buf[7], buf[8], buf[9]);
        for (std::size_t k = 0; i + k < n; ++k) {
            out.r[i + k] = buf[6][k];
            out.g[i + k] = buf[7][k];
            out.b[i + k] = buf[8][k];
            if constexpr (F.alpha) out.a[i + k] = buf[9][k];
        }
    }
}

} // namespace phong

#if defined(PHONG_BATCH_POP_DIAGNOSTICS)
#  pragma GCC diagnostic pop
#  undef PHONG_BATCH_POP_DIAGNOSTICS
#endif
