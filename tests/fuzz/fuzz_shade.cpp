// libFuzzer target for phong::shade and phong::validate.
// SPDX-License-Identifier: MIT
//
// Build (see build.sh):  clang++ -std=c++20 -O1 -g -DNDEBUG -fsanitize=fuzzer,address,undefined ...
// Run:                   ./fuzz_shade corpus/ -max_total_time=60
//
// The input bytes are decoded into a point Q, a normal n, an environment (La, eye), a material and
// 1-8 lights; the first byte picks the number type (bit 4: float or double), the front_facing flag
// (bit 5), whether parameters are repaired into the domain (bit 6, `repair`: extreme but valid
// values, so that the bound checks see many more inputs), and the feature set (bits 0-3, one of the
// `phong::features` instantiations below: phong/blinn, exact/stable, attenuation
// none/polynomial/windowed, spots, two-sided, every view model) and the front_facing flag.
// Every scalar may be any bit pattern (NaN, inf, subnormal, huge) or a small grid value.
//
// Checks (a violation calls __builtin_trap(), so libFuzzer saves the input):
//  1. validate(material) and validate(light) agree with an independent re-statement of the
//     documented domain (`material_in_domain`, `light_in_domain` below).
//  2. No sanitizer report (ASan, UBSan) for any input; shade is called on invalid parameters too
//     (the fuzzer is built with -DNDEBUG, so shade's debug assertion does not fire).
//  3. Valid parameters, NaN or inf in Q or n (or in the eye, for view_model::eye_point):
//     every channel is NaN (shade.hpp's documented policy).
//  4. Valid parameters, finite geometry, finite La >= 0: every channel is >= 0, not NaN, and
//     bounded (see `upper_bound`); finite unless the bound itself is near overflow; alpha is the
//     material's alpha.
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
#include <span>
#include <utility>

namespace {

using wide = long double;

void (*describe_input)() = nullptr; // prints the decoded scene of the current input

[[noreturn]] void fail(const char* what)
{
    std::fprintf(stderr, "fuzz_shade: check failed: %s\n", what);
    if (describe_input) describe_input();
    __builtin_trap();
}
// Counts of what the checks reached (printed at exit when built with -DFUZZ_SHADE_STATS).
struct statistics {
    unsigned long inputs = 0, params_valid = 0, nan_policy = 0, sign_checked = 0, bound_checked = 0;
#ifdef FUZZ_SHADE_STATS
    ~statistics()
    {
        std::fprintf(stderr, "fuzz_shade: %lu inputs, %lu with valid parameters, %lu NaN-policy checks, "
                     "%lu sign/finiteness checks, %lu bound checks\n", inputs, params_valid, nan_policy, sign_checked, bound_checked);
    }
#endif
} stats;

#define FUZZ_CHECK(cond, what) \
    do {                       \
        if (!(cond)) fail(what); \
    } while (0)

// ---------------------------------------------------------------------------------------------
// Decoding
// ---------------------------------------------------------------------------------------------

struct reader {
    const std::uint8_t* data;
    std::size_t size;
    std::uint8_t byte()
    {
        if (size == 0) return 0x40; // grid value 0 once the input is exhausted
        --size;
        return *data++;
    }
};

using phong_fuzz::scalar;
using phong_fuzz::vec;

/// Flags byte: bits 0-1 w (0, 1, or a scalar), bit 2 range = inf, bit 3 normalize the spot axis,
/// bit 4 cos_cutoff = -1, bit 5 aim the spot axis exactly at Q (so that c = -l.s is 1 up to
/// rounding), bit 6 (with bit 5) scale the aimed axis by 1 + 2^-11 (inside validate's tolerance).
template <class T>
phong::light<T> decode_light(reader& in, const glm::vec<3, T>& Q)
{
    phong::light<T> L;
    const std::uint8_t flags = in.byte();
    const glm::vec<3, T> xyz = vec<3, T>(in, true);
    const T w = (flags & 3) == 0 ? T(0) : (flags & 3) == 1 ? T(1) : scalar<T>(in);
    L.position = glm::vec<4, T>(xyz, w);
    L.ambient = vec<3, T>(in);
    L.diffuse = vec<3, T>(in);
    L.specular = vec<3, T>(in);
    L.attenuation.constant = scalar<T>(in);
    L.attenuation.linear = scalar<T>(in);
    L.attenuation.quadratic = scalar<T>(in);
    L.attenuation.range = (flags & 4) ? std::numeric_limits<T>::infinity() : scalar<T>(in);
    glm::vec<3, T> axis = vec<3, T>(in, true);
    if (flags & 8) { // normalized in long double and rounded once: unit within rounding
        const wide a = axis.x, b = axis.y, c = axis.z, len = std::sqrt(a * a + b * b + c * c);
        if (std::isfinite(len) && len > 0) axis = glm::vec<3, T>(T(a / len), T(b / len), T(c / len));
    }
    if (flags & 32) { // axis = normalize(Q - L.xyz), in long double, rounded once
        const wide a = wide(Q.x) - wide(xyz.x), b = wide(Q.y) - wide(xyz.y), c = wide(Q.z) - wide(xyz.z);
        const wide len = std::sqrt(a * a + b * b + c * c) / ((flags & 64) ? 1 + std::ldexp(wide(1), -11) : wide(1));
        if (std::isfinite(len) && len > 0) axis = glm::vec<3, T>(T(a / len), T(b / len), T(c / len));
    }
    L.spot.direction = axis;
    L.spot.exponent = scalar<T>(in);
    L.spot.cos_cutoff = (flags & 16) ? T(-1) : scalar<T>(in, true);
    L.spot.cos_inner = scalar<T>(in, true);
    L.spot.cos_outer = scalar<T>(in, true);
    return L;
}

template <class T>
struct scene {
    glm::vec<3, T> position, normal;
    phong::environment<T> env;
    phong::material<T> mat;
    std::array<phong::light<T>, 8> lights;
    std::size_t count;
    bool front_facing;
};

template <int L, class T> void print(const char* name, const glm::vec<L, T>& v)
{
    std::fprintf(stderr, "  %s = (", name);
    for (int k = 0; k < L; ++k) std::fprintf(stderr, "%s%.17Lg", k ? ", " : "", static_cast<wide>(v[k]));
    std::fprintf(stderr, ")\n");
}
template <class T> void print(const char* name, T x) { std::fprintf(stderr, "  %s = %.17Lg\n", name, static_cast<wide>(x)); }

template <class T> const scene<T>* current = nullptr;
std::size_t current_features = 0;
wide last_out[4]{};
int last_channels = 0;
template <class T> void describe()
{
    const scene<T>& s = *current<T>;
    std::fprintf(stderr, "features #%zu, out = (", current_features);
    for (int c = 0; c < last_channels; ++c) std::fprintf(stderr, "%s%.17Lg", c ? ", " : "", last_out[c]);
    std::fprintf(stderr, ")\nscene (%s, front_facing %d, %zu lights):\n", sizeof(T) == 4 ? "float" : "double", s.front_facing, s.count);
    print("Q", s.position), print("n", s.normal), print("La", s.env.ambient), print("eye", s.env.eye);
    print("ka", s.mat.ka), print("kd", s.mat.kd), print("ks", s.mat.ks), print("emission", s.mat.emission);
    print("shininess", s.mat.shininess), print("alpha", s.mat.alpha);
    for (std::size_t i = 0; i < s.count; ++i) {
        const phong::light<T>& L = s.lights[i];
        std::fprintf(stderr, " light %zu:\n", i);
        print("position", L.position), print("ambient", L.ambient), print("diffuse", L.diffuse), print("specular", L.specular);
        print("c0 c1 c2 range", glm::vec<4, T>(L.attenuation.constant, L.attenuation.linear, L.attenuation.quadratic, L.attenuation.range));
        print("spot axis", L.spot.direction);
        print("exponent cos_cutoff cos_inner cos_outer", glm::vec<4, T>(L.spot.exponent, L.spot.cos_cutoff, L.spot.cos_inner, L.spot.cos_outer));
    }
}

// ---------------------------------------------------------------------------------------------
// The domain, re-stated from the doc comments of validate(material) and validate(light), in
// long double with <cmath> classification (independent of validate.hpp's helpers).
// ---------------------------------------------------------------------------------------------

template <class T> bool fin(T x) { return std::isfinite(static_cast<wide>(x)); }
template <class T> bool fin_nonneg(T x) { return fin(x) && static_cast<wide>(x) >= 0; } // -0 counts as 0
template <int L, class T> bool all_fin(const glm::vec<L, T>& v)
{
    for (int k = 0; k < L; ++k)
        if (!fin(v[k])) return false;
    return true;
}
template <int L, class T> bool all_fin_nonneg(const glm::vec<L, T>& v)
{
    for (int k = 0; k < L; ++k)
        if (!fin_nonneg(v[k])) return false;
    return true;
}

/// material.hpp: ka, kd, ks, emission finite and >= 0; shininess finite and >= 0; alpha in [0, 1].
template <class T> bool material_in_domain(const phong::material<T>& m)
{
    return all_fin_nonneg(m.ka) && all_fin_nonneg(m.kd) && all_fin_nonneg(m.ks) && all_fin_nonneg(m.emission) &&
           fin_nonneg(m.shininess) && static_cast<wide>(m.alpha) >= 0 && static_cast<wide>(m.alpha) <= 1;
}

enum class verdict { reject, accept, either };

/// light.hpp: position finite with w = 0 or w = 1 (-0 is 0); strengths finite and >= 0; c0, c1, c2 finite, >= 0 and
/// not all zero; range > 0 (inf allowed); spot exponent finite and >= 0; cos_cutoff -1 or in
/// [0, 1]; cos_inner, cos_outer in [-1, 1] with cos_outer <= cos_inner; |axis| = 1 "within 1e-3",
/// read as |axis|^2 in (0.998, 1.002), or the zero axis (no cone). Within 1e-6 (relative) of those two ends either answer is
/// accepted: that is where rounding of |axis|^2 in T decides.
template <class T> verdict light_in_domain(const phong::light<T>& L)
{
    const auto& a = L.attenuation;
    const auto& s = L.spot;
    const wide w = L.position.w;
    const bool ok = all_fin(L.position) && (w == 0 || w == 1) && all_fin_nonneg(L.ambient) && all_fin_nonneg(L.diffuse) &&
                    all_fin_nonneg(L.specular) && fin_nonneg(a.constant) && fin_nonneg(a.linear) &&
                    fin_nonneg(a.quadratic) && !(a.constant == 0 && a.linear == 0 && a.quadratic == 0) &&
                    static_cast<wide>(a.range) > 0 && fin_nonneg(s.exponent) &&
                    (static_cast<wide>(s.cos_cutoff) == -1 || (static_cast<wide>(s.cos_cutoff) >= 0 && static_cast<wide>(s.cos_cutoff) <= 1)) &&
                    static_cast<wide>(s.cos_inner) >= -1 && static_cast<wide>(s.cos_inner) <= 1 &&
                    static_cast<wide>(s.cos_outer) >= -1 && static_cast<wide>(s.cos_outer) <= 1 &&
                    static_cast<wide>(s.cos_outer) <= static_cast<wide>(s.cos_inner);
    if (!ok) return verdict::reject;
    const wide x = s.direction.x, y = s.direction.y, z = s.direction.z;
    const wide a2 = x * x + y * y + z * z; // no underflow in long double for float or double components
    if (a2 == 0) return verdict::accept;  // a zero axis: no cone
    const auto near = [&](wide edge) { return std::fabs(a2 - edge) <= 1e-6L * edge; };
    if (near(0.998L) || near(1.002L)) return verdict::either;
    return (a2 > 0.998L && a2 < 1.002L) ? verdict::accept : verdict::reject;
}

// ---------------------------------------------------------------------------------------------
// The upper bound (shade.hpp's formula with every factor at its largest):
//   I <= emission + ka (La + sum_i g_i La_i) + kd sum_i f_i Ld_i + ks sum_i f_i Ls_i
// with, for light i,
//   f_i = a_i * spot_i <= cap_i,   spot_i <= 1   (OpenGL: max(c, 0)^e with c = -l.s <= 1;
//                                                  smooth: smoothstep of t in [0, 1]),
//   a_i = 1 without attenuation, for directional lights (w = 0, or light_kind::directional);
//   polynomial: a_i = 1 / max(c0 + c1 d + c2 d^2, dmin) <= 1 / max(c0, dmin)   (d >= 0, c_k >= 0);
//   windowed:   a_i = window^2 / max(d^2, dmin) <= 1 / dmin                     (window in [0, 1]);
//   dmin = sqrt(smallest normal T) = 2^((min_exponent - 1) / 2)   (attenuation.hpp's doc);
//   g_i = f_i when features::attenuate_ambient, else 1;
//   the diffuse factor max(n.l, 0) <= 1 and the specular factor (base clamped to [0, 1])^m <= 1.
// Rounding: the computed unit vectors have length 1 + O(eps), so the output may exceed the exact
// bound by a relative (8 * lights + 32) eps; results in the subnormal range may round up by a few
// denorm_min. The bound is evaluated in long double (no overflow for float or double inputs).
// ---------------------------------------------------------------------------------------------

template <class T> wide dmin()
{
    return std::ldexp(wide(1), (std::numeric_limits<T>::min_exponent - 1) / 2);
}

template <phong::features F, class T>
wide attenuation_cap(const phong::light<T>& L)
{
    using phong::attenuation_model;
    using phong::light_kind;
    if constexpr (F.attenuation == attenuation_model::none || F.lights == light_kind::directional) {
        return 1;
    } else {
        const bool positional = F.lights == light_kind::positional || L.position.w > 0;
        if (!positional) return 1;
        if constexpr (F.attenuation == attenuation_model::polynomial)
            return 1 / std::fmax(static_cast<wide>(L.attenuation.constant), dmin<T>());
        else
            return 1 / dmin<T>();
    }
}

template <class T> struct bound3 {
    wide total[3]{};
    wide largest_part = 0; ///< the largest intermediate sum: overflow of T is possible above max/8
};

template <phong::features F, class T>
bound3<T> upper_bound(const scene<T>& s)
{
    bound3<T> b;
    for (int c = 0; c < 3; ++c) {
        wide amb = 0, dif = 0, spe = 0;
        for (std::size_t i = 0; i < s.count; ++i) {
            const phong::light<T>& L = s.lights[i];
            const wide f = attenuation_cap<F>(L); // times spot <= 1
            amb += (F.attenuate_ambient ? f : wide(1)) * static_cast<wide>(L.ambient[c]);
            dif += f * static_cast<wide>(L.diffuse[c]);
            spe += f * static_cast<wide>(L.specular[c]);
        }
        wide La = F.scene_ambient ? static_cast<wide>(s.env.ambient[c]) : wide(0);
        if (F.light_ambient) La += amb;
        wide t = 0;
        if (F.emission) t += s.mat.emission[c];
        t += s.mat.ka[c] * La;
        if (F.diffuse) t += s.mat.kd[c] * dif;
        if (F.specular != phong::specular_model::none) t += s.mat.ks[c] * spe;
        b.total[c] = t;
        for (wide part : {La, dif, spe, t, wide(s.mat.ka[c] * La), wide(s.mat.kd[c] * dif), wide(s.mat.ks[c] * spe)})
            b.largest_part = std::fmax(b.largest_part, part);
    }
    return b;
}

/// Coordinates the exact mode handles without losing precision: zero, or a magnitude in
/// [2^-e, 2^e] (e = 15 for float, 120 for double), so that every difference L.xyz - w Q and every
/// |v|^2 is a normal number (normalize_unscaled's precondition, vector.hpp). Outside it the
/// exact mode is documented as inaccurate; only signs and NaN-freedom are checked there.
template <class T> bool moderate(T x)
{
    constexpr int e = sizeof(T) == 4 ? 15 : 120;
    const wide a = std::fabs(static_cast<wide>(x));
    return a == 0 || (a >= std::ldexp(wide(1), -e) && a <= std::ldexp(wide(1), e));
}
template <int L, class T> bool moderate(const glm::vec<L, T>& v)
{
    for (int k = 0; k < L; ++k)
        if (!moderate(v[k])) return false;
    return true;
}

// ---------------------------------------------------------------------------------------------
// One feature set
// ---------------------------------------------------------------------------------------------

template <phong::features F, class T>
void check(const scene<T>& s, bool params_valid)
{
    using phong::view_model;
    const std::span<const phong::light<T>> lights(s.lights.data(), s.count);
    const auto out = phong::shade<F>(s.position, s.normal, s.mat, lights, s.env, s.front_facing);
    last_channels = F.alpha ? 4 : 3;
    for (int c = 0; c < last_channels; ++c) last_out[c] = static_cast<wide>(out[c]);
    constexpr int channels = F.alpha ? 4 : 3;
    if (!params_valid) return; // only the sanitizers judge out-of-domain parameters
    ++stats.params_valid;

    const bool eye_read = F.view != view_model::eye_at_origin;
    const bool geometry_finite = all_fin(s.position) && all_fin(s.normal) && (F.view != view_model::eye_point || all_fin(s.env.eye));
    if (!geometry_finite) { // shade.hpp: NaN or inf in position, normal or (eye_point) eye: every channel NaN
        ++stats.nan_policy;
        for (int c = 0; c < channels; ++c) FUZZ_CHECK(std::isnan(out[c]), "non-finite geometry must give NaN in every channel");
        return;
    }
    if (!all_fin_nonneg(s.env.ambient) || (eye_read && !all_fin(s.env.eye))) return; // environment not in the domain

    if constexpr (F.alpha) FUZZ_CHECK(out[3] == s.mat.alpha, "alpha channel must be the material's alpha");

    const bound3<T> b = upper_bound<F>(s);
    const bool may_overflow = b.largest_part > static_cast<wide>(std::numeric_limits<T>::max()) / 8;
#ifndef FUZZ_SHADE_STRICT
    // Known finding, reported (README): once a sum of f_i L_i or a product k * sum overflows T,
    // a channel whose k is 0 gets 0 * inf = NaN. FUZZ_SHADE_STRICT keeps checking it.
    if (may_overflow) {
        for (int c = 0; c < 3; ++c) FUZZ_CHECK(!(out[c] < 0), "negative channel");
        return;
    }
#endif
    ++stats.sign_checked;
    for (int c = 0; c < 3; ++c) {
        FUZZ_CHECK(!std::isnan(out[c]), "finite in-domain input gave NaN");
        FUZZ_CHECK(out[c] >= 0, "negative channel");
        if (!may_overflow) FUZZ_CHECK(std::isfinite(out[c]), "finite in-domain input gave inf");
    }

    bool bound_applies = true;
    if constexpr (F.mode == phong::evaluation::exact) {
        bool m = moderate(s.position) && moderate(s.normal) && (!eye_read || moderate(s.env.eye));
        for (std::size_t i = 0; i < s.count; ++i) m = m && moderate(s.lights[i].position);
        bound_applies = m;
    }
    if (!bound_applies) return;
    ++stats.bound_checked;
    const wide eps = std::numeric_limits<T>::epsilon();
    const wide slack = (8 * static_cast<wide>(s.count) + 32) * eps;
    // Gradual underflow: a sum rounded in the subnormal range is off by up to a subnormal half-ulp,
    // which the material coefficient then multiplies (found: kd = 1.5e63 times a sum of 1e-323
    // terms, 7.6e-261 over the bound); so the absolute allowance scales with the largest
    // coefficient, as accuracy::exact_absolute_allowance does.
    wide k_max = 1;
    for (int c = 0; c < 3; ++c)
        k_max = std::max({k_max, static_cast<wide>(s.mat.ka[c]), static_cast<wide>(s.mat.kd[c]), static_cast<wide>(s.mat.ks[c])});
    for (int c = 0; c < 3; ++c) {
        const wide limit = b.total[c] * (1 + slack) + 64 * k_max * static_cast<wide>(std::numeric_limits<T>::denorm_min());
        const bool overflowed = may_overflow && std::isinf(out[c]); // rounding to inf is correct there
        if (!(static_cast<wide>(out[c]) <= limit || overflowed)) {
            std::fprintf(stderr, "channel %d: got %.21Lg, bound %.21Lg\n", c, static_cast<wide>(out[c]), b.total[c]);
            fail("output exceeds emission + ka (La + sum g La_i) + kd sum f Ld_i + ks sum f Ls_i");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The feature sets exercised (index = low 4 bits of the first byte)
// ---------------------------------------------------------------------------------------------

using namespace phong;
constexpr features feature_table[] = {
    features{}, // seed 000's default: phong, exact, no attenuation, perspective
    presets::classic_phong,
    presets::with_mode(presets::classic_phong, evaluation::stable),
    presets::blinn_phong_per_light_ambient,
    presets::with_mode(presets::blinn_phong_per_light_ambient, evaluation::stable),
    presets::glsl_ads,
    presets::diffuse_only,
    features{.light_ambient = true, .specular = specular_model::blinn, .attenuation = attenuation_model::windowed,
             .spot = spot_model::smooth, .attenuate_ambient = false, .two_sided = facing::flag,
             .view = view_model::fixed_direction, .emission = true, .alpha = true, .mode = evaluation::stable},
    features{.specular = specular_model::phong, .lights = light_kind::positional, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::opengl, .two_sided = facing::view, .emission = true, .mode = evaluation::stable,
             .precision = stable_precision::twofold}, // float's twofold route (float's default is wider)
    features{.specular = specular_model::phong, .lights = light_kind::directional, .attenuation = attenuation_model::windowed,
             .spot = spot_model::opengl, .view = view_model::fixed_direction, .mode = evaluation::exact},
    features{.specular = specular_model::blinn, .specular_gate = false, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::smooth, .two_sided = facing::flag, .view = view_model::eye_point, .mode = evaluation::exact},
    features{.light_ambient = true, .specular = specular_model::phong, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::opengl, .attenuate_ambient = true, .mode = evaluation::exact},
    features{.light_ambient = true, .specular = specular_model::blinn, .attenuation = attenuation_model::polynomial,
             .spot = spot_model::opengl, .two_sided = facing::view, .view = view_model::eye_point, .emission = true,
             .alpha = true, .mode = evaluation::stable, .precision = stable_precision::twofold},
    features{.specular = specular_model::phong, .specular_gate = false, .attenuation = attenuation_model::windowed,
             .spot = spot_model::smooth, .two_sided = facing::flag, .mode = evaluation::stable},
    features{.scene_ambient = false, .specular = specular_model::none, .lights = light_kind::positional,
             .attenuation = attenuation_model::windowed, .spot = spot_model::opengl, .mode = evaluation::stable},
    features{.scene_ambient = false, .diffuse = false, .specular = specular_model::none, .emission = true,
             .mode = evaluation::exact},
};
constexpr std::size_t feature_count = sizeof(feature_table) / sizeof(feature_table[0]);
static_assert(feature_count == 16);

template <class T, std::size_t... I>
void dispatch(std::size_t index, const scene<T>& s, bool valid, std::index_sequence<I...>)
{
    ((index == I ? check<feature_table[I], T>(s, valid) : void()), ...);
}

/// Moves every material and light parameter into the documented domain, keeping magnitudes: NaN
/// and inf become 1, negatives their absolute value, a light's w becomes 1 if it was > 0 (else 0),
/// alpha and cosines are folded into their ranges, the spot axis is normalized (in long double) and all-zero attenuation gets c0 = 1.
/// Geometry (Q, n, eye, light positions' xyz) is left as decoded.
template <class T> T repaired(T x) { return std::isfinite(x) ? std::fabs(x) : T(1); }
template <class T> T folded(T x, T lo, T hi) { return std::isfinite(x) ? std::clamp(x, lo, hi) : hi; }
template <class T> void repair(scene<T>& s)
{
    for (int k = 0; k < 3; ++k) {
        s.mat.ka[k] = repaired(s.mat.ka[k]), s.mat.kd[k] = repaired(s.mat.kd[k]);
        s.mat.ks[k] = repaired(s.mat.ks[k]), s.mat.emission[k] = repaired(s.mat.emission[k]);
        s.env.ambient[k] = repaired(s.env.ambient[k]);
    }
    s.mat.shininess = repaired(s.mat.shininess);
    s.mat.alpha = folded(s.mat.alpha, T(0), T(1));
    for (std::size_t i = 0; i < s.count; ++i) {
        phong::light<T>& L = s.lights[i];
        for (int k = 0; k < 3; ++k) {
            if (!std::isfinite(L.position[k])) L.position[k] = T(1);
            L.ambient[k] = repaired(L.ambient[k]), L.diffuse[k] = repaired(L.diffuse[k]), L.specular[k] = repaired(L.specular[k]);
        }
        L.position.w = repaired(L.position.w) > 0 ? T(1) : T(0); // w > 0 positional, else directional
        auto& a = L.attenuation;
        a.constant = repaired(a.constant), a.linear = repaired(a.linear), a.quadratic = repaired(a.quadratic);
        if (a.constant == 0 && a.linear == 0 && a.quadratic == 0) a.constant = T(1);
        if (std::isnan(a.range) || a.range == 0) a.range = std::numeric_limits<T>::infinity();
        a.range = std::fabs(a.range);
        auto& sp = L.spot;
        sp.exponent = repaired(sp.exponent);
        if (sp.cos_cutoff != T(-1)) sp.cos_cutoff = folded(std::fabs(sp.cos_cutoff), T(0), T(1));
        sp.cos_inner = folded(sp.cos_inner, T(-1), T(1)), sp.cos_outer = folded(sp.cos_outer, T(-1), T(1));
        if (sp.cos_outer > sp.cos_inner) std::swap(sp.cos_outer, sp.cos_inner);
        const wide x = sp.direction.x, y = sp.direction.y, z = sp.direction.z, len = std::sqrt(x * x + y * y + z * z);
        sp.direction = (std::isfinite(len) && len > 0) ? glm::vec<3, T>(T(x / len), T(y / len), T(z / len))
                                                       : glm::vec<3, T>(T(0), T(0), T(-1));
    }
}

template <class T>
void run(reader& in, std::uint8_t selector)
{
    scene<T> s{};
    s.front_facing = (selector & 0x20) != 0;
    s.count = 1 + in.byte() % 8;
    s.position = vec<3, T>(in, true);
    s.normal = vec<3, T>(in, true);
    s.env.ambient = vec<3, T>(in);
    s.env.eye = vec<4, T>(in, true);
    s.mat.ka = vec<3, T>(in);
    s.mat.kd = vec<3, T>(in);
    s.mat.ks = vec<3, T>(in);
    s.mat.emission = vec<3, T>(in);
    s.mat.shininess = scalar<T>(in);
    s.mat.alpha = scalar<T>(in);
    for (std::size_t i = 0; i < s.count; ++i) s.lights[i] = decode_light<T>(in, s.position);
    if (selector & 0x40) repair(s);

    current<T> = &s;
    current_features = selector & 0x0f;
    describe_input = &describe<T>;
    // 1. validate against the re-stated domain.
    bool valid = material_in_domain(s.mat);
    FUZZ_CHECK(static_cast<bool>(phong::validate(s.mat)) == valid, "validate(material) disagrees with the documented domain");
    for (std::size_t i = 0; i < s.count; ++i) {
        const verdict v = light_in_domain(s.lights[i]);
        const bool got = static_cast<bool>(phong::validate(s.lights[i]));
        if (v != verdict::either) FUZZ_CHECK(got == (v == verdict::accept), "validate(light) disagrees with the documented domain");
        valid = valid && got;
    }
    // 2-4. shade.
    dispatch<T>(selector & 0x0f, s, valid, std::make_index_sequence<feature_count>{});
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
