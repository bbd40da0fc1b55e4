// Test support: per-type tolerances, a sign-aware ULP distance, errors against the wide reference,
// and approximate comparison of GLM vectors.
#pragma once

#include "wide.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace phong_test {

/// Tolerances per type: a relative tolerance of `ulps` units of epsilon<T>.
template <class T> struct tolerance {
    static constexpr T eps = std::numeric_limits<T>::epsilon();
    static constexpr T rel(int ulps) { return eps * T(ulps); }
};

/// x finite, by its bits: std::isfinite is folded to true under -ffinite-math-only (the
/// -ffast-math builds of .ci/steps/36-fast-math.sh).
template <class T> bool finite_bits(T x)
{
    using U = std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>;
    const U exponent = sizeof(T) == 4 ? U(0x7f800000u) : U(0x7ff0000000000000ull);
    return (std::bit_cast<U>(x) & exponent) != exponent;
}

/// Maps a float/double to an integer whose order is the order of the values (-0 and +0 both 0),
/// so the difference of two mapped values is their distance in ulp, also across zero (GLM's
/// floatDistance breaks there).
template <class T> std::int64_t ordered_bits(T x)
{
    using bits_t = std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>;
    const bits_t b = std::bit_cast<bits_t>(x);
    return b < 0 ? -std::int64_t(b & std::numeric_limits<bits_t>::max()) : std::int64_t(b);
}

/// Sign-aware distance in ulp between two finite values of T (NaN gives max).
template <class T> std::uint64_t ulp_distance(T a, T b)
{
    if (std::isnan(a) || std::isnan(b)) return std::numeric_limits<std::uint64_t>::max();
    const std::int64_t d = ordered_bits(a) - ordered_bits(b);
    return std::uint64_t(d < 0 ? -d : d);
}

/// The spacing of T at the magnitude of r (ulp(r)); for r = 0 the smallest subnormal.
template <class T> wide ulp_of(wide r)
{
    const T t = T(wabs(r));
    if (t == 0) return wide(std::numeric_limits<T>::denorm_min());
    const T up = std::nextafter(t, std::numeric_limits<T>::infinity());
    return wide(up) - wide(t);
}

/// Error of a computed T against the wide reference, in ulp of the reference's magnitude in T
/// (fractional; 0.5 is a correctly rounded result). NaN/inf computed gives +inf.
template <class T> double error_ulp(T computed, wide reference)
{
    if (!std::isfinite(computed)) return std::numeric_limits<double>::infinity();
    return double(wabs(wide(computed) - reference) / ulp_of<T>(reference));
}

/// Relative error |computed - reference| / |reference| (absolute when reference = 0).
template <class T> double error_rel(T computed, wide reference)
{
    if (!std::isfinite(computed)) return std::numeric_limits<double>::infinity();
    const wide diff = wabs(wide(computed) - reference);
    return double(reference == 0 ? diff : diff / wabs(reference));
}

/// |a - b| <= tol * max(|a|, |b|, floor), componentwise.
template <glm::length_t L, class T, glm::qualifier Q>
bool approx_equal(const glm::vec<L, T, Q>& a, const glm::vec<L, T, Q>& b, T tol, T floor = T(1))
{
    for (glm::length_t k = 0; k < L; ++k) {
        const T scale = std::max({std::abs(a[k]), std::abs(b[k]), floor});
        if (!(std::abs(a[k] - b[k]) <= tol * scale)) return false;
    }
    return true;
}

} // namespace phong_test
