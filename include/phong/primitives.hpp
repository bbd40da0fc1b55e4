// phong: the ray tracer model's generic primitives (sphere, plane, square, tapered cylinder with
// radius 1 at z = 0 and s at z = 1, cube [-1, 1]^3): their normals m' at a generic hit point P', and
// ray intersections in generic (object) coordinates. t is the same for the world ray and the
// inverse-transformed ray; m' is not normalized: carry it with the normal matrix, then normalize.
// SPDX-License-Identifier: MIT
#pragma once

#include "core/vector.hpp"

#include <limits>

#include "core/diagnostics_push.hpp"

namespace phong {

// ---- normals at a generic hit point -------------------------------------------------------

/// Generic sphere: m' = P'. Pre: P' on the unit sphere (any P' gives the radial direction). Edge: 0 at P' = 0.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> sphere_normal(const glm::vec<3, T, Q>& p)
{
    return p;
}

/// Generic plane z = 0: m' = (0, 0, 1) at every point (the +z side is the front).
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> plane_normal(const glm::vec<3, T, Q>& /*p*/)
{
    return {T(0), T(0), T(1)};
}

/// Generic square z = 0, |x|, |y| <= 1: m' = (0, 0, 1), the plane's normal.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> square_normal(const glm::vec<3, T, Q>& /*p*/)
{
    return {T(0), T(0), T(1)};
}

/// Wall of the generic tapered cylinder F = x^2 + y^2 - (1 + (s - 1) z)^2 = 0, outward:
///   m' = grad F / 2 = (x, y, -(s - 1)(1 + (s - 1) z))
/// Pre: s >= 0, P' on the wall, 0 <= z <= 1. Edge: a cone's apex (s = 0, z = 1, x = y = 0) gives 0.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> tapered_cylinder_wall_normal(const glm::vec<3, T, Q>& p, T s)
{
    const T k = s - T(1);
    return {p.x, p.y, -k * (T(1) + k * p.z)};
}

/// Base disk of the generic tapered cylinder (z = 0, radius 1): m' = (0, 0, -1), outward.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> tapered_cylinder_base_normal(const glm::vec<3, T, Q>& /*p*/)
{
    return {T(0), T(0), T(-1)};
}

/// Cap disk of the generic tapered cylinder (z = 1, radius s): m' = (0, 0, 1), outward.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> tapered_cylinder_cap_normal(const glm::vec<3, T, Q>& /*p*/)
{
    return {T(0), T(0), T(1)};
}

/// Generic cube max(|x|, |y|, |z|) = 1: m' = sign(p_k) e_k for the axis k of the largest |p_k|
/// (outward face normal). Edge: on an edge or corner (a tie) the first axis in x, y, z order
/// wins; p_k = 0 on that axis (only for P' = 0) gives +e_k. NaN components lose every comparison.
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> cube_normal(const glm::vec<3, T, Q>& p)
{
    const T ax = detail::abs(p.x), ay = detail::abs(p.y), az = detail::abs(p.z);
    if (ax >= ay && ax >= az) return {p.x < T(0) ? T(-1) : T(1), T(0), T(0)};
    if (ay >= az) return {T(0), p.y < T(0) ? T(-1) : T(1), T(0)};
    return {T(0), T(0), p.z < T(0) ? T(-1) : T(1)};
}

// ---- ray intersection in generic coordinates ----------------------------------------------

/// Which part of a generic primitive a ray hit.
enum class primitive_part : unsigned char { none, surface, wall, base, cap };

/// The nearest hit of a ray S + t c with t > t_min; a miss has part = none and t = +inf.
template <class T>
struct ray_hit {
    T t = std::numeric_limits<T>::infinity();   ///< the ray parameter of the hit (+inf: a miss)
    primitive_part part = primitive_part::none; ///< the part hit (none: a miss)
    /// Whether the ray hit something.
    PHONG_HD constexpr explicit operator bool() const { return part != primitive_part::none; }
};

namespace detail {

/// Keeps the nearer of two hits (the first on a tie).
template <class T>
PHONG_HD constexpr ray_hit<T> nearer(const ray_hit<T>& a, const ray_hit<T>& b)
{
    return b.t < a.t ? b : a;
}

/// The roots of A t^2 + 2 B t + C = 0 without cancellation (Numerical Recipes 5.6): q = -(B + sign(B)
/// sqrt(B^2 - A C)), t = q / A, C / q; A = 0 leaves -C / (2B). Returns how many (0-2), unordered.
template <class T>
PHONG_HD constexpr int quadratic_roots(T A, T B, T C, T& t0, T& t1)
{
    const T disc = B * B - A * C;
    if (!(disc >= T(0))) return 0; // also NaN
    const T root = detail::sqrt(disc);
    const T q = -(B + (B < T(0) ? -root : root));
    if (q == T(0)) { // B = 0 and disc = 0: A t^2 + C = 0 with A C = 0
        if (A != T(0) && C == T(0)) { t0 = T(0); return 1; }
        return 0;
    }
    t0 = C / q;
    if (A == T(0)) return 1;
    t1 = q / A;
    return 2;
}

/// The hit at the smaller of t0 and t1 that is > t_min (roots beyond the range are dropped).
template <class T>
PHONG_HD constexpr ray_hit<T> first_after(int count, T t0, T t1, T t_min, primitive_part part)
{
    ray_hit<T> h;
    if (count >= 1 && t0 > t_min && t0 < std::numeric_limits<T>::infinity()) h = {t0, part}; // inf: beyond T's range, no hit
    if (count >= 2 && t1 > t_min && t1 < h.t) h = {t1, part};
    return h;
}

/// Ray S + t c against the disk z = z0, x^2 + y^2 <= radius^2; the hit's time is reported as
/// t_offset + t (the ray's origin S lies at time t_offset of the caller's ray; 0 + t is t).
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_disk(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T z0, T radius, T t_min,
                                       primitive_part part, T t_offset = T(0))
{
    if (c.z == T(0)) return {};
    const T t = (z0 - S.z) / c.z;
    const T t_total = t_offset + t;
    if (!(t_total > t_min) || t_total == std::numeric_limits<T>::infinity()) return {};
    const T x = S.x + t * c.x, y = S.y + t * c.y;
    if (!(x * x + y * y <= radius * radius)) return {};
    return {t_total, part};
}

/// Slab method: the times [enter, leave] during which S + t c lies in the box lo <= P <= hi.
/// Returns false when the ray's line misses the box, for c = 0 outside it, and for NaN input.
template <class T, glm::qualifier Q>
PHONG_HD constexpr bool ray_box(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, const glm::vec<3, T, Q>& lo,
                                const glm::vec<3, T, Q>& hi, T& enter, T& leave)
{
    const T inf = std::numeric_limits<T>::infinity();
    enter = -inf;
    leave = inf;
    for (glm::length_t a = 0; a < 3; ++a) {
        if (c[a] == T(0)) {
            if (!(S[a] >= lo[a] && S[a] <= hi[a])) return false;
            continue;
        }
        T t0 = (lo[a] - S[a]) / c[a], t1 = (hi[a] - S[a]) / c[a];
        if (t0 != t0 || t1 != t1) return false; // NaN input
        if (t1 < t0) { const T tmp = t0; t0 = t1; t1 = tmp; }
        enter = detail::max(enter, t0);
        leave = detail::min(leave, t1);
    }
    return enter <= leave;
}

/// For a direction c whose c.c overflows or underflows: the power of two s that brings c's largest
/// component into [1, 2) (S + t' (c s) is the same ray, t = t' s, exact but for underflow); 0 when
/// c = 0 or a component is inf or NaN (no hit).
template <class T, glm::qualifier Q>
PHONG_HD constexpr T direction_scale(const glm::vec<3, T, Q>& c)
{
    constexpr T max = std::numeric_limits<T>::max();
    if (!(detail::abs(c.x) <= max && detail::abs(c.y) <= max && detail::abs(c.z) <= max)) return T(0);
    const T largest = detail::max_abs(c);
    if (largest == T(0)) return T(0);
    return math_traits<T>::inverse_pow2_scale(largest);
}

/// A hit h of the ray S + t' (c scale) as a hit of S + t c: t = t' scale, no hit where that is
/// not after t_min or beyond T's range.
template <class T> PHONG_HD constexpr ray_hit<T> scaled_back(const ray_hit<T>& h, T scale, T t_min)
{
    const T t = h.t * scale;
    if (!h || !(t > t_min) || t == std::numeric_limits<T>::infinity()) return {};
    return {t, h.part};
}

} // namespace detail

/// Ray S + t c against the generic unit sphere |P| = 1: the smallest root t > t_min of
///   (c.c) t^2 + 2 (S.c) t + (S.S - 1) = 0.
/// The discriminant is taken as (c.c)(1 - |S - (S.c / c.c) c|^2) (the line's distance from the
/// centre, Ray Tracing Gems ch. 7), not (S.c)^2 - (c.c)(S.S - 1), so far and near-tangent rays keep
/// their digits. A c whose c.c overflows or underflows is scaled by a power of two (t scaled back),
/// and where S.S overflows the root C / q is taken from |S|: finite S and c never give t = inf nor
/// miss a hit for overflow. Part: surface. Pre: S, c finite; c need not be unit.
/// Edge: c = 0, NaN, inf, a miss, a tangent ray that rounds to a miss, or t = inf: no hit.
/// Accuracy: near tangency the roots merge; t is then within about eps (t0 + t1) / |t0 - t1|.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_sphere(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T t_min = T(0))
{
    const T a = detail::dot(c, c);
    if (!detail::normal_square(a)) [[unlikely]] { // c.c overflowed or underflowed, or c is 0 or NaN
        const T s = detail::direction_scale(c); // the same ray with c s, t = t' s
        if (s == T(0)) return {};               // c = 0, inf or NaN
        return detail::scaled_back(phong::ray_sphere(S, c * s, t_min / s), s, t_min);
    }
    const T b = detail::dot(S, c);
    const glm::vec<3, T, Q> closest = S - c * (b / a); // the foot of the perpendicular from the centre
    const T one_minus = T(1) - detail::dot(closest, closest); // disc / (c.c)
    if (!(one_minus >= T(0))) return {};
    const T root = detail::sqrt(a) * detail::sqrt(one_minus); // sqrt(disc), no overflow of a * ...
    const T q = -(b + (b < T(0) ? -root : root));
    if (q == T(0)) return detail::first_after(1, T(0), T(0), t_min, primitive_part::surface); // tangent at S
    const T SS = detail::dot(S, S);
    T t0;
    if (SS <= std::numeric_limits<T>::max()) {
        t0 = (SS - T(1)) / q;
    } else { // S.S overflowed: (|S|^2 - 1) / q as (|S| / q) |S| - 1 / q
        const T L = detail::length(S);
        t0 = (L / q) * L - T(1) / q;
    }
    return detail::first_after(2, t0, q / a, t_min, primitive_part::surface);
}

/// Ray S + t c against the generic plane z = 0: t = -S.z / c.z when t > t_min. Part: surface.
/// Edge: c.z = 0 (even a ray in the plane) and a time that overflows to inf give no hit.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_plane(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T t_min = T(0))
{
    if (c.z == T(0)) return {};
    const T t = -S.z / c.z;
    if (!(t > t_min) || t == std::numeric_limits<T>::infinity()) return {};
    return {t, primitive_part::surface};
}

/// Ray S + t c against the generic square z = 0, |x| <= 1, |y| <= 1 (edges included).
/// Part: surface. Edge: as ray_plane; a hit outside the square is no hit.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_square(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T t_min = T(0))
{
    const ray_hit<T> h = phong::ray_plane(S, c, t_min);
    if (!h) return h;
    const T x = S.x + h.t * c.x, y = S.y + h.t * c.y;
    if (!(detail::abs(x) <= T(1) && detail::abs(y) <= T(1))) return {};
    return h;
}

namespace detail {
/// The tapered cylinder's hits of the ray S + t c, reported at times t_offset + t.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> tapered_cylinder_hits(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T s, T t_min,
                                                    T t_offset)
{
    const T k = s - T(1);
    const T w = T(1) + k * S.z, e = k * c.z;
    const T A = c.x * c.x + c.y * c.y - e * e;
    const T B = S.x * c.x + S.y * c.y - w * e;
    const T C = S.x * S.x + S.y * S.y - w * w;
    T t[2] = {T(0), T(0)};
    const int n = quadratic_roots(A, B, C, t[0], t[1]);
    ray_hit<T> best;
    for (int i = 0; i < n; ++i) {
        const T z = S.z + t[i] * c.z;
        const T t_total = t_offset + t[i];
        if (t_total > t_min && t_total < best.t && z >= T(0) && z <= T(1)) best = {t_total, primitive_part::wall};
    }
    best = nearer(best, ray_disk(S, c, T(0), T(1), t_min, primitive_part::base, t_offset));
    if (s > T(0)) best = nearer(best, ray_disk(S, c, T(1), s, t_min, primitive_part::cap, t_offset));
    return best;
}
} // namespace detail

/// Ray S + t c against the generic tapered cylinder with small radius s (wall, base and cap):
///   wall: A t^2 + 2 B t + C = 0 with k = s - 1, w = 1 + k S.z, e = k c.z,
///         A = cx^2 + cy^2 - e^2, B = Sx cx + Sy cy - w e, C = Sx^2 + Sy^2 - w^2, a root counts when 0 <= z <= 1;
///   base: z = 0 with x^2 + y^2 <= 1;  cap: z = 1 with x^2 + y^2 <= s^2.
/// Returns the nearest hit after t_min and its part (wall, base or cap). An origin outside the
/// bounding box [-R, R]^2 x [0, 1] (R = max(1, s)) grown by R first moves to the box's entry time t_e
/// (t = t_e + t'): at a far S, B^2 and A C (~|S|^2 |c|^2) would cancel down to the discriminant's
/// size (|c|^2); from the box, t is as accurate as the rounding of S + t_e c (docs/models.md).
/// A c whose c.c overflows or underflows is scaled by a power of two first, as in ray_sphere.
/// Pre: s >= 0 (s < 0 would add the cone's other nappe). Edge: s = 0 has no cap and the apex is a
/// wall hit; a ray along a generator line (A = 0) takes the linear root; c = 0, NaN, inf and a hit
/// at t = inf give no hit.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_tapered_cylinder(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T s,
                                                   T t_min = T(0))
{
    if (!detail::normal_square(detail::dot(c, c))) [[unlikely]] { // as in ray_sphere
        const T scale = detail::direction_scale(c); // the same ray with c scale, t = t' scale
        if (scale == T(0)) return {};               // c = 0, inf or NaN
        return detail::scaled_back(phong::ray_tapered_cylinder(S, c * scale, s, t_min / scale), scale, t_min);
    }
    const T R = detail::max(T(1), s);
    if (detail::abs(S.x) <= T(2) * R && detail::abs(S.y) <= T(2) * R && S.z >= -R && S.z <= T(1) + R)
        return detail::tapered_cylinder_hits(S, c, s, t_min, T(0));
    T enter = T(0), leave = T(0);
    if (!detail::ray_box(S, c, glm::vec<3, T, Q>(-R, -R, T(0)), glm::vec<3, T, Q>(R, R, T(1)), enter, leave) || !(leave > t_min) ||
        !(enter < std::numeric_limits<T>::infinity()))
        return {}; // the line misses the box (or NaN), the box lies before t_min, or beyond T's range
    return detail::tapered_cylinder_hits(S + enter * c, c, s, t_min, enter);
}

/// Ray S + t c against the generic cube [-1, 1]^3 (slab method): the entry time when it is
/// > t_min, else the exit time (a ray starting inside). Part: surface; cube_normal gives m'.
/// Edge: a ray parallel to a pair of faces and outside their slab misses; c = 0 and NaN miss.
template <class T, glm::qualifier Q>
PHONG_HD constexpr ray_hit<T> ray_cube(const glm::vec<3, T, Q>& S, const glm::vec<3, T, Q>& c, T t_min = T(0))
{
    const T inf = std::numeric_limits<T>::infinity();
    T enter = -inf, leave = inf;
    if (!detail::ray_box(S, c, glm::vec<3, T, Q>(T(-1)), glm::vec<3, T, Q>(T(1)), enter, leave)) return {};
    if (enter > t_min && enter < inf) return {enter, primitive_part::surface};
    if (leave > t_min && leave < inf) return {leave, primitive_part::surface};
    return {};
}

/// The generic normal m' of the tapered cylinder part hit (wall, base or cap) at P'.
/// Edge: part none or surface (or a value outside the enumeration) gives 0 (no normal).
template <class T, glm::qualifier Q>
PHONG_HD constexpr glm::vec<3, T, Q> tapered_cylinder_normal(const glm::vec<3, T, Q>& p, T s, primitive_part part)
{
    switch (part) {
    case primitive_part::wall: return phong::tapered_cylinder_wall_normal(p, s);
    case primitive_part::base: return phong::tapered_cylinder_base_normal(p);
    case primitive_part::cap: return phong::tapered_cylinder_cap_normal(p);
    case primitive_part::none:
    case primitive_part::surface: break;
    }
    return glm::vec<3, T, Q>(T(0));
}

} // namespace phong
#include "core/diagnostics_pop.hpp"
