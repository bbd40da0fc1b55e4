// Test support: the wide number type of the reference (__float128 where available, else long
// double), and its math. Kept apart from phong's own math on purpose: the reference must not
// share code with the library it checks.
#pragma once

#include <cmath>
#include <limits>

#if defined(PHONG_HAVE_QUADMATH)
extern "C" {
#include <quadmath.h>
}
#endif

namespace phong_test {

#if defined(PHONG_HAVE_QUADMATH)
__extension__ typedef __float128 wide; ///< 113-bit significand
inline wide wsqrt(wide x) { return sqrtq(x); }
inline wide wexp(wide x) { return expq(x); }
inline wide wlog(wide x) { return logq(x); }
inline wide wpow(wide x, wide y) { return powq(x, y); }
inline constexpr int wide_digits = 113;
#else
typedef long double wide; ///< 64-bit significand on x86-64
inline wide wsqrt(wide x) { return std::sqrt(x); }
inline wide wexp(wide x) { return std::exp(x); }
inline wide wlog(wide x) { return std::log(x); }
inline wide wpow(wide x, wide y) { return std::pow(x, y); }
inline constexpr int wide_digits = std::numeric_limits<long double>::digits;
#endif

inline wide wabs(wide x) { return x < 0 ? -x : x; }
inline wide wmax(wide a, wide b) { return a < b ? b : a; }
inline wide wmin(wide a, wide b) { return b < a ? b : a; }
inline wide wclamp(wide x, wide lo, wide hi) { return wmin(wmax(x, lo), hi); }

/// A 3-vector of wide numbers (GLM is not used for the reference).
struct wvec3 {
    wide x = 0, y = 0, z = 0;
    friend wvec3 operator+(wvec3 a, wvec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
    friend wvec3 operator-(wvec3 a, wvec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
    friend wvec3 operator*(wvec3 a, wide s) { return {a.x * s, a.y * s, a.z * s}; }
    friend wvec3 operator*(wvec3 a, wvec3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
    friend wvec3 operator-(wvec3 a) { return {-a.x, -a.y, -a.z}; }
};
inline wide wdot(wvec3 a, wvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
/// Length without overflow for any float/double input: __float128 and x86 long double have a
/// 15-bit exponent, so squares of float/double values never overflow or underflow.
inline wide wlength(wvec3 a) { return wsqrt(wdot(a, a)); }
inline wvec3 wnormalize(wvec3 a)
{
    const wide len = wlength(a);
    return len > 0 ? a * (wide(1) / len) : wvec3{};
}

template <class V> wvec3 widen(const V& v) { return {wide(v.x), wide(v.y), wide(v.z)}; }

} // namespace phong_test
