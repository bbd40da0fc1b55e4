// libFuzzer target for phong::shade_batch against the scalar phong::shade (issue 15 item 1).
// SPDX-License-Identifier: MIT
//
// Build (see build_batch.sh): twice, at the baseline ISA (SSE2: 4 float / 2 double lanes) and
// with -march=native (AVX-512 here: 16 / 8 lanes), clang++ -fsanitize=fuzzer,address,undefined.
// Run:                        ./fuzz_batch corpus_batch/ -max_total_time=30
//
// Input: byte 0 selects the feature set (bits 0-3, `feature_table` below), double or float (bit 4),
// one material per point or one shared (bit 5), interleaved or SoA output (bit 6), front_facing
// flags read from the input (bit 7). Then the point count N (1-48), the light count (1-4), the
// environment, the lights, the material(s) and the points. Scalars are decoded as in fuzz_shade
// (raw bit patterns, special values, grid values); past the end of the input, grid values from a
// generator seeded by the input (`reader`). Material and light parameters are folded into
// the documented domain (absolute values, ranges) and coefficients capped at 2^16, and then kept
// only if validate() accepts them (a rejected light is dropped, a rejected material replaced by
// the default): shade_batch is only defined on validated parameters.
//
// Checks (a violation calls __builtin_trap(), so libFuzzer saves the input):
//  1. No sanitizer report (ASan, UBSan) for any accepted parameters (huge shininess and spot
//     exponents included, the inputs that found xsimd's exp float-cast-overflow).
//  2. Per point, finite geometry (and finite eye where the view model reads it): every channel of
//     shade_batch is finite and >= 0 (no NaN, no inf: the 2^16 caps keep the exact colour far
//     below overflow, see `bound_slack`), alpha is the material's alpha; non-finite geometry: NaN
//     in every channel, as shade<F> (shade.hpp's policy).
//  3. Agreement with the scalar shade<F> point by point within `tolerance` (derived below), where
//     the comparison is meaningful: away from the model's discontinuities (the specular gate
//     n.l = 0, the two-sided flip n.v = 0, a spot cutoff or hard cone edge, Blinn's l = -v), away
//     from L.xyz - w Q overflowing T, or E.xyz - E.w Q outside the stable mode (no direction in T,
//     one in float's wider route), and for the exact mode only on moderate geometry (documented as
//     inaccurate outside).
#include <phong/batch.hpp>
#include "decode.hpp"

#include <phong/phong.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace {

using wide = long double;
using namespace phong;

// ---------------------------------------------------------------------------------------------
// Reporting
// ---------------------------------------------------------------------------------------------

struct statistics {
    unsigned long lights_kept = 0, lights_rejected = 0;
    unsigned long inputs = 0, points = 0, finite_checked = 0, nan_checked = 0, compared = 0, skipped_edge = 0, differing = 0;
    wide worst_ratio = 0; ///< max |batch - scalar| / tolerance over the compared channels
    wide worst_regular = 0; ///< the same without powers of exponent in (0, 1) (Hoelder: tolerance ~ the term)
    ~statistics()
    {
        std::fprintf(stderr,
                     "fuzz_batch: %lu inputs, %lu points, %lu finiteness checks, %lu NaN-policy checks, %lu compared "
                     "with the scalar path (%lu skipped at a discontinuity, %lu channels not bitwise equal); worst |batch - scalar| / "
                     "tolerance = %.3Lg\n",
                     inputs, points, finite_checked, nan_checked, compared, skipped_edge, differing, worst_ratio);
        std::fprintf(stderr, "fuzz_batch: %lu lights kept, %lu rejected by validate; worst ratio with every exponent 0 or >= 1: %.3Lg\n",
                     lights_kept, lights_rejected, worst_regular);
    }
} stats;

void (*describe_input)() = nullptr;

[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "fuzz_batch: check failed: %s\n", what);
    if (describe_input) describe_input();
    __builtin_trap();
}
#define FUZZ_CHECK(cond, what) \
    do {                       \
        if (!(cond)) fail(what); \
    } while (0)

// ---------------------------------------------------------------------------------------------
// Decoding (the scalar encoding of fuzz_shade.cpp)
// ---------------------------------------------------------------------------------------------

/// Bytes of the input, then (once it is exhausted) grid-value bytes 0x40-0xFF from a generator
/// seeded by the input: short inputs still give full scenes with nonzero coefficients, and
/// libFuzzer's mutations of any byte change the whole tail.
struct reader {
    const std::uint8_t* data;
    std::size_t size;
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    reader(const std::uint8_t* d, std::size_t n) : data(d), size(n)
    {
        for (std::size_t i = 0; i < n; ++i) state = (state ^ d[i]) * 0x100000001B3ull;
    }
    std::uint8_t byte()
    {
        if (size == 0) {
            state += 0x9E3779B97F4A7C15ull; // splitmix64
            std::uint64_t z = state;
            z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
            z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
            z ^= z >> 31;
            return std::uint8_t(0x40 + z % 0xC0);
        }
        --size;
        return *data++;
    }
};

using phong_fuzz::scalar;
using phong_fuzz::vec;

constexpr wide coefficient_cap = 65536; // strengths, reflectivities, emission, scene ambient

/// Into the domain: NaN and inf become 1, negatives their absolute value, capped at 2^16.
template <class T> T coefficient(T x) { return std::isfinite(x) ? std::min(std::fabs(x), T(coefficient_cap)) : T(1); }
template <class T> glm::vec<3, T> coefficient(const glm::vec<3, T>& v) { return {coefficient(v.x), coefficient(v.y), coefficient(v.z)}; }
template <class T> T non_negative(T x) { return std::isfinite(x) ? std::fabs(x) : T(1); }
template <class T> T folded(T x, T lo, T hi) { return std::isfinite(x) ? std::clamp(x, lo, hi) : hi; }

/// Flags: bit 0 w (0 or 1), bit 2 range = inf, bits 3, 6 and 7 all set: the axis as decoded (else
/// normalized), bit 4 cos_cutoff = -1,
/// bit 5 aim the axis exactly at `aim` (the first point) so that the spot cosine is 1 there.
template <class T> light<T> decode_light(reader& in, const glm::vec<3, T>& aim)
{
    light<T> L;
    const std::uint8_t flags = in.byte();
    glm::vec<3, T> xyz = vec<3, T>(in, true);
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(xyz[k])) xyz[k] = T(1);
    L.position = glm::vec<4, T>(xyz, (flags & 1) ? T(1) : T(0));
    L.ambient = coefficient(vec<3, T>(in));
    L.diffuse = coefficient(vec<3, T>(in));
    L.specular = coefficient(vec<3, T>(in));
    auto& a = L.attenuation;
    a.constant = non_negative(scalar<T>(in));
    a.linear = non_negative(scalar<T>(in));
    a.quadratic = non_negative(scalar<T>(in));
    if (a.constant == 0 && a.linear == 0 && a.quadratic == 0) a.constant = T(1);
    a.range = (flags & 4) ? std::numeric_limits<T>::infinity() : scalar<T>(in);
    if (std::isnan(a.range) || a.range == 0) a.range = std::numeric_limits<T>::infinity();
    a.range = std::fabs(a.range);
    glm::vec<3, T> axis = vec<3, T>(in, true);
    if (flags & 32) axis = aim - xyz;
    if ((flags & 0xC8) != 0xC8) { // normalized in long double, rounded once (bits 3, 6, 7: as decoded, often rejected)
        const wide x = axis.x, y = axis.y, z = axis.z, len = std::sqrt(x * x + y * y + z * z);
        axis = std::isfinite(len) && len > 0 ? glm::vec<3, T>(T(x / len), T(y / len), T(z / len)) : glm::vec<3, T>(0, 0, -1);
    }
    L.spot.direction = axis;
    L.spot.exponent = non_negative(scalar<T>(in));
    L.spot.cos_cutoff = (flags & 16) ? T(-1) : folded(std::fabs(scalar<T>(in, true)), T(0), T(1));
    L.spot.cos_inner = folded(scalar<T>(in, true), T(-1), T(1));
    L.spot.cos_outer = folded(scalar<T>(in, true), T(-1), T(1));
    if (L.spot.cos_outer > L.spot.cos_inner) std::swap(L.spot.cos_outer, L.spot.cos_inner);
    return L;
}

template <class T> material<T> decode_material(reader& in)
{
    material<T> m;
    m.ka = coefficient(vec<3, T>(in));
    m.kd = coefficient(vec<3, T>(in));
    m.ks = coefficient(vec<3, T>(in));
    m.emission = coefficient(vec<3, T>(in));
    m.shininess = non_negative(scalar<T>(in));
    m.alpha = folded(scalar<T>(in), T(0), T(1));
    if (!validate(m)) m = material<T>{};
    return m;
}

template <class T> struct scene {
    std::size_t n = 0;
    std::vector<T> px, py, pz, nx, ny, nz;
    std::vector<material<T>> mats; // one per point (a shared material is repeated)
    std::unique_ptr<bool[]> front;
    bool per_point = false, read_front = false, interleaved = false;
    environment<T> env;
    std::vector<light<T>> lights;
};

template <class T> const scene<T>* current = nullptr;
std::size_t current_features = 0, current_point = 0;
template <class T> void describe()
{
    const scene<T>& s = *current<T>;
    std::fprintf(stderr, "features #%zu, %s, %zu points (%s materials, %s output), %zu lights; point %zu:\n",
                 current_features, sizeof(T) == 4 ? "float" : "double", s.n, s.per_point ? "per-point" : "shared",
                 s.interleaved ? "interleaved" : "SoA", s.lights.size(), current_point);
    const std::size_t i = current_point;
    if (i < s.n) {
        std::fprintf(stderr, "  Q = (%.17Lg, %.17Lg, %.17Lg), n = (%.17Lg, %.17Lg, %.17Lg), front %d\n", wide(s.px[i]),
                     wide(s.py[i]), wide(s.pz[i]), wide(s.nx[i]), wide(s.ny[i]), wide(s.nz[i]), int(s.front[i]));
        const material<T>& m = s.mats[i];
        std::fprintf(stderr, "  ka %.9Lg %.9Lg %.9Lg kd %.9Lg %.9Lg %.9Lg ks %.9Lg %.9Lg %.9Lg m %.17Lg alpha %.9Lg\n",
                     wide(m.ka.x), wide(m.ka.y), wide(m.ka.z), wide(m.kd.x), wide(m.kd.y), wide(m.kd.z), wide(m.ks.x),
                     wide(m.ks.y), wide(m.ks.z), wide(m.shininess), wide(m.alpha));
    }
    std::fprintf(stderr, "  La = (%.9Lg, %.9Lg, %.9Lg), eye = (%.17Lg, %.17Lg, %.17Lg, %.17Lg)\n", wide(s.env.ambient.x),
                 wide(s.env.ambient.y), wide(s.env.ambient.z), wide(s.env.eye.x), wide(s.env.eye.y), wide(s.env.eye.z),
                 wide(s.env.eye.w));
    for (const light<T>& L : s.lights)
        std::fprintf(stderr,
                     "  light (%.17Lg, %.17Lg, %.17Lg, %Lg) amb %.9Lg dif %.9Lg spec %.9Lg att %.9Lg %.9Lg %.9Lg range %.9Lg "
                     "axis (%.17Lg, %.17Lg, %.17Lg) e %.17Lg cutoff %.17Lg inner %.17Lg outer %.17Lg\n",
                     wide(L.position.x), wide(L.position.y), wide(L.position.z), wide(L.position.w), wide(L.ambient.x),
                     wide(L.diffuse.x), wide(L.specular.x), wide(L.attenuation.constant), wide(L.attenuation.linear),
                     wide(L.attenuation.quadratic), wide(L.attenuation.range), wide(L.spot.direction.x),
                     wide(L.spot.direction.y), wide(L.spot.direction.z), wide(L.spot.exponent), wide(L.spot.cos_cutoff),
                     wide(L.spot.cos_inner), wide(L.spot.cos_outer));
}

// ---------------------------------------------------------------------------------------------
// The tolerance of batch against scalar, point by point.
//
// Both paths run the same templates (shade.hpp) on the same inputs; they differ only in the
// rounding of individual operations: the float lanes' rsqrt (hardware estimate + Newton, < 2 ulp,
// against 1/sqrt), xsimd's exp/log/log1p (a few ulp) against libm's, FMA contraction, and for the
// float stable mode the scalar's wider (double) route against the batch's twofold one (both a few
// ulp of the exact model, accuracy.hpp). So with eps = epsilon<T>:
//  * every unit vector differs by a few eps, every cosine (n.l, r.v, n.h, the spot's -l.s) by at
//    most K eps absolute, K = 16; every product, sum and the attenuation by a few eps relative:
//    at most K0 eps relative to the channel's scale S (below), K0 = 2 (8 lights + 32) + 8 K
//    (twice fuzz_shade's rounding slack for one path, plus the windowed attenuation's window,
//    whose derivative in d is at most 8 / range: 8 K eps of 1 / d^2);
//  * the scale S = emission + ka (La + sum_i g_i La_i) + sum_i a_i (kd Ld_i + ks Ls_i), with a_i
//    the attenuation (polynomial: its value; windowed: its cap 1 / max(d^2, dmin), the window is
//    <= 1; 1 without attenuation or for directional lights) and g_i = a_i (attenuate_ambient) or
//    1: every term of the model with each factor <= 1 (cosines, powers, spot) at its largest;
//  * a power t^p of a cosine t in [0, 1] known to delta = K eps moves by at most
//    amp(p) = p delta for p >= 1 (derivative p t^(p-1) <= p), delta^p for 0 < p < 1 (Hoelder),
//    0 for p = 0, capped at 1 (the power is in [0, 1]). This is the exact mode's specular factor
//    (p = m: the "amplified by m" of batch.hpp's doc), the OpenGL spot's clamp(c, 0, 1)^e
//    (p = e, both modes), and Blinn's exact n.h, whose delta grows to K eps (1 + 2 / |l + v|)
//    (h = normalize(l + v) loses accuracy as l + v cancels).
//  * the stable mode's specular (1 - x)^m = exp(m log1p(-x)), x = |chord|^2 / 2 carried with
//    relative error ~ eps: d/dx changes it by m (1 - x)^(m-1) x eps <= eps / e for m >= 1, and
//    exp's relative error times |m log1p(-x)| e^(m log1p(-x)) <= 1/e: at most K eps, whatever m;
//    for m < 1 Hoelder again: delta^m.
//  * the smooth spot smoothstep((c - cos_outer) / width) has slope <= 1.5 / width: 1.5 K eps / width.
// Tolerance per channel: K0 eps S + sum_i a_i [(ka La_i [attenuate_ambient] + kd Ld_i + ks Ls_i)
// spot_error_i + ks Ls_i spec_error_i] + 64 k_max denorm_min (results in the subnormal range, k_max
// the largest material coefficient or 1); a light
// whose a_i is below T's normal range (denominator beyond max, or f subnormal) is uncertain as a
// whole: a_i (ka La_i + kd Ld_i + ks Ls_i) more.
// ---------------------------------------------------------------------------------------------

constexpr wide K = 16;

template <class T> wide eps() { return std::numeric_limits<T>::epsilon(); }
template <class T> wide dmin() { return std::ldexp(wide(1), (std::numeric_limits<T>::min_exponent - 1) / 2); }

/// How much t^p moves when t in [0, 1] moves by delta.
wide power_error(wide p, wide delta)
{
    if (p == 0) return 0;
    if (p >= 1) return std::min(wide(1), p * delta);
    return std::min(wide(1), std::pow(delta, p));
}

struct wvec {
    wide x, y, z;
};
wide dot(const wvec& a, const wvec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
wide norm(const wvec& a) { return std::sqrt(dot(a, a)); }
wvec scaled(const wvec& a, wide s) { return {a.x * s, a.y * s, a.z * s}; }
wvec operator+(const wvec& a, const wvec& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
wvec operator-(const wvec& a, const wvec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class T> wvec widen(const glm::vec<3, T>& v) { return {wide(v.x), wide(v.y), wide(v.z)}; }

/// Exact-mode geometry that mode handles: zero or a magnitude in [2^-e, 2^e] (e = 15 float, 120
/// double; fuzz_shade's `moderate`), every vector it normalizes likewise.
template <class T> bool moderate(wide a)
{
    constexpr int e = sizeof(T) == 4 ? 15 : 120;
    a = std::fabs(a);
    return a == 0 || (a >= std::ldexp(wide(1), -e) && a <= std::ldexp(wide(1), e));
}
template <class T> bool moderate(const wvec& v) { return moderate<T>(v.x) && moderate<T>(v.y) && moderate<T>(v.z); }
template <class T> bool moderate_length(const wvec& v)
{
    const wide l = norm(v);
    return l > 0 && moderate<T>(l);
}

struct tolerance_result {
    bool comparable = false;
    bool hoelder = false; ///< a power with exponent in (0, 1) (shininess or spot): delta^p, nearly the whole term
    wide tol[3]{};
};

template <features F, class T>
tolerance_result tolerance(const scene<T>& s, std::size_t i)
{
    tolerance_result out;
    const wide e = eps<T>(), delta = K * e, edge = 4 * delta;
    const bool exact = F.mode == evaluation::exact;
    const material<T>& mat = s.mats[i];
    const wvec Q{wide(s.px[i]), wide(s.py[i]), wide(s.pz[i])};
    wvec n{wide(s.nx[i]), wide(s.ny[i]), wide(s.nz[i])};
    wvec v{};
    if constexpr (F.view == view_model::eye_at_origin) v = scaled(Q, -1);
    else if constexpr (F.view == view_model::fixed_direction) v = widen(glm::vec<3, T>(s.env.eye));
    else v = widen(glm::vec<3, T>(s.env.eye)) - scaled(Q, wide(s.env.eye.w));
    if (norm(n) == 0 || norm(v) == 0) return out; // no diffuse or specular at all: fuzz_shade's domain
    // A homogeneous difference P.xyz - P.w Q beyond the range of T (|P.w Q| or the difference
    // itself > max) has no direction in T (shade.hpp), but float's wider route (double) has one:
    // the two routes legitimately disagree there.
    const wide top = std::numeric_limits<T>::max();
    const auto overflows = [&](const wvec& xyz, wide w) {
        const wvec wq = scaled(Q, w), d = xyz - wq;
        for (wide x : {wq.x, wq.y, wq.z, d.x, d.y, d.z})
            if (std::fabs(x) > top) return true;
        return false;
    };
    // The stable mode forms E.xyz - E.w Q scaled by powers of two (detail/stable.hpp's prepare):
    // it has the viewer's direction however large E.w Q is.
    if (F.view == view_model::eye_point && F.mode != evaluation::stable &&
        overflows(widen(glm::vec<3, T>(s.env.eye)), wide(s.env.eye.w)))
        return out;
    if (exact && !(moderate<T>(Q) && moderate<T>(n) && moderate_length<T>(n) && moderate_length<T>(v) &&
                   (F.view == view_model::eye_at_origin || moderate<T>(widen(glm::vec<3, T>(s.env.eye))))))
        return out;
    n = scaled(n, 1 / norm(n));
    v = scaled(v, 1 / norm(v));
    if constexpr (F.two_sided == facing::view) {
        const wide nv = dot(n, v);
        if (std::fabs(nv) < edge) return out;
        if (nv < 0) n = scaled(n, -1);
    } else if constexpr (F.two_sided == facing::flag) {
        if (s.read_front && !s.front[i]) n = scaled(n, -1);
    }
    const std::size_t count = s.lights.size();
    const wide K0 = 2 * (8 * wide(count) + 32) + 8 * K;
    wide scale[3], extra[3];
    for (int c = 0; c < 3; ++c) {
        wide La = F.scene_ambient ? wide(s.env.ambient[c]) : 0;
        scale[c] = (F.emission ? wide(mat.emission[c]) : 0) + wide(mat.ka[c]) * La;
        extra[c] = 0;
    }
    const wide m = mat.shininess;
    for (const light<T>& L : s.lights) {
        const wide w = F.lights == light_kind::positional ? 1 : F.lights == light_kind::directional ? 0 : wide(L.position.w);
        if (overflows(widen(glm::vec<3, T>(L.position)), w)) return out;
        const wvec d = widen(glm::vec<3, T>(L.position)) - scaled(Q, w);
        const wide dist = norm(d);
        if (exact && dist > 0 && !(moderate<T>(widen(glm::vec<3, T>(L.position))) && moderate_length<T>(d))) return out;
        wide a = 1; // attenuation scale
        if constexpr (F.attenuation != attenuation_model::none) {
            if (w == 1) {
                if constexpr (F.attenuation == attenuation_model::polynomial)
                    a = 1 / std::max(wide(L.attenuation.constant) + dist * (wide(L.attenuation.linear) + wide(L.attenuation.quadratic) * dist), dmin<T>());
                else
                    a = 1 / std::max(dist * dist, dmin<T>());
            }
        }
        const wvec l = dist > 0 ? scaled(d, 1 / dist) : wvec{0, 0, 0};
        const wide nl = dot(n, l);
        wide spot_error = 0;
        if constexpr (F.spot != spot_model::none) {
            const wide cs = -dot(l, widen(L.spot.direction));
            if constexpr (F.spot == spot_model::opengl) {
                if (wide(L.spot.cos_cutoff) > -1) {
                    if (std::fabs(cs - wide(L.spot.cos_cutoff)) < edge) return out; // the cutoff
                    spot_error = power_error(wide(L.spot.exponent), delta);
                    out.hoelder = out.hoelder || (L.spot.exponent > 0 && L.spot.exponent < 1);
                }
            } else {
                const wide width = wide(L.spot.cos_inner) - wide(L.spot.cos_outer);
                if (width <= 0) {
                    if (std::fabs(cs - wide(L.spot.cos_outer)) < edge) return out; // hard edge
                } else {
                    spot_error = std::min(wide(1), wide(1.5) * delta / width);
                }
            }
        }
        wide spec_error = 0;
        if constexpr (F.specular != specular_model::none) {
            if (F.specular_gate && std::fabs(nl) < edge) return out; // the gate n.l > 0
            wide base_error = delta;
            if constexpr (F.specular == specular_model::blinn) {
                const wide lv = norm(l + v);
                if (dist > 0 && lv < wide(1e-3)) return out; // l = -v: n.h taken as 0
                if (exact && dist > 0) base_error = delta * (1 + 2 / lv);
            }
            out.hoelder = out.hoelder || (m > 0 && m < 1);
            if (exact) spec_error = power_error(m, base_error);
            else spec_error = m >= 1 ? delta : power_error(m, delta) + delta;
            // Float's stable scalar is the wider route: the exact formulas in double, whose cosine
            // carries K 2^-53 that the power amplifies by m (shade.hpp: correctly rounded while
            // m 2^-53 stays far below float's eps; m = 9e27 at the highlight found this).
            if (!exact && std::is_same_v<T, float>)
                spec_error = std::max(spec_error, power_error(m, K * std::ldexp(wide(1), -53)));
            // The twofold route (double, and float's batch) knows 1 - cosine to ~eps^2 absolute,
            // which the power amplifies by m: beyond m ~ 1/eps^2 even exactly parallel vectors
            // (cosine 1, factor 1) may give 0 (found by fuzz_batch_native: double, Blinn,
            // m = 1.08e236, n = l = v = (1, 1, 1)/sqrt(3): batch 1, scalar 0).
            if (!exact) spec_error = std::max(spec_error, power_error(m, K * e * e));
        }
        for (int c = 0; c < 3; ++c) {
            const wide ambient = wide(mat.ka[c]) * wide(L.ambient[c]);
            if (F.light_ambient) scale[c] += (F.attenuate_ambient ? a : 1) * ambient;
            const wide lit = (F.diffuse ? wide(mat.kd[c]) * wide(L.diffuse[c]) : 0) +
                             (F.specular != specular_model::none ? wide(mat.ks[c]) * wide(L.specular[c]) : 0);
            scale[c] += a * lit;
            const wide spotted = lit + (F.light_ambient && F.attenuate_ambient ? ambient : 0);
            extra[c] += a * (spotted * spot_error + (F.specular != specular_model::none ? wide(mat.ks[c]) * wide(L.specular[c]) : 0) * spec_error);
            // An attenuation below T's normal range (a denominator beyond max, or a subnormal f)
            // is lost in T arithmetic, while float's wider route (double) keeps it: the whole
            // term is uncertain (found by fuzz_batch_native: 1e-40 against 0 at d = 9e19).
            if (a < wide(std::numeric_limits<T>::min())) extra[c] += a * spotted;
        }
    }
    out.comparable = true;
    // Gradual underflow: a sum rounded in the subnormal range is off by up to a subnormal half-ulp,
    // which the material coefficient then multiplies where the material is not folded into the
    // lights (found: kd = 65536 times Ld n.l = 2e-44, stable float batch against the wider scalar,
    // 2e-42 apart); so the absolute allowance scales with the largest coefficient, as fuzz_shade's
    // and accuracy::exact_absolute_allowance do.
    wide k_max = 1;
    for (int c = 0; c < 3; ++c) k_max = std::max({k_max, wide(mat.ka[c]), wide(mat.kd[c]), wide(mat.ks[c])});
    for (int c = 0; c < 3; ++c)
        out.tol[c] = K0 * e * scale[c] + extra[c] + 64 * k_max * wide(std::numeric_limits<T>::denorm_min());
    return out;
}

// ---------------------------------------------------------------------------------------------
// One feature set
// ---------------------------------------------------------------------------------------------

template <features F, class T>
void check(scene<T>& s)
{
    constexpr int channels = F.alpha ? 4 : 3;
    const std::size_t n = s.n;
    const soa3<T> pos{s.px, s.py, s.pz}, nor{s.nx, s.ny, s.nz};
    const std::span<const light<T>> lights(s.lights);
    const std::span<const bool> front(s.front.get(), s.read_front ? n : 0);
    std::vector<std::array<T, 4>> got(n);
    if (s.interleaved) {
        std::vector<color<F, T>> out(n);
        if (s.per_point) shade_batch<F>(pos, nor, std::span<const material<T>>(s.mats), lights, std::span<color<F, T>>(out), s.env, front);
        else shade_batch<F>(pos, nor, s.mats[0], lights, std::span<color<F, T>>(out), s.env, front);
        for (std::size_t i = 0; i < n; ++i)
            for (int c = 0; c < channels; ++c) got[i][c] = out[i][c];
    } else {
        std::vector<T> r(n), g(n), b(n), a(n);
        const soa_rgba<T> out{r, g, b, F.alpha ? std::span<T>(a) : std::span<T>()};
        if (s.per_point) shade_batch<F>(pos, nor, std::span<const material<T>>(s.mats), lights, out, s.env, front);
        else shade_batch<F>(pos, nor, s.mats[0], lights, out, s.env, front);
        for (std::size_t i = 0; i < n; ++i) got[i] = {r[i], g[i], b[i], a[i]};
    }
    const bool eye_read = F.view != view_model::eye_at_origin;
    for (std::size_t i = 0; i < n; ++i) {
        current_point = i;
        ++stats.points;
        const glm::vec<3, T> Q(s.px[i], s.py[i], s.pz[i]), N(s.nx[i], s.ny[i], s.nz[i]);
        const bool facing = s.read_front ? s.front[i] : true;
        const auto want = shade<F>(Q, N, s.mats[i], lights, s.env, facing);
        const bool geometry_finite = std::isfinite(Q.x) && std::isfinite(Q.y) && std::isfinite(Q.z) && std::isfinite(N.x) &&
                                     std::isfinite(N.y) && std::isfinite(N.z) &&
                                     (F.view != view_model::eye_point ||
                                      (std::isfinite(s.env.eye.x) && std::isfinite(s.env.eye.y) && std::isfinite(s.env.eye.z) && std::isfinite(s.env.eye.w)));
        if (!geometry_finite) {
            ++stats.nan_checked;
            for (int c = 0; c < channels; ++c) FUZZ_CHECK(std::isnan(got[i][c]), "non-finite geometry must give NaN in every channel");
            continue;
        }
        if (eye_read && !(std::isfinite(s.env.eye.x) && std::isfinite(s.env.eye.y) && std::isfinite(s.env.eye.z) && std::isfinite(s.env.eye.w)))
            continue; // orthographic with a non-finite eye direction: outside the documented domain
        ++stats.finite_checked;
        for (int c = 0; c < 3; ++c) {
            FUZZ_CHECK(!std::isnan(got[i][c]), "finite in-domain input gave NaN in shade_batch");
            FUZZ_CHECK(std::isfinite(got[i][c]), "finite in-domain input gave inf in shade_batch");
            FUZZ_CHECK(got[i][c] >= 0, "negative channel in shade_batch");
        }
        if constexpr (F.alpha) FUZZ_CHECK(got[i][3] == s.mats[i].alpha, "alpha channel must be the material's alpha");
        const tolerance_result t = tolerance<F>(s, i);
        if (!t.comparable) {
            ++stats.skipped_edge;
            continue;
        }
        ++stats.compared;
        for (int c = 0; c < 3; ++c) {
            const wide diff = std::fabs(wide(got[i][c]) - wide(want[c]));
            if (diff != 0) ++stats.differing;
#ifdef FUZZ_BATCH_VERBOSE // each new worst ratio above 1/4 (no Hoelder case), with its scene
            if (!t.hoelder && diff / t.tol[c] > std::max(stats.worst_regular, wide(0.25))) {
                std::fprintf(stderr, "new worst: channel %d: batch %.21Lg, scalar %.21Lg, |difference| %.6Lg, tolerance %.6Lg\n", c,
                             wide(got[i][c]), wide(want[c]), diff, t.tol[c]);
                describe<T>();
            }
#endif
            stats.worst_ratio = std::max(stats.worst_ratio, diff / t.tol[c]);
            if (!t.hoelder) stats.worst_regular = std::max(stats.worst_regular, diff / t.tol[c]);
            if (!(diff <= t.tol[c])) {
                std::fprintf(stderr, "channel %d: batch %.21Lg, scalar %.21Lg, |difference| %.6Lg > tolerance %.6Lg\n", c,
                             wide(got[i][c]), wide(want[c]), diff, t.tol[c]);
                fail("shade_batch differs from shade beyond the derived tolerance");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The feature sets (index = low 4 bits of the first byte)
// ---------------------------------------------------------------------------------------------

constexpr features feature_table[] = {
    features{},                                         // Phong, exact, perspective
    features{.mode = evaluation::stable},               // Phong, stable
    features{.specular = specular_model::blinn},        // Blinn, exact
    features{.specular = specular_model::blinn, .mode = evaluation::stable},
    features{.specular = specular_model::none},         // diffuse only, exact
    features{.specular = specular_model::none, .lights = light_kind::positional, .attenuation = attenuation_model::polynomial,
             .mode = evaluation::stable},
    features{.light_ambient = true, .lights = light_kind::positional, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::opengl, .mode = evaluation::stable},
    features{.light_ambient = true, .attenuation = attenuation_model::windowed, .spot = spot_model::smooth,
             .attenuate_ambient = false, .mode = evaluation::exact},
    features{.lights = light_kind::directional, .two_sided = facing::view, .view = view_model::fixed_direction,
             .mode = evaluation::stable},
    features{.specular = specular_model::blinn, .specular_gate = false, .two_sided = facing::flag,
             .view = view_model::eye_point, .emission = true, .alpha = true, .mode = evaluation::stable},
    presets::classic_phong, // exact, eye_point, polynomial, two-sided view, alpha
    presets::with_mode(presets::classic_phong, evaluation::stable),
    presets::blinn_phong_per_light_ambient, // Blinn, exact, positional, eye_point, no gate
    features{.attenuation = attenuation_model::polynomial, .spot = spot_model::opengl, .view = view_model::fixed_direction,
             .mode = evaluation::exact},
    features{.specular = specular_model::blinn, .attenuation = attenuation_model::windowed, .spot = spot_model::smooth,
             .mode = evaluation::stable, .precision = stable_precision::twofold},
    features{.scene_ambient = false, .light_ambient = true, .specular = specular_model::blinn,
             .lights = light_kind::directional, .two_sided = facing::flag, .view = view_model::eye_point,
             .mode = evaluation::exact},
};
constexpr std::size_t feature_count = sizeof(feature_table) / sizeof(feature_table[0]);
static_assert(feature_count == 16);

template <class T, std::size_t... I> void dispatch(std::size_t index, scene<T>& s, std::index_sequence<I...>)
{
    ((index == I ? check<feature_table[I], T>(s) : void()), ...);
}

template <class T> void run(reader& in, std::uint8_t selector)
{
    scene<T> s;
    s.per_point = (selector & 0x20) != 0;
    s.interleaved = (selector & 0x40) != 0;
    s.read_front = (selector & 0x80) != 0;
    s.n = 1 + in.byte() % 48;
    const std::size_t light_count = 1 + in.byte() % 4;
    s.env.ambient = coefficient(vec<3, T>(in));
    s.env.eye = vec<4, T>(in, true);
    // Points first (the lights may aim at point 0).
    s.px.resize(s.n), s.py.resize(s.n), s.pz.resize(s.n), s.nx.resize(s.n), s.ny.resize(s.n), s.nz.resize(s.n);
    s.front.reset(new bool[s.n]);
    for (std::size_t i = 0; i < s.n; ++i) {
        const std::uint8_t how = in.byte();
        if (i > 0 && (how & 3) == 0) { // a neighbour of the previous point: steps of one ulp-ish
            s.px[i] = std::nextafter(s.px[i - 1], T(1)), s.py[i] = s.py[i - 1], s.pz[i] = s.pz[i - 1];
            s.nx[i] = s.nx[i - 1], s.ny[i] = s.ny[i - 1], s.nz[i] = s.nz[i - 1];
        } else {
            const glm::vec<3, T> q = vec<3, T>(in, true), nn = vec<3, T>(in, true);
            s.px[i] = q.x, s.py[i] = q.y, s.pz[i] = q.z, s.nx[i] = nn.x, s.ny[i] = nn.y, s.nz[i] = nn.z;
        }
        s.front[i] = (how & 4) == 0;
    }
    const glm::vec<3, T> aim(s.px[0], s.py[0], s.pz[0]);
    for (std::size_t k = 0; k < light_count; ++k) {
        const light<T> L = decode_light<T>(in, std::isfinite(aim.x) && std::isfinite(aim.y) && std::isfinite(aim.z) ? aim : glm::vec<3, T>(0));
        if (validate(L)) s.lights.push_back(L); // only what validate accepts
        else ++stats.lights_rejected;
    }
    s.mats.resize(s.n);
    s.mats[0] = decode_material<T>(in);
    for (std::size_t i = 1; i < s.n; ++i) s.mats[i] = s.per_point ? decode_material<T>(in) : s.mats[0];

    stats.lights_kept += s.lights.size();
    current<T> = &s;
    current_features = selector & 0x0f;
    describe_input = &describe<T>;
    dispatch<T>(selector & 0x0f, s, std::make_index_sequence<feature_count>{});
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size < 2) return 0;
    ++stats.inputs;
    reader in{data + 1, size - 1};
    const std::uint8_t selector = data[0];
    if (selector & 0x10) run<double>(in, selector);
    else run<float>(in, selector);
    return 0;
}
