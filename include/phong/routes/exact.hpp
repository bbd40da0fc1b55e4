// phong: the exact evaluation route (features::mode = exact; in double, the stable mode's wider
// route for float; the fast mode with fast::pow_unit and fast::rsqrt). The model's formulas as
// written, one small function per step; finite input never gives NaN or inf.
// SPDX-License-Identifier: MIT
#pragma once

#include "../terms/direction.hpp"
#include "../core/fast_math.hpp"
#include "../terms/specular.hpp"
#include "light_terms.hpp"
#include "../core/twofold.hpp"

#include <cmath>
#include <limits>
#include <type_traits>

#include "../core/diagnostics_push.hpp"

namespace phong::detail::exact {

/// The frame's fields for SIMD lanes only (empty for scalars):
///  - minus_position: -Q, hidden from the compiler (opaque_lanes), so that d = L.xyz + (-Q) is one
///    add with a memory operand (x - y and x + (-y) give the same bits);
///  - nv_seen (Blinn): n.v where sees_viewer, else -inf, so n.l + n.v <= 0 there (no mask per pair).
template <class T, glm::qualifier Q, bool Lanes = !std::is_floating_point_v<T>> struct lanes_frame {};
template <class T, glm::qualifier Q> struct lanes_frame<T, Q, true> {
    glm::vec<3, T, Q> minus_position = glm::vec<3, T, Q>(T(0));
    T nv_seen = T(0);
};

/// Per-point quantities shared by every light (five fields: they stay in registers).
template <class T, glm::qualifier Q>
struct surface_frame {
    glm::vec<3, T, Q> position; ///< Q
    glm::vec<3, T, Q> normal;   ///< unit normal after two-sided negation (0 if undefined)
    glm::vec<3, T, Q> view;     ///< unit view vector v (0 if undefined, and where no term reads v)
    mask_t<T> defined;          ///< the normal is nonzero and the inputs finite: diffuse and specular can be on
    mask_t<T> sees_viewer;      ///< the view vector exists (not at the eye, not a zero given v): specular can be on
    T poison;                   ///< 0, or NaN when the point's inputs are not finite
    T nv = T(0);                ///< with a specular term: n.v
    [[no_unique_address]] lanes_frame<T, Q> lanes = {}; ///< SIMD lanes: see lanes_frame
};

/// x unchanged, hidden from the compiler's algebra (GCC and Clang, SIMD lanes): an x + (-y)
/// built from it is not folded back into x - y.
template <class T>
PHONG_INLINE T opaque_lanes(T x)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
    if constexpr (requires { typename T::register_type; }) {
        typename T::register_type r = x;
#  if defined(__AVX512F__)
        __asm__("" : "+v"(r)); // any vector register, xmm/ymm/zmm 0-31
#  else
        __asm__("" : "+x"(r));
#  endif
        return T(r);
    }
#endif
    return x;
}

/// A unit vector with its squared length: v / |v|, or 0 when |v|^2 is not a normal number.
template <class T, glm::qualifier Q>
struct unit_vector {
    glm::vec<3, T, Q> unit;
    T square;     ///< |v|^2 as computed (inf or NaN when v is not finite or overflows)
    mask_t<T> ok; ///< unit is a unit vector
};
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr unit_vector<T, Q> unit_of(const glm::vec<3, T, Q>& v, T sign = T(1))
{
    const T dd = detail::dot(v, v);
    if constexpr (std::is_floating_point_v<T>) {
        const T inv = exact_inverse_length(dd);
        return {v * (inv * sign), dd, inv > T(0)};
    } else {
        // SIMD lanes keep exact_inverse_length's range test as the mask (no second compare).
        const mask_t<T> normal = normal_square(dd);
        const T inv = detail::select(normal, detail::rsqrt_normal(dd), T(0));
        return {v * (inv * sign), dd, normal};
    }
}

/// unit(e * sign), or only its square (for the NaN test) where no term reads v.
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr unit_vector<T, Q> view_unit(const glm::vec<3, T, Q>& e, T sign)
{
    if constexpr (F.specular == specular_model::none && F.two_sided != facing::view) {
        return {glm::vec<3, T, Q>(T(0)), detail::dot(e, e), mask_t<T>(true)};
    } else {
        return unit_of(e, sign);
    }
}

/// The view vector v at Q per F.view (normalized unless unit_inputs). Its square tells whether the
/// inputs may be non-finite (fixed_direction: |Q|^2 does).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr unit_vector<T, Q> view_at(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& given_view,
                                                 const environment<T, Q>& env)
{
    using vec3 = glm::vec<3, T, Q>;
    const vec3 eye(env.eye.x, env.eye.y, env.eye.z);
    if constexpr (F.view == view_model::given && F.unit_inputs) {
        return {given_view, T(1), mask_t<T>(true)}; // unit by precondition
    } else if constexpr (F.view == view_model::fixed_direction) {
        if constexpr (F.unit_inputs) return {eye, detail::dot(position, position), mask_t<T>(true)}; // unit by precondition
        const vec3 v = detail::normalize(eye);
        return {v, detail::dot(position, position), detail::dot(v, v) > T(0)};
    } else if constexpr (F.view == view_model::eye_at_origin) {
        return view_unit<F>(position, T(-1)); // -Q, as Q times -1/|Q|: no negation of Q's components
    } else {
        return view_unit<F>(detail::unnormalized_view<F.view>(position, given_view, eye, env.eye.w), T(1));
    }
}

/// Lane-wise: both squares at most T's largest, i.e. finite inputs (given v: |Q|^2 joins the test).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr mask_t<T> squares_in_range(const glm::vec<3, T, Q>& position, T normal_square, T view_square)
{
    if constexpr (F.view == view_model::given) view_square = view_square + detail::dot(position, position);
    else (void)position;
    return math_traits<T>::both(normal_square <= largest<T>(), view_square <= largest<T>());
}

/// Whether every lane's squares are in range (finite inputs). Where both unit vectors come from
/// unit_of, their ok masks are the test (a zero vector then takes the exact test: rare).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr bool finite_squares(const glm::vec<3, T, Q>& position, const unit_vector<T, Q>& n, const unit_vector<T, Q>& v)
{
    constexpr bool view_of_position = (F.view == view_model::eye_at_origin || F.view == view_model::eye_point) &&
                                      !(F.specular == specular_model::none && F.two_sided != facing::view); // view_unit: unit_of
    if constexpr (!F.unit_inputs && view_of_position) {
        (void)position;
        if constexpr (requires { math_traits<T>::all_both(n.ok, v.ok); }) return math_traits<T>::all_both(n.ok, v.ok);
        else return math_traits<T>::all(math_traits<T>::both(n.ok, v.ok));
    } else {
        return math_traits<T>::all(squares_in_range<F>(position, n.square, v.square));
    }
}

/// The point's poison (poison_of), scalars: the exact test runs only when a square is out of range.
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr T point_poison(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                  const glm::vec<3, T, Q>& given_view, const environment<T, Q>& env, T normal_square,
                                  T view_square)
{
    if (!squares_in_range<F>(position, normal_square, view_square)) [[unlikely]]
        return poison_of<F>(position, normal, given_view, env);
    return T(0);
}

/// The per-point frame: unit normal (faced toward the viewer when two-sided), view vector, whether
/// both exist, the poison, n.v.
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr surface_frame<T, Q> prepare(const glm::vec<3, T, Q>& position, const glm::vec<3, T, Q>& normal,
                                               const glm::vec<3, T, Q>& given_view, const environment<T, Q>& env,
                                               mask_t<T> front_facing)
{
    using vec3 = glm::vec<3, T, Q>;
    unit_vector<T, Q> n{normal, T(1), mask_t<T>(true)}; // unit_inputs: unit by precondition
    if constexpr (!F.unit_inputs) n = unit_of(normal);
    const unit_vector<T, Q> v = view_at<F>(position, given_view, env);
    // A NaN point has every channel NaN through poison; its terms are off, so no NaN power runs.
    T poison;
    mask_t<T> defined;
    if constexpr (std::is_floating_point_v<T>) {
        poison = point_poison<F>(position, normal, given_view, env, n.square, v.square);
        defined = math_traits<T>::both(n.ok, poison == T(0));
    } else {
        // SIMD lanes: poison 0 and defined = n.ok unless a lane's squares are not finite (rare).
        poison = T(0);
        defined = n.ok;
        if (!finite_squares<F>(position, n, v)) [[unlikely]] {
            poison = poison_of<F>(position, normal, given_view, env);
            defined = math_traits<T>::both(n.ok, poison == T(0));
        }
    }
    vec3 unit_normal = n.unit;
    if constexpr (F.two_sided != facing::none) unit_normal = unit_normal * facing_sign<F>(unit_normal, v.unit, front_facing);
    else (void)front_facing;
    T nv = T(0);
    if constexpr (F.specular != specular_model::none) nv = detail::dot(unit_normal, v.unit);
    lanes_frame<T, Q> lanes{};
    if constexpr (!std::is_floating_point_v<T>) {
        const T minus_zero(scalar_t<T>(-0.0f));
        lanes.minus_position = vec3(opaque_lanes(minus_zero - position.x), opaque_lanes(minus_zero - position.y), opaque_lanes(minus_zero - position.z));
        if constexpr (F.specular == specular_model::blinn)
            lanes.nv_seen = detail::select(v.ok, nv, T(-std::numeric_limits<scalar_t<T>>::infinity()));
    }
    return {vec3(position.x, position.y, position.z), vec3(unit_normal.x, unit_normal.y, unit_normal.z),
            vec3(v.unit.x, v.unit.y, v.unit.z), defined, v.ok, poison, nv, lanes};
}

/// Whether a pair is lit (dd = |d|^2, nd = n.d): |d|^2 a normal number, the point defined, and,
/// where gated, n.l > 0. Scalars test the sign first (it rejects the most pairs).
template <features F, class T, glm::qualifier Q>
PHONG_INLINE constexpr mask_t<T> lit(const surface_frame<T, Q>& s, T dd, T nd)
{
    if constexpr (std::is_floating_point_v<T>) {
        return s.defined && (!gated<F> || nd > T(0)) && dd >= exact_min_square<T>() && dd <= largest<T>();
    } else {
        mask_t<T> on = s.defined;
        if constexpr (gated<F>) on = math_traits<T>::both(on, nd > T(0));
        return both_normal_square(on, dd);
    }
}

/// The power of add_specular: detail::cosine_power, or in the fast mode fast::pow_unit of the
/// clamped cosine. Float SIMD lanes keep cosine_power: their exact power is already a polynomial
/// of the same cost, within fast::pow_unit_max_rel (docs/batch.md).
template <evaluation M, class T>
PHONG_INLINE constexpr T route_cosine_power(T x, T scale, T m)
{
    if constexpr (M == evaluation::fast && (std::is_floating_point_v<T> || !std::is_same_v<scalar_t<T>, float>))
        return fast::pow_unit(detail::clamp(x * scale, T(0), T(1)), m);
    else return detail::cosine_power(x, scale, m);
}

/// The fast mode's shininess on SIMD lanes where every lane has the same integer n in
/// [1, fast::detail::pow_integer_max_exponent]: fast::detail::pow_integer with n's schedule made
/// once, within fast::detail::pow_integer_max_rel <= fast::pow_unit_max_rel. The power of base 0 is
/// 0, so add_specular zeroes the base of off lanes. Bases whose power is below the power floor
/// (ieee::power_floor_log2) are taken as 0 (least, least_half): no subnormal results.
/// Squarings: n = 2^Squarings known at compile time (that many squarings, the same bits);
/// runtime_squarings: n known at run time only.
inline constexpr unsigned runtime_squarings = ~0u;
template <class T, unsigned Squarings = runtime_squarings> struct integer_exponent {
    fast::detail::pow_integer_plan plan; ///< of the shininess n of every lane, n >= 1
    fast::detail::pow_integer_plan half; ///< of n / 2 where n is even (Blinn's power of (n.h)^2, add_halfway_specular_fast)
    bool even;                   ///< n is even
    T least;                     ///< the least base whose n-th power is at least the power floor
    T least_half;                ///< the same for n / 2 (0 for n = 1)
    static integer_exponent of(unsigned n)
    {
        return {fast::detail::plan_pow_integer(n), fast::detail::plan_pow_integer(n / 2), n % 2 == 0, T(least_base(n)), T(least_base(n / 2))};
    }
    /// x^n (fast::detail::pow_integer); 0 for x below least
    PHONG_INLINE T power(T x) const
    {
        x = detail::select(x >= least, x, T(0));
        if constexpr (Squarings == runtime_squarings) return fast::detail::pow_integer(x, plan);
        else return squared<Squarings>(x);
    }
    /// n is even
    PHONG_INLINE bool is_even() const
    {
        if constexpr (Squarings == runtime_squarings) return even;
        else return Squarings > 0;
    }
    /// x^(n/2), n even; 0 for x below least_half
    PHONG_INLINE T half_power(T x) const
    {
        x = detail::select(x >= least_half, x, T(0));
        if constexpr (Squarings == runtime_squarings) return fast::detail::pow_integer(x, half);
        else if constexpr (Squarings == 0) return x; // n = 1 is odd: not called
        else return squared<Squarings - 1>(x);
    }
    /// The same shininess with n = 2^K known at compile time (K = plan.squarings, n a power of two).
    template <unsigned K> PHONG_INLINE integer_exponent<T, K> with_squarings() const { return {plan, half, even, least, least_half}; }

private:
    /// 2^(floor / n) rounded up to the scalar type (n = 0: 0, no base is cut).
    static scalar_t<T> least_base(unsigned n)
    {
        using S = scalar_t<T>;
        if (n == 0) return S(0);
        const double b = std::exp2(double(ieee::power_floor_log2<S>) / double(n));
        const S r = S(b);
        return double(r) < b ? std::nextafter(r, S(1)) : r;
    }
    template <unsigned K> PHONG_INLINE static T squared(T x)
    {
        if constexpr (K == 0) return x;
        else return squared<K - 1>(x * x);
    }
};
template <class Exponent, class T> inline constexpr bool is_integer_exponent = false;
template <class T, unsigned K> inline constexpr bool is_integer_exponent<integer_exponent<T, K>, T> = true;

/// The shininess on SIMD lanes with m == 0 tested once per call: cosine_power's power, the same
/// bits. The cosine is clamped above only (pow_unit gives x <= 0 and NaN the power of 0).
template <class T> struct lane_shininess {
    T m;
    mask_t<T> zero; ///< m == 0
    bool any_zero;  ///< any(zero)
    T threshold;    ///< the cosine above which the power is taken: float lanes least_base(m) (the power floor), other lanes 0; -inf where m == 0 (pow(c, 0) = 1 for every c)
    T bounded;      ///< min(m, 2^100): the same powers of every x in [0, 1] (x^m = 0 for x < 1 from m ~ 2^31 on), and m log2 x finite
};

/// One step's specular constants on float SIMD lanes (step_specular_of): m = lane_shininess::bounded;
/// threshold: the power is taken where c > threshold, +inf where the point does not see the viewer;
/// halfway_min (Blinn): the least |h|^2 with a halfway vector (u^2), +inf there too. A pair's
/// specular mask is then one compare (v = 0 there makes Phong's cosine 0).
template <class T> struct step_specular {
    T m;
    T threshold;
    T halfway_min;
};

/// The routes that take step_specular: Phong, and exact Blinn without a spot.
template <features F>
inline constexpr bool step_specular_route = F.specular == specular_model::phong ||
                                            (F.specular == specular_model::blinn && F.spot == spot_model::none && F.mode == evaluation::exact);

/// u^2 (u = epsilon / 2): the least |h|^2 with a halfway vector on SIMD lanes.
template <class T> PHONG_INLINE constexpr T lanes_halfway_min()
{
    constexpr scalar_t<T> u = std::numeric_limits<scalar_t<T>>::epsilon() / 2;
    return T(u * u);
}

/// step_specular for one step: m's per-call (or per-step material) fields and the frame's sees_viewer.
template <class T>
PHONG_INLINE step_specular<T> step_specular_of(const lane_shininess<T>& m, mask_t<T> sees_viewer)
{
    const T inf(std::numeric_limits<scalar_t<T>>::infinity());
    return {m.bounded, detail::select(sees_viewer, m.threshold, inf), detail::select(sees_viewer, lanes_halfway_min<T>(), inf)};
}

/// The least |h|^2 with a halfway vector of a step's lanes: step_specular's per lane, else u^2.
template <class T, class Exponent> PHONG_INLINE T halfway_min_of([[maybe_unused]] const Exponent& m)
{
    if constexpr (std::is_same_v<Exponent, step_specular<T>>) return m.halfway_min;
    else return lanes_halfway_min<T>();
}

template <evaluation M, class T>
PHONG_INLINE constexpr T route_cosine_power(T x, T scale, const lane_shininess<T>& m)
{
    if constexpr (M == evaluation::fast && !std::is_same_v<scalar_t<T>, float>)
        return fast::pow_unit(detail::clamp(x * scale, T(0), T(1)), m.m);
    else return math_traits<T>::pow_unit(math_traits<T>::min(x * scale, T(1)), m.m, m.zero);
}

/// Whether a lane that is on has shininess 0 (pow(0, 0) = 1 keeps the specular term on).
template <class T, class Exponent> PHONG_INLINE constexpr bool any_zero_exponent(const Exponent& m, const mask_t<T>& on)
{
    if constexpr (std::is_same_v<Exponent, lane_shininess<T>>) return m.any_zero && math_traits<T>::any(math_traits<T>::both(on, m.zero));
    else if constexpr (is_integer_exponent<Exponent, T>) return false; // n >= 1
    else return math_traits<T>::any(math_traits<T>::both(on, m == T(0)));
}

/// The specular term Ls_i f max(c, 0)^m of a lit pair, c = x * scale. on: the lanes lit and seeing
/// the viewer (scalars run a point without a view vector with the specular term removed).
template <evaluation M, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class Exponent>
PHONG_INLINE constexpr void add_specular(Sums<T, Q>& sums, const Light& L, T f, T x, T scale, const Exponent& m,
                                     [[maybe_unused]] mask_t<T> on)
{
    glm::vec<3, T, Q>& sum = sum_of<term_kind::specular>(sums);
    if constexpr (std::is_floating_point_v<T>) {
        if (x > T(0)) sum += in_type<T>(specular_of(L)) * (f * route_cosine_power<M>(x, scale, m));
        else if (m == T(0)) sum += in_type<T>(specular_of(L)) * f; // 0^m = 1 for m = 0 (power_of_zero), no product by 0^m
    } else if constexpr (is_integer_exponent<Exponent, T>) {
        // The base is zeroed where the lane is off or c <= 0 (power 0): max(c, 0) in place of a
        // compare (on AVX-512 a compare takes a multiplier slot) and of a skip (docs/batch.md).
        // No clamp to 1: on lanes c <= 1 up to rounding, amplified by n either way, and finite.
        sum += in_type<T>(specular_of(L)) * (f * m.power(math_traits<T>::max(detail::select(on, x * scale, T(0)), T(0))));
    } else if constexpr (std::is_same_v<Exponent, step_specular<T>>) {
        // The lanes whose power is not 0: on and c > threshold (the least cosine whose power
        // reaches the power floor; -inf for m = 0). The same skip as below.
        const T c = x * scale;
        const mask_t<T> powered = math_traits<T>::both(on, c > m.threshold);
        if (!math_traits<T>::any(powered)) return; // every power 0: the sum would gain +0
        sum += in_type<T>(specular_of(L)) * (f * math_traits<T>::pow_unit_kept(math_traits<T>::min(c, T(1)), m.m, powered));
    } else {
        // No lane on with c > 0 (nor m = 0): every power 0, skipped per step as scalars skip it
        // per point (the same bits).
        if (!math_traits<T>::any(math_traits<T>::both(on, x > T(0))) && !any_zero_exponent<T>(m, on)) return;
        sum += in_type<T>(specular_of(L)) * (f * detail::select(on, route_cosine_power<M>(x, scale, m), T(0)));
    }
}

/// 1/|d| of a lit pair: detail::rsqrt_normal, or fast::rsqrt in the fast mode but on float SIMD
/// lanes (their rsqrt_normal, estimate + Newton step, is within fast::rsqrt_max_rel already).
template <evaluation M, class T>
PHONG_INLINE constexpr T lit_inverse_length(T dd)
{
    if constexpr (M == evaluation::fast && (std::is_floating_point_v<T> || !std::is_same_v<scalar_t<T>, float>))
        return fast::rsqrt(dd);
    else return detail::rsqrt_normal(dd);
}

/// l + v with l = d inv not rounded first: d inv + v, one fma per component (SIMD lanes).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr glm::vec<3, T, Q> unrounded_halfway_sum(const glm::vec<3, T, Q>& d, T inv, const glm::vec<3, T, Q>& v)
{
    return {math_traits<T>::fma(d.x, inv, v.x), math_traits<T>::fma(d.y, inv, v.y), math_traits<T>::fma(d.z, inv, v.z)};
}

/// 1/|h| where |h|^2 >= min_square (below: l = -v, no halfway vector), else 0.
template <evaluation M, class T, glm::qualifier Q>
PHONG_INLINE constexpr T inverse_length_at_least(const glm::vec<3, T, Q>& h, T min_square)
{
    const T hh = detail::dot(h, h);
    return detail::select(hh >= min_square, lit_inverse_length<M>(hh), T(0));
}

/// Blinn's 1/|l + v| (inverse_halfway_length), or in the fast mode fast::rsqrt, 0 where
/// |l + v| < 4 fast::rsqrt_max_rel (l = -v within the fast 1/|d|'s error: n.h taken as 0).
template <evaluation M, class T, glm::qualifier Q>
PHONG_INLINE constexpr T route_inverse_halfway_length(const glm::vec<3, T, Q>& l, const glm::vec<3, T, Q>& v)
{
    if constexpr (M == evaluation::fast) {
        constexpr double er = fast::detail::rsqrt_max_rel<scalar_t<T>>;
        return inverse_length_at_least<M>(l + v, T(scalar_t<T>(16 * er * er)));
    } else if constexpr (!std::is_same_v<mask_t<T>, bool>) {
        // SIMD lanes: lit lanes have |l + v|^2 <= 4, so only l = -v needs a test.
        return inverse_length_at_least<M>(l + v, exact_min_square<T>());
    } else {
        return detail::inverse_halfway_length(l, v);
    }
}

/// Blinn's 1/|l + v| on SIMD lanes, exact mode: h = d inv + v by fma (no rounded l), 0 where
/// |h|^2 < halfway_min (u^2, or +inf per lane without a view vector). fl(d inv) = -v leaves
/// |h| <= u / 2, taken as n.h = 0; no case with an exact bound is zeroed (accuracy.hpp).
template <class T, glm::qualifier Q>
PHONG_INLINE constexpr T lanes_inverse_halfway_length(const glm::vec<3, T, Q>& d, T inv, const glm::vec<3, T, Q>& v, T halfway_min)
{
    return inverse_length_at_least<evaluation::exact>(unrounded_halfway_sum(d, inv, v), halfway_min);
}

/// Blinn's specular term, fast mode, SIMD lanes, integer shininess n >= 1 (nl = n.l, 0 where off):
///   h = d inv + v (fma), n.h = (n.l + n.v) / |h|;
///   n even: ((n.l + n.v)^2 / hh)^(n/2), 1/hh by fast::detail::reciprocal_normal (no square root,
///           one squaring fewer; base error u + reciprocal_max_rel / 2, below the 1/|h| route's);
///   n odd:  (n.l + n.v) rsqrt_normal(hh).
/// Base 0 where hh < 16 fast::rsqrt_max_rel^2 (l = -v within l's error), n.l + n.v <= 0, or off.
/// l is not rounded before l + v: one rounding is more accurate (fast does not cancel l = -v exactly).
template <class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, unsigned K>
PHONG_INLINE constexpr void add_halfway_specular_fast(Sums<T, Q>& sums, const Light& L, T f, T nl, T inv, const glm::vec<3, T, Q>& d,
                                                  const surface_frame<T, Q>& s, const integer_exponent<T, K>& m, mask_t<T> on)
{
    using S = scalar_t<T>;
    // n.(l + v); nv_seen = -inf where the point has no view vector, so it is not positive
    const T numerator = nl + s.lanes.nv_seen;
    const mask_t<T> positive = math_traits<T>::both(on, numerator > T(0));
    if (!math_traits<T>::any(positive)) return; // every power 0: the sum would gain +0
    const glm::vec<3, T, Q> h(math_traits<T>::fma(d.x, inv, s.view.x), math_traits<T>::fma(d.y, inv, s.view.y),
                              math_traits<T>::fma(d.z, inv, s.view.z));
    const T hh = detail::dot(h, h);
    constexpr double er = fast::detail::rsqrt_max_rel<S>;
    const mask_t<T> defined = math_traits<T>::both(positive, hh >= T(S(16 * er * er)));
    T power;
    if (m.is_even()) power = m.half_power(detail::select(defined, (numerator * numerator) * fast::detail::reciprocal_normal(hh), T(0)));
    else power = m.power(detail::select(defined, numerator * detail::rsqrt_normal(hh), T(0)));
    sum_of<term_kind::specular>(sums) += in_type<T>(specular_of(L)) * (f * power);
}

/// A pair's geometry (light_terms_of), for add_light_terms: d = L.xyz - w Q, 1/|d| where read, the
/// unit light vector l (spot, Blinn), the light factor f, n.d, n.l, and whether the pair is lit.
template <class T, glm::qualifier Q>
struct light_terms {
    glm::vec<3, T, Q> d;
    glm::vec<3, T, Q> l;
    T inv, f, nd, nl;
    mask_t<T> on;
};

/// The first half of add_light: the pair's geometry, up to n.l.
template <features F, class T, glm::qualifier Q, class Light, class W>
PHONG_INLINE constexpr light_terms<T, Q> light_terms_of(const surface_frame<T, Q>& s, const Light& L, W visibility)
{
    using vec3 = glm::vec<3, T, Q>;
    light_terms<T, Q> t{vec3(T(0)), vec3(T(0)), T(0), T(0), T(0), T(0), mask_t<T>(false)};
    const T w = light_w<F, T>(L);
    decltype(auto) p = position_of(L);
    vec3& d = t.d;
    if constexpr (F.lights == light_kind::positional && !std::is_floating_point_v<T>)
        d = vec3(T(p.x), T(p.y), T(p.z)) + s.lanes.minus_position; // L.xyz - Q, the same bits (see lanes_frame)
    else d = detail::homogeneous_difference<F.lights>(vec3(T(p.x), T(p.y), T(p.z)), w, s.position);
    const T dd = detail::dot(d, d);
    t.nd = detail::dot(s.normal, d);

    // l: the unit light vector, read by the spot (every pair) and by Blinn; inv = 1/|d|
    if constexpr (F.spot != spot_model::none) {
        t.inv = exact_inverse_length(dd);
        t.l = d * t.inv;
        for (glm::length_t k = 0; k < 3; ++k) t.l[k] = detail::select(t.inv > T(0), t.l[k], T(0)); // an overflowed d: inf * 0
    }
    T distance = T(0); // only attenuation reads it
    if constexpr (F.attenuation != attenuation_model::none && F.lights != light_kind::directional) distance = detail::sqrt(dd);
    t.f = light_factor<F>(L, distance, w, t.l, visibility);

    t.on = lit<F>(s, dd, t.nd);
    // Scalars stop at an unlit pair (nl not computed). SIMD lanes select every term by `on` (off
    // lanes may compute inf or NaN, never added): a branch per light would mispredict.
    if constexpr (std::is_same_v<mask_t<T>, bool>) {
        if (!t.on) return t;
    }
    if constexpr (F.specular == specular_model::none && F.spot == spot_model::none) {
        t.nl = t.nd / detail::sqrt(dd); // one rounding (SIMD lanes that are off may divide by 0: not selected)
    } else {
        if constexpr (F.spot == spot_model::none) t.inv = lit_inverse_length<F.mode>(dd); // lanes where dd is not normal are not lit: selected away
        t.nl = t.nd * t.inv;
    }
    return t;
}

/// The second half of add_light: the pair's terms (light_terms_of) added to the sums.
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class Exponent>
PHONG_INLINE constexpr void add_light_terms(Sums<T, Q>& sums, const surface_frame<T, Q>& s, const Light& L, const Exponent& m,
                                            light_terms<T, Q> t)
{
    using vec3 = glm::vec<3, T, Q>;
    const vec3& d = t.d;
    const T f = t.f, nl = t.nl, inv = t.inv;
    const mask_t<T> on = t.on;
    add_ambient<F>(sums, L, f);
    if constexpr (std::is_same_v<mask_t<T>, bool>) {
        if (!on) return;
    }
    // Scalars with light_sums add diffuse last (the same bits), so a colour read by both terms is not
    // held across the power; SIMD lanes and folded_sums: diffuse first (docs/batch.md).
    constexpr bool diffuse_last = std::is_floating_point_v<T> && std::is_same_v<Sums<T, Q>, light_sums<T, Q>>;
    if constexpr (F.diffuse && !diffuse_last) add_diffuse<F>(sums, L, f, nl, on);
    // Phong with the fast integer power: no view vector means v = 0, a cosine 0 and power 0 (NaN v:
    // poisoned): no sees_viewer test per pair; step_specular's threshold and halfway_min do the same.
    static_assert(!std::is_same_v<Exponent, step_specular<T>> || step_specular_route<F>);
    [[maybe_unused]] mask_t<T> specular_on;
    if constexpr ((F.specular == specular_model::phong && is_integer_exponent<Exponent, T>) ||
                  std::is_same_v<Exponent, step_specular<T>>)
        specular_on = on;
    else specular_on = math_traits<T>::both(on, s.sees_viewer);
    if constexpr (F.specular == specular_model::phong) {
        add_specular<F.mode>(sums, L, f, detail::reflection_cosine_scaled(t.nd, s.nv, d, s.view), inv, m, specular_on);
    } else if constexpr (F.specular == specular_model::blinn && F.spot == spot_model::none &&
                         is_integer_exponent<Exponent, T>) {
        add_halfway_specular_fast(sums, L, f, detail::select(on, nl, T(0)), inv, d, s, m, on);
    } else if constexpr (F.specular == specular_model::blinn && F.spot == spot_model::none && F.mode == evaluation::exact &&
                         !std::is_same_v<mask_t<T>, bool>) {
        add_specular<F.mode>(sums, L, f, nl + s.nv, lanes_inverse_halfway_length(d, inv, s.view, halfway_min_of<T>(m)), m, specular_on);
    } else if constexpr (F.specular == specular_model::blinn) {
        // Rounded products: an fma contracted into l + v would keep l = -v from cancelling exactly.
        if constexpr (F.spot == spot_model::none)
            t.l = vec3(detail::rounded_product(d.x, inv), detail::rounded_product(d.y, inv), detail::rounded_product(d.z, inv));
        add_specular<F.mode>(sums, L, f, nl + s.nv, route_inverse_halfway_length<F.mode>(t.l, s.view), m, specular_on);
    }
    if constexpr (F.diffuse && diffuse_last) add_diffuse<F>(sums, L, f, nl, on);
}

/// One light's terms added to the sums (light_terms_of, then add_light_terms). Light: a
/// light_source of scalar T, or float lights in double (the stable mode's wider route); visibility:
/// unweighted or a weight in [0, 1]; m: T, or on SIMD lanes lane_shininess, integer_exponent or
/// step_specular. Dot products use d itself, scaled by 1/|d| only for lit pairs: the branch signs
/// do not wait for a square root.
template <features F, class T, glm::qualifier Q, template <class, glm::qualifier> class Sums, class Light, class Exponent, class W>
PHONG_INLINE constexpr void add_light(Sums<T, Q>& sums, const surface_frame<T, Q>& s, const Light& L, const Exponent& m, W visibility)
{
    add_light_terms<F>(sums, s, L, m, light_terms_of<F>(s, L, visibility));
}

} // namespace phong::detail::exact
#include "../core/diagnostics_pop.hpp"
