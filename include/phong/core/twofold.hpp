// phong: twofold ("double-word") arithmetic for the stable mode: hi + lo, |lo| <~ eps |hi|, so unit
// vectors, n.l and the chords r - v, n - h are known to ~eps^2, removing the sqrt(m) eps error of
// the highlight (docs/accuracy.md). Branch-free and constexpr on a scalar-like T (SIMD batches too).
// Requirement: detail::fma must round once (a math_traits whose fma is a*b + c, as xsimd 8.1's
// generic one, zeroes every error term; emulate it with Dekker's product).
// SPDX-License-Identifier: MIT
#pragma once

#include "vector.hpp"

namespace phong::detail {

/// fl(a b), never contracted into a later addition (the error-free transformations need the
/// rounded product): fma(a, b, +0) where FMA instructions are on, else a * b.
template <class T> PHONG_INLINE constexpr T rounded_product(T a, T b)
{
#if defined(__FP_FAST_FMA) || defined(__FP_FAST_FMAF)
    return ieee::opaque(detail::fma(a, b, T(0)));
#else
    return ieee::opaque(a * b);
#endif
}

/// The twofold route's TwoSum, refused at compile time where the compiler may reassociate.
template <class T> PHONG_INLINE constexpr T twofold_sum_error(T a, T b, T hi)
{
    static_assert(ieee::twofold_allowed<T>,
                  "phong: the stable mode's twofold arithmetic (double, or features::precision = twofold) needs IEEE "
                  "additions, and -ffast-math (-fassociative-math) reorders them: build this translation unit with "
                  "-fno-associative-math (or -fno-fast-math), or use evaluation::exact or fast, or float's stable "
                  "mode with precision = wider");
    return two_sum_error(a, b, hi);
}

/// a - b = hi + lo exactly (TwoSum on a + (-b)); returns lo for hi = fl(a - b).
template <class T> PHONG_INLINE constexpr T difference_error(T a, T b, T hi)
{
    return twofold_sum_error(a, -b, hi);
}

/// A unit vector carried twofold: hi + lo = d / |d| with an error of a few eps^2 per component.
template <class T, glm::qualifier Q>
struct unit_twofold {
    glm::vec<3, T, Q> hi; ///< the unit vector rounded (0 when d = 0)
    glm::vec<3, T, Q> lo; ///< its rounding error
    T inv_scaled;         ///< 1 / |d * scale| (0 when d = 0): > 0 exactly when the direction exists
    T length;             ///< |d| rounded (inf only if |d| exceeds the range of T)
};

/// The unit vector along the exact d + dlo (dlo: d's rounding error, or 0): d rescaled by a power
/// of two, S = |d|^2 twofold, r ~ 1/sqrt(S), one Newton step on e = 1 - S r^2 (exact by Sterbenz):
/// d r + d r e/2 + dlo r, to O(eps^2). Edge: d = 0 gives 0 (length 0); an inf component gives 0,
/// inv_scaled = 0, length = inf, never NaN.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr unit_twofold<T, Q> unit_twofold_of(const glm::vec<3, T, Q>& d, const glm::vec<3, T, Q>& dlo)
{
    using vec3 = glm::vec<3, T, Q>;
    // Renormalize d + dlo first: where d cancels, dlo can be a sizeable fraction of d, and the
    // O(dlo^2) terms dropped below would then leave |hi + lo| off 1.
    vec3 dh(T(0)), dl(T(0));
    for (glm::length_t k = 0; k < 3; ++k) {
        dh[k] = d[k] + dlo[k];
        dl[k] = twofold_sum_error(d[k], dlo[k], dh[k]);
    }
    const T largest_d = detail::max_abs(dh);
    const mask_t<T> in_range = math_traits<T>::both(detail::max_abs(d) <= largest<T>(), largest_d <= largest<T>());
    const T scale = math_traits<T>::inverse_pow2_scale(detail::select(in_range, largest_d, T(1)));
    vec3 a(T(0)), al(T(0));
    for (glm::length_t k = 0; k < 3; ++k) {
        a[k] = detail::select(in_range, dh[k] * scale, T(0));
        al[k] = detail::select(in_range, dl[k] * scale, T(0)); // NaN when d overflowed
    }
    // S = |a + al|^2 = sh + sl (products exact by fma, sums by TwoSum; al^2 is below eps^2).
    T sh = rounded_product(a[0], a[0]);
    T sl = detail::fma(a[0], a[0], -sh) + T(2) * a[0] * al[0];
    for (glm::length_t k = 1; k < 3; ++k) {
        const T p = rounded_product(a[k], a[k]);
        const T pe = detail::fma(a[k], a[k], -p);
        const T s = sh + p;
        sl = sl + (twofold_sum_error(sh, p, s) + pe + T(2) * a[k] * al[k]);
        sh = s;
    }
    const T s_hi = sh + sl;
    sl = sl - (s_hi - sh);
    sh = s_hi;
    const mask_t<T> nonzero = sh > T(0);
    const T r = detail::select(nonzero, T(1) / detail::sqrt(detail::select(nonzero, sh, T(1))), T(0));
    // e = 1 - S r^2: r^2 = r2h + r2l exactly, sh r2h = th + tl exactly, 1 - th exact.
    const T r2h = rounded_product(r, r);
    const T r2l = detail::fma(r, r, -r2h);
    const T th = rounded_product(sh, r2h);
    const T tl = detail::fma(sh, r2h, -th);
    const T e = detail::select(nonzero, ((T(1) - th) - tl) - sh * r2l - sl * r2h, T(0));
    const T rl = r * e * T(0.5); // 1/|a| = r + rl + O(e^2)
    unit_twofold<T, Q> u{vec3(T(0)), vec3(T(0)), r, T(0)};
    for (glm::length_t k = 0; k < 3; ++k) {
        u.hi[k] = rounded_product(a[k], r);
        u.lo[k] = detail::fma(a[k], r, -u.hi[k]) + (a[k] * rl + al[k] * r);
    }
    u.length = detail::select(in_range, detail::sqrt(sh) / scale, T(std::numeric_limits<scalar_t<T>>::infinity()));
    return u;
}

/// (ah + al) . (bh + bl) as a twofold value, returned rounded in hi and its error in lo:
/// Dot2 on the high parts (exact products, TwoSum accumulation) plus the first-order cross terms.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr void dot_twofold(const glm::vec<3, T, Q>& ah, const glm::vec<3, T, Q>& al, const glm::vec<3, T, Q>& bh,
                                    const glm::vec<3, T, Q>& bl, T& hi, T& lo)
{
    T p = rounded_product(ah[0], bh[0]);
    T err = detail::fma(ah[0], bh[0], -p) + (ah[0] * bl[0] + al[0] * bh[0]);
    for (glm::length_t k = 1; k < 3; ++k) {
        const T h = rounded_product(ah[k], bh[k]);
        const T r = detail::fma(ah[k], bh[k], -h);
        const T s = p + h;
        err = err + (twofold_sum_error(p, h, s) + r + (ah[k] * bl[k] + al[k] * bh[k]));
        p = s;
    }
    hi = p + err;
    lo = err - (hi - p);
}

/// A specular cosine c as x = 1 - c and as c, each rounded once from the same twofold value: x
/// accurate near the highlight, c where small (1 - x would give c an absolute error of eps / 2).
template <class T>
struct cosine_complement {
    T complement; ///< x = 1 - c = |chord|^2 / 2, rounded once
    T cosine;     ///< c, rounded once where x >= 1/2 (there 1 - x is exact); elsewhere within eps of it
};

/// |c + c_lo|^2 / 2 and 1 minus it, each rounded once ((1 - x) exact for x in [1/2, 2]: Sterbenz).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr cosine_complement<T> half_square(const glm::vec<3, T, Q>& c, const glm::vec<3, T, Q>& c_lo)
{
    T hi = rounded_product(c[0], c[0]);
    T lo = detail::fma(c[0], c[0], -hi) + T(2) * c[0] * c_lo[0];
    for (glm::length_t k = 1; k < 3; ++k) {
        const T p = rounded_product(c[k], c[k]);
        const T s = hi + p;
        lo = lo + (twofold_sum_error(hi, p, s) + detail::fma(c[k], c[k], -p) + T(2) * c[k] * c_lo[k]);
        hi = s;
    }
    const T sum = hi + lo;
    const T sum_lo = lo - (sum - hi);
    const T x = sum * T(0.5), x_lo = sum_lo * T(0.5);
    return {x, (T(1) - x) - x_lo};
}

/// 1 - r.v = |r - v|^2 / 2 and r.v for r = 2 (n.l) n - l, from twofold n, l, v and n.l: about
/// 1 eps relative however close r is to v. Pre: n, l, v unit (or 0).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr cosine_complement<T> one_minus_rv(const glm::vec<3, T, Q>& nh, const glm::vec<3, T, Q>& nlo, T nl_hi,
                                                    T nl_lo, const glm::vec<3, T, Q>& lh, const glm::vec<3, T, Q>& llo,
                                                    const glm::vec<3, T, Q>& vh, const glm::vec<3, T, Q>& vlo)
{
    glm::vec<3, T, Q> c(T(0)), c_lo(T(0)); // initialized: constant evaluation needs an active union member
    for (glm::length_t k = 0; k < 3; ++k) {
        const T q = rounded_product(nl_hi, nh[k]); // (n.l) n_k; 2 q + pe exact below
        const T ph = T(2) * q;
        const T pe = T(2) * (detail::fma(nl_hi, nh[k], -q) + (nl_hi * nlo[k] + nl_lo * nh[k]));
        const T s1 = ph - lh[k];
        const T e1 = twofold_sum_error(ph, -lh[k], s1);
        const T s2 = s1 - vh[k];
        const T e2 = twofold_sum_error(s1, -vh[k], s2);
        c[k] = s2 + (((e1 + e2) + pe) - (llo[k] + vlo[k]));
        c_lo[k] = (((e1 + e2) + pe) - (llo[k] + vlo[k])) - (c[k] - s2);
    }
    return half_square(c, c_lo);
}

/// 1 - n.h = |n - h|^2 / 2 and n.h for twofold unit n and h (chord and square to O(eps^2), each
/// rounded once).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr cosine_complement<T> one_minus_nh(const glm::vec<3, T, Q>& nh, const glm::vec<3, T, Q>& nlo,
                                                    const glm::vec<3, T, Q>& hh, const glm::vec<3, T, Q>& hlo)
{
    glm::vec<3, T, Q> c(T(0)), c_lo(T(0)); // initialized: constant evaluation needs an active union member
    for (glm::length_t k = 0; k < 3; ++k) {
        const T s = nh[k] - hh[k];
        const T lo = twofold_sum_error(nh[k], -hh[k], s) + (nlo[k] - hlo[k]);
        c[k] = s + lo;
        c_lo[k] = lo - (c[k] - s);
    }
    return half_square(c, c_lo);
}

/// 1 - n.h for h = normalize(l + v), from twofold n, l and v. Pre: n, l, v unit (or 0).
/// Edge: l = -v (no halfway vector) gives 1 and n.h = 0.
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr cosine_complement<T> one_minus_halfway(const glm::vec<3, T, Q>& nh, const glm::vec<3, T, Q>& nlo,
                                                         const glm::vec<3, T, Q>& lh, const glm::vec<3, T, Q>& llo,
                                                         const glm::vec<3, T, Q>& vh, const glm::vec<3, T, Q>& vlo)
{
    glm::vec<3, T, Q> sum(T(0)), sum_lo(T(0));
    for (glm::length_t k = 0; k < 3; ++k) {
        sum[k] = lh[k] + vh[k];
        sum_lo[k] = twofold_sum_error(lh[k], vh[k], sum[k]) + (llo[k] + vlo[k]);
        // Renormalized: where l and v cancel, lo could exceed hi and overflow in unit_twofold_of.
        const T t = sum[k] + sum_lo[k];
        sum_lo[k] = twofold_sum_error(sum[k], sum_lo[k], t);
        sum[k] = t;
    }
    const unit_twofold<T, Q> h = unit_twofold_of(sum, sum_lo);
    const cosine_complement<T> x = one_minus_nh(nh, nlo, h.hi, h.lo);
    const mask_t<T> exists = h.inv_scaled > T(0);
    return {detail::select(exists, x.complement, T(1)), detail::select(exists, x.cosine, T(0))};
}

} // namespace phong::detail
