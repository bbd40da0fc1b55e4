// phong: constexpr vector kernels on glm::vec<L, T, Q> (dot, length, normalize, reflect), for any
// qualifier and any T with math_traits; unlike GLM's, safe for v = 0 and huge or tiny v.
// SPDX-License-Identifier: MIT
#pragma once

#include "math.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <limits>
#include <type_traits>

#include "diagnostics_push.hpp"

namespace phong {
namespace detail {

/// Constant evaluation only: the +-inf (or NaN) dot(a, b) gives at run time where a product or
/// partial sum overflows T, else 0 (compilers reject the overflow itself); in long double.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T constant_dot_overflow(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b)
{
#if defined(__CUDA_ARCH__) // no long double in device code: constant evaluation happens on the host
    (void)a;
    (void)b;
    return T(0);
#else
    using W = long double;
    constexpr W max = W(std::numeric_limits<T>::max()), eps = W(std::numeric_limits<T>::epsilon());
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

/// dot(a, b) = sum_k a_k b_k in index order (GLSL `dot`). Edge: overflow gives inf; NaN propagates.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T dot(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b)
{
    if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>)
        if (PHONG_DETAIL_CONSTANT_EVALUATED())
            if (const T overflow = detail::constant_dot_overflow(a, b); overflow != T(0)) return overflow;
    // Named components, not v[k]: GLM's operator[] is a switch that misleads g++'s block layout.
    T sum = a.x * b.x;
    if constexpr (std::is_floating_point_v<T>) {
        if constexpr (L > 1) sum += a.y * b.y;
        if constexpr (L > 2) sum += a.z * b.z;
        if constexpr (L > 3) sum += a.w * b.w;
    } else { // lanes: each further product fused into the sum where the target has fma, in this order
             // whatever loop inlines it (a compiler's own contraction picks the product by operand order)
        if constexpr (L > 1) sum = math_traits<T>::madd(a.y, b.y, sum);
        if constexpr (L > 2) sum = math_traits<T>::madd(a.z, b.z, sum);
        if constexpr (L > 3) sum = math_traits<T>::madd(a.w, b.w, sum);
    }
    return sum;
}

/// Compensated dot product (Ogita-Rump-Oishi Dot2): |error| <= eps |dot| + L^2 eps^2 sum |a_k b_k|.
/// Pre: every product finite (an overflowing one gives NaN).
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

/// v * 2^-e, exact, the largest component in [1, 2): squares neither overflow nor underflow.
/// Edge: zero stays zero; NaN or inf components stay NaN or inf.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> rescaled(const glm::vec<L, T, Q>& v)
{
    return v * math_traits<T>::inverse_pow2_scale(detail::max_abs(v));
}

/// |v| = sqrt(dot(v, v)) on the rescaled vector: < 2 ulp over the whole finite range.
/// Edge: length(0) = 0; inf only when |v| exceeds T's range or a component is inf; NaN gives NaN.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr T length(const glm::vec<L, T, Q>& v)
{
    const T s = math_traits<T>::inverse_pow2_scale(detail::max_abs(v));
    const glm::vec<L, T, Q> w = v * s;
    return detail::sqrt(detail::dot(w, w)) / s;
}

/// v / |v|, rescaled first: a unit vector (< 2 eps per component) for every finite nonzero v.
/// Edge: normalize(0) = 0; a NaN component stays NaN, the others 0; an inf component gives NaN.
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> normalize(const glm::vec<L, T, Q>& v)
{
    const glm::vec<L, T, Q> w = detail::rescaled(v);
    const T dd = detail::dot(w, w);
    return w * detail::select(dd > T(0), detail::rsqrt(dd), T(0));
}

/// v / |v| without rescaling (GLSL's form). Pre: |v|^2 representable. Edge: 0 for v = 0 and where
/// |v|^2 overflows or underflows to 0 (never NaN).
template <glm::length_t L, class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<L, T, Q> normalize_unscaled(const glm::vec<L, T, Q>& v)
{
    const T dd = detail::dot(v, v);
    return v * detail::select(dd > T(0), detail::rsqrt(dd), T(0));
}


/// The exact mode's threshold on a squared length, T's smallest normal: below it v / |v| is not a
/// unit vector, so such a vector counts as zero (its terms give 0, never garbage or NaN).
template <class T> PHONG_INLINE constexpr T exact_min_square() { return T(std::numeric_limits<scalar_t<T>>::min()); }

/// dd is a positive normal number: the exact mode's test of a squared length.
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




/// a x b = (a.y b.z - a.z b.y, a.z b.x - a.x b.z, a.x b.y - a.y b.x). Edge: zero or parallel
/// vectors give 0 (up to rounding); overflow gives inf (or NaN from inf - inf).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> cross(const glm::vec<3, T, Q>& a, const glm::vec<3, T, Q>& b)
{
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

} // namespace detail

/// GLSL reflect(i, n) = i - 2 dot(n, i) n, i mirrored about the plane of unit normal n (keeps
/// |i|). Pre: n unit length. Edge: n = 0 returns i.
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
#include "diagnostics_pop.hpp"
