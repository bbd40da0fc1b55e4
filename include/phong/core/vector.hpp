// phong: constexpr vector kernels on glm::vec<L, T, Q>: dot, length, normalize, reflect.
// SPDX-License-Identifier: MIT
//
// GLM 0.9.9.8's dot/length/normalize/reflect are not usable in constant evaluation, and its
// normalize overflows for |v|^2 > max and returns NaN for v = 0. These are constexpr, work for
// any qualifier and any number type with math_traits (float, double, long double, SIMD).
#pragma once

#include "math.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <limits>
#include <type_traits>

namespace phong {
namespace detail {

/// In constant evaluation, for float and double finite inputs: the value dot(a, b) takes at run
/// time when a product or a partial sum (in index order, as dot sums) rounds to +-inf in T (+-inf,
/// or NaN for inf - inf), else 0. g++ rejects a finite operation whose result overflows as not a
/// constant expression, and clang inf - inf; dot returns this value instead. Evaluated in long
/// double, whose range and precision hold every such product and the overflow threshold (the
/// largest T plus half its ulp: from there on, round to nearest gives inf).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T constant_dot_overflow(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b)
{
#if defined(__CUDA_ARCH__) // no long double in device code: constant evaluation happens on the host
    (void)a;
    (void)b;
    return T(0);
#else
    using W = long double;
    constexpr W max = std::numeric_limits<T>::max(), eps = std::numeric_limits<T>::epsilon();
    constexpr W threshold = max + max / (W(2) - eps) * eps / 2; // max = (2 - eps) 2^(e-1), ulp = eps 2^(e-1)
    const auto rounded = [](W x) { // x rounded to T, an overflow as +-1 (the sign of the inf)
        return x >= threshold ? W(1) : x <= -threshold ? W(-1) : W(0);
    };
    W sum = 0, sum_inf = 0; // the partial sum, finite (in T's values), or its inf's sign
    for (glm::length_t k = 0; k < L; ++k) {
        if (!(a[k] == a[k]) || !(b[k] == b[k])) return T(0); // NaN: propagates on the normal path
        const W p = W(a[k]) * W(b[k]);
        const W p_inf = rounded(p);
        if (sum_inf != 0 && p_inf != 0 && sum_inf != p_inf) return std::numeric_limits<T>::quiet_NaN(); // inf - inf
        if (sum_inf != 0 || p_inf != 0) {
            sum_inf = sum_inf != 0 ? sum_inf : p_inf;
            continue;
        }
        const W s = k == 0 ? W(T(p)) : sum + W(T(p)); // rounded to T at each step, as at run time
        sum_inf = rounded(s);
        if (sum_inf == 0) sum = W(T(s));
    }
    return sum_inf > 0 ? std::numeric_limits<T>::infinity() : sum_inf < 0 ? -std::numeric_limits<T>::infinity() : T(0);
#endif
}

/// Dot product: dot(a, b) = sum_k a_k b_k, summed in index order (GLSL `dot`).
/// Edge: overflows to inf when a product exceeds the range of T (in constant evaluation too);
/// NaN propagates.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T dot(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>)
        if (std::is_constant_evaluated())
            if (const T overflow = detail::constant_dot_overflow(a, b); overflow != T(0)) return overflow;
    // Named components, not v[k] in a loop from k = 1: GLM's operator[] is a switch, and g++ 12
    // drops the probability of the case it prunes (k = 0), so every loop around a dot product is
    // then laid out as cold code (docs/design.md).
    T sum = a.x * b.x;
    if constexpr (L > 1) sum += a.y * b.y;
    if constexpr (L > 2) sum += a.z * b.z;
    if constexpr (L > 3) sum += a.w * b.w;
    return sum;
}

/// Compensated dot product (Ogita, Rump and Oishi's Dot2): the result is as accurate as if
/// computed in twice the working precision, then rounded: |error| <= eps |dot| + L^2 eps^2
/// sum |a_k b_k|. Used where cancellation matters (n.l near grazing incidence).
/// Pre: every product a_k b_k finite (an overflowing one gives NaN, where dot gives inf).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T dot_compensated(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b)
{
    T p = a[0] * b[0];
    T err = detail::fma(a[0], b[0], -p);
    for (glm::length_t k = 1; k < L; ++k) {
        const T h = a[k] * b[k];
        const T r = detail::fma(a[k], b[k], -h);
        const T s = p + h;
        const T q = detail::two_sum_error(p, h, s); // p + h = s + q exactly
        p = s;
        err += q + r;
    }
    return p + err;
}

/// max_k |v_k|. Edge: NaN components may or may not be returned (comparison order).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T max_abs(const glm::vec<L, T, Q>& v)
{
    T m = detail::abs(v.x); // named components: see dot
    if constexpr (L > 1) m = detail::max(m, detail::abs(v.y));
    if constexpr (L > 2) m = detail::max(m, detail::abs(v.z));
    if constexpr (L > 3) m = detail::max(m, detail::abs(v.w));
    return m;
}

/// v * 2^-e, an exact power-of-two rescaling that brings the largest component into [1, 2):
/// the direction is kept bit for bit and squares of the result neither overflow nor underflow.
/// Edge: the zero vector stays zero; NaN or inf components stay NaN or inf (the rest is scaled).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> rescaled(const glm::vec<L, T, Q>& v)
{
    return v * math_traits<T>::inverse_pow2_scale(detail::max_abs(v));
}

/// Euclidean length |v| = sqrt(dot(v, v)), computed on the rescaled vector so that it is
/// accurate (< 2 ulp) over the whole finite range: huge components do not overflow, tiny and
/// subnormal ones do not underflow. Edge: length(0) = 0; the result is inf only when the true
/// length exceeds the largest finite T (or a component is inf); a NaN component gives NaN.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T length(const glm::vec<L, T, Q>& v)
{
    const T s = math_traits<T>::inverse_pow2_scale(detail::max_abs(v));
    const glm::vec<L, T, Q> w = v * s;
    return detail::sqrt(detail::dot(w, w)) / s;
}

/// Unit vector along v: v / |v|. Scaled first (see `rescaled`), so every finite nonzero v gives
/// a unit vector (error < 2 eps per component, i.e. < 3 ulp of the component; tests/vector.test.cpp), including |v| ~ 1e-40 or 1e30 in float.
/// Edge: normalize(0) = 0 (zero in, zero out; GLM gives NaN). A NaN component stays NaN, the
/// others become 0 (the NaN length takes the zero branch); an inf component gives NaN there.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> normalize(const glm::vec<L, T, Q>& v)
{
    const glm::vec<L, T, Q> w = detail::rescaled(v);
    const T dd = detail::dot(w, w);
    return w * detail::select(dd > T(0), detail::rsqrt(dd), T(0));
}

/// v / |v| without rescaling: the fastest form, as GLSL writes it, guarded for zero only.
/// Pre: |v|^2 representable (about 1e-19 < |v| < 1e19 in float). Edge: normalize_unscaled(0) = 0;
/// when |v|^2 overflows the result is 0, when it underflows to 0 the result is 0 (never NaN).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> normalize_unscaled(const glm::vec<L, T, Q>& v)
{
    const T dd = detail::dot(v, v);
    return v * detail::select(dd > T(0), detail::rsqrt(dd), T(0));
}


/// The exact mode's threshold on a squared length: the smallest normal number of T. Below it
/// |v|^2 has lost bits to underflow and v / |v| would not be a unit vector (a light 1e-22 from Q
/// in float gave n.l and r.v off by factors), so such a vector counts as zero: its terms give 0
/// (a relative error of at most 1), never garbage or NaN.
template <class T> PHONG_INLINE constexpr T exact_min_square() { return T(std::numeric_limits<scalar_t<T>>::min()); }

/// dd is a positive normal number (exact_min_square <= dd <= largest): the exact mode's test of a
/// squared length (SIMD lanes: math_traits' positive_normal where it has one, e.g. one vfpclass).
template <class T>
PHONG_INLINE constexpr mask_t<T> normal_square(T dd)
{
    if constexpr (requires { math_traits<T>::positive_normal(dd); }) return math_traits<T>::positive_normal(dd);
    else return math_traits<T>::both(dd >= exact_min_square<T>(), dd <= largest<T>());
}

/// on && normal_square(dd).
template <class T>
PHONG_INLINE constexpr mask_t<T> both_normal_square(mask_t<T> on, T dd)
{
    if constexpr (requires { math_traits<T>::both_positive_normal(on, dd); }) return math_traits<T>::both_positive_normal(on, dd);
    else return math_traits<T>::both(on, normal_square(dd));
}

/// The exact mode's 1/|v| from dd = |v|^2: 0 when dd is not a normal number (rsqrt(inf) = 0 too).
template <class T>
PHONG_INLINE constexpr T exact_inverse_length(T dd)
{
    if constexpr (std::is_floating_point_v<T>) {
        if (dd >= exact_min_square<T>()) [[likely]] return detail::rsqrt(dd);
        return T(0);
    } else {
        return detail::select(normal_square(dd), detail::rsqrt_normal(dd), T(0));
    }
}




/// Cross product a x b = (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x) (GLM's is
/// constexpr-unfriendly in some configurations). Edge: a zero vector gives 0, parallel ones 0 up
/// to rounding; products beyond T's range give inf (or NaN from inf - inf).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> cross(const glm::vec<3, T, Q>& a, const glm::vec<3, T, Q>& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

} // namespace detail

/// GLSL reflect: reflect(i, n) = i - 2 dot(n, i) n, the mirror image of the incident direction
/// i about the plane with unit normal n. Pre: n unit length (else the result is not a mirror
/// image). It keeps |i| and is an involution (up to rounding) for unit n. Edge: n = 0 returns i.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> reflect(const glm::vec<L, T, Q>& i, const glm::vec<L, T, Q>& n)
{
    return i - n * (T(2) * detail::dot(n, i));
}

/// GLSL faceforward: faceforward(n, i, nref) = dot(nref, i) < 0 ? n : -n.
/// Edge: dot(nref, i) = 0 or NaN gives -n (as GLSL).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> faceforward(const glm::vec<L, T, Q>& n, const glm::vec<L, T, Q>& i,
                                                 const glm::vec<L, T, Q>& nref)
{
    const T sign = detail::select(detail::dot(nref, i) < T(0), T(1), T(-1));
    return n * sign;
}

} // namespace phong
