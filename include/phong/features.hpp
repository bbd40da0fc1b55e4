// phong: `features`, the compile-time description of what a scene needs.
// SPDX-License-Identifier: MIT
//
// A structural aggregate, passed as a non-type template parameter to shade<F>(...). Every
// optional term of the model sits behind `if constexpr` on one of these fields, so a term a
// scene leaves out is not in the compiled code (checked by an instruction count, see
// benchmarks/feature_cost.sh). Kept in its own header because shade.hpp, batch.hpp and the
// presets all read it.
#pragma once

#include "detail/config.hpp"

namespace phong {

/// Which specular term: none, reflection-based (seed 000/003: max(r.v, 0)^m with
/// r = reflect(-l, n)) or halfway-based (seed 001, Blinn: max(n.h, 0)^m with h = normalize(l + v)).
enum class specular_model : unsigned char { none, phong, blinn };

/// What the light positions' w may be. `any`: read at run time (w = 1 positional, w = 0
/// directional, one branch-free rule). `positional`: w = 1 assumed. `directional`: w = 0 assumed,
/// so no distance and no attenuation are computed.
enum class light_kind : unsigned char { any, positional, directional };

/// Distance attenuation f_i(Q). `none`: f = 1. `polynomial`: OpenGL / seed 000,
/// f = 1 / (c0 + c1 d + c2 d^2). `windowed`: inverse square with a smooth window that reaches
/// exactly 0 at the light's range (Filament, three.js): f = clamp(1 - (d/range)^4, 0, 1)^2 / d^2.
enum class attenuation_model : unsigned char { none, polynomial, windowed };

/// Spot cone. `opengl`: max(-l.s, 0)^e inside the cutoff, 0 outside (cutoff 180 = no spot).
/// `smooth`: smoothstep from the outer to the inner cone (Filament, three.js).
enum class spot_model : unsigned char { none, opengl, smooth };

/// Two-sided lighting: how the normal is conditionally negated. `none`: used as given. `view`:
/// negated when it faces away from the viewer, n.v < 0 (seed 000's "conditionally negated").
/// `flag`: negated when the caller says the point is back-facing (e.g. gl_FrontFacing).
enum class facing : unsigned char { none, view, flag };

/// Where the eye is, and so how v is computed. `perspective`: the eye at the origin of eye
/// coordinates, v = normalize(-Q) (seed 000, 003). `orthographic`: a constant v, the environment's
/// eye direction (w = 0), normalized once per call. `eye_point`: the general homogeneous rule,
/// v = normalize(E.xyz - E.w Q) for the environment's eye E (seed 001's ray start; view.hpp
/// derives E from any projection matrix).
enum class view_model : unsigned char { perspective, orthographic, eye_point };

/// How the terms are evaluated (accuracy against speed; bounds in phong/accuracy.hpp).
/// `exact`: the formulas as written, guarded so they never give NaN/Inf for finite input.
/// `stable`: a few ulp or better on stiff and extreme inputs (phong/accuracy.hpp), by one of two
/// routes (features::precision): float evaluated in double, or power-of-two rescaled vectors with
/// the unit vectors n, l, v (h), n.l and the chords r - v, n - h carried twofold (to ~eps^2, from the
/// exact L - Q; detail/twofold.hpp) and the half-chord exponent exp(m log1p(-|r - v|^2/2)).
enum class evaluation : unsigned char { exact, stable };

/// Where the stable mode's extra precision comes from (phong/accuracy.hpp has the bounds).
/// `wider`: float is evaluated in double with the exact mode's formulas and rounded once. Every
/// float input is exact in double, no square of a float overflows or underflows there, and double
/// carries 29 more bits than float, so the colour is float's correct rounding of the model but for
/// near-ties (about 0.5 ulp). The default: on CPUs it is the fastest and most accurate choice.
/// T without a wider hardware type (double, SIMD batches) takes `twofold`. `twofold`: T arithmetic
/// with power-of-two rescaled vectors and twofold unit vectors, n.l and chords (detail/twofold.hpp);
/// for GPU code, where double runs at a fraction of float's rate.
enum class stable_precision : unsigned char { wider, twofold };

/// Everything shade<F> can compute. Defaults: seed 000's classic model with one ambient term,
/// reflection-based specular gated on n.l > 0, perspective view, exact evaluation.
struct features {
    bool scene_ambient = true;   ///< ka * La (seed 000), the same as seed 001's IG = GlobalAmbient * ka
    bool light_ambient = false;  ///< per-light ambient lightamb * ka (seed 001 Iamb, seed 003 La * Ka)
    bool diffuse = true;         ///< kd * max(n.l, 0)
    specular_model specular = specular_model::phong;
    bool specular_gate = true;   ///< specular only where n.l > 0 (seed 003); seed 001 has no gate
    light_kind lights = light_kind::any;
    attenuation_model attenuation = attenuation_model::none;
    spot_model spot = spot_model::none;
    bool attenuate_ambient = true; ///< f_i and the spot also scale the per-light ambient (OpenGL)
    facing two_sided = facing::none;
    view_model view = view_model::perspective;
    bool emission = false;       ///< material emission added
    bool alpha = false;          ///< return rgba with the material's alpha appended
    evaluation mode = evaluation::exact;
    stable_precision precision = stable_precision::wider; ///< stable mode only: wider (float in double) or twofold
    /// Stable mode with twofold precision only: 0 (the default) carries every pair twofold, the accuracy that
    /// phong/accuracy.hpp publishes. M > 0 rounds each component once for pairs with shininess
    /// m <= M (Blinn: unless l + v nearly cancels), less than half the cost, at an error that
    /// grows like sqrt(m) eps. With M = 256, float, 2000 scenes per input class against __float128
    /// (tests/stable_hybrid.test.cpp): well-conditioned p99 2.6 ulp, max 16 ulp; worst class max
    /// 50 ulp, max relative 3.5e-6; every target of the stable mode met. Higher m stays twofold.
    unsigned stable_twofold_above = 0;
};

/// Ready-made feature sets reproducing the seeds.
namespace presets {

/// Seed 000, classic Phong in eye coordinates:
/// I = ka La + sum_i f_i(Q) L_i (kd max(n.l_i, 0) + ks max(r_i.v, 0)^m), normal negated when it
/// faces away from the viewer, alpha appended, view vector from the eye point of ec_lds
/// (perspective or orthographic), polynomial attenuation. The seed writes n.l and (r.v)^m without
/// clamps; they are clamped at 0 here (as in every shader of that model) and not gated.
inline constexpr features seed000_classic{
    .scene_ambient = true, .light_ambient = false, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = false, .lights = light_kind::any,
    .attenuation = attenuation_model::polynomial, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::view, .view = view_model::eye_point,
    .emission = false, .alpha = true, .mode = evaluation::exact};

/// Seed 001, the ray tracer's Blinn-Phong: I = sum_i (Iamb + Idiff + Ispec) + IG with
/// Iamb = lightamb * materialamb, Idiff = lightdiff * materialdiff * max(l.m, 0),
/// Ispec = lightspec * materialspec * max(0, h.m)^f, IG = GlobalAmbient * materialamb.
/// No attenuation, no gate (as written), positional lights, the eye at the ray's start.
inline constexpr features seed001_raytracer{
    .scene_ambient = true, .light_ambient = true, .diffuse = true,
    .specular = specular_model::blinn, .specular_gate = false, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::eye_point,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// Seed 003, GLSL ADS (phong.vert): La Ka + Ld Kd max(s.n, 0) + [s.n > 0] Ls Ks max(r.v, 0)^f
/// with r = reflect(-s, n), v = normalize(-eyeCoords), s = normalize(LightPosition - eyeCoords).
inline constexpr features seed003_ads{
    .scene_ambient = false, .light_ambient = true, .diffuse = true,
    .specular = specular_model::phong, .specular_gate = true, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::perspective,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// Seed 003, diffuse.vert: Ld Kd max(s.n, 0) only.
inline constexpr features seed003_diffuse{
    .scene_ambient = false, .light_ambient = false, .diffuse = true,
    .specular = specular_model::none, .specular_gate = true, .lights = light_kind::positional,
    .attenuation = attenuation_model::none, .spot = spot_model::none,
    .attenuate_ambient = true, .two_sided = facing::none, .view = view_model::perspective,
    .emission = false, .alpha = false, .mode = evaluation::exact};

/// The same feature set evaluated in another mode (e.g. with_mode(seed000_classic, stable)).
PHONG_HD constexpr features with_mode(features f, evaluation mode)
{
    f.mode = mode;
    return f;
}

} // namespace presets
} // namespace phong
